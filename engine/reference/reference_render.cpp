#include "reference/reference_render.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "environment/environment.h"
#include "reference/probe_reference.h"
#include "reference/visibility.h"
#include "reference/reference_draws.h"
#include "shading/environment_brdf.h"

namespace patina {

namespace {
// What the renderer draws behind the mesh at (x, y): background.frag on the CPU.
glm::vec3 backgroundRadiance(const Scene& scene, const Environment* environment, const Light* light, int width,
                             int height, int x, int y) {
    if (!environment || !scene.display.backgroundFromEnvironment) {
        return scene.display.background;
    }
    const glm::vec2 rotation = environmentRotation(light->rotationDegrees);
    const glm::vec3 d =
        shader::toEnvironmentFrame(pixelRayDirection(scene.camera, width, height, x, y), rotation.x, rotation.y);
    return light->intensity *
           sampleCube(environment->prefiltered, d, shader::roughnessToLod(scene.display.backgroundBlur, environment->maxLod()));
}
}  // namespace

ReferenceImage renderReference(const PreparedScene& prepared, const PixelSurfaces& surfaces,
                               const ReferenceRenderOptions& options, const ReferencePassDone& passDone) {
    const Scene& scene = prepared.scene;
    const Light* light = enabledEnvironment(scene);
    const std::shared_ptr<const Environment> environment =
        light ? environmentShown(prepared.environment, light->source) : nullptr;
    const size_t pixels = size_t(surfaces.width) * size_t(surfaces.height);
    ReferenceImage image;
    image.value = {surfaces.width, surfaces.height, std::vector<float>(pixels * 3, 0.0f)};
    image.standardError = image.value;
    image.backdrop.assign(pixels, 0);
    for (int y = 0; y < surfaces.height; ++y) {
        for (int x = 0; x < surfaces.width; ++x) {
            const size_t pixel = size_t(y) * size_t(surfaces.width) + size_t(x);
            if (surfaces.sampleOfPixel[pixel] < 0) {
                const glm::vec3 b = backgroundRadiance(scene, environment.get(), light, surfaces.width, surfaces.height, x, y);
                std::copy(&b.x, &b.x + 3, &image.value.rgb[pixel * 3]);
                image.backdrop[pixel] = !environment || !scene.display.backgroundFromEnvironment;
            }
        }
    }
    // Per sample, the running sums of the pass means weighted by their counts, and of the squared
    // standard errors: independent passes, so the variance of the overall mean adds as
    // sum n_p^2 se_p^2 / N^2.
    std::vector<glm::dvec3> sum(surfaces.samples.size(), glm::dvec3(0.0)), variance = sum;
    // A textured model's samples each have their own material (surface_maps.h).
    const bool mapped = !surfaces.sampleMaterials.empty();
    std::vector<int32_t> ownMaterial;
    if (mapped) {
        ownMaterial.resize(surfaces.samples.size());
        std::iota(ownMaterial.begin(), ownMaterial.end(), 0);
    }
    std::optional<RayCaster> occluders;
    if (options.visibility) {
        // The model's triangles and the ground's, which the model's shadows fall on and which
        // hides what lies below it.
        std::vector<glm::vec3> positions = prepared.mesh->positions;
        std::vector<uint32_t> indices = prepared.mesh->indices;
        if (const std::optional<Mesh> ground = groundOf(prepared)) {
            const uint32_t first = uint32_t(positions.size());
            positions.insert(positions.end(), ground->positions.begin(), ground->positions.end());
            for (const uint32_t i : ground->indices) {
                indices.push_back(first + i);
            }
        }
        occluders.emplace(positions, indices);
    }
    const RayCaster* blocking = occluders ? &*occluders : nullptr;
    const int perPass = std::max(1, options.samplesPerPass);
    for (uint64_t pass = 0; image.samplesPerPixel < options.samplesPerPixel; ++pass) {
        const int n = std::min(perPass, options.samplesPerPixel - image.samplesPerPixel);
        std::vector<ReferenceRow> rows =
            mapped ? probeReference(surfaces.sampleMaterials, ownMaterial, scene.lights, surfaces.samples, environment, n,
                                    pass, surfaces.occlusion, blocking)
                   : probeReference(surfaces.materials, surfaces.drawOfSample, scene.lights, surfaces.samples,
                                    environment, n, pass, {}, blocking);
        for (size_t i = 0; i < surfaces.emission.size(); ++i) {
            rows[i].value += surfaces.emission[i];   // exact: no error added
        }
        image.samplesPerPixel += n;
        const double total = double(image.samplesPerPixel);
        for (size_t pixel = 0; pixel < pixels; ++pixel) {
            const int32_t i = surfaces.sampleOfPixel[pixel];
            if (i < 0) {
                continue;
            }
            sum[size_t(i)] += glm::dvec3(rows[size_t(i)].value) * double(n);
            const glm::dvec3 se(rows[size_t(i)].standardError);
            variance[size_t(i)] += se * se * double(n) * double(n);
            const glm::vec3 mean(sum[size_t(i)] / total), error(glm::sqrt(variance[size_t(i)]) / total);
            std::copy(&mean.x, &mean.x + 3, &image.value.rgb[pixel * 3]);
            std::copy(&error.x, &error.x + 3, &image.standardError.rgb[pixel * 3]);
        }
        if (passDone && !passDone(image)) {
            break;
        }
    }
    return image;
}

}  // namespace patina
