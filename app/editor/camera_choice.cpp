#include "camera_choice.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/glm.hpp>

#include "scene/camera_placement.h"

namespace patina::editor {

std::vector<CameraChoice> cameraChoices(const Document& document) {
    std::vector<CameraChoice> choices{
        {kFrontCamera,
         "From the front and 15 degrees above, the whole shape in view: how model-viewer shows a model (camera-orbit "
         "0deg 75deg 105%), and how Patina frames a model it opens",
         true, -1}};
    if (!document.model) {
        return choices;
    }
    const std::vector<ModelCamera>& cameras = document.model->cameras;
    for (size_t i = 0; i < cameras.size(); ++i) {
        const ModelCamera& file = cameras[i];
        std::string detail = "The file's camera " + std::to_string(file.index) + " (node \"" + file.node + "\"): ";
        if (file.perspective) {
            char fov[64];
            std::snprintf(fov, sizeof fov, "perspective, %.1f degrees high",
                          double(std::clamp(glm::degrees(file.yfov), 1.0f, 179.0f)));
            detail += fov;
        } else {
            detail += "orthographic, which Patina does not draw";
        }
        choices.push_back({file.name, detail, file.perspective, int(i)});
    }
    return choices;
}

std::string currentCameraName(const EditorState& state) {
    if (!state.cameraName.empty() && state.cameraView == state.scene.camera) {
        return state.cameraName;
    }
    return state.scene.camera == state.savedScene.camera ? "the scene's" : "free";
}

void rememberCamera(EditorState& state, const std::string& name) {
    state.cameraName = name;
    state.cameraView = state.scene.camera;
}

void chooseCamera(EditorState& state, const CameraChoice& choice) {
    const bool inModel = state.model && choice.fileCamera >= 0 && choice.fileCamera < int(state.model->cameras.size());
    if (!choice.usable || (choice.fileCamera >= 0 && !inModel)) {
        state.status = choice.detail;
        return;
    }
    float roll = 0.0f;
    if (inModel) {
        roll = placeModelCamera(state.scene.camera, state.model->cameras[size_t(choice.fileCamera)], meshBounds(state));
    } else {
        frameAsModelViewer(state.scene.camera, meshBounds(state));
    }
    rememberCamera(state, choice.name);
    state.status = "Camera: " + choice.name;
    if (std::abs(roll) > 0.5f) {
        char text[120];
        std::snprintf(text, sizeof text, " (rolled %.1f degrees in the file: shown level, +Y up)", double(roll));
        state.status += text;
    }
}

}  // namespace patina::editor
