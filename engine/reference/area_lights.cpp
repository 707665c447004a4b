#include "reference/area_lights.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>

#include <glm/geometric.hpp>

#include "shading/brdf_models.h"

namespace patina {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// A tube of radius 0 is a line, with no area to sample: the estimate takes it as this thin.
constexpr double kMinTubeRadius = 1e-5;

// The light's shape in double: the capsule of `radius` around the segment a..b, a sphere when
// a = b.
struct Capsule {
    glm::dvec3 a, b;
    double radius;
    double length() const { return glm::length(b - a); }
    double area() const { return 4.0 * std::numbers::pi * radius * radius + 2.0 * std::numbers::pi * radius * length(); }
};

Capsule capsuleOf(const shader::PackedLight& light) {
    const glm::dvec3 a(light.position);
    if (light.type == shader::LIGHT_TUBE) {
        return {a, glm::dvec3(light.tubeEnd), std::max(double(light.sourceRadius), kMinTubeRadius)};
    }
    return {a, a, double(light.sourceRadius)};
}

glm::dvec3 closestOnSegment(const Capsule& c, glm::dvec3 p) {
    const glm::dvec3 d = c.b - c.a;
    const double dd = glm::dot(d, d);
    const double t = dd > 0.0 ? std::clamp(glm::dot(p - c.a, d) / dd, 0.0, 1.0) : 0.0;
    return c.a + t * d;
}

bool contains(const Capsule& c, glm::dvec3 p) {
    const glm::dvec3 e = p - closestOnSegment(c, p);
    return glm::dot(e, e) < c.radius * c.radius;
}

// The ray parameters o + t w (unit w) inside a convex part; empty when enter > exit.
struct Interval {
    double enter = kInfinity, exit = -kInfinity;
    bool empty() const { return enter > exit; }
};

Interval intersect(Interval x, Interval y) {
    return {std::max(x.enter, y.enter), std::min(x.exit, y.exit)};
}

Interval sphereInterval(glm::dvec3 o, glm::dvec3 w, glm::dvec3 centre, double radius) {
    const glm::dvec3 oc = o - centre;
    const double b = glm::dot(oc, w);
    const double discriminant = b * b - (glm::dot(oc, oc) - radius * radius);
    if (discriminant < 0.0) {
        return {};
    }
    const double root = std::sqrt(discriminant);
    return {-b - root, -b + root};
}

// The solid cylinder between the segment's end planes.
Interval cylinderInterval(glm::dvec3 o, glm::dvec3 w, const Capsule& c) {
    const double length = c.length();
    if (!(length > 0.0)) {
        return {};
    }
    const glm::dvec3 axis = (c.b - c.a) / length;
    const glm::dvec3 offset = o - c.a;
    const double along = glm::dot(offset, axis), alongW = glm::dot(w, axis);
    Interval slab;
    if (alongW != 0.0) {
        const double t0 = -along / alongW, t1 = (length - along) / alongW;
        slab = {std::min(t0, t1), std::max(t0, t1)};
    } else if (along >= 0.0 && along <= length) {
        slab = {-kInfinity, kInfinity};
    }
    const glm::dvec3 offsetAcross = offset - along * axis, wAcross = w - alongW * axis;
    const double a = glm::dot(wAcross, wAcross), b = glm::dot(offsetAcross, wAcross);
    const double cc = glm::dot(offsetAcross, offsetAcross) - c.radius * c.radius;
    Interval tube;
    if (a > 0.0) {
        const double discriminant = b * b - a * cc;
        if (discriminant >= 0.0) {
            const double root = std::sqrt(discriminant);
            tube = {(-b - root) / a, (-b + root) / a};
        }
    } else if (cc < 0.0) {   // along the axis, within the radius
        tube = {-kInfinity, kInfinity};
    }
    return intersect(slab, tube);
}

// Where a ray from P first meets the capsule's surface (entering it from outside, leaving it
// from inside), with the outward normal there. The capsule is convex, so the union of its
// parts' intervals is one interval.
struct SurfaceHit {
    bool found = false;
    double distance = 0.0;
    glm::dvec3 normal{0.0};
};

SurfaceHit firstHit(const Capsule& c, glm::dvec3 o, glm::dvec3 w) {
    Interval all;
    for (const Interval part : {sphereInterval(o, w, c.a, c.radius), sphereInterval(o, w, c.b, c.radius),
                                cylinderInterval(o, w, c)}) {
        if (!part.empty()) {
            all = {std::min(all.enter, part.enter), std::max(all.exit, part.exit)};
        }
    }
    if (all.empty() || !(all.exit > 0.0)) {
        return {};
    }
    const double t = all.enter > 0.0 ? all.enter : all.exit;
    const glm::dvec3 q = o + t * w;
    const glm::dvec3 fromAxis = q - closestOnSegment(c, q);
    const double r = glm::length(fromAxis);
    if (!(r > 0.0)) {
        return {};
    }
    return {true, t, fromAxis / r};
}

// A unit vector's orthonormal complement.
void frameAround(glm::dvec3 w, glm::dvec3& e1, glm::dvec3& e2) {
    const glm::dvec3 up = std::abs(w.z) < 0.999 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    e1 = glm::normalize(glm::cross(up, w));
    e2 = glm::cross(w, e1);
}

// A point uniformly distributed over the capsule's area (u in [0, 1)^3), with its outward normal.
struct SurfacePoint {
    glm::dvec3 position, normal;
};

SurfacePoint sampleCapsule(const Capsule& c, glm::dvec3 u) {
    const double length = c.length();
    const double phi = 2.0 * std::numbers::pi * u.z;
    if (u.x * c.area() < 2.0 * std::numbers::pi * c.radius * length) {   // the cylinder
        const glm::dvec3 axis = (c.b - c.a) / length;
        glm::dvec3 e1, e2;
        frameAround(axis, e1, e2);
        const glm::dvec3 n = std::cos(phi) * e1 + std::sin(phi) * e2;
        return {c.a + (u.y * length) * axis + c.radius * n, n};
    }
    // A whole sphere's worth of caps: each half goes to the end it faces.
    const double z = 1.0 - 2.0 * u.y, across = std::sqrt(std::max(0.0, 1.0 - z * z));
    const glm::dvec3 n(across * std::cos(phi), across * std::sin(phi), z);
    const glm::dvec3 end = glm::dot(n, c.b - c.a) > 0.0 ? c.b : c.a;
    return {end + c.radius * n, n};
}

// The solid-angle pdf of area sampling at a surface point seen at `distance` along unit w.
double areaPdf(const Capsule& c, double distance, glm::dvec3 normal, glm::dvec3 w) {
    const double cosine = std::abs(glm::dot(normal, w));
    return cosine > 0.0 ? distance * distance / (c.area() * cosine) : 0.0;
}

// The power heuristic's weight over the pdf, for a sample drawn with pdf `own` (Veach 1997).
double misWeightOverPdf(double own, double other) {
    const double squares = own * own + other * other;
    return squares > 0.0 ? own / squares : 0.0;
}
}  // namespace

