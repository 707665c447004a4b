#include "accuracy/model_split_sum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>

#include "common/luminance.h"
#include "common/parallel_for.h"
#include "environment/environment.h"
#include "reference/radiance.h"
#include "shading/brdf_models.h"
#include "shading/cpu_shading.h"

namespace patina {

namespace {
struct NamedMaterial {
    const char* name;
    glm::vec3 baseColor;
    float metallic;
};
constexpr NamedMaterial kMaterials[] = {{"grey dielectric", glm::vec3(0.5f), 0.0f},
                                        {"white metal", glm::vec3(1.0f), 1.0f}};

struct Grid {
    std::vector<glm::vec3> normals;
    std::vector<float> NoV, roughness;
    int samples;
};

Grid gridFor(bool quick) {
    if (quick) {
        return {spreadNormals(4), {0.4f, 0.9f}, {0.2f, 0.6f, 1.0f}, 256};
    }
    return {spreadNormals(8), {0.2f, 0.5f, 0.8f, 1.0f}, {0.1f, 0.3f, 0.5f, 0.7f, 0.9f, 1.0f}, 2048};
}

struct PointError {
    double signedError = 0.0, truthSe = 0.0;
};
}  // namespace

std::vector<std::string> modelSplitSumMaterials() {
    std::vector<std::string> names;
    for (const NamedMaterial& material : kMaterials) {
        names.emplace_back(material.name);
    }
    return names;
}

std::vector<ModelSplitSumRow> measureModelSplitSum(const std::vector<NamedEnvironment>& environments,
                                                   const std::vector<BrdfModelId>& models, bool quick) {
    const Grid grid = gridFor(quick);
    std::vector<ModelSplitSumRow> rows;
    for (const NamedEnvironment& named : environments) {
        const Environment& environment = *named.environment;
        const EnvironmentDistribution distribution(environment.image);
        const ReferenceEnvironment reference{&environment, &distribution, 1.0f, 0.0f};
        for (BrdfModelId model : models) {
            for (const NamedMaterial& material : kMaterials) {
                for (float roughness : grid.roughness) {
                    const shader::SurfaceMaterial surface =
                        shader::deriveSurfaceMaterial(material.baseColor, roughness, 0.5f, material.metallic);
                    const size_t count = grid.normals.size() * grid.NoV.size();
                    std::vector<PointError> points(count);
                    parallelFor(count, [&](size_t i) {
                        const size_t n = i / grid.NoV.size();
                        const glm::vec3 N = grid.normals[n];
                        const glm::vec3 V = viewAt(N, grid.NoV[i % grid.NoV.size()], int(n));
                        const float product =
                            luminance(shadeEnvironmentOnCpu(model, surface, environment, 1.0f, 0.0f, N, V));
                        ReferenceOptions options;
                        options.samples = grid.samples;
                        options.seed = 0x2545F4914F6CDD1Dull * (i + 1);
                        const ReferenceEstimate truth = referenceRadiance(model, surface, reference, {}, glm::vec3(0.0f),
                                                                          N, V, options);
                        const double value = std::max(double(luminance(truth.value)), 1e-9);
                        points[i] = {(product - value) / value, luminance(truth.standardError) / value};
                    });
                    ModelSplitSumRow row{named.name, std::string(brdfModel(model).name), material.name, roughness};
                    for (const PointError& p : points) {
                        row.meanSignedError += p.signedError / double(count);
                        row.meanRelativeError += std::abs(p.signedError) / double(count);
                        row.truthRelativeStandardError += p.truthSe / double(count);
                    }
                    rows.push_back(row);
                }
            }
        }
    }
    return rows;
}

std::string modelSplitSumCsv(const std::vector<ModelSplitSumRow>& rows) {
    std::string csv = "environment,model,material,roughness,mean_signed_error,mean_relative_error,truth_relative_se\n";
    char line[320];
    for (const ModelSplitSumRow& r : rows) {
        std::snprintf(line, sizeof line, "\"%s\",%s,%s,%.3g,%.6f,%.6f,%.6f\n", r.environment.c_str(), r.model.c_str(),
                      r.material.c_str(), double(r.roughness), r.meanSignedError, r.meanRelativeError,
                      r.truthRelativeStandardError);
        csv += line;
    }
    return csv;
}

}  // namespace patina
