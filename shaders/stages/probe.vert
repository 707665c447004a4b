// One point per probe row, drawn at its own pixel of a float target.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aView;

uniform ivec2 uTargetSize;

flat out vec3 vPosition;
flat out vec3 vNormal;
flat out vec3 vView;

void main() {
    int x = gl_VertexID % uTargetSize.x;
    int y = gl_VertexID / uTargetSize.x;
    vec2 pixelCenter = (vec2(float(x), float(y)) + vec2(0.5f)) / vec2(uTargetSize);
    vPosition = aPosition;
    vNormal = aNormal;
    vView = aView;
    gl_Position = vec4(pixelCenter * 2.0f - vec2(1.0f), 0.0f, 1.0f);
    gl_PointSize = 1.0f;
}
