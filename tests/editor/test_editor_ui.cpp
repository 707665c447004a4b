// The editor's UI driven headlessly: Dear ImGui with synthetic mouse and keys, the engine
// renderer on the EGL context, no window.
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <chrono>
#include <thread>

#include <epoxy/gl.h>
#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "picture/compositing.h"
#include "scene/camera_control.h"
#include "scene/camera_placement.h"
#include "state/camera_choice.h"
#include "gltf_builder.h"
#include "image/image.h"
#include "gltf/export.h"
#include "gltf/model_export.h"
#include "window/keys.h"
#include "panels/file_dialog.h"
#include "panels/panels.h"
#include "views/preview_scene.h"
#include "picture/png_text.h"
#include "scratch_test.h"
#include "io/scene_file.h"
#include "test_support.h"
#include "window/ui_scale.h"
#include "window/widgets.h"
#include "files/file_bytes.h"

namespace patina::editor {
namespace {

class EditorUi : public test::ScratchTest {
protected:
    void SetUp() override {
        ScratchTest::SetUp();
        test::glContext();
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(1280, 800);
        // The window's font and style (DejaVu Sans), so the layout is the one users see.
        EXPECT_EQ(applyUiScale(1.0f), "");
        services_ = std::make_unique<EditorServices>(state_.assets);
        state_.screenshotFolder = dir_;
        frames(3);   // lay out every panel
    }

    void TearDown() override {
        services_.reset();
        ImGui::DestroyContext();
        ScratchTest::TearDown();
    }

    void frames(int count) {
        for (int i = 0; i < count; ++i) {
            ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
            ImGui::NewFrame();
            drawEditorFrame(state_, *services_);
            ImGui::Render();
        }
    }

    ImVec2 centreOf(const std::string& item) {
        ImVec2 min, max;
        EXPECT_TRUE(itemRect(item, &min, &max)) << item;
        return ImVec2((min.x + max.x) * 0.5f, (min.y + max.y) * 0.5f);
    }

    void click(ImVec2 at) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = at;
        frames(1);
        io.MouseDown[0] = true;
        frames(1);
        io.MouseDown[0] = false;
        frames(2);
    }

    void drag(ImVec2 from, ImVec2 to, int steps = 8) { drag(from, to, steps, 0); }

    void drag(ImVec2 from, ImVec2 to, int steps, int button) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = from;
        frames(1);
        io.MouseDown[button] = true;
        frames(1);
        for (int i = 1; i <= steps; ++i) {
            io.MousePos = ImVec2(from.x + (to.x - from.x) * float(i) / float(steps),
                                 from.y + (to.y - from.y) * float(i) / float(steps));
            frames(1);
        }
        io.MouseDown[button] = false;
        frames(2);
    }

    void press(int key, bool ctrl = false, bool shift = false) {
        services_->keyPresses = {{key, ctrl, shift}};
        frames(1);
        services_->keyPresses.clear();
        frames(1);
    }

    // The scene's lights replaced by one point light in front of the sphere, in view.
    Light onlyALamp() {
        Light lamp;
        lamp.name = "lamp";
        lamp.position = {0.4f, 0.5f, 1.2f};
        state_.scene.lights = {lamp};
        state_.committed = state_.snapshot();
        return lamp;
    }

    // Where a point of the scene is in the viewport, on screen.
    ImVec2 onScreen(glm::vec3 point) {
        ImVec2 min, max;
        EXPECT_TRUE(itemRect("viewport", &min, &max));
        const auto at = projectToViewport(state_.scene.camera, glm::vec2(max.x - min.x, max.y - min.y), point);
        EXPECT_TRUE(at.has_value());
        return at ? ImVec2(min.x + at->x, min.y + at->y) : min;
    }

    EditorState state_;
    std::unique_ptr<EditorServices> services_;
};

int differingPixels(const LdrImage& a, const LdrImage& b) {
    int count = 0;
    for (size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4) {
        count += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2];
    }
    return count;
}

TEST_F(EditorUi, DraggingTheRoughnessSliderChangesMaterialAndPixels) {
    const float before = state_.scene.material.roughness;
    const LdrImage pixelsBefore = services_->viewportPixels(EditorServices::Shown::Edited);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Roughness", &min, &max));
    drag(ImVec2(min.x + (max.x - min.x) * before, (min.y + max.y) * 0.5f),
         ImVec2(min.x + 4.0f, (min.y + max.y) * 0.5f));
    EXPECT_LT(state_.scene.material.roughness, 0.1f);
    frames(1);   // the full-quality render after release
    const LdrImage pixelsAfter = services_->viewportPixels(EditorServices::Shown::Edited);
    EXPECT_GT(differingPixels(pixelsBefore, pixelsAfter), 100);
    // The whole drag is one undo step.
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.material.roughness, before);
    press(kKeyZ, true, true);   // Ctrl+Shift+Z redoes
    EXPECT_LT(state_.scene.material.roughness, 0.1f);
}

// KHR_materials_clearcoat in the editor: a part's Clearcoat section under its factors, its Coat
// slider dragged puts a coat on the part (the picture changes), one undo step takes it off,
// and the part's coat is what the scene saves.
TEST_F(EditorUi, APartsClearcoatIsDraggedOnUndoneAndSaved) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    frames(2);
    ASSERT_EQ(state_.selectedModelMaterial, 0);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).clearcoat, 0.0f);
    EXPECT_FALSE(itemsOfLastFrame().count("Coat")) << "closed on a part without a coat";
    click(centreOf("Clearcoat"));
    frames(1);
    const LdrImage bare = services_->viewportPixels(EditorServices::Shown::Edited);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Coat", &min, &max));
    drag(ImVec2(min.x + 2.0f, (min.y + max.y) * 0.5f), ImVec2(max.x + 40.0f, (min.y + max.y) * 0.5f));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).clearcoat, 1.0f);
    frames(1);
    EXPECT_GT(differingPixels(bare, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
    const Json saved = sceneToJson(state_.scene);
    ASSERT_TRUE(saved.contains("modelMaterials"));
    EXPECT_EQ(saved["modelMaterials"][0]["material"]["clearcoat"], 1.0);
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).clearcoat, 0.0f);
    // A part with a coat shows its section open when it is first picked, whatever another
    // part's shows.
    click(centreOf("Clearcoat"));
    frames(1);
    EXPECT_FALSE(itemsOfLastFrame().count("Coat")) << "closed again";
    Material coated = modelMaterial(state_, state_.scene, 1);
    coated.clearcoat = 0.5f;
    setModelMaterial(state_, state_.scene, 1, coated);
    state_.selectedModelMaterial = 1;
    frames(2);
    EXPECT_TRUE(itemsOfLastFrame().count("Coat"));
}

// A layer section opens where the part has the layer in every model opened: the open states
// left on one file's part are not another file's part of the same index (a glass opened after
// a model whose part 0 had its Clearcoat opened showed the coat's section open and its own
// Transmission closed).
TEST_F(EditorUi, EachModelsPartsOpenTheirOwnLayerSections) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    frames(2);
    click(centreOf("Clearcoat"));
    frames(1);
    ASSERT_TRUE(itemsOfLastFrame().count("Coat")) << "opened by the click";
    Model glass = test::twoBalls();
    glass.materials[0].factors.transmission = 1.0f;
    exportGltfModel(path("glass.glb"), glass);
    ASSERT_TRUE(openFile(state_, path("glass.glb"))) << state_.error;
    frames(2);
    ASSERT_EQ(state_.selectedModelMaterial, 0);
    EXPECT_FALSE(itemsOfLastFrame().count("Coat")) << "the glass has no coat";
    EXPECT_TRUE(itemsOfLastFrame().count("Transmission factor")) << "the glass's transmission shows";
}

// KHR_materials_sheen in the editor: a part's Sheen section under its Clearcoat, closed on a part
// without one; its colour's red dragged up puts a sheen on the part (the picture changes), the
// drag is one undo step, the roughness another, and the part's sheen is what the scene saves.
TEST_F(EditorUi, APartsSheenIsDraggedOnUndoneAndSaved) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    frames(2);
    ASSERT_EQ(state_.selectedModelMaterial, 0);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).sheenColor, glm::vec3(0.0f));
    EXPECT_FALSE(itemsOfLastFrame().count("Sheen roughness")) << "closed on a part without a sheen";
    click(centreOf("Sheen"));
    frames(1);
    const LdrImage bare = services_->viewportPixels(EditorServices::Shown::Edited);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Sheen colour", &min, &max));
    const float y = (min.y + max.y) * 0.5f;
    drag(ImVec2(min.x + 4.0f, y), ImVec2(min.x + 124.0f, y));   // the red field, 120 pixels right
    const glm::vec3 dragged = modelMaterial(state_, state_.scene, 0).sheenColor;
    EXPECT_GT(dragged.r, 0.0f);
    EXPECT_EQ(dragged.g, 0.0f);
    frames(1);
    EXPECT_GT(differingPixels(bare, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    ASSERT_TRUE(itemRect("Sheen roughness", &min, &max));
    drag(ImVec2(min.x + 2.0f, (min.y + max.y) * 0.5f), ImVec2(max.x + 40.0f, (min.y + max.y) * 0.5f));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).sheenRoughness, 1.0f);
    EXPECT_EQ(state_.history.undoSteps(), 2u);
    const Json saved = sceneToJson(state_.scene);
    ASSERT_TRUE(saved.contains("modelMaterials"));
    EXPECT_EQ(saved["modelMaterials"][0]["material"]["sheenRoughness"], 1.0);
    EXPECT_NEAR(saved["modelMaterials"][0]["material"]["sheenColor"][0].get<double>(), dragged.r, 1e-6);
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).sheenRoughness, 0.0f);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).sheenColor, dragged);
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).sheenColor, glm::vec3(0.0f));
    // A part with a sheen shows its section open when it is first picked.
    Material sheened = modelMaterial(state_, state_.scene, 1);
    sheened.sheenColor = glm::vec3(0.5f);
    setModelMaterial(state_, state_.scene, 1, sheened);
    state_.selectedModelMaterial = 1;
    frames(2);
    EXPECT_TRUE(itemsOfLastFrame().count("Sheen roughness"));
}

// Issue 36: a layer is put on or taken off a part whole, each one step to undo: Add coat gives a
// full, nearly smooth coat; Remove coat takes both factors to 0; the same for the sheen.
TEST_F(EditorUi, ALayerIsAddedAndRemovedWholeInOneStep) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    frames(2);
    click(centreOf("Clearcoat"));
    frames(1);
    const LdrImage bare = services_->viewportPixels(EditorServices::Shown::Edited);
    click(centreOf("Add coat"));
    frames(1);
    Material part = modelMaterial(state_, state_.scene, 0);
    EXPECT_EQ(part.clearcoat, 1.0f);
    EXPECT_EQ(part.clearcoatRoughness, 0.03f);
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    EXPECT_GT(differingPixels(bare, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
    EXPECT_TRUE(itemsOfLastFrame().count("Remove coat"));
    // The status line says what the button did, to which part.
    EXPECT_NE(state_.status.find("Added the clear coat to \"" + part.name + "\""), std::string::npos) << state_.status;
    click(centreOf("Remove coat"));
    EXPECT_NE(state_.status.find("Took the clear coat off \"" + part.name + "\""), std::string::npos) << state_.status;
    part = modelMaterial(state_, state_.scene, 0);
    EXPECT_EQ(part.clearcoat, 0.0f);
    EXPECT_EQ(part.clearcoatRoughness, 0.0f);
    EXPECT_EQ(state_.history.undoSteps(), 2u);
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).clearcoatRoughness, 0.03f) << "the coat back whole";
    click(centreOf("Sheen"));
    frames(1);
    click(centreOf("Add sheen"));
    part = modelMaterial(state_, state_.scene, 0);
    EXPECT_EQ(part.sheenColor, glm::vec3(0.5f));
    EXPECT_EQ(part.sheenRoughness, 0.5f);
    frames(1);
    click(centreOf("Remove sheen"));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).sheenColor, glm::vec3(0.0f));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).sheenRoughness, 0.0f);
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).sheenColor, glm::vec3(0.5f));
    // A transmission too: on whole (a clear glass), off, one step each.
    click(centreOf("Transmission"));
    frames(1);
    const size_t steps = state_.history.undoSteps();
    click(centreOf("Add transmission"));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).transmission, 1.0f);
    EXPECT_NE(state_.status.find("Added the transmission to"), std::string::npos) << state_.status;
    frames(1);
    click(centreOf("Remove transmission"));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).transmission, 0.0f);
    EXPECT_EQ(state_.history.undoSteps(), steps + 2);
}

// KHR_materials_anisotropy in the editor: a part's Anisotropy section, closed on a part without
// one; Add anisotropy stretches the highlight (the picture changes) in one undo step, Remove
// takes it off, Ctrl+Z puts it back, and the scene saves strength and rotation.
TEST_F(EditorUi, APartsAnisotropyIsAddedAndRemovedWholeInOneStep) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    frames(2);
    EXPECT_FALSE(itemsOfLastFrame().count("Anisotropy strength")) << "closed on a part without one";
    click(centreOf("Anisotropy"));
    frames(1);
    const LdrImage round = services_->viewportPixels(EditorServices::Shown::Edited);
    click(centreOf("Add anisotropy"));
    frames(1);
    Material part = modelMaterial(state_, state_.scene, 0);
    EXPECT_EQ(part.anisotropyStrength, 0.5f);
    EXPECT_EQ(part.anisotropyRotation, 0.0f);
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    EXPECT_GT(differingPixels(round, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
    EXPECT_TRUE(itemsOfLastFrame().count("Anisotropy rotation"));
    click(centreOf("Remove anisotropy"));
    part = modelMaterial(state_, state_.scene, 0);
    EXPECT_EQ(part.anisotropyStrength, 0.0f);
    EXPECT_EQ(part.anisotropyRotation, 0.0f);
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).anisotropyStrength, 0.5f) << "back whole";
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    const Json saved = sceneToJson(state_.scene);
    EXPECT_EQ(saved["modelMaterials"][0]["material"]["anisotropyStrength"], 0.5);
    EXPECT_FALSE(saved["modelMaterials"][0]["material"].contains("anisotropyRotation")) << "0, the default: not written";
}

// KHR_materials_transmission and _volume in the editor: a part's Transmission and Volume
// sections under its Sheen, closed on a part without them; the transmission dragged to 1 changes
// the picture, each drag is one undo step, and the part's values are what the scene saves.
TEST_F(EditorUi, APartsTransmissionAndVolumeAreDraggedUndoneAndSaved) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    frames(2);
    ASSERT_EQ(state_.selectedModelMaterial, 0);
    EXPECT_FALSE(itemsOfLastFrame().count("Transmission factor")) << "closed on a part without one";
    EXPECT_FALSE(itemsOfLastFrame().count("Thickness"));
    click(centreOf("Transmission"));
    frames(1);
    const LdrImage opaque = services_->viewportPixels(EditorServices::Shown::Edited);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Transmission factor", &min, &max));
    drag(ImVec2(min.x + 2.0f, (min.y + max.y) * 0.5f), ImVec2(max.x + 40.0f, (min.y + max.y) * 0.5f));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).transmission, 1.0f);
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    frames(1);
    EXPECT_GT(differingPixels(opaque, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
    click(centreOf("Volume"));
    frames(1);
    ASSERT_TRUE(itemRect("Thickness", &min, &max));
    drag(ImVec2(min.x + 2.0f, (min.y + max.y) * 0.5f), ImVec2(max.x + 40.0f, (min.y + max.y) * 0.5f));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).thickness, 10.0f);
    EXPECT_EQ(state_.history.undoSteps(), 2u);
    const Json saved = sceneToJson(state_.scene);
    ASSERT_TRUE(saved.contains("modelMaterials"));
    EXPECT_EQ(saved["modelMaterials"][0]["material"]["transmission"], 1.0);
    EXPECT_EQ(saved["modelMaterials"][0]["material"]["thickness"], 10.0);
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).thickness, 0.0f);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).transmission, 1.0f);
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).transmission, 0.0f);
}

