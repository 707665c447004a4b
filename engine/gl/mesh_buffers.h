#pragma once
#include <epoxy/gl.h>

#include "geometry/hidden_faces.h"
#include "geometry/mesh.h"

namespace patina {

// A mesh on the GPU: interleaved position and normal (attributes 0 and 1) and 32-bit indices;
// a mesh with UVs or tangents also has uv0, uv1 and the tangent (attributes 2, 3, 4; zeros for
// a set it lacks, and no tangent's w is 0, which shade.frag takes for "none"). A mesh with
// neither keeps the six floats a vertex (the built-in meshes). A mesh with vertex colours
// (COLOR_0) has them in a buffer of their own, attribute 6; without, attribute 6 is off and
// reads GL's current value (the renderer sets 1).
class MeshBuffers {
public:
    MeshBuffers();
    ~MeshBuffers();
    MeshBuffers(const MeshBuffers&) = delete;
    MeshBuffers& operator=(const MeshBuffers&) = delete;

    void upload(const Mesh& mesh);
    // Draws the triangles; `occlusion`, a buffer of a float per vertex, is attribute 5
    // (mesh.vert's aAmbientOcclusion, gl/occlusion_buffers.h), 0 for none.
    void draw(GLuint occlusion = 0) const;
    static constexpr GLuint kOcclusionAttribute = 5;
    static constexpr GLuint kColorAttribute = 6;
    bool hasColors() const { return hasColors_; }
    const BoundingBox& bounds() const { return bounds_; }
    const FaceCulling& culling() const { return culling_; }
    size_t triangleCount() const { return size_t(indexCount_) / 3; }

private:
    GLuint vertexArray_ = 0, vertices_ = 0, indices_ = 0, colors_ = 0;
    bool hasColors_ = false;
    GLsizei indexCount_ = 0;
    mutable bool occlusionEnabled_ = false;   // attribute 5 on in the vertex array
    BoundingBox bounds_;
    FaceCulling culling_;
};

}  // namespace patina
