#include "reference/reference_render.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "environment/environment.h"
#include "reference/probe_reference.h"
#include "reference/visibility.h"
#include "reference/reference_draws.h"
#include "common/luminance.h"
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

namespace {
// The background at every pixel no item covers (and at the shadow catcher's, which darkens it).
void drawBackground(ReferenceImage& image, const Scene& scene, const Environment* environment, const Light* light,
                    const PixelSurfaces& surfaces, int32_t catcher) {
    for (int y = 0; y < surfaces.height; ++y) {
        for (int x = 0; x < surfaces.width; ++x) {
            const size_t pixel = size_t(y) * size_t(surfaces.width) + size_t(x);
            const int32_t i = surfaces.sampleOfPixel[pixel];
            if (i < 0 || surfaces.drawOfSample[size_t(i)] == catcher) {
                const glm::vec3 b = backgroundRadiance(scene, environment, light, surfaces.width, surfaces.height, x, y);
                std::copy(&b.x, &b.x + 3, &image.value.rgb[pixel * 3]);
                image.backdrop[pixel] = !environment || !scene.display.backgroundFromEnvironment;
            }
        }
    }
}

// The model's triangles and the ground's, which the model's shadows fall on and which hides
// what lies below it.
void makeOccluders(std::optional<RayCaster>& occluders, const PreparedScene& prepared) {
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

// The shadow catcher's samples, shaded a second time without visibility: the share of its
// material's light that its shadows leave (luminance over luminance, as shade.frag's
// PATINA_SHADOW_CATCHER takes it, the environment in both) darkens the background behind it.
struct CatcherSamples {
    std::vector<int32_t> ofSample;              // per sample, its index here; -1 off the catcher
    std::vector<ProbeSample> samples;
    std::vector<MaterialParameters> materials;   // each one's own
    std::vector<int32_t> own;
    std::vector<glm::dvec3> open;               // the running sums without visibility
};

CatcherSamples catcherSamples(const PixelSurfaces& surfaces, int32_t catcher) {
    CatcherSamples c;
    c.ofSample.assign(surfaces.samples.size(), -1);
    for (size_t i = 0; i < surfaces.samples.size() && catcher >= 0; ++i) {
        if (surfaces.drawOfSample[i] == catcher) {
            c.ofSample[i] = int32_t(c.samples.size());
            c.own.push_back(int32_t(c.samples.size()));
            c.samples.push_back(surfaces.samples[i]);
            c.materials.push_back(surfaces.sampleMaterials.empty() ? surfaces.materials[size_t(catcher)]
                                                                   : surfaces.sampleMaterials[i]);
        }
    }
    c.open.assign(c.samples.size(), glm::dvec3(0.0));
    return c;
}

// The background at `pixel` (drawBackground's) times the share its catcher sample's shadows
// leave, from the running sums with and without visibility.
glm::vec3 caughtBackground(const HdrImage& behind, size_t pixel, glm::dvec3 shadowed, glm::dvec3 open) {
    const glm::vec3 background(behind.rgb[pixel * 3], behind.rgb[pixel * 3 + 1], behind.rgb[pixel * 3 + 2]);
    const double unshadowed = luminance(open);
    return unshadowed > 0.0 && luminance(shadowed) < unshadowed ? background * float(std::clamp(luminance(shadowed) / unshadowed, 0.0, 1.0)) : background;
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
    const int32_t catcher = catcherDraw(prepared, surfaces.materials.size());
    drawBackground(image, scene, environment.get(), light, surfaces, catcher);
    const HdrImage background = catcher >= 0 ? image.value : HdrImage{};   // behind the catcher
    CatcherSamples caught = catcherSamples(surfaces, catcher);
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
        makeOccluders(occluders, prepared);
    }
    const RayCaster* blocking = occluders ? &*occluders : nullptr;
    const int perPass = std::max(1, options.samplesPerPass);
    for (uint64_t pass = 0; image.samplesPerPixel < options.samplesPerPixel; ++pass) {
        const int n = std::min(perPass, options.samplesPerPixel - image.samplesPerPixel);
        std::vector<ReferenceRow> rows =
            mapped ? probeReference(surfaces.sampleMaterials, ownMaterial, scene.lights, surfaces.samples, environment, n,
                                    pass, surfaces.occlusion, blocking, surfaces.tangents)
                   : probeReference(surfaces.materials, surfaces.drawOfSample, scene.lights, surfaces.samples,
                                    environment, n, pass, {}, blocking, surfaces.tangents);
        const std::vector<ReferenceRow> open =
            caught.samples.empty() || !blocking ? std::vector<ReferenceRow>()   // without shadows: the background
                                   : probeReference(caught.materials, caught.own, scene.lights, caught.samples,
                                                    environment, n, pass);
        for (size_t i = 0; i < surfaces.emission.size(); ++i) {
            rows[i].value += surfaces.emission[i];   // exact: no error added
        }
        for (size_t j = 0; j < open.size(); ++j) {
            caught.open[j] += glm::dvec3(open[j].value) * double(n);
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
            const int32_t j = caught.ofSample[size_t(i)];
            const glm::vec3 shown =
                j < 0 ? mean : caughtBackground(background, pixel, sum[size_t(i)], caught.open[size_t(j)]);
            std::copy(&shown.x, &shown.x + 3, &image.value.rgb[pixel * 3]);
            std::copy(&error.x, &error.x + 3, &image.standardError.rgb[pixel * 3]);
        }
        if (passDone && !passDone(image)) {
            break;
        }
    }
    return image;
}

}  // namespace patina
