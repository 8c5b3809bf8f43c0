#include <tbb/blocked_range.h>
#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>

#include <optional>

#include "core/error.h"
#include "render/constant_bricks.h"
#include "render/empty_bricks.h"
#include "render/receiver_map.h"
#include "render/view_pass.h"
#include "render/volume_kernels_cpu.h"

// The per-pixel loop is compiled a second time for x86-64 with AVX2, with everything it calls
// inlined into it (flatten), and runs that way where the processor has AVX2. No FMA is enabled,
// so no a·b + c is contracted: both copies do the same IEEE operations and give the same bytes
// (tests/render/test_view_isa.cpp). The AVX2 copy took 0.85× the time of the view at 128³
// (BENCHMARKS.md, "AVX2"). It is two copies, one for straight rays and one for curved, each with
// the other kind's code left out (renderPixelOf's `curved` a constant): the Houdini smoke's
// straight rays took 0.91-0.93× the time of one copy with both (BENCHMARKS.md). Not under the
// sanitizers, where the flattened copies would take many minutes to compile, nor off x86-64.
//
// Where the processor has AVX-512 (F and VL) the view runs a third pair of copies compiled for it:
// its 32 vector registers hold scalar floats the AVX2 copy (16 registers) spilled to the stack,
// about 120 stores a step (callgrind): houdini_smoke's view took 0.93× the AVX2 copy's time on one
// core (BENCHMARKS.md). GCC's AVX-512 brings FMA with it, so this file is compiled with
// -ffp-contract=off (render/CMakeLists.txt): no a·b + c is fused, and the copies give the same
// bytes.
#if defined(__x86_64__) && defined(__GNUC__) && defined(__OPTIMIZE__) && \
    !defined(__SANITIZE_ADDRESS__)
#define EK_VIEW_AVX2 1
#endif

