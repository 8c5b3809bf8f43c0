#include "render/preview_budget.h"

#include <algorithm>
#include <cmath>

namespace eikon {

int budgetedPreviewScale(int scale, double frameMs, double viewMs, double budgetMs) {
    if (!(budgetMs > 0.0) || !std::isfinite(budgetMs) || !std::isfinite(frameMs) ||
        !std::isfinite(viewMs) || scale < 1)
        return scale;
    const double view = std::clamp(viewMs, 0.0, std::max(frameMs, 0.0));
    const double fixed = std::max(frameMs, 0.0) - view;
    for (int candidate = 1; candidate < kMaxPreviewScale; candidate *= 2) {
        const double ratio = double(scale) / double(candidate);
        const double predicted = fixed + view * ratio * ratio;
        const double limit = candidate < scale ? kPreviewFinerMargin * budgetMs : budgetMs;
        if (predicted <= limit) return candidate;
    }
    return kMaxPreviewScale;
}

}  // namespace eikon
