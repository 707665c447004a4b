#pragma once
// Helpers shared by the tests: the one headless GL context, conversions to the double
// reference, and seeded random directions.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "assets/asset_cache.h"
#include "gl/headless_context.h"
#include "gl/renderer.h"
#include "scene/probe.h"
#include "reference_shading.h"
#include "scene/scene.h"
#include "common/hdr_image.h"
#include "shading/shading.h"

namespace patina::test {

// Created on first use and kept for the whole test binary (contexts are slow to make).
HeadlessContext& glContext();

// One cache for the whole test binary, as a program owns one: built-ins are made once.
AssetCache& assetCache();
// `scene` with what it names loaded through assetCache() (assets/prepare_scene.h); refers to
// `scene`. Warnings are dropped.
PreparedScene prepared(const Scene& scene);
PreparedScene prepared(Scene&& scene) = delete;
// defaultScene(), prepared.
const PreparedScene& preparedDefault();
// An environment light's source ("builtin:studio") made ready through assetCache().
std::shared_ptr<const Environment> madeEnvironment(const std::string& source);

// A rectangle of half sides `halfWidth` and `halfHeight` in the xy plane around the origin,
// facing +z (counter-clockwise seen from there).
Mesh facingQuad(float halfWidth, float halfHeight);

// Two unit spheres at x = -1.2 ("left ball", material "left") and x = 1.2 ("right ball",
// material "right"): a model of two parts to pick between.
Model twoBalls();

// Pixel (x, y) of `image` (rows top first), and the pixel `point` lands in seen by `camera` in a
// width x height image.
glm::vec3 pixel(const HdrImage& image, int x, int y);
glm::ivec2 pixelOf(const Camera& camera, glm::vec3 point, int width, int height);
// The Rec. 709 luminance of the pixel `point` lands in, seen by `camera`.
float luminanceAt(const HdrImage& image, const Camera& camera, glm::vec3 point);

// One light of every type and the studio environment around the default scene's unit sphere:
// the scene the material layers' render tests draw (ClearcoatRender, SheenRender).
std::vector<Light> everyLightType();

// Default settings but for the image size, path and MSAA samples.
RenderSettings renderSettings(int width, int height, RenderPath passes, int samples);

// The default scene's unit sphere seen down -z from 3.4 units, lit by `light` alone: at the
// centre of the image N = V = +z (the layers' GPU-against-CPU-twin tests).
Scene sphereSeenDownZ(const Light& light);
// Blue, the strongest channel of the layers' bases, at the centre of a `size` x `size` render of
// `scene` (size odd) on `path`, one sample a pixel.
float centreBlue(Renderer& renderer, const Scene& scene, int size, RenderPath path);

reference::Vec3 toReference(glm::vec3 v);
reference::Material toReference(const Material& material);
std::vector<reference::Light> toReference(const std::vector<Light>& lights);

glm::vec3 randomUnitVector(std::mt19937& rng);
// A unit vector at `cosine` to the unit vector `axis` (to rounding), at a random azimuth.
glm::vec3 vectorAtCosine(glm::vec3 axis, float cosine, std::mt19937& rng);
glm::dvec3 vectorAtCosine(glm::dvec3 axis, double cosine, std::mt19937& rng);

// |a - b| / |b| per channel where |b| > floor; the largest one.
double maxRelativeError(const std::vector<glm::vec3>& values,
                        const std::vector<reference::Vec3>& reference, double floor);

// |a - b| / max(|b|, 0.01) over every channel of two images of one size: the largest.
double maxRelativeDifference(const HdrImage& a, const HdrImage& b);

// An equirect image of radiance `f(direction)` at its pixel centres (environment tests).
template <typename F>
HdrImage equirectOf(int width, int height, F f) {
    HdrImage image{width, height, std::vector<float>(size_t(width) * size_t(height) * 3)};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const glm::vec3 d = shader::equirectToDirection(
                glm::vec2((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)));
            const glm::vec3 value = f(d);
            for (int c = 0; c < 3; ++c) {
                image.rgb[(size_t(y) * size_t(width) + size_t(x)) * 3 + size_t(c)] = value[c];
            }
        }
    }
    return image;
}

// A flat (not run-length encoded) Radiance file of width x height pixels of one grey `level`
// (RGBE with exponent 129: level / 256 * 2).
std::filesystem::path writeFlatHdr(const std::filesystem::path& path, int width, int height, uint8_t level);

}  // namespace patina::test