// KHR_materials_specular and _ior in the editor: a part's Specular colour section, closed on a
// part without a tint or weight; the weight dragged to 0 takes the reflection off the part (the
// picture changes) in one undo step, the scene saves it, and Ctrl+Z puts it back.
TEST_F(EditorUi, APartsSpecularWeightIsDraggedUndoneAndSaved) {
    ImGui::GetIO().DisplaySize = ImVec2(1280, 1600);   // the section lies below an 800-pixel panel's end
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    frames(2);
    EXPECT_FALSE(itemsOfLastFrame().count("Specular weight")) << "closed on a part without one";
    click(centreOf("Specular colour"));
    frames(1);
    EXPECT_TRUE(itemsOfLastFrame().count("Specular tint"));
    const LdrImage before = services_->viewportPixels(EditorServices::Shown::Edited);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Specular weight", &min, &max));
    drag(ImVec2(min.x + 2.0f, (min.y + max.y) * 0.5f), ImVec2(min.x - 40.0f, (min.y + max.y) * 0.5f));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).specularWeight, 0.0f);
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    frames(1);
    EXPECT_GT(differingPixels(before, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
    const Json saved = sceneToJson(state_.scene);
    EXPECT_EQ(saved["modelMaterials"][0]["material"]["specularWeight"], 0.0);
    EXPECT_FALSE(saved["modelMaterials"][0]["material"].contains("specularTint")) << "1, the default: not written";
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).specularWeight, 1.0f);
    ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
}

// KHR_materials_iridescence in the editor: a part's Iridescence section, closed on a part
// without a film; Add iridescence colours the picture in one undo step, the scene saves the film,
// Remove takes it off and Ctrl+Z puts it back whole.
TEST_F(EditorUi, APartsFilmIsAddedAndRemovedWholeInOneStep) {
    ImGui::GetIO().DisplaySize = ImVec2(1280, 1600);   // the section lies below an 800-pixel panel's end
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    frames(2);
    EXPECT_FALSE(itemsOfLastFrame().count("Film thickness")) << "closed on a part without one";
    click(centreOf("Iridescence"));
    frames(1);
    const LdrImage before = services_->viewportPixels(EditorServices::Shown::Edited);
    click(centreOf("Add iridescence"));
    frames(1);
    Material part = modelMaterial(state_, state_.scene, 0);
    EXPECT_EQ(part.iridescence, 1.0f);
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    EXPECT_NE(state_.status.find("Added the thin film to"), std::string::npos) << state_.status;
    EXPECT_GT(differingPixels(before, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
    EXPECT_TRUE(itemsOfLastFrame().count("Film thickness"));
    const Json saved = sceneToJson(state_.scene);
    EXPECT_EQ(saved["modelMaterials"][0]["material"]["iridescence"], 1.0);
    EXPECT_EQ(saved["modelMaterials"][0]["material"]["iridescenceThicknessMaximum"], 400.0);
    click(centreOf("Remove iridescence"));
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).iridescence, 0.0f);
    press(kKeyZ, true);
    EXPECT_EQ(modelMaterial(state_, state_.scene, 0).iridescence, 1.0f) << "back whole";
    ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
}

// A slider's step leaves no status of its own: an older "Added the clear coat ... (Ctrl+Z undoes
// it)" then promised what Ctrl+Z no longer undid first (it undid the drag). It goes with the
// step, and Ctrl+Z names what it undid.
TEST_F(EditorUi, ASlidersStepClearsAnOlderUndoPromise) {
    ImGui::GetIO().DisplaySize = ImVec2(1280, 1600);
    click(centreOf("Clearcoat"));
    frames(1);
    click(centreOf("Add coat"));
    frames(1);
    EXPECT_NE(state_.status.find("Added the clear coat to"), std::string::npos) << state_.status;
    EXPECT_NE(state_.status.find("(Ctrl+Z undoes it)"), std::string::npos) << state_.status;
    const ImVec2 from = centreOf("Coat roughness");
    drag(from, ImVec2(from.x + 40.0f, from.y));
    frames(2);
    EXPECT_GT(state_.scene.material.clearcoatRoughness, 0.03f);
    EXPECT_TRUE(state_.status.empty()) << state_.status;
    press(kKeyZ, true);
    EXPECT_EQ(state_.status, "Undid the clear coat's roughness");
    EXPECT_EQ(state_.scene.material.clearcoat, 1.0f) << "the coat stays: the drag was undone";
    ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
}

// Patina's own material (no model) has the layer sections too: the anodised preset's film opens
// its Iridescence section, Remove takes the film off in one step and Ctrl+Z puts it back; the
// specular tint's red is dragged past 1 (a gem's F0), which a colour picker could not reach.
TEST_F(EditorUi, TheOwnMaterialsLayersAreTunedWhereThePresetIsUsed) {
    ImGui::GetIO().DisplaySize = ImVec2(1280, 1600);
    Material anodised;   // as presets/titanium-anodised.json: a metal under a film
    anodised.name = "anodised";
    anodised.model = BrdfModelId::Gltf;
    anodised.metallic = 1.0f;
    anodised.iridescence = 1.0f;
    anodised.iridescenceIor = 2.4f;
    anodised.iridescenceThicknessMaximum = 120.0f;
    std::ofstream(dir_ / "anodised.json") << materialToJson(anodised).dump();
    ASSERT_TRUE(openFile(state_, path("anodised.json"))) << state_.error;
    frames(2);
    ASSERT_EQ(state_.scene.material.iridescence, 1.0f);
    EXPECT_TRUE(itemsOfLastFrame().count("Film thickness")) << "open: the material has a film";
    click(centreOf("Remove iridescence"));
    EXPECT_EQ(state_.scene.material.iridescence, 0.0f);
    EXPECT_NE(state_.status.find("Took the thin film off"), std::string::npos) << state_.status;
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.material.iridescence, 1.0f);
    click(centreOf("Specular colour"));
    frames(1);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Specular tint", &min, &max));
    const float y = (min.y + max.y) * 0.5f;   // red, the first of the three numbers: 0.01 a pixel
    drag(ImVec2(min.x + 6.0f, y), ImVec2(min.x + 206.0f, y), 20);
    EXPECT_GT(state_.scene.material.specularTint.r, 1.5f) << "past 1, not clamped to a colour";
    EXPECT_EQ(state_.scene.material.specularTint.g, 1.0f);
    ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
}

TEST_F(EditorUi, AddPointLightButtonAddsALight) {
    const size_t before = state_.scene.lights.size();
    click(centreOf("Add point"));
    ASSERT_EQ(state_.scene.lights.size(), before + 1);
    EXPECT_EQ(state_.scene.lights.back().type, LightType::Point);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights.size(), before);
}

// A large screenshot keeps the window waiting for seconds (16384 x 16384: about 40 s here):
// the frame F12 is pressed in says so, and the render starts with the next frame.
TEST_F(EditorUi, F12SaysItIsRenderingBeforeTheWindowWaits) {
    state_.screenshotWidth = 96;
    state_.screenshotHeight = 64;
    services_->keyPresses = {{kKeyF12, false, false}};
    frames(1);
    services_->keyPresses.clear();
    EXPECT_EQ(state_.status, "Rendering the 96 x 64 screenshot...");
    EXPECT_TRUE(std::filesystem::is_empty(dir_)) << "nothing is written before the message is shown";
    frames(1);
    EXPECT_FALSE(std::filesystem::is_empty(dir_)) << state_.error;
    EXPECT_EQ(state_.status.rfind("Screenshot saved", 0), 0u) << state_.status;
    EXPECT_FALSE(state_.screenshotRequested.has_value());
}

TEST_F(EditorUi, ScreenshotEmbedsTheSceneAndReopensIt) {
    state_.scene.material.name = "round trip";
    state_.scene.material.roughness = 0.123456f;
    state_.scene.material.baseColor = {0.1f, 0.2f, 0.3f};
    frames(1);
    press(kKeyF12);
    std::vector<std::filesystem::path> shots;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
        shots.push_back(entry.path());
    }
    ASSERT_EQ(shots.size(), 1u) << state_.error;
    const LdrImage image = decodePng(readFileBytes(shots[0]));
    EXPECT_EQ(image.width, services_->viewportWidth);
    EXPECT_EQ(image.height, services_->viewportHeight);

    EditorState reopened;
    ASSERT_TRUE(openFile(reopened, shots[0])) << reopened.error;
    EXPECT_EQ(reopened.scene.material, state_.scene.material);   // exactly, every bit
    EXPECT_EQ(reopened.scene.lights, state_.scene.lights);
}

// A screenshot of a model reopens as the model with its tuning (it used to be refused for
// naming its mesh file).
TEST_F(EditorUi, AScreenshotOfAModelReopensWithTheModel) {
    const std::filesystem::path models = dir_ / "models";
    std::filesystem::create_directories(models);
    exportGltfModel(models / "two.glb", test::twoBalls());
    ASSERT_TRUE(openFile(state_, models / "two.glb")) << state_.error;
    Material gold = modelMaterial(state_, state_.scene, 1);
    gold.baseColor = {1.0f, 0.7f, 0.3f};
    setModelMaterial(state_, state_.scene, 1, gold);
    frames(1);
    press(kKeyF12);
    std::vector<std::filesystem::path> shots;
    for (const auto& entry : std::filesystem::directory_iterator(dir_)) {
        if (entry.path().extension() == ".png") {
            shots.push_back(entry.path());
        }
    }
    ASSERT_EQ(shots.size(), 1u) << state_.error;
    EditorState reopened;
    ASSERT_TRUE(openFile(reopened, shots[0])) << reopened.error;
    EXPECT_EQ(reopened.scene.meshFile, state_.scene.meshFile);
    EXPECT_EQ(reopened.scene.modelMaterials, state_.scene.modelMaterials);
    ASSERT_NE(reopened.model, nullptr);
}

TEST_F(EditorUi, SetAThenSplitShowsBothMaterials) {
    click(centreOf("Set A"));
    ASSERT_TRUE(state_.compareA.has_value());
    EXPECT_EQ(state_.compareView, CompareView::Split);
    state_.scene.material.baseColor = {0.1f, 0.3f, 0.9f};   // B turns blue
    frames(2);
    const LdrImage a = services_->viewportPixels(EditorServices::Shown::A);
    const LdrImage b = services_->viewportPixels(EditorServices::Shown::Edited);
    const int centre = (a.height / 2 * a.width + a.width / 2) * 4;
    EXPECT_GT(int(a.rgba[size_t(centre)]), int(a.rgba[size_t(centre) + 2]));   // A is terracotta
    EXPECT_GT(int(b.rgba[size_t(centre) + 2]), int(b.rgba[size_t(centre)]));   // B is blue
    const std::filesystem::path exported = dir_ / "ab.png";
    ASSERT_TRUE(services_->exportComparison(state_, state_, state_, exported).has_value()) << state_.error;
    EXPECT_EQ(decodePng(readFileBytes(exported)).width % 2, 0);
}

TEST_F(EditorUi, LoadingABadPresetShowsTheErrorAndKeepsTheMaterial) {
    std::ofstream(dir_ / "broken.json") << "{\"format\": \"patina-material\", \"version\": 9}";
    state_.presetFolders = {dir_};
    const Material before = state_.scene.material;
    frames(2);
    click(centreOf("preset:broken"));
    EXPECT_EQ(state_.scene.material, before);
    EXPECT_NE(state_.error.find("newer"), std::string::npos) << state_.error;
}

// Opening a file over unsaved work asks first, and while it asks nothing edits the document
// behind the prompt: Ctrl+Z used to undo, and Ctrl+O to open a dialog, under "Unsaved changes".
TEST_F(EditorUi, UnsavedChangesAreNotDroppedWithoutAskingAndNothingEditsBehindThePrompt) {
    Material other;
    other.name = "other";
    std::ofstream(dir_ / "other.json") << materialToJson(other).dump();
    state_.scene.material.metallic = 0.7f;   // dirty
    frames(2);
    requestOpen(state_, dir_ / "other.json");
    frames(2);
    EXPECT_TRUE(state_.pendingOpen.has_value());
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Discard changes", &min, &max)) << "the prompt is shown";
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.material.metallic, 0.7f) << "Ctrl+Z behind the prompt";
    press(kKeyO, true);
    EXPECT_EQ(state_.pathDialog, EditorState::PathDialog::None) << "Ctrl+O behind the prompt";
    press(kKeyN, true);
    EXPECT_FALSE(state_.pendingNew) << "Ctrl+N behind the prompt";
    click(centreOf("Discard changes"));
    EXPECT_EQ(state_.scene.material.name, "other");
    EXPECT_FALSE(promptOpen(state_, state_));
}

// Discard drops the stage's edits too: a material file opened keeps the stage, and it used to
// keep the display and lights just discarded (a new user's review).
TEST_F(EditorUi, DiscardTakesTheStageBackToItsSavedStateBeforeTheNextFileKeepsIt) {
    Material other;
    other.name = "other";
    std::ofstream(dir_ / "other.json") << materialToJson(other).dump();
    const Scene saved = state_.savedScene;
    state_.scene.material.metallic = 0.7f;
    state_.scene.display.exposure = saved.display.exposure + 2.0f;
    state_.scene.display.ground = Ground::Floor;
    state_.scene.lights[0].intensity *= 3.0f;
    frames(2);
    requestOpen(state_, dir_ / "other.json");
    frames(2);
    click(centreOf("Discard changes"));
    EXPECT_EQ(state_.scene.material.name, "other");
    EXPECT_EQ(state_.scene.display, saved.display);
    EXPECT_EQ(state_.scene.lights, saved.lights);
    EXPECT_FALSE(state_.dirty());
}

TEST_F(EditorUi, ChoosingAModelChangesThePictureAndTheErrorNumbers) {
    const LdrImage epic = services_->viewportPixels(EditorServices::Shown::Edited);
    EXPECT_GT(services_->accuracy(state_.scene.material).physical.relativeRmse, 1e-3);
    state_.scene.material.model = BrdfModelId::Reference;
    frames(2);
    EXPECT_GT(differingPixels(epic, services_->viewportPixels(EditorServices::Shown::Edited)), 100);
    EXPECT_EQ(services_->accuracy(state_.scene.material).physical.relativeRmse, 0.0);
    press(kKeyZ, true);   // the model is part of the material: undoable
    EXPECT_EQ(state_.scene.material.model, BrdfModelId::Epic);
}


TEST_F(EditorUi, OpeningAGltfShowsItsMeshAndABadOneKeepsThePrevious) {
    const LdrImage sphere = services_->viewportPixels(EditorServices::Shown::Edited);
    Mesh torus = makeTorus();
    for (glm::vec3& p : torus.positions) {
        p = p * 3.0f + glm::vec3(10.0f, 0.0f, 0.0f);   // far from the origin: the camera must follow
    }
    exportGltf(path("torus.glb"), torus, Material{});
    ASSERT_TRUE(openFile(state_, path("torus.glb"))) << state_.error;
    frames(2);
    EXPECT_EQ(std::filesystem::path(state_.scene.meshFile).filename(), "torus.glb");
    EXPECT_NEAR(state_.scene.camera.target.x, 10.0f, 0.5f);   // framed on the model
    EXPECT_GT(differingPixels(sphere, services_->viewportPixels(EditorServices::Shown::Edited)), 1000);

    write("broken.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "../../etc/passwd", "byteLength": 4}]})");
    const std::string before = state_.scene.meshFile;
    EXPECT_FALSE(openFile(state_, path("broken.gltf")));
    EXPECT_FALSE(state_.error.empty());
    EXPECT_EQ(state_.scene.meshFile, before);

    // A scene naming a glTF brings its mesh; one naming a missing file fails and changes nothing.
    write("with-mesh.json", R"({"format": "patina-scene", "version": 1, "mesh": "torus.glb"})");
    ASSERT_TRUE(openFile(state_, path("with-mesh.json"))) << state_.error;
    ASSERT_TRUE(state_.mesh() != nullptr);
    EXPECT_EQ(state_.mesh()->positions.size(), makeTorus().positions.size());
    frames(1);
    write("missing-mesh.json", R"({"format": "patina-scene", "version": 1, "mesh": "gone.glb", "lights": []})");
    const EditSnapshot snapshot = state_.snapshot();
    EXPECT_FALSE(openFile(state_, path("missing-mesh.json")));
    EXPECT_NE(state_.error.find("gone.glb"), std::string::npos) << state_.error;
    EXPECT_EQ(state_.snapshot(), snapshot);
    EXPECT_EQ(std::filesystem::path(state_.scene.meshFile).filename(), "torus.glb");
}


