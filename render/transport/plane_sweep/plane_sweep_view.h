#pragma once
// The plane sweep's interleaved view (Magnus's thesis, ch. 5.2, Algorithm 1): the view rays
// advance through the volume with the light planes, each shading its samples from the last few
// slices swept (eight), so no fluence volume is stored: what the light needs grows with the image
// and the plane, not with the volume, and a light move costs a sweep and a view like a camera move.
//
// The planes are the volume's slices across the axis the camera looks most along (from the
// camera to the volume's centre), the thesis's planes perpendicular to the view, kept to the
// volume's axes as the light sweep is. Every view ray crosses them front to back, and every
// light must cross them forward too (light from the camera's side, as in the thesis).
//
// Each view ray is the view pass's own (shaders/shared/view_march.h: curvedRayAdvance,
// straightRayAdvance), stopped where its next sample would read a slice not swept yet
// (viewSampleReady) and taken on when it is. Its samples read the slices held exactly as
// they would read the whole volume, so where the sweeps cross the same planes the image is the
// volume path's to the bit; what differs: reflections at sharp surfaces are seen in the
// environment (the view pass traces two through the volume, back toward the camera, against
// the sweep). A ray that meets a receiver keeps the hit (receiverDeferred) and is shaded once
// the receiver's light is complete: a voxel receiver's when the slices in front of it are held,
// a plane receiver's map after the last plane (it fills as the planes pass it).
//
// CPU twin only (its GPU port keeps the ray states in buffers between dispatches; not yet).
#include <cstdint>
#include <string>
#include <vector>

#include "render/image.h"
#include "render/transport/plane_sweep/plane_sweep_cpu.h"

namespace eikon {

class GpuStageTimer;

// The planes the interleaved view sweeps: across the axis the camera looks most along.
SweepAxis interleavedSweepAxis(const ViewSetup& setup);

// Throws eikon::Error (at `where`, the settings' JSON pointer) for what the interleaved view
// cannot do: a camera inside the slab of planes or beside it (its rays must cross them front to
// back), a light that does not cross them forward with at least min_cosine.
void checkInterleavedView(const ViewSetup& setup, const PlaneSweepSettings& settings,
                          const std::string& where);

// What the view rays and the slices held take for this setup, in bytes (the sweeps' own
// buffers aside).
size_t interleavedViewBytes(const ViewSetup& setup);

struct InterleavedViewCpu {
    Image image;
    // The sweeps' counters and memory; no fluence or direction volume, outputBytes 0.
    PlaneSweepResultCpu sweep;
    size_t windowBytes = 0;  // the slices of fluence and direction held
    size_t rayBytes = 0;     // the view rays' states
    // Samples of view rays that turned back against the sweep: read from the nearer slice held
    // instead of the one dropped.
    int64_t samplesBehind = 0;
    int64_t viewSteps = 0;  // view ray steps, all pixels
};

// Sweeps every light of the fluence beside the view rays and returns the frame.
// `gradient`: the ∇n volume; `environment`: as renderViewCpu's. Under dispersion
// (dispersesView, curved rays) `channelGradients` holds the red and blue channels' ∇n volumes:
// each light is swept once a channel and each pixel has a ray a channel, as the volume path has.
// The timer (null: none) gets the sweeps' share as stage "plane_sweep" and the rays' as "view".
InterleavedViewCpu renderInterleavedCpu(const ViewSetup& setup,
                                        const std::vector<const DenseGrid*>& slotGrids,
                                        const RefractionVolumeCpu& gradient,
                                        const PlaneSweepSettings& settings,
                                        const Image* environment,
                                        const ChannelGradientsCpu* channelGradients = nullptr,
                                        GpuStageTimer* timer = nullptr);

}  // namespace eikon
