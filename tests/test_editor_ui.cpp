// The editor's UI driven headlessly: Dear ImGui with synthetic mouse and keys, the engine
// renderer on the EGL context, no window.
#include <fstream>

#include <gtest/gtest.h>
#include <imgui.h>

#include "image.h"
#include "gltf_export.h"
#include "keys.h"
#include "panels.h"
#include "png_text.h"
#include "scratch_test.h"
#include "scene_file.h"
#include "test_support.h"
#include "widgets.h"

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
        unsigned char* pixels = nullptr;
        int width = 0, height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);   // builds the font atlas
        services_ = std::make_unique<EditorServices>();
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

    void drag(ImVec2 from, ImVec2 to, int steps = 8) {
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = from;
        frames(1);
        io.MouseDown[0] = true;
        frames(1);
        for (int i = 1; i <= steps; ++i) {
            io.MousePos = ImVec2(from.x + (to.x - from.x) * float(i) / float(steps),
                                 from.y + (to.y - from.y) * float(i) / float(steps));
            frames(1);
        }
        io.MouseDown[0] = false;
        frames(2);
    }

    void press(int key, bool ctrl = false, bool shift = false) {
        services_->keyPresses = {{key, ctrl, shift}};
        frames(1);
        services_->keyPresses.clear();
        frames(1);
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
    const LdrImage pixelsBefore = services_->viewportPixels(0);
    ImVec2 min, max;
    ASSERT_TRUE(itemRect("Roughness", &min, &max));
    drag(ImVec2(min.x + (max.x - min.x) * before, (min.y + max.y) * 0.5f),
         ImVec2(min.x + 4.0f, (min.y + max.y) * 0.5f));
    EXPECT_LT(state_.scene.material.roughness, 0.1f);
    frames(1);   // the full-quality render after release
    const LdrImage pixelsAfter = services_->viewportPixels(0);
    EXPECT_GT(differingPixels(pixelsBefore, pixelsAfter), 100);
    // The whole drag is one undo step.
    EXPECT_EQ(state_.history.undoSteps(), 1u);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.material.roughness, before);
    press(kKeyZ, true, true);   // Ctrl+Shift+Z redoes
    EXPECT_LT(state_.scene.material.roughness, 0.1f);
}

TEST_F(EditorUi, AddPointLightButtonAddsALight) {
    const size_t before = state_.scene.lights.size();
    click(centreOf("Add point"));
    ASSERT_EQ(state_.scene.lights.size(), before + 1);
    EXPECT_EQ(state_.scene.lights.back().type, LightType::Point);
    press(kKeyZ, true);
    EXPECT_EQ(state_.scene.lights.size(), before);
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

TEST_F(EditorUi, SetAThenSplitShowsBothMaterials) {
    click(centreOf("Set A"));
    ASSERT_TRUE(state_.compareA.has_value());
    EXPECT_EQ(state_.compareView, CompareView::Split);
    state_.scene.material.baseColor = {0.1f, 0.3f, 0.9f};   // B turns blue
    frames(2);
    const LdrImage a = services_->viewportPixels(1);
    const LdrImage b = services_->viewportPixels(0);
    const int centre = (a.height / 2 * a.width + a.width / 2) * 4;
    EXPECT_GT(int(a.rgba[size_t(centre)]), int(a.rgba[size_t(centre) + 2]));   // A is terracotta
    EXPECT_GT(int(b.rgba[size_t(centre) + 2]), int(b.rgba[size_t(centre)]));   // B is blue
    const std::filesystem::path exported = dir_ / "ab.png";
    ASSERT_TRUE(services_->exportComparison(state_, exported).has_value()) << state_.error;
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

TEST_F(EditorUi, UnsavedChangesAreNotDroppedWithoutAsking) {
    Material other;
    other.name = "other";
    std::ofstream(dir_ / "other.json") << materialToJson(other).dump();
    state_.presetFolders = {dir_};
    state_.scene.material.metallic = 0.7f;   // dirty
    frames(2);
    click(centreOf("preset:other"));
    EXPECT_TRUE(state_.pendingOpen.has_value());
    EXPECT_EQ(state_.scene.material.metallic, 0.7f);
    frames(2);
    click(centreOf("Discard changes"));
    EXPECT_EQ(state_.scene.material.name, "other");
}

}  // namespace
}  // namespace patina::editor

namespace patina::editor {
namespace {

TEST_F(EditorUi, ChoosingAModelChangesThePictureAndTheErrorNumbers) {
    const LdrImage epic = services_->viewportPixels(0);
    EXPECT_GT(services_->accuracy(state_.scene.material).physical.relativeRmse, 1e-3);
    state_.scene.material.model = BrdfModelId::Reference;
    frames(2);
    EXPECT_GT(differingPixels(epic, services_->viewportPixels(0)), 100);
    EXPECT_EQ(services_->accuracy(state_.scene.material).physical.relativeRmse, 0.0);
    press(kKeyZ, true);   // the model is part of the material: undoable
    EXPECT_EQ(state_.scene.material.model, BrdfModelId::Epic);
}

}  // namespace
}  // namespace patina::editor

namespace patina::editor {
namespace {

TEST_F(EditorUi, OpeningAGltfShowsItsMeshAndABadOneKeepsThePrevious) {
    const LdrImage sphere = services_->viewportPixels(0);
    Mesh torus = makeTorus();
    for (glm::vec3& p : torus.positions) {
        p = p * 3.0f + glm::vec3(10.0f, 0.0f, 0.0f);   // far from the origin: the camera must follow
    }
    exportGltf(path("torus.glb"), torus, Material{});
    ASSERT_TRUE(openFile(state_, path("torus.glb"))) << state_.error;
    frames(2);
    EXPECT_EQ(std::filesystem::path(state_.scene.meshFile).filename(), "torus.glb");
    EXPECT_NEAR(state_.scene.camera.target.x, 10.0f, 0.5f);   // framed on the model
    EXPECT_GT(differingPixels(sphere, services_->viewportPixels(0)), 1000);

    write("broken.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "../../etc/passwd", "byteLength": 4}]})");
    const std::string before = state_.scene.meshFile;
    EXPECT_FALSE(openFile(state_, path("broken.gltf")));
    EXPECT_FALSE(state_.error.empty());
    EXPECT_EQ(state_.scene.meshFile, before);

    // A scene naming a glTF brings its mesh; one naming a missing file fails and changes nothing.
    write("with-mesh.json", R"({"format": "patina-scene", "version": 1, "mesh": "torus.glb"})");
    ASSERT_TRUE(openFile(state_, path("with-mesh.json"))) << state_.error;
    EXPECT_TRUE(state_.importedMesh != nullptr);
    frames(1);
    write("missing-mesh.json", R"({"format": "patina-scene", "version": 1, "mesh": "gone.glb", "lights": []})");
    const EditSnapshot snapshot = state_.snapshot();
    EXPECT_FALSE(openFile(state_, path("missing-mesh.json")));
    EXPECT_NE(state_.error.find("gone.glb"), std::string::npos) << state_.error;
    EXPECT_EQ(state_.snapshot(), snapshot);
    EXPECT_EQ(std::filesystem::path(state_.scene.meshFile).filename(), "torus.glb");
}

}  // namespace
}  // namespace patina::editor
