#include "environment/irradiance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <glm/vec2.hpp>

#include "common/parallel_for.h"

namespace patina {

namespace {
// The moment of an equirect pixel separates into a part of its row (theta from t0 to t1) and
// a part of its column (phi from p0 to p1), with l dl = (sin t sin p, cos t, -sin t cos p) sin t dt dp.
struct RowPart {
    double sinSquared;   // integral of sin^2 t dt = (t1 - t0) / 2 - (sin 2 t1 - sin 2 t0) / 4
    double sinCos;       // integral of sin t cos t dt = (sin^2 t1 - sin^2 t0) / 2
};
struct ColumnPart {
    double sin;     // integral of sin p dp = cos p0 - cos p1
    double cos;     // integral of cos p dp = sin p1 - sin p0
    double width;   // p1 - p0
};

RowPart rowPart(int height, int y) {
    const double pi = std::numbers::pi;
    const double t0 = pi * double(y) / double(height), t1 = pi * double(y + 1) / double(height);
    const double s0 = std::sin(t0), s1 = std::sin(t1);
    return {(t1 - t0) / 2.0 - (std::sin(2.0 * t1) - std::sin(2.0 * t0)) / 4.0, (s1 * s1 - s0 * s0) / 2.0};
}

ColumnPart columnPart(int width, int x) {
    const double pi = std::numbers::pi;
    const double p0 = 2.0 * pi * double(x) / double(width) - pi, p1 = 2.0 * pi * double(x + 1) / double(width) - pi;
    return {std::cos(p0) - std::cos(p1), std::sin(p1) - std::sin(p0), p1 - p0};
}

glm::dvec3 moment(const RowPart& row, const ColumnPart& column) {
    return {row.sinSquared * column.sin, row.sinCos * column.width, -row.sinSquared * column.cos};
}

// Per channel, the cells' moments as three arrays (x, y, z), padded with zeros to a multiple of
// kLanes so that the sum below runs kLanes cells at a time.
constexpr size_t kLanes = 8;
struct CellMoments {
    size_t count = 0;
    std::array<std::array<std::vector<float>, 3>, 3> axes;   // [channel][axis][cell]
};

CellMoments cellMoments(const HdrImage& image, int cellSize) {
    const size_t cells = size_t(6) * size_t(cellSize) * size_t(cellSize);
    std::vector<glm::dvec3> sums(cells * 3, glm::dvec3(0.0));   // [cell][channel]
    std::vector<ColumnPart> columns(size_t(image.width));
    std::vector<glm::dvec2> columnSinCos(size_t(image.width));   // sin, cos of phi at the pixel's centre
    for (int x = 0; x < image.width; ++x) {
        columns[size_t(x)] = columnPart(image.width, x);
        const double phi = (double(x) + 0.5) / double(image.width) * 2.0 * std::numbers::pi - std::numbers::pi;
        columnSinCos[size_t(x)] = {std::sin(phi), std::cos(phi)};
    }
    for (int y = 0; y < image.height; ++y) {
        const RowPart row = rowPart(image.height, y);
        const double theta = (double(y) + 0.5) / double(image.height) * std::numbers::pi;
        const double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
        for (int x = 0; x < image.width; ++x) {
            const float* p = &image.rgb[(size_t(y) * size_t(image.width) + size_t(x)) * 3];
            if (p[0] == 0.0f && p[1] == 0.0f && p[2] == 0.0f) {
                continue;
            }
            const glm::dvec2 phi = columnSinCos[size_t(x)];
            const CubeCoordinate c = cubeCoordinate(glm::vec3(sinTheta * phi.x, cosTheta, -sinTheta * phi.y));
            const int s = std::min(int(c.s * float(cellSize)), cellSize - 1);
            const int t = std::min(int(c.t * float(cellSize)), cellSize - 1);
            const size_t cell = (size_t(c.face) * size_t(cellSize) + size_t(t)) * size_t(cellSize) + size_t(s);
            const glm::dvec3 m = moment(row, columns[size_t(x)]);
            for (size_t channel = 0; channel < 3; ++channel) {
                sums[cell * 3 + channel] += double(p[channel]) * m;
            }
        }
    }
    CellMoments moments;
    moments.count = (cells + kLanes - 1) / kLanes * kLanes;
    for (size_t channel = 0; channel < 3; ++channel) {
        for (size_t axis = 0; axis < 3; ++axis) {
            std::vector<float>& values = moments.axes[channel][axis];
            values.assign(moments.count, 0.0f);
            for (size_t cell = 0; cell < cells; ++cell) {
                values[cell] = float(sums[cell * 3 + channel][int(axis)]);
            }
        }
    }
    return moments;
}

// Sum over the cells of max(n.M, 0), kLanes partial sums at a time (the compiler vectorises it).
float clampedSum(glm::vec3 n, const std::array<std::vector<float>, 3>& axes, size_t count) {
    const float *x = axes[0].data(), *y = axes[1].data(), *z = axes[2].data();
    float partial[kLanes] = {};
    for (size_t i = 0; i < count; i += kLanes) {
        for (size_t lane = 0; lane < kLanes; ++lane) {
            const float d = n.x * x[i + lane] + n.y * y[i + lane] + n.z * z[i + lane];
            partial[lane] += d > 0.0f ? d : 0.0f;
        }
    }
    float sum = 0.0f;
    for (float value : partial) {
        sum += value;
    }
    return sum;
}
}  // namespace

glm::dvec3 pixelMoment(int width, int height, int x, int y) {
    return moment(rowPart(height, y), columnPart(width, x));
}

CubeLevel irradianceCube(const HdrImage& equirect, int faceSize, int cellSize) {
    const CellMoments moments = cellMoments(equirect, cellSize);
    CubeLevel level(faceSize);
    parallelFor(size_t(6) * size_t(faceSize), [&](size_t row) {
        const int face = int(row) / faceSize, t = int(row) % faceSize;
        for (int s = 0; s < faceSize; ++s) {
            const glm::vec3 n = cubeTexelDirection(face, s, t, faceSize);
            glm::vec3 irradiance;
            for (int channel = 0; channel < 3; ++channel) {
                irradiance[channel] = clampedSum(n, moments.axes[size_t(channel)], moments.count);
            }
            level.setTexel(face, s, t, irradiance);
        }
    });
    return level;
}

}  // namespace patina