bool isAreaLight(const shader::PackedLight& light) {
    return light.type == shader::LIGHT_SPHERE || light.type == shader::LIGHT_TUBE;
}

glm::dvec3 areaLightRadiance(const shader::PackedLight& light, glm::vec3 P) {
    const glm::vec3 L0 = light.position - P;
    const glm::vec3 L1 = (light.type == shader::LIGHT_TUBE ? light.tubeEnd : light.position) - P;
    // The distance the approximation's falloff takes (shaders/shared/brdf_model.glsl).
    const float t = light.type == shader::LIGHT_TUBE ? std::sqrt(std::max(shader::lineIrradianceDistanceSquared(L0, L1), 0.0f))
                                                     : glm::length(L0);
    const double falloff = double(shader::pointLightAttenuation(t, light.inverseRange, light.attenuation)) * double(t) * double(t);
    const Capsule c = capsuleOf(light);
    return glm::dvec3(light.radiance) * falloff / (std::numbers::pi * c.radius * (c.radius + 0.5 * c.length()));
}

namespace {
// One sphere or tube light made ready for the estimate at a point x.
struct PreparedAreaLight {
    Capsule shape;
    glm::dvec3 radiance;
    bool inside = false;   // x within the light
    // Outside a sphere: the cone towards it, sampled uniformly in solid angle.
    bool cone = false;
    glm::dvec3 axis{0.0};
    double oneMinusCosMax = 0.0, conePdf = 0.0;
};

PreparedAreaLight prepareAreaLight(const shader::PackedLight& light, glm::vec3 P) {
    const glm::dvec3 x(P);
    PreparedAreaLight p{capsuleOf(light), areaLightRadiance(light, P)};
    p.inside = contains(p.shape, x);
    if (light.type == shader::LIGHT_SPHERE && !p.inside && p.shape.radius > 0.0) {
        const glm::dvec3 toCentre = p.shape.a - x;
        const double d = glm::length(toCentre);
        const double sinSquared = std::min(p.shape.radius * p.shape.radius / (d * d), 1.0);
        p.cone = true;
        p.axis = toCentre / d;
        // 1 - cos theta_max without cancelling: sin^2 / (1 + cos).
        p.oneMinusCosMax = sinSquared / (1.0 + std::sqrt(1.0 - sinSquared));
        p.conePdf = 1.0 / (2.0 * std::numbers::pi * p.oneMinusCosMax);
    }
    return p;
}

// The light strategy's pdf of direction L from x, 0 where L misses the light.
double lightPdf(const PreparedAreaLight& light, glm::dvec3 x, glm::dvec3 L) {
    if (light.cone) {
        const glm::dvec3 across = glm::cross(L, light.axis);
        const double sinSquared = glm::dot(across, across);
        const double maxSinSquared = light.oneMinusCosMax * (2.0 - light.oneMinusCosMax);
        return glm::dot(L, light.axis) > 0.0 && sinSquared <= maxSinSquared ? light.conePdf : 0.0;
    }
    const SurfaceHit hit = firstHit(light.shape, x, L);
    return hit.found ? areaPdf(light.shape, hit.distance, hit.normal, L) : 0.0;
}

// The shading point's side of the estimate: f(L) NoL by the lobes asked for, and the GGX pdf.
struct AreaLightIntegrand {
    BrdfModelId model;
    const shader::SurfaceMaterial& material;
    glm::vec3 P, N, V;
    const ReferenceOptions& options;
    ReferenceLayers layers;

