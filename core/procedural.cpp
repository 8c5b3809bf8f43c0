#include "core/procedural.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "core/bspline_edge.h"
#include "core/error.h"
#include "core/memory_limit.h"
#include "core/scene.h"
#include "core/vdb_grid_check.h"

namespace eikon {
namespace {

openvdb::math::Transform::Ptr cellAlignedTransform(float h) {
    auto xform = openvdb::math::Transform::createLinearTransform(double(h));
    xform->postTranslate(openvdb::Vec3d(0.5 * h));
    return xform;
}

double maxComponent(glm::dvec3 v) {
    return std::max(v.x, std::max(v.y, v.z));
}

// Signed distance to the shape's surface: negative inside.
double signedDistance(const SourceSpec& src, glm::dvec3 p) {
    if (src.type == SourceType::Sphere)
        return glm::length(p - glm::dvec3(src.center)) - double(src.radius);
    // A box with rounded edges is the box shrunk by the radius, then grown by it.
    const glm::dvec3 lo(src.boxMin), hi(src.boxMax);
    const double r = src.cornerRadius;
    const glm::dvec3 q = glm::abs(p - 0.5 * (lo + hi)) - (0.5 * (hi - lo) - r);
    return glm::length(glm::max(q, 0.0)) + std::min(maxComponent(q), 0.0) - r;
}

// The shape's axis-aligned extent.
void shapeExtent(const SourceSpec& src, glm::dvec3& lo, glm::dvec3& hi) {
    if (src.type == SourceType::Sphere) {
        lo = glm::dvec3(src.center) - double(src.radius);
        hi = glm::dvec3(src.center) + double(src.radius);
    } else {
        lo = glm::dvec3(src.boxMin);
        hi = glm::dvec3(src.boxMax);
    }
}

// The profile at p, or where it meets the surface for points outside.
double profileAt(const SourceSpec& src, glm::dvec3 p) {
    switch (src.profile) {
        case SourceProfile::Uniform:
            break;
        case SourceProfile::Luneburg:
            return double(src.value) *
                   luneburgExcessIndex(glm::length(p - glm::dvec3(src.center)), src.radius);
        case SourceProfile::Ramp: {
            glm::dvec3 lo, hi;
            shapeExtent(src, lo, hi);
            const int a = src.rampAxis;
            const double t = std::clamp((p[a] - lo[a]) / (hi[a] - lo[a]), 0.0, 1.0);
            return double(src.rampFrom) + (double(src.rampTo) - double(src.rampFrom)) * t;
        }
    }
    return double(src.value);
}

// The voxels makeProceduralField visits: the shape's extent grown by its falloff, clipped, one
// voxel of margin. False when the clip box leaves nothing.
bool proceduralVoxelBox(const SourceSpec& src, glm::ivec3& i0, glm::ivec3& i1) {
    if (src.type != SourceType::Sphere && src.type != SourceType::Box)
        throw Error(src.jsonPath, "not a procedural source (sphere or box)");
    glm::dvec3 lo, hi;
    shapeExtent(src, lo, hi);
    lo -= double(src.falloff);
    hi += double(src.falloff);
    // The B-spline edge filter reaches 2h past the falloff (edgeWeight).
    if (resolvedEdgeFilter(src) == EdgeFilter::BSpline) {
        lo -= 2.0 * double(src.voxelSize);
        hi += 2.0 * double(src.voxelSize);
    }
    if (src.clip) {
        lo = glm::max(lo, glm::dvec3(src.clip->min));
        hi = glm::min(hi, glm::dvec3(src.clip->max));
    }
    if (glm::any(glm::greaterThanEqual(lo, hi))) return false;
    const double h = src.voxelSize;
    // Voxel indices are ints; the scene reader keeps shapes far closer (kMaxProceduralVoxels).
    constexpr double kMaxIndex = double(1 << 30);
    if (glm::any(glm::greaterThan(glm::abs(glm::max(glm::abs(lo), glm::abs(hi)) / h),
                                  glm::dvec3(kMaxIndex))))
        throw Error(src.jsonPath, "the shape lies more than 2^30 voxels from the origin");
    i0 = glm::ivec3(glm::floor(lo / h)) - 1;
    i1 = glm::ivec3(glm::ceil(hi / h)) + 1;
    return true;
}

bool insideClip(const SourceSpec& src, glm::dvec3 p) {
    if (!src.clip) return true;
    const glm::dvec3 lo(src.clip->min), hi(src.clip->max);
    return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x < hi.x && p.y < hi.y && p.z < hi.z;
}

}  // namespace

double luneburgExcessIndex(double r, double radius) {
    const double s = std::min(r / radius, 1.0);
    return std::sqrt(2.0 - s * s) - 1.0;
}

namespace {

// The edge e (1 inside, 1 − s/falloff over the falloff, 0 beyond; a step when falloff is 0) at
// signed distance d averaged along the normal with the cubic B-spline B(s/h)/h. With
// ramp(x) = ∫ max(x − s, 0) B(s) ds, e = 1 − (clamp(d, 0, F))/F = 1 − (max(d, 0) − max(d − F, 0))/F
// averages to 1 − (h/F)(ramp(d/h) − ramp((d − F)/h)), and to 1 − ∫_{−∞}^{d/h} B as F → 0.
double bsplineAveragedEdge(double d, double falloff, double h) {
    // A falloff far below the filter's width is a step to 1e-6 (and the difference of ramps,
    // divided by it, would be rounding).
    if (falloff < 1e-6 * h) return 1.0 - cubicBSplineCdf(d / h);
    return 1.0 - (h / falloff) * (cubicBSplineRamp(d / h) - cubicBSplineRamp((d - falloff) / h));
}

// The same edge averaged across the voxel's width along the normal (a box of width h).
// G(s) = ∫ e up to s, less the part inside.
double boxAveragedEdge(double d, double falloff, double h) {
    const auto G = [falloff](double s) {
        if (s <= 0.0) return s;
        if (s >= falloff) return 0.5 * falloff;
        return s - s * s / (2.0 * falloff);
    };
    return (G(d + 0.5 * h) - G(d - 0.5 * h)) / h;
}

}  // namespace

EdgeFilter resolvedEdgeFilter(const SourceSpec& src) {
    if (src.edgeFilter != EdgeFilter::ShapeDefault) return src.edgeFilter;
    return src.type == SourceType::Sphere ? EdgeFilter::BSpline : EdgeFilter::Box;
}

double edgeWeight(double d, double falloff, double h, EdgeFilter filter, double sphereRadius) {
    const bool bspline = filter == EdgeFilter::BSpline;
    // A sphere bends away from its tangent plane by t²/(2ρ) at tangential offset t: over the
    // filter's two tangential directions (mean t² = h²/12 each for the box, h²/3 for the
    // B-spline) the plane's distance grows by h²/(12ρ) or h²/(3ρ) on average.
    if (sphereRadius > 0.0)
        d += h * h / ((bspline ? 3.0 : 12.0) * std::max(sphereRadius + d, 0.5 * h));
    const double w = bspline ? bsplineAveragedEdge(d, falloff, h) : boxAveragedEdge(d, falloff, h);
    // A face on a voxel boundary (a box on multiples of h) puts its neighbours' centres h/2
    // away up to the float rounding of the scene's numbers (0.9f is 24 · 0.0375f less 1.6e-6 h):
    // they are wholly in or out, not a hair in (which would add a layer of active voxels and move
    // every value off the shape's). 1e-4 of a voxel's coverage is below anything a picture shows.
    constexpr double kWhole = 1e-4;
    if (w < kWhole) return 0.0;
    if (w > 1.0 - kWhole) return 1.0;
    return w;
}

double proceduralValue(const SourceSpec& src, glm::dvec3 p) {
    if (!insideClip(src, p)) return 0.0;
    const double d = signedDistance(src, p);
    // The Luneburg profile falls to 0 at the surface already: no step to average.
    if (src.profile == SourceProfile::Luneburg) return d <= 0.0 ? profileAt(src, p) : 0.0;
    const double w =
        edgeWeight(d, double(src.falloff), double(src.voxelSize), resolvedEdgeFilter(src),
                   src.type == SourceType::Sphere ? double(src.radius) : 0.0);
    return w > 0.0 ? profileAt(src, p) * w : 0.0;
}

double proceduralFieldBytes(const SourceSpec& src) {
    glm::ivec3 i0, i1;
    if (!proceduralVoxelBox(src, i0, i1)) return 0.0;
    // The nodes of OpenVDB's 5-4-3 tree the voxel box touches: 8³ leaves, 128³ and 4096³
    // internal nodes (a shape astride the origin touches up to 8 of each kind). Partly covered
    // nodes cost as much as full ones. A sphere's leaves fill about π/6 of its box (a quarter
    // more for the leaves its surface cuts); its internal nodes are counted as the box's.
    // Voxel centres in the margin the loop adds lie outside the extent and stay unset.
    const glm::dvec3 first = glm::dvec3(i0) + 1.0, last = glm::dvec3(i1) - 2.0;
    const auto nodesAcross = [&](int a, double width) {
        return std::floor(last[a] / width) - std::floor(first[a] / width) + 1.0;
    };
    double nodes[3] = {1.0, 1.0, 1.0};
    const double widths[3] = {8.0, 128.0, 4096.0};
    for (int level = 0; level < 3; ++level)
        for (int a = 0; a < 3; ++a) nodes[level] *= nodesAcross(a, widths[level]);
    constexpr double kSphereFill = 3.14159265358979 / 6.0 * 1.25;
    const double fill = src.type == SourceType::Sphere ? std::min(1.0, kSphereFill) : 1.0;
    VdbTreeNodeCounts counts;
    counts.leaves = std::uint64_t(std::ceil(fill * nodes[0]));
    counts.internal[0] = std::uint64_t(nodes[1]);
    counts.internal[1] = std::uint64_t(nodes[2]);
    VdbTreeLayout floats;
    vdbTreeLayoutFor("Tree_float_5_4_3", false, floats);
    return counts.bytes(floats);
}

void checkProceduralFieldMemory(const SourceSpec& src, const std::string& where) {
    double bytes = 0.0;
    try {
        bytes = proceduralFieldBytes(src);
    } catch (const Error& e) {
        throw Error(where, e.reason());
    }
    const std::string shape = src.type == SourceType::Sphere ? "sphere" : "box";
    std::ostringstream what;
    what << "the " << shape << "'s field at voxel size " << src.voxelSize;
    checkMemory(where, bytes, what.str(), "use a larger voxel_size");
}

openvdb::FloatGrid::Ptr makeProceduralField(const SourceSpec& src) {
    glm::ivec3 i0, i1;
    const bool any = proceduralVoxelBox(src, i0, i1);
    const float h = src.voxelSize;
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setTransform(cellAlignedTransform(h));
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    if (!any) return grid;  // clipped away
    auto acc = grid->getAccessor();
    for (int k = i0.z; k <= i1.z; ++k)
        for (int j = i0.y; j <= i1.y; ++j)
            for (int i = i0.x; i <= i1.x; ++i) {
                // The centre as the grid's transform computes it, so that samples there return
                // exactly this value.
                const glm::dvec3 p = (glm::dvec3(i, j, k) + 0.5) * double(h);
                const float v = float(proceduralValue(src, p));
                if (v != 0.0f) acc.setValue(openvdb::Coord(i, j, k), v);
            }
    return grid;
}

openvdb::FloatGrid::Ptr makeSphereField(glm::vec3 center, float radius, float value, float falloff,
                                        float voxelSize) {
    SourceSpec src;
    src.type = SourceType::Sphere;
    src.center = center;
    src.radius = radius;
    src.value = value;
    src.falloff = falloff;
    src.voxelSize = voxelSize;
    return makeProceduralField(src);
}

openvdb::FloatGrid::Ptr makeBoxField(glm::vec3 boxMin, glm::vec3 boxMax, float value, float falloff,
                                     float voxelSize) {
    SourceSpec src;
    src.type = SourceType::Box;
    src.boxMin = boxMin;
    src.boxMax = boxMax;
    src.value = value;
    src.falloff = falloff;
    src.voxelSize = voxelSize;
    return makeProceduralField(src);
}

}  // namespace eikon
