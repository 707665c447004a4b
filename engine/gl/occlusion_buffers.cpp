#include "gl/occlusion_buffers.h"

namespace patina {

OcclusionBuffers::~OcclusionBuffers() {
    release();
}

void OcclusionBuffers::release() {
    for (const auto& [values, buffer] : buffers_) {
        glDeleteBuffers(1, &buffer);
    }
    buffers_.clear();
    shown_.reset();
}

void OcclusionBuffers::upload(const std::shared_ptr<const AmbientOcclusion>& occlusion) {
    // A frame without occlusion keeps the last one's buffers: a frame with it again (an A/B
    // pair, the checkbox ticked back) draws them without uploading the ground's grid anew.
    if (!occlusion || occlusion == shown_) {
        return;
    }
    release();
    std::vector<const std::vector<float>*> lists;
    for (const std::vector<float>& values : occlusion->items) {
        lists.push_back(&values);
    }
    lists.push_back(&occlusion->groundValues);
    for (const std::vector<float>* values : lists) {
        GLuint buffer = 0;
        glGenBuffers(1, &buffer);
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(values->size() * sizeof(float)), values->data(), GL_STATIC_DRAW);
        buffers_[values] = buffer;
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    if (occlusion->withGround) {
        ground_.upload(occlusion->ground);
    }
    shown_ = occlusion;
}

GLuint OcclusionBuffers::bufferOf(const std::vector<float>* values) const {
    const auto found = buffers_.find(values);
    return found != buffers_.end() ? found->second : 0;
}

}  // namespace patina