    // Whether the light's surface along L is in sight of P (options.occluders).
    bool sees(const PreparedAreaLight& light, glm::dvec3 L) const {
        if (!options.occluders) {
            return true;
        }
        const SurfaceHit hit = firstHit(light.shape, glm::dvec3(P), L);
        return hit.found && unoccluded(options.occluders, P, N, glm::vec3(L), float(hit.distance));
    }

    glm::dvec3 operator()(const PreparedAreaLight& light, glm::dvec3 L) const {
        const float NoL = float(glm::dot(glm::dvec3(N), L));
        if (!(NoL > 0.0f) || !sees(light, L)) {
            return glm::dvec3(0.0);
        }
        const shader::BrdfValue f = evaluateBrdf(model, material, N, V, glm::vec3(L));
        return light.radiance * glm::dvec3(coatedBrdf(f, layers, N, V, glm::vec3(L), options)) * double(std::min(NoL, 1.0f));
    }
    double ggx(glm::dvec3 L) const { return double(ggxPdf(N, V, glm::vec3(L), material.alpha)); }
};

using Uniform = std::function<double()>;

// The light's own strategy: one direction towards it, MIS-weighted against GGX sampling.
glm::dvec3 sampleLight(const PreparedAreaLight& light, glm::dvec3 x, const AreaLightIntegrand& f, const Uniform& u) {
    if (light.cone) {
        const double oneMinusCos = u() * light.oneMinusCosMax;
        const double sinTheta = std::sqrt(std::max(0.0, oneMinusCos * (2.0 - oneMinusCos)));
        const double phi = 2.0 * std::numbers::pi * u();
        glm::dvec3 e1, e2;
        frameAround(light.axis, e1, e2);
        const glm::dvec3 L =
            glm::normalize(sinTheta * (std::cos(phi) * e1 + std::sin(phi) * e2) + (1.0 - oneMinusCos) * light.axis);
        return f(light, L) * misWeightOverPdf(light.conePdf, f.ggx(L));
    }
    const double u0 = u(), u1 = u(), u2 = u();
    const SurfacePoint q = sampleCapsule(light.shape, {u0, u1, u2});
    const glm::dvec3 toPoint = q.position - x;
    const double distance = glm::length(toPoint);
    const glm::dvec3 L = toPoint / distance;
    // From outside, a point facing away lies behind the capsule's near side.
    if (distance > 0.0 && (light.inside || glm::dot(q.normal, L) < 0.0)) {
        const double pdf = areaPdf(light.shape, distance, q.normal, L);
        return f(light, L) * misWeightOverPdf(pdf, f.ggx(L));
    }
    return glm::dvec3(0.0);
}

// GGX half-vector sampling (Karis 2013's sampler, shaders/shared/ibl.glsl): the ray counts where
// it reaches the light, MIS-weighted against the light's strategy.
glm::dvec3 sampleGgx(const PreparedAreaLight& light, glm::dvec3 x, const AreaLightIntegrand& f, const Uniform& u) {
    // Drawn in a fixed order: as two arguments of one call their order was the compiler's (GCC's,
    // second first, is kept: the same estimates as before).
    const float u1 = float(u()), u0 = float(u());
    const glm::vec3 H = shader::importanceSampleGGX(glm::vec2(u0, u1), f.material.alpha, f.N);
    const glm::dvec3 L = glm::normalize(glm::dvec3(2.0f * glm::dot(f.V, H) * H - f.V));
    const double ggx = f.ggx(L);
    const double other = lightPdf(light, x, L);
    return ggx > 0.0 && other > 0.0 ? f(light, L) * misWeightOverPdf(ggx, other) : glm::dvec3(0.0);
}
}  // namespace

