// Structs shared by the host and the shaders, in std430 layout. Every member is a vec4, ivec4 or
// a 4-byte scalar, placed so that C++ offsets equal std430 offsets; tests/render/test_std430.cpp
// asks the GL driver for each offset and compares.
#ifndef EIKON_SHARED_GPU_TYPES_H
#define EIKON_SHARED_GPU_TYPES_H
#include "platform.h"

EK_NAMESPACE_BEGIN

#define EK_MAX_MATERIALS 4
#define EK_MAX_LIGHTS 4
#define EK_MAX_RECEIVERS 4
#define EK_MAX_CLIP_PLANES 4
// Entries of a material's particle colour table (core/particle_color.h): a colour map's 256
// entries, or a [value, r, g, b] function sampled at as many values.
#define EK_PARTICLE_COLOR_TABLE 256

#define EK_LIGHT_POINT 0
#define EK_LIGHT_DIRECTIONAL 1
#define EK_LIGHT_SPOT 2

// How the viewing pass finds a light's transmittance at a sample.
#define EK_SHADOWS_VOLUME 0   // lookup in a light volume marched from every voxel centre
#define EK_SHADOWS_MARCHED 1  // a ray marched toward the light from every sample (reference)
#define EK_SHADOWS_SWEPT 2    // lookup in a light volume swept slice by slice (directional)

// What a view ray sees when it leaves the volume (shaders/shared/environment.h).
#define EK_ENVIRONMENT_COLOR 0     // background.rgb in every direction
#define EK_ENVIRONMENT_GRADIENT 1  // zenith, horizon and ground colours blended by elevation
#define EK_ENVIRONMENT_IMAGE 2     // an equirectangular image (fetchEnvironment) × intensity

// How a receiver (shaders/shared/receivers.h) learns the irradiance of the lights in the fluence.
#define EK_RECEIVER_PLANE 0   // from its receiver map: the flux crossing the plane, per area
#define EK_RECEIVER_VOXELS 1  // from the fluence volumes beside the plane (Sun et al.'s floors)

// fetchVolume slots after the fields (0..) and the light volumes: the ∇n volume (xyz = ∇n, w = n).
#define EK_GRADIENT_SLOT (EK_MAX_MATERIALS + EK_MAX_LIGHTS)
// The light-transport method's fluence volumes, the output contract the view reads
// (render/light_transport.h; the photons' are their smoothed deposits,
// render/transport/photons/photon_radiance.h): rgb = Σ flux·length per voxel (power × scene
// units), and xyz = the luminance-weighted sum of the directions the light travels.
#define EK_FLUENCE_SLOT (EK_GRADIENT_SLOT + 1)
#define EK_FLUENCE_DIRECTION_SLOT (EK_GRADIENT_SLOT + 2)

// One material: optics per unit of its field's value (see core/scene.h).
// The packed members are read through the accessors below (materialPhaseG(m), ...).
struct GpuMaterial {
    vec4 absorption;  // rgb: per scene unit; w: Henyey–Greenstein g (materialPhaseG)
    // rgb: per scene unit; w: 1/T_ambient for Gladstone–Dale air, else 0 (materialInverseAmbient)
    vec4 scattering;
    // rgb: radiance per scene unit; w: n − 1 per unit of the field, ior − 1 (materialIndexSlope)
    vec4 emission;
    // x: which field texture the material reads (materialSlot); y: 1 where the edge of its field
    // is a sharp surface that reflects part of the light crossing it (materialFresnel); z: bit k
    // set = clip plane k cuts its opacity (materialClipMask, optics.h materialClipWeight); w: 0,
    // or 1 + the field slot whose value its particle colour reads (materialColorSlot, optics.h
    // particleColorOverStep): its own slot, or the raw field's where a transfer function maps its
    // own
    ivec4 slot;
    // x: the roughness of its sharp surfaces' specular highlights (materialRoughness, specular.h);
    // 0: none. yzw: 0.
    vec4 surface;
};

