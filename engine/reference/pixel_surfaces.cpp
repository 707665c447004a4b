#include "reference/pixel_surfaces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include "model/placement.h"
#include "reference/surface_maps.h"
#include "scene/view.h"
#include "shading/shading.h"

namespace patina {

namespace {
struct ClipVertex {
    glm::vec4 clip;
    glm::vec3 position, normal;
    MapCoordinates maps;   // what mesh.vert hands on for a textured item
};

template <typename T>
T along(const T& a, const T& b, float t) {
    return a + (b - a) * t;
}

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, float t) {
    return {along(a.clip, b.clip, t), along(a.position, b.position, t), along(a.normal, b.normal, t),
            {along(a.maps.uv0, b.maps.uv0, t), along(a.maps.uv1, b.maps.uv1, t), along(a.maps.tangent, b.maps.tangent, t),
             along(a.maps.color, b.maps.color, t)}};
}

// The polygon's part in front of the near plane (z >= -w in GL clip space): Sutherland-Hodgman
// against that one plane. The others need no clipping: pixels outside the image are not visited.
std::vector<ClipVertex> clipToNearPlane(const std::vector<ClipVertex>& polygon) {
    std::vector<ClipVertex> kept;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const ClipVertex& a = polygon[i];
        const ClipVertex& b = polygon[(i + 1) % polygon.size()];
        const float da = a.clip.z + a.clip.w, db = b.clip.z + b.clip.w;
        if (da >= 0.0f) {
            kept.push_back(a);
        }
        if ((da >= 0.0f) != (db >= 0.0f)) {
            kept.push_back(lerp(a, b, da / (da - db)));
        }
    }
    return kept;
}
}  // namespace

namespace {
struct Hit {
    glm::vec3 position, normal;
    MapCoordinates maps;
    int32_t draw = -1;
};

// The nearest fragment of each pixel so far, as the depth test keeps it.
struct Raster {
    int width = 0, height = 0;
    std::vector<float> depth;
    std::vector<Hit> hits;
    const MapTextures* textures = nullptr;   // the model's maps, where an item has any
};

// One triangle (window coordinates, x right, y down) of draw item `draw` into `raster`: each
// pixel centre inside it whose depth is nearer than what is there and that MASK keeps. `area`
// is its signed area.
void fillTriangle(Raster& raster, const ClipVertex* const corner[3], const glm::vec2 screen[3], const float z[3],
                  const float inverseW[3], float area, const SceneDraw& item, int32_t draw, bool reverseNormal) {
    const float minX = std::min({screen[0].x, screen[1].x, screen[2].x});
    const float maxX = std::max({screen[0].x, screen[1].x, screen[2].x});
    const float minY = std::min({screen[0].y, screen[1].y, screen[2].y});
    const float maxY = std::max({screen[0].y, screen[1].y, screen[2].y});
    const int x0 = std::max(0, int(std::floor(minX))), x1 = std::min(raster.width - 1, int(std::ceil(maxX)));
    const int y0 = std::max(0, int(std::floor(minY))), y1 = std::min(raster.height - 1, int(std::ceil(maxY)));
    // The barycentric coordinates of window point p, and the perspective-correct weights of the
    // corners' attributes there (over w, interpolated, divided by 1/w).
    auto barycentric = [&](glm::vec2 p, float b[3]) {
        for (int c = 0; c < 3; ++c) {
            const glm::vec2& e0 = screen[(c + 1) % 3];
            const glm::vec2& e1 = screen[(c + 2) % 3];
            b[c] = ((e1.x - e0.x) * (p.y - e0.y) - (p.x - e0.x) * (e1.y - e0.y)) / area;
        }
    };
    auto weights = [&](const float b[3], float weight[3]) {
        const float w = b[0] * inverseW[0] + b[1] * inverseW[1] + b[2] * inverseW[2];
        for (int c = 0; c < 3; ++c) {
            weight[c] = b[c] * inverseW[c] / w;
        }
    };
    // The UVs on the triangle's plane at window point p (outside the triangle too).
    auto uvsAt = [&](glm::vec2 p) {
        float b[3], weight[3];
        barycentric(p, b);
        weights(b, weight);
        std::pair<glm::vec2, glm::vec2> uvs{glm::vec2(0.0f), glm::vec2(0.0f)};
        for (int c = 0; c < 3; ++c) {
            uvs.first += weight[c] * corner[c]->maps.uv0;
            uvs.second += weight[c] * corner[c]->maps.uv1;
        }
        return uvs;
    };
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            float b[3];
            barycentric(p, b);
            if (b[0] < 0.0f || b[1] < 0.0f || b[2] < 0.0f) {
                continue;
            }
            const size_t pixel = size_t(y) * size_t(raster.width) + size_t(x);
            const float d = b[0] * z[0] + b[1] * z[1] + b[2] * z[2];   // linear in screen space
            if (!(d < raster.depth[pixel]) || d > 1.0f) {
                continue;
            }
            float weight[3];
            weights(b, weight);
            Hit hit{glm::vec3(0.0f), glm::vec3(0.0f), {}, draw};
            hit.maps.color = glm::vec4(0.0f);
            for (int c = 0; c < 3; ++c) {
                hit.position += weight[c] * corner[c]->position;
                hit.normal += weight[c] * corner[c]->normal;
                hit.maps.uv0 += weight[c] * corner[c]->maps.uv0;
                hit.maps.uv1 += weight[c] * corner[c]->maps.uv1;
                hit.maps.tangent += weight[c] * corner[c]->maps.tangent;
                hit.maps.color += weight[c] * corner[c]->maps.color;
            }
            if (item.maps) {   // the UVs' change to the next pixel centre: the level of detail
                const auto [rightUv0, rightUv1] = uvsAt(p + glm::vec2(1.0f, 0.0f));
                const auto [downUv0, downUv1] = uvsAt(p + glm::vec2(0.0f, 1.0f));
                hit.maps.uv0Dx = rightUv0 - hit.maps.uv0;
                hit.maps.uv1Dx = rightUv1 - hit.maps.uv1;
                hit.maps.uv0Dy = downUv0 - hit.maps.uv0;
                hit.maps.uv1Dy = downUv1 - hit.maps.uv1;
            }
            if (raster.textures && !keptByMask(item, *raster.textures, hit.maps)) {
                continue;   // cut out: no depth written, what is behind shows
            }
            raster.depth[pixel] = d;
            if (reverseNormal) {
                hit.normal = -hit.normal;
            }
            raster.hits[pixel] = hit;
        }
    }
}

