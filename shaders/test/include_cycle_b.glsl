// include_cycle_b.glsl
#include "include_cycle_a.glsl"
const float CYCLE_B = 2.0;