struct GpuLight {
    vec4 position;   // xyz: world position (point, spot); w: type, EK_LIGHT_* (lightType)
    vec4 direction;  // xyz: unit direction the light travels (directional, spot); w: the outer
                     // cone's versine 1 − cos θ (lightVersineOuter); a directional light's disc,
                     // the versine of its angular radius (lightDiscVersine; 0: one direction)
    vec4 radiance;   // rgb: colour × intensity; w: the inner cone's versine, where the spot edge
                     // starts (lightVersineInner). Versines, not cosines: a 0.05° cone's cosine
                     // is 1 − 3.8e-7 and float resolves 6e-8 there, its versine to 1e-7 relative
};

// A diffuse plane across the volume (core/scene.h ReceiverSpec). Its map has texels.x × texels.y
// texels over the volume's extent along the plane's axes u = (axis + 1) % 3 (x fastest) and
// w = (axis + 2) % 3, stored from index texels.z of the receiver map.
struct GpuReceiver {
    // x: normal axis, 0, 1, 2 (receiverAxis); y: position on it (receiverPosition); z: facing, ±1
    // (receiverFacing); w: EK_RECEIVER_* (receiverKind)
    vec4 plane;
    vec4 albedo;  // rgb: diffuse reflectance; w: unused
    // x, y: texels along u and w (receiverMapWidth, receiverMapHeight); z: the index of its first
    // texel in the receiver map (receiverMapStart); w: unused
    ivec4 texels;
};

// Everything the viewing pass needs besides the field textures.
struct GpuViewParams {
    vec4 cameraOrigin;  // xyz; w: tan(horizontal fov / 2) (tanHalfFovX)
    vec4 cameraRight;   // xyz unit; w: image aspect, width / height (imageAspect)
    // xyz unit; w: with dispersion, the colour channel this pass traces + 1 (each channel's rays
    // bend with its own n, render/view_pass_*.cpp); 0: one ray for all three (viewChannel)
    vec4 cameraUp;
    // xyz unit; w: view rays cross a sharp surface (fresnel.h) where n_surface changes by more
    // than this per voxel: Fresnel reflection toward the camera there; 0: none (viewSurfaceSlope)
    vec4 cameraForward;
    vec4 volumeMin;    // xyz world; w: view step, scene units (viewStep)
    vec4 volumeMax;    // xyz world; w: shadow step, scene units (shadowStep)
    ivec4 resolution;  // xyz voxels; w: material count (materialCount)
    ivec4 image;       // x, y: pixels; z: light count (lightCount); w: EK_SHADOWS_* (shadowMode)
    vec4 background;   // rgb radiance; w: a ray stops below it (minTransmittance)
    // The packed flags, read through the accessors below. x: 0 = straight view rays, 1 + EK_RAY_*
    // = curved through the ∇n volume with that integrator (curvedRays, viewIntegrator); y: 1 =
    // in-scattering read from the fluence volumes (readsFluence); z: bit l set = light l's light
    // reaches the medium through the fluence volumes, not through its light volume
    // (lightInFluence); w: receiver count (receiverCount).
    ivec4 pipeline;
    // The environment (shaders/shared/environment.h). x: EK_ENVIRONMENT_* (environmentType); y, z:
    // the image's width and height in texels (environmentWidth, environmentHeight); w: 0.
    ivec4 environment;
    // Gradient: rgb zenith. Image: x intensity (environmentIntensity); y, z: cosine and sine of
    // the rotation about +y (environmentRotationCos, environmentRotationSin).
    vec4 environmentSky;
    vec4 environmentHorizon;  // gradient: rgb horizon
    vec4 environmentGround;   // gradient: rgb ground
    // Clip planes (core/scene.h ClipPlaneSpec) in volume index coordinates: the weight a clipped
    // material's opacity keeps at index position p is clamp(dot(xyz, p) + w, 0, 1), a ramp from 0
    // to 1 across one voxel's extent along the normal, centred on the plane (optics.h).
    vec4 clipPlanes[EK_MAX_CLIP_PLANES];
    GpuMaterial materials[EK_MAX_MATERIALS];
    GpuLight lights[EK_MAX_LIGHTS];
    GpuReceiver receivers[EK_MAX_RECEIVERS];
    // Each material's particle colour (optics.h particleColorOverStep; used where materialColorSlot
    // is set): x the value of its first entry, y entries per unit of value, (N − 1)/(hi − lo).
    vec4 particleColorRanges[EK_MAX_MATERIALS];
    // rgb: linear colour; EK_PARTICLE_COLOR_TABLE entries per material, evenly over its range.
    vec4 particleColors[EK_MAX_MATERIALS * EK_PARTICLE_COLOR_TABLE];
    // rgb: the pre-integration table, ∫ colour from the first entry to this one, in entries
    // (optics.h particleColorIntegral); built with the colours (render/view_params.cpp).
    vec4 particleColorIntegrals[EK_MAX_MATERIALS * EK_PARTICLE_COLOR_TABLE];
};

