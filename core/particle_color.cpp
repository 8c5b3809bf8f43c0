#include "core/particle_color.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace eikon {
namespace {

constexpr int kMapEntries = 256;

struct NamedMap {
    const char* name;
    std::array<std::array<float, 3>, kMapEntries> srgb;
};

// matplotlib's tables as sRGB display values (scripts/make-color-maps.py writes them).
const NamedMap kMaps[] = {
#include "core/color_maps_data.inc"
};

const NamedMap* findMap(const std::string& name) {
    for (const NamedMap& m : kMaps)
        if (name == m.name) return &m;
    return nullptr;
}

glm::vec3 linearEntry(const NamedMap& m, int i) {
    const std::array<float, 3>& c = m.srgb[std::size_t(i)];
    return {srgbToLinear(c[0]), srgbToLinear(c[1]), srgbToLinear(c[2])};
}

glm::vec3 pointsColorAt(const std::vector<glm::vec4>& points, float value) {
    const auto rgb = [](glm::vec4 p) { return glm::vec3(p.y, p.z, p.w); };
    if (!(value > points.front().x)) return rgb(points.front());  // NaN too
    if (value >= points.back().x) return rgb(points.back());
    std::size_t i = 1;
    while (points[i].x <= value) ++i;  // points[i − 1].x <= value < points[i].x
    const glm::vec4 a = points[i - 1], b = points[i];
    const float t = (value - a.x) / (b.x - a.x);
    return rgb(a) + t * (rgb(b) - rgb(a));
}

}  // namespace

float srgbToLinear(float display) {
    return display <= 0.04045f ? display / 12.92f : std::pow((display + 0.055f) / 1.055f, 2.4f);
}

const std::vector<std::string>& colorMapNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const NamedMap& m : kMaps) n.emplace_back(m.name);
        return n;
    }();
    return names;
}

std::string particleColorProblem(const ParticleColorSpec& spec) {
    std::ostringstream out;
    if (!spec.map.empty()) {
        if (!findMap(spec.map)) {
            out << "unknown colour map '" << spec.map << "'; known:";
            const std::vector<std::string>& names = colorMapNames();
            for (std::size_t i = 0; i < names.size(); ++i) out << (i ? ", " : " ") << names[i];
        } else if (!std::isfinite(spec.range.x) || !std::isfinite(spec.range.y) ||
                   !(spec.range.y > spec.range.x)) {
            out << "range [" << spec.range.x << ", " << spec.range.y
                << "]: its high end must be finite and above its low end";
        }
        return out.str();
    }
    const std::vector<glm::vec4>& points = spec.points;
    if (points.size() < 2 || points.size() > kMaxParticleColorPoints) {
        out << "has " << points.size() << " points; it takes 2 to " << kMaxParticleColorPoints;
        return out.str();
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const glm::vec4 p = points[i];
        if (!std::isfinite(p.x))
            out << "point " << i << ": its value is not finite";
        else if (!(p.y >= 0.0f && p.z >= 0.0f && p.w >= 0.0f) || !std::isfinite(p.y) ||
                 !std::isfinite(p.z) || !std::isfinite(p.w))
            out << "point " << i << ": its colour is not finite numbers >= 0";
        else if (i > 0 && !(p.x > points[i - 1].x))
            out << "point " << i << ": value " << p.x << " is not above the one before, "
                << points[i - 1].x;
        if (!out.str().empty()) return out.str();
    }
    return "";
}

glm::vec2 particleColorRange(const ParticleColorSpec& spec) {
    if (!spec.map.empty()) return spec.range;
    return {spec.points.front().x, spec.points.back().x};
}

glm::vec3 particleColorAt(const ParticleColorSpec& spec, float value) {
    if (spec.map.empty()) return pointsColorAt(spec.points, value);
    const NamedMap& m = *findMap(spec.map);
    const float last = float(kMapEntries - 1);
    const float t = (value - spec.range.x) / (spec.range.y - spec.range.x) * last;
    if (!(t > 0.0f)) return linearEntry(m, 0);  // NaN too
    if (t >= last) return linearEntry(m, kMapEntries - 1);
    const int i = std::min(int(t), kMapEntries - 2);
    const float w = t - float(i);
    return linearEntry(m, i) + w * (linearEntry(m, i + 1) - linearEntry(m, i));
}

std::vector<glm::vec3> particleColorTable(const ParticleColorSpec& spec, int entries) {
    std::vector<glm::vec3> table(std::size_t(std::max(entries, 2)));
    const int n = int(table.size());
    if (!spec.map.empty() && n == kMapEntries) {
        const NamedMap& m = *findMap(spec.map);
        for (int i = 0; i < n; ++i) table[std::size_t(i)] = linearEntry(m, i);
        return table;
    }
    const glm::vec2 range = particleColorRange(spec);
    for (int i = 0; i < n; ++i) {
        const float value = range.x + (range.y - range.x) * (float(i) / float(n - 1));
        table[std::size_t(i)] = particleColorAt(spec, value);
    }
    return table;
}

}  // namespace eikon
