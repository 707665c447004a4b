#pragma once
#include <filesystem>
#include <list>
#include <map>
#include <memory>
#include <optional>

#include "gl/renderer.h"
#include "accuracy/accuracy.h"
#include "accuracy/albedo_curve.h"
#include "state/editor_state.h"
#include "gl/texture.h"
#include "picture/pbr_tally.h"
#include "reference/pixel_story.h"
#include "scene/render_inputs.h"
#include "window/keys.h"

namespace patina::editor {

// The current material's error against reference and fp32's against fp64 (accuracy_panel.cpp).
struct AccuracyNumbers {
    ErrorStats physical;
    ErrorStats implementation;
};
AccuracyNumbers accuracyOf(const Material& material);

// How a picture of the viewport is drawn: its size, the render path and MSAA samples, and the
// Interaction's choices of how the environment is shaded and which debug channel shows. Handed
// over with each draw, so that what the services draw is never a copy left from another frame.
struct PictureRequest {
    int width = 0, height = 0;
    RenderPath path = RenderPath::Single;
    int samples = 4;
    EnvironmentShading environment;
    ChannelRequest channel;   // channel -1: the picture
    bool operator==(const PictureRequest&) const = default;
};

// What panels need beyond EditorState: the renderer (a current GL context is assumed) and its
// caches. Rendering happens here only when what it shows changed; what it draws comes
// prepared (EditorState's mesh and environment), and its own preview scenes are prepared
// through `assets`, the editor's cache (Jobs::assets).
class EditorServices {
public:
    explicit EditorServices(std::shared_ptr<AssetCache> assets);

    // What the viewport shows: the material being edited, or the comparison's A. Each has its
    // own render target, and offscreen renders (screenshots, thumbnails, exports) another, so
    // none of them replaces a texture the current UI frame already shows.
    enum class Shown { Edited, A };
    // The display texture of `scene` as `request` asks for it for `shown`, re-rendered only when
    // the scene or the request changed since its last render. Returns the GL texture.
    unsigned viewportTexture(const PreparedScene& scene, const PictureRequest& request, Shown shown);
    // View > PBR validation overlay over what viewportTexture(..., shown) shows: the pbr-validation
    // channel of `scene` at the request's size (ranges as its `channel.strictPbr` says) as a
    // texture, rows top-down, its flagged pixels striped in their verdict's colour and the rest
    // clear, and its tally; rendered only when the scene or size changed.
    struct PbrOverlay {
        std::unique_ptr<Texture> texture;
        PbrTally tally;
    };
    const PbrOverlay& pbrOverlay(const PreparedScene& scene, const PictureRequest& request, Shown shown);
    // What the status line counts: the edited picture's pbr-validation tally while the overlay or
    // the channel shows it (the viewport sets it each frame), else nothing.
    std::optional<PbrTally> pbrTally;
    // The pbr-validation tally of what viewportTexture last drew for `shown`, when that was
    // the channel.
    std::optional<PbrTally> channelPbrTally(Shown shown) const { return view(shown).pbrTally; }

    double lastRenderMilliseconds() const { return lastRenderMilliseconds_; }
    double lastGpuMilliseconds() const { return lastGpuMilliseconds_; }
    int viewportWidth = 0, viewportHeight = 0;   // set by the viewport panel
    KeyPresses keyPresses;                        // this frame's, filled by the app (or a test)

    // The inspector's read-out of pixel (x, y) of a width x height picture of `scene`
    // (reference/pixel_story.h): null on the background or outside. The surfaces under the
    // picture are rasterised on the CPU once per scene and size, so hovering costs nothing more.
    const PixelStory* pixelStory(const PreparedScene& scene, int width, int height, int x, int y);

    // What the viewport shows for `shown`, read back (for tests and automation).
    LdrImage viewportPixels(Shown shown) const { return renderer_->readBack(view(shown).target, false).ldr; }

    // Renders `scene` at the given size offscreen, the environment shaded as `environment` says,
    // and returns the image (for screenshots, thumbnails and exports); what the viewport shows
    // is untouched.
    RenderOutput renderImage(const PreparedScene& scene, int width, int height, RenderPath passes,
                             const EnvironmentShading& environment, const ChannelRequest& channel = {});

    // A material file's thumbnail, rendered in the fixed preview scene (preview_scene.h, its
    // environment shaded by the split sum) once per file modification time, and its material's
    // name; null for a file that does not read.
    struct Preset {
        std::unique_ptr<Texture> texture;
        std::string name;
    };
    const Preset* preset(const std::filesystem::path& material);

