#include "sim/container_fill.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/error.h"

namespace eikon {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Heights sampled over the container's bounds to find the cavity, before bisection refines its
// ends; finer than any wall a 128³ render resolves.
constexpr int kProbeHeights = 1024;
constexpr int kBisections = 40;
constexpr double kEndSlack = 1e-9;
// Rings narrower than this fraction of the widest are a rounded floor's point.
constexpr double kTinyRing = 1e-3;

// A piece of the slice at one height: where a triangle crosses the plane, with the horizontal
// part of the triangle's outward normal (which side the material is on).
struct Segment {
    glm::dvec2 a, b;
    glm::dvec2 normal;
};

class Slicer {
public:
    explicit Slicer(const TriangleMesh& mesh) : mesh_(mesh) {}

    std::vector<Segment> at(double y) const {
        std::vector<Segment> out;
        for (const glm::uvec3& t : mesh_.triangles) {
            const glm::dvec3 p[3] = {glm::dvec3(mesh_.positions[t.x]),
                                     glm::dvec3(mesh_.positions[t.y]),
                                     glm::dvec3(mesh_.positions[t.z])};
            // A vertex exactly on the plane counts as above it (a symbolic shift), so every
            // triangle agrees where the slice's polygons close.
            bool above[3];
            for (int i = 0; i < 3; ++i) above[i] = p[i].y >= y;
            if (above[0] == above[1] && above[1] == above[2]) continue;
            glm::dvec2 cut[2];
            int found = 0;
            for (int i = 0; i < 3 && found < 2; ++i) {
                const glm::dvec3& u = p[i];
                const glm::dvec3& v = p[(i + 1) % 3];
                if (above[i] == above[(i + 1) % 3]) continue;
                const double s = (y - u.y) / (v.y - u.y);
                cut[found++] = glm::dvec2(u.x + s * (v.x - u.x), u.z + s * (v.z - u.z));
            }
            const glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
            out.push_back({cut[0], cut[1], glm::dvec2(n.x, n.z)});
        }
        return out;
    }

private:
    const TriangleMesh& mesh_;
};

// The nearest wall a horizontal ray from `origin` along `dir` meets: its distance (infinity when
// none) and whether the ray enters the material there.
struct Hit {
    double distance = std::numeric_limits<double>::infinity();
    bool entering = false;
};

Hit castRay(const std::vector<Segment>& slice, glm::dvec2 origin, glm::dvec2 dir) {
    Hit best;
    for (const Segment& s : slice) {
        const glm::dvec2 e = s.b - s.a;
        const double denom = dir.x * e.y - dir.y * e.x;  // cross(dir, e)
        if (denom == 0.0) continue;                      // parallel: the neighbours count
        const glm::dvec2 w = s.a - origin;
        const double t = (w.x * e.y - w.y * e.x) / denom;
        const double u = (w.x * dir.y - w.y * dir.x) / denom;
        // A ray through a vertex the slice's segments share must not slip between them.
        if (t <= 0.0 || u < -kEndSlack || u > 1.0 + kEndSlack || t >= best.distance) continue;
        best.distance = t;
        best.entering = glm::dot(s.normal, dir) < 0.0;
    }
    return best;
}

enum class Height { Cavity, Open, Solid };

class CavityProbe {
public:
    CavityProbe(const TriangleMesh& mesh, glm::dvec2 axis, int sectors)
        : slicer_(mesh), axis_(axis) {
        for (int a = 0; a < sectors; ++a) {
            const double theta = 2.0 * kPi * a / sectors;
            dirs_.emplace_back(std::cos(theta), std::sin(theta));
        }
    }

    Height classify(double y) const {
        const std::vector<Segment> slice = slicer_.at(y);
        bool allEntering = true;
        for (const glm::dvec2& d : dirs_) {
            const Hit hit = castRay(slice, axis_, d);
            if (!std::isfinite(hit.distance)) return Height::Open;
            allEntering = allEntering && hit.entering;
        }
        return allEntering ? Height::Cavity : Height::Solid;
    }

    // The inner wall's distance from the axis along every ray at height y (a cavity height).
    std::vector<double> radii(double y) const {
        const std::vector<Segment> slice = slicer_.at(y);
        std::vector<double> r;
        for (const glm::dvec2& d : dirs_) r.push_back(castRay(slice, axis_, d).distance);
        return r;
    }

    // Between a cavity height and one that is not, the last cavity height before the change.
    double boundary(double cavity, double other) const {
        for (int i = 0; i < kBisections; ++i) {
            const double mid = 0.5 * (cavity + other);
            (classify(mid) == Height::Cavity ? cavity : other) = mid;
        }
        return cavity;
    }

