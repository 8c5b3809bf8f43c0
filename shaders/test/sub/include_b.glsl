// sub/include_b.glsl: a parent-relative path, a sibling, and a path from the shaders root.
#include "../include_common.glsl"
#include "include_sibling.glsl"
#include "test/include_common.glsl"
const float B_MARKER = SIBLING_MARKER + 1.0;
