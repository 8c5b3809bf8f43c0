#pragma once
// Procedural shapes written into fields: the test and demo scenes use them where a closed-form
// answer is wanted (a homogeneous cube of known extinction and side, a Luneburg lens, a slab
// whose index grows linearly with height).
//
// One mechanism for every shape: a signed distance d(p) to the surface (sphere, box, box with
// rounded edges), a value inside it given by a profile (uniform, Luneburg, linear ramp), a linear
// falloff outside it, and an optional clip box:
//   f(p) = P(p)                      d(p) <= 0
//        = P(p) · (1 − d/falloff)     0 < d(p) < falloff
//        = 0                          otherwise, and wherever p is outside the clip box,
// where outside the shape the profile P is taken where it is at the surface (the ramp's
// coordinate clamped to the shape's extent, the Luneburg radius clamped to R).
#include <string>

#include <openvdb/openvdb.h>

#include <glm/vec3.hpp>

namespace eikon {

struct SourceSpec;
enum class EdgeFilter;

// Grids whose voxel i covers [i·h, (i+1)·h) in world space (cell centres at (i + ½)·h), so that a
// box whose faces lie on multiples of h is covered exactly. Each voxel holds f at its centre.
// `src` is a Sphere or Box source; throws eikon::Error for any other type.
openvdb::FloatGrid::Ptr makeProceduralField(const SourceSpec& src);
// An upper bound of the bytes makeProceduralField's grid takes (core/memory_limit.h), computed
// from the shape alone, before anything is allocated.
double proceduralFieldBytes(const SourceSpec& src);
// Throws eikon::Error at `where` (a file and JSON pointer) when that exceeds the memory limit.
void checkProceduralFieldMemory(const SourceSpec& src, const std::string& where);

// f at a world point, computed in double: what makeProceduralField stores at a voxel centre
// (rounded to float): the profile times edgeWeight of the point's signed distance.
double proceduralValue(const SourceSpec& src, glm::dvec3 p);

// The shape's edge as a voxel of size h holds it: the edge e (1 inside, falling linearly to 0
// over `falloff` outside, a step when falloff is 0) at signed distance d of the voxel's centre
// (negative inside), averaged along the surface's normal by `filter` (Box or BSpline, resolved
// already):
//   Box      across the voxel's width: with falloff 0 on a flat surface the voxel's coverage,
//            clamp(1/2 − d/h, 0, 1). Exact for faces on the grid's planes; on a curved surface
//            its kinks alias: a glass ball's caustic carried rings and a cross (issue 15).
//   BSpline  with the cubic B-spline B(s/h)/h (support ±2h, variance h²/3): with falloff 0,
//            1 − ∫_{−∞}^{d/h} B. Nearly band-limited, so the sampled field's ∇n does not alias;
//            its integer shifts sum to 1, so a flat edge's samples still sum to its volume.
// On a sphere of radius `sphereRadius` (0: a flat surface) d first grows by the surface's mean
// bend away from its tangent plane under the filter, h²/(12 r) (Box) or h²/(3 r) (BSpline), so
// that a sphere's field keeps its volume. Either way the field has its 1/2 level on the surface to
// a fraction of a voxel and ∇n normal to it. Sampling the step at voxel centres instead terraced
// the surface: a glass ball's caps were flat for several voxels with ∇n straight down, and the
// ball did not focus (issue 15).
double edgeWeight(double d, double falloff, double h, EdgeFilter filter, double sphereRadius = 0.0);

// The filter a source's edge gets: its own, or its shape's default (core/scene.h, EdgeFilter).
EdgeFilter resolvedEdgeFilter(const SourceSpec& src);

// The Luneburg profile's shape at radius r of a sphere of radius R: sqrt(2 − (r/R)²) − 1 for
// r <= R, 0 beyond (continuous at R). 1 + this is the Luneburg lens's index.
double luneburgExcessIndex(double r, double radius);

// Uniform shapes: `value` inside, falling linearly to zero over `falloff` scene units outside
// (0: a sharp edge).
openvdb::FloatGrid::Ptr makeSphereField(glm::vec3 center, float radius, float value, float falloff,
                                        float voxelSize);
openvdb::FloatGrid::Ptr makeBoxField(glm::vec3 boxMin, glm::vec3 boxMax, float value, float falloff,
                                     float voxelSize);

}  // namespace eikon
