#pragma once
// The environment's diffuse light against its ground truth (docs/LIGHTING.md, "Diffuse"): the
// irradiance the renderer reads (environment/irradiance.h's map) and the nine spherical-harmonic
// coefficients it replaced, against the exact cosine convolution of the image
// (reference/exact_irradiance.h); the Monte Carlo reference's own estimate against the same
// (so that its bias is known); and matte objects as the renderer draws them against the
// ground-truth render, pixel by pixel.
#include <string>
#include <vector>

#include "accuracy/split_sum_accuracy.h"
#include "common/hdr_image.h"
#include "gl/environment_method.h"

namespace patina {

// One way of computing E(n), over normals spread evenly over the sphere: |E - exact| / exact
// on luminance, its mean and maximum, and the mean of (E - exact) / exact (the bias).
struct IrradianceErrorRow {
    std::string environment, method;
    double meanRelativeError = 0.0, maxRelativeError = 0.0, meanSignedError = 0.0;
};

// The methods, in order: the map as shipped, the map at other face and cell sizes, the nine
// coefficients clamped at 0 and windowed, and the Monte Carlo reference at `referenceSamples`
// iterations (a white Lambert surface, its diffuse lobe alone). `normals` of them each.
std::vector<IrradianceErrorRow> measureIrradiance(const NamedEnvironment& environment, int normals,
                                                  int referenceSamples);

// A matte grey object (specular 0, roughness 1, base colour 0.5, the `epic` model) lit by the
// environment alone, rendered by the GPU (split sum, single path, no MSAA: pixel centres) and by
// the ground truth (reference/reference_render.h) at the same pixel centres.
enum class MatteShape { Cube, Sphere };
const char* matteShapeName(MatteShape shape);

struct MatteRow {
    std::string environment, shape, method;   // method: how the renderer shaded it (environmentMethodName)
    int pixels = 0;
    // render / truth on luminance over the object's pixels: the mean and the 5th, 50th and 95th
    // percentiles. The truth is the integral the reference estimates with its diffuse lobe
    // computed exactly (c_diff / pi times ExactIrradiance at the pixel's normal) and its specular
    // lobe by the reference's Monte Carlo estimate: a pixel's noise is then the specular lobe's
    // alone, small beside the bounds, where the whole estimate's would widen the percentiles.
    double meanRatio = 0.0, p5 = 0.0, p50 = 0.0, p95 = 0.0;
    // That truth's own noise: the median and 95th percentile over the pixels of its relative
    // standard error.
    double truthMedianRelativeError = 0.0, truthP95RelativeError = 0.0;
    // Against the reference render itself (`patina render --reference`, both lobes by Monte
    // Carlo): the mean ratio, that mean's standard error from the reference's noise, and the
    // median of a pixel's relative standard error.
    double referenceMeanRatio = 0.0, referenceMeanRatioStandardError = 0.0, referenceMedianRelativeError = 0.0;
    // The diffuse lobe alone, the renderer's `diffuse` channel against c_diff / pi E(n) exactly
    // (no noise): what the irradiance is responsible for.
    double diffuseMeanRatio = 0.0, diffuseP5 = 0.0, diffuseP95 = 0.0;
};

struct MatteOptions {
    int size = 64;          // the image's side
    int samples = 1024;     // the reference's iterations a pixel (the specular lobe's and the render's)
    bool referenceRender = true;   // also the whole reference render (the reference_* values; else NaN)
    EnvironmentShading shading;    // how the renderer shades the environment
};

// Needs a current GL context.
MatteRow measureMatte(const NamedEnvironment& environment, MatteShape shape, const MatteOptions& options);

// A test environment with a small sun: a sky of radiance `sky` (a little brighter at the
// zenith, a darker ground) and a disc of `radius` degrees, 10^4 times the sky's radiance, at
// `elevation` degrees, in an equirect image of width x width / 2.
HdrImage sunEnvironment(int width, float elevation = 30.0f, float radius = 0.5f);

// CSV: environment,method,mean_relative_error,max_relative_error,mean_signed_error
std::string irradianceCsv(const std::vector<IrradianceErrorRow>& rows);
// CSV: environment,shape,method,pixels,mean_ratio,p5,p50,p95,truth_median_rse,truth_p95_rse,
// reference_mean_ratio,reference_mean_ratio_se,reference_median_rse,diffuse_mean_ratio,diffuse_p5,
// diffuse_p95
std::string matteCsv(const std::vector<MatteRow>& rows);

}  // namespace patina