// Named reads of the packed members of GpuViewParams, the same in the shaders, the CPU twin and on
// the host: code reads curvedRays(params), never params.pipeline.x. C++ has them as functions,
// GLSL as macros over the same expressions: a GLSL function would take the whole block by value,
// and though Mesa optimises that copy away, the code it then generates is not the code of the
// member read (the llvmpipe program binaries differ); a macro gives the very same instructions.
// Keep the two lists equal.
#ifdef __cplusplus
inline bool curvedRays(const GpuViewParams& p) {
    return p.pipeline.x != 0;  // view rays bend through the ∇n volume
}
inline int viewIntegrator(const GpuViewParams& p) {
    return p.pipeline.x - 1;  // EK_RAY_* (shaders/shared/ray_equation.h), for curved rays
}
inline bool readsFluence(const GpuViewParams& p) {
    return p.pipeline.y != 0;  // in-scattering read from the fluence volumes
}
// Whether light l's light comes through the fluence volumes, not straight.
inline bool lightInFluence(const GpuViewParams& p, int l) {
    return (p.pipeline.z & (1 << l)) != 0;
}
inline bool anyLightInFluence(const GpuViewParams& p) {
    return p.pipeline.z != 0;
}
inline bool allLightsInFluence(const GpuViewParams& p) {
    return p.pipeline.z == (1 << p.image.z) - 1;
}
inline int receiverCount(const GpuViewParams& p) {
    return p.pipeline.w;
}
// Whether some material's sharp surfaces show the lights' highlights (view_march.h
// anyRoughSurfaces, on the host: which view shader variant to run).
inline bool anySurfaceHighlights(const GpuViewParams& p) {
    for (int m = 0; m < p.resolution.w; ++m)
        if (p.materials[m].slot.y != 0 && p.materials[m].surface.x > 0.0f) return true;
    return false;
}
inline int lightCount(const GpuViewParams& p) {
    return p.image.z;
}
inline int shadowMode(const GpuViewParams& p) {
    return p.image.w;  // EK_SHADOWS_*
}
inline int materialCount(const GpuViewParams& p) {
    return p.resolution.w;
}
inline float viewStep(const GpuViewParams& p) {
    return p.volumeMin.w;  // scene units
}
inline float shadowStep(const GpuViewParams& p) {
    return p.volumeMax.w;  // scene units
}
inline float minTransmittance(const GpuViewParams& p) {
    return p.background.w;  // a view ray stops below it
}
inline float viewSurfaceSlope(const GpuViewParams& p) {
    return p.cameraForward.w;  // per voxel; 0: view rays see no Fresnel reflection
}
inline int viewChannel(const GpuViewParams& p) {
    return int(p.cameraUp.w) - 1;  // 0, 1, 2: red, green, blue alone; −1: all at once
}
inline float tanHalfFovX(const GpuViewParams& p) {
    return p.cameraOrigin.w;
}
inline float imageAspect(const GpuViewParams& p) {
    return p.cameraRight.w;  // width / height
}
inline int environmentType(const GpuViewParams& p) {
    return p.environment.x;  // EK_ENVIRONMENT_*
}
inline int environmentWidth(const GpuViewParams& p) {
    return p.environment.y;  // texels of the image
}
inline int environmentHeight(const GpuViewParams& p) {
    return p.environment.z;
}
inline float environmentIntensity(const GpuViewParams& p) {
    return p.environmentSky.x;  // the image's
}
inline float environmentRotationCos(const GpuViewParams& p) {
    return p.environmentSky.y;  // the image's rotation about +y
}
inline float environmentRotationSin(const GpuViewParams& p) {
    return p.environmentSky.z;
}
#else
#define curvedRays(p) ((p).pipeline.x != 0)
#define viewIntegrator(p) ((p).pipeline.x - 1)
#define readsFluence(p) ((p).pipeline.y != 0)
#define lightInFluence(p, l) (((p).pipeline.z & (1 << (l))) != 0)
#define anyLightInFluence(p) ((p).pipeline.z != 0)
#define allLightsInFluence(p) ((p).pipeline.z == (1 << (p).image.z) - 1)
#define receiverCount(p) ((p).pipeline.w)
#define lightCount(p) ((p).image.z)
#define shadowMode(p) ((p).image.w)
#define materialCount(p) ((p).resolution.w)
#define viewStep(p) ((p).volumeMin.w)
#define shadowStep(p) ((p).volumeMax.w)
#define minTransmittance(p) ((p).background.w)
#define viewSurfaceSlope(p) ((p).cameraForward.w)
#define viewChannel(p) (int((p).cameraUp.w) - 1)
#define tanHalfFovX(p) ((p).cameraOrigin.w)
#define imageAspect(p) ((p).cameraRight.w)
#define environmentType(p) ((p).environment.x)
#define environmentWidth(p) ((p).environment.y)
#define environmentHeight(p) ((p).environment.z)
#define environmentIntensity(p) ((p).environmentSky.x)
#define environmentRotationCos(p) ((p).environmentSky.y)
#define environmentRotationSin(p) ((p).environmentSky.z)
#endif