// A click on a part of a model selects its material for the Material panel, a drag does not;
// a map's checkbox leaves the map out of the picture, undoably.
TEST_F(EditorUi, AClickOnAPartSelectsItAndAMapsCheckboxLeavesTheMapOut) {
    const glm::vec3 left(-1.2f, 0.0f, 0.0f), right(1.2f, 0.0f, 0.0f);   // test::twoBalls's
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    frames(2);
    ASSERT_EQ(state_.selectedModelMaterial, 0);
    click(onScreen(right));
    EXPECT_EQ(state_.selectedModelMaterial, 1);
    EXPECT_NE(state_.status.find("\"right\""), std::string::npos) << state_.status;
    const ImVec2 from = onScreen(left);
    drag(from, ImVec2(from.x + 60.0f, from.y));   // an orbit, not a pick
    EXPECT_EQ(state_.selectedModelMaterial, 1);

    const std::filesystem::path box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!std::filesystem::exists(box)) {
        GTEST_SKIP() << "needs Debian's assimp-testmodels";
    }
    ASSERT_TRUE(openFile(state_, box)) << state_.error;
    frames(2);
    const LdrImage logo = services_->viewportPixels(EditorServices::Shown::Edited);
    click(centreOf("map: base colour"));
    EXPECT_FALSE(mapShown(state_.scene, 0, "baseColorTexture"));
    EXPECT_GT(differingPixels(logo, services_->viewportPixels(EditorServices::Shown::Edited)), 1000);
    press(kKeyZ, true);
    EXPECT_TRUE(mapShown(state_.scene, 0, "baseColorTexture"));
    frames(2);   // the undo draws the logo again, no widget held to force a render
    EXPECT_LT(differingPixels(logo, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
}

// Issue 34: 2CylinderEngine's Parts list showed "Material_17" nine times in a box of 6 rows
// out of 34. Each row names the nodes drawn with its part, a search box keeps the parts whose
// material or node has what is typed, and the list grows with the panel.
TEST_F(EditorUi, ThePartsListTellsPartsApartSearchesAndGrows) {
    Model model = test::twoBalls();
    model.materials.clear();
    model.draws.clear();
    for (int i = 0; i < 34; ++i) {
        ModelMaterial material;
        material.name = "Material_17";
        model.materials.push_back(material);
        glm::mat4 transform(1.0f);
        transform[3] = glm::vec4(2.5f * float(i), 0.0f, 0.0f, 1.0f);
        model.draws.push_back({0, i, transform, "body_" + std::to_string(i)});
    }
    exportGltfModel(path("parts.glb"), model);
    ASSERT_TRUE(openFile(state_, path("parts.glb"))) << state_.error;
    frames(3);
    std::map<std::string, RecordedItem> items = itemsOfLastFrame();
    ASSERT_TRUE(items.count("part:3"));
    EXPECT_NE(items.at("part:3").tooltip.find("Drawn on: body_3"), std::string::npos) << items.at("part:3").tooltip;
    const float line = ImGui::GetTextLineHeightWithSpacing();
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Model material", &min, &max));
    EXPECT_GT(max.y - min.y, 10.0f * line) << "more than six rows where the panel has room";

    click(centreOf("part search"));
    for (char c : std::string("BODY_33")) {
        ImGui::GetIO().AddInputCharacter(static_cast<unsigned>(c));
    }
    frames(2);
    items = itemsOfLastFrame();
    EXPECT_TRUE(items.count("part:33"));
    EXPECT_FALSE(items.count("part:3")) << "filtered out";
    click(centreOf("part:33"));
    EXPECT_EQ(state_.selectedModelMaterial, 33);
}

// Every file told (issue 36): a model whose file has an extension Patina does not draw says so
// in amber beside the status line, and the File extensions section lists it.
TEST_F(EditorUi, AnExtensionNotDrawnIsCountedInTheStatusAndListed) {
    test::GltfBuilder coated = test::cubeModel();
    coated.json["extensionsUsed"] = {"KHR_materials_diffuse_transmission", "KHR_texture_transform"};
    coated.json["materials"][0]["extensions"]["KHR_materials_diffuse_transmission"] = {{"diffuseTransmissionFactor", 1.0}};
    coated.writeGlb(path("coated.glb"));
    ASSERT_TRUE(openFile(state_, path("coated.glb"))) << state_.error;
    frames(3);
    std::map<std::string, RecordedItem> items = itemsOfLastFrame();
    ASSERT_TRUE(items.count("status notes")) << state_.status;
    EXPECT_NE(items.at("status notes").tooltip.find("uses KHR_materials_diffuse_transmission (not drawn)"), std::string::npos);
    ASSERT_TRUE(items.count("File extensions"));
    ASSERT_EQ(state_.model->extensions.size(), 2u);
    click(centreOf("File extensions"));
    frames(2);
    EXPECT_TRUE(ImGui::FindWindowByName("Material")) << "the panel draws the open section without failing";

    // A file with nothing left out has no count.
    coated.json.erase("extensionsUsed");
    coated.writeGlb(path("plain.glb"));
    ASSERT_TRUE(openFile(state_, path("plain.glb"))) << state_.error;
    frames(3);
    EXPECT_FALSE(itemsOfLastFrame().count("status notes")) << state_.status;
}

// Issue 34: a preset put on a model's part kept the part's name, and the comparison's halves
// both read "A: left" / "B: left". They say which preset, while the part holds it unchanged.
TEST_F(EditorUi, APresetOnAPartIsNamedInTheComparisonsLabels) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    std::filesystem::create_directories(path("presets"));
    for (const char* name : {"gold", "silver"}) {
        std::filesystem::copy_file(std::filesystem::path(PATINA_PRESETS_DIR) / (std::string(name) + ".json"),
                                   path("presets") / (std::string(name) + ".json"));
    }
    state_.presetFolders = {path("presets")};
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    ASSERT_TRUE(openFile(state_, path("presets") / "gold.json")) << state_.error;
    frames(2);
    click(centreOf("Set A"));
    ASSERT_TRUE(openFile(state_, path("presets") / "silver.json")) << state_.error;
    frames(2);
    auto label = [](const char* name) {
        const std::string tooltip = itemsOfLastFrame().at(name).tooltip;
        return tooltip.substr(0, tooltip.find(" ("));   // the label, before what it is
    };
    std::map<std::string, RecordedItem> items = itemsOfLastFrame();
    ASSERT_TRUE(items.count("label A") && items.count("label B"));
    EXPECT_EQ(items.at("label A").tooltip.rfind("A: left (gold)", 0), 0u) << items.at("label A").tooltip;
    EXPECT_EQ(items.at("label B").tooltip.rfind("B: left (silver)", 0), 0u) << items.at("label B").tooltip;
    // Tuned by hand, it is no longer the preset: the part's name alone.
    Material tuned = editedMaterial(state_, state_);
    tuned.roughness = 0.61f;
    setEditedMaterial(state_, state_, state_.scene, tuned);
    frames(2);
    EXPECT_EQ(label("label B"), "B: left");
}

// Replace... puts an image file in place of a map: drawn at once, one undoable step, saved in
// the scene and back when it is opened again; Restore draws the file's own map; an image that
// cannot be read changes nothing and says why.
TEST_F(EditorUi, AMapIsReplacedByAnImageFileAndRestored) {
    const std::filesystem::path box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!std::filesystem::exists(box)) {
        GTEST_SKIP() << "needs Debian's assimp-testmodels";
    }
    ASSERT_TRUE(openFile(state_, box)) << state_.error;
    frames(2);
    const std::shared_ptr<const Model> file = state_.model;
    const LdrImage logo = services_->viewportPixels(EditorServices::Shown::Edited);
    ImVec2 min, max;
    EXPECT_FALSE(itemRect("map restore: base colour", &min, &max)) << "nothing to restore yet";
    const LdrImage red{2, 2, std::vector<uint8_t>{200, 20, 10, 255, 200, 20, 10, 255, 200, 20, 10, 255, 200, 20, 10, 255}};
    writeFileAtomic(path("red.png"), encodePng(red));

    click(centreOf("map replace: base colour"));
    frames(1);
    ASSERT_EQ(state_.pathDialog, EditorState::PathDialog::ReplaceMap);
    EXPECT_EQ(state_.pathDialogText, box.parent_path().string() + "/") << "the model's folder";
    ImGuiIO& io = ImGui::GetIO();   // typed over, as a user does: Ctrl+A, then the path
    io.KeyMap[ImGuiKey_A] = 'A';
    io.KeyCtrl = io.KeysDown[int('A')] = true;
    frames(1);
    io.KeyCtrl = io.KeysDown[int('A')] = false;
    for (char c : path("red.png").string()) {
        io.AddInputCharacter(static_cast<unsigned>(c));
    }
    frames(2);
    click(centreOf("path:confirm"));
    frames(2);
    EXPECT_TRUE(state_.error.empty()) << state_.error;
    EXPECT_EQ(mapReplacement(state_.scene, 0, "baseColorTexture"), path("red.png").string());
    ASSERT_NE(state_.model, file);
    const int image = state_.model->materials.at(0).baseColor.image;
    EXPECT_EQ(state_.model->images.at(size_t(image)).rgba, red.rgba);
    EXPECT_NE(state_.status.find("Replaced the base colour map of \"Texture\" with red.png"), std::string::npos)
        << state_.status;
    const LdrImage replaced = services_->viewportPixels(EditorServices::Shown::Edited);
    EXPECT_GT(differingPixels(logo, replaced), 1000);
    EXPECT_TRUE(itemRect("map restore: base colour", &min, &max));

    press(kKeyZ, true);
    frames(2);
    EXPECT_EQ(state_.model, file);
    EXPECT_EQ(mapReplacement(state_.scene, 0, "baseColorTexture"), "");
    EXPECT_LT(differingPixels(logo, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
    press(kKeyY, true);
    frames(2);
    EXPECT_NE(state_.model, file);
    EXPECT_LT(differingPixels(replaced, services_->viewportPixels(EditorServices::Shown::Edited)), 50);

    // Saved with the scene, and drawn again when it is opened.
    ASSERT_TRUE(saveScene(state_, state_, state_, path("replaced.json"))) << state_.error;
    newDocument(state_, state_, state_, state_);
    ASSERT_TRUE(openFile(state_, path("replaced.json"))) << state_.error;
    frames(2);
    EXPECT_EQ(mapReplacement(state_.scene, 0, "baseColorTexture"), path("red.png").string());
    EXPECT_LT(differingPixels(replaced, services_->viewportPixels(EditorServices::Shown::Edited)), 50);

    click(centreOf("map restore: base colour"));
    frames(2);
    EXPECT_EQ(mapReplacement(state_.scene, 0, "baseColorTexture"), "");
    EXPECT_LT(differingPixels(logo, services_->viewportPixels(EditorServices::Shown::Edited)), 50);
    EXPECT_TRUE(state_.dirty());

    // Not an image: nothing changes, and the error says which file and why.
    write("notes.png", "not a picture");
    const EditSnapshot before = state_.snapshot();
    EXPECT_FALSE(replaceMap(state_, *state_.assets, state_, 0, "baseColorTexture", path("notes.png")));
    EXPECT_NE(state_.error.find("notes.png: the image is neither PNG, JPEG nor WebP"), std::string::npos) << state_.error;
    EXPECT_EQ(state_.snapshot(), before);
    frames(1);
}

// Each opening of a path dialog selects its whole path, so that what is typed replaces it: the
// field used to keep the last opening's cursor, and typing went into the middle of the path.
TEST_F(EditorUi, APathDialogOpenedAgainTakesTheTypedPathWhole) {
    ImGuiIO& io = ImGui::GetIO();
    for (const std::string& typed : {path("first.png").string(), path("second.png").string()}) {
        startPathDialog(state_, EditorState::PathDialog::ReplaceMap, "/usr/share/assimp/models/glTF2/");
        frames(2);
        for (char c : typed) {
            io.AddInputCharacter(static_cast<unsigned>(c));
        }
        frames(2);
        EXPECT_EQ(state_.pathDialogText, typed);
        click(centreOf("path:cancel"));
        EXPECT_EQ(state_.pathDialog, EditorState::PathDialog::None);
    }
}

// Issue 34: on File > Open's first opening, what was typed at once was lost: the dialog sizes
// itself in a hidden first frame, and its field took the keys only a frame later. What is typed
// from the frame it opens on is the path.
TEST_F(EditorUi, ThePathFieldTakesWhatIsTypedAtOnceOnItsFirstOpening) {
    ImGuiIO& io = ImGui::GetIO();
    for (const std::string& typed : {path("first.json").string(), path("second.json").string()}) {
        startPathDialog(state_, EditorState::PathDialog::Open, dir_ / "");
        for (char c : typed.substr(0, 5)) {   // with the key that opened it
            io.AddInputCharacter(static_cast<unsigned>(c));
        }
        frames(1);
        for (char c : typed.substr(5)) {
            io.AddInputCharacter(static_cast<unsigned>(c));
            frames(1);
        }
        EXPECT_EQ(state_.pathDialogText, typed);
        click(centreOf("path:cancel"));
    }
    // Enter at once takes the path offered (Ctrl+Alt+S, Enter).
    startPathDialog(state_, EditorState::PathDialog::SaveSceneAs, path("at-once.json"));
    io.KeyMap[ImGuiKey_Enter] = 257;   // GLFW's, as the window maps it
    io.KeysDown[257] = true;
    frames(1);
    io.KeysDown[257] = false;
    frames(2);
    EXPECT_EQ(state_.pathDialog, EditorState::PathDialog::None);
    EXPECT_TRUE(std::filesystem::exists(path("at-once.json"))) << state_.error;
}

// A model read on a worker is shown once read, but not behind a prompt: it waits for the
// answer, as every edit does.
TEST_F(EditorUi, AModelReadOnAWorkerWaitsForAnOpenPrompt) {
    exportGltf(path("torus.glb"), makeTorus(), Material{});
    requestOpen(state_, path("torus.glb"));
    state_.scene.material.roughness = 0.9f;   // unsaved, so that File > New asks
    state_.pendingNew = true;
    while (!state_.modelLoad->ready()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    frames(2);
    EXPECT_TRUE(state_.scene.meshFile.empty());
    state_.pendingNew = false;
    frames(2);
    // The roughness was edited after the model was asked for: it asks before replacing it.
    EXPECT_TRUE(state_.scene.meshFile.empty());
    ASSERT_EQ(state_.pendingOpen, path("torus.glb"));
    click(centreOf("Discard changes"));
    frames(2);
    EXPECT_EQ(std::filesystem::path(state_.scene.meshFile).filename(), "torus.glb");
    EXPECT_EQ(state_.modelLoad, nullptr);
}

// The model being read shows its name, seconds and Cancel last on the toolbar: no control moves
// under the pointer when it appears or while its seconds count.
TEST_F(EditorUi, AModelBeingReadMovesNoToolbarControl) {
    exportGltf(path("torus.glb"), makeTorus(), Material{});
    frames(2);
    ImVec2 exposureMin, exposureMax, clearMin, clearMax;
    ASSERT_TRUE(itemRect("Exposure", &exposureMin, &exposureMax));
    ASSERT_TRUE(itemRect("Clear A", &clearMin, &clearMax));
    requestOpen(state_, path("torus.glb"));
    state_.scene.material.roughness = 0.9f;   // unsaved, so that File > New asks and the load waits
    state_.pendingNew = true;
    frames(2);
    ASSERT_NE(state_.modelLoad, nullptr);
    ImVec2 min, max, cancelMin, cancelMax;
    ASSERT_TRUE(itemRect("Exposure", &min, &max));
    EXPECT_EQ(min.x, exposureMin.x);
    EXPECT_EQ(min.y, exposureMin.y);
    ASSERT_TRUE(itemRect("Clear A", &min, &max));
    EXPECT_EQ(min.x, clearMin.x);
    ASSERT_TRUE(itemRect("Model cancel", &cancelMin, &cancelMax));
    EXPECT_TRUE(cancelMin.y > clearMin.y || cancelMin.x > clearMax.x) << "after every other control";
    state_.pendingNew = false;
}

// An error floats over the picture, below every row of the toolbar, so Set A and the views
// stay clickable while it is shown.
TEST_F(EditorUi, AnErrorCoversNoToolbarControl) {
    state_.error = "Could not save x.gltf: the folder /nowhere does not exist";
    frames(2);
    ImVec2 dismissMin, dismissMax, clearMin, clearMax, pictureMin, pictureMax;
    ASSERT_TRUE(itemRect("error:dismiss", &dismissMin, &dismissMax));
    ASSERT_TRUE(itemRect("Clear A", &clearMin, &clearMax));
    ASSERT_TRUE(itemRect("viewport", &pictureMin, &pictureMax));
    EXPECT_GT(dismissMin.y, clearMax.y);
    EXPECT_GE(dismissMin.y, pictureMin.y);
    click(centreOf("Set A"));
    EXPECT_TRUE(state_.compareA.has_value()) << "Set A takes the click";
}

// The outer ring's value stays whole inside the plot, however long (a mirror's peak reads
// "1.55e+03 /sr"; it used to run off the plot's right edge).
TEST_F(EditorUi, TheLobesOuterValueIsNeverCut) {
    state_.scene.material.roughness = 0.0f;
    state_.scene.material.metallic = 1.0f;
    frames(2);
    ImVec2 valueMin, valueMax, plotMin, plotMax;
    ASSERT_TRUE(itemRect("lobe:outer value", &valueMin, &valueMax));
    ASSERT_TRUE(itemRect("lobe", &plotMin, &plotMax));
    EXPECT_GT(valueMax.x - valueMin.x, 0.0f);
    EXPECT_LE(valueMax.x, plotMax.x);
    EXPECT_GE(valueMin.x, plotMin.x);
}

// File > New by its shortcut replaces the document before the viewport draws in that frame:
// the new scene's environment is looked up first, never reported as not prepared.
TEST_F(EditorUi, NewByItsShortcutDrawsTheNewScenesEnvironmentAtOnce) {
    ASSERT_GE(state_.environmentIndex(), 0);
    frames(2);
    press(kKeyN, true);
    EXPECT_EQ(state_.status, "New scene");
    EXPECT_EQ(state_.error, "");
    ASSERT_NE(state_.environment, nullptr);
}

// Every texture the last rendered UI frame draws (the font atlas has none headlessly), with
// its size as the GL has it now; -1 x -1 for a name that is no longer a texture.
std::map<unsigned, std::pair<int, int>> drawnTextures() {
    std::map<unsigned, std::pair<int, int>> textures;
    const ImDrawData* data = ImGui::GetDrawData();
    for (int list = 0; data && list < data->CmdListsCount; ++list) {
        for (const ImDrawCmd& command : data->CmdLists[list]->CmdBuffer) {
            const auto name = unsigned(reinterpret_cast<intptr_t>(command.TextureId));
            if (name == 0) {
                continue;
            }
            GLint width = -1, height = -1;
            if (glIsTexture(name)) {
                glBindTexture(GL_TEXTURE_2D, name);
                glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
                glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &height);
                glBindTexture(GL_TEXTURE_2D, 0);
            }
            textures[name] = {width, height};
        }
    }
    return textures;
}

// Each map of the selected part is shown as a thumbnail of its image beside its checkbox.
TEST_F(EditorUi, EachMapIsShownAsAThumbnailOfItsImage) {
    const std::filesystem::path box = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!std::filesystem::exists(box)) {
        GTEST_SKIP() << "needs Debian's assimp-testmodels";
    }
    frames(2);
    const auto before = drawnTextures();
    ASSERT_TRUE(openFile(state_, box)) << state_.error;
    frames(2);
    ImVec2 min, max, boxMin, boxMax;
    ASSERT_TRUE(itemRect("map image: base colour", &min, &max));
    ASSERT_TRUE(itemRect("map: base colour", &boxMin, &boxMax));
    EXPECT_LT(max.x, boxMin.x + 1.0f) << "left of its checkbox";
    EXPECT_NEAR(max.x - min.x, max.y - min.y, 1.0f) << "the logo is square";
    // The thumbnail is a texture of its own: the 211 x 211 logo shrunk to 160 x 160.
    int thumbnails = 0;
    for (const auto& [name, size] : drawnTextures()) {
        thumbnails += !before.count(name) && size == std::make_pair(160, 160);
    }
    EXPECT_EQ(thumbnails, 1);
}

