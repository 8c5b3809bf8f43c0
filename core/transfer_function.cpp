#include "core/transfer_function.h"

#include <cmath>
#include <sstream>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace eikon {

std::string transferFunctionProblem(const std::vector<glm::vec2>& points) {
    std::ostringstream out;
    if (points.size() < 2 || points.size() > kMaxTransferPoints) {
        out << "has " << points.size() << " points; it takes 2 to " << kMaxTransferPoints;
        return out.str();
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec2 p = points[i];
        if (!std::isfinite(p.x))
            out << "point " << i << ": its value is not finite";
        else if (!(p.y >= 0.0f) || !std::isfinite(p.y))
            out << "point " << i << ": its amount " << p.y << " is not a finite number >= 0";
        else if (i > 0 && !(p.x > points[i - 1].x))
            out << "point " << i << ": value " << p.x << " is not above the one before, "
                << points[i - 1].x;
        if (!out.str().empty()) return out.str();
    }
    const float atZero = transferAmount(points, 0.0f);
    if (atZero != 0.0f)
        out << "maps 0 to " << atZero
            << ", and must map it to 0: the render volume reads 0 where the field has no voxels, "
               "which would fill all of it";
    return out.str();
}

float transferAmount(const std::vector<glm::vec2>& points, float f) {
    if (points.empty()) return f;
    if (!(f > points.front().x)) return points.front().y;  // NaN too: the first amount
    if (f >= points.back().x) return points.back().y;
    std::size_t i = 1;
    while (points[i].x <= f) ++i;  // points[i − 1].x <= f < points[i].x
    const glm::vec2 a = points[i - 1], b = points[i];
    const float t = (f - a.x) / (b.x - a.x);
    return a.y + t * (b.y - a.y);
}

std::string materialSlotName(const MaterialSpec& m) {
    return m.transfer.empty() ? m.field : m.field + "|" + m.name;
}

const MaterialSpec* transferMaterialOfSlot(const Scene& scene, const std::string& slotName) {
    for (const MaterialSpec& m : scene.materials)
        if (!m.transfer.empty() && materialSlotName(m) == slotName) return &m;
    return nullptr;
}

DenseGrid applyTransfer(const DenseGrid& field, const std::vector<glm::vec2>& points,
                        const std::string& slotName, std::uint64_t version) {
    DenseGrid out;
    out.field = slotName;
    out.version = version;
    out.volume = field.volume;
    out.values.resize(field.values.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, field.values.size(), 1 << 16),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t v = r.begin(); v != r.end(); ++v)
                              out.values[v] = transferAmount(points, field.values[v]);
                      });
    return out;
}

}  // namespace eikon
