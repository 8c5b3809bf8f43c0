// Every binding point of the GPU passes, named once for both sides: the shaders write
// `layout(binding = EK_...)` (GLSL takes a constant expression there) and the host binds with the
// same names (glActiveTexture(GL_TEXTURE0 + EK_UNIT_...), glBindImageTexture(EK_IMAGE_...),
// glBindBufferBase(GL_SHADER_STORAGE_BUFFER, EK_SSBO_...)). Only #defines: C++ and GLSL read this
// file as it is.
//
// Three name spaces, each numbered on its own by GL:
//   EK_UNIT_*   texture units (sampler bindings);
//   EK_IMAGE_*  image units (image3D / image2D bindings);
//   EK_SSBO_*   shader storage buffer bindings.
// A number shared by two names below belongs to passes that never run at the same time: each pass
// binds what it declares before it dispatches. Where a pass writes a texture through an image
// unit, that texture must not stay bound to a texture unit the same pass samples (the hosts
// unbind it; render/transport/light_volumes/light_volume_gpu.cpp, photon_radiance_gpu.cpp).
#ifndef EIKON_SHARED_BINDINGS_H
#define EIKON_SHARED_BINDINGS_H

// ---- Texture units ----------------------------------------------------------------------------
// The volume passes (shaders/volume_bindings.glsl): one 3D texture per kind of volume, so that
// every fetch of a kind goes through one sampler (see there).
#define EK_UNIT_FIELDS 0  // R32F: the field volumes, EK_MAX_MATERIALS slots stacked in z
#define EK_UNIT_LIGHT_TRANSMITTANCE 1  // RGBA32F: one transmittance volume per light, stacked in z
#define EK_UNIT_GRADIENT 2             // RGBA32F: xyz = ∇n, w = n (curved rays, photons)
#define EK_UNIT_OCTREE 3               // RGBA32F: the photon march's octree (photon_trace.comp)
#define EK_UNIT_FLUENCE 4              // RGBA32F: the method's fluence, rgb = Σ flux·length
#define EK_UNIT_FLUENCE_DIRECTION 5    // RGBA32F: xyz = Σ luminance-weighted direction
#define EK_UNIT_ENVIRONMENT 6          // RGBA32F 2D: the equirectangular environment image
// The display pass (shaders/display.frag), a graphics program of its own.
#define EK_UNIT_DISPLAY_IMAGE 0  // RGBA32F 2D: the linear image shown

// ---- Image units ------------------------------------------------------------------------------
#define EK_IMAGE_VIEW_OUTPUT 0          // view.comp: the rendered image (RGBA32F 2D)
#define EK_IMAGE_LIGHT_TRANSMITTANCE 1  // light_march.comp, light_sweep.comp: all lights, stacked
#define EK_IMAGE_GRADIENT 2             // refraction_gradient.comp writes, octree_minmax.comp reads
#define EK_IMAGE_OCTREE 2               // octree_label.comp writes
#define EK_IMAGE_PHOTON_RADIANCE_RAW 1  // photon_resolve.comp writes the unsmoothed volumes
#define EK_IMAGE_PHOTON_DIRECTION_RAW 2
#define EK_IMAGE_SMOOTH_SOURCE 1  // smooth_volume.comp reads (RGBA32F)
#define EK_IMAGE_SMOOTH_TARGET 2  //   and writes
#define EK_IMAGE_BLUR_SOURCE 1    // gaussian_blur.comp reads (R32F)
#define EK_IMAGE_BLUR_TARGET 2    //   and writes
#define EK_IMAGE_COVERAGE 1       // voxelize_coverage.comp writes (R32F)
// plane_sweep.comp: the light buffers (RGBA32F 2D) and the output contract's volumes it fills.
#define EK_IMAGE_SWEEP_LIGHT_IN 0
#define EK_IMAGE_SWEEP_DIRECTION_IN 1
#define EK_IMAGE_SWEEP_TRACE 2
#define EK_IMAGE_SWEEP_LIGHT_OUT 3
#define EK_IMAGE_SWEEP_DIRECTION_OUT 4
#define EK_IMAGE_SWEEP_FLUENCE 5
#define EK_IMAGE_SWEEP_FLUENCE_DIRECTION 6

// ---- Shader storage buffers -------------------------------------------------------------------
#define EK_SSBO_VIEW_PARAMS 0        // GpuViewParams (render/params_buffer.cpp), every volume pass
#define EK_SSBO_OCTREE_PYRAMID 3     // octree_minmax.comp, octree_label.comp: the min/max pyramid
#define EK_SSBO_PHOTONS 4            // photon_trace.comp: every photon's state
#define EK_SSBO_PHOTON_DEPOSITS 5    // photon_trace.comp adds, photon_resolve.comp reads
#define EK_SSBO_PHOTON_TOTALS 6      // photon_trace.comp: escaped, extinguished, ... (int64 pairs)
#define EK_SSBO_RECEIVER_DEPOSITS 7  // photon_trace.comp: flux per receiver map texel
#define EK_SSBO_RECEIVER_MAP 8       // view.comp: irradiance per receiver map texel
#define EK_SSBO_PHOTON_ROUNDS 9      // photon_trace.comp, photon_round.comp: rounds and lists
#define EK_SSBO_PHOTON_EXTINGUISHED 10  // photon_trace.comp: flux lost so far, per photon
// plane_sweep.comp, which never runs beside the photon passes (low numbers: GL 4.3 promises a
// compute shader only 8 storage blocks).
#define EK_SSBO_SWEEP_COUNTERS 4       // texels whose light was lost
#define EK_SSBO_SWEEP_RECEIVER_SUMS 5  // power per receiver map texel
// view_interleaved.comp (the plane sweep's interleaved view), whose dispatches alternate with
// plane_sweep.comp's: numbers apart from the sweep's; EK_SSBO_RECEIVER_MAP as view.comp.
#define EK_SSBO_INTERLEAVED_RAYS 1      // every pixel's view ray state (CurvedRay or StraightRay)
#define EK_SSBO_INTERLEAVED_FLAGS 2     // per pixel: in the volume, ended
#define EK_SSBO_INTERLEAVED_HITS 3      // per pixel: the receiver hit waiting to be shaded
#define EK_SSBO_INTERLEAVED_COUNTERS 6  // view ray steps, samples behind the sweep
// wavefront_trace.comp and wavefront_scan.comp (the wavefront's rounds), which never run beside the
// photon passes or the octree's; the deposits, receiver sums and receiver map as photons.
#define EK_SSBO_WAVE_LIST_IN 1   // GpuWavefrontEntry per patch of the list a round traces
#define EK_SSBO_WAVE_LIST_OUT 2  // the list it leaves (a generating dispatch: the starting patches)
#define EK_SSBO_WAVE_SCAN 3      // per patch its outcome and prefix sums, then the blocks' sums
#define EK_SSBO_WAVE_ROUNDS 4    // the round header, then the totals (shared/wavefront_rounds.h)
#define EK_SSBO_WAVE_ROOT_STATE 6  // per starting patch: patches made, first request of the round
// The voxelizer's passes (voxelize_*.comp) run apart from the volume passes: binding 0 is theirs
// until render/params_buffer.cpp binds the parameters again before the next volume pass.
#define EK_SSBO_VOXELIZE_POSITIONS 0  // voxelize_toggle.comp: vertex positions
#define EK_SSBO_VOXELIZE_TRIANGLES 1  // voxelize_toggle.comp: vertex indices
#define EK_SSBO_VOXELIZE_BITS 2       // voxelize_*.comp: the inside bits of the fine columns

#endif