namespace eikon {
namespace {

// The pixels of a tile; `curved` is curvedRays(params), a constant where the copies below call it.
#define EK_RENDER_TILE_PIXELS(curved)                                    \
    for (int y = tile.rows().begin(); y != tile.rows().end(); ++y) {     \
        for (int x = tile.cols().begin(); x != tile.cols().end(); ++x) { \
            image.at(x, y) = kernel.renderPixelOf(x, y, curved);         \
        }                                                                \
    }

void renderTileBaseline(shared::ViewKernelCpu& kernel, Image& image,
                        const tbb::blocked_range2d<int>& tile) {
    EK_RENDER_TILE_PIXELS(shared::curvedRays(kernel.params));
}

#ifdef EK_VIEW_AVX2
// Two functions, not a template, and the loop by a macro: GCC inlined neither instance of a
// template into them.
[[gnu::target("avx2"), gnu::flatten]] void renderStraightTileAvx2(
    shared::ViewKernelCpu& kernel, Image& image, const tbb::blocked_range2d<int>& tile) {
    EK_RENDER_TILE_PIXELS(false);
}

[[gnu::target("avx2"), gnu::flatten]] void renderCurvedTileAvx2(
    shared::ViewKernelCpu& kernel, Image& image, const tbb::blocked_range2d<int>& tile) {
    EK_RENDER_TILE_PIXELS(true);
}

[[gnu::target("avx2,avx512f,avx512vl"), gnu::flatten]] void renderStraightTileAvx512(
    shared::ViewKernelCpu& kernel, Image& image, const tbb::blocked_range2d<int>& tile) {
    EK_RENDER_TILE_PIXELS(false);
}

[[gnu::target("avx2,avx512f,avx512vl"), gnu::flatten]] void renderCurvedTileAvx512(
    shared::ViewKernelCpu& kernel, Image& image, const tbb::blocked_range2d<int>& tile) {
    EK_RENDER_TILE_PIXELS(true);
}
#endif

}  // namespace

bool viewCpuHasAvx2() {
#ifdef EK_VIEW_AVX2
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

bool viewCpuHasAvx512() {
#ifdef EK_VIEW_AVX2
    return viewCpuHasAvx2() && __builtin_cpu_supports("avx512f") &&
           __builtin_cpu_supports("avx512vl");
#else
    return false;
#endif
}

Image renderViewCpu(const ViewSetup& setup, const std::vector<const DenseGrid*>& slotGrids,
                    const TransportOutputCpu& light, const std::vector<glm::vec4>& gradient,
                    const Image* environment, const ChannelGradientsCpu* channelGradients,
                    const ViewCpuOptions& options) {
    const shared::GpuViewParams& p = setup.params;
    if (slotGrids.size() != setup.slotFields.size())
        throw Error("view pass (CPU)", "expected " + std::to_string(setup.slotFields.size()) +
                                           " field grids, got " + std::to_string(slotGrids.size()));
    if (viewReadsLightTransmittance(setup) &&
        int(light.lightTransmittance.size()) != shared::lightCount(p))
        throw Error("view pass (CPU)", "the light volumes were not computed");
    const size_t voxels = size_t(p.resolution.x) * size_t(p.resolution.y) * size_t(p.resolution.z);
    if (shared::curvedRays(p) && gradient.size() != voxels)
        throw Error("view pass (CPU)", "curved rays need the gradient volume");
    const bool dispersed = shared::curvedRays(p) && dispersesView(setup);
    if (dispersed && (!channelGradients || channelGradients->red.size() != voxels ||
                      channelGradients->blue.size() != voxels))
        throw Error("view pass (CPU)",
                    "dispersion needs the red and blue channels' gradient volumes");
    if (shared::readsFluence(p)) {
        if (!light.fluence || !light.direction || light.fluenceVoxels != voxels)
            throw Error("view pass (CPU)", "lighting through the fluence needs its volumes");
        if (light.receiverTexels != receiverMapTexels(p))
            throw Error("view pass (CPU)", "the receiver map was not computed");
    }
    if (shared::environmentType(p) == EK_ENVIRONMENT_IMAGE &&
        (!environment || environment->width != shared::environmentWidth(p) ||
         environment->height != shared::environmentHeight(p)))
        throw Error("view pass (CPU)", "the environment image was not loaded");
    for (size_t s = 0; s < slotGrids.size(); ++s) {
        const glm::ivec3 res = slotGrids[s]->volume.resolution;
        if (res != glm::ivec3(p.resolution.x, p.resolution.y, p.resolution.z))
            throw Error("view pass (CPU)",
                        "field '" + slotGrids[s]->field + "' was resampled on a different volume");
    }
    std::vector<const float*> fields;
    for (const DenseGrid* grid : slotGrids) fields.push_back(grid->values.data());
    // Every kernel reads the same volumes; under dispersion each channel's its own ∇n, and so has
    // its own empty bricks.
    const auto attach = [&](shared::ViewKernelCpu& kernel, const std::vector<glm::vec4>& grad,
                            EmptyBricks& bricks, std::optional<ConstantBricks>& constant) {
        if (options.skipEmptySpace) {
            bricks = findEmptyBricks(glm::ivec3(p.resolution), fields,
                                     shared::curvedRays(p) ? grad.data() : nullptr);
            // Null where none is empty: curved steps then skip looking (anyEmptyBricks).
            kernel.emptyBricks = bricks.emptyCount() > 0 ? bricks.empty.data() : nullptr;
            kernel.emptyBrickCount = bricks.count;
        }
        if (options.constantBricks) {
            constant.emplace(glm::ivec3(p.resolution));
            // Straight steps take no sample in an empty brick. Curved ones do, where a step
            // crosses a brick's face (only a step that starts and ends in one is skipped): the
            // glass view at 128³ took 4597 -> 5086 ms on one core with those left out too.
            const bool leaveOutEmpty = options.skipEmptySpace && !shared::curvedRays(p);
            if (leaveOutEmpty) constant->leaveOut(bricks.empty);
            for (size_t s = 0; s < fields.size(); ++s) constant->addField(int(s), fields[s]);
            for (size_t l = 0; l < light.lightTransmittance.size(); ++l)
                constant->addVolume(EK_MAX_MATERIALS + int(l), light.lightTransmittance[l]);
            if (shared::curvedRays(p)) constant->addVolume(EK_GRADIENT_SLOT, grad.data());
            if (shared::readsFluence(p)) {
                constant->addVolume(EK_FLUENCE_SLOT, light.fluence);
                constant->addVolume(EK_FLUENCE_DIRECTION_SLOT, light.direction);
            }
            // Every sample pays for the lookup; only the samples in constant bricks gain. Where no
            // slot is constant over an eighth of the bricks the view samples, the lookups cost
            // more than they save (houdini_smoke's view: 4 %, BENCHMARKS.md), and the kernel gets
            // none: the same floats either way.
            const size_t sampled =
                constant->mask.size() - (leaveOutEmpty ? bricks.emptyCount() : size_t(0));
            bool pays = false;
            for (int slot = 0; slot < kVolumeSlotCount; ++slot)  // slots not added count 0
                pays = pays || (constant->column[slot] >= 0 &&
                                constant->constantCount(slot) * 8 >= sampled);
            kernel.constantBricks = pays ? &*constant : nullptr;
        }
        for (size_t l = 0; l < light.lightTransmittance.size(); ++l)
            kernel.lights[l] = light.lightTransmittance[l];
        if (shared::curvedRays(p)) kernel.gradient = grad.data();
        if (shared::readsFluence(p)) {
            kernel.fluence = light.fluence;
            kernel.fluenceDirection = light.direction;
            kernel.receiverMap = light.receiverMap;
        }
        if (shared::environmentType(p) == EK_ENVIRONMENT_IMAGE)
            kernel.environment = environment->pixels.data();
        for (size_t s = 0; s < slotGrids.size(); ++s)
            kernel.fields[s] = slotGrids[s]->values.data();
    };
    Image image(p.image.x, p.image.y);
    // In tiles of 8×8 pixels: neighbouring rays read the same voxels, so a tile finds most of
    // them in the cache (rows of 640 did not: the view at 128³ took 1.05× the time).
    const auto forEachTile = [&](const auto& renderTile) {
        tbb::parallel_for(tbb::blocked_range2d<int>(0, image.height, 8, 0, image.width, 8),
                          renderTile, tbb::simple_partitioner());
    };
    if (!dispersed) {
        shared::ViewKernelCpu kernel{{p}};
        EmptyBricks bricks;
        std::optional<ConstantBricks> constant;
        attach(kernel, gradient, bricks, constant);
        const bool avx2 = options.avx2 && viewCpuHasAvx2();
        const bool avx512 = avx2 && options.avx512 && viewCpuHasAvx512();
        const bool curved = shared::curvedRays(p);
        forEachTile([&](const tbb::blocked_range2d<int>& tile) {
#ifdef EK_VIEW_AVX2
            if (avx512 && curved) return renderCurvedTileAvx512(kernel, image, tile);
            if (avx512) return renderStraightTileAvx512(kernel, image, tile);
            if (avx2 && curved) return renderCurvedTileAvx2(kernel, image, tile);
            if (avx2) return renderStraightTileAvx2(kernel, image, tile);
#endif
            renderTileBaseline(kernel, image, tile);
        });
        return image;
    }
    // Dispersion: each channel's rays bend with its own n (shaders/shared/view_march.h,
    // renderPixelChannel), red, green, blue in turn as the GPU's three dispatches add them.
    const shared::GpuViewParams red = channelViewParams(setup, 0);
    const shared::GpuViewParams green = channelViewParams(setup, 1);
    const shared::GpuViewParams blue = channelViewParams(setup, 2);
    shared::ViewKernelCpu kernels[3] = {{{red}}, {{green}}, {{blue}}};
    EmptyBricks bricks[3];
    std::optional<ConstantBricks> constant[3];
    attach(kernels[0], channelGradients->red, bricks[0], constant[0]);
    attach(kernels[1], gradient, bricks[1], constant[1]);
    attach(kernels[2], channelGradients->blue, bricks[2], constant[2]);
    forEachTile([&](const tbb::blocked_range2d<int>& tile) {
        for (int y = tile.rows().begin(); y != tile.rows().end(); ++y)
            for (int x = tile.cols().begin(); x != tile.cols().end(); ++x) {
                glm::vec4 pixel(0.0f);
                for (shared::ViewKernelCpu& kernel : kernels)
                    pixel = kernel.renderPixelChannel(x, y, pixel);
                image.at(x, y) = pixel;
            }
    });
    return image;
}

}  // namespace eikon
