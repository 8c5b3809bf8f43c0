#version 430 core
// A triangle that covers the viewport (render/display_pass.cpp); no vertex buffer needed.
out vec2 uv;

void main() {
    const vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    uv = vec2(corner.x, 1.0f - corner.y);  // image row 0 is the top
    gl_Position = vec4(corner * 2.0f - 1.0f, 0.0f, 1.0f);
}