// The triangles of draw item `draw` into `raster`, placed as mesh.vert places them: the world
// position uModel * p, the clip position uViewProjection times that, the normal through the
// normal matrix.
void rasterizeDraw(Raster& raster, const SceneDraw& item, int32_t draw, const glm::mat4& viewProjection) {
    const Mesh& mesh = *item.mesh;
    const bool mirrored = mirrors(item.transform);
    const glm::mat3 linear(item.transform);
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::vector<ClipVertex> polygon;
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t i = mesh.indices[t + k];
            const glm::vec4 world = item.transform * glm::vec4(mesh.positions[i], 1.0f);
            ClipVertex vertex{viewProjection * world, glm::vec3(world), item.normalTransform * mesh.normals[i], {}};
            // As mesh.vert hands them on (with maps, or the tangent alone with anisotropy): the
            // tangent moves with the surface.
            if (item.maps || item.material.anisotropyStrength > 0.0f) {
                vertex.maps.uv0 = mesh.uv0.empty() ? glm::vec2(0.0f) : mesh.uv0[i];
                vertex.maps.uv1 = mesh.uv1.empty() ? glm::vec2(0.0f) : mesh.uv1[i];
                const glm::vec4 tangent = mesh.tangents.empty() ? glm::vec4(0.0f) : mesh.tangents[i];
                vertex.maps.tangent = glm::vec4(linear * glm::vec3(tangent), mirrored ? -tangent.w : tangent.w);
                vertex.maps.color = mesh.colors.empty() ? glm::vec4(1.0f) : mesh.colors[i];
            }
            polygon.push_back(vertex);
        }
        polygon = clipToNearPlane(polygon);
        // Fan triangles of the clipped polygon, in window coordinates (x right, y down).
        for (size_t k = 1; k + 1 < polygon.size(); ++k) {
            const ClipVertex* const corner[3] = {&polygon[0], &polygon[k], &polygon[k + 1]};
            glm::vec2 screen[3];
            float z[3], inverseW[3];
            for (int c = 0; c < 3; ++c) {
                inverseW[c] = 1.0f / corner[c]->clip.w;
                screen[c] = {(corner[c]->clip.x * inverseW[c] * 0.5f + 0.5f) * float(raster.width),
                             (0.5f - corner[c]->clip.y * inverseW[c] * 0.5f) * float(raster.height)};
                z[c] = corner[c]->clip.z * inverseW[c];
            }
            const float area = (screen[1].x - screen[0].x) * (screen[2].y - screen[0].y) -
                               (screen[2].x - screen[0].x) * (screen[1].y - screen[0].y);
            if (!(std::abs(area) > 0.0f)) {
                continue;
            }
            // Counter-clockwise in GL's window space (y up) is a negative area here (y down);
            // a mirroring transform makes clockwise the front (glTF 2.0 §3.7.2.1).
            const bool front = (area < 0.0f) != mirrored;
            if (!front && !item.doubleSided) {
                continue;   // glTF 2.0 §3.9.5: back faces culled
            }
            fillTriangle(raster, corner, screen, z, inverseW, area, item, draw, !front && item.reverseBackNormals);
        }
    }
}
}  // namespace