// The PNGs in `folder`, oldest first.
std::vector<std::filesystem::path> pngsIn(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() == ".png") {
            files.push_back(entry.path());
        }
    }
    std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
        return std::filesystem::last_write_time(a) < std::filesystem::last_write_time(b);
    });
    return files;
}

class EditorScreenshots : public EditorUi {
protected:
    // F12 taken in the frame after the key (which says "Rendering..."): the textures that frame
    // draws must be those of the frame before, alive and of the same size (the window's GL
    // backend draws them after the frame's code ran).
    void expectF12KeepsTheFramesTextures(const std::string& what) {
        frames(2);
        const auto before = drawnTextures();
        ASSERT_FALSE(before.empty());
        const size_t shots = pngsIn(dir_).size();
        services_->keyPresses = {{kKeyF12, false, false}};
        frames(1);
        services_->keyPresses.clear();
        frames(1);
        EXPECT_EQ(drawnTextures(), before) << what;
        ASSERT_EQ(pngsIn(dir_).size(), shots + 1) << what << ": " << state_.error;
        EXPECT_TRUE(state_.error.empty()) << what << ": " << state_.error;
        frames(2);
        EXPECT_EQ(drawnTextures(), before) << what << ", the frames after";
    }
};

// The two crash routes of the editor issue: F12 in Side by side, and F12 at a fixed
// screenshot size. Each rendered the screenshot into the viewport's own target, replacing a
// texture the frame had already queued for drawing.
TEST_F(EditorScreenshots, F12InSideBySideLeavesTheViewportsTexturesAlone) {
    click(centreOf("Set A"));
    click(centreOf("Side by side"));
    ASSERT_EQ(state_.compareView, CompareView::SideBySide);
    expectF12KeepsTheFramesTextures("side by side");
}

TEST_F(EditorScreenshots, F12AtAFixedSizeLeavesTheViewportsTextureAlone) {
    state_.screenshotWidth = 800;
    state_.screenshotHeight = 600;
    expectF12KeepsTheFramesTextures("800 x 600");
    const LdrImage shot = decodePng(readFileBytes(pngsIn(dir_).back()));
    EXPECT_EQ(shot.width, 800);
    EXPECT_EQ(shot.height, 600);
}

// A screenshot shows what the viewport shows: in Side by side both halves, captioned; in
// Split A's side left of the divider and B's right of it.
TEST_F(EditorScreenshots, ComparisonsAreScreenshotAsShown) {
    click(centreOf("Set A"));
    state_.scene.material.baseColor = {0.1f, 0.3f, 0.9f};   // B turns blue; A stays terracotta
    click(centreOf("Side by side"));
    state_.screenshotWidth = 600;
    state_.screenshotHeight = 400;
    press(kKeyF12);
    const LdrImage both = decodePng(readFileBytes(pngsIn(dir_).back()));
    const int half = 300, middle = 200;
    EXPECT_EQ(both.width, 2 * half + kCellGap);
    EXPECT_GT(both.height, 400) << "captions under the halves";
    auto pixel = [](const LdrImage& image, int x, int y) {
        const size_t at = (size_t(y) * size_t(image.width) + size_t(x)) * 4;
        return glm::ivec3(image.rgba[at], image.rgba[at + 1], image.rgba[at + 2]);
    };
    EXPECT_GT(pixel(both, half / 2, middle).r, pixel(both, half / 2, middle).b) << "A on the left";
    EXPECT_GT(pixel(both, half + kCellGap + half / 2, middle).b, pixel(both, half + kCellGap + half / 2, middle).r)
        << "B on the right";

    click(centreOf("Split"));
    state_.splitPosition = 0.5f;
    press(kKeyF12);
    const LdrImage split = decodePng(readFileBytes(pngsIn(dir_).back()));
    ASSERT_EQ(split.width, 600);
    // The sphere's left and right of the centre: A's colour, then B's.
    const int quarter = split.width / 2 - split.width / 10;
    EXPECT_GT(pixel(split, quarter, middle).r, pixel(split, quarter, middle).b);
    EXPECT_GT(pixel(split, split.width - quarter, middle).b, pixel(split, split.width - quarter, middle).r);
    EXPECT_EQ(pixel(split, split.width / 2, middle), glm::ivec3(255)) << "the divider";
}

// A screenshot of a comparison reopens as that comparison: A, B, the view and the split (it
// used to reopen as B alone).
TEST_F(EditorScreenshots, AComparisonsScreenshotReopensAsTheComparison) {
    click(centreOf("Set A"));
    const Material a = state_.scene.material;
    state_.scene.material.baseColor = {0.1f, 0.3f, 0.9f};
    state_.scene.material.name = "blue";
    state_.screenshotWidth = 200;
    state_.screenshotHeight = 150;
    for (const CompareView view : {CompareView::Split, CompareView::SideBySide}) {
        state_.compareView = view;
        state_.splitPosition = 0.25f;
        press(kKeyF12);
        ASSERT_TRUE(state_.error.empty()) << state_.error;
        EditorState reopened;
        ASSERT_TRUE(openFile(reopened, pngsIn(dir_).back())) << reopened.error;
        ASSERT_TRUE(reopened.compareA.has_value());
        EXPECT_EQ(*reopened.compareA, a);
        EXPECT_EQ(reopened.scene.material, state_.scene.material);
        EXPECT_EQ(reopened.compareView, view);
        EXPECT_EQ(reopened.splitPosition, 0.25f);
    }
    // A single view's screenshot reopens as a single view, whatever was compared before.
    state_.compareView = CompareView::Single;
    press(kKeyF12);
    EditorState reopened;
    reopened.compareA = a;
    reopened.compareView = CompareView::Split;
    ASSERT_TRUE(openFile(reopened, pngsIn(dir_).back())) << reopened.error;
    EXPECT_EQ(reopened.compareView, CompareView::Single);
}

// On a model both sides are drawn on the part A was taken from: its screenshot reopens on that
// part (it reopened on part 0: A's material over another part, B labelled as that one).
TEST_F(EditorScreenshots, AComparisonOfAModelsPartReopensOnThatPart) {
    exportGltfModel(path("two.glb"), test::twoBalls());
    ASSERT_TRUE(openFile(state_, path("two.glb"))) << state_.error;
    state_.selectedModelMaterial = 1;
    frames(2);
    click(centreOf("Set A"));
    ASSERT_TRUE(state_.compareA.has_value());
    const Material a = *state_.compareA;
    Material changed = modelMaterial(state_, state_.scene, 1);
    changed.baseColor = {0.1f, 0.3f, 0.9f};
    setModelMaterial(state_, state_.scene, 1, changed);
    state_.screenshotWidth = 200;
    state_.screenshotHeight = 150;
    for (const CompareView view : {CompareView::Split, CompareView::SideBySide}) {
        state_.compareView = view;
        press(kKeyF12);
        ASSERT_TRUE(state_.error.empty()) << state_.error;
        EditorState reopened;
        ASSERT_TRUE(openFile(reopened, pngsIn(dir_).back())) << reopened.error;
        EXPECT_EQ(reopened.selectedModelMaterial, 1);
        ASSERT_TRUE(reopened.compareA.has_value());
        EXPECT_EQ(*reopened.compareA, a);
        EXPECT_EQ(labelledMaterial(reopened, reopened).baseColor, changed.baseColor) << "B is the part A was on";
    }
}

// An error thrown while a panel draws (here a viewport wider than the GL can render) is shown
// and the editor goes on: ImGui's window stack is closed, and the next frames draw normally.
TEST_F(EditorUi, AnErrorInsideAPanelIsShownAndTheEditorGoesOn) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    ImGui::GetIO().DisplaySize = ImVec2(float(maxSize) + 2000.0f, 800.0f);
    frames(3);
    EXPECT_NE(state_.error.find("The viewport failed"), std::string::npos) << state_.error;
    EXPECT_NE(state_.error.find("outside"), std::string::npos) << state_.error;
    // What comes after the viewport in a frame still runs: the undo commit and the shortcuts.
    const size_t lights = state_.scene.lights.size();
    click(centreOf("Add point"));
    EXPECT_EQ(state_.scene.lights.size(), lights + 1);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights.size(), lights);

    ImGui::GetIO().DisplaySize = ImVec2(1280, 800);
    state_.error.clear();
    frames(3);
    EXPECT_TRUE(state_.error.empty()) << state_.error;
    EXPECT_EQ(services_->viewportPixels(EditorServices::Shown::Edited).width, services_->viewportWidth);
}


// Quitting after light edits asks, and Save on a scene without a file goes on to Save as
// (it used to stop behind the prompt with "Use Save as first"); once saved, the quit goes on.
TEST_F(EditorUi, QuittingAfterLightEditsAsksAndSaveGoesOnToSaveAs) {
    click(centreOf("Add point"));
    ASSERT_TRUE(state_.dirty());
    state_.pendingQuit = true;
    frames(2);
    click(centreOf("Save changes"));
    EXPECT_FALSE(state_.quitConfirmed);
    EXPECT_EQ(state_.pathDialog, EditorState::PathDialog::SaveSceneAs) << state_.error;
    state_.pathDialogText = path("quit-scene.json").string();
    frames(2);
    click(centreOf("path:confirm"));
    frames(2);
    EXPECT_TRUE(std::filesystem::exists(path("quit-scene.json"))) << state_.error;
    EXPECT_TRUE(state_.quitConfirmed);
    std::vector<std::string> warnings;
    EXPECT_EQ(loadSceneFile(path("quit-scene.json"), warnings).lights, state_.scene.lights);
}

// A light's new name is kept when the field loses focus, not only on Enter, as one undo step.
TEST_F(EditorUi, ARenamedLightKeepsItsNameWhenTheFieldLosesFocus) {
    state_.selectedLight = 0;
    frames(2);
    const std::string before = state_.scene.lights[0].name;
    click(centreOf("Light name"));
    ImGuiIO& io = ImGui::GetIO();
    for (char c : std::string(" two")) {
        io.AddInputCharacter(static_cast<unsigned>(c));
    }
    frames(2);
    click(centreOf("viewport"));   // focus elsewhere, no Enter
    EXPECT_EQ(state_.scene.lights[0].name, before + " two");
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights[0].name, before);
}

// Intensity drags in proportion to itself: 8 to past 100 in 300 pixels (at the old fixed step
// of 0.05 a pixel it took 1800).
TEST_F(EditorUi, IntensityDragsInProportionToItself) {
    state_.selectedLight = 0;
    state_.scene.lights[0].intensity = 8.0f;
    frames(2);
    const ImVec2 at = centreOf("Intensity");
    drag(at, ImVec2(at.x + 300.0f, at.y), 60);
    EXPECT_GT(state_.scene.lights[0].intensity, 100.0f);
    EXPECT_LT(state_.scene.lights[0].intensity, 1000.0f);
}

// Issue 34: after opening 2CylinderEngine the key light read 784563.938, the rig's intensity
// times the model's radius squared, and the field's limit of 10^6 clamped it at the first touch.
// At a model's scale the field reads as it did on the unit sphere; the scene keeps the intensity.
TEST_F(EditorUi, ALightsIntensityReadsAtTheModelsScale) {
    Mesh big = makeTorus();
    for (glm::vec3& p : big.positions) {
        p *= 500.0f;
    }
    exportGltf(path("big.glb"), big, Material{});
    size_t point = 0;
    while (state_.scene.lights[point].type != LightType::Point) {
        ++point;
    }
    state_.scene.lights[point].intensity = 8.0f;
    ASSERT_TRUE(openFile(state_, path("big.glb"))) << state_.error;
    const float scale = intensityScale(state_, state_.scene.lights[point]);
    EXPECT_NEAR(scale, meshBounds(state_).radius * meshBounds(state_).radius, 1.0f);
    EXPECT_NEAR(state_.scene.lights[point].intensity / scale, 8.0f, 1e-3f) << "the rig followed the model";
    state_.selectedLight = int(point);
    frames(2);
    EXPECT_NE(itemsOfLastFrame().at("Intensity").tooltip.find("at the model's scale"), std::string::npos);
    const ImVec2 at = centreOf("Intensity");
    drag(at, ImVec2(at.x + 300.0f, at.y), 60);
    EXPECT_GT(state_.scene.lights[point].intensity / scale, 100.0f) << "not clamped at 10^6";
    EXPECT_LT(state_.scene.lights[point].intensity / scale, 1000.0f);
    EXPECT_EQ(intensityScale(state_, state_.scene.lights[point]), scale);
    chooseBuiltinMesh(state_, MeshKind::Sphere);
    EXPECT_EQ(intensityScale(state_, state_.scene.lights[point]), 1.0f);
}

