#include "scene/ambient_occlusion.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "model/placement.h"
#include "scene/ground.h"

namespace patina {

namespace {
// The points to bake: each vertex in the world with its normal, and where each item's begin.
struct BakePoints {
    std::vector<glm::vec3> positions, normals;
    std::vector<size_t> starts;   // an entry per item and one past the last
    void add(const Mesh& mesh, const glm::mat4& transform) {
        starts.push_back(positions.size());
        const glm::mat3 normals3 = normalTransform(transform);
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            positions.push_back(glm::vec3(transform * glm::vec4(mesh.positions[i], 1.0f)));
            normals.push_back(unitNormal(normals3 * (i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0))));
        }
    }
};

// Rays a vertex: `rays`, or more for a shape of few vertices (up to 24 x 24, within about four
// million rays): its smooth faces show a few percent of per-vertex noise as streaks (a new
// user's review: the built-in sphere's lower half, in the specular occlusion most), where a
// model of many vertices hides it in its detail and keeps the 64.
OcclusionRays raysFor(const OcclusionRays& rays, size_t vertices) {
    constexpr double kRayBudget = 4.0e6;
    const int side = int(std::sqrt(kRayBudget / double(std::max<size_t>(vertices, 1))));
    OcclusionRays more = rays;
    more.side = std::max(rays.side, std::min(side, 24));
    return more;
}
}  // namespace

AmbientOcclusion bakeAmbientOcclusion(const Mesh& world, const Model* model, bool ground, const OcclusionRays& rays) {
    AmbientOcclusion occlusion;
    occlusion.withGround = ground;
    const GroundPlane plane = groundUnder(boundingBox(world));
    // The occluders: the shape, and the ground, which hides the sky below it.
    std::vector<glm::vec3> positions = world.positions;
    std::vector<uint32_t> indices = world.indices;
    if (ground) {
        // A hair below the model's lowest point: a vertex lying on the ground (a sphere's pole)
        // lifts its rays' start off along its normal (rayOrigin), which would put it under a
        // plane at its own height, seeing the sky through it.
        GroundPlane lowered = plane;
        lowered.centre.y -= 1e-3f * std::max(plane.halfSize, 1.0f);
        const Mesh square = groundMesh(lowered);
        const uint32_t first = uint32_t(positions.size());
        positions.insert(positions.end(), square.positions.begin(), square.positions.end());
        for (const uint32_t i : square.indices) {
            indices.push_back(first + i);
        }
        occlusion.ground = groundGrid(plane, kOcclusionGroundCells);
    }
    const RayCaster occluders(positions, indices);
    BakePoints points;
    if (model) {
        for (const DrawItem& item : model->draws) {
            points.add(model->primitives.at(size_t(item.primitive)), item.transform);
        }
    } else {
        points.add(world, glm::mat4(1.0f));
    }
    points.starts.push_back(points.positions.size());
    // One pass over every vertex (one pool of threads, not one per item).
    const std::vector<float> shares =
        unoccludedShares(occluders, points.positions, points.normals, raysFor(rays, points.positions.size()));
    for (size_t k = 0; k + 1 < points.starts.size(); ++k) {
        occlusion.items.emplace_back(shares.begin() + std::ptrdiff_t(points.starts[k]),
                                     shares.begin() + std::ptrdiff_t(points.starts[k + 1]));
    }
    // The ground's grid with four times the rays: its noise would show as blotches over a
    // plain floor, where a model's hides in its detail.
    OcclusionRays groundRays = rays;
    groundRays.side = 2 * rays.side;
    occlusion.groundValues = unoccludedShares(occluders, occlusion.ground.positions, occlusion.ground.normals, groundRays);
    return occlusion;
}

const std::vector<float>* itemOcclusion(const AmbientOcclusion& occlusion, int item, size_t vertices) {
    const size_t index = item < 0 ? 0 : size_t(item);
    if (index >= occlusion.items.size() || occlusion.items[index].size() != vertices) {
        return nullptr;
    }
    return &occlusion.items[index];
}

}  // namespace patina
