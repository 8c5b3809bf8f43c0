// compile_error_include.glsl: line 6 uses an undeclared name on purpose
// (tests/render/test_shader_program.cpp expects "<this file>:6: error").

float useBroken() {
    float fine = 1.0;
    return fine + undeclaredOnPurpose;
}
