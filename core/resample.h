#pragma once
// From sparse OpenVDB fields to the dense render volume.
#include "core/dense_grid.h"
#include "core/field_registry.h"
#include "core/scene.h"

namespace eikon {

// The render volume a scene asks for: its bounds ("auto": the union of the active world bounds
// of every field a material reads) and resolution ("auto": that of the first such field, capped
// at max_resolution along the longest axis, keeping voxels cubic). Throws eikon::Error when a
// material's field is missing or empty.
RenderVolume chooseRenderVolume(const Scene& scene, const FieldRegistry& fields);

// Trilinear samples of a scalar field at the centres of the volume's voxels, in parallel with a
// result that does not depend on the thread count.
DenseGrid resampleToDense(const Field& field, const RenderVolume& volume);

}  // namespace eikon
