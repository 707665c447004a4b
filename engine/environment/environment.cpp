#include "environment/environment.h"

#include <algorithm>
#include <map>
#include <mutex>
#include <stdexcept>

#include "environment/builtin_environments.h"
#include "environment/equirect.h"
#include "shading/environment_brdf.h"

namespace patina {

std::shared_ptr<const Environment> prepareEnvironment(HdrImage image, std::string source,
                                                      const EnvironmentSettings& settings, const Progress& progress) {
    auto environment = std::make_shared<Environment>();
    environment->source = std::move(source);
    environment->settings = settings;
    environment->replacedPixels = replaceInvalidPixels(image);
    const CubeChain cube = cubeMipChain(equirectToCube(image, cubeFaceSizeFor(image.width)));
    environment->prefiltered = threadPrefilter()(cube, settings.prefilter, progress);
    if (environment->prefiltered.empty()) {
        return nullptr;
    }
    const ShCoefficients sh = projectSH(image);
    environment->sh = settings.windowSH ? windowSH(sh) : sh;
    environment->image = std::move(image);
    return environment;
}

namespace {
std::mutex builtinMutex;
std::map<std::string, std::shared_ptr<const Environment>> builtins;   // made with the default settings
}  // namespace

void adoptBuiltinEnvironment(const std::shared_ptr<const Environment>& environment) {
    if (environment && environment->source.starts_with("builtin:") && environment->settings == EnvironmentSettings{}) {
        std::lock_guard lock(builtinMutex);
        builtins.try_emplace(environment->source, environment);
    }
}

std::shared_ptr<const Environment> preparedBuiltinEnvironment(const std::string& source, bool make) {
    if (!source.starts_with("builtin:")) {
        return nullptr;
    }
    std::lock_guard lock(builtinMutex);
    if (!make) {
        const auto found = builtins.find(source);
        return found == builtins.end() ? nullptr : found->second;
    }
    std::map<std::string, std::shared_ptr<const Environment>>& prepared = builtins;
    std::shared_ptr<const Environment>& environment = prepared[source];
    if (!environment) {
        std::optional<HdrImage> image = builtinEnvironment(std::string_view(source).substr(8));
        if (!image) {
            prepared.erase(source);
            return nullptr;
        }
        environment = prepareEnvironment(std::move(*image), source);
    }
    return environment;
}

std::shared_ptr<const Environment> environmentShown(const std::shared_ptr<const Environment>& resolved,
                                                   const std::string& source) {
    if (resolved && resolved->source == source) {
        return resolved;
    }
    if (std::shared_ptr<const Environment> builtin = preparedBuiltinEnvironment(source)) {
        return builtin;
    }
    throw std::invalid_argument("the environment " + source + " was never loaded (resolveEnvironment)");
}

glm::vec3 shadeEnvironmentOnCpu(BrdfModelId model, const shader::SurfaceMaterial& material, const Environment& environment,
                                float intensity, float rotationDegrees, glm::vec3 N, glm::vec3 V, bool dominant) {
    const std::function<glm::vec3(glm::vec3, float)> read = [&](glm::vec3 d, float lod) {
        return sampleCube(environment.prefiltered, d, lod);
    };
    glm::vec3 sh[9];
    std::copy(environment.sh.begin(), environment.sh.end(), sh);
    return shadeEnvironment(model, read, environment.maxLod(), sh, intensity, rotationDegrees, material, N, V, dominant);
}

glm::vec3 stochasticEnvironmentOnCpu(BrdfModelId model, const shader::SurfaceMaterial& material,
                                     const Environment& environment, const CubeChain& sourceChain, float intensity,
                                     float rotationDegrees, glm::vec3 N, glm::vec3 V, unsigned count,
                                     glm::vec2 jitter) {
    const std::function<glm::vec3(glm::vec3, float)> read = [&](glm::vec3 d, float lod) {
        return sampleCube(sourceChain, d, lod);
    };
    glm::vec3 sh[9];
    std::copy(environment.sh.begin(), environment.sh.end(), sh);
    return shadeEnvironmentStochastic(model, read, float(sourceChain.front().size), sh, intensity, rotationDegrees,
                                      material, N, V, count, jitter);
}

CubeChain sourceMipChain(const Environment& environment) {
    return cubeMipChain(equirectToCube(environment.image, environment.prefiltered.front().size));
}

}  // namespace patina
