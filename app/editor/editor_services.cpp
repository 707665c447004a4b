#include "editor_services.h"

#include <chrono>
#include <ctime>

#include "compositing.h"
#include "png_text.h"
#include "scene_file.h"

namespace patina::editor {

namespace {
// "patina-<material>-YYYYmmdd-HHMMSS.png" in `folder`, the name reduced to file-safe
// characters; "-2", "-3", ... when that second already has a screenshot.
std::filesystem::path screenshotPath(const std::filesystem::path& folder, const std::string& material) {
    std::string safe;
    for (char c : material) {
        safe += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
    }
    const std::time_t now = std::time(nullptr);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", std::localtime(&now));
    const std::string stem = "patina-" + (safe.empty() ? "material" : safe) + "-" + stamp;
    std::filesystem::path path = folder / (stem + ".png");
    for (int n = 2; std::filesystem::exists(path); ++n) {
        path = folder / (stem + "-" + std::to_string(n) + ".png");
    }
    return path;
}
}  // namespace

EditorServices::EditorServices() : renderer_(std::make_unique<Renderer>()) {}

void EditorServices::useMesh(const Scene& scene) {
    // A file mesh is the same whatever the built-in kind says; a built-in one is its kind.
    const bool same = scene.meshFile == meshFile_ && (!meshFile_.empty() || scene.mesh == mesh_);
    if (!same) {
        replaceMesh(makeMesh(scene), scene.mesh, scene.meshFile);
    }
}

void EditorServices::provideMesh(const std::string& meshFile, const Mesh& mesh) {
    replaceMesh(mesh, mesh_, meshFile);
}

void EditorServices::replaceMesh(const Mesh& mesh, MeshKind kind, const std::string& meshFile) {
    renderer_->setMesh(mesh);
    mesh_ = kind;
    meshFile_ = meshFile;
    for (auto& slot : slots_) {
        slot.reset();
    }
}

unsigned EditorServices::viewportTexture(const Scene& scene, int width, int height, PassMode passes,
                                         int slot, int samples) {
    useMesh(scene);
    SlotKey key{scene, width, height, passes, samples};
    if (slots_[slot] != key) {
        RenderSettings settings;
        settings.width = width;
        settings.height = height;
        settings.passes = passes;
        settings.samples = samples;
        settings.readHdr = false;   // the viewport shows and saves the display image only
        const auto start = std::chrono::steady_clock::now();
        slotTextures_[slot] = renderer_->draw(scene, settings, slot);
        lastRenderMilliseconds_ =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        slots_[slot] = std::move(key);
    }
    lastGpuMilliseconds_ = renderer_->lastGpuMilliseconds();
    return slotTextures_[slot];
}

RenderOutput EditorServices::renderImage(const Scene& scene, int width, int height, PassMode passes) {
    useMesh(scene);
    RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.passes = passes;
    settings.readHdr = false;   // thumbnails, screenshots and comparisons use the display image
    // Slot 0 is the viewport's: it must be drawn again afterwards.
    slots_[0].reset();
    return renderer_->render(scene, settings);
}

const Texture* EditorServices::thumbnail(const std::filesystem::path& material, const Scene& scene) {
    std::error_code error;
    const auto modified = std::filesystem::last_write_time(material, error);
    if (error) {
        return nullptr;
    }
    Thumbnail& entry = thumbnails_[material];
    if (!entry.texture || entry.modified != modified) {
        std::vector<std::string> warnings;
        try {
            Scene preview = scene;
            preview.material = loadMaterialFile(material, warnings);
            entry.texture = std::make_unique<Texture>(renderImage(preview, 64, 64, PassMode::Single).ldr);
        } catch (const std::exception&) {
            entry.texture.reset();   // the browser shows the file without a picture
        }
        entry.modified = modified;
    }
    return entry.texture.get();
}

const AccuracyNumbers& EditorServices::accuracy(const Material& material) {
    if (!accuracy_ || accuracy_->first != material) {
        accuracy_ = std::pair{material, accuracyOf(material)};
    }
    return accuracy_->second;
}

const Texture* EditorServices::benchChart(const std::filesystem::path& png) {
    std::error_code error;
    const auto modified = std::filesystem::last_write_time(png, error);
    if (error) {
        return nullptr;
    }
    if (!benchChart_.texture || benchChart_.modified != modified) {
        try {
            benchChart_.texture = std::make_unique<Texture>(decodePng(readFileBytes(png)));
        } catch (const std::exception&) {
            benchChart_.texture.reset();
        }
        benchChart_.modified = modified;
    }
    return benchChart_.texture.get();
}

std::optional<std::filesystem::path> EditorServices::screenshot(EditorState& state, int width, int height) {
    try {
        const Scene scene = renderedScene(state);
        const RenderOutput image = renderImage(scene, width, height, state.passes);
        const std::filesystem::path path = screenshotPath(state.screenshotFolder, scene.material.name);
        writeFileAtomic(path, encodePngWithText(image.ldr, {{kSceneTextKeyword, sceneToJson(state.scene).dump()}}));
        state.status = "Screenshot " + path.string();
        return path;
    } catch (const std::exception& error) {
        state.error = "Screenshot failed: " + std::string(error.what());
        return std::nullopt;
    }
}

std::optional<std::filesystem::path> EditorServices::exportComparison(EditorState& state,
                                                                      const std::filesystem::path& path) {
    if (!state.compareA) {
        state.error = "Set A first: the comparison needs an A material.";
        return std::nullopt;
    }
    try {
        const int width = std::max(viewportWidth / 2, 64), height = std::max(viewportHeight, 64);
        const LdrImage a = renderImage(withMaterial(state, *state.compareA), width, height, state.passes).ldr;
        const LdrImage b = renderImage(renderedScene(state), width, height, state.passes).ldr;
        writeFileAtomic(path, encodePng(sideBySide(a, b, materialCaption(*state.compareA, width),
                                                   materialCaption(state.scene.material, width))));
        state.status = "Exported " + path.string();
        return path;
    } catch (const std::exception& error) {
        state.error = "Export failed: " + std::string(error.what());
        return std::nullopt;
    }
}

}  // namespace patina::editor
