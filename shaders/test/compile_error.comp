// Fixture: compiles only up to the deliberate mistake in compile_error_include.glsl, line 6.
#version 430 core
layout(local_size_x = 1) in;
#include "compile_error_include.glsl"

void main() { useBroken(); }
