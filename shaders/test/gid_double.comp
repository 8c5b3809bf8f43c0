// Test shader (tests/render/test_gl_context.cpp): out[i] = 2 i + 1 for the first `count` uints.
#version 430 core
layout(local_size_x = 64) in;

layout(std430, binding = 0) buffer Output {
    uint values[];
};

uniform uint count;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < count) values[i] = i * 2u + 1u;
}
