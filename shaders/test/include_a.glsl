// include_a.glsl
#include "include_common.glsl"
const float A_MARKER = COMMON_MARKER + 1.0;
