#pragma once
// What a render of a scene reads, and nothing it does not: no names, notes or a file's unknown
// keys. Two scenes whose inputs are equal draw the same image, so a cache of rendered images
// (the editor's viewport) compares these each frame instead of whole scenes, walking no JSON.
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/mesh.h"
#include "scene/prepared_scene.h"
#include "shading/material_parameters.h"
#include "shading/shading.h"

namespace patina {

struct RenderInputs {
    std::shared_ptr<const Mesh> mesh;                 // the prepared one
    std::shared_ptr<const Model> model;               // the prepared one, with its draws' materials
    std::vector<ModelMaterialEdit> modelMaterials;    // the scene's tuning of them: factors, maps left out
    MaterialParameters material;
    glm::vec3 cameraPosition{0.0f}, cameraTarget{0.0f};
    float fovYDegrees = 0.0f;
    std::vector<shader::PackedLight> lights;          // the enabled ones, as the shaders read them
    float exposure = 0.0f;
    Tonemap tonemap = Tonemap::None;
    glm::vec3 background{0.0f};
    // The enabled environment: what it shows (the prepared one, and the source its light
    // names), intensity and rotation; the background drawn from it.
    std::shared_ptr<const Environment> environment;
    std::string environmentSource;
    float environmentIntensity = 0.0f, environmentRotation = 0.0f;
    bool backgroundFromEnvironment = false;
    float backgroundBlur = 0.0f;
    Ground ground = Ground::None;   // and the floor's material
    glm::vec3 groundColor{0.0f};
    float groundRoughness = 0.0f;
    std::shared_ptr<const AmbientOcclusion> occlusion;   // the prepared one, while the display has it on

    // Light rows compared as their bytes: plain floats and ints, so equal bytes are equal
    // lights (a -0 against a 0 only costs one render more).
    bool operator==(const RenderInputs& other) const;
};

RenderInputs renderInputs(const PreparedScene& prepared);

}  // namespace patina
