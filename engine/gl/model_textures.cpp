#include "gl/model_textures.h"

#include "shading/texture_sampling.h"

namespace patina {

namespace {
GLuint uploadImage(const ModelImage& image, bool srgb) {
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Rows in file order: glTF's (0, 0) is the image's top-left, and GL's first row is t = 0,
    // so UVs are used as given, with no flip anywhere.
    const GLenum format = srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    glTexImage2D(GL_TEXTURE_2D, 0, format, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    // The mip levels the CPU twin samples (shading/texture_sampling.h), not the driver's: an
    // sRGB image's averaged in linear light, as the assets contract asks.
    const std::vector<ImageLevel> levels = mipLevels(image.rgba.data(), image.width, image.height, srgb);
    for (size_t i = 0; i < levels.size(); ++i) {
        glTexImage2D(GL_TEXTURE_2D, GLint(i + 1), format, levels[i].width, levels[i].height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, levels[i].rgba.data());
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(levels.size()));
    glBindTexture(GL_TEXTURE_2D, 0);
    return id;
}
}  // namespace

GLint glWrap(TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
    case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
    case TextureWrap::Repeat: return GL_REPEAT;
    }
    return GL_REPEAT;
}

ModelTextures::~ModelTextures() {
    clear();
    for (const auto& [key, id] : samplers_) {
        glDeleteSamplers(1, &id);
    }
}

void ModelTextures::clear() {
    for (const auto& [key, id] : textures_) {
        glDeleteTextures(1, &id);
    }
    textures_.clear();
    model_.reset();
}

void ModelTextures::upload(std::shared_ptr<const Model> shown) {
    if (model_ == shown) {
        return;
    }
    clear();
    model_ = std::move(shown);
    if (!model_) {
        return;
    }
    const Model& model = *model_;
    for (const ModelMaterial& material : model.materials) {
        for (const auto& [slot, srgb, name, key] : mapsOf(material)) {
            const bool usable = slot->present() && size_t(slot->image) < model.images.size() &&
                                !model.images[size_t(slot->image)].rgba.empty();
            if (usable && !textures_.count({slot->image, srgb})) {
                textures_[{slot->image, srgb}] = uploadImage(model.images[size_t(slot->image)], srgb);
            }
        }
    }
}

GLuint ModelTextures::sampler(const TextureSampler& wanted) {
    const auto key = std::make_tuple(int(wanted.wrapS), int(wanted.wrapT), wanted.nearestMagnification,
                                     wanted.nearestMinification, wanted.mipmaps);
    if (const auto found = samplers_.find(key); found != samplers_.end()) {
        return found->second;
    }
    GLuint id = 0;
    glGenSamplers(1, &id);
    glSamplerParameteri(id, GL_TEXTURE_WRAP_S, glWrap(wanted.wrapS));
    glSamplerParameteri(id, GL_TEXTURE_WRAP_T, glWrap(wanted.wrapT));
    glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, wanted.nearestMagnification ? GL_NEAREST : GL_LINEAR);
    const GLint minification = wanted.mipmaps ? (wanted.nearestMinification ? GL_NEAREST_MIPMAP_LINEAR
                                                                            : GL_LINEAR_MIPMAP_LINEAR)
                                              : (wanted.nearestMinification ? GL_NEAREST : GL_LINEAR);
    glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, minification);
    samplers_[key] = id;
    return id;
}

bool ModelTextures::bind(int unit, const TextureSlot& slot, bool srgb) {
    const auto found = textures_.find({slot.image, srgb});
    if (!slot.present() || found == textures_.end()) {
        return false;
    }
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, found->second);
    glBindSampler(GLuint(unit), sampler(slot.sampler));
    return true;
}

}  // namespace patina
