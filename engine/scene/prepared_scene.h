#pragma once
// What the renderer and the ground truth draw: the document with what was loaded for it.
#include <memory>

#include "environment/environment.h"
#include "geometry/mesh.h"
#include "scene/scene.h"

namespace patina {

// A scene document and the things it names, made ready (assets/prepare_scene.h). Whoever
// draws it loads nothing: a mesh or an environment missing here is the caller's mistake.
// It refers to the document, which must outlive it; the loaded things are shared.
struct PreparedScene {
    const Scene& scene;
    std::shared_ptr<const Mesh> mesh;                // never null: the file's or the built-in kind's
    // The enabled environment light's source made ready (kept while the light is off, so
    // turning it on again loads nothing); null when the scene has none.
    std::shared_ptr<const Environment> environment;
};

}  // namespace patina
