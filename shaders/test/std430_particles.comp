#version 430 core
// Test shader (tests/render/test_std430.cpp): the driver's std430 layout of the particle structs
// the photon and wavefront passes keep in buffers, GpuPhoton, GpuWavefrontPatch and the wavefront's
// round lists' GpuWavefrontEntry.
layout(local_size_x = 1) in;
#define EK_PHOTON_TYPES_ONLY
#include "shared/photons.h"
#define EK_WAVEFRONT_TYPES_ONLY
#include "shared/wavefront.h"

layout(std430, binding = 0) buffer P {
    GpuPhoton photonList[];
};

layout(std430, binding = 1) buffer W {
    GpuWavefrontPatch patchList[];
};

layout(std430, binding = 2) buffer E {
    GpuWavefrontEntry entryList[];
};

void main() {
    // Touch every member so that none is optimized away.
    photonList[0].position.x += photonList[0].direction.x + photonList[0].flux.x;
    for (int k = 0; k < 4; ++k)
        patchList[0].power.x += patchList[0].corner[k].x + patchList[0].velocity[k].x;
    patchList[0].state.x += patchList[0].surface.x + patchList[0].surfaceNormal.x;
    entryList[0].tally.lost.x += entryList[0].tally.reflected.x + entryList[0].piece.power.x +
                                 float(entryList[0].tally.root.x);
}
