#pragma once
// The ambient occlusion of the shape shown (scene/ambient_occlusion.h) on the GPU: a buffer of a
// float per vertex for each draw item and the ground, and the ground's grid, which carries the
// ground's. Uploaded once per occlusion, while it is the one drawn.
#include <map>
#include <memory>
#include <vector>

#include <epoxy/gl.h>

#include "scene/ambient_occlusion.h"
#include "gl/mesh_buffers.h"

namespace patina {

class OcclusionBuffers {
public:
    OcclusionBuffers() = default;
    ~OcclusionBuffers();
    OcclusionBuffers(const OcclusionBuffers&) = delete;
    OcclusionBuffers& operator=(const OcclusionBuffers&) = delete;

    // Makes `occlusion`'s values (and its ground grid) the ones drawn; nothing where it is
    // already, or for none (the last one's are kept). Holds it, so its values' addresses stand
    // for them.
    void upload(const std::shared_ptr<const AmbientOcclusion>& occlusion);
    // The buffer of `values`, one of the shown occlusion's (SceneDraw::occlusion); 0 for another.
    GLuint bufferOf(const std::vector<float>* values) const;
    // The shown occlusion's ground grid.
    const MeshBuffers& ground() const { return ground_; }
    const AmbientOcclusion* shown() const { return shown_.get(); }

private:
    void release();
    std::shared_ptr<const AmbientOcclusion> shown_;
    std::map<const std::vector<float>*, GLuint> buffers_;
    MeshBuffers ground_;
};

}  // namespace patina
