// One triangle that covers the viewport; no vertex buffer needed.
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0f - vec2(1.0f), 0.0f, 1.0f);
}
