// KHR_materials_specular and _ior on the GPU (shade.frag's PATINA_SPECULAR): a tinted F0 and a
// weighted Fresnel (shader::withSpecular) shade on the GPU as the same code on the CPU, under
// every light type and under the studio environment's split sum, for glTF's model and the seed's;
// the three paths draw it alike, on a base and through a transmission, and it changes the picture.
// KHR_materials_iridescence's thin film (PATINA_IRIDESCENCE) likewise.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "gl/gpu_probe.h"
#include "gl/renderer.h"
#include "shading/brdf_models.h"
#include "scene/probe.h"
#include "test_support.h"

namespace patina {
namespace {

Material tinted(BrdfModelId model, glm::vec3 tint, float weight, float metallic) {
    Material material;
    material.model = model;
    material.baseColor = {0.7f, 0.3f, 0.2f};
    material.roughness = 0.35f;
    material.specular = 1.0f;
    material.metallic = metallic;
    material.specularTint = tint;
    material.specularWeight = weight;
    return material;
}

std::vector<ProbeSample> probes(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<ProbeSample> samples;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 N = test::randomUnitVector(rng);
        const glm::vec3 V = test::vectorAtCosine(N, 0.05f + 0.95f * unit(rng), rng);
        samples.push_back({2.0f * test::randomUnitVector(rng), N, V});
    }
    return samples;
}

double gpuAgainstCpu(GpuProbe& probe, const Material& material, const std::vector<Light>& lights,
                     const std::shared_ptr<const Environment>& environment) {
    const std::vector<ProbeSample> samples = probes(256, 11);
    const std::vector<glm::vec3> gpu = probe.evaluate(material, lights, samples, environment);
    const std::vector<glm::vec3> cpu = probeOnCpu(material, lights, samples, environment);
    std::vector<reference::Vec3> expected;
    for (const glm::vec3& c : cpu) {
        expected.push_back(test::toReference(c));
    }
    return test::maxRelativeError(gpu, expected, 1e-3);
}

Light studioLight() {
    Light studio;
    studio.type = LightType::Environment;
    studio.source = "builtin:studio";
    return studio;
}

// Under every light type, and under the studio environment alone: the GPU is the CPU twin.
void expectTheGpuIsTheTwin(GpuProbe& probe, const Material& material) {
    const Light studio = studioLight();
    const auto environment = test::madeEnvironment(studio.source);
    EXPECT_LE(gpuAgainstCpu(probe, material, test::everyLightType(), environment), 1e-4);
    EXPECT_LE(gpuAgainstCpu(probe, material, {studio}, environment), 1e-4);
}

TEST(SpecularRender, TheGpuIsTheCpuTwinUnderEveryLightAndTheEnvironment) {
    test::glContext();
    GpuProbe probe;
    const Light studio = studioLight();
    const auto environment = test::madeEnvironment(studio.source);
    for (BrdfModelId model : {BrdfModelId::Gltf, BrdfModelId::Epic}) {
        for (const Material& material : {tinted(model, {3.0f, 1.0f, 0.2f}, 0.6f, 0.0f),
                                         tinted(model, {0.4f, 1.0f, 0.7f}, 1.0f, 0.5f),
                                         tinted(model, glm::vec3(1.0f), 0.0f, 0.0f)}) {
            SCOPED_TRACE(std::string(brdfModel(model).name) + " weight " + std::to_string(material.specularWeight));
            expectTheGpuIsTheTwin(probe, material);
            // And it is not the untinted material's light.
            Material plain = material;
            plain.specularTint = glm::vec3(1.0f);
            plain.specularWeight = 1.0f;
            const std::vector<ProbeSample> samples = probes(64, 3);
            const std::vector<glm::vec3> a = probe.evaluate(material, {studio}, samples, environment);
            const std::vector<glm::vec3> b = probe.evaluate(plain, {studio}, samples, environment);
            double largest = 0.0;
            for (size_t i = 0; i < a.size(); ++i) {
                largest = std::max(largest, double(glm::length(a[i] - b[i]) / std::max(glm::length(b[i]), 1e-3f)));
            }
            EXPECT_GT(largest, 0.02);
        }
    }
}

TEST(SpecularRender, TheThreePathsDrawItAlikeOnABaseAndThroughAWall) {
    test::glContext();
    Renderer renderer;
    for (float transmission : {0.0f, 1.0f}) {
        Scene scene = defaultScene();
        scene.lights = test::everyLightType();
        scene.material = tinted(BrdfModelId::Gltf, {2.5f, 1.0f, 0.3f}, 0.7f, 0.0f);
        scene.material.transmission = transmission;
        const HdrImage single =
            renderer.render(test::prepared(scene), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
        for (RenderPath path : {RenderPath::Multi, RenderPath::Specialised}) {
            const HdrImage other = renderer.render(test::prepared(scene), test::renderSettings(64, 64, path, 1)).hdr;
            EXPECT_LE(test::maxRelativeDifference(other, single), 1e-4) << renderPathName(path) << " " << transmission;
        }
        Scene plain = scene;
        plain.material.specularTint = glm::vec3(1.0f);
        plain.material.specularWeight = 1.0f;
        const HdrImage bare =
            renderer.render(test::prepared(plain), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
        EXPECT_GT(test::maxRelativeDifference(single, bare), 0.05) << transmission;
    }
}

Material filmed(BrdfModelId model, float metallic, float thickness) {
    Material material = tinted(model, glm::vec3(1.0f), 1.0f, metallic);
    material.iridescence = 0.8f;
    material.iridescenceIor = 1.6f;
    material.iridescenceThicknessMaximum = thickness;
    return material;
}

TEST(IridescenceRender, TheGpuIsTheCpuTwinUnderEveryLightAndTheEnvironment) {
    test::glContext();
    GpuProbe probe;
    for (BrdfModelId model : {BrdfModelId::Gltf, BrdfModelId::Epic}) {
        for (const Material& material : {filmed(model, 0.0f, 300.0f), filmed(model, 1.0f, 650.0f),
                                         filmed(model, 0.4f, 120.0f)}) {
            SCOPED_TRACE(std::string(brdfModel(model).name) + " metallic " + std::to_string(material.metallic));
            expectTheGpuIsTheTwin(probe, material);
        }
    }
}

TEST(IridescenceRender, TheThreePathsDrawItAlikeAndItColoursThePicture) {
    test::glContext();
    Renderer renderer;
    Scene scene = defaultScene();
    scene.lights = test::everyLightType();
    scene.material = filmed(BrdfModelId::Gltf, 1.0f, 500.0f);
    const HdrImage single = renderer.render(test::prepared(scene), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
    for (RenderPath path : {RenderPath::Multi, RenderPath::Specialised}) {
        const HdrImage other = renderer.render(test::prepared(scene), test::renderSettings(64, 64, path, 1)).hdr;
        EXPECT_LE(test::maxRelativeDifference(other, single), 1e-4) << renderPathName(path);
    }
    Scene plain = scene;
    plain.material.iridescence = 0.0f;
    const HdrImage bare = renderer.render(test::prepared(plain), test::renderSettings(64, 64, RenderPath::Single, 1)).hdr;
    EXPECT_GT(test::maxRelativeDifference(single, bare), 0.05);
    // A strength of 0 is none (hasIridescence): the bare program, the same bytes, whatever the film.
    Scene none = plain;
    none.material.iridescenceIor = 2.0f;
    none.material.iridescenceThicknessMaximum = 900.0f;
    for (RenderPath path : {RenderPath::Single, RenderPath::Specialised}) {
        const HdrImage a = renderer.render(test::prepared(none), test::renderSettings(48, 48, path, 1)).hdr;
        const HdrImage b = renderer.render(test::prepared(plain), test::renderSettings(48, 48, path, 1)).hdr;
        EXPECT_EQ(a.rgb, b.rgb) << renderPathName(path);
    }
}

}  // namespace
}  // namespace patina