    const std::vector<glm::dvec2>& dirs() const { return dirs_; }

private:
    Slicer slicer_;
    glm::dvec2 axis_;
    std::vector<glm::dvec2> dirs_;
};

std::string format(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

}  // namespace

LiquidFill fillContainer(const TriangleMesh& container, double fill, const std::string& what,
                         const LiquidFillOptions& options) {
    if (!(fill > 0.0 && fill <= 1.0))
        throw Error(
            what, "fill must be in (0, 1] (a fraction of the cavity's depth), got " + format(fill));
    if (options.rings < 1 || options.sectors < 3)
        throw Error(what, "a liquid needs at least 1 ring and 3 sectors");
    const Bounds3 bounds = boundsOf(container);
    if (!bounds.valid()) throw Error(what, "the container has no triangles");
    const glm::dvec2 axis(0.5 * (double(bounds.min.x) + double(bounds.max.x)),
                          0.5 * (double(bounds.min.z) + double(bounds.max.z)));
    const CavityProbe probe(container, axis, options.sectors);

    // The topmost run of cavity heights, from above.
    const double y0 = bounds.min.y, y1 = bounds.max.y;
    const double dy = (y1 - y0) / kProbeHeights;
    auto probeY = [&](int j) { return y0 + (j + 0.5) * dy; };
    int top = -1;
    for (int j = kProbeHeights - 1; j >= 0 && top < 0; --j)
        if (probe.classify(probeY(j)) == Height::Cavity) top = j;
    if (top < 0)
        throw Error(what, "the container has no cavity around its vertical axis (x = " +
                              format(axis.x) + ", z = " + format(axis.y) +
                              " in its object space) to fill: is it a glass or cup standing "
                              "along +y?");
    int bottom = top;
    while (bottom > 0 && probe.classify(probeY(bottom - 1)) == Height::Cavity) --bottom;

    LiquidFill out;
    out.axis = glm::vec2(axis);
    // Past the bounds' ends nothing is cavity: a cup whose rim is its top bisects up to it.
    const double rimY =
        probe.boundary(probeY(top), top + 1 < kProbeHeights ? probeY(top + 1) : y1 + dy);
    const double bottomY =
        probe.boundary(probeY(bottom), bottom > 0 ? probeY(bottom - 1) : y0 - dy);
    const double levelY = bottomY + fill * (rimY - bottomY);
    out.rim = float(rimY);
    out.bottom = float(bottomY);
    out.level = float(levelY);

    // Rings spaced by 1 − cos: dense where a rounded floor narrows fast, even near the surface.
    std::vector<double> heights;
    std::vector<std::vector<double>> radii;
    double widest = 0.0;
    for (int k = 0; k <= options.rings; ++k) {
        const double s = 1.0 - std::cos(0.5 * kPi * k / options.rings);
        const double y = k == options.rings ? levelY : bottomY + s * (levelY - bottomY);
        std::vector<double> r = probe.radii(y);
        for (double ri : r) {
            if (!std::isfinite(ri))
                throw Error(what, "a ray from the container's axis at height " + format(y) +
                                      " escapes: the cavity is not closed around the axis there");
            widest = std::max(widest, ri);
        }
        heights.push_back(y);
        radii.push_back(std::move(r));
    }
    // A rounded floor starts at a point: rings that small would be degenerate triangles, so the
    // floor's centre joins the first ring of real size instead.
    size_t first = 0;
    auto tiny = [&](const std::vector<double>& r) {
        return *std::max_element(r.begin(), r.end()) < kTinyRing * widest;
    };
    while (first + 1 < radii.size() && tiny(radii[first])) ++first;
    const int rings = int(radii.size() - first);
    const auto sectors = std::uint32_t(options.sectors);
    TriangleMesh& mesh = out.mesh;
    for (size_t k = first; k < radii.size(); ++k)
        for (std::uint32_t a = 0; a < sectors; ++a) {
            const glm::dvec2 p = axis + radii[k][a] * probe.dirs()[a];
            mesh.positions.emplace_back(float(p.x), float(heights[k]), float(p.y));
        }
    const auto floorCentre = std::uint32_t(mesh.positions.size());
    mesh.positions.emplace_back(float(axis.x), float(bottomY), float(axis.y));
    mesh.positions.emplace_back(float(axis.x), float(levelY), float(axis.y));
    const std::uint32_t surfaceCentre = floorCentre + 1;
    // Angles run from +x towards +z, which seen from above (+y) is clockwise: the windings below
    // are outward for that order.
    auto at = [&](int k, std::uint32_t a) { return std::uint32_t(k) * sectors + a % sectors; };
    for (std::uint32_t a = 0; a < sectors; ++a)
        mesh.triangles.emplace_back(floorCentre, at(0, a), at(0, a + 1));
    for (int k = 0; k + 1 < rings; ++k)
        for (std::uint32_t a = 0; a < sectors; ++a) {
            mesh.triangles.emplace_back(at(k, a), at(k + 1, a), at(k + 1, a + 1));
            mesh.triangles.emplace_back(at(k, a), at(k + 1, a + 1), at(k, a + 1));
        }
    for (std::uint32_t a = 0; a < sectors; ++a)
        mesh.triangles.emplace_back(surfaceCentre, at(rings - 1, a + 1), at(rings - 1, a));
    return out;
}

}  // namespace eikon