// Named reads of the packed members of one material, light or receiver, the same way: C++
// functions, GLSL macros over the same expressions (materialPhaseG(params.materials[m]), never
// materialPhaseG(params.materials[m])). Keep the two lists equal.
#ifdef __cplusplus
inline float materialPhaseG(const GpuMaterial& m) {
    return m.absorption.w;  // Henyey–Greenstein g
}
inline float materialInverseAmbient(const GpuMaterial& m) {
    return m.scattering.w;  // 1/T_ambient for Gladstone–Dale air, else 0 (material_index.h)
}
inline float materialIndexSlope(const GpuMaterial& m) {
    return m.emission.w;  // ior − 1: n − 1 per unit of the field at f = 0 (material_index.h)
}
inline int materialSlot(const GpuMaterial& m) {
    return m.slot.x;  // the field slot the material reads (fetchVolume)
}
inline bool materialFresnel(const GpuMaterial& m) {
    return m.slot.y != 0;  // its edge reflects by Fresnel's law (shaders/shared/fresnel.h)
}
inline int materialClipMask(const GpuMaterial& m) {
    return m.slot.z;  // bit k: clip plane k cuts its opacity
}
inline int materialColorSlot(const GpuMaterial& m) {
    return m.slot.w - 1;  // the slot its particle colour reads; −1: no particle colour
}
inline float materialRoughness(const GpuMaterial& m) {
    return m.surface.x;  // its sharp surfaces' highlights (specular.h); 0: none
}
inline int lightType(const GpuLight& l) {
    return int(l.position.w);  // EK_LIGHT_*
}
inline float lightVersineOuter(const GpuLight& l) {
    return l.direction.w;  // a spot light's cone: no light outside
}
inline float lightVersineInner(const GpuLight& l) {
    return l.radiance.w;  // a spot light's cone: full light inside
}
inline float lightDiscVersine(const GpuLight& l) {
    return l.direction.w;  // a directional light's disc: 1 − cos of its angular radius
}
inline int receiverAxis(const GpuReceiver& r) {
    return int(r.plane.x);  // the normal's axis, 0, 1 or 2
}
inline float receiverPosition(const GpuReceiver& r) {
    return r.plane.y;  // the plane's world coordinate along its axis
}
inline float receiverFacing(const GpuReceiver& r) {
    return r.plane.z;  // ±1: the front face's normal along the axis
}
inline int receiverKind(const GpuReceiver& r) {
    return int(r.plane.w);  // EK_RECEIVER_*
}
inline int receiverMapWidth(const GpuReceiver& r) {
    return r.texels.x;  // texels along u = (axis + 1) % 3
}
inline int receiverMapHeight(const GpuReceiver& r) {
    return r.texels.y;  // texels along w = (axis + 2) % 3
}
inline int receiverMapStart(const GpuReceiver& r) {
    return r.texels.z;  // the index of its first texel in the receiver map
}
#else
#define materialPhaseG(m) ((m).absorption.w)
#define materialInverseAmbient(m) ((m).scattering.w)
#define materialIndexSlope(m) ((m).emission.w)
#define materialSlot(m) ((m).slot.x)
#define materialFresnel(m) ((m).slot.y != 0)
#define materialClipMask(m) ((m).slot.z)
#define materialColorSlot(m) ((m).slot.w - 1)
#define materialRoughness(m) ((m).surface.x)
#define lightType(l) (int((l).position.w))
#define lightVersineOuter(l) ((l).direction.w)
#define lightVersineInner(l) ((l).radiance.w)
#define lightDiscVersine(l) ((l).direction.w)
#define receiverAxis(r) (int((r).plane.x))
#define receiverPosition(r) ((r).plane.y)
#define receiverFacing(r) ((r).plane.z)
#define receiverKind(r) (int((r).plane.w))
#define receiverMapWidth(r) ((r).texels.x)
#define receiverMapHeight(r) ((r).texels.y)
#define receiverMapStart(r) ((r).texels.z)
#endif

