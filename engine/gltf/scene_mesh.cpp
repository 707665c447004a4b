#include "gltf/scene_mesh.h"

#include "gltf/import.h"

namespace patina {

Mesh makeMesh(const Scene& scene) {
    return scene.meshFile.empty() ? makeMesh(scene.mesh) : importGltf(scene.meshFile).mesh;
}

}  // namespace patina
