#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string_view>

#include "gl/environment_method.h"
#include "gl/render_path.h"
#include "gl/shader_specialisation.h"
#include "gl/shadow_settings.h"
#include "common/hdr_image.h"
#include "common/ldr_image.h"
#include "geometry/mesh.h"
#include "scene/channel.h"
#include "scene/prepared_scene.h"
#include "shading/shading.h"

namespace patina {

class GlProgram;
struct RenderTargets;

// The images a draw writes into, owned by whoever shows or reads them: the viewport, each side
// of a comparison, a screenshot. Drawing into one never touches another's textures, so a
// texture a UI frame already refers to stays valid while other images are rendered. Needs the
// GL context of the renderer that draws into it for its whole life.
class RenderTarget {
public:
    RenderTarget();
    ~RenderTarget();
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    // The last draw's display texture (GL_RGBA8, sRGB-encoded, GL's bottom-up rows); 0 before
    // the first. Valid until this target is drawn again at another size.
    unsigned displayTexture() const;

private:
    friend class Renderer;
    std::unique_ptr<RenderTargets> images_;
};

// The multisampled colour a one-off render (a file written, a screenshot) may take before it is
// drawn in strips (RenderSettings::maxTargetBytes): its peak memory stays low at any size the
// GL allows. Without it an 8192 x 8192 screenshot asked llvmpipe for 4 GiB at once and failed.
inline constexpr size_t kOneOffTargetBytes = size_t(16) << 20;

struct RenderSettings {
    int width = 800;
    int height = 800;
    RenderPath path = RenderPath::Single;
    int samples = 4;   // MSAA; clamped to what the implementation offers
    // Most bytes the multisampled colour target may take; a larger image is drawn in strips
    // of rows that fit, each resolved into place (the same pixels: the viewport only moves).
    // 0: no limit. Strips trade memory for vertex work (the mesh is drawn once per strip), so
    // there are never more than 16: past that the strips grow beyond the budget.
    size_t maxTargetBytes = 0;
    // Keep the linear image, for readBack(target, true) (and render() reads it back). Without it
    // no full-size linear image is written at all, which saves a pass's memory and bandwidth.
    bool readHdr = true;
    // With MSAA, shade and resolve only the pixels the mesh can cover (its bounding box on
    // screen); the rest is background, filled without samples. false: every pixel, the
    // same image (for tests).
    bool cropToMesh = true;
    // Specialised (and the floor): take the first lights as flat inputs from the vertex stage
    // where that pays for this mesh and image (flatLightsPay, shader_specialisation.h), always,
    // or never. The image is the same to rounding.
    enum class FlatLights { WherePaying, Always, Never };
    FlatLights flatLightUse = FlatLights::WherePaying;
    // Skip the faces of a closed mesh that no eye outside it can see (hidden_faces.h) where
    // this camera is outside it: the same image from fewer fragments. llvmpipe with MSAA
    // shades a fragment that fails the depth test all the same. false: every face (for tests).
    bool cullHiddenFaces = true;
    // Specialised only: the light code to compile, from the enabled lights as packed and the
    // number taken as flat inputs, instead of specialiseFor's; for callers that write their
    // own (bench/'s BRDF-only floor). Empty: the scene's.
    std::function<ShaderSpecialisation(const std::vector<shader::PackedLight>&, size_t flatSlots)> lightCode;
    // How the scene's environment is shaded: the split sum, or a variant docs/LIGHTING.md
    // measures against it.
    EnvironmentShading environment;
    // The inspector: a debug channel (scene/channel.h) written instead of the radiance, by the
    // single path with one sample a pixel whatever `path` and `samples` say, every item opaque, the
    // environment by the split sum. The display image then holds the channel as channels.glsl's
    // shownChannel shows it (no exposure or tone map), the background as a value of 0.
    ChannelRequest channel;
    // The shadowed lights' maps: their resolution and bias (docs/LIGHTING.md section 6). The
    // defaults are every render's; the shadow measurement varies them.
    ShadowMapSettings shadowMaps;
};

struct RenderOutput {
    HdrImage hdr;   // linear radiance, before exposure and tone map (MSAA resolved)
    LdrImage ldr;   // after the display transform, sRGB
};

// Draws prepared scenes (scene/prepared_scene.h), each with its own draw items (sceneDraws: a
// model's primitives, each where its transform puts it with its own material, or the one mesh)
// and environment, with the shared shaders; it loads and prefilters nothing itself. Needs a
// current OpenGL 3.3 core context (a HeadlessContext or the editor's window) for its whole life.
class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // How many lights a specialised shader takes as flat inputs (shader_specialisation.h).
    size_t flatLightSlots() const;
    // The specialised programs compiled and kept (for tests and benchmarks).
    size_t specialisedProgramCount() const;
    // Renders into `target` and returns its display texture (RenderTarget::displayTexture).
    // Leaves framebuffer 0 bound. Throws std::invalid_argument for a size (of the image or of
    // the shadow maps) outside [1, max size], a negative or non-finite shadow bias,
    // or a prepared scene without the mesh or the environment its document names (or whose
    // model's items name what it lacks).
    unsigned draw(const PreparedScene& scene, const RenderSettings& settings, RenderTarget& target);
    // The same into the renderer's own target (for render(), benchmarks and tests).
    unsigned draw(const PreparedScene& scene, const RenderSettings& settings) { return draw(scene, settings, own_); }
    // The last draw into `target`, read back to the CPU with rows top to bottom (empty if never
    // drawn); without `hdr`, RenderOutput::hdr stays empty. Throws std::logic_error for `hdr`
    // when the draw did not keep it (RenderSettings::readHdr).
    RenderOutput readBack(const RenderTarget& target, bool hdr = true) const;
    RenderOutput readBack(bool hdr = true) const { return readBack(own_, hdr); }
    // GPU time of the most recent draw whose timer queries have completed (two GL_TIMESTAMPs,
    // read without waiting), in milliseconds; negative before the first. On llvmpipe, where
    // the rasteriser is the "GPU", it runs from the start of the draw's binning to the end of
    // its rasterisation, close to the draw's wall time.
    double lastGpuMilliseconds();
    // draw into the renderer's own target and wait for it: the GPU time of that draw in milliseconds (for
    // benchmarks; it stalls the pipeline).
    double timedDraw(const PreparedScene& scene, const RenderSettings& settings);
    // draw + readBack of the renderer's own target.
    RenderOutput render(const PreparedScene& scene, const RenderSettings& settings);

private:
    struct State;
    struct Frame;   // one draw, strip by strip (renderer.cpp)
    std::unique_ptr<State> state_;
    RenderTarget own_;
    // Uploads the prepared scene's primitives (its model's, or its one mesh) unless they are
    // the ones drawn last.
    static void uploadShape(State& s, const PreparedScene& prepared);
};

}  // namespace patina
