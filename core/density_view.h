#pragma once
// What the default scene of a VDB file (`eikon render cache.vdb`, no scene) reads from its
// density grid to place the automatic camera: the voxel size, the box of what shows (density at
// or above kVisibleFraction of the grid's largest value: a file whose every voxel is active
// around a small puff frames the puff, not the grid), the density-weighted centre of that box's
// voxels, and the up axis the file's writer implies.
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "core/bounds.h"

namespace eikon {

constexpr float kVisibleFraction = 0.01f;

struct DensityView {
    float voxelSize = 1.0f;          // the smallest of the density grid's three
    std::optional<Bounds3> visible;  // world box; none when no voxel reaches the fraction
    glm::vec3 centroid{0.0f};        // world; density-weighted, over the visible voxels
    std::optional<glm::vec3> up;     // the writer's up axis, when the file says or implies one
    std::string upReason;            // why, for the one line that states it
};

// Throws eikon::Error naming `path` when it has no density grid (density, smoke, soot,
// density.*) or the grid is not float.
DensityView viewDensity(const std::string& path);

// Whether `path` has a grid the density aliases name (without reading any grid's voxels).
bool holdsDensityGrid(const std::string& path);

// The up axis the file's writer implies (DensityView::up and upReason), for files without
// density: a level set's default scene stands it on a floor below it.
DensityView writerUpOf(const std::string& path);

// "x", "y" or "z" (also "+z"): the axis as a unit vector; nothing for anything else.
std::optional<glm::vec3> parseUpAxis(const std::string& text);

}  // namespace eikon