    // Image `image` of `model` shrunk to a thumbnail (at most 160 pixels a side), made once per
    // image while the model is the one asked about; null for an image the model lacks.
    const Texture* mapThumbnail(const std::shared_ptr<const Model>& model, int image);

    // A panorama of the environment's image (equirectPreview), made once per environment.
    const Texture* environmentThumbnail(const std::shared_ptr<const Environment>& environment);

    // accuracyOf(material), recomputed only when the material changes.
    const AccuracyNumbers& accuracy(const Material& material);
    // The lobe panel's directional albedo of `material` against theta_v beside its ground truth
    // (accuracy/albedo_curve.h), kept for the last few materials asked about: the ground truth
    // takes milliseconds, too long to redo every frame of a slider drag for a material that did
    // not change. A curve stays where it is while it is kept (A's and B's are drawn together).
    const std::vector<AlbedoPoint>& albedo(const MaterialParameters& material);
    // The bench chart PNG as a texture, reloaded when the file changes; null when there is none.
    const Texture* benchChart(const std::filesystem::path& png);

    // What the viewport shows, at width x height: the edited material alone; or A and B side
    // by side, each half as wide and captioned; or A left of the split and B right of it,
    // with the divider and labels.
    LdrImage shownImage(const Document& document, const Interaction& interaction, int width, int height);
    // Screenshot of what the viewport shows (shownImage) with the scene embedded, in the
    // preferences' screenshot folder; returns the file written, and says so (or why not).
    std::optional<std::filesystem::path> screenshot(const Document& document, const Interaction& interaction,
                                                    const Preferences& preferences, Prompts& prompts, int width,
                                                    int height);
    // A and B side by side with captions; returns the file written.
    std::optional<std::filesystem::path> exportComparison(const Document& document, const Interaction& interaction,
                                                          Prompts& prompts, const std::filesystem::path& path);

private:
    struct ViewKey {
        RenderInputs inputs;   // what the image depends on: no names or unknown keys compared
        PictureRequest request;
        bool operator==(const ViewKey&) const = default;
    };
    struct ViewImage {
        RenderTarget target;
        std::optional<ViewKey> drawn;   // what the target holds
        std::optional<PbrTally> pbrTally;   // when it holds the pbr-validation channel
    };
    struct OverlayImage {
        ViewImage channel;   // the pbr-validation channel, drawn
        PbrOverlay overlay;  // made from it
    };
    OverlayImage overlays_[2];   // by Shown
    std::shared_ptr<AssetCache> assets_;
    std::unique_ptr<Renderer> renderer_;
    struct ReadOut {
        struct Key {
            RenderInputs inputs;
            int width = 0, height = 0;
            bool operator==(const Key&) const = default;
        };
        std::optional<Key> key;   // the scene and size the surfaces are of
        std::optional<PixelSurfaces> surfaces;
        int x = -1, y = -1;
        std::optional<PixelStory> story;   // of (x, y)
    } readOut_;
    ViewImage views_[2];   // by Shown
    double lastRenderMilliseconds_ = 0.0, lastGpuMilliseconds_ = 0.0;
    struct Thumbnail {
        std::filesystem::file_time_type modified;
        std::unique_ptr<Texture> texture;
    };
    struct PresetEntry {
        std::filesystem::file_time_type modified;
        std::optional<Preset> preset;
    };
    std::map<std::filesystem::path, PresetEntry> presets_;
    std::optional<std::pair<Material, AccuracyNumbers>> accuracy_;
    std::list<std::pair<MaterialParameters, std::vector<AlbedoPoint>>> albedoCurves_;   // the latest first
    Thumbnail benchChart_;
    std::pair<std::shared_ptr<const Environment>, std::unique_ptr<Texture>> environmentThumbnail_;
    std::shared_ptr<const Model> thumbnailModel_;   // held, so another model at its address is not taken for it
    std::map<int, std::unique_ptr<Texture>> mapThumbnails_;   // thumbnailModel_'s, by image

    // B (the edited material, solo applied) or, with `a`, A in its place, at width x height, drawn as
    // the interaction asks (render path, environment shading).
    LdrImage sideImage(const Document& document, const Interaction& interaction, const Material* a, int width,
                       int height);
    // A and B, each halfWidth x height, side by side with their captions.
    LdrImage comparisonImage(const Document& document, const Interaction& interaction, int halfWidth, int height);
    ViewImage& view(Shown shown) { return views_[shown == Shown::A ? 1 : 0]; }
    const ViewImage& view(Shown shown) const { return views_[shown == Shown::A ? 1 : 0]; }
};

}  // namespace patina::editor
