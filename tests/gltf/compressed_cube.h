#pragma once
// The test cube with texture coordinates, as a plain glTF, and meshes compared as triangle
// soups: what the compressed-mesh tests (Draco, meshopt, quantization) read back against.
#include <algorithm>
#include <array>
#include <vector>

#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "geometry/mesh.h"
#include "gltf_builder.h"

namespace patina::test {

// Each face's texture coordinates: the square's corners.
inline std::vector<glm::vec2> cubeUvs(const Cube& cube) {
    std::vector<glm::vec2> uvs;
    for (size_t i = 0; i < cube.positions.size(); ++i) {
        const int corner = int(i % 4);
        uvs.emplace_back(corner == 1 || corner == 2 ? 1.0f : 0.0f, corner >= 2 ? 1.0f : 0.0f);
    }
    return uvs;
}

// The cube uncompressed: positions, normals, UVs and 32-bit indices.
inline GltfBuilder plainCube(const Cube& cube, const std::vector<glm::vec2>& uvs) {
    GltfBuilder gltf;
    const int position = gltf.positions(cube.positions);
    const int normal = gltf.data(GltfBuilder::flatten(cube.normals), kFloat, "VEC3", 3);
    std::vector<float> uvNumbers;
    for (const glm::vec2& uv : uvs) {
        uvNumbers.insert(uvNumbers.end(), {uv.x, uv.y});
    }
    const int uv = gltf.data(uvNumbers, kFloat, "VEC2", 2);
    const int indices = gltf.data(cube.indices, kUnsignedInt, "SCALAR", 1);
    gltf.meshNode({{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}},
                   {"indices", indices}});
    return gltf;
}

// A mesh's triangles, each as its corners' position, normal and UV in winding order starting
// at its least corner, sorted: the same surface gives the same list whatever the order of its
// vertices and triangles (Draco's edgebreaker reorders both).
using Corner = std::array<float, 8>;
inline std::vector<std::array<Corner, 3>> triangleSoup(const Mesh& mesh) {
    std::vector<std::array<Corner, 3>> soup;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::array<Corner, 3> triangle;
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t v = mesh.indices[t + k];
            const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
            const glm::vec2 uv = mesh.uv0.empty() ? glm::vec2(0.0f) : mesh.uv0[v];
            triangle[k] = {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y};
        }
        std::rotate(triangle.begin(), std::min_element(triangle.begin(), triangle.end()), triangle.end());
        soup.push_back(triangle);
    }
    std::sort(soup.begin(), soup.end());
    return soup;
}

// Every number of two triangle soups alike within `tolerance`.
inline void expectNear(const std::vector<std::array<Corner, 3>>& a, const std::vector<std::array<Corner, 3>>& b,
                float tolerance) {
    ASSERT_EQ(a.size(), b.size());
    for (size_t t = 0; t < a.size(); ++t) {
        for (size_t k = 0; k < 3; ++k) {
            for (size_t i = 0; i < a[t][k].size(); ++i) {
                EXPECT_NEAR(a[t][k][i], b[t][k][i], tolerance) << "triangle " << t << " corner " << k << " number " << i;
            }
        }
    }
}

}  // namespace patina::test
