#include "gltf/scene_mesh.h"

#include "gltf/import.h"

namespace patina {

void resolveMesh(Scene& scene) {
    scene.resolvedMesh = scene.meshFile.empty() ? builtinMesh(scene.mesh)
                                                : std::make_shared<const Mesh>(importGltf(scene.meshFile).mesh);
}

}  // namespace patina
