#pragma once
// A model's images on the GPU, each in the format its maps read it in, and a sampler object for
// each way they are sampled (glTF 2.0 section 3.8). Needs a current context.
#include <map>
#include <memory>
#include <tuple>
#include <utility>

#include <epoxy/gl.h>

#include "model/model.h"

namespace patina {

class ModelTextures {
public:
    ModelTextures() = default;
    ~ModelTextures();
    ModelTextures(const ModelTextures&) = delete;
    ModelTextures& operator=(const ModelTextures&) = delete;

    // Uploads every image a material of `model` maps (once per image and colour space), with
    // mipmaps; forgets what was uploaded for another model. Holds the model while its images
    // are on the GPU, so a later model at the same address is never taken for it.
    void upload(std::shared_ptr<const Model> model);
    // Binds `slot`'s image (sRGB-decoded when `srgb`: base colour and emissive) and sampler to
    // texture unit `unit`. False, binding nothing, when the slot has no image uploaded.
    bool bind(int unit, const TextureSlot& slot, bool srgb);

private:
    GLuint sampler(const TextureSampler& wanted);
    void clear();

    std::shared_ptr<const Model> model_;
    std::map<std::pair<int, bool>, GLuint> textures_;   // (image, sRGB) -> texture
    std::map<std::tuple<int, int, bool, bool, bool>, GLuint> samplers_;
};

// GL's wrap mode for glTF's (10497 REPEAT, 33071 CLAMP_TO_EDGE, 33648 MIRRORED_REPEAT: the same
// numbers GL uses).
GLint glWrap(TextureWrap wrap);

}  // namespace patina
