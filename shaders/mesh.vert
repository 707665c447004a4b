// Mesh vertices are in world space (Patina's meshes have no transform of their own).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;

uniform mat4 uViewProjection;

out vec3 vPosition;
out vec3 vNormal;

// The multi-pass path draws the mesh once per light with depth test EQUAL: every pass must
// produce bit-identical depth.
invariant gl_Position;

void main() {
    vPosition = aPosition;
    vNormal = aNormal;
    gl_Position = uViewProjection * vec4(aPosition, 1.0f);
}