ReferenceEstimate areaLightReference(BrdfModelId model, const shader::SurfaceMaterial& material,
                                     const std::vector<shader::PackedLight>& lights, glm::vec3 P, glm::vec3 N,
                                     glm::vec3 V, const ReferenceOptions& options) {
    N = shader::safeNormalize(N);
    V = shader::safeNormalize(V);
    std::vector<PreparedAreaLight> prepared;
    for (const shader::PackedLight& light : lights) {
        if (isAreaLight(light)) {
            prepared.push_back(prepareAreaLight(light, P));
        }
    }
    if (prepared.empty() || !(glm::dot(N, N) > 0.0f) || options.samples < 1) {
        return {};
    }
    const glm::dvec3 x(P);
    const AreaLightIntegrand integrand{model, material, P, N, V, options,
                                       {referenceCoat(options, N, V), referenceSheen(options, N, V)}};
    std::mt19937_64 random(options.seed ^ 0xA5EA11A5EA11A5EAull);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const Uniform u = [&] { return uniform(random); };
    SampleMoments moments;
    for (int i = 0; i < options.samples; ++i) {
        glm::dvec3 sample(0.0);
        for (const PreparedAreaLight& light : prepared) {
            sample += sampleLight(light, x, integrand, u);
            sample += sampleGgx(light, x, integrand, u);
        }
        moments.add(sample);
    }
    const double count = double(options.samples);
    return {glm::vec3(moments.mean(count)), glm::vec3(glm::sqrt(moments.varianceOfMean(count)))};
}

}  // namespace patina
