// include_missing.glsl: line 3 names a file that does not exist.
#version 430 core
#include "does_not_exist.glsl"
