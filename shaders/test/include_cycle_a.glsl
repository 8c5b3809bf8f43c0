// include_cycle_a.glsl includes include_cycle_b.glsl, which includes this file again.
#version 430 core
#include "include_cycle_b.glsl"
const float CYCLE_A = CYCLE_B;
