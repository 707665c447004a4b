#pragma once
#include "geometry/mesh.h"
#include "scene/scene.h"

namespace patina {

// The scene's mesh: its glTF file when it names one (InputError if that cannot be loaded),
// else the built-in kind.
Mesh makeMesh(const Scene& scene);

}  // namespace patina
