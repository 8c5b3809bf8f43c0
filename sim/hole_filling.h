#pragma once
// Closing small holes in a triangle mesh (scanner holes, a missing cap) so that it can be a
// closed refractive object.
//
// Method: the minimum-area triangulation of each hole's boundary loop (Barequet & Sharir 1995, the
// first step of Liepa 2003, "Filling holes in meshes"), by dynamic programming over the loop's
// vertices: O(n³) time, O(n²) memory, no new vertices. Chosen over a fan around the centroid,
// which folds over wherever the loop is not star-shaped around its centroid (measured: 3 of the
// 5 holes of stanford-bunny.obj), and over ear clipping, which needs the non-planar loop
// projected to a plane where it may not stay simple. The triangulation exists for every loop and
// uses each boundary edge once, backwards, so the patch is wound like the surface around it and
// the result is watertight. Liepa's refinement and fairing of the patch are not done: the patch
// is flat-ish and coarse, which suits the small holes this is for.
#include <cstddef>
#include <vector>

#include "core/triangle_mesh.h"

namespace eikon {

// Holes above this many edges are never filled (the cost grows as n³).
constexpr std::size_t kMaxFillableHoleEdges = 2000;

struct FilledHole {
    std::size_t edges = 0;      // boundary edges around it
    std::size_t triangles = 0;  // added (edges − 2)
    double area = 0.0;          // of the patch, in scene units²
};

struct HoleFilling {
    std::vector<FilledHole> filled;
    std::vector<std::size_t> tooLarge;   // edges of holes above the limit
    std::vector<std::size_t> notSimple;  // edges of holes that are not one simple loop
    std::size_t leftOpen() const { return tooLarge.size() + notSimple.size(); }
};

// Fills every hole of at most `maxEdges` boundary edges (0 fills none). Triangles are appended;
// positions and existing triangles are untouched.
HoleFilling closeHoles(TriangleMesh& mesh, std::size_t maxEdges);

}  // namespace eikon
