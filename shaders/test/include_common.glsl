// include_common.glsl: included three times under different spellings, expanded once.
const float COMMON_MARKER = 10.0;
