#pragma once
#include <memory>

#include "environment/environment.h"

namespace patina {

// An environment's prefiltered chain as a GL cube map (RGB32F, one mip per level, seamless
// filtering on, trilinear), uploaded once per Environment shown. Needs a current context.
class EnvironmentTexture {
public:
    EnvironmentTexture() = default;
    ~EnvironmentTexture();
    EnvironmentTexture(const EnvironmentTexture&) = delete;
    EnvironmentTexture& operator=(const EnvironmentTexture&) = delete;

    // Uploads `environment` unless it is the one uploaded last, then binds it to `unit`.
    void bind(const std::shared_ptr<const Environment>& environment, int unit);

private:
    unsigned texture_ = 0;
    std::shared_ptr<const Environment> shown_;
};

}  // namespace patina
