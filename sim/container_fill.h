#pragma once
// The liquid in a container: the closed mesh of what fills a glass, cup or bowl up to a level,
// made from the container's own triangles (the wine in the shared wine glass).
//
// The container stands along its object-space y axis, through the centre of its bounds in x and
// z. At a height y the horizontal slice of the container is a set of segments; rays from the
// axis outward in `sectors` directions find the inner wall. A height is in the cavity when every
// ray first meets a wall it enters (the wall's outward normal faces the axis); it is open when a
// ray escapes, and solid when the axis itself is inside the container's material. The cavity
// filled is the topmost run of cavity heights: its bottom is where the axis meets the material
// (the bowl's floor), its rim where rays start to escape (or a lid starts). The liquid is a
// stack of rings on the inner wall from the bottom to bottom + fill·(rim − bottom), closed by
// flat caps: it touches the wall, which is what a liquid does, so the overlap rule of the
// renderer (a later mesh displaces earlier ones) gives the wall's voxels to the liquid listed
// after the glass only where both cover them.
//
// What it cannot fill: the parts of a cavity the axis cannot see along a horizontal ray (a
// teapot's spout), and cavities not around the vertical axis; no meniscus.
#include <string>

#include <glm/vec2.hpp>

#include "core/triangle_mesh.h"

namespace eikon {

struct LiquidFillOptions {
    int rings = 48;    // heights from the bottom to the surface, denser near the bottom
    int sectors = 96;  // rays (and vertices) around each ring
};

struct LiquidFill {
    TriangleMesh mesh;     // closed, wound outward, in the container's object space
    glm::vec2 axis{0.0f};  // x, z of the vertical axis
    float bottom = 0.0f;   // y where the axis meets the cavity's floor
    float rim = 0.0f;      // y where the cavity ends (rays escape, or a lid begins)
    float level = 0.0f;    // y of the liquid's surface
};

// Fills `container`'s cavity to `fill` of its depth, fill in (0, 1]. Throws eikon::Error at
// `what` (the scene's JSON path of the liquid) when the container has no cavity around its axis
// or fill is out of range.
LiquidFill fillContainer(const TriangleMesh& container, double fill, const std::string& what,
                         const LiquidFillOptions& options = {});

}  // namespace eikon
