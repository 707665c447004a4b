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
    bool hasMoreSamples = false;   // ldMoreSamples measured (full runs)
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

namespace {
constexpr unsigned kExactSamples = 4096;   // GGX samples for the exact LD and (A, B)

// One environment as each point reads it: the source it is prefiltered from, that source
// prefiltered at more samples (full runs only), and the ground truth's view of it.
struct MeasuredEnvironment {
    const Environment& environment;
    const CubeChain& source;
    const CubeChain& moreSamples;   // empty in --quick
    const ReferenceEnvironment& reference;
    int referenceSamples;
};

// The stochastic mode's mean |error| over the grid's jitters at each F0, against the truth
// (linear in F0), kept as (mean |error| of the luminance, 0, 0).
std::vector<glm::vec3> stochasticErrors(const Grid& grid, const MeasuredEnvironment& measured, const PointEstimates& e,
                                        float roughness, unsigned count, glm::vec3 N, glm::vec3 V) {
    std::vector<glm::vec3> perF0;
    for (float f0 : grid.f0) {
        const glm::vec3 truth = e.truth0 + f0 * (e.truth1 - e.truth0);
        double error = 0.0;
        for (int j = 0; j < grid.jitters; ++j) {
            const glm::vec2 jitter(std::fmod(0.618034f * float(j + 1), 1.0f),
                                   std::fmod(0.754878f * float(j + 1) + 0.31f, 1.0f));
            const glm::vec3 s = stochasticEnvironmentOnCpu(BrdfModelId::Epic, metal(f0, roughness), measured.environment,
                                                           measured.source, 1.0f, 0.0f, N, V, count, jitter);
            error += std::abs(double(luminance(s)) - double(luminance(truth)));
        }
        perF0.emplace_back(float(error / grid.jitters), 0.0f, 0.0f);
    }
    return perF0;
}

// Everything measured at grid point `index` (normal, NoV, r: r fastest).
PointEstimates estimatePoint(const Grid& grid, const MeasuredEnvironment& measured, size_t index) {
    const size_t r = index % grid.roughness.size();
    const size_t v = index / grid.roughness.size() % grid.NoV.size();
    const size_t n = index / grid.roughness.size() / grid.NoV.size();
    const glm::vec3 N = grid.normals[n];
    const glm::vec3 V = viewAt(N, grid.NoV[v], int(n));
    const float NoV = std::max(glm::dot(N, V), 1e-4f);
    PointEstimates e;
    ReferenceOptions referenceOptions;
    referenceOptions.samples = measured.referenceSamples;
    referenceOptions.seed = 0x5851F42D4C957F2Dull * (index + 1);
    referenceOptions.diffuse = false;
    const ReferenceEstimate t0 = referenceRadiance(BrdfModelId::Epic, metal(0.0f, grid.roughness[r]), measured.reference,
                                                   {}, glm::vec3(0), N, V, referenceOptions);
    const ReferenceEstimate t1 = referenceRadiance(BrdfModelId::Epic, metal(1.0f, grid.roughness[r]), measured.reference,
                                                   {}, glm::vec3(0), N, V, referenceOptions);
    e.truth0 = t0.value;
    e.truth1 = t1.value;
    e.truthSe0 = t0.standardError;
    e.truthSe1 = t1.standardError;
    const Environment& environment = measured.environment;
    const shader::SurfaceMaterial m = metal(1.0f, grid.roughness[r]);
    const glm::vec3 R = glm::reflect(-V, N);
    const float lod = shader::roughnessToLod(m.roughness, environment.maxLod());
    const std::function<glm::vec3(glm::vec3, float)> readSource = [&](glm::vec3 d, float l) {
        return sampleCube(measured.source, d, l);
    };
    e.ldChain = sampleCube(environment.prefiltered, R, lod);
    e.ldDominant = sampleCube(environment.prefiltered, shader::environmentReflection(m, N, V, true), lod);
    e.ldExact = shader::prefilterEnvironment(readSource, R, m.roughness, kExactSamples,
                                             float(measured.source.front().size));
    if (!measured.moreSamples.empty()) {
        e.ldMoreSamples = sampleCube(measured.moreSamples, R, lod);
        e.hasMoreSamples = true;
    }
    e.abShipped = environmentBrdf(BrdfModelId::Epic, NoV, m.roughness);
    e.abExact = integrateEnvironmentBrdf(BrdfModelId::Epic, NoV, m.roughness, kExactSamples);
    for (unsigned count : grid.stochasticCounts) {
        e.stochastic.push_back(stochasticErrors(grid, measured, e, grid.roughness[r], count, N, V));
    }
    return e;
}

// Each method's relative error summed over methods in the order first met.
class MethodSums {
public:
    void add(const std::string& method, double error) {
        auto found = std::find_if(sums_.begin(), sums_.end(), [&](auto& p) { return p.first == method; });
        if (found == sums_.end()) {
            sums_.emplace_back(method, error);
        } else {
            found->second += error;
        }
    }
    const std::vector<std::pair<std::string, double>>& sums() const { return sums_; }

private:
    std::vector<std::pair<std::string, double>> sums_;
};

// One point's error by every method at F0 index `f`, relative to the truth; returns the truth's
// own relative standard error.
double addPointErrors(const Grid& grid, const std::vector<TableVariant>& tables, const PointEstimates& e, size_t v,
                      size_t r, size_t f, MethodSums& sums) {
    const float f0 = grid.f0[f];
    const double truth = luminance(e.truth0 + f0 * (e.truth1 - e.truth0));
    const double se = luminance(e.truthSe0 + f0 * (e.truthSe1 - e.truthSe0));
    const double floor = std::max(truth, 1e-6);
    auto split = [&](glm::vec3 ld, glm::vec2 ab) { return double(luminance(ld * (f0 * ab.x + ab.y))); };
    const double exact = split(e.ldExact, e.abExact);
    sums.add(kSplitSum, std::abs(split(e.ldChain, e.abShipped) - truth) / floor);
    sums.add(kDominant, std::abs(split(e.ldDominant, e.abShipped) - truth) / floor);
    for (size_t c = 0; c < grid.stochasticCounts.size(); ++c) {
        sums.add(stochasticName(grid.stochasticCounts[c]), double(e.stochastic[c][f].x) / floor);
    }
    sums.add(kSplit, std::abs(exact - truth) / floor);
    sums.add(kMips, std::abs(split(e.ldChain, e.abExact) - exact) / floor);
    if (e.hasMoreSamples) {
        sums.add(kMoreSamples, std::abs(split(e.ldMoreSamples, e.abExact) - exact) / floor);
    }
    const float NoV = std::max(grid.NoV[v], 1e-4f);
    const float roughness = metal(1.0f, grid.roughness[r]).roughness;
    for (const TableVariant& table : tables) {
        sums.add(table.name, std::abs(split(e.ldExact, lookup(table, NoV, roughness)) - exact) / floor);
    }
    return se / floor;
}

// Rows: each method at each (NoV, r, F0), the mean over normals.
void appendRows(const Grid& grid, const std::vector<TableVariant>& tables, const std::string& environment,
                const std::vector<PointEstimates>& estimates, std::vector<SplitSumErrorRow>& rows) {
    for (size_t v = 0; v < grid.NoV.size(); ++v) {
        for (size_t r = 0; r < grid.roughness.size(); ++r) {
            for (size_t f = 0; f < grid.f0.size(); ++f) {
                MethodSums sums;
                double truthSe = 0.0;
                for (size_t n = 0; n < grid.normals.size(); ++n) {
                    const PointEstimates& e = estimates[(n * grid.NoV.size() + v) * grid.roughness.size() + r];
                    truthSe += addPointErrors(grid, tables, e, v, r, f, sums);
                }
                const double count = double(grid.normals.size());
                for (const auto& [method, sum] : sums.sums()) {
                    rows.push_back(
                        {environment, method, grid.NoV[v], grid.roughness[r], grid.f0[f], sum / count, truthSe / count});
                }
            }
        }
    }
}
}  // namespace

