#include "test_support.h"

#include "assets/prepare_scene.h"
#include "common/luminance.h"
#include "scene/view.h"

#include <fstream>

#include <algorithm>

namespace patina::test {

HeadlessContext& glContext() {
    static HeadlessContext context;
    context.makeCurrent();
    return context;
}

reference::Vec3 toReference(glm::vec3 v) {
    return {double(v.x), double(v.y), double(v.z)};
}

reference::Material toReference(const Material& material) {
    return {toReference(material.baseColor), double(material.roughness),
            double(material.specular), double(material.metallic)};
}

std::vector<reference::Light> toReference(const std::vector<Light>& lights) {
    std::vector<reference::Light> result;
    for (const Light& light : lights) {
        if (!light.enabled) {
            continue;
        }
        reference::Light r{};
        r.type = light.type == LightType::Point         ? reference::Light::Point
                 : light.type == LightType::Directional ? reference::Light::Directional
                                                        : reference::Light::Hemisphere;
        r.color = toReference(light.color);
        r.intensity = light.intensity;
        r.position = toReference(light.position);
        r.range = light.range;
        r.ac = light.attenuation.x;
        r.al = light.attenuation.y;
        r.aq = light.attenuation.z;
        r.direction = toReference(light.direction);
        r.sky = toReference(light.sky);
        r.ground = toReference(light.ground);
        result.push_back(r);
    }
    return result;
}

AssetCache& assetCache() {
    static AssetCache cache;
    return cache;
}

PreparedScene prepared(const Scene& scene) {
    std::vector<std::string> warnings;
    return prepareScene(scene, assetCache(), warnings);
}

std::shared_ptr<const Environment> madeEnvironment(const std::string& source) {
    std::vector<std::string> warnings;
    return assetCache().environment(source, warnings);
}

const PreparedScene& preparedDefault() {
    static const Scene scene = defaultScene();
    static const PreparedScene prepared = test::prepared(scene);
    return prepared;
}

Model twoBalls() {
    Model model;
    model.primitives = {makeUvSphere(16, 32)};
    for (const char* name : {"left", "right"}) {
        ModelMaterial material;
        material.name = name;
        model.materials.push_back(material);
    }
    auto at = [](float x) {
        glm::mat4 transform(1.0f);
        transform[3] = glm::vec4(x, 0.0f, 0.0f, 1.0f);
        return transform;
    };
    model.draws = {{0, 0, at(-1.2f), "left ball"}, {0, 1, at(1.2f), "right ball"}};
    return model;
}

Mesh facingQuad(float halfWidth, float halfHeight) {
    Mesh quad;
    quad.positions = {{-halfWidth, -halfHeight, 0.0f},
                      {halfWidth, -halfHeight, 0.0f},
                      {halfWidth, halfHeight, 0.0f},
                      {-halfWidth, halfHeight, 0.0f}};
    quad.normals.assign(4, glm::vec3(0.0f, 0.0f, 1.0f));
    quad.indices = {0, 1, 2, 0, 2, 3};
    return quad;
}

glm::vec3 pixel(const HdrImage& image, int x, int y) {
    const size_t i = (size_t(y) * size_t(image.width) + size_t(x)) * 3;
    return {image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]};
}

glm::ivec2 pixelOf(const Camera& camera, glm::vec3 point, int width, int height) {
    const glm::vec4 clip = viewProjection(camera, float(width) / float(height)) * glm::vec4(point, 1.0f);
    return {int((clip.x / clip.w * 0.5f + 0.5f) * float(width)), int((0.5f - clip.y / clip.w * 0.5f) * float(height))};
}

float luminanceAt(const HdrImage& image, const Camera& camera, glm::vec3 point) {
    const glm::ivec2 at = pixelOf(camera, point, image.width, image.height);
    return luminance(pixel(image, at.x, at.y));
}