// The Delete key deletes the selected light, undoably; not while a text field has the keys.
TEST_F(EditorUi, TheDeleteKeyDeletesTheSelectedLight) {
    const std::vector<Light> lights = state_.scene.lights;
    state_.selectedLight = 1;
    press(kKeyDelete);
    ASSERT_EQ(state_.scene.lights.size(), lights.size() - 1);
    EXPECT_EQ(state_.scene.lights[1].name, lights[2].name);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights, lights);
}

// A screenshot folder that does not exist yet is made, and the message gives the whole path.
TEST_F(EditorUi, AScreenshotMakesItsFolderAndSaysWhereItWent) {
    state_.screenshotFolder = dir_ / "not" / "yet";
    press(kKeyF12);
    const std::vector<std::filesystem::path> shots = pngsIn(dir_ / "not" / "yet");
    ASSERT_EQ(shots.size(), 1u) << state_.error;
    EXPECT_NE(state_.status.find(std::filesystem::absolute(shots[0]).string()), std::string::npos) << state_.status;
}

// A texture's pixels (RGBA8, GL's rows).
std::vector<uint8_t> texturePixels(const Texture& texture) {
    std::vector<uint8_t> pixels(size_t(texture.width()) * size_t(texture.height()) * 4);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    glBindTexture(GL_TEXTURE_2D, 0);
    return pixels;
}

glm::dvec3 meanColour(const std::vector<uint8_t>& rgba) {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i + 3 < rgba.size(); i += 4) {
        sum += glm::dvec3(rgba[i], rgba[i + 1], rgba[i + 2]);
    }
    return sum / double(rgba.size() / 4);
}

// Presets are thumbnails in one fixed preview scene, whatever is being edited (an unlit scene
// used to give black thumbnails), captioned with their material's name, and metals under it
// tell apart by colour.
TEST_F(EditorUi, PresetsShowTheirNamesInAFixedPreviewScene) {
    std::vector<std::string> warnings;
    for (const char* name : {"gold", "silver"}) {
        std::filesystem::copy_file(std::filesystem::path(PATINA_PRESETS_DIR) / (std::string(name) + ".json"),
                                   path(std::string(name) + ".json"));
    }
    state_.presetFolders = {dir_};
    state_.scene.lights.clear();
    state_.scene.camera.position = {0.0f, 5.0f, 0.1f};
    frames(3);
    const EditorServices::Preset* gold = services_->preset(path("gold.json"));
    const EditorServices::Preset* silver = services_->preset(path("silver.json"));
    ASSERT_TRUE(gold && silver);
    EXPECT_EQ(gold->name, loadMaterialFile(path("gold.json"), warnings).name);
    const glm::dvec3 g = meanColour(texturePixels(*gold->texture));
    const glm::dvec3 s = meanColour(texturePixels(*silver->texture));
    EXPECT_GT(g.r + g.g + g.b, 3 * 0.18 * 255 * 0.5) << "lit, not black";
    EXPECT_GT(g.r / g.b, 1.15 * (s.r / s.b)) << "gold is yellower than silver";
    // Under the studio environment: a metal reflects it all over, not a few highlights.
    const Scene preview = previewScene(loadMaterialFile(path("silver.json"), warnings));
    EXPECT_TRUE(enabledEnvironment(preview));
    EXPECT_GT(s.r + s.g + s.b, 3 * 0.18 * 255 * 0.6) << "silver reads as a lit metal";
    // The caption sits under its thumbnail.
    ImVec2 buttonMin, buttonMax, captionMin, captionMax;
    ASSERT_TRUE(itemRect("preset:gold", &buttonMin, &buttonMax));
    ASSERT_TRUE(itemRect("caption:gold", &captionMin, &captionMax));
    EXPECT_GE(captionMin.y, buttonMax.y - 1.0f);
    EXPECT_LT(captionMin.x, buttonMax.x);
    // Rendered again when the file changes.
    const std::vector<uint8_t> before = texturePixels(*gold->texture);
    Material rough = loadMaterialFile(path("gold.json"), warnings);
    rough.roughness = 0.9f;
    saveMaterialFile(path("gold.json"), rough);
    std::filesystem::last_write_time(path("gold.json"),
                                     std::filesystem::last_write_time(path("gold.json")) + std::chrono::seconds(2));
    frames(2);
    EXPECT_NE(texturePixels(*services_->preset(path("gold.json"))->texture), before);
}

// Issue 34: the browser's header was the build tree's whole path. The shipped presets are
// "Built-in", the user's are theirs, from their home folder; no path of the machine shows.
TEST_F(EditorUi, ThePresetBrowserNamesItsFoldersWithoutLocalPaths) {
    state_.userPresetFolder = path("config/patina/presets");
    std::filesystem::create_directories(state_.userPresetFolder);
    std::filesystem::copy_file(std::filesystem::path(PATINA_PRESETS_DIR) / "gold.json",
                               state_.userPresetFolder / "mine.json");
    state_.presetFolders = {PATINA_PRESETS_DIR, state_.userPresetFolder};
    const std::string home = std::getenv("HOME") ? std::getenv("HOME") : "";
    setenv("HOME", dir_.c_str(), 1);
    frames(2);
    setenv("HOME", home.c_str(), 1);
    const std::map<std::string, RecordedItem> items = itemsOfLastFrame();
    ASSERT_TRUE(items.count("presets:built-in"));
    ASSERT_TRUE(items.count("presets:yours"));
    EXPECT_NE(items.at("presets:yours").tooltip.find("~/config/patina/presets"), std::string::npos)
        << items.at("presets:yours").tooltip;
    for (const auto& [name, item] : items) {
        EXPECT_EQ(item.tooltip.find(PATINA_PRESETS_DIR), std::string::npos) << name << ": " << item.tooltip;
        EXPECT_EQ(item.tooltip.find(dir_.string()), std::string::npos) << name << ": " << item.tooltip;
    }
}

// Issue 34: the read-out listed the lights in the order the renderer packs them (area lights
// last), not in the lights panel's.
TEST_F(EditorUi, ThePixelReadOutListsTheLightsInThePanelsOrder) {
    Light sphere;
    sphere.type = LightType::Sphere;
    sphere.name = "first, a sphere";
    sphere.position = {0.5f, 0.5f, 2.0f};
    sphere.sourceRadius = 0.2f;
    Light point;
    point.name = "then a point";
    point.position = {-0.5f, 0.5f, 2.0f};
    state_.scene.lights = {sphere, point};
    const Scene shown = renderedScene(state_, state_);
    const PixelStory* story = services_->pixelStory(sceneToDraw(state_, shown), 64, 64, 32, 32);
    ASSERT_NE(story, nullptr);
    std::vector<std::string> names;
    for (const LightShare& light : story->lights) {
        names.push_back(light.name);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"first, a sphere", "then a point"}));
}

// Issue 34: a long status ran off the window's edge with no way to read it. Its first line is
// cut with "..." inside the window, and the whole status is its tooltip.
TEST_F(EditorUi, ALongStatusStaysInTheWindowAndReadsWholeOnHover) {
    state_.status = "Opened 2CylinderEngine.glb: 34 materials (the Material panel shows \"Material_17\"; pick another "
                    "in Parts or click a part), 0 texture images, and a note long enough to run past the window's edge"
                    "\nnode 12: a second line";
    frames(2);
    const std::map<std::string, RecordedItem> items = itemsOfLastFrame();
    ASSERT_TRUE(items.count("status"));
    EXPECT_LE(items.at("status").max.x, ImGui::GetIO().DisplaySize.x);
    EXPECT_EQ(items.at("status").tooltip, state_.status);
}

// Reset goes back to the opened file's value; a right-click to the default.
TEST_F(EditorUi, ResetRevertsToTheFilesValueAndRightClickToTheDefault) {
    Material opened;
    opened.name = "opened";
    opened.roughness = 0.2f;
    opened.baseColor = {0.1f, 0.5f, 0.9f};
    saveMaterialFile(path("opened.json"), opened);
    ASSERT_TRUE(openFile(state_, path("opened.json"))) << state_.error;
    state_.scene.material.roughness = 0.9f;
    state_.scene.material.baseColor = {1.0f, 1.0f, 1.0f};
    frames(2);
    click(centreOf("Reset Roughness"));
    EXPECT_EQ(state_.scene.material.roughness, 0.2f);
    click(centreOf("Reset Base colour"));
    EXPECT_EQ(state_.scene.material.baseColor, opened.baseColor);
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = centreOf("Reset Roughness");
    frames(1);
    io.MouseDown[1] = true;
    frames(1);
    io.MouseDown[1] = false;
    frames(2);
    EXPECT_EQ(state_.scene.material.roughness, Material{}.roughness);
}

// View > Frame mesh aims the camera as the F key does (it used to do nothing).
TEST_F(EditorUi, FrameMeshFromTheViewMenuAimsAtTheMesh) {
    state_.scene.camera.target = {3.0f, 1.0f, 0.0f};
    click(centreOf("menu:View"));
    click(centreOf("Frame mesh"));
    EXPECT_NEAR(glm::length(state_.scene.camera.target), 0.0f, 1e-5f);
}

// The editor holds the mesh loaded for its scene: it draws the very triangles openFile loaded,
// and choosing a built-in mesh lets go of the file's.
TEST_F(EditorUi, TheEditorHoldsTheMeshItDraws) {
    exportGltf(path("torus.glb"), makeTorus(), Material{});
    ASSERT_TRUE(openFile(state_, path("torus.glb"))) << state_.error;
    const std::shared_ptr<const LoadedModel> torus = state_.fileModel;
    ASSERT_TRUE(torus);
    frames(2);
    const LdrImage shown = services_->viewportPixels(EditorServices::Shown::Edited);
    state_.scene.meshFile.clear();
    state_.fileModel.reset();
    frames(2);
    EXPECT_GT(differingPixels(shown, services_->viewportPixels(EditorServices::Shown::Edited)), 1000)
        << "the sphere again";
    state_.scene.meshFile = path("torus.glb").string();
    state_.fileModel = torus;
    frames(2);
    EXPECT_EQ(differingPixels(shown, services_->viewportPixels(EditorServices::Shown::Edited)), 0);
}


// A right drag in the viewport turns the environment, lighting and background together, as one
// undo step, and leaves the camera where it was.
TEST_F(EditorUi, ARightDragTurnsTheEnvironment) {
    Light* environment = editedEnvironment(state_);
    ASSERT_NE(environment, nullptr);
    const float before = environment->rotationDegrees;
    const Camera camera = state_.scene.camera;
    const ImVec2 at = centreOf("viewport");
    drag(ImVec2(at.x - 40.0f, at.y), ImVec2(at.x + 40.0f, at.y), 8, 1);
    EXPECT_NEAR(editedEnvironment(state_)->rotationDegrees, before + 40.0f, 5.0f);
    EXPECT_EQ(state_.scene.camera, camera);
    press(kKeyZ, true);
    EXPECT_EQ(editedEnvironment(state_)->rotationDegrees, before);
}

// Choosing an environment file prepares it on a worker: the panel shows the progress and a
// Cancel while the picture keeps the old one, and the panorama of the new one once it is done.
TEST_F(EditorUi, AnEnvironmentFileShowsItsProgressThenItsPanorama) {
    state_.selectedLight = int(std::find_if(state_.scene.lights.begin(), state_.scene.lights.end(),
                                            [](const Light& l) { return l.type == LightType::Environment; }) -
                               state_.scene.lights.begin());
    frames(2);
    ImVec2 min, max;
    EXPECT_TRUE(itemRect("Environment panorama", &min, &max)) << "the studio's panorama";
    // A file too large to finish within a frame or two (1024 x 512) to see the progress, with
    // a cache of its own so that it is prepared, not read back from an earlier run.
    setenv("PATINA_CACHE_DIR", dir_.c_str(), 1);
    test::writeFlatHdr(path("big.hdr"), 1024, 512, 100);
    ASSERT_TRUE(setEnvironmentSource(state_, state_, state_, state_, path("big.hdr").string()));
    frames(1);
    ASSERT_TRUE(state_.environmentLoad);
    {
        EXPECT_EQ(itemsOfLastFrame().count("Environment progress"), 1u);
        EXPECT_NE(state_.environment ? state_.environment->source : "", path("big.hdr").string());
    }
    ASSERT_TRUE(finishEnvironmentLoad(state_, state_, state_, state_, true)) << state_.error;
    unsetenv("PATINA_CACHE_DIR");
    frames(2);
    ASSERT_TRUE(state_.environment);
    EXPECT_EQ(state_.environment->source, path("big.hdr").string());
    EXPECT_EQ(itemsOfLastFrame().count("Environment progress"), 0u);
    EXPECT_EQ(itemsOfLastFrame().count("Environment panorama"), 1u);
}

// A point light's dot is dragged, not the camera orbited (the viewport's button held the click
// and the gizmo asked whether the window was hovered, which it then is not), and the drag is
// one undo step.
TEST_F(EditorUi, DraggingAPointLightsGizmoMovesTheLightNotTheCamera) {
    const Light lamp = onlyALamp();
    frames(2);
    const Camera camera = state_.scene.camera;
    const ImVec2 from = onScreen(lamp.position);
    drag(from, ImVec2(from.x + 60.0f, from.y + 30.0f));
    EXPECT_EQ(state_.scene.camera, camera) << "the camera orbited";
    EXPECT_GT(glm::distance(state_.scene.lights[0].position, lamp.position), 0.1f) << "the light did not move";
    EXPECT_EQ(state_.selectedLight, 0);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights[0].position, lamp.position);
}


// The recorded items of the last frame that are cut by their window's edge or the display's.
std::vector<std::string> clippedItems() {
    std::vector<std::string> names;
    for (const auto& [name, item] : itemsOfLastFrame()) {
        if (clipped(item)) {
            char where[160];
            std::snprintf(where, sizeof where, " [%.0f %.0f %.0f %.0f] in [%.0f %.0f %.0f %.0f]", double(item.min.x),
                          double(item.min.y), double(item.max.x), double(item.max.y), double(item.visibleMin.x),
                          double(item.visibleMin.y), double(item.visibleMax.x), double(item.visibleMax.y));
            names.push_back(name + where);
        }
    }
    return names;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& line : lines) {
        text += line + "\n";
    }
    return text;
}

// At a laptop's and a desktop's size, and at 4K with the UI at 200%, no recorded widget is cut
// off (at 1400 x 860 the colour's Reset showed as "Re" and the pass choice was clipped): with
// Advanced open or closed, whichever light is selected, and with the shortcuts window open.
TEST_F(EditorUi, NoWidgetIsClippedAtCommonScreenSizes) {
    struct Screen {
        float width, height, scale;
    };
    for (const Screen screen : {Screen{1280, 720, 1.0f}, Screen{1920, 1080, 1.0f}, Screen{3840, 2160, 2.0f}}) {
        ASSERT_EQ(applyUiScale(screen.scale), "");
        ImGui::GetIO().DisplaySize = ImVec2(screen.width, screen.height);
        for (bool advanced : {false, true}) {
            state_.showAdvanced = advanced;
            state_.showShortcuts = advanced;
            for (int light = 0; light < int(state_.scene.lights.size()); ++light) {
                state_.selectedLight = light;
                frames(3);
                ASSERT_FALSE(itemsOfLastFrame().empty());
                EXPECT_EQ(clippedItems(), std::vector<std::string>{})
                    << screen.width << " x " << screen.height << " at " << screen.scale << ", advanced " << advanced
                    << ", light " << light << ":\n" << joined(clippedItems());
            }
        }
        EXPECT_TRUE(itemsOfLastFrame().contains("Path specialised"));
        EXPECT_TRUE(itemsOfLastFrame().contains("shortcuts"));
        EXPECT_TRUE(state_.error.empty()) << state_.error;
    }
    ASSERT_EQ(applyUiScale(1.0f), "");
}