SplitSumAccuracy measureSplitSum(const std::vector<NamedEnvironment>& environments,
                                 const SplitSumAccuracyOptions& options) {
    const Grid grid = gridFor(options.quick);
    const int referenceSamples = options.referenceSamples > 0 ? options.referenceSamples : options.quick ? 256 : 4096;
    const std::vector<TableVariant> tables = tableVariants(options.quick);
    SplitSumAccuracy result;
    for (const NamedEnvironment& named : environments) {
        const Environment& environment = *named.environment;
        const CubeChain source = sourceMipChain(environment);
        CubeChain moreSamples;
        if (!options.quick) {
            PrefilterSettings settings = environment.settings.prefilter;
            settings.samples = 1024;
            moreSamples = prefilterCube(source, settings);
        }
        const EnvironmentDistribution distribution(environment.image);
        const ReferenceEnvironment reference{&environment, &distribution, 1.0f, 0.0f};
        const MeasuredEnvironment measured{environment, source, moreSamples, reference, referenceSamples};
        // Every (normal, NoV, r) on every core.
        std::vector<PointEstimates> estimates(grid.normals.size() * grid.NoV.size() * grid.roughness.size());
        parallelFor(estimates.size(), [&](size_t index) { estimates[index] = estimatePoint(grid, measured, index); });
        appendRows(grid, tables, named.name, estimates, result.rows);
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
