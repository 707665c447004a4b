#include "geometry/ray_caster.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>

namespace patina {

struct RayCaster::Embree {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    ~Embree() {
        if (scene) {
            rtcReleaseScene(scene);
        }
        if (device) {
            rtcReleaseDevice(device);
        }
    }
    void check(const char* step) const {
        const RTCError error = rtcGetDeviceError(device);
        if (error != RTC_ERROR_NONE) {
            throw std::runtime_error(std::string("Embree could not ") + step + " (error " + std::to_string(int(error)) + ")");
        }
    }
};

RayCaster::RayCaster(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices)
    : embree_(std::make_unique<Embree>()), triangles_(indices.size() / 3) {
    embree_->device = rtcNewDevice(nullptr);
    if (!embree_->device) {
        throw std::runtime_error("Embree could not start (rtcNewDevice)");
    }
    embree_->scene = rtcNewScene(embree_->device);
    embree_->check("make a scene");
    if (triangles_ > 0 && !positions.empty()) {
        RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        // Embree reads its vertex buffers 16 bytes at a time: one float of padding at the end.
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size() + 1));
        auto* triangles = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triangles_));
        embree_->check("allocate the triangles");
        std::memcpy(vertices, positions.data(), positions.size() * sizeof(glm::vec3));
        std::fill(vertices + 3 * positions.size(), vertices + 3 * positions.size() + 3, 0.0f);
        std::memcpy(triangles, indices.data(), triangles_ * 3 * sizeof(uint32_t));
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(embree_->scene, geometry);
        rtcReleaseGeometry(geometry);
    }
    rtcCommitScene(embree_->scene);
    embree_->check("build its hierarchy");
}

RayCaster::~RayCaster() = default;

bool RayCaster::occluded(glm::vec3 origin, glm::vec3 direction, float near, float far) const {
    if (triangles_ == 0) {
        return false;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = direction.x;
    ray.dir_y = direction.y;
    ray.dir_z = direction.z;
    ray.tnear = near;
    ray.tfar = far;
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(embree_->scene, &context, &ray);
    return ray.tfar < 0.0f;   // Embree marks a blocked ray with tfar = -inf
}

glm::vec3 rayOrigin(glm::vec3 P, glm::vec3 N, glm::vec3 direction) {
    const float scale = std::max({1.0f, std::abs(P.x), std::abs(P.y), std::abs(P.z)});
    const float side = glm::dot(N, direction) >= 0.0f ? 1.0f : -1.0f;
    return P + N * (side * 1e-4f * scale);
}

bool unoccluded(const RayCaster* occluders, glm::vec3 P, glm::vec3 N, glm::vec3 L, float far) {
    if (!occluders) {
        return true;
    }
    const glm::vec3 origin = rayOrigin(P, N, L);
    // The light's own end of the ray stops short of it by the same lift, for a light on a surface.
    return !occluders->occluded(origin, L, 0.0f, std::isinf(far) ? far : far - glm::length(origin - P));
}

}  // namespace patina
