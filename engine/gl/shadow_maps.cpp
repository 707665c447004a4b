#include "gl/shadow_maps.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace patina {

namespace {
// Clip space's [-1, 1] to the map's [0, 1], depth included.
const glm::mat4 kClipToTexture = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));

glm::vec3 upFor(glm::vec3 forward) {
    return std::abs(forward.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

// A sphere's or tube's extent across the view `look` (uShadowSources' row, ShadowView::source):
// the tube's half-segment as the map sees it plus the radius along it, the radius across it.
glm::vec4 sourceExtent(const shader::PackedLight& light, const glm::mat4& look, float texelAtUnitW) {
    if (light.type != shader::LIGHT_SPHERE && light.type != shader::LIGHT_TUBE) {
        return glm::vec4(0.0f);
    }
    const float radius = std::max(light.sourceRadius, 0.0f);
    const glm::vec3 half = light.type == shader::LIGHT_TUBE ? 0.5f * (light.tubeEnd - light.position) : glm::vec3(0.0f);
    const glm::vec2 seen{look[0][0] * half.x + look[1][0] * half.y + look[2][0] * half.z,
                         look[0][1] * half.x + look[1][1] * half.y + look[2][1] * half.z};   // its right and up
    const float length = glm::length(seen);
    const glm::vec2 axis = length > 0.0f ? seen / length : glm::vec2(1.0f, 0.0f);
    const glm::vec2 along = seen + radius * axis;
    return glm::vec4(along / texelAtUnitW, radius / texelAtUnitW, 0.0f);
}

// A directional light's orthographic view along its direction, fitted to the sphere.
ShadowView directionalView(const shader::PackedLight& light, glm::vec3 centre, float radius, const ShadowMapSettings& maps) {
    ShadowView view;
    const glm::vec3 forward = -glm::normalize(light.directionToLight);
    const glm::mat4 look = glm::lookAt(centre - 2.0f * radius * forward, centre, upFor(forward));
    view.clip = glm::ortho(-radius, radius, -radius, radius, radius, 3.0f * radius) * look;
    view.texel = {maps.biasScale * 2.0f * radius / float(maps.size), 1.0f / float(maps.size), 1.0f, 0.0f};
    return view;
}

// A perspective view from `eye` along `forward`, `fieldOfView` wide (radians), from `nearPlane`
// to `farPlane`, with the light's size across it for PCSS (sourceExtent) and its depths.
ShadowView perspectiveView(const shader::PackedLight& light, glm::vec3 eye, glm::vec3 forward, float fieldOfView,
                           float nearPlane, float farPlane, const ShadowMapSettings& maps) {
    ShadowView view;
    const glm::mat4 look = glm::lookAt(eye, eye + forward, upFor(forward));
    view.clip = glm::perspective(fieldOfView, 1.0f, nearPlane, farPlane) * look;
    const float texelAtUnitW = 2.0f * std::tan(0.5f * fieldOfView) / float(maps.size);
    view.texel = {maps.biasScale * texelAtUnitW, 1.0f / float(maps.size), 1.0f, 0.0f};
    view.source = sourceExtent(light, look, texelAtUnitW);
    view.range = {nearPlane, farPlane};
    return view;
}
}  // namespace

std::vector<ShadowView> shadowViewsOf(const shader::PackedLight& light, glm::vec3 centre, float radius,
                                      const ShadowMapSettings& maps) {
    if (!(radius > 0.0f) || light.type == shader::LIGHT_HEMISPHERE) {
        return {};
    }
    std::vector<ShadowView> views;
    if (light.type == shader::LIGHT_DIRECTIONAL) {
        views.push_back(directionalView(light, centre, radius, maps));
    } else {
        // A tube looks from its segment's middle.
        const glm::vec3 eye = light.type == shader::LIGHT_TUBE ? 0.5f * (light.position + light.tubeEnd) : light.position;
        const float distance = glm::length(centre - eye);
        if (distance > 1.01f * radius) {   // the narrowest cone that holds the sphere
            const float nearPlane = std::max(distance - radius, 0.01f * distance);
            views.push_back(perspectiveView(light, eye, (centre - eye) / distance, 2.0f * std::asin(radius / distance),
                                            nearPlane, distance + radius, maps));
        } else {   // among the casters: every way, out to the sphere's far side
            // Each face a little wider than its 90 degrees (tan 1.06, about 60 texels at 2048 a
            // side): the filter's taps near a face's edge read depths, not the border's "lit"
            // (thin lines of light along the seams).
            const float fieldOfView = 2.0f * std::atan(1.06f);
            const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
            for (const glm::vec3& forward : axes) {
                views.push_back(perspectiveView(light, eye, forward, fieldOfView, 0.005f * radius, distance + radius, maps));
            }
        }
    }
    for (ShadowView& view : views) {
        view.texture = kClipToTexture * view.clip;
    }
    return views;
}

ShadowMaps::~ShadowMaps() {
    glDeleteSamplers(1, &depthSampler_);
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &texture_);
}

GLuint ShadowMaps::depthSampler() {
    if (!depthSampler_) {
        glGenSamplers(1, &depthSampler_);
        glSamplerParameteri(depthSampler_, GL_TEXTURE_COMPARE_MODE, GL_NONE);
        glSamplerParameteri(depthSampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glSamplerParameteri(depthSampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glSamplerParameteri(depthSampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        glSamplerParameteri(depthSampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        const GLfloat far[4] = {1.0f, 1.0f, 1.0f, 1.0f};   // outside the map: no blocker
        glSamplerParameterfv(depthSampler_, GL_TEXTURE_BORDER_COLOR, far);
    }
    return depthSampler_;
}

void ShadowMaps::beginLayer(int layers, int layer, int size) {
    layers = std::max(layers, 1);
    if (layers > layers_ || size != size_) {
        glDeleteTextures(1, &texture_);
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_2D_ARRAY, texture_);
        glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT24, size, size, layers, 0,
                     GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
        // Hardware PCF: each tap compares the four nearest texels and filters the results.
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        // Outside the map: the far depth, lit.
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        const GLfloat far[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        glTexParameterfv(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BORDER_COLOR, far);
        layers_ = layers;
        size_ = size;
    }
    if (!framebuffer_) {
        glGenFramebuffers(1, &framebuffer_);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, texture_, 0, layer);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw std::runtime_error("the shadow map's framebuffer is incomplete");
    }
    glViewport(0, 0, size, size);
    glDisable(GL_SCISSOR_TEST);
    glDepthMask(GL_TRUE);
    const GLfloat clearDepth = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &clearDepth);
}

}  // namespace patina
