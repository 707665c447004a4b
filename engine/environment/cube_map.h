#pragma once
#include <array>
#include <vector>

#include <glm/vec3.hpp>

namespace patina {

// One mip of a cube map as OpenGL lays it out: faces +X, -X, +Y, -Y, +Z, -Z (the order of
// GL_TEXTURE_CUBE_MAP_POSITIVE_X + i), each size x size RGB floats, row t = 0 first.
struct CubeLevel {
    int size = 0;
    std::array<std::vector<float>, 6> faces;

    explicit CubeLevel(int faceSize = 0);
    glm::vec3 texel(int face, int s, int t) const;
    void setTexel(int face, int s, int t, glm::vec3 value);
};

// Mip 0 first, each level half the size of the one before.
using CubeChain = std::vector<CubeLevel>;

// The direction through face coordinates (sc, tc) in [-1, 1] (OpenGL 4.5 core, table 8.19,
// inverted), not normalised, and the face and (s, t) in [0, 1] a direction falls on.
glm::vec3 cubeFaceDirection(int face, float sc, float tc);
struct CubeCoordinate {
    int face;
    float s, t;
};
CubeCoordinate cubeCoordinate(glm::vec3 direction);
// The direction through the centre of texel (s, t) of a face of `size` texels, normalised.
glm::vec3 cubeTexelDirection(int face, int s, int t, int size);

// Bilinear filtering within a level, seamless across faces as with
// GL_TEXTURE_CUBE_MAP_SEAMLESS: a neighbour off the face's edge is read from the face next to
// it. Trilinear between levels at a fractional lod, clamped to the chain.
glm::vec3 sampleCubeLevel(const CubeLevel& level, glm::vec3 direction);
glm::vec3 sampleCube(const CubeChain& chain, glm::vec3 direction, float lod);

// Each level the 2x2 box average of the one before, down to 1 texel (as glGenerateMipmap).
CubeChain cubeMipChain(CubeLevel base);

}  // namespace patina
