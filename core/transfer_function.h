#pragma once
// Transfer functions: a material reads amount(f), a piecewise-linear map of its field's value, in
// place of f (scientific volume rendering's classification: a CT's value to how much of a tissue
// is there, so that enamel, dentin and soft tissue become separate materials of one scan). The map
// is applied at the render volume's voxel centres, before any interpolation (pre-classification),
// so every light-transport method, the ∇n volume and the octree read the mapped values as they
// read any field, and the GPU and the CPU twin read the same bytes.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/dense_grid.h"
#include "core/scene.h"

namespace eikon {

// At most this many control points a transfer function.
constexpr std::size_t kMaxTransferPoints = 16;

// What is wrong with `points` as a transfer function, "" when nothing is: fewer than 2 or more
// than kMaxTransferPoints points, values not finite or not strictly increasing ("point 3: value
// 0.5 is not above the one before, 0.5"), an amount negative or not finite, or amount(0) ≠ 0
// (where the field has no voxels the render volume reads 0, and the whole of it would fill).
// The scene's "transfer" and the library's Material::transfer share it.
std::string transferFunctionProblem(const std::vector<glm::vec2>& points);

// amount(f) through `points` ((value, amount), values strictly increasing): linear between
// neighbouring points, the first amount below the first value, the last above the last. Empty
// points: f itself.
float transferAmount(const std::vector<glm::vec2>& points, float f);

// The name of the render volume slot material `m` reads: its field's name, or, with a transfer
// function, "<field>|<material>" (the field mapped through the material's function).
std::string materialSlotName(const MaterialSpec& m);

// The material of `scene` whose transfer function makes slot `slotName`; null for a slot that is
// a field itself.
const MaterialSpec* transferMaterialOfSlot(const Scene& scene, const std::string& slotName);

// `field`'s values mapped through `points`, voxel by voxel (in parallel, the same bytes for any
// thread count), as slot `slotName` at version `version`.
DenseGrid applyTransfer(const DenseGrid& field, const std::vector<glm::vec2>& points,
                        const std::string& slotName, std::uint64_t version);

}  // namespace eikon
