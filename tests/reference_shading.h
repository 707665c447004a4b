#pragma once
// A plainly written double-precision reference of docs/SHADING.md S1, with no
// guards: each formula exactly as S1 states it. It shares no code with shaders/, so the
// shared GLSL/C++ is checked against an independent transcription.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace patina::reference {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(Vec3 a, Vec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) { return (1.0 / length(a)) * a; }


struct Material {
    Vec3 baseColor;
    double roughness, specular, metallic;
};

struct Light {
    enum Type { Point, Directional, Hemisphere } type;
    Vec3 color;
    double intensity;
    Vec3 position;
    double range;
    double ac, al, aq;
    Vec3 direction;
    Vec3 sky, ground;
};

inline Vec3 diffuseColor(const Material& m) { return (1.0 - m.metallic) * m.baseColor; }

inline Vec3 specularColor(const Material& m) {
    const Vec3 dielectric{0.08 * m.specular, 0.08 * m.specular, 0.08 * m.specular};
    return (1.0 - m.metallic) * dielectric + m.metallic * m.baseColor;
}

inline double D(double NoH, double r) {
    const double alpha = r * r, a2 = alpha * alpha;
    const double base = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (std::numbers::pi * base * base);
}

inline double G(double NoL, double NoV, double r) {
    const double k = (r + 1.0) * (r + 1.0) / 8.0;
    auto G1 = [k](double x) { return x / (x * (1.0 - k) + k); };
    return G1(NoL) * G1(NoV);
}

inline Vec3 F(Vec3 cSpec, double VoH) {
    const double w = std::pow(2.0, (-5.55473 * VoH - 6.98316) * VoH);
    return cSpec + w * (Vec3{1, 1, 1} - cSpec);
}

struct Brdf {
    Vec3 diffuse, specular;
};

// f = d + sp. N, V, L are made unit here, in double: fp32 inputs are unit only to about 1e-7,
// and 1 - NoH^2 near the GGX peak magnifies that a thousandfold.
inline Brdf brdf(const Material& m, Vec3 N, Vec3 V, Vec3 L) {
    N = normalize(N);
    V = normalize(V);
    L = normalize(L);
    const Vec3 H = normalize(L + V);
    const double NoL = dot(N, L), NoV = dot(N, V), NoH = dot(N, H), VoH = dot(V, H);
    const Vec3 d = (1.0 / std::numbers::pi) * diffuseColor(m);
    const Vec3 sp = (D(NoH, m.roughness) * G(NoL, NoV, m.roughness) / (4.0 * NoL * NoV)) *
                    F(specularColor(m), VoH);
    return {d, sp};
}

// c_out for one light; zero where the light is behind the surface.
inline Vec3 shade(const Material& m, const Light& light, Vec3 P, Vec3 N, Vec3 V) {
    N = normalize(N);
    const Vec3 cLight = light.intensity * light.color;
    if (light.type == Light::Hemisphere) {
        const double w = std::clamp(N.y, 0.0, 1.0);
        const Vec3 sky = (1.0 - w) * light.ground + w * light.sky;
        return (sky * cLight) * ((1.0 / std::numbers::pi) * diffuseColor(m));
    }
    Vec3 L;
    double attenuation = 1.0;
    if (light.type == Light::Point) {
        const Vec3 toLight = light.position - P;
        const double t = length(toLight);
        L = (1.0 / t) * toLight;
        double window = 1.0;
        if (light.range > 0) {
            window = std::clamp(1.0 - std::pow(t / light.range, 4.0), 0.0, 1.0);
            window *= window;
        }
        attenuation = window / (light.ac + light.al * t + light.aq * t * t);
    } else {
        L = -1.0 * normalize(light.direction);
    }
    const double NoL = dot(N, L);
    if (NoL <= 0) {
        return {};
    }
    const Brdf f = brdf(m, N, V, L);
    return (attenuation * NoL) * (cLight * (f.diffuse + f.specular));
}

inline Vec3 shadeAll(const Material& m, const std::vector<Light>& lights, Vec3 P, Vec3 N, Vec3 V) {
    Vec3 sum;
    for (const Light& light : lights) {
        sum = sum + shade(m, light, P, N, V);
    }
    return sum;
}

}  // namespace patina::reference
