#include "environment/cube_map.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "shading/shading.h"

namespace patina {

CubeLevel::CubeLevel(int faceSize) : size(faceSize) {
    for (std::vector<float>& face : faces) {
        face.assign(size_t(size) * size_t(size) * 3, 0.0f);
    }
}

glm::vec3 CubeLevel::texel(int face, int s, int t) const {
    const float* p = &faces[size_t(face)][(size_t(t) * size_t(size) + size_t(s)) * 3];
    return {p[0], p[1], p[2]};
}

void CubeLevel::setTexel(int face, int s, int t, glm::vec3 value) {
    float* p = &faces[size_t(face)][(size_t(t) * size_t(size) + size_t(s)) * 3];
    p[0] = value.x;
    p[1] = value.y;
    p[2] = value.z;
}

glm::vec3 cubeFaceDirection(int face, float sc, float tc) {
    return shader::cubeFaceDirection(face, sc, tc);
}

CubeCoordinate cubeCoordinate(glm::vec3 d) {
    const float ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
    int face;
    float sc, tc, ma;
    // Ties go to x, then y, as in Mesa; either face holds the same texel on an edge.
    if (ax >= ay && ax >= az) {
        face = d.x >= 0.0f ? 0 : 1;
        sc = d.x >= 0.0f ? -d.z : d.z;
        tc = -d.y;
        ma = ax;
    } else if (ay >= az) {
        face = d.y >= 0.0f ? 2 : 3;
        sc = d.x;
        tc = d.y >= 0.0f ? d.z : -d.z;
        ma = ay;
    } else {
        face = d.z >= 0.0f ? 4 : 5;
        sc = d.z >= 0.0f ? d.x : -d.x;
        tc = -d.y;
        ma = az;
    }
    if (!(ma > 0.0f)) {
        return {4, 0.5f, 0.5f};   // the zero vector: any texel is as good
    }
    return {face, 0.5f * (sc / ma + 1.0f), 0.5f * (tc / ma + 1.0f)};
}

glm::vec3 cubeTexelDirection(int face, int s, int t, int size) {
    const float sc = (float(s) + 0.5f) / float(size) * 2.0f - 1.0f;
    const float tc = (float(t) + 0.5f) / float(size) * 2.0f - 1.0f;
    return glm::normalize(cubeFaceDirection(face, sc, tc));
}

namespace {
// Texel (s, t) of `face`, which may lie one texel off the face: then the texel of the face that
// the direction through its centre falls on.
glm::vec3 seamlessTexel(const CubeLevel& level, int face, int s, int t) {
    const int n = level.size;
    if (s >= 0 && s < n && t >= 0 && t < n) {
        return level.texel(face, s, t);
    }
    const float sc = (float(s) + 0.5f) / float(n) * 2.0f - 1.0f;
    const float tc = (float(t) + 0.5f) / float(n) * 2.0f - 1.0f;
    const CubeCoordinate c = cubeCoordinate(cubeFaceDirection(face, sc, tc));
    const int s2 = std::clamp(int(c.s * float(n)), 0, n - 1);
    const int t2 = std::clamp(int(c.t * float(n)), 0, n - 1);
    return level.texel(c.face, s2, t2);
}
}  // namespace

glm::vec3 sampleCubeLevel(const CubeLevel& level, glm::vec3 direction) {
    const CubeCoordinate c = cubeCoordinate(direction);
    const float x = c.s * float(level.size) - 0.5f, y = c.t * float(level.size) - 0.5f;
    const float x0f = std::floor(x), y0f = std::floor(y);
    const int x0 = int(x0f), y0 = int(y0f);
    const float fx = x - x0f, fy = y - y0f;
    glm::vec3 a = seamlessTexel(level, c.face, x0, y0), b = seamlessTexel(level, c.face, x0 + 1, y0);
    glm::vec3 d = seamlessTexel(level, c.face, x0, y0 + 1), e = seamlessTexel(level, c.face, x0 + 1, y0 + 1);
    // At a cube corner three faces meet and the footprint's fourth texel is on none of them: it
    // is the average of the other three, as Mesa (and the GL spec's note on seamless cube maps) does.
    const int n = level.size;
    const bool offX0 = x0 < 0, offX1 = x0 + 1 >= n, offY0 = y0 < 0, offY1 = y0 + 1 >= n;
    if ((offX0 || offX1) && (offY0 || offY1)) {
        glm::vec3& corner = offX0 ? (offY0 ? a : d) : (offY0 ? b : e);
        corner = (a + b + d + e - corner) / 3.0f;
    }
    return (a * (1.0f - fx) + b * fx) * (1.0f - fy) + (d * (1.0f - fx) + e * fx) * fy;
}

glm::vec3 sampleCube(const CubeChain& chain, glm::vec3 direction, float lod) {
    const float maxLod = float(chain.size() - 1);
    lod = std::clamp(std::isfinite(lod) ? lod : 0.0f, 0.0f, maxLod);
    const int lower = int(lod);
    const float f = lod - float(lower);
    const glm::vec3 a = sampleCubeLevel(chain[size_t(lower)], direction);
    if (f == 0.0f || lower + 1 >= int(chain.size())) {
        return a;
    }
    return a * (1.0f - f) + sampleCubeLevel(chain[size_t(lower) + 1], direction) * f;
}

CubeChain cubeMipChain(CubeLevel base) {
    CubeChain chain;
    chain.push_back(std::move(base));
    while (chain.back().size > 1) {
        const CubeLevel& above = chain.back();
        CubeLevel level(above.size / 2);
        for (int face = 0; face < 6; ++face) {
            for (int t = 0; t < level.size; ++t) {
                for (int s = 0; s < level.size; ++s) {
                    const glm::vec3 sum = above.texel(face, 2 * s, 2 * t) + above.texel(face, 2 * s + 1, 2 * t) +
                                          above.texel(face, 2 * s, 2 * t + 1) +
                                          above.texel(face, 2 * s + 1, 2 * t + 1);
                    level.setTexel(face, s, t, sum * 0.25f);
                }
            }
        }
        chain.push_back(std::move(level));
    }
    return chain;
}

}  // namespace patina
