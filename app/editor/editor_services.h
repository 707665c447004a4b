#pragma once
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include "gl/renderer.h"
#include "accuracy.h"
#include "editor_state.h"
#include "gl/texture.h"
#include "keys.h"

namespace patina::editor {

// The current material's error against reference and fp32's against fp64 (accuracy_panel.cpp).
struct AccuracyNumbers {
    ErrorStats physical;
    ErrorStats implementation;
};
AccuracyNumbers accuracyOf(const Material& material);

// What panels need beyond EditorState: the renderer (a current GL context is assumed) and its
// caches. Rendering happens here only when what it shows changed.
class EditorServices {
public:
    EditorServices();

    // The display texture of `scene` at `size` in `slot`, re-rendered only when the scene,
    // size, pass mode or MSAA samples changed since that slot's last render. Returns the GL
    // texture name.
    unsigned viewportTexture(const Scene& scene, int width, int height, PassMode passes, int slot,
                             int samples = 4);
    double lastRenderMilliseconds() const { return lastRenderMilliseconds_; }
    double lastGpuMilliseconds() const { return lastGpuMilliseconds_; }
    int viewportWidth = 0, viewportHeight = 0;   // set by the viewport panel
    KeyPresses keyPresses;                        // this frame's, filled by the app (or a test)

    // What the viewport shows in `slot`, read back (for tests and automation).
    LdrImage viewportPixels(int slot) const { return renderer_->readBack(slot, false).ldr; }

    // The mesh the next draw of a scene with this meshFile uses (the editor imports it once,
    // in openFile, and hands it over here).
    void provideMesh(const std::string& meshFile, const Mesh& mesh);

    // Renders `scene` at the given size and returns the image (for screenshots and exports).
    RenderOutput renderImage(const Scene& scene, int width, int height, PassMode passes);

    // Thumbnails of material files, rendered once per file modification time.
    const Texture* thumbnail(const std::filesystem::path& material, const Scene& scene);

    // accuracyOf(material), recomputed only when the material changes.
    const AccuracyNumbers& accuracy(const Material& material);
    // The bench chart PNG as a texture, reloaded when the file changes; null when there is none.
    const Texture* benchChart(const std::filesystem::path& png);

    // Screenshot of the current view with the scene embedded; returns the file written.
    std::optional<std::filesystem::path> screenshot(EditorState& state, int width, int height);
    // A and B side by side with captions; returns the file written.
    std::optional<std::filesystem::path> exportComparison(EditorState& state, const std::filesystem::path& path);

private:
    struct SlotKey {
        Scene scene;
        int width = 0, height = 0;
        PassMode passes = PassMode::Single;
        int samples = 4;
        bool operator==(const SlotKey&) const = default;
    };
    std::unique_ptr<Renderer> renderer_;
    MeshKind mesh_ = MeshKind::Sphere;
    std::string meshFile_;
    std::optional<SlotKey> slots_[Renderer::kSlots];
    unsigned slotTextures_[Renderer::kSlots] = {};
    double lastRenderMilliseconds_ = 0.0, lastGpuMilliseconds_ = 0.0;
    struct Thumbnail {
        std::filesystem::file_time_type modified;
        std::unique_ptr<Texture> texture;
    };
    std::map<std::filesystem::path, Thumbnail> thumbnails_;
    std::optional<std::pair<Material, AccuracyNumbers>> accuracy_;
    Thumbnail benchChart_;

    // The renderer's mesh for `scene` (a glTF arrives through provideMesh, read once).
    void useMesh(const Scene& scene);
    void replaceMesh(const Mesh& mesh, MeshKind kind, const std::string& meshFile);
};

}  // namespace patina::editor
