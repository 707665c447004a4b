#include "state/camera_choice.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/glm.hpp>

#include "scene/camera_placement.h"
#include "views/text_match.h"

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

std::string currentCameraName(const Document& document, const Interaction& interaction) {
    if (!interaction.cameraName.empty() && interaction.cameraView == document.scene.camera) {
        return interaction.cameraName;
    }
    return document.scene.camera == document.savedScene.camera ? "the scene's" : "free";
}

void rememberCamera(Interaction& interaction, const Camera& camera, const std::string& name) {
    interaction.cameraName = name;
    interaction.cameraView = camera;
}

void chooseCamera(Document& document, Interaction& interaction, Prompts& prompts, const CameraChoice& choice) {
    const bool inModel =
        document.model && choice.fileCamera >= 0 && choice.fileCamera < int(document.model->cameras.size());
    if (!choice.usable || (choice.fileCamera >= 0 && !inModel)) {
        prompts.status = choice.detail;
        return;
    }
    float roll = 0.0f;
    if (inModel) {
        roll = placeModelCamera(document.scene.camera, document.model->cameras[size_t(choice.fileCamera)],
                                meshBounds(document));
    } else {
        frameAsModelViewer(document.scene.camera, meshBounds(document));
    }
    rememberCamera(interaction, document.scene.camera, choice.name);
    prompts.status = "Camera: " + choice.name;
    if (std::abs(roll) > 0.5f) {
        char text[120];
        std::snprintf(text, sizeof text, " (rolled %.1f degrees in the file: shown level, +Y up)", double(roll));
        prompts.status += text;
    }
}

void saveBookmark(Document& document, Interaction& interaction, Prompts& prompts, const std::string& name) {
    const std::string named = trimmed(name);
    if (named.empty()) {
        prompts.status = "A bookmark needs a name: type one beside Save view";
        return;
    }
    applyEdit(document, [&](Document& d) {
        std::vector<CameraBookmark>& bookmarks = d.scene.bookmarks;
        const auto same = std::find_if(bookmarks.begin(), bookmarks.end(),
                                       [&](const CameraBookmark& bookmark) { return bookmark.name == named; });
        if (same != bookmarks.end()) {
            same->camera = d.scene.camera;
        } else {
            bookmarks.push_back({named, d.scene.camera});
        }
    });
    rememberCamera(interaction, document.scene.camera, named);
    prompts.status = "Saved the view as the bookmark " + named;
}

void goToBookmark(Document& document, Interaction& interaction, Prompts& prompts, size_t index) {
    if (index >= document.scene.bookmarks.size()) {
        return;
    }
    const CameraBookmark& bookmark = document.scene.bookmarks[index];
    document.scene.camera = bookmark.camera;
    rememberCamera(interaction, bookmark.camera, bookmark.name);
    prompts.status = "Camera: the bookmark " + bookmark.name;
}

void deleteBookmark(Document& document, Prompts& prompts, size_t index) {
    if (index >= document.scene.bookmarks.size()) {
        return;
    }
    const std::string name = document.scene.bookmarks[index].name;
    applyEdit(document, [&](Document& d) { d.scene.bookmarks.erase(d.scene.bookmarks.begin() + std::ptrdiff_t(index)); });
    prompts.status = "Deleted the bookmark " + name + " (Ctrl+Z brings it back)";
}

}  // namespace patina::editor