namespace {
// What the maps make of each sample (shade.frag's order: the normal unit and reversed on a back
// face first, then mapped); the sample's normal becomes the mapped one.
void mapSamples(PixelSurfaces& surfaces, const std::vector<SceneDraw>& draws, const MapTextures& textures,
                const Raster& raster) {
    const size_t count = surfaces.samples.size();
    surfaces.sampleMaterials.resize(count);
    surfaces.occlusion.assign(count, 1.0f);
    surfaces.emission.assign(count, glm::vec3(0.0f));
    surfaces.alpha.assign(count, 1.0f);
    surfaces.coordinates.assign(count, MapCoordinates{});
    for (size_t pixel = 0; pixel < surfaces.sampleOfPixel.size(); ++pixel) {
        const int32_t i = surfaces.sampleOfPixel[pixel];
        if (i < 0) {
            continue;
        }
        const Hit& hit = raster.hits[pixel];
        ProbeSample& sample = surfaces.samples[size_t(i)];
        const MappedSurface mapped =
            mappedSurface(draws[size_t(hit.draw)], textures, hit.maps, shader::safeNormalize(sample.normal));
        surfaces.sampleMaterials[size_t(i)] = mapped.material;
        surfaces.occlusion[size_t(i)] = mapped.occlusion;
        surfaces.emission[size_t(i)] = mapped.emission;
        surfaces.alpha[size_t(i)] = mapped.alpha;
        surfaces.coordinates[size_t(i)] = hit.maps;
        sample.normal = mapped.normal;
    }
}
}  // namespace

PixelSurfaces rasterizeSurfaces(const std::vector<SceneDraw>& draws, const Camera& camera, int width, int height,
                                const Model* model) {
    const size_t pixels = size_t(width) * size_t(height);
    const bool anyMaps =
        model && std::any_of(draws.begin(), draws.end(), [](const SceneDraw& draw) { return draw.maps != nullptr; });
    const std::optional<MapTextures> textures = anyMaps ? std::optional<MapTextures>(std::in_place, *model) : std::nullopt;
    Raster raster{width, height, std::vector<float>(pixels, std::numeric_limits<float>::infinity()),
                  std::vector<Hit>(pixels), textures ? &*textures : nullptr};
    const glm::mat4 viewProjection = patina::viewProjection(camera, float(width) / float(height));
    for (size_t d = 0; d < draws.size(); ++d) {
        rasterizeDraw(raster, draws[d], int32_t(d), viewProjection);
    }
    PixelSurfaces surfaces;
    surfaces.width = width;
    surfaces.height = height;
    surfaces.sampleOfPixel.assign(pixels, -1);
    for (const SceneDraw& draw : draws) {
        // The volume's thickness in world units, as the GPU scales it (uThicknessScale).
        MaterialParameters material = draw.material;
        material.thickness *= thicknessScaleOf(draw.transform);
        surfaces.materials.push_back(material);
    }
    for (size_t pixel = 0; pixel < pixels; ++pixel) {
        if (std::isfinite(raster.depth[pixel])) {
            surfaces.sampleOfPixel[pixel] = int32_t(surfaces.samples.size());
            const Hit& hit = raster.hits[pixel];
            surfaces.samples.push_back({hit.position, hit.normal, shader::safeNormalize(camera.position - hit.position)});
            surfaces.drawOfSample.push_back(hit.draw);
            surfaces.geometryNormals.push_back(shader::safeNormalize(hit.normal));
            surfaces.tangents.push_back(hit.maps.tangent);
        }
    }
    if (textures) {
        mapSamples(surfaces, draws, *textures, raster);
    }
    return surfaces;
}

PixelSurfaces rasterizeSurfaces(const PreparedScene& prepared, int width, int height) {
    return rasterizeSurfaces(sceneDraws(prepared), prepared.scene.camera, width, height, prepared.model.get());
}

glm::vec3 pixelRayDirection(const Camera& camera, int width, int height, int x, int y) {
    const glm::mat4 inverse = glm::inverse(viewProjection(camera, float(width) / float(height)));
    const glm::vec2 ndc((float(x) + 0.5f) / float(width) * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / float(height) * 2.0f);
    const glm::vec4 far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    return glm::normalize(glm::vec3(far) / far.w - camera.position);
}

}  // namespace patina
