#include "core/ray_integrator.h"

#include <algorithm>

#include "core/error.h"

namespace eikon {

const std::vector<std::string>& rayIntegratorNames() {
    static const std::vector<std::string> names = {"euler", "midpoint", "rk4", "verlet"};
    return names;
}

const std::string& rayIntegratorName(RayIntegrator integrator) {
    return rayIntegratorNames().at(static_cast<size_t>(integrator));
}

RayIntegrator rayIntegratorNamed(const std::string& name) {
    const std::vector<std::string>& names = rayIntegratorNames();
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) throw Error("integrator", "no ray integrator '" + name + "'");
    return static_cast<RayIntegrator>(it - names.begin());
}

}  // namespace eikon
