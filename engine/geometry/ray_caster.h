#pragma once
// What blocks a ray: the scene's triangles in world space, in Embree 3's BVH (Debian's
// libembree). The product's ambient occlusion (scene/ambient_occlusion.h) and the ground
// truth's visibility (reference/visibility.h: shadow rays to each light, the environment's
// occlusion) both cast through it; queries are safe from many threads at once.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

namespace patina {

class RayCaster {
public:
    // Triangles as corners of `positions` three indices at a time. Throws std::runtime_error
    // when Embree cannot build (it names Embree's error).
    RayCaster(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& indices);
    ~RayCaster();
    RayCaster(const RayCaster&) = delete;
    RayCaster& operator=(const RayCaster&) = delete;

    // Whether a triangle lies on the ray from `origin` along unit `direction`, between `near`
    // and `far` (infinity: the whole ray).
    bool occluded(glm::vec3 origin, glm::vec3 direction, float near, float far) const;

    size_t triangles() const { return triangles_; }

private:
    struct Embree;
    std::unique_ptr<Embree> embree_;
    size_t triangles_ = 0;
};

// The start of a shadow ray from a surface point: lifted off the surface along its normal (on
// the side the ray leaves by) by a distance that grows with the point's distance from the
// origin, so that the ray does not find the triangle it starts on (float rounding of P and of
// the triangle's plane; Wächter & Binder 2019, "A Fast and Robust Method for Avoiding
// Self-Intersection", Ray Tracing Gems ch. 6, in its simplest, scale-relative form).
glm::vec3 rayOrigin(glm::vec3 P, glm::vec3 N, glm::vec3 direction);

// Whether nothing of `occluders` lies between the surface point P (normal N) and the point
// `far` along unit L from it; true without occluders.
bool unoccluded(const RayCaster* occluders, glm::vec3 P, glm::vec3 N, glm::vec3 L, float far);

}  // namespace patina
