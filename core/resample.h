#pragma once
// From sparse OpenVDB fields to the dense render volume.
#include <map>
#include <string>
#include <vector>

#include "core/dense_grid.h"
#include "core/field_registry.h"
#include "core/scene.h"

namespace eikon {

// The render volume a scene asks for: its bounds ("auto": the union of the active world bounds
// of every field a material reads and of the meshes, each mesh grown by its blur radius + 2
// voxels so that its blurred index fits) and resolution ("auto": that of the first field a
// material reads, or kMeshVoxelsAcross along the longest axis when only meshes have materials;
// capped at max_resolution along the longest axis, keeping voxels cubic). `meshBounds` holds the
// world bounds of scene.meshes, in order. Throws eikon::Error when a material's field is missing
// or empty.
RenderVolume chooseRenderVolume(const Scene& scene, const FieldRegistry& fields,
                                const std::vector<Bounds3>& meshBounds = {});

// Voxels along the longest axis of an automatic volume of meshes alone (Sun et al.'s 128³).
constexpr int kMeshVoxelsAcross = 128;

// Which compiled copy of resampleToDense's loop runs. Auto: the AVX2 copy where resampleRunsAvx2,
// else the baseline x86-64 copy; Baseline: that one. Both give BoxSampler::sample's floats to the
// bit.
enum class ResampleCopy { Auto, Baseline };

// Whether ResampleCopy::Auto runs the AVX2 copy here: an x86-64 processor with AVX2, a build
// without sanitizers, and EIKON_CPU_AVX2 not 0 (as for the view, render/frame_renderer.cpp).
bool resampleRunsAvx2();

// Trilinear samples of a scalar field at the centres of the volume's voxels (OpenVDB's
// BoxSampler::sample, to the bit), in parallel with a result that does not depend on the thread
// count. Throws eikon::Error (at the field's origin) when a sample is NaN or infinite.
DenseGrid resampleToDense(const Field& field, const RenderVolume& volume,
                          ResampleCopy copy = ResampleCopy::Auto);

// The refractive index the linear materials make of the resampled fields, n = 1 + Σ f·(ior − 1),
// must be >= 1 at every voxel: a field a material with ior > 1 reads must not go negative there.
// A Gladstone–Dale material's field (a temperature excess) must stay above absolute zero,
// −ambient_kelvin; its n < 1 where the air is hot is meant (n is relative to the ambient air).
// Throws eikon::Error at the first voxel (x fastest) where either fails, naming the material's
// JSON path, its field, where the field came from, the position and n or the value. `dense`
// holds, by field name, the grid of every field a material reads.
void checkRefractiveIndex(const Scene& scene, const FieldRegistry& fields,
                          const std::map<std::string, DenseGrid>& dense);

}  // namespace eikon