// Every control in the panels and the toolbar is named in the layout dump with a tooltip; the
// pictures (the viewport, the lobe plot, the preset captions) need none.
TEST_F(EditorUi, EveryControlIsNamedAndHasATooltip) {
    state_.showAdvanced = true;
    state_.compareA = state_.scene.material;
    for (int light = 0; light < int(state_.scene.lights.size()); ++light) {
        state_.selectedLight = light;
        frames(2);
        for (const auto& [name, item] : itemsOfLastFrame()) {
            const bool picture = name == "viewport" || name == "lobe" || name.starts_with("caption:") ||
                                 name.starts_with("menu:");
            EXPECT_TRUE(picture || !item.tooltip.empty()) << name << " has no tooltip";
        }
    }
    // Sweep the mouse over the panels: wherever ImGui finds a control under it, a named item
    // is there too.
    ImGuiIO& io = ImGui::GetIO();
    ImGuiContext& context = *ImGui::GetCurrentContext();
    std::vector<std::string> unnamed;
    for (const char* panel : {"Material", "Lights", "Viewport", "Lobe"}) {
        const ImGuiWindow* window = ImGui::FindWindowByName(panel);
        ASSERT_NE(window, nullptr) << panel;
        // Inside its edges and scrollbar, which can be dragged, and away from its resize corner.
        const ImRect inner(window->InnerRect.Min.x + 6, window->InnerRect.Min.y + 6, window->InnerRect.Max.x - 6,
                           window->InnerRect.Max.y - 6);
        const float corner = ImGui::GetFontSize() * 2.0f;
        for (float y = inner.Min.y; y < inner.Max.y; y += 9.0f) {
            for (float x = inner.Min.x; x < inner.Max.x; x += 14.0f) {
                if (x > inner.Max.x - corner && y > inner.Max.y - corner) {
                    continue;
                }
                io.MousePos = ImVec2(x, y);
                frames(1);
                if (context.HoveredId == 0) {
                    continue;
                }
                bool named = false;
                for (const auto& [name, item] : itemsOfLastFrame()) {
                    named |= x >= item.min.x && x <= item.max.x && y >= item.min.y && y <= item.max.y;
                }
                if (!named) {
                    unnamed.push_back(std::string(panel) + " at " + std::to_string(int(x)) + ", " +
                                      std::to_string(int(y)));
                }
            }
        }
    }
    EXPECT_EQ(unnamed, std::vector<std::string>{}) << joined(unnamed);
}

// The research controls start closed: no BRDF model, path or Accuracy tab until Advanced is
// opened, and then they are all there.
TEST_F(EditorUi, ResearchControlsAreBehindAdvanced) {
    for (const char* name : {"Model", "Path single", "Accuracy tab"}) {
        EXPECT_FALSE(itemsOfLastFrame().contains(name)) << name;
    }
    click(centreOf("Advanced"));
    EXPECT_TRUE(state_.showAdvanced);
    for (const char* name : {"Model", "Path single", "Path multi", "Accuracy tab"}) {
        EXPECT_TRUE(itemsOfLastFrame().contains(name)) << name;
    }
}

// View > Channel shows a debug channel instead of the picture, labelled, in both comparison
// views too; a light channel whose light goes away falls back to the picture and says so; Picture
// goes back. Screenshots stay the picture.
TEST_F(EditorUi, TheViewMenuShowsAChannelInsteadOfThePicture) {
    const LdrImage picture = services_->viewportPixels(EditorServices::Shown::Edited);
    click(centreOf("menu:View"));
    click(centreOf("Channel"));
    click(centreOf("channel:base-color"));
    ASSERT_EQ(channelName(state_.channel), "base-color");
    frames(2);
    EXPECT_TRUE(itemsOfLastFrame().contains("channel label"));
    const LdrImage channel = services_->viewportPixels(EditorServices::Shown::Edited);
    ASSERT_EQ(channel.width, picture.width);
    // The sphere's middle shows the base colour as data: the linear value times 255.
    const uint8_t* middle = &channel.rgba[(size_t(channel.height / 2) * size_t(channel.width) + size_t(channel.width / 2)) * 4];
    EXPECT_NEAR(middle[0], std::lround(state_.scene.material.baseColor.r * 255.0f), 1);
    EXPECT_NEAR(middle[1], std::lround(state_.scene.material.baseColor.g * 255.0f), 1);
    EXPECT_GT(differingPixels(picture, channel), 1000);

    click(centreOf("Set A"));
    for (const char* view : {"Split", "Side by side"}) {
        click(centreOf(view));
        frames(2);
        EXPECT_TRUE(itemsOfLastFrame().contains("channel label")) << view;
    }
    click(centreOf("Single"));

    const std::string name = state_.scene.lights[0].name;
    click(centreOf("menu:View"));
    click(centreOf("Channel"));
    click(centreOf("channel:light:" + name));
    EXPECT_EQ(state_.channel.light, name);
    state_.scene.lights[0].enabled = false;
    frames(2);
    EXPECT_EQ(state_.channel.channel, -1);
    EXPECT_NE(state_.status.find("picture again"), std::string::npos) << state_.status;
    state_.scene.lights[0].enabled = true;

    click(centreOf("menu:View"));
    click(centreOf("Channel"));
    click(centreOf("channel:shading-normal"));
    click(centreOf("menu:View"));
    click(centreOf("Channel"));
    click(centreOf("channel:picture"));
    frames(2);
    EXPECT_EQ(state_.channel.channel, -1);
    EXPECT_FALSE(itemsOfLastFrame().contains("channel label"));
    EXPECT_EQ(differingPixels(picture, services_->viewportPixels(EditorServices::Shown::Edited)), 0);
}

// The read-out in a comparison: the tooltip tells the story of the picture under the mouse (A's
// half or B's side by side, either side of the divider in Split), and a pin placed on A's half
// marks the same place in B's.
TEST_F(EditorUi, PixelReadOutTellsAOrBInEveryView) {
    click(centreOf("menu:View"));
    click(centreOf("Pixel read-out"));
    click(centreOf("Set A"));
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("viewport", &min, &max));
    const float w = max.x - min.x, y = (min.y + max.y) * 0.5f;
    ImGuiIO& io = ImGui::GetIO();
    for (const char* view : {"Side by side", "Split"}) {
        click(centreOf(view));
        // Side by side: the halves' middles; Split (divider in the middle): a quarter in from each side.
        const float left = min.x + w * 0.25f, right = min.x + w * 0.75f;
        io.MousePos = ImVec2(left, y);
        frames(2);
        EXPECT_TRUE(itemsOfLastFrame().contains("pixel story A")) << view;
        io.MousePos = ImVec2(right, y);
        frames(2);
        EXPECT_TRUE(itemsOfLastFrame().contains("pixel story B")) << view;
        EXPECT_FALSE(itemsOfLastFrame().contains("pixel story A")) << view;
    }
    click(centreOf("Side by side"));
    io.KeyCtrl = true;
    click(ImVec2(min.x + w * 0.25f, y));   // the middle of A's half
    io.KeyCtrl = false;
    ASSERT_EQ(state_.pins.size(), 1u);
    EXPECT_NEAR(state_.pins[0].x, 0.5f, 0.02f);
    EXPECT_NEAR(state_.pins[0].y, 0.5f, 0.02f);
    EXPECT_TRUE(itemsOfLastFrame().contains("unpin:1"));
    // A plain click pins too; a drag (the camera turning) pins nothing.
    click(ImVec2(min.x + w * 0.7f, y));
    EXPECT_EQ(state_.pins.size(), 2u);
    drag(ImVec2(min.x + w * 0.6f, y), ImVec2(min.x + w * 0.6f + 60.0f, y + 20.0f));
    EXPECT_EQ(state_.pins.size(), 2u);
}

// Every channel in every view: the label shows, nothing fails, and Picture gives the picture back.
TEST_F(EditorUi, EveryChannelShowsInEveryView) {
    click(centreOf("Set A"));
    for (const char* view : {"Single", "Split", "Side by side"}) {
        click(centreOf(view));
        std::vector<std::string> names = fixedChannelNames();
        names.push_back("light:" + state_.scene.lights[0].name);
        for (const std::string& name : names) {
            click(centreOf("menu:View"));
            click(centreOf("Channel"));
            click(centreOf("channel:" + name));
            ASSERT_EQ(channelName(state_.channel), name) << view;
            frames(1);
            EXPECT_TRUE(itemsOfLastFrame().contains("channel label")) << view << " " << name;
            EXPECT_TRUE(state_.error.empty()) << view << " " << name << ": " << state_.error;
        }
        click(centreOf("menu:View"));
        click(centreOf("Channel"));
        click(centreOf("channel:picture"));
        frames(1);
        EXPECT_FALSE(itemsOfLastFrame().contains("channel label")) << view;
    }
}

// A light whose channel shows, switched off in the lights panel (drawn before the viewport in
// the same frame): the picture comes back and the status says why; no panel fails.
TEST_F(EditorUi, SwitchingOffTheShownLightInThePanelGivesThePictureBack) {
    const std::string name = state_.scene.lights[1].name;
    click(centreOf("menu:View"));
    click(centreOf("Channel"));
    click(centreOf("channel:light:" + name));
    ASSERT_EQ(state_.channel.light, name);
    click(centreOf("light:1 enabled"));
    ASSERT_FALSE(state_.scene.lights[1].enabled);
    frames(2);
    EXPECT_EQ(state_.channel.channel, -1);
    EXPECT_TRUE(state_.error.empty()) << state_.error;
    EXPECT_NE(state_.status.find("picture again"), std::string::npos) << state_.status;
}

// The lobe panel's BRDF Explorer views: each draws (with A beside B), the slice's hover tells a
// cell's angles, and dragging the 3D lobe turns it.
TEST_F(EditorUi, TheLobePanelShowsTheSliceTheAlbedoAndTheThreeDLobe) {
    click(centreOf("Set A"));
    click(centreOf("lobe view:Slice"));
    EXPECT_EQ(state_.lobe.view, LobeView::Slice);
    EXPECT_TRUE(itemsOfLastFrame().contains("slice"));
    EXPECT_TRUE(itemsOfLastFrame().contains("phi_d"));
    click(centreOf("lobe view:Albedo"));
    EXPECT_EQ(state_.lobe.view, LobeView::Albedo);
    EXPECT_TRUE(itemsOfLastFrame().contains("albedo"));
    click(centreOf("lobe view:3D"));
    EXPECT_EQ(state_.lobe.view, LobeView::Lobe3d);
    ASSERT_TRUE(itemsOfLastFrame().contains("lobe 3d"));
    const float yaw = state_.lobe.yawDegrees;
    const ImVec2 middle = centreOf("lobe 3d");
    drag(middle, ImVec2(middle.x + 40.0f, middle.y));
    EXPECT_NEAR(state_.lobe.yawDegrees, yaw + 20.0f, 0.5f);
    click(centreOf("lobe view:Polar"));
    EXPECT_TRUE(itemsOfLastFrame().contains("lobe"));
    EXPECT_FALSE(itemsOfLastFrame().contains("lobe 3d"));
}

// View > PBR validation overlay: the status line counts the flagged pixels of the picture (all
// of them for a base colour darker than charcoal, none for a plausible one), the strict ranges
// flag what the default ones pass, the count holds in every view, the pbr-validation channel
// counts the same, and turning the overlay off takes the count away.
TEST_F(EditorUi, ThePbrOverlayCountsTheFlaggedPixelsInTheStatusLine) {
    state_.scene.material.baseColor = glm::vec3(0.004f);
    state_.scene.material.metallic = 0.0f;
    click(centreOf("menu:View"));
    click(centreOf("PBR validation overlay"));
    ASSERT_TRUE(state_.pbrOverlay);
    frames(2);
    EXPECT_TRUE(itemsOfLastFrame().contains("PBR tally"));
    ASSERT_TRUE(services_->pbrTally);
    const PbrTally dark = *services_->pbrTally;
    EXPECT_GT(dark.texels, 1000u);
    EXPECT_EQ(dark.dielectricDark, dark.texels);
    // The overlay goes over the picture; it is not the picture.
    EXPECT_EQ(tallyPbrChannel(services_->viewportPixels(EditorServices::Shown::Edited)).flagged(), 0u);

    state_.scene.material.baseColor = glm::vec3(0.025f);   // lightness 44: between 30 and 50
    frames(2);
    EXPECT_EQ(services_->pbrTally->flagged(), 0u);
    click(centreOf("menu:View"));
    click(centreOf("Channel"));
    click(centreOf("Strict PBR ranges"));
    ASSERT_TRUE(state_.channel.strictPbr);
    frames(2);
    EXPECT_EQ(services_->pbrTally->dielectricDark, services_->pbrTally->texels);

    click(centreOf("Set A"));
    for (const char* view : {"Split", "Side by side"}) {
        click(centreOf(view));
        frames(2);
        ASSERT_TRUE(services_->pbrTally) << view;
        EXPECT_GT(services_->pbrTally->flagged(), 500u) << view;
    }
    click(centreOf("Single"));
    frames(2);
    const PbrTally overlay = *services_->pbrTally;

    click(centreOf("menu:View"));
    click(centreOf("Channel"));
    click(centreOf("channel:pbr-validation"));
    frames(2);
    ASSERT_TRUE(services_->pbrTally);
    EXPECT_EQ(services_->pbrTally->flagged(), overlay.flagged());
    EXPECT_EQ(tallyPbrChannel(services_->viewportPixels(EditorServices::Shown::Edited)).flagged(), overlay.flagged());
    click(centreOf("menu:View"));
    click(centreOf("Channel"));
    click(centreOf("channel:picture"));
    click(centreOf("menu:View"));
    click(centreOf("PBR validation overlay"));
    frames(2);
    EXPECT_FALSE(state_.pbrOverlay);
    EXPECT_FALSE(services_->pbrTally);
    EXPECT_FALSE(itemsOfLastFrame().contains("PBR tally"));
}

// View > Pixel read-out: hovering tells the pixel's story, Ctrl+click pins it (picking no part),
// the pin is listed, copied as CSV with the values the viewport shows there, and removable.
TEST_F(EditorUi, PixelReadOutPinsAPixelWithTheValuesTheViewportShows) {
    click(centreOf("menu:View"));
    click(centreOf("Pixel read-out"));
    ASSERT_TRUE(state_.pixelReadOut);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("viewport", &min, &max));
    const ImVec2 middle((min.x + max.x) * 0.5f, (min.y + max.y) * 0.5f);
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = true;
    click(middle);
    io.KeyCtrl = false;
    ASSERT_EQ(state_.pins.size(), 1u);
    frames(2);
    EXPECT_TRUE(itemsOfLastFrame().contains("unpin:1"));
    click(centreOf("Copy pins as CSV"));
    const std::string csv = ImGui::GetClipboardText();
    ASSERT_EQ(csv.rfind("pin,x,y,item,material,radiance_r", 0), 0u) << csv;
    // Each light's share has its columns, named after the light.
    std::string stem = state_.scene.lights[0].name;
    std::replace(stem.begin(), stem.end(), ' ', '_');
    EXPECT_NE(csv.substr(0, csv.find('\n')).find("," + stem + "_diffuse_r,"), std::string::npos) << csv;
    // The pin's line: its pixel and its displayed bytes, as the viewport (MSAA) shows them.
    const std::string line = csv.substr(csv.find('\n') + 1);
    std::vector<std::string> fields;
    for (size_t start = 0, comma; start <= line.size(); start = comma + 1) {
        comma = line.find_first_of(",\n", start);
        fields.push_back(line.substr(start, comma - start));
        if (comma == std::string::npos || line[comma] == '\n') {
            break;
        }
    }
    ASSERT_GE(fields.size(), 11u) << line;
    const int x = std::stoi(fields[1]), y = std::stoi(fields[2]);
    EXPECT_NEAR(x, int(middle.x - min.x), 1);
    const LdrImage shown = services_->viewportPixels(EditorServices::Shown::Edited);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(std::stod(fields[size_t(8 + c)]), shown.rgba[(size_t(y) * size_t(shown.width) + size_t(x)) * 4 + size_t(c)], 2)
            << line;
    }
    click(centreOf("unpin:1"));
    EXPECT_TRUE(state_.pins.empty());
}

