#version 430 core
// Voxelization step 2 (shaders/shared/voxelize.h): one invocation per fine column turns its flips
// into inside bits by a prefix XOR from the bottom up.
layout(local_size_x = 64) in;

#include "shared/bindings.h"

layout(std430, binding = EK_SSBO_VOXELIZE_BITS) buffer Bits { uint bits[]; };

uniform int columnCount;
uniform int wordsPerColumn;

void toggleSample(int column, int k) {}
uint fetchInsideWord(int index) { return bits[index]; }

#include "shared/platform.h"
#include "shared/voxelize.h"

void main() {
    const int column = int(gl_GlobalInvocationID.x);
    if (column >= columnCount) return;
    uint carry = 0u;
    for (int w = 0; w < wordsPerColumn; ++w)
        bits[column * wordsPerColumn + w] = voxelizePrefixXor(bits[column * wordsPerColumn + w],
                                                              carry);
}
