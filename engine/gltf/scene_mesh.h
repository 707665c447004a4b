#pragma once
#include "geometry/mesh.h"
#include "scene/scene.h"

namespace patina {

// Sets scene.resolvedMesh: its glTF file's triangles when it names one (read here, once; an
// InputError if that cannot be loaded, leaving the scene as it was), else the built-in kind's.
void resolveMesh(Scene& scene);

}  // namespace patina
