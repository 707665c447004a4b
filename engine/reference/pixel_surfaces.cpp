#include "reference/pixel_surfaces.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

#include "model/placement.h"
#include "scene/view.h"
#include "shading/shading.h"

namespace patina {

namespace {
struct ClipVertex {
    glm::vec4 clip;
    glm::vec3 position, normal;
};

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, float t) {
    return {a.clip + (b.clip - a.clip) * t, a.position + (b.position - a.position) * t,
            a.normal + (b.normal - a.normal) * t};
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
    int32_t draw = -1;
};

// The nearest fragment of each pixel so far, as the depth test keeps it.
struct Raster {
    int width = 0, height = 0;
    std::vector<float> depth;
    std::vector<Hit> hits;
};

// One triangle (window coordinates, x right, y down) of draw item `draw` into `raster`: each
// pixel centre inside it whose depth is nearer than what is there. `area` is its signed area.
void fillTriangle(Raster& raster, const ClipVertex* const corner[3], const glm::vec2 screen[3], const float z[3],
                  const float inverseW[3], float area, int32_t draw, bool reverseNormal) {
    const float minX = std::min({screen[0].x, screen[1].x, screen[2].x});
    const float maxX = std::max({screen[0].x, screen[1].x, screen[2].x});
    const float minY = std::min({screen[0].y, screen[1].y, screen[2].y});
    const float maxY = std::max({screen[0].y, screen[1].y, screen[2].y});
    const int x0 = std::max(0, int(std::floor(minX))), x1 = std::min(raster.width - 1, int(std::ceil(maxX)));
    const int y0 = std::max(0, int(std::floor(minY))), y1 = std::min(raster.height - 1, int(std::ceil(maxY)));
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
            float b[3];
            for (int c = 0; c < 3; ++c) {
                const glm::vec2& e0 = screen[(c + 1) % 3];
                const glm::vec2& e1 = screen[(c + 2) % 3];
                b[c] = ((e1.x - e0.x) * (p.y - e0.y) - (p.x - e0.x) * (e1.y - e0.y)) / area;
            }
            if (b[0] < 0.0f || b[1] < 0.0f || b[2] < 0.0f) {
                continue;
            }
            const size_t pixel = size_t(y) * size_t(raster.width) + size_t(x);
            const float d = b[0] * z[0] + b[1] * z[1] + b[2] * z[2];   // linear in screen space
            if (!(d < raster.depth[pixel]) || d > 1.0f) {
                continue;
            }
            raster.depth[pixel] = d;
            // Perspective-correct: attributes over w, interpolated, divided by 1/w.
            const float w = b[0] * inverseW[0] + b[1] * inverseW[1] + b[2] * inverseW[2];
            Hit hit{glm::vec3(0.0f), glm::vec3(0.0f), draw};
            for (int c = 0; c < 3; ++c) {
                const float weight = b[c] * inverseW[c] / w;
                hit.position += weight * corner[c]->position;
                hit.normal += weight * corner[c]->normal;
            }
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
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        std::vector<ClipVertex> polygon;
        for (size_t k = 0; k < 3; ++k) {
            const uint32_t i = mesh.indices[t + k];
            const glm::vec4 world = item.transform * glm::vec4(mesh.positions[i], 1.0f);
            polygon.push_back({viewProjection * world, glm::vec3(world), item.normalTransform * mesh.normals[i]});
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
            fillTriangle(raster, corner, screen, z, inverseW, area, draw, !front && item.reverseBackNormals);
        }
    }
}
}  // namespace

PixelSurfaces rasterizeSurfaces(const std::vector<SceneDraw>& draws, const Camera& camera, int width, int height) {
    const size_t pixels = size_t(width) * size_t(height);
    Raster raster{width, height, std::vector<float>(pixels, std::numeric_limits<float>::infinity()),
                  std::vector<Hit>(pixels)};
    const glm::mat4 viewProjection = patina::viewProjection(camera, float(width) / float(height));
    for (size_t d = 0; d < draws.size(); ++d) {
        rasterizeDraw(raster, draws[d], int32_t(d), viewProjection);
    }
    PixelSurfaces surfaces;
    surfaces.width = width;
    surfaces.height = height;
    surfaces.sampleOfPixel.assign(pixels, -1);
    for (const SceneDraw& draw : draws) {
        surfaces.materials.push_back(draw.material);
    }
    for (size_t pixel = 0; pixel < pixels; ++pixel) {
        if (std::isfinite(raster.depth[pixel])) {
            surfaces.sampleOfPixel[pixel] = int32_t(surfaces.samples.size());
            const Hit& hit = raster.hits[pixel];
            surfaces.samples.push_back({hit.position, hit.normal, shader::safeNormalize(camera.position - hit.position)});
            surfaces.drawOfSample.push_back(hit.draw);
        }
    }
    return surfaces;
}

PixelSurfaces rasterizeSurfaces(const PreparedScene& prepared, int width, int height) {
    return rasterizeSurfaces(sceneDraws(prepared), prepared.scene.camera, width, height);
}

glm::vec3 pixelRayDirection(const Camera& camera, int width, int height, int x, int y) {
    const glm::mat4 inverse = glm::inverse(viewProjection(camera, float(width) / float(height)));
    const glm::vec2 ndc((float(x) + 0.5f) / float(width) * 2.0f - 1.0f, 1.0f - (float(y) + 0.5f) / float(height) * 2.0f);
    const glm::vec4 far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    return glm::normalize(glm::vec3(far) / far.w - camera.position);
}

}  // namespace patina
