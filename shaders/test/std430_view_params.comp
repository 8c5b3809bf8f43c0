// Test shader (tests/render/test_std430.cpp): the driver's std430 offsets for the shared structs.
#version 430 core
layout(local_size_x = 1) in;
#include "shared/gpu_types.h"

layout(std430, binding = 0) buffer B {
    GpuViewParams params;
};

layout(std430, binding = 1) buffer M {
    GpuMaterial materialList[];
};

layout(std430, binding = 2) buffer L {
    GpuLight lightList[];
};

void main() {
    // Touch every block so that none is optimized away.
    params.cameraOrigin.x += materialList[0].absorption.x + lightList[0].radiance.x;
}
