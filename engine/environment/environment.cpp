#include "environment/environment.h"

#include <algorithm>
#include <stdexcept>

#include "environment/equirect.h"
#include "shading/environment_brdf.h"

namespace patina {

std::shared_ptr<const Environment> prepareEnvironment(HdrImage image, std::string source,
                                                      const EnvironmentSettings& settings, const Progress& progress,
                                                      PrefilterFunction prefilter) {
    auto environment = std::make_shared<Environment>();
    environment->source = std::move(source);
    environment->settings = settings;
    environment->replacedPixels = replaceInvalidPixels(image);
    const CubeChain cube = cubeMipChain(equirectToCube(image, cubeFaceSizeFor(image.width)));
    environment->prefiltered = prefilter(cube, settings.prefilter, progress);
    if (environment->prefiltered.empty()) {
        return nullptr;
    }
    environment->irradiance = irradianceCube(image);
    environment->image = std::move(image);
    return environment;
}

std::shared_ptr<const Environment> environmentShown(const std::shared_ptr<const Environment>& prepared,
                                                   const std::string& source) {
    if (prepared && prepared->source == source) {
        return prepared;
    }
    throw std::invalid_argument("the environment " + source + " was not prepared for this scene (assets/)");
}

glm::vec3 shadeEnvironmentOnCpu(BrdfModelId model, const shader::SurfaceMaterial& material, const Environment& environment,
                                float intensity, float rotationDegrees, glm::vec3 N, glm::vec3 V, bool dominant) {
    const std::function<glm::vec3(glm::vec3, float)> read = [&](glm::vec3 d, float lod) {
        return sampleCube(environment.prefiltered, d, lod);
    };
    return shadeEnvironment(model, read, environment.maxLod(), irradianceReader(environment), intensity, rotationDegrees,
                            material, N, V, dominant);
}

glm::vec3 transmissionEnvironmentOnCpu(BrdfModelId model, const shader::SurfaceMaterial& material,
                                       const shader::Transmission& transmission, const Environment& environment,
                                       float intensity, float rotationDegrees, glm::vec3 V) {
    const std::function<glm::vec3(glm::vec3, float)> read = [&](glm::vec3 d, float lod) {
        return sampleCube(environment.prefiltered, d, lod);
    };
    return transmissionEnvironment(model, read, environment.maxLod(), intensity, rotationDegrees, material, transmission,
                                   V);
}

glm::vec3 stochasticEnvironmentOnCpu(BrdfModelId model, const shader::SurfaceMaterial& material,
                                     const Environment& environment, const CubeChain& sourceChain, float intensity,
                                     float rotationDegrees, glm::vec3 N, glm::vec3 V, unsigned count,
                                     glm::vec2 jitter) {
    const std::function<glm::vec3(glm::vec3, float)> read = [&](glm::vec3 d, float lod) {
        return sampleCube(sourceChain, d, lod);
    };
    return shadeEnvironmentStochastic(model, read, float(sourceChain.front().size), irradianceReader(environment),
                                      intensity, rotationDegrees, material, N, V, count, jitter);
}

std::function<glm::vec3(glm::vec3, float)> irradianceReader(const Environment& environment) {
    return [&environment](glm::vec3 n, float) { return sampleCubeLevel(environment.irradiance, n); };
}

CubeChain sourceMipChain(const Environment& environment) {
    return cubeMipChain(equirectToCube(environment.image, environment.prefiltered.front().size));
}

}  // namespace patina