std::vector<Light> everyLightType() {
    Light point;
    point.type = LightType::Point;
    point.position = {1.5f, 1.0f, 2.0f};
    point.range = 8.0f;
    point.intensity = 4.0f;
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = {-0.4f, -0.5f, -1.0f};
    sun.intensity = 1.5f;
    Light sky;
    sky.type = LightType::Hemisphere;
    sky.sky = {0.2f, 0.2f, 0.3f};
    Light sphere;
    sphere.type = LightType::Sphere;
    sphere.position = {-1.5f, 1.2f, 1.5f};
    sphere.sourceRadius = 0.2f;
    sphere.intensity = 3.0f;
    Light tube;
    tube.type = LightType::Tube;
    tube.start = {1.0f, -0.8f, 1.8f};
    tube.end = {1.5f, 0.2f, 1.8f};
    tube.sourceRadius = 0.05f;
    tube.intensity = 2.0f;
    Light environment;
    environment.type = LightType::Environment;
    environment.source = "builtin:studio";
    environment.intensity = 0.5f;
    return {point, sun, sky, sphere, tube, environment};
}

double maxRelativeDifference(const HdrImage& a, const HdrImage& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        worst = std::max(worst, double(std::abs(a.rgb[i] - b.rgb[i])) / std::max(1e-2, double(std::abs(b.rgb[i]))));
    }
    return worst;
}

RenderSettings renderSettings(int width, int height, RenderPath passes, int samples) {
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.path = passes;
    settings.samples = samples;
    return settings;
}

Scene sphereSeenDownZ(const Light& light) {
    Scene scene = defaultScene();
    scene.camera.position = {0.0f, 0.0f, 3.4f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.lights = {light};
    return scene;
}

float centreBlue(Renderer& renderer, const Scene& scene, int size, RenderPath path) {
    const HdrImage image = renderer.render(prepared(scene), renderSettings(size, size, path, 1)).hdr;
    const int centre = size / 2;
    return image.rgb[size_t((centre * size + centre) * 3 + 2)];
}

glm::vec3 randomUnitVector(std::mt19937& rng) {
    std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
    for (;;) {
        const glm::vec3 v(uniform(rng), uniform(rng), uniform(rng));
        const float lengthSquared = glm::dot(v, v);
        if (lengthSquared > 1e-4f && lengthSquared <= 1.0f) {
            return v / std::sqrt(lengthSquared);
        }
    }
}

namespace {
template <typename Vec, typename Real>
Vec vectorAtCosineT(Vec axis, Real cosine, std::mt19937& rng) {
    Vec side = glm::cross(axis, Vec(randomUnitVector(rng)));
    while (glm::dot(side, side) < Real(1e-6)) {
        side = glm::cross(axis, Vec(randomUnitVector(rng)));
    }
    side = glm::normalize(side);
    const Real sine = std::sqrt(std::max(Real(0), Real(1) - cosine * cosine));
    return glm::normalize(cosine * axis + sine * side);
}
}  // namespace

glm::vec3 vectorAtCosine(glm::vec3 axis, float cosine, std::mt19937& rng) {
    return vectorAtCosineT(axis, cosine, rng);
}

glm::dvec3 vectorAtCosine(glm::dvec3 axis, double cosine, std::mt19937& rng) {
    return vectorAtCosineT(axis, cosine, rng);
}

double maxRelativeError(const std::vector<glm::vec3>& values,
                        const std::vector<reference::Vec3>& reference, double floor) {
    double worst = 0.0;
    for (size_t i = 0; i < values.size(); ++i) {
        const double expected[3] = {reference[i].x, reference[i].y, reference[i].z};
        for (int c = 0; c < 3; ++c) {
            if (std::abs(expected[c]) > floor) {
                worst = std::max(worst, std::abs(double(values[i][c]) - expected[c]) /
                                            std::abs(expected[c]));
            }
        }
    }
    return worst;
}

std::filesystem::path writeFlatHdr(const std::filesystem::path& path, int width, int height, uint8_t level) {
    std::ofstream out(path, std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n";
    for (int i = 0; i < width * height; ++i) {
        out << char(level) << char(level) << char(level) << char(129);
    }
    return path;
}

}  // namespace patina::test
