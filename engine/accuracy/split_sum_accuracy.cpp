#include "accuracy/split_sum_accuracy.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>

#include <glm/geometric.hpp>

#include "common/luminance.h"
#include "common/parallel_for.h"
#include "reference/radiance.h"
#include "shading/brdf_models.h"
#include "shading/environment_brdf.h"
#include "shading/half.h"

namespace patina {

// `count` unit vectors spread evenly over the sphere (a Fibonacci lattice): surfaces facing up,
// down and sideways, so a sun, a floor and the horizon all count.
std::vector<glm::vec3> spreadNormals(int count) {
    std::vector<glm::vec3> normals;
    const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < count; ++i) {
        const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(count);
        const float radius = std::sqrt(std::max(0.0f, 1.0f - y * y));
        normals.emplace_back(radius * std::cos(golden * float(i)), y, radius * std::sin(golden * float(i)));
    }
    return normals;
}

// V at NoV to N, turned about N by an azimuth of its own for each normal.
glm::vec3 viewAt(glm::vec3 N, float NoV, int index) {
    const glm::vec3 up = std::abs(N.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 t = glm::normalize(glm::cross(up, N)), b = glm::cross(N, t);
    const float phi = 2.39996f * float(index) + 0.7f;
    const glm::vec3 tangent = t * std::cos(phi) + b * std::sin(phi);
    return glm::normalize(NoV * N + std::sqrt(std::max(0.0f, 1.0f - NoV * NoV)) * tangent);
}

namespace {

shader::SurfaceMaterial metal(float f0, float roughness) {
    return shader::deriveSurfaceMaterial(glm::vec3(f0), roughness, 0.5f, 1.0f);
}

// A table stored in another format: each value rounded as the texture would hold it.
enum class TableFormat { Float32, Float16, Unorm16, Unorm8 };
const char* formatName(TableFormat format) {
    switch (format) {
    case TableFormat::Float32: return "fp32";
    case TableFormat::Float16: return "fp16";
    case TableFormat::Unorm16: return "unorm16";
    case TableFormat::Unorm8: return "unorm8";
    }
    return "?";
}

float stored(float value, TableFormat format) {
    switch (format) {
    case TableFormat::Float32: return value;
    case TableFormat::Float16: return roundToHalf(value);
    case TableFormat::Unorm16: return std::round(std::clamp(value, 0.0f, 1.0f) * 65535.0f) / 65535.0f;
    case TableFormat::Unorm8: return std::round(std::clamp(value, 0.0f, 1.0f) * 255.0f) / 255.0f;
    }
    return value;
}

struct TableVariant {
    std::string name;
    int size;
    std::vector<glm::vec2> table;
};

// Bilinear in a table placed as the shaders place theirs (energy_table.glsl's tableCoordinate).
glm::vec2 lookup(const TableVariant& variant, float NoV, float roughness) {
    const shader::TableCoordinate c = shader::tableCoordinate(NoV, roughness, variant.size);
    auto texel = [&](int x, int y) { return variant.table[size_t(y) * size_t(variant.size) + size_t(x)]; };
    const glm::vec2 bottom = glm::mix(texel(c.x0, c.y0), texel(c.x0 + 1, c.y0), c.fx);
    const glm::vec2 top = glm::mix(texel(c.x0, c.y0 + 1), texel(c.x0 + 1, c.y0 + 1), c.fx);
    return glm::mix(bottom, top, c.fy);
}

std::vector<TableVariant> tableVariants(bool quick) {
    std::vector<std::pair<int, TableFormat>> wanted =
        quick ? std::vector<std::pair<int, TableFormat>>{{16, TableFormat::Float32}, {64, TableFormat::Unorm8}}
              : std::vector<std::pair<int, TableFormat>>{{16, TableFormat::Float32}, {32, TableFormat::Float32},
                                                         {64, TableFormat::Float32}, {128, TableFormat::Float32},
                                                         {64, TableFormat::Float16}, {64, TableFormat::Unorm16},
                                                         {64, TableFormat::Unorm8}};
    std::vector<TableVariant> variants;
    for (const auto& [size, format] : wanted) {
        std::vector<glm::vec2> table = size == kEnvironmentBrdfSize
                                           ? environmentBrdfTable(BrdfModelId::Epic)
                                           : integrateEnvironmentBrdfTable(BrdfModelId::Epic, size, kEnvironmentBrdfSamples);
        for (glm::vec2& ab : table) {
            ab = {stored(ab.x, format), stored(ab.y, format)};
        }
        variants.push_back({"LUT " + std::to_string(size) + "x" + std::to_string(size) + " " + formatName(format), size,
                            std::move(table)});
    }
    return variants;
}

struct Grid {
    std::vector<glm::vec3> normals;
    std::vector<float> NoV, roughness, f0;
    std::vector<unsigned> stochasticCounts;
    int jitters;
};

Grid gridFor(bool quick) {
    if (quick) {
        return {spreadNormals(4), {0.25f, 0.75f}, {0.1f, 0.5f, 1.0f}, {0.04f, 1.0f}, {4, 16, 64}, 4};
    }
    return {spreadNormals(8),         {0.1f, 0.3f, 0.6f, 0.9f}, {0.05f, 0.15f, 0.3f, 0.5f, 0.75f, 1.0f},
            {0.04f, 0.5f, 1.0f},      {4, 8, 16, 32, 64},        8};
}

// Everything measured at one (normal, NoV, r): the truth and the prefiltered radiance each
// variant reads (linear in F0 from here on).
struct PointEstimates {
    glm::vec3 truth0, truth1, truthSe0, truthSe1;   // the ground truth at F0 = 0 and F0 = 1
    glm::vec3 ldChain, ldDominant, ldExact, ldMoreSamples;
    glm::vec2 abExact, abShipped;
    std::vector<std::vector<glm::vec3>> stochastic;   // [count][F0 index], mean |error| kept apart
};

const char* const kSplitSum = "split sum";
const char* const kDominant = "split sum, dominant direction";
const char* const kSplit = "N = V and the split (exact LD and AB)";
const char* const kMips = "mip quantisation (chain against exact LD)";
const char* const kMoreSamples = "mip quantisation, prefilter at 1024 samples";

std::string stochasticName(unsigned count) {
    return "stochastic, " + std::to_string(count) + " samples";
}
}  // namespace

std::vector<std::string> splitSumMethods(bool quick) {
    std::vector<std::string> methods{kSplitSum, kDominant};
    for (unsigned count : gridFor(quick).stochasticCounts) {
        methods.push_back(stochasticName(count));
    }
    methods.push_back(kSplit);
    methods.push_back(kMips);
    if (!quick) {
        methods.push_back(kMoreSamples);
    }
    for (const TableVariant& variant : tableVariants(quick)) {
        methods.push_back(variant.name);
    }
    return methods;
}

SplitSumAccuracy measureSplitSum(const std::vector<NamedEnvironment>& environments,
                                 const SplitSumAccuracyOptions& options) {
    const Grid grid = gridFor(options.quick);
    const int referenceSamples = options.referenceSamples > 0 ? options.referenceSamples : options.quick ? 256 : 4096;
    const std::vector<TableVariant> tables = tableVariants(options.quick);
    constexpr unsigned kExactSamples = 4096;   // GGX samples for the exact LD and (A, B)
    SplitSumAccuracy result;
    for (const NamedEnvironment& named : environments) {
        const Environment& environment = *named.environment;
        const CubeChain source = sourceMipChain(environment);
        const std::function<glm::vec3(glm::vec3, float)> readSource = [&](glm::vec3 d, float lod) {
            return sampleCube(source, d, lod);
        };
        CubeChain moreSamples;
        if (!options.quick) {
            PrefilterSettings settings = environment.settings.prefilter;
            settings.samples = 1024;
            moreSamples = prefilterCube(source, settings);
        }
        const EnvironmentDistribution distribution(environment.image);
        const ReferenceEnvironment reference{&environment, &distribution, 1.0f, 0.0f};
        const float maxLod = environment.maxLod();
        const float faceSize = float(source.front().size);

        // Every (normal, NoV, r) on every core.
        const size_t points = grid.normals.size() * grid.NoV.size() * grid.roughness.size();
        std::vector<PointEstimates> estimates(points);
        parallelFor(points, [&](size_t index) {
            const size_t r = index % grid.roughness.size();
            const size_t v = index / grid.roughness.size() % grid.NoV.size();
            const size_t n = index / grid.roughness.size() / grid.NoV.size();
            const glm::vec3 N = grid.normals[n];
            const glm::vec3 V = viewAt(N, grid.NoV[v], int(n));
            const float NoV = std::max(glm::dot(N, V), 1e-4f);
            PointEstimates& e = estimates[index];
            ReferenceOptions referenceOptions;
            referenceOptions.samples = referenceSamples;
            referenceOptions.seed = 0x5851F42D4C957F2Dull * (index + 1);
            referenceOptions.diffuse = false;
            const ReferenceEstimate t0 =
                referenceRadiance(BrdfModelId::Epic, metal(0.0f, grid.roughness[r]), reference, {}, glm::vec3(0), N, V,
                                  referenceOptions);
            const ReferenceEstimate t1 =
                referenceRadiance(BrdfModelId::Epic, metal(1.0f, grid.roughness[r]), reference, {}, glm::vec3(0), N, V,
                                  referenceOptions);
            e.truth0 = t0.value;
            e.truth1 = t1.value;
            e.truthSe0 = t0.standardError;
            e.truthSe1 = t1.standardError;
            const shader::SurfaceMaterial m = metal(1.0f, grid.roughness[r]);
            const glm::vec3 R = glm::reflect(-V, N);
            const float lod = shader::roughnessToLod(m.roughness, maxLod);
            e.ldChain = sampleCube(environment.prefiltered, R, lod);
            e.ldDominant = sampleCube(environment.prefiltered, shader::environmentReflection(m, N, V, true), lod);
            e.ldExact = shader::prefilterEnvironment(readSource, R, m.roughness, kExactSamples, faceSize);
            if (!moreSamples.empty()) {
                e.ldMoreSamples = sampleCube(moreSamples, R, lod);
            }
            e.abShipped = environmentBrdf(BrdfModelId::Epic, NoV, m.roughness);
            e.abExact = integrateEnvironmentBrdf(BrdfModelId::Epic, NoV, m.roughness, kExactSamples);
            for (unsigned count : grid.stochasticCounts) {
                std::vector<glm::vec3> perF0;
                for (float f0 : grid.f0) {
                    // The mean |error| over jitters, kept as (sum of |error| lum, 0, 0).
                    glm::vec3 truth = t0.value + f0 * (t1.value - t0.value);
                    double error = 0.0;
                    for (int j = 0; j < grid.jitters; ++j) {
                        const glm::vec2 jitter(std::fmod(0.618034f * float(j + 1), 1.0f),
                                               std::fmod(0.754878f * float(j + 1) + 0.31f, 1.0f));
                        const glm::vec3 s = stochasticEnvironmentOnCpu(BrdfModelId::Epic, metal(f0, grid.roughness[r]),
                                                                       environment, source, 1.0f, 0.0f, N, V, count,
                                                                       jitter);
                        error += std::abs(double(luminance(s)) - double(luminance(truth)));
                    }
                    perF0.emplace_back(float(error / grid.jitters), 0.0f, 0.0f);
                }
                e.stochastic.push_back(std::move(perF0));
            }
        });

        // Rows: each method at each (NoV, r, F0), the mean over normals.
        for (size_t v = 0; v < grid.NoV.size(); ++v) {
            for (size_t r = 0; r < grid.roughness.size(); ++r) {
                for (size_t f = 0; f < grid.f0.size(); ++f) {
                    const float f0 = grid.f0[f];
                    std::vector<std::pair<std::string, double>> sums;
                    double truthSe = 0.0;
                    auto add = [&](const std::string& method, double error) {
                        auto found = std::find_if(sums.begin(), sums.end(), [&](auto& p) { return p.first == method; });
                        if (found == sums.end()) {
                            sums.emplace_back(method, error);
                        } else {
                            found->second += error;
                        }
                    };
                    for (size_t n = 0; n < grid.normals.size(); ++n) {
                        const PointEstimates& e =
                            estimates[(n * grid.NoV.size() + v) * grid.roughness.size() + r];
                        const double truth = luminance(e.truth0 + f0 * (e.truth1 - e.truth0));
                        const double se = luminance(e.truthSe0 + f0 * (e.truthSe1 - e.truthSe0));
                        const double floor = std::max(truth, 1e-6);
                        truthSe += se / floor;
                        auto split = [&](glm::vec3 ld, glm::vec2 ab) { return double(luminance(ld * (f0 * ab.x + ab.y))); };
                        const double exact = split(e.ldExact, e.abExact);
                        add(kSplitSum, std::abs(split(e.ldChain, e.abShipped) - truth) / floor);
                        add(kDominant, std::abs(split(e.ldDominant, e.abShipped) - truth) / floor);
                        for (size_t c = 0; c < grid.stochasticCounts.size(); ++c) {
                            add(stochasticName(grid.stochasticCounts[c]), double(e.stochastic[c][f].x) / floor);
                        }
                        add(kSplit, std::abs(exact - truth) / floor);
                        add(kMips, std::abs(split(e.ldChain, e.abExact) - exact) / floor);
                        if (!moreSamples.empty()) {
                            add(kMoreSamples, std::abs(split(e.ldMoreSamples, e.abExact) - exact) / floor);
                        }
                        const float NoV = std::max(grid.NoV[v], 1e-4f);
                        const float roughness = metal(1.0f, grid.roughness[r]).roughness;
                        for (const TableVariant& table : tables) {
                            add(table.name, std::abs(split(e.ldExact, lookup(table, NoV, roughness)) - exact) / floor);
                        }
                    }
                    const double count = double(grid.normals.size());
                    for (const auto& [method, sum] : sums) {
                        result.rows.push_back(
                            {named.name, method, grid.NoV[v], grid.roughness[r], f0, sum / count, truthSe / count});
                    }
                }
            }
        }

        // Diffuse: a white Lambert surface, irradiance / pi.
        const std::vector<glm::vec3> normals = spreadNormals(options.quick ? 16 : 64);
        std::vector<double> truth(normals.size());
        parallelFor(normals.size(), [&](size_t i) {
            ReferenceOptions referenceOptions;
            referenceOptions.samples = referenceSamples;
            referenceOptions.seed = 0x2545F4914F6CDD1Dull * (i + 1);
            referenceOptions.specular = false;
            const shader::SurfaceMaterial white = shader::deriveSurfaceMaterial(glm::vec3(1.0f), 1.0f, 0.0f, 0.0f);
            truth[i] = luminance(referenceRadiance(BrdfModelId::Epic, white, reference, {}, glm::vec3(0), normals[i],
                                                   normals[i], referenceOptions)
                                     .value);
        });
        const ShCoefficients raw = projectSH(environment.image), windowed = windowSH(raw);
        struct ShMethod {
            const char* name;
            const ShCoefficients* coefficients;
            bool clamp;
        };
        for (const ShMethod method : {ShMethod{"SH 9 coefficients, unguarded", &raw, false},
                                      ShMethod{"SH 9 coefficients, clamped at 0", &raw, true},
                                      ShMethod{"SH 9 coefficients, windowed and clamped", &windowed, true}}) {
            ShErrorRow row{named.name, method.name};
            int negative = 0;
            for (size_t i = 0; i < normals.size(); ++i) {
                const glm::vec3 unclamped = irradianceUnclamped(*method.coefficients, normals[i]);
                negative += luminance(unclamped) < 0.0f;
                const glm::vec3 e = method.clamp ? glm::max(unclamped, glm::vec3(0.0f)) : unclamped;
                const double error = std::abs(double(luminance(e)) / double(std::numbers::pi_v<float>) - truth[i]) /
                                     std::max(truth[i], 1e-6);
                row.meanRelativeError += error / double(normals.size());
                row.maxRelativeError = std::max(row.maxRelativeError, error);
            }
            row.negativeFraction = double(negative) / double(normals.size());
            result.sh.push_back(row);
        }
    }
    return result;
}

std::string splitSumCsv(const std::vector<SplitSumErrorRow>& rows) {
    std::ostringstream csv;
    csv << "environment,method,NoV,roughness,f0,relative_error,truth_relative_se\n";
    csv.precision(6);
    for (const SplitSumErrorRow& row : rows) {
        csv << row.environment << ",\"" << row.method << "\"," << row.NoV << "," << row.roughness << "," << row.f0 << ","
            << row.relativeError << "," << row.truthRelativeStandardError << "\n";
    }
    return csv.str();
}

std::string shCsv(const std::vector<ShErrorRow>& rows) {
    std::ostringstream csv;
    csv << "environment,method,mean_relative_error,max_relative_error,negative_fraction\n";
    csv.precision(6);
    for (const ShErrorRow& row : rows) {
        csv << row.environment << ",\"" << row.method << "\"," << row.meanRelativeError << "," << row.maxRelativeError
            << "," << row.negativeFraction << "\n";
    }
    return csv.str();
}

double meanError(const std::vector<SplitSumErrorRow>& rows, const std::string& method, const std::string& environment) {
    double sum = 0.0;
    int count = 0;
    for (const SplitSumErrorRow& row : rows) {
        if (row.method == method && (environment.empty() || row.environment == environment)) {
            sum += row.relativeError;
            ++count;
        }
    }
    return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace patina
