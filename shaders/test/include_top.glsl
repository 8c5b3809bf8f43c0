// Fixture for tests/render/test_shader_program.cpp: nested, repeated and relative includes.
#version 430 core
#include "include_a.glsl"
#include "sub/include_b.glsl"
#include "include_a.glsl"
const float TOP_MARKER = 1.0;
