#include "gl/environment_texture.h"

#include <epoxy/gl.h>

namespace patina {

EnvironmentTexture::~EnvironmentTexture() {
    glDeleteTextures(1, &prefiltered_.texture);
    glDeleteTextures(1, &irradiance_.texture);
    glDeleteTextures(1, &source_.texture);
}

unsigned uploadCubeChain(const CubeChain& chain) {
    unsigned texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_CUBE_MAP, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (size_t level = 0; level < chain.size(); ++level) {
        for (int face = 0; face < 6; ++face) {
            glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), GLint(level), GL_RGB32F, chain[level].size,
                         chain[level].size, 0, GL_RGB, GL_FLOAT, chain[level].faces[size_t(face)].data());
        }
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, GLint(chain.size() - 1));
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R}) {
        glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
    }
    // A cube map filtered face by face shows its seams, more the rougher the level (docs/LIGHTING.md L5).
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    return texture;
}

void EnvironmentTexture::bindCube(Cube& cube, const std::shared_ptr<const Environment>& environment, int unit,
                                  CubeChain (*chainOf)(const Environment&)) {
    glActiveTexture(GLenum(GL_TEXTURE0 + unit));
    if (environment != cube.shown) {
        glDeleteTextures(1, &cube.texture);
        cube.texture = uploadCubeChain(chainOf(*environment));
        cube.shown = environment;
    } else {
        glBindTexture(GL_TEXTURE_CUBE_MAP, cube.texture);
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    }
    glActiveTexture(GL_TEXTURE0);
}

void EnvironmentTexture::bind(const std::shared_ptr<const Environment>& environment, int unit, int irradianceUnit) {
    bindCube(prefiltered_, environment, unit, [](const Environment& e) { return e.prefiltered; });
    bindCube(irradiance_, environment, irradianceUnit, [](const Environment& e) { return CubeChain{e.irradiance}; });
}

void EnvironmentTexture::bindSource(const std::shared_ptr<const Environment>& environment, int unit) {
    bindCube(source_, environment, unit, sourceMipChain);
}

}  // namespace patina