// Issue 34: the Pinned pixels window opened over the model. It opens beside the picture.
TEST_F(EditorUi, ThePinnedPixelsWindowOpensBesideThePicture) {
    state_.pixelReadOut = true;
    frames(2);
    click(centreOf("viewport"));
    ASSERT_EQ(state_.pins.size(), 1u);
    frames(2);
    const ImGuiWindow* pins = ImGui::FindWindowByName("Pinned pixels");
    ASSERT_NE(pins, nullptr);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("viewport", &min, &max));
    const bool apart = pins->Pos.y >= max.y || pins->Pos.x >= max.x || pins->Pos.x + pins->Size.x <= min.x ||
                       pins->Pos.y + pins->Size.y <= min.y;
    EXPECT_TRUE(apart) << "window at " << pins->Pos.x << ", " << pins->Pos.y << " size " << pins->Size.x << " x "
                       << pins->Size.y << "; picture " << min.x << ", " << min.y << " to " << max.x << ", " << max.y;
    EXPECT_LE(pins->Pos.y + pins->Size.y, ImGui::GetIO().DisplaySize.y) << "whole on the screen";
    for (int more = 0; more < 4; ++more) {   // more stories than the window holds: they scroll
        state_.pins.push_back(state_.pins[0]);
    }
    frames(2);
    const std::map<std::string, RecordedItem> items = itemsOfLastFrame();
    ASSERT_TRUE(items.count("Copy pins as CSV"));
    EXPECT_FALSE(clipped(items.at("Copy pins as CSV"))) << "the buttons stay in view";
}

// With the gizmos hidden (View menu), a drag where a light's dot was orbits the camera.
TEST_F(EditorUi, HiddenGizmosCannotBeGrabbed) {
    const Light lamp = onlyALamp();
    click(centreOf("menu:View"));
    click(centreOf("Light gizmos"));
    ASSERT_FALSE(state_.showGizmos);
    const Camera camera = state_.scene.camera;
    const ImVec2 from = onScreen(lamp.position);
    drag(from, ImVec2(from.x + 60.0f, from.y + 30.0f));
    EXPECT_EQ(state_.scene.lights[0].position, lamp.position);
    EXPECT_NE(state_.scene.camera, camera) << "the drag orbits";
}

// Solo greys out the other lights in the list; they can still be picked.
TEST_F(EditorUi, SoloGreysOutTheOtherLights) {
    ASSERT_GE(state_.scene.lights.size(), 3u);
    EXPECT_FALSE(itemsOfLastFrame().at("light:0").dimmed);
    click(centreOf("light:1 solo"));
    ASSERT_EQ(state_.soloLight, 1);
    const auto items = itemsOfLastFrame();
    EXPECT_TRUE(items.at("light:0").dimmed);
    EXPECT_FALSE(items.at("light:1").dimmed);
    EXPECT_TRUE(items.at("light:2").dimmed);
    click(centreOf("light:2"));
    EXPECT_EQ(state_.selectedLight, 2);
}

// File > Save as preset writes into the user's presets folder (made for it), the material
// takes the file's name, and the preset browser shows it in the next frame.
TEST_F(EditorUi, SaveAsPresetShowsInTheBrowserAtOnce) {
    state_.userPresetFolder = dir_ / "config" / "presets";
    state_.presetFolders = {state_.userPresetFolder};
    click(centreOf("menu:File"));
    click(centreOf("Save as preset"));
    ASSERT_EQ(state_.pathDialog, EditorState::PathDialog::SavePreset);
    EXPECT_EQ(state_.pathDialogText, (state_.userPresetFolder / "terracotta.json").string());
    // Typed over, as a user does: the path field has the keys; Ctrl+A, then the new path.
    ImGuiIO& io = ImGui::GetIO();
    io.KeyMap[ImGuiKey_A] = 'A';
    io.KeyCtrl = io.KeysDown[int('A')] = true;
    frames(1);
    io.KeyCtrl = io.KeysDown[int('A')] = false;
    for (char c : (state_.userPresetFolder / "warm clay.json").string()) {
        io.AddInputCharacter(static_cast<unsigned>(c));
    }
    frames(2);
    EXPECT_EQ(state_.pathDialogText, (state_.userPresetFolder / "warm clay.json").string()) << "written as typed";
    ImVec2 folderMin, folderMax, listMin, listMax;
    ASSERT_TRUE(itemRect("path:folder", &folderMin, &folderMax)) << "the folder listed is named";
    ASSERT_TRUE(itemRect("path:up", &listMin, &listMax));
    EXPECT_LT(folderMax.y, listMin.y + 1.0f) << "above its listing";
    click(centreOf("path:confirm"));
    ASSERT_TRUE(std::filesystem::exists(state_.userPresetFolder / "warm clay.json")) << state_.error;
    EXPECT_EQ(state_.scene.material.name, "warm clay");
    EXPECT_TRUE(itemsOfLastFrame().contains("preset:warm clay"));
    EXPECT_TRUE(itemsOfLastFrame().contains("caption:warm clay"));
}

// The UI font is DejaVu Sans at a readable size, scaled with the UI; without the file the
// built-in font is used and the editor says why.
TEST_F(EditorUi, TheFontIsDejaVuSansAndAMissingOneFallsBack) {
    ASSERT_EQ(applyUiScale(2.0f), "");
    ImFont* font = ImGui::GetIO().Fonts->Fonts[0];
    EXPECT_NE(std::string(font->GetDebugName()).find("DejaVuSans"), std::string::npos) << font->GetDebugName();
    EXPECT_EQ(font->FontSize, 2.0f * kUiFontPixels);
    EXPECT_EQ(uiScale(), 2.0f);
    const std::string message = applyUiScale(1.0f, dir_ / "missing.ttf");
    EXPECT_NE(message.find("fonts-dejavu-core"), std::string::npos) << message;
    EXPECT_NE(std::string(ImGui::GetIO().Fonts->Fonts[0]->GetDebugName()).find("ProggyClean"), std::string::npos);
    frames(2);   // the built-in font still draws the editor
    EXPECT_TRUE(state_.error.empty()) << state_.error;
}

// After a screenshot, the status line offers its folder, opened with the desktop's opener.
TEST_F(EditorUi, AScreenshotsFolderOpensFromTheStatusLine) {
    const std::filesystem::path script = path("opener.sh");
    std::ofstream(script) << "#!/bin/sh\necho \"$1\" > '" << path("opened.txt").string() << "'\n";
    std::filesystem::permissions(script, std::filesystem::perms::owner_all);
    state_.folderOpener = script.string();
    state_.screenshotFolder = dir_ / "shots";
    press(kKeyF12);
    click(centreOf("Open folder"));
    std::ifstream opened(path("opened.txt"));
    std::string line;
    std::getline(opened, line);
    EXPECT_EQ(line, (dir_ / "shots").string());
    state_.folderOpener = "patina-no-such-opener";
    click(centreOf("Open folder"));
    EXPECT_NE(state_.error.find("xdg-utils"), std::string::npos) << state_.error;
}

TEST_F(EditorUi, AddSphereAndAddTubeAddLightsThatShowAndUndo) {
    const LdrImage before = services_->viewportPixels(EditorServices::Shown::Edited);
    const size_t count = state_.scene.lights.size();
    click(centreOf("Add sphere"));
    ASSERT_EQ(state_.scene.lights.size(), count + 1);
    EXPECT_EQ(state_.scene.lights.back().type, LightType::Sphere);
    EXPECT_GT(state_.scene.lights.back().sourceRadius, 0.0f);
    click(centreOf("Add tube"));
    ASSERT_EQ(state_.scene.lights.size(), count + 2);
    const Light& tube = state_.scene.lights.back();
    EXPECT_EQ(tube.type, LightType::Tube);
    EXPECT_NE(tube.start, tube.end);
    frames(2);
    EXPECT_GT(differingPixels(before, services_->viewportPixels(EditorServices::Shown::Edited)), 100);
    press(kKeyZ, true);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights.size(), count);
}

// The size sliders: a sphere's source radius, a tube's length about its middle; each drag one
// undo step.
TEST_F(EditorUi, SourceRadiusAndLengthSlidersResizeTheLightAndUndo) {
    Light sphere;
    sphere.type = LightType::Sphere;
    sphere.sourceRadius = 0.1f;
    Light tube;
    tube.type = LightType::Tube;
    tube.start = {-0.5f, 1.0f, 1.0f};
    tube.end = {0.5f, 1.0f, 1.0f};
    state_.scene.lights = {sphere, tube};
    state_.selectedLight = 0;
    state_.committed = state_.snapshot();
    frames(2);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Source radius", &min, &max));
    drag(ImVec2(min.x + 0.3f * (max.x - min.x), (min.y + max.y) * 0.5f), ImVec2(max.x - 2.0f, (min.y + max.y) * 0.5f));
    EXPECT_GT(state_.scene.lights[0].sourceRadius, 1.0f);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights[0].sourceRadius, 0.1f);

    state_.selectedLight = 1;
    frames(2);
    ASSERT_TRUE(itemRect("Length", &min, &max));
    drag(ImVec2(min.x + 0.1f * (max.x - min.x), (min.y + max.y) * 0.5f), ImVec2(min.x + 0.5f * (max.x - min.x), (min.y + max.y) * 0.5f));
    const Light& resized = state_.scene.lights[1];
    EXPECT_GT(glm::distance(resized.start, resized.end), 2.0f);
    EXPECT_LT(glm::distance(0.5f * (resized.start + resized.end), glm::vec3(0.0f, 1.0f, 1.0f)), 1e-5f) << "the middle stays";
    EXPECT_LT(glm::length(glm::cross(resized.end - resized.start, glm::vec3(1, 0, 0))), 1e-5f) << "the axis stays";
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights[1].end, tube.end);
}

// A tube's end is dragged on its own, its middle moves both ends; each drag one undo step.
TEST_F(EditorUi, DraggingATubesGizmosMovesItsEndsOrTheWholeTube) {
    Light tube;
    tube.type = LightType::Tube;
    tube.start = {-0.6f, 0.5f, 1.2f};
    tube.end = {0.6f, 0.5f, 1.2f};
    state_.scene.lights = {tube};
    state_.committed = state_.snapshot();
    frames(2);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("viewport", &min, &max));
    const Camera camera = state_.scene.camera;
    const glm::vec2 view(max.x - min.x, max.y - min.y);
    const auto end = projectToViewport(camera, view, tube.end);
    ASSERT_TRUE(end.has_value());
    drag(ImVec2(min.x + end->x, min.y + end->y), ImVec2(min.x + end->x + 40.0f, min.y + end->y - 30.0f));
    EXPECT_EQ(state_.scene.camera, camera) << "the camera orbited";
    EXPECT_EQ(state_.scene.lights[0].start, tube.start);
    EXPECT_GT(glm::distance(state_.scene.lights[0].end, tube.end), 0.1f);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights[0].end, tube.end);

    const auto middle = projectToViewport(camera, view, 0.5f * (tube.start + tube.end));
    ASSERT_TRUE(middle.has_value());
    drag(ImVec2(min.x + middle->x, min.y + middle->y), ImVec2(min.x + middle->x, min.y + middle->y + 40.0f));
    const Light& moved = state_.scene.lights[0];
    EXPECT_GT(glm::distance(moved.start, tube.start), 0.1f);
    EXPECT_LT(glm::distance(moved.end - moved.start, tube.end - tube.start), 1e-4f) << "moved whole";
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights[0].start, tube.start);
}

// Issue 23: a window shrunk to 300 x 200 for a moment used to keep the panels at the sizes it
// squeezed them to (the lobe 44 pixels high, saved so). The sizes the user dragged to come
// back when there is room; only a drag of a panel's edge changes them.
TEST_F(EditorUi, PanelsGrowBackAfterTheWindowShrinksAndOnlyADragResizesThem) {
    ImGuiIO& io = ImGui::GetIO();
    io.BackendFlags |= ImGuiBackendFlags_HasMouseCursors;   // as GLFW's backend: edges resize
    io.ConfigWindowsResizeFromEdges = true;   // ImGui turned it off without that flag
    const PanelLayout wanted = state_.layout;
    io.DisplaySize = ImVec2(300, 200);
    frames(3);
    io.DisplaySize = ImVec2(1280, 800);
    frames(3);
    EXPECT_EQ(state_.layout.leftWidth, wanted.leftWidth);
    EXPECT_EQ(state_.layout.rightWidth, wanted.rightWidth);
    EXPECT_EQ(state_.layout.lobeHeight, wanted.lobeHeight);
    const ImGuiWindow* lobe = ImGui::FindWindowByName("Lobe");
    ASSERT_NE(lobe, nullptr);
    EXPECT_FLOAT_EQ(lobe->Size.y, wanted.lobeHeight);

    // The material panel's right edge, dragged 60 pixels right: the new width is kept.
    const ImGuiWindow* material = ImGui::FindWindowByName("Material");
    ASSERT_NE(material, nullptr);
    const float edge = material->Pos.x + material->Size.x;
    drag(ImVec2(edge - 1.0f, 400.0f), ImVec2(edge + 59.0f, 400.0f));
    EXPECT_NEAR(state_.layout.leftWidth, wanted.leftWidth + 60.0f, 2.0f);
}

// Issue 23: the lobe took a third of the centre column at 1280 x 720 and could not be hidden.
// View > Lobe panel hides it and the viewport takes the room.
TEST_F(EditorUi, TheLobePanelCanBeHiddenFromTheViewMenu) {
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("viewport", &min, &max));
    const float height = max.y - min.y;
    EXPECT_TRUE(itemsOfLastFrame().contains("lobe"));
    click(centreOf("menu:View"));
    click(centreOf("Lobe panel"));
    EXPECT_FALSE(state_.layout.showLobe);
    frames(2);
    EXPECT_FALSE(itemsOfLastFrame().contains("lobe"));
    EXPECT_EQ(ImGui::FindWindowByName("Lobe")->Active, false);
    ASSERT_TRUE(itemRect("viewport", &min, &max));
    EXPECT_GT(max.y - min.y, height + 200.0f);
    click(centreOf("menu:View"));
    click(centreOf("Lobe panel"));
    frames(2);
    EXPECT_TRUE(itemsOfLastFrame().contains("lobe"));
}

// Issue 23: Split was labelled only "A" and "B", Side by side not at all. Both name the
// materials, in the viewport and in a Split screenshot (Side by side's is captioned).
TEST_F(EditorUi, BothComparisonViewsNameTheirMaterials) {
    state_.scene.material.name = "terracotta";
    click(centreOf("Set A"));
    state_.scene.material.name = "blue glaze";
    for (const char* view : {"Split", "Side by side"}) {
        click(centreOf(view));
        frames(1);
        const auto items = itemsOfLastFrame();
        ASSERT_TRUE(items.contains("label A")) << view;
        ASSERT_TRUE(items.contains("label B")) << view;
        EXPECT_NE(items.at("label A").tooltip.find("A: terracotta"), std::string::npos) << view;
        EXPECT_NE(items.at("label B").tooltip.find("B: blue glaze"), std::string::npos) << view;
        ImVec2 min, max;
        ASSERT_TRUE(itemRect("viewport", &min, &max));
        EXPECT_LT(items.at("label A").max.x, items.at("label B").min.x) << view << ": A left of B";
        EXPECT_GE(items.at("label A").min.x, min.x) << view;
        EXPECT_LE(items.at("label B").max.x, max.x) << view;
    }
    click(centreOf("Single"));
    frames(1);
    EXPECT_FALSE(itemsOfLastFrame().contains("label A"));

    // A Split screenshot's labels are as wide as the names, not a letter each.
    state_.compareView = CompareView::Split;
    const LdrImage split = services_->shownImage(state_, state_, 600, 400);
    const int scale = captionScale(600);
    int rightmost = 0;
    // The caption's ink: its colour, or nearly (its stems are anti-aliased).
    auto near = [](uint8_t value, uint8_t ink) { return std::abs(int(value) - int(ink)) <= 24; };
    for (int y = 24; y < 24 + textHeight(scale); ++y) {
        for (int x = 0; x < 300; ++x) {
            const size_t at = (size_t(y) * 600 + size_t(x)) * 4;
            if (near(split.rgba[at], kCaptionColour.r) && near(split.rgba[at + 1], kCaptionColour.g) &&
                near(split.rgba[at + 2], kCaptionColour.b)) {
                rightmost = std::max(rightmost, x);
            }
        }
    }
    EXPECT_GE(rightmost, 8 + textWidth("A: terracott", scale)) << "A's label names it";
}