#ifdef __cplusplus
// The host's writes of the same members (render/view_params.cpp, the light-transport methods'
// configure()).
inline void setTanHalfFovX(GpuViewParams& p, float t) {
    p.cameraOrigin.w = t;
}
inline void setImageAspect(GpuViewParams& p, float aspect) {
    p.cameraRight.w = aspect;
}
inline void setViewStep(GpuViewParams& p, float step) {
    p.volumeMin.w = step;
}
inline void setShadowStep(GpuViewParams& p, float step) {
    p.volumeMax.w = step;
}
inline void setMaterialCount(GpuViewParams& p, int count) {
    p.resolution.w = count;
}
inline void setLightCount(GpuViewParams& p, int count) {
    p.image.z = count;
}
inline void setShadowMode(GpuViewParams& p, int mode) {
    p.image.w = mode;
}
inline void setMinTransmittance(GpuViewParams& p, float t) {
    p.background.w = t;
}
inline void setViewSurfaceSlope(GpuViewParams& p, float perVoxel) {
    p.cameraForward.w = perVoxel;
}
// Curved view rays stepped by `integrator` (EK_RAY_*), or straight ones (integrator < 0).
inline void setCurvedRays(GpuViewParams& p, int integrator) {
    p.pipeline.x = integrator >= 0 ? 1 + integrator : 0;
}
inline void setReadsFluence(GpuViewParams& p, bool on) {
    p.pipeline.y = on ? 1 : 0;
}
inline void setLightInFluence(GpuViewParams& p, int l) {
    p.pipeline.z |= 1 << l;
}
inline void setReceiverCount(GpuViewParams& p, int count) {
    p.pipeline.w = count;
}
#endif

EK_NAMESPACE_END

#endif
