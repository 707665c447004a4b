#include "gl/mesh_buffers.h"

#include <vector>

namespace patina {

MeshBuffers::MeshBuffers() {
    glGenVertexArrays(1, &vertexArray_);
    glGenBuffers(1, &vertices_);
    glGenBuffers(1, &indices_);
    glGenBuffers(1, &colors_);
}

namespace {
constexpr int kSurfaceFloats = 3 + 3 + 2 + 2 + 4;   // position, normal, uv0, uv1, tangent

bool hasSurfaceAttributes(const Mesh& mesh) {
    return !mesh.uv0.empty() || !mesh.uv1.empty() || !mesh.tangents.empty();
}

// Attribute `index`, `size` floats at `offset` floats into a vertex `stride` floats long.
void attribute(GLuint index, GLint size, int offset, int stride) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, GLsizei(stride * sizeof(float)),
                          reinterpret_cast<const void*>(offset * sizeof(float)));
}

std::vector<float> interleave(const Mesh& mesh, bool surface) {
    std::vector<float> interleaved;
    interleaved.reserve(mesh.positions.size() * (surface ? kSurfaceFloats : 6));
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3 p = mesh.positions[i], n = mesh.normals[i];
        interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
        if (surface) {
            const glm::vec2 uv0 = mesh.uv0.empty() ? glm::vec2(0.0f) : mesh.uv0[i];
            const glm::vec2 uv1 = mesh.uv1.empty() ? glm::vec2(0.0f) : mesh.uv1[i];
            const glm::vec4 t = mesh.tangents.empty() ? glm::vec4(0.0f) : mesh.tangents[i];
            interleaved.insert(interleaved.end(), {uv0.x, uv0.y, uv1.x, uv1.y, t.x, t.y, t.z, t.w});
        }
    }
    return interleaved;
}
}  // namespace

MeshBuffers::~MeshBuffers() {
    glDeleteBuffers(1, &colors_);
    glDeleteBuffers(1, &indices_);
    glDeleteBuffers(1, &vertices_);
    glDeleteVertexArrays(1, &vertexArray_);
}

void MeshBuffers::upload(const Mesh& mesh) {
    // Before anything changes: a throw leaves the old mesh whole, never new buffers beside the
    // old mesh's verdict on its faces.
    const BoundingBox bounds = boundingBox(mesh);
    const FaceCulling culling = faceCulling(mesh);
    const bool surface = hasSurfaceAttributes(mesh);
    const std::vector<float> interleaved = interleave(mesh, surface);
    glBindVertexArray(vertexArray_);
    glBindBuffer(GL_ARRAY_BUFFER, vertices_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
    const int stride = surface ? kSurfaceFloats : 6;
    attribute(0, 3, 0, stride);
    attribute(1, 3, 3, stride);
    for (GLuint extra = 2; extra <= 4; ++extra) {
        glDisableVertexAttribArray(extra);
    }
    if (surface) {
        attribute(2, 2, 6, stride);
        attribute(3, 2, 8, stride);
        attribute(4, 4, 10, stride);
    }
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)),
                 interleaved.data(), GL_STATIC_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)),
                 mesh.indices.data(), GL_STATIC_DRAW);
    hasColors_ = !mesh.colors.empty();
    if (hasColors_) {
        glBindBuffer(GL_ARRAY_BUFFER, colors_);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.colors.size() * sizeof(glm::vec4)), mesh.colors.data(),
                     GL_STATIC_DRAW);
        attribute(kColorAttribute, 4, 0, 4);
    } else {
        glDisableVertexAttribArray(kColorAttribute);
    }
    glBindVertexArray(0);
    indexCount_ = GLsizei(mesh.indices.size());
    bounds_ = bounds;
    culling_ = culling;
}

void MeshBuffers::draw(GLuint occlusion) const {
    glBindVertexArray(vertexArray_);
    if (occlusion) {
        glBindBuffer(GL_ARRAY_BUFFER, occlusion);
        glEnableVertexAttribArray(kOcclusionAttribute);
        glVertexAttribPointer(kOcclusionAttribute, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
    } else if (occlusionEnabled_) {
        glDisableVertexAttribArray(kOcclusionAttribute);
    }
    occlusionEnabled_ = occlusion != 0;
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
}

}  // namespace patina
