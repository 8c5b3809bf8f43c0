// sub/include_sibling.glsl
const float SIBLING_MARKER = 20.0;
