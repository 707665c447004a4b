#pragma once
// Emulated IEEE 754 binary16 ("half") arithmetic on the CPU: every value, and the result of
// every operation and function, is rounded to the nearest half (ties to even), overflowing to
// infinity past 65504 and keeping subnormals. Enough of GLSL's vocabulary to compile the shared
// shaders with `float` meaning half (engine/shading/shading_f16.h), the fp16 row of `patina stability`.
#include <algorithm>
#include <cmath>

namespace patina {

// The nearest binary16 value of x, as a float.
inline float roundToHalf(float x) {
    if (!std::isfinite(x) || x == 0.0f) {
        return x;
    }
    const float magnitude = std::fabs(x);
    if (magnitude >= 65520.0f) {   // 65504 plus half an ulp rounds to infinity
        return std::copysign(INFINITY, x);
    }
    if (magnitude < 6.103515625e-05f) {   // subnormal: a fixed quantum of 2^-24
        return std::copysign(std::nearbyint(magnitude * 16777216.0f) / 16777216.0f, x);
    }
    int exponent = 0;
    std::frexp(magnitude, &exponent);   // magnitude = m 2^exponent, m in [0.5, 1)
    const float quantum = std::ldexp(1.0f, exponent - 11);   // 11 significant bits
    return std::copysign(std::nearbyint(magnitude / quantum) * quantum, x);
}

struct Half {
    float value = 0.0f;   // always a binary16 value

    Half() = default;
    Half(float v) : value(roundToHalf(v)) {}
    Half(double v) : value(roundToHalf(float(v))) {}
    Half(int v) : value(roundToHalf(float(v))) {}
    explicit operator float() const { return value; }
    explicit operator double() const { return value; }
    explicit operator int() const { return int(value); }

    Half& operator+=(Half o) { return *this = Half(value + o.value); }
    Half& operator-=(Half o) { return *this = Half(value - o.value); }
    Half& operator*=(Half o) { return *this = Half(value * o.value); }
    Half& operator/=(Half o) { return *this = Half(value / o.value); }
};

inline Half operator+(Half a, Half b) { return Half(a.value + b.value); }
inline Half operator-(Half a, Half b) { return Half(a.value - b.value); }
inline Half operator*(Half a, Half b) { return Half(a.value * b.value); }
inline Half operator/(Half a, Half b) { return Half(a.value / b.value); }
inline Half operator-(Half a) { return Half(-a.value); }
inline bool operator<(Half a, Half b) { return a.value < b.value; }
inline bool operator>(Half a, Half b) { return a.value > b.value; }
inline bool operator<=(Half a, Half b) { return a.value <= b.value; }
inline bool operator>=(Half a, Half b) { return a.value >= b.value; }
inline bool operator==(Half a, Half b) { return a.value == b.value; }
inline bool operator!=(Half a, Half b) { return a.value != b.value; }

// GLSL's vec3 in half precision.
struct HalfVec3 {
    Half x, y, z;

    HalfVec3() = default;
    explicit HalfVec3(Half s) : x(s), y(s), z(s) {}
    explicit HalfVec3(float s) : HalfVec3(Half(s)) {}
    HalfVec3(Half a, Half b, Half c) : x(a), y(b), z(c) {}

    HalfVec3& operator+=(HalfVec3 o) { return *this = HalfVec3(x + o.x, y + o.y, z + o.z); }
    Half operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
};

inline HalfVec3 operator+(HalfVec3 a, HalfVec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline HalfVec3 operator-(HalfVec3 a, HalfVec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline HalfVec3 operator*(HalfVec3 a, HalfVec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline HalfVec3 operator/(HalfVec3 a, HalfVec3 b) { return {a.x / b.x, a.y / b.y, a.z / b.z}; }
inline HalfVec3 operator*(HalfVec3 a, Half s) { return {a.x * s, a.y * s, a.z * s}; }
inline HalfVec3 operator*(Half s, HalfVec3 a) { return a * s; }
inline HalfVec3 operator/(HalfVec3 a, Half s) { return {a.x / s, a.y / s, a.z / s}; }
inline HalfVec3 operator-(HalfVec3 a) { return {-a.x, -a.y, -a.z}; }

// The GLSL built-ins the shared shaders use, each rounding its result.
namespace half_glsl {
inline Half max(Half a, Half b) { return a > b ? a : b; }
inline Half min(Half a, Half b) { return a < b ? a : b; }
inline int min(int a, int b) { return std::min(a, b); }
inline Half clamp(Half x, Half lo, Half hi) { return min(max(x, lo), hi); }
inline HalfVec3 min(HalfVec3 a, HalfVec3 b) { return {min(a.x, b.x), min(a.y, b.y), min(a.z, b.z)}; }
inline Half mix(Half a, Half b, Half t) { return a + (b - a) * t; }
inline HalfVec3 mix(HalfVec3 a, HalfVec3 b, Half t) { return a + (b - a) * t; }
inline Half sqrt(Half x) { return Half(std::sqrt(x.value)); }
inline Half inversesqrt(Half x) { return Half(1.0f / std::sqrt(x.value)); }
inline Half exp2(Half x) { return Half(std::exp2(x.value)); }
inline Half log2(Half x) { return Half(std::log2(x.value)); }
inline Half acos(Half x) { return Half(std::acos(x.value)); }
inline Half atan(Half x) { return Half(std::atan(x.value)); }
inline Half dot(HalfVec3 a, HalfVec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Half abs(Half x) { return x < Half(0.0f) ? -x : x; }
inline Half length(HalfVec3 a) { return sqrt(dot(a, a)); }
inline HalfVec3 normalize(HalfVec3 a) { return a * inversesqrt(dot(a, a)); }
inline HalfVec3 cross(HalfVec3 a, HalfVec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
}  // namespace half_glsl

}  // namespace patina
