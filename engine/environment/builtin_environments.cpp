#include "environment/builtin_environments.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <glm/geometric.hpp>

#include "shading/shading.h"

namespace patina {

namespace {
constexpr std::string_view kNames[] = {"studio", "white"};

float smoothstep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// A rectangular soft box seen from the centre: `halfWidth` and `halfHeight` the tangents of
// its half angles, the last 20% of each a soft falloff.
struct SoftBox {
    glm::vec3 towards;
    float halfWidth, halfHeight;
    float radiance;

    float at(glm::vec3 d) const {
        const glm::vec3 c = glm::normalize(towards);
        const float along = glm::dot(d, c);
        if (along <= 0.0f) {
            return 0.0f;
        }
        const glm::vec3 helper = std::abs(c.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 right = glm::normalize(glm::cross(helper, c));
        const glm::vec3 up = glm::cross(c, right);
        const float x = std::abs(glm::dot(d, right) / along) / halfWidth;
        const float y = std::abs(glm::dot(d, up) / along) / halfHeight;
        return radiance * (1.0f - smoothstep(0.8f, 1.0f, x)) * (1.0f - smoothstep(0.8f, 1.0f, y));
    }
};

HdrImage studio() {
    // The camera looks along -Z from +Z: the key is in front of the object, up and to the left.
    const SoftBox boxes[] = {
        {{-0.55f, 0.55f, 0.65f}, 0.42f, 0.30f, 6.0f},   // key
        {{0.85f, 0.15f, 0.35f}, 0.25f, 0.50f, 1.6f},    // fill
        {{0.0f, 1.0f, 0.05f}, 0.90f, 0.14f, 3.0f},      // overhead strip
        {{0.35f, 0.35f, -0.85f}, 0.16f, 0.42f, 4.0f},   // rim, behind
    };
    HdrImage image{512, 256, std::vector<float>(size_t(512) * 256 * 3)};
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 d = shader::equirectToDirection(
                glm::vec2((float(x) + 0.5f) / float(image.width), (float(y) + 0.5f) / float(image.height)));
            // A grey cyclorama: brighter towards the zenith, a soft horizon, a darker floor.
            const float sky = 0.30f + 0.25f * std::sqrt(std::max(d.y, 0.0f));
            const float floor = 0.10f + 0.04f * (1.0f + d.y);
            float value = d.y >= 0.0f ? sky : floor + (sky - floor) * smoothstep(-0.06f, 0.0f, d.y);
            for (const SoftBox& box : boxes) {
                value += box.at(d);
            }
            float* p = &image.rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3];
            p[0] = p[1] = p[2] = value;
        }
    }
    return image;
}
}  // namespace

std::span<const std::string_view> builtinEnvironmentNames() {
    return kNames;
}

std::optional<HdrImage> builtinEnvironment(std::string_view name) {
    if (name == "white") {
        return HdrImage{64, 32, std::vector<float>(size_t(64) * 32 * 3, 1.0f)};
    }
    if (name == "studio") {
        return studio();
    }
    return std::nullopt;
}

std::string environmentName(std::string_view source) {
    if (const auto name = builtinName(source)) {
        return std::string(*name);
    }
    return std::filesystem::path(source).stem().string();
}

}  // namespace patina