// F12 saves what the viewport shows (docs/EDITOR.md): a debug channel where View > Channel shows
// one (it saved the shaded picture whatever the viewport showed), and the PBR overlay's stripes
// over it where the overlay is on.
TEST_F(EditorUi, AScreenshotIsTheChannelAndTheOverlayTheViewportShows) {
    const int width = 160, height = 120;
    const LdrImage picture = services_->shownImage(state_, state_, width, height);
    state_.channel = *channelFromName("D");
    const LdrImage channel = services_->shownImage(state_, state_, width, height);
    EXPECT_NE(channel.rgba, picture.rgba);
    const Scene shown = renderedScene(state_, state_);   // PreparedScene holds its scene by reference
    const PreparedScene prepared = sceneToDraw(state_, shown);
    EXPECT_EQ(channel.rgba, services_->renderImage(prepared, width, height, state_.renderPath,
                                                   state_.environmentShading, state_.channel)
                                .ldr.rgba);
    state_.channel = {};
    state_.scene.material.baseColor = glm::vec3(1.0f);   // a white dielectric: brighter than snow
    state_.scene.material.metallic = 0.0f;
    auto reddish = [](const LdrImage& image) {
        int count = 0;
        for (size_t i = 0; i < image.rgba.size(); i += 4) {
            count += image.rgba[i] > image.rgba[i + 1] + 60;
        }
        return count;
    };
    EXPECT_EQ(reddish(services_->shownImage(state_, state_, width, height)), 0);
    state_.pbrOverlay = true;
    EXPECT_GT(reddish(services_->shownImage(state_, state_, width, height)), 1000) << "the flagged pixels striped red";
}

// Issue 23: the exposure slider was 110 pixels for 16 stops, so 60 pixels moved 8 EV. A drag
// moves it in fine steps (0.02 EV a pixel), one undo step a drag.
TEST_F(EditorUi, ExposureDragsInFineSteps) {
    const ImVec2 from = centreOf("Exposure");
    drag(from, ImVec2(from.x + 60.0f, from.y));
    EXPECT_GT(state_.scene.display.exposure, 0.5f);
    EXPECT_LT(state_.scene.display.exposure, 2.0f);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.display.exposure, 0.0f);
}

// The tone map list offers every view transform under the names scene files and render
// --tonemap use; a choice changes the picture, and undo takes it back.
TEST_F(EditorUi, TheToneMapListOffersEveryViewTransform) {
    const LdrImage before = services_->viewportPixels(EditorServices::Shown::Edited);
    click(centreOf("Tone map"));
    ImVec2 min, max;
    for (const Tonemap tonemap : kTonemaps) {
        EXPECT_TRUE(itemRect("tonemap:" + std::string(tonemapName(tonemap)), &min, &max)) << tonemapName(tonemap);
    }
    click(centreOf("tonemap:agx"));
    EXPECT_EQ(state_.scene.display.tonemap, Tonemap::Agx);
    frames(2);
    EXPECT_GT(differingPixels(before, services_->viewportPixels(EditorServices::Shown::Edited)), 1000);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.display.tonemap, Tonemap::PbrNeutral);
}

// Issue 37: the Ground list offers its three names; the floor and a light's Shadows checkbox
// each change the picture (the sphere's shadow falls on the floor), and undo takes each back.
TEST_F(EditorUi, TheGroundListAndALightsShadowsCheckboxChangeThePictureAndUndo) {
    const LdrImage before = services_->viewportPixels(EditorServices::Shown::Edited);
    click(centreOf("Ground plane"));
    ImVec2 min, max;
    for (const Ground ground : kGrounds) {
        EXPECT_TRUE(itemRect("ground:" + std::string(groundName(ground)), &min, &max)) << groundName(ground);
    }
    click(centreOf("ground:floor"));
    ASSERT_EQ(state_.scene.display.ground, Ground::Floor);
    frames(2);
    const LdrImage floor = services_->viewportPixels(EditorServices::Shown::Edited);
    EXPECT_GT(differingPixels(before, floor), 1000);
    state_.selectedLight = 1;   // the cool fill, directional
    frames(2);
    click(centreOf("Light shadows"));
    ASSERT_TRUE(state_.scene.lights[1].shadows);
    frames(2);
    EXPECT_GT(differingPixels(floor, services_->viewportPixels(EditorServices::Shown::Edited)), 200);
    EXPECT_TRUE(state_.error.empty()) << state_.error;
    press(kKeyZ, true);
    EXPECT_FALSE(state_.scene.lights[1].shadows);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.display.ground, Ground::None);
}

// Issue 37 item 2: the Ambient occlusion checkbox beside the Ground list bakes the sphere's
// occlusion and its floor's (the floor darkens under the sphere), and undo takes it back.
TEST_F(EditorUi, TheAmbientOcclusionCheckboxDarkensTheFloorUnderTheSphereAndUndoes) {
    click(centreOf("Ground plane"));
    click(centreOf("ground:floor"));
    ASSERT_EQ(state_.scene.display.ground, Ground::Floor);
    frames(2);
    const LdrImage floor = services_->viewportPixels(EditorServices::Shown::Edited);
    click(centreOf("Ambient occlusion"));
    ASSERT_TRUE(state_.scene.display.ambientOcclusion);
    // Baked on a worker: the frames go on meanwhile, and the one after it ends shows it.
    for (int i = 0; i < 500 && !state_.occlusion; ++i) {
        frames(1);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_TRUE(state_.occlusion);
    EXPECT_FALSE(state_.occlusionBake);
    frames(1);
    EXPECT_TRUE(state_.occlusion->withGround);
    const LdrImage occluded = services_->viewportPixels(EditorServices::Shown::Edited);
    EXPECT_GT(differingPixels(floor, occluded), 500);
    EXPECT_TRUE(state_.error.empty()) << state_.error;
    press(kKeyZ, true);
    EXPECT_FALSE(state_.scene.display.ambientOcclusion);
    frames(2);
    EXPECT_FALSE(state_.occlusion);
    EXPECT_EQ(differingPixels(floor, services_->viewportPixels(EditorServices::Shown::Edited)), 0);
}

// A model opened is framed as model-viewer frames it, wherever the camera looked before; the
// Camera list offers that framing and the file's own cameras (an orthographic one listed,
// dimmed, not taken), and the field of view drags.
TEST_F(EditorUi, TheCameraListTakesTheModelsCamerasAndTheFieldOfViewDrags) {
    test::GltfBuilder model = test::twoQuadsAndTheirCameras();
    model.writeGltf(path("quads.gltf"));
    EXPECT_EQ(currentCameraName(state_, state_), "the scene's");
    orbitCamera(state_.scene.camera, 1.2f, 0.4f);   // from the side and above
    EXPECT_EQ(currentCameraName(state_, state_), "free");
    ASSERT_TRUE(openFile(state_, path("quads.gltf"))) << state_.error;
    frames(2);
    Camera expected = state_.scene.camera;
    frameAsModelViewer(expected, meshBounds(state_));
    EXPECT_EQ(state_.scene.camera, expected) << "framed from the front";
    EXPECT_EQ(currentCameraName(state_, state_), kFrontCamera);
    const LdrImage framed = services_->viewportPixels(EditorServices::Shown::Edited);

    click(centreOf("Camera"));
    ASSERT_TRUE(itemsOfLastFrame().count("camera:3"));
    EXPECT_TRUE(itemsOfLastFrame().at("camera:3").dimmed) << "the orthographic camera";
    EXPECT_FALSE(itemsOfLastFrame().at("camera:2").dimmed);
    click(centreOf("camera:2"));   // "right", the file's camera 1
    ASSERT_TRUE(state_.model);
    expected = state_.scene.camera;
    placeModelCamera(expected, state_.model->cameras[1], meshBounds(state_));
    EXPECT_EQ(state_.scene.camera, expected);
    EXPECT_EQ(currentCameraName(state_, state_), "right");
    EXPECT_EQ(state_.status, "Camera: right");
    frames(2);
    const LdrImage right = services_->viewportPixels(EditorServices::Shown::Edited);
    EXPECT_GT(differingPixels(framed, right), 1000);
    const size_t centre = (size_t(right.height / 2) * size_t(right.width) + size_t(right.width / 2)) * 4;
    EXPECT_GT(right.rgba[centre + 1], right.rgba[centre]) << "the green quad fills the middle";

    const float fov = state_.scene.camera.fovYDegrees;
    const ImVec2 from = centreOf("FOV");
    drag(from, ImVec2(from.x + 50.0f, from.y));
    EXPECT_NEAR(state_.scene.camera.fovYDegrees, fov + 10.0f, 2.0f) << "0.2 degrees a pixel";
    EXPECT_EQ(currentCameraName(state_, state_), "free");
    frames(2);
    EXPECT_GT(differingPixels(right, services_->viewportPixels(EditorServices::Shown::Edited)), 1000);

    click(centreOf("Camera"));
    click(centreOf("camera:0"));
    expected = state_.scene.camera;
    frameAsModelViewer(expected, meshBounds(state_));
    EXPECT_EQ(state_.scene.camera, expected) << "the front again, at the field of view now set";
}

// Issue 23: Escape did not close the F1 help; it does, as any help window.
TEST_F(EditorUi, EscapeClosesTheShortcuts) {
    press(kKeyF1);
    ASSERT_TRUE(state_.showShortcuts);
    EXPECT_TRUE(itemsOfLastFrame().contains("shortcuts"));
    press(kKeyEscape);
    EXPECT_FALSE(state_.showShortcuts);
    EXPECT_FALSE(itemsOfLastFrame().contains("shortcuts"));
}

// Issue 23: a new tube light appeared above the view, and a directional light's handle could
// be dragged out of the viewport, out of reach. New lights start in view, wherever the camera
// looks from, and a handle dragged past the picture's edge stays on it.
TEST_F(EditorUi, NewLightsStartInViewAndHandlesStayOnThePicture) {
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("viewport", &min, &max));
    auto inView = [&](const std::string& name) {
        const auto items = itemsOfLastFrame();
        const auto it = items.find(name);
        return it != items.end() && it->second.min.x >= min.x && it->second.min.y >= min.y &&
               it->second.max.x <= max.x && it->second.max.y <= max.y;
    };
    click(centreOf("Add tube"));
    const std::string tube = "gizmo:" + std::to_string(state_.scene.lights.size() - 1);
    EXPECT_TRUE(inView(tube)) << "the tube's middle";
    EXPECT_TRUE(inView(tube + " start"));
    EXPECT_TRUE(inView(tube + " end"));

    // The camera orbited far round: a new point light is in view all the same.
    orbitCamera(state_.scene.camera, 2.5f, 0.6f);
    click(centreOf("Add point"));
    EXPECT_TRUE(inView("gizmo:" + std::to_string(state_.scene.lights.size() - 1)));

    click(centreOf("Add directional"));
    const std::string arrow = "gizmo:" + std::to_string(state_.scene.lights.size() - 1);
    ASSERT_TRUE(inView(arrow));
    for (const ImVec2 away : {ImVec2(min.x - 400.0f, min.y - 300.0f), ImVec2(max.x + 300.0f, (min.y + max.y) / 2)}) {
        const Camera camera = state_.scene.camera;
        const glm::vec3 direction = state_.scene.lights.back().direction;
        drag(centreOf(arrow), away);
        EXPECT_EQ(state_.scene.camera, camera) << "the handle was held, not the view";
        EXPECT_NE(state_.scene.lights.back().direction, direction);
        EXPECT_TRUE(inView(arrow)) << "the handle is still on the picture";
    }
    // A point light's dot, dragged below the picture, stays on it too.
    const std::string dot = "gizmo:" + std::to_string(state_.scene.lights.size() - 2);
    drag(centreOf(dot), ImVec2(centreOf(dot).x, max.y + 200.0f));
    EXPECT_TRUE(inView(dot));
}

// Issue 23: presets could not be searched, renamed or deleted. The search box narrows the
// browser; a right-click on one of the user's presets renames it (a taken name is said in the
// prompt, which stays) or deletes it after asking.
TEST_F(EditorUi, PresetsAreSearchedRenamedAndDeletedFromTheBrowser) {
    state_.userPresetFolder = dir_ / "presets";
    state_.presetFolders = {state_.userPresetFolder};
    std::filesystem::create_directories(state_.userPresetFolder);
    for (const char* name : {"copper", "brick", "gold"}) {
        Material material;
        material.name = name;
        saveMaterialFile(state_.userPresetFolder / (std::string(name) + ".json"), material);
    }
    frames(2);
    ImGuiIO& io = ImGui::GetIO();
    auto type = [&](const std::string& text) {
        for (char c : text) {
            io.AddInputCharacter(static_cast<unsigned>(c));
        }
        frames(2);
    };
    click(centreOf("preset search"));
    type("OP");
    EXPECT_EQ(state_.presets.filter, "OP");
    EXPECT_TRUE(itemsOfLastFrame().contains("preset:copper"));
    EXPECT_FALSE(itemsOfLastFrame().contains("preset:brick"));
    click(centreOf("viewport"));   // the field lets go of the keys, and then it is emptied
    state_.presets.filter.clear();
    frames(2);
    ASSERT_TRUE(itemsOfLastFrame().contains("preset:brick"));

    auto rightClick = [&](const std::string& item) {
        io.MousePos = centreOf(item);
        frames(1);
        io.MouseDown[1] = true;
        frames(1);
        io.MouseDown[1] = false;
        frames(2);
    };
    rightClick("preset:copper");
    click(centreOf("preset:rename"));
    ASSERT_EQ(state_.presets.renaming, state_.userPresetFolder / "copper.json");
    io.KeyMap[ImGuiKey_A] = 'A';
    io.KeyCtrl = io.KeysDown[int('A')] = true;   // the field has the keys: Ctrl+A, then the name
    frames(1);
    io.KeyCtrl = io.KeysDown[int('A')] = false;
    type("brick");
    click(centreOf("preset prompt:confirm"));
    EXPECT_NE(state_.presets.problem.find("already there"), std::string::npos) << state_.presets.problem;
    EXPECT_TRUE(itemsOfLastFrame().contains("preset:new name")) << "the prompt stays, saying why";
    state_.presets.newName = "old penny";
    click(centreOf("preset prompt:confirm"));
    EXPECT_TRUE(state_.presets.renaming.empty()) << state_.presets.problem;
    frames(2);
    EXPECT_TRUE(itemsOfLastFrame().contains("preset:old penny"));
    EXPECT_FALSE(std::filesystem::exists(state_.userPresetFolder / "copper.json"));

    rightClick("preset:brick");
    click(centreOf("preset:delete"));
    click(centreOf("preset prompt:cancel"));
    EXPECT_TRUE(std::filesystem::exists(state_.userPresetFolder / "brick.json")) << "Cancel deletes nothing";
    rightClick("preset:brick");
    click(centreOf("preset:delete"));
    click(centreOf("preset prompt:confirm"));
    frames(2);
    EXPECT_FALSE(itemsOfLastFrame().contains("preset:brick"));
    EXPECT_TRUE(std::filesystem::exists(state_.userPresetFolder / "brick.json.bak"));
    EXPECT_TRUE(state_.error.empty()) << state_.error;
}

}  // namespace
}  // namespace patina::editor
