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

// How a receiver (shaders/shared/receivers.h) learns the irradiance photons bring it.
#define EK_RECEIVER_PLANE 0   // from the map of the flux of photons crossing the plane
#define EK_RECEIVER_VOXELS 1  // from the photon volumes beside the plane (Sun et al.'s floors)

// fetchVolume slots after the fields (0..) and the light volumes: the ∇n volume (xyz = ∇n, w = n).
#define EK_GRADIENT_SLOT (EK_MAX_MATERIALS + EK_MAX_LIGHTS)
// The smoothed photon volumes (render/transport/photons/photon_radiance.h): rgb = Σ flux·length per
// voxel (power × scene units), and xyz = the luminance-weighted sum of the directions the light
// travels.
#define EK_PHOTON_RADIANCE_SLOT (EK_GRADIENT_SLOT + 1)
#define EK_PHOTON_DIRECTION_SLOT (EK_GRADIENT_SLOT + 2)

// One material: optics per unit of its field's value (see core/scene.h).
struct GpuMaterial {
    vec4 absorption;  // rgb: per scene unit; w: Henyey–Greenstein g
    vec4 scattering;  // rgb: per scene unit; w: 1/T_ambient for Gladstone–Dale air, else 0
    vec4 emission;    // rgb: radiance per scene unit; w: n − 1 per unit of the field (ior − 1)
    ivec4 slot;       // x: which field texture the material reads; yzw: unused
};

struct GpuLight {
    vec4 position;   // xyz: world position (point, spot); w: type (EK_LIGHT_*)
    vec4 direction;  // xyz: unit direction the light travels (directional, spot); w: cos(outer)
    vec4 radiance;   // rgb: colour × intensity; w: cos(inner), where the spot edge starts
};

// A diffuse plane across the volume (core/scene.h ReceiverSpec). Its map has texels.x × texels.y
// texels over the volume's extent along the plane's axes u = (axis + 1) % 3 (x fastest) and
// w = (axis + 2) % 3, stored from index texels.z of the receiver map.
struct GpuReceiver {
    vec4 plane;   // x: normal axis (0, 1, 2); y: position on it; z: facing (±1); w: EK_RECEIVER_*
    vec4 albedo;  // rgb: diffuse reflectance; w: unused
    ivec4 texels;
};

// Everything the viewing pass needs besides the field textures.
struct GpuViewParams {
    vec4 cameraOrigin;   // xyz; w: tan(horizontal fov / 2)
    vec4 cameraRight;    // xyz unit; w: image aspect (width / height)
    vec4 cameraUp;       // xyz unit
    vec4 cameraForward;  // xyz unit
    vec4 volumeMin;      // xyz world; w: view step (scene units)
    vec4 volumeMax;      // xyz world; w: shadow step (scene units)
    ivec4 resolution;    // xyz voxels; w: material count
    ivec4 image;         // x, y: pixels; z: light count; w: EK_SHADOWS_*
    vec4 background;     // rgb radiance; w: minimum transmittance before a ray stops
    ivec4 pipeline;      // x: 1 = curved view rays through the ∇n volume, 0 = straight;
                         // y: 1 = in-scattering read from the photon volumes;
                         // z: bit l set = light l's light reaches the medium through the photon
                         //    volumes (not through its light volume); w: receiver count
    // The environment (shaders/shared/environment.h). x: EK_ENVIRONMENT_*; y, z: the image's
    // width and height in texels; w: 0.
    ivec4 environment;
    // Gradient: rgb zenith. Image: x intensity; y, z: cosine and sine of the rotation about +y.
    vec4 environmentSky;
    vec4 environmentHorizon;  // gradient: rgb horizon
    vec4 environmentGround;   // gradient: rgb ground
    GpuMaterial materials[EK_MAX_MATERIALS];
    GpuLight lights[EK_MAX_LIGHTS];
    GpuReceiver receivers[EK_MAX_RECEIVERS];
};

EK_NAMESPACE_END

#endif
