#include "gl/renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <tuple>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "scene/ground.h"
#include "scene/light_packing.h"
#include "scene/view.h"
#include "gl/environment_texture.h"
#include "gl/frame_plan.h"
#include "gl/mesh_buffers.h"
#include "gl/model_textures.h"
#include "gl/occlusion_buffers.h"
#include "gl/program.h"
#include "gl/render_targets.h"
#include "gl/scene_behind.h"
#include "gl/shading_inputs.h"
#include "gl/shading_programs.h"
#include "gl/shadow_maps.h"

namespace patina {

namespace shader_sources {
extern const char* const mesh_vert;
extern const char* const black_frag;
extern const char* const texture_glsl;
extern const char* const surface_maps_glsl;
extern const char* const fullscreen_vert;
extern const char* const display_glsl;
extern const char* const display_frag;
extern const char* const brdf_glsl;
extern const char* const environment_glsl;
extern const char* const ibl_glsl;
extern const char* const background_frag;
}  // namespace shader_sources

namespace {
// Binds again, however the scope is left, the framebuffer that was bound when it began. A draw
// that threw halfway (a target the GL could not make) used to leave its own bound, and the
// editor's UI then drew into it: the window stopped repainting until another draw went through.
class FramebufferKept {
public:
    FramebufferKept() { glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound_); }
    ~FramebufferKept() { glBindFramebuffer(GL_FRAMEBUFFER, GLuint(bound_)); }
    FramebufferKept(const FramebufferKept&) = delete;
    FramebufferKept& operator=(const FramebufferKept&) = delete;

private:
    GLint bound_ = 0;
};

template <typename T>
void flipRows(std::vector<T>& values, size_t rowLength, int rows) {
    for (int y = 0; y < rows / 2; ++y) {
        std::swap_ranges(values.begin() + std::ptrdiff_t(size_t(y) * rowLength),
                         values.begin() + std::ptrdiff_t(size_t(y + 1) * rowLength),
                         values.begin() + std::ptrdiff_t(size_t(rows - 1 - y) * rowLength));
    }
}

// A program compiled on first use: a render that needs no pre-pass or display pass (no multi
// path, no MSAA) compiles neither.
class LazyProgram {
public:
    LazyProgram(std::vector<const char*> vertex, std::vector<const char*> fragment,
                std::vector<std::string> defines = {})
        : vertex_(std::move(vertex)), fragment_(std::move(fragment)), defines_(std::move(defines)) {}
    const GlProgram& get() {
        if (!program_) {
            program_ = std::make_unique<GlProgram>(vertex_, fragment_, defines_);
        }
        return *program_;
    }

private:
    std::vector<const char*> vertex_, fragment_;
    std::vector<std::string> defines_;
    std::unique_ptr<GlProgram> program_;
};
}  // namespace

// What a frame's shadow maps depend on, for the shape shown (a new one drops the key:
// uploadShape): each view, the maps' size and bias, where each opaque item stands, and a MASK
// item's alpha. Equal to the last frame's, the maps are kept: a material drag redrew a 2048 x
// 2048 map of the whole model every frame (a quarter of 2CylinderEngine's drag frame under a
// shadowed sun).
struct ShadowCasters {
    std::vector<glm::mat4> views;
    ShadowMapSettings maps;
    std::vector<std::tuple<const Mesh*, int, glm::mat4, bool, float, float, const ModelMaterial*>> items;
    bool operator==(const ShadowCasters&) const = default;
};

struct Renderer::State {
    ShadingPrograms shading;
    LazyProgram depthPrepass{{shader_sources::mesh_vert}, {shader_sources::black_frag}};
    // The same for a frame with maps: MASK's cut-outs lay down no depth.
    LazyProgram depthPrepassMaps{{shader_sources::mesh_vert},
                                 {shader_sources::texture_glsl, shader_sources::surface_maps_glsl,
                                  shader_sources::black_frag},
                                 {"PATINA_TEXTURED"}};
    // And with vertex colours, whose alpha cuts out too.
    LazyProgram depthPrepassColors{{shader_sources::mesh_vert},
                                   {shader_sources::texture_glsl, shader_sources::surface_maps_glsl,
                                    shader_sources::black_frag},
                                   {"PATINA_TEXTURED", "PATINA_VERTEX_COLOR"}};
    LazyProgram& prepass(bool maps, bool colors) {
        return colors ? depthPrepassColors : maps ? depthPrepassMaps : depthPrepass;
    }
    LazyProgram display{{shader_sources::fullscreen_vert}, {shader_sources::display_glsl, shader_sources::display_frag}};
    // With a shadow catcher over the flat background (display.frag's PATINA_CAUGHT_BACKGROUND).
    LazyProgram displayCaught{{shader_sources::fullscreen_vert},
                              {shader_sources::display_glsl, shader_sources::display_frag},
                              {"PATINA_CAUGHT_BACKGROUND"}};
    // By the sample count the GL made, and whether a catcher darkened the flat background.
    std::map<std::pair<int, bool>, LazyProgram> resolves;

    LazyProgram& resolve(int samples, bool caught) {
        auto found = resolves.find({samples, caught});
        if (found == resolves.end()) {
            const std::vector<const char*> vertex{shader_sources::fullscreen_vert};
            const std::vector<const char*> fragment{shader_sources::display_glsl, shader_sources::display_frag};
            std::vector<std::string> defines{"PATINA_MULTISAMPLED", "PATINA_SAMPLE_COUNT " + std::to_string(samples)};
            if (caught) {
                defines.push_back("PATINA_CAUGHT_BACKGROUND");
            }
            found = resolves.try_emplace(std::pair{samples, caught}, vertex, fragment, defines).first;
        }
        return found->second;
    }
    // The environment behind the mesh, by whether it writes display values too.
    std::map<bool, LazyProgram> backgrounds;
    LazyProgram& background(bool displayOutput) {
        auto found = backgrounds.find(displayOutput);
        if (found == backgrounds.end()) {
            const std::vector<const char*> fragment{shader_sources::brdf_glsl, shader_sources::environment_glsl,
                                                    shader_sources::ibl_glsl, shader_sources::display_glsl,
                                                    shader_sources::background_frag};
            std::vector<std::string> defines;
            if (displayOutput) {
                defines.push_back("PATINA_DISPLAY_OUTPUT");
            }
            found = backgrounds.try_emplace(displayOutput, std::vector<const char*>{shader_sources::fullscreen_vert},
                                            fragment, defines)
                        .first;
        }
        return found->second;
    }
    EnvironmentTexture environment;
    LightBuffer lights;
    // The primitives of the shape drawn last (a model's, or the one mesh), uploaded once for
    // as long as it is drawn; `shapeShown` holds it, so it cannot be freed and its address
    // reused by another while these stand for it.
    std::vector<std::unique_ptr<MeshBuffers>> primitives;
    ModelTextures textures;   // the shown model's maps' images
    // The ground (scene/ground.h): the box of the mesh it lies under, taken once per mesh
    // (`boundsOf` holds the mesh, so its address stands for it), and its plane uploaded.
    std::shared_ptr<const Mesh> boundsOf;
    BoundingBox modelBounds;
    std::optional<GroundPlane> groundPlane;
    Mesh groundMesh;
    MeshBuffers groundBuffers;
    ShadowMaps shadowMaps;
    // What the shadow maps hold: drawn again only when it changes (drawShadowMaps).
    std::optional<ShadowCasters> shadowsDrawn;
    SceneBehind sceneBehind;
    OcclusionBuffers occlusion;   // the shown shape's ambient occlusion, where the display has it
    const BoundingBox& boundsOfMesh(const std::shared_ptr<const Mesh>& mesh) {
        if (boundsOf != mesh) {
            modelBounds = boundingBox(*mesh);
            boundsOf = mesh;
        }
        return modelBounds;
    }
    std::shared_ptr<const void> shapeShown;
    GLuint emptyVertexArray = 0;
    GLuint timerQueries[2] = {0, 0};   // GL_TIMESTAMP before and after a draw
    bool timerPending = false;
    double gpuMilliseconds = -1.0;
    int maxSamples = 0, maxSize = 0;
    size_t flatLightSlots = 0;
    bool flushTimerStart = false;
};

RenderTarget::RenderTarget() : images_(std::make_unique<RenderTargets>()) {}
RenderTarget::~RenderTarget() = default;

unsigned RenderTarget::displayTexture() const {
    return images_->drawn ? images_->display.name : 0;
}

Renderer::Renderer() : state_(std::make_unique<State>()) {
    State& s = *state_;
    glGenVertexArrays(1, &s.emptyVertexArray);
    glGenQueries(2, s.timerQueries);
    // The samples are a texture (the display pass reads them) and the depth a renderbuffer.
    GLint renderbufferSamples = 0, textureSamples = 0, renderbufferSize = 0, textureSize = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &renderbufferSamples);
    glGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &textureSamples);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbufferSize);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &textureSize);
    s.maxSamples = std::min(renderbufferSamples, textureSamples);
    s.maxSize = std::min(renderbufferSize, textureSize);
    // Two vec4 rows a flat light, after mesh.vert's two outputs and one vec4 kept back in case the
    // implementation counts gl_Position. GL 3.3's minimum (60 varying components) leaves 6 lights.
    GLint vertexOutputs = 0, fragmentInputs = 0, varyings = 0;
    glGetIntegerv(GL_MAX_VERTEX_OUTPUT_COMPONENTS, &vertexOutputs);
    glGetIntegerv(GL_MAX_FRAGMENT_INPUT_COMPONENTS, &fragmentInputs);
    glGetIntegerv(GL_MAX_VARYING_COMPONENTS, &varyings);
    glGetError();   // a core context may refuse the last (deprecated in 3.x); draw() checks errors
    const int vectors = std::min({vertexOutputs, fragmentInputs, varyings > 0 ? varyings : vertexOutputs}) / 4;
    s.flatLightSlots = size_t(std::max(vectors - 3, 0) / 2);
    // llvmpipe bins a query into every tile of the scene it lands in, and each tile overwrites
    // the last one's stamp: a query in the draw's own scene timed one tile (about 0.02 ms of a
    // 40 ms frame; GL_TIME_ELAPSED the same). A flush after the start stamp gives it a scene of
    // its own. Elsewhere the stamps go with the draw, so no gap in submission is counted.
    const GLubyte* rendererName = glGetString(GL_RENDERER);
    s.flushTimerStart =
        rendererName && std::string_view(reinterpret_cast<const char*>(rendererName)).starts_with("llvmpipe");
}

Renderer::~Renderer() {
    glDeleteQueries(2, state_->timerQueries);
    glDeleteVertexArrays(1, &state_->emptyVertexArray);
}

size_t Renderer::specialisedProgramCount() const {
    return state_->shading.specialisedCount();
}

size_t Renderer::flatLightSlots() const {
    return state_->flatLightSlots;
}

double Renderer::lastGpuMilliseconds() {
    State& s = *state_;
    if (s.timerPending) {
        GLint available = 0;
        glGetQueryObjectiv(s.timerQueries[1], GL_QUERY_RESULT_AVAILABLE, &available);
        if (available) {
            GLuint64 start = 0, end = 0;
            glGetQueryObjectui64v(s.timerQueries[0], GL_QUERY_RESULT, &start);
            glGetQueryObjectui64v(s.timerQueries[1], GL_QUERY_RESULT, &end);
            s.gpuMilliseconds = double(end - start) * 1e-6;
            s.timerPending = false;
        }
    }
    return s.gpuMilliseconds;
}

namespace {
// The meshes a prepared scene's draw items index: its model's primitives, or its one mesh.
std::vector<const Mesh*> primitivesOf(const PreparedScene& prepared) {
    if (!prepared.model) {
        return {prepared.mesh.get()};
    }
    std::vector<const Mesh*> meshes;
    for (const Mesh& primitive : prepared.model->primitives) {
        meshes.push_back(&primitive);
    }
    return meshes;
}
}  // namespace

void Renderer::uploadShape(State& s, const PreparedScene& prepared) {
    const std::shared_ptr<const void> shape =
        prepared.model ? std::shared_ptr<const void>(prepared.model) : std::shared_ptr<const void>(prepared.mesh);
    if (shape == s.shapeShown) {
        return;
    }
    s.shapeShown.reset();   // until every primitive is up: a throw leaves nothing half-shown
    s.shadowsDrawn.reset();   // its casters' addresses may be another shape's
    const std::vector<const Mesh*> meshes = primitivesOf(prepared);
    s.primitives.resize(meshes.size());
    for (size_t i = 0; i < meshes.size(); ++i) {
        if (!s.primitives[i]) {
            s.primitives[i] = std::make_unique<MeshBuffers>();
        }
        s.primitives[i]->upload(*meshes[i]);   // the hidden-faces analysis runs here, once per primitive shown
    }
    s.textures.upload(prepared.model);
    s.shapeShown = shape;
}

// One draw: its plan, the programs and lights it uses, and the strips it draws one by one. Made
// in full before the first strip, so that everything that can throw (targets the GL cannot
// make, a shader that does not compile) comes before the timer query starts and a failed draw
// leaves no state behind.
struct Renderer::Frame {
    Frame(State& state, const PreparedScene& prepared, const RenderSettings& settings, RenderTargets& targets);
    void draw();
    bool keepsLinear() const { return plan.keepLinear; }

private:
    using Items = std::span<const DrawPlan>;
    void planDraw();
    void addGround();
    void assignShadowMaps();
    void choosePrograms();
    ShadingPrograms::SinglePass singlePassOf() const;
    void chooseShadingPrograms(const ShadingPrograms::SinglePass& singlePass, ShadingPrograms::Output output);
    void chooseSceneBehindPrograms(const ShadingPrograms::SinglePass& singlePass);
    std::optional<ShadowCasters> shadowCasters() const;   // null: nothing lasting to key the maps by
    void drawShadowMaps() const;
    void bindShadowMaps() const;
    void drawSceneBehind();
    // shade.frag's uSceneBehindPlace: the strip's first row, log2 of the width, and whether this
    // pass adds the scene behind (1) or only hides the light beyond it (2).
    void setSceneBehindPlace(GLint location, bool adds) const {
        glUniform3f(location, float(stripTop), std::log2(float(w)), adds ? 1.0f : 2.0f);
    }
    void drawCatcher() const;
    const MeshBuffers& buffersOf(const SceneDraw& item) const;
    void environmentUniforms(const GlProgram& program) const;
    void prepare(const GlProgram& program) const;   // the per-draw uniforms of a mesh pass
    void shadowUniforms(const GlProgram& program) const;   // PATINA_SHADOWS' (prepare)
    void clearAroundMesh() const;
    void drawStrip(int top);
    void drawItems() const;
    void drawSinglePass(Items opaque, Items blended, bool catcher = true) const;
    // The shading program of `item`: the one for its BRDF model, whether it has a clear coat
    // (PATINA_CLEARCOAT: only a coated item pays for the coat), a sheen (PATINA_SHEEN) and a
    // transmission (PATINA_TRANSMISSION), an anisotropy (PATINA_ANISOTROPY), a specular tint or
    // weight (PATINA_SPECULAR), a thin film (PATINA_IRIDESCENCE), and, in the specialised path
    // with maps, its map set (programKeyOf).
    struct ProgramKey {
        BrdfModelId model;
        int mapSet;
        bool clearcoat;
        bool sheen;
        bool transmission;
        bool ambientOcclusion;
        bool anisotropy;
        bool specular;
        bool iridescence;
        auto operator<=>(const ProgramKey&) const = default;
    };
    struct ItemProgram {
        BrdfModelId model;
        const GlProgram* program;
    };
    ProgramKey programKeyOf(const SceneDraw& draw) const;
    // What a program for `key` is compiled with in this frame: its layers, `transmission` (the
    // scene behind a transmission is drawn without it), the frame's maps and vertex colours.
    ShadingPrograms::Surface surfaceOfKey(const ProgramKey& key, bool transmission) const {
        return ShadingPrograms::surfaceOf(maps, key.clearcoat, key.sheen, transmission, key.ambientOcclusion,
                                          key.anisotropy, vertexColors, key.specular, key.iridescence);
    }
    ItemProgram programOf(const DrawPlan& item) const;
    // Makes `program` current with its model's tables bound (another model's may be).
    void useProgram(const ItemProgram& program) const;
    void drawMultiPass(Items opaque, Items blended) const;
    void lightPasses(const GlProgram& shading, const DrawPlan& item) const;
    void useItem(const DrawUniforms& uniforms, const DrawPlan& item) const;
    void drawItem(const DrawPlan& item) const;
    ModelTextures* mapTextures() const { return maps ? &s.textures : nullptr; }
    void clearStrip(int top, const PixelRect& area);
    void drawBackground(int top) const;
    void displayStrip(int top, const PixelRect& area) const;

    State& s;
    const PreparedScene& prepared;
    const Scene& scene;   // prepared.scene
    const RenderSettings& settings;
    RenderTargets& t;
    const int w, h;
    std::vector<SceneDraw> draws;   // what is drawn, in the list's order, the ground last
    // Ground::Shadow's catcher, drawn after the opaque items and before the blended ones (its
    // plan taken out of plan.items); only where some light casts a shadow.
    std::optional<DrawPlan> catcherPlan;
    const GlProgram* catcherProgram = nullptr;
    std::vector<ShadowView> shadowViews;   // by layer of the shadow maps
    const Light* environmentLight = nullptr;
    std::shared_ptr<const Environment> environmentMap;
    bool environment = false;
    bool environmentBackground = false;   // a drawn background covers every pixel
    bool maps = false;                    // an item has texture maps: the programs read them
    bool ambientOcclusion = false;        // the items carry their ambient occlusion (SceneDraw::occlusion)
    bool vertexColors = false;            // an item with maps has vertex colours: the programs read them
    FramePlan plan;
    std::vector<shader::PackedLight> packed;
    ChannelLights channelLights;   // with a channel: its lights in `packed`
    const GlImage* linear = nullptr;
    const GlProgram* displayPass = nullptr;
    // By (BRDF model, map set, coat, sheen, transmission, occlusion): each item's, programKeyOf. One model, no maps and
    // no layer: one program.
    std::map<ProgramKey, const GlProgram*> shading;
    // The multi path's scene behind a transmission is drawn by the single path's programs
    // (drawSceneBehind): its passes sum into one sample each. Empty elsewhere.
    std::map<ProgramKey, const GlProgram*> behindShading;
    const std::map<ProgramKey, const GlProgram*>* drawing = &shading;   // what programOf reads
    const GlProgram* backgroundPass = nullptr;
    int exposureTonemap = 0;
    glm::vec3 background{0.0f};
    float stamp = 1.0f;   // this strip's (RenderTargets::SampleStamp); 1 without MSAA
    int stripTop = 0;     // the image row the strip drawn now starts at
    bool sceneBehind = false;   // a transmitting item sees the scene behind it (choosePrograms)
};

namespace {
// What a frame draws: sceneDraws, and for a channel every item opaque (a channel is the front
// surface's data, as the CPU twin's; blending data would mean nothing).
std::vector<SceneDraw> drawnItems(const PreparedScene& prepared, const RenderSettings& settings) {
    std::vector<SceneDraw> draws = sceneDraws(prepared);
    if (settings.channel.channel >= 0) {
        for (SceneDraw& draw : draws) {
            draw.blend = false;
            draw.occlusion = nullptr;   // a channel is the surface's data: no occlusion, as no shadow
        }
    }
    return draws;
}
}  // namespace

Renderer::Frame::Frame(State& state, const PreparedScene& prepared, const RenderSettings& settings,
                       RenderTargets& targets)
    : s(state), prepared(prepared), scene(prepared.scene), settings(settings), t(targets), w(settings.width),
      h(settings.height), draws(drawnItems(prepared, settings)) {
    uploadShape(s, prepared);
    ambientOcclusion = prepared.occlusion && settings.channel.channel < 0;
    s.occlusion.upload(ambientOcclusion ? prepared.occlusion : nullptr);
    addGround();
    planDraw();
    // Until this draw succeeds the target has nothing to read back.
    t.drawn = false;
    t.prepare(w, h, plan.stripRows, plan.samples, plan.keepLinear, plan.displayInPass);
    linear = plan.keepLinear ? &t.linear : nullptr;
    choosePrograms();
    exposureTonemap = tonemapShaderIndex(scene.display.tonemap);
    background = settings.channel.channel < 0 ? scene.display.background : glm::vec3(0.0f);
}

// The environment shown, the frame plan, and the enabled lights uploaded.
void Renderer::Frame::planDraw() {
    environmentLight = enabledEnvironment(scene);
    environmentMap = environmentLight ? environmentShown(prepared.environment, environmentLight->source) : nullptr;
    environment = environmentLight != nullptr;
    // A channel's background is no surface: 0, not a picture.
    environmentBackground = environment && scene.display.backgroundFromEnvironment && settings.channel.channel < 0;
    RenderSettings planned = settings;
    planned.cropToMesh = settings.cropToMesh && !environmentBackground;   // nothing left to fill around the mesh
    std::vector<DrawFacts> facts;
    for (const SceneDraw& item : draws) {
        const MeshBuffers& buffers = buffersOf(item);
        facts.push_back({{buffers.bounds(), buffers.culling(), buffers.triangleCount()},
                         item.transform,
                         item.doubleSided,
                         item.blend});
    }
    maps = std::any_of(draws.begin(), draws.end(), [](const SceneDraw& item) { return item.maps != nullptr; });
    vertexColors = std::any_of(draws.begin(), draws.end(),
                               [](const SceneDraw& item) { return item.maps && !item.mesh->colors.empty(); });
    // The maps' three vertex outputs (surface_maps.glsl) take two flat lights' rows and more.
    // The ambient occlusion's one output and the vertex colours' one take one more light's each.
    const size_t taken = (maps ? 2 : 0) + (ambientOcclusion ? 1 : 0) + (vertexColors ? 1 : 0);
    const size_t flatSlots = s.flatLightSlots - std::min(s.flatLightSlots, taken);
    plan = planFrame(planned, scene.camera, facts, s.maxSamples, flatSlots);
    packed = packEnabledLights(scene.lights);
    assignShadowMaps();
    if (scene.display.ground == Ground::Shadow && !draws.empty() && draws.back().primitive < 0) {
        // The catcher multiplies what is behind it: drawn on its own, between opaque and blended.
        const auto catcher = std::find_if(plan.items.begin(), plan.items.end(),
                                          [&](const DrawPlan& item) { return item.item == draws.size() - 1; });
        catcherPlan = *catcher;
        plan.items.erase(catcher);
        if (shadowViews.empty() && !ambientOcclusion) {
            catcherPlan.reset();   // no shadow or occlusion to catch: the background unchanged
        }
    }
    if (settings.channel.channel >= 0) {
        channelLights = patina::channelLights(scene.lights, settings.channel);
    }
    s.lights.upload(packed);
    s.lights.bind();
}

// The ground under the model (DisplaySettings::ground, scene/ground.h) as one more item, last:
// the floor, opaque with its own material, or the shadow catcher, blended (what is behind it
// must be there first). A channel shows the floor's data but no catcher, which is no surface.
void Renderer::Frame::addGround() {
    const Ground ground = scene.display.ground;
    if (ground == Ground::None || (ground == Ground::Shadow && settings.channel.channel >= 0)) {
        return;
    }
    const GroundPlane plane = groundUnder(s.boundsOfMesh(prepared.mesh));
    if (s.groundPlane != plane) {
        s.groundMesh = groundMesh(plane);
        s.groundBuffers.upload(s.groundMesh);
        s.groundPlane = plane;
    }
    SceneDraw draw;
    draw.mesh = &s.groundMesh;
    if (ambientOcclusion && s.occlusion.shown()->withGround) {   // the grid that carries its occlusion
        draw.mesh = &s.occlusion.shown()->ground;
        draw.occlusion = &s.occlusion.shown()->groundValues;
    }
    draw.primitive = -1;   // buffersOf: the ground's
    draw.material = groundMaterial(scene.display);
    draw.doubleSided = false;   // seen from above only
    draw.blend = ground == Ground::Shadow;
    draws.push_back(draw);
}

// Each enabled light with shadows on gets a layer of the shadow maps and its view of the model
// (its packed row's shadowMap says which), up to kMaxShadowedLights and kMaxShadowMaps layers;
// a light no view can hold (shadowViewsOf) casts none. None for a channel, which shows no shadow.
void Renderer::Frame::assignShadowMaps() {
    if (settings.channel.channel >= 0 ||
        std::none_of(scene.lights.begin(), scene.lights.end(), [](const Light& light) { return light.shadows; })) {
        return;
    }
    const BoundingBox& bounds = s.boundsOfMesh(prepared.mesh);
    const glm::vec3 centre = 0.5f * (bounds.low + bounds.high);
    const float radius = bounds.empty() ? 0.0f : 0.5f * glm::length(bounds.high - bounds.low);
    const std::vector<size_t> order = enabledLightOrder(scene.lights);
    int lights = 0;
    for (size_t i = 0; i < packed.size() && lights < kMaxShadowedLights; ++i) {
        if (!scene.lights[order[i]].shadows) {
            continue;
        }
        const std::vector<ShadowView> views = shadowViewsOf(packed[i], centre, radius, settings.shadowMaps);
        if (views.empty() || shadowViews.size() + views.size() > size_t(kMaxShadowMaps)) {
            continue;
        }
        // 1 + its first layer, negative for a cube map's six (shade.frag's shadowOf).
        packed[i].shadowMap = (views.size() > 1 ? -1.0f : 1.0f) * float(shadowViews.size() + 1);
        shadowViews.insert(shadowViews.end(), views.begin(), views.end());
        ++lights;
    }
}

// The display, shading and background programs (compiled on first use), the environment bound.
void Renderer::Frame::choosePrograms() {
    const bool caught = catcherPlan && !environmentBackground;
    displayPass = plan.msaa            ? &s.resolve(std::max(t.samples.actualSamples, 1), caught).get()
                  : plan.displayInPass ? nullptr
                  : caught             ? &s.displayCaught.get()
                                       : &s.display.get();
    const ShadingPrograms::Output output =
        plan.displayInPass ? ShadingPrograms::Output::LinearAndDisplay : ShadingPrograms::Output::Linear;
    EnvironmentShading environmentShading = settings.environment;
    environmentShading.samples = std::clamp(environmentShading.samples, 1, 256);
    s.shading.setEnvironmentShading(environmentShading);
    const ShadingPrograms::SinglePass singlePass = singlePassOf();
    s.shading.beginFrame();
    chooseShadingPrograms(singlePass, output);
    chooseSceneBehindPrograms(singlePass);
    if (catcherPlan) {
        ShadingPrograms::SinglePass catcher = singlePass;
        catcher.catcher = true;
        catcherProgram = &s.shading.useSingle(draws.back().material.model, catcher, ShadingPrograms::Output::Linear,
                                              ShadingPrograms::surfaceOf(maps, false, false, false,
                                                                         draws.back().occlusion != nullptr, false,
                                                                         vertexColors));
    }
    if (settings.path == RenderPath::Multi || singlePass.shadows) {
        s.prepass(maps, vertexColors).get();
    }
    backgroundPass = environmentBackground ? &s.background(plan.displayInPass).get() : nullptr;
    if (environment) {
        s.environment.bind(environmentMap, ShadingPrograms::kEnvironmentMapUnit,
                          ShadingPrograms::kEnvironmentIrradianceUnit);
        if (environmentShading.method == EnvironmentMethod::Stochastic) {
            s.environment.bindSource(environmentMap, ShadingPrograms::kEnvironmentSourceUnit);
        }
    }
}

// What the single path's program is compiled for: the packed lights, the environment, the
// inspected channel and whether any light casts shadows.
ShadingPrograms::SinglePass Renderer::Frame::singlePassOf() const {
    ShadingPrograms::SinglePass singlePass = ShadingPrograms::singlePassFor(packed);
    singlePass.environment = environment;
    singlePass.channel = settings.channel.channel;
    singlePass.shadows = !shadowViews.empty();
    return singlePass;
}

// A program for each BRDF model the items are shaded with and, specialised with maps, each set
// of maps they have: a map an item lacks costs it nothing.
void Renderer::Frame::chooseShadingPrograms(const ShadingPrograms::SinglePass& singlePass,
                                            ShadingPrograms::Output output) {
    // The specialised shader leaves out diffuse only where no item has any.
    // A metallic-roughness map can lower metallic below its factor's 1 (a base colour map can
    // only darken a black factor's nothing).
    const bool noDiffuse = std::all_of(draws.begin(), draws.end(), [](const SceneDraw& item) {
        const bool mapLowersMetallic = item.maps && item.maps->metallicRoughness.present();
        return hasNoDiffuse(item.material) && (item.material.baseColor == glm::vec3(0.0f) || !mapLowersMetallic);
    });
    auto specialisation = [&] {
        ShaderSpecialisation key = settings.lightCode ? settings.lightCode(packed, plan.flatLightCount)
                                                      : specialiseFor(packed, noDiffuse, plan.flatLightCount);
        key.environment = environment;
        return key;
    };
    const ShaderSpecialisation specialised = settings.path == RenderPath::Specialised ? specialisation()
                                                                                      : ShaderSpecialisation{};
    for (const SceneDraw& item : draws) {
        const ProgramKey itemKey = programKeyOf(item);
        const GlProgram*& program = shading[itemKey];
        if (program) {
            continue;
        }
        const BrdfModelId model = itemKey.model;
        const ShadingPrograms::Surface surface = surfaceOfKey(itemKey, itemKey.transmission);
        ShaderSpecialisation key = specialised;
        key.mapSet = itemKey.mapSet;
        program = settings.path == RenderPath::Single ? &s.shading.useSingle(model, singlePass, output, surface)
                  : settings.path == RenderPath::Multi
                      ? &s.shading.use(model, ShadingPrograms::Use::MultiPass, output, environment, surface,
                                       singlePass.shadows)
                      : &s.shading.useSpecialised(model, key, output, surface);
    }
}

// A transmitting item sees the scene behind it (drawSceneBehind); a channel shows data. The
// multi path draws that scene with the single path's programs.
void Renderer::Frame::chooseSceneBehindPrograms(const ShadingPrograms::SinglePass& singlePass) {
    sceneBehind = settings.channel.channel < 0 &&
                  std::any_of(draws.begin(), draws.end(), [](const SceneDraw& item) {
                      return hasTransmission(item.material);
                  });
    if (!sceneBehind || settings.path != RenderPath::Multi) {
        return;
    }
    for (const SceneDraw& item : draws) {
        const ProgramKey itemKey = programKeyOf(item);
        if (!item.blend && !itemKey.transmission && !behindShading.count(itemKey)) {
            const ShadingPrograms::Surface surface = surfaceOfKey(itemKey, false);
            behindShading[itemKey] =
                &s.shading.useSingle(itemKey.model, singlePass, ShadingPrograms::Output::Linear, surface);
        }
    }
}

void Renderer::Frame::environmentUniforms(const GlProgram& program) const {
    if (environment) {
        setEnvironmentUniforms(program, *environmentMap, *environmentLight, ShadingPrograms::kEnvironmentMapUnit);
    }
}

void Renderer::Frame::prepare(const GlProgram& program) const {
    environmentUniforms(program);
    glUniform1f(program.uniform("uSampleStamp"), stamp);
    if (sceneBehind) {   // the uniforms of transmitting programs; 0 (not drawn) elsewhere
        glUniform1i(program.uniform("uSceneBehind"), ShadingPrograms::kSceneBehindUnit);
        setSceneBehindPlace(program.uniform("uSceneBehindPlace"), true);
    }
    glUniformMatrix4fv(program.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(plan.transform));
    glUniform3fv(program.uniform("uCameraPosition"), 1, glm::value_ptr(scene.camera.position));
    if (settings.channel.channel >= 0) {
        glUniform1i(program.uniform("uChannelLight"), channelLights.asked);
        glUniform1i(program.uniform("uKeyLight"), channelLights.key);
        glUniform1i(program.uniform("uChannelSrgb"), settings.channel.srgb ? 1 : 0);
        glUniform3fv(program.uniform("uPbrRanges"), 1, glm::value_ptr(channelPbrRanges(settings.channel)));
    }
    if (plan.displayInPass) {
        glUniform1f(program.uniform("uExposure"), scene.display.exposure);
        glUniform1i(program.uniform("uTonemap"), exposureTonemap);
    }
    if (!shadowViews.empty()) {
        shadowUniforms(program);
    }
}

// shade.frag's PATINA_SHADOWS uniforms: each map's transform, texel, light size and depth range.
void Renderer::Frame::shadowUniforms(const GlProgram& program) const {
    std::vector<glm::mat4> transforms;
    std::vector<glm::vec4> texels, sources;
    std::vector<glm::vec2> ranges;
    for (const ShadowView& view : shadowViews) {
        transforms.push_back(view.texture);
        texels.push_back(view.texel);
        sources.push_back(view.source);
        ranges.push_back(view.range);
    }
    const auto count = GLsizei(shadowViews.size());
    glUniform1i(program.uniform("uShadowMaps"), ShadingPrograms::kShadowMapUnit);
    glUniform1i(program.uniform("uShadowDepthMaps"), ShadingPrograms::kShadowDepthUnit);
    glUniformMatrix4fv(program.uniform("uShadowTransforms"), count, GL_FALSE, glm::value_ptr(transforms[0]));
    glUniform4fv(program.uniform("uShadowTexels"), count, glm::value_ptr(texels[0]));
    glUniform4fv(program.uniform("uShadowSources"), count, glm::value_ptr(sources[0]));
    glUniform2fv(program.uniform("uShadowRanges"), count, glm::value_ptr(ranges[0]));
}

namespace {
// Alpha 0: nothing drawn here, so the display pass shows the backdrop (display.frag).
std::array<GLfloat, 4> clearLinearOf(glm::vec3 background) {
    return {background.r, background.g, background.b, 0.0f};
}

// A channel's background is no surface, a value of 0 as the channel shows it (mid-grey for a
// normal), as the CLI's PNG of its values shows it.
std::array<GLfloat, 4> clearDisplayOf(glm::vec3 background, const ChannelRequest& channel) {
    const glm::vec3 shown = channel.channel < 0 ? shader::srgbColor(background)
                                                : shader::shownChannel(channel.channel, glm::vec3(0.0f), channel.srgb);
    return {shown.r, shown.g, shown.b, 1.0f};
}
}  // namespace

// The pixels around the mesh's area, which no strip draws.
void Renderer::Frame::clearAroundMesh() const {
    if (plan.meshArea == PixelRect{0, 0, w, h}) {
        return;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, t.displayFramebuffer);
    if (linear) {
        glClearBufferfv(GL_COLOR, 0, clearLinearOf(background).data());
    }
    glClearBufferfv(GL_COLOR, 1, clearDisplayOf(background, settings.channel).data());
}

void Renderer::Frame::draw() {
    // The display image is bytes: a GL may dither what it writes there, and the bytes must
    // be the display values rounded (a float image read back was never dithered).
    glDisable(GL_DITHER);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    if (ambientOcclusion) {
        // An item without values (baked for another shape) reads attribute 5's constant: none.
        glVertexAttrib1f(MeshBuffers::kOcclusionAttribute, 1.0f);
    }
    if (vertexColors) {   // an item without colours multiplies by none
        glVertexAttrib4f(MeshBuffers::kColorAttribute, 1.0f, 1.0f, 1.0f, 1.0f);
    }
    drawShadowMaps();
    drawSceneBehind();
    clearAroundMesh();
    for (int top = 0; top < h; top += plan.stripRows) {
        drawStrip(top);
    }
}

// What a transmitting item sees through its wall (gl/scene_behind.h): the opaque items that do
// not transmit, drawn whole (not in strips) into an image of their own, their samples stamped 1
// (coverage), the catcher left out (it only darkens the background, which is not drawn here).
// The multi path draws it with the single path's programs (behindShading): its light passes
// sum into one sample each. A channel shows data, not what is behind.
void Renderer::Frame::drawSceneBehind() {
    if (!sceneBehind) {
        return;
    }
    std::vector<DrawPlan> behind;
    for (const DrawPlan& item : plan.items) {
        if (!draws[item.item].blend && !hasTransmission(draws[item.item].material)) {
            behind.push_back(item);
        }
    }
    s.sceneBehind.begin(w, h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    const float stripStamp = std::exchange(stamp, 1.0f);
    stripTop = 0;
    if (settings.path == RenderPath::Multi) {
        drawing = &behindShading;
    }
    drawSinglePass(behind, {}, false);
    drawing = &shading;
    stamp = stripStamp;
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    s.sceneBehind.finish(ShadingPrograms::kSceneBehindUnit);
}

// The rows [top, top + stripRows) of the image, where they cross the mesh's area.
void Renderer::Frame::drawStrip(int top) {
    stripTop = top;
    const int rows = std::min(plan.stripRows, h - top);
    const PixelRect area{plan.meshArea.x0, std::max(plan.meshArea.y0, top), plan.meshArea.x1,
                         std::min(plan.meshArea.y1, top + rows)};
    if (area.empty()) {
        return;
    }
    clearStrip(top, area);
    if (backgroundPass) {
        drawBackground(top);
    }
    drawItems();
    glDisable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    if (displayPass) {
        displayStrip(top, area);
    }
}

// The glPolygonOffset of the shadow maps' depth (docs/LIGHTING.md "Shadows"): the slope-scaled
// bias, in units of the depth's slope across a texel, and the constant one, in the depth's
// smallest steps, each times ShadowMapSettings::biasScale. The lookup's normal offset
// (shade.frag) does the rest.
constexpr float kShadowSlopeBias = 2.0f;
constexpr float kShadowConstantBias = 4.0f;

std::optional<ShadowCasters> Renderer::Frame::shadowCasters() const {
    ShadowCasters casters{{}, settings.shadowMaps, {}};
    for (const ShadowView& view : shadowViews) {
        casters.views.push_back(view.clip);
    }
    for (const SceneDraw& item : draws) {
        if (item.primitive < 0 || item.blend) {
            continue;   // the ground and the blended items cast nothing
        }
        if (item.alphaCutoff >= 0.0f && item.tunedMaps) {
            return std::nullopt;   // a MASK cut by maps made for this frame: no lasting key
        }
        casters.items.emplace_back(item.mesh, item.primitive, item.transform, item.doubleSided, item.alphaCutoff,
                                   item.alphaCutoff >= 0.0f ? item.alpha : 1.0f,
                                   item.alphaCutoff >= 0.0f ? item.maps : nullptr);
    }
    return casters;
}

// Each shadowed light's map: the depth of every opaque item but the ground, seen from the
// light, both sides (a model's open surfaces cast too), unless the last frame's hold the same
// casters (ShadowCasters); then the maps bound for the shading.
void Renderer::Frame::drawShadowMaps() const {
    if (shadowViews.empty()) {
        return;
    }
    std::optional<ShadowCasters> casters = shadowCasters();
    if (casters && casters == s.shadowsDrawn) {
        bindShadowMaps();
        return;
    }
    s.shadowsDrawn.reset();   // until drawn
    const GlProgram& program = s.prepass(maps, vertexColors).get();
    program.use();
    const DrawUniforms uniforms(program, mapTextures());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    const float bias = settings.shadowMaps.biasScale;
    glPolygonOffset(bias * kShadowSlopeBias, bias * kShadowConstantBias);
    for (size_t layer = 0; layer < shadowViews.size(); ++layer) {
        s.shadowMaps.beginLayer(int(shadowViews.size()), int(layer), settings.shadowMaps.size);
        glUniformMatrix4fv(program.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(shadowViews[layer].clip));
        for (const SceneDraw& item : draws) {
            if (item.primitive >= 0 && !item.blend) {
                uniforms.set(item);
                buffersOf(item).draw();
            }
        }
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    s.shadowsDrawn = std::move(casters);
    bindShadowMaps();
}

void Renderer::Frame::bindShadowMaps() const {
    glActiveTexture(GL_TEXTURE0 + ShadingPrograms::kShadowMapUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, s.shadowMaps.texture());
    // The same texture again, read without the comparison: PCSS's blocker search.
    glActiveTexture(GL_TEXTURE0 + ShadingPrograms::kShadowDepthUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, s.shadowMaps.texture());
    glBindSampler(ShadingPrograms::kShadowDepthUnit, s.shadowMaps.depthSampler());
    glActiveTexture(GL_TEXTURE0);
}

// The shadow catcher: what is behind it (the background, drawn or cleared) times the share of
// its light its shadows leave (shade.frag's PATINA_SHADOW_CATCHER); alpha takes its stamp, so
// the sample counts as drawn (over the environment), or the stamp negated over the flat colour,
// which the display pass then shows as it shows that colour. Leaves blending on and depth
// writes off.
void Renderer::Frame::drawCatcher() const {
    if (!catcherPlan) {
        return;
    }
    s.shading.bind(draws.back().material.model, *catcherProgram, environment);
    prepare(*catcherProgram);
    if (!environmentBackground) {
        // The flat background darkened is background still (display.frag's PATINA_CAUGHT_BACKGROUND).
        glUniform1f(catcherProgram->uniform("uSampleStamp"), -stamp);
    }
    const DrawUniforms uniforms(*catcherProgram, mapTextures());
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ONE, GL_ZERO);
    useItem(uniforms, *catcherPlan);
    drawItem(*catcherPlan);
}

// Every item of the plan: the opaque ones, then the blended ones over them.
void Renderer::Frame::drawItems() const {
    const Items items(plan.items);
    const auto firstBlended = std::find_if(items.begin(), items.end(),
                                           [&](const DrawPlan& item) { return draws[item.item].blend; });
    const Items opaque(items.begin(), firstBlended), blended(firstBlended, items.end());
    if (settings.path == RenderPath::Multi) {
        drawMultiPass(opaque, blended);
    } else {
        drawSinglePass(opaque, blended);
    }
}

// The item's faces culled, its front winding, and its uniforms set (its program in use).
void Renderer::Frame::useItem(const DrawUniforms& uniforms, const DrawPlan& item) const {
    if (item.culled == HiddenFaces::None) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(item.culled == HiddenFaces::Back ? GL_BACK : GL_FRONT);
    }
    glFrontFace(item.frontClockwise ? GL_CW : GL_CCW);
    uniforms.set(draws[item.item]);
}

void Renderer::Frame::drawItem(const DrawPlan& item) const {
    const SceneDraw& draw = draws[item.item];
    buffersOf(draw).draw(draw.occlusion ? s.occlusion.bufferOf(draw.occlusion) : 0);
}

const MeshBuffers& Renderer::Frame::buffersOf(const SceneDraw& item) const {
    if (item.primitive < 0) {   // the ground: its plane, or the grid that carries its occlusion
        return item.mesh == &s.groundMesh ? s.groundBuffers : s.occlusion.ground();
    }
    return *s.primitives[size_t(item.primitive)];
}

namespace {
// glTF's BLEND, "over" (§3.9.4) by the item's alpha, a constant blend colour: what is behind
// times 1 - alpha plus the item times alpha. Alpha takes the shader's (the sample stamp, or 1):
// the sample now holds a drawn value.
void blendOver(float alpha) {
    glEnable(GL_BLEND);
    glBlendColor(0.0f, 0.0f, 0.0f, alpha);
    glBlendFuncSeparate(GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA, GL_ONE, GL_ZERO);
}
}  // namespace

Renderer::Frame::ProgramKey Renderer::Frame::programKeyOf(const SceneDraw& draw) const {
    const bool byMapSet = settings.path == RenderPath::Specialised && maps;
    return {draw.material.model, byMapSet ? (draw.maps ? mapSetOf(*draw.maps) : 0) : ShaderSpecialisation{}.mapSet,
            hasClearcoat(draw.material), hasSheen(draw.material), hasTransmission(draw.material),
            draw.occlusion != nullptr, hasAnisotropy(draw.material),
            hasSpecularTint(draw.material) || (draw.maps && hasSpecularMaps(*draw.maps)),
            hasIridescence(draw.material)};
}

Renderer::Frame::ItemProgram Renderer::Frame::programOf(const DrawPlan& item) const {
    const ProgramKey key = programKeyOf(draws[item.item]);
    return {key.model, drawing->at(key)};
}

void Renderer::Frame::useProgram(const ItemProgram& program) const {
    s.shading.bind(program.model, *program.program, environment);
}

// Single and specialised: each item in one pass of every light. Blended items test against
// the opaque items' depth and write none, so each shows what lies behind it.
void Renderer::Frame::drawSinglePass(Items opaque, Items blended, bool catcher) const {
    // Items keep the plan's order (the same depth ties as one program); the program changes
    // only where an item's BRDF model or map set does.
    const GlProgram* current = nullptr;
    std::optional<DrawUniforms> uniforms;
    auto drawWithItsProgram = [&](const DrawPlan& item) {
        const ItemProgram program = programOf(item);
        if (program.program != current) {
            current = program.program;
            useProgram(program);
            prepare(*current);
            uniforms.emplace(*current, mapTextures());
        }
        useItem(*uniforms, item);
        drawItem(item);
    };
    for (const DrawPlan& item : opaque) {
        drawWithItsProgram(item);
    }
    if (catcherPlan && catcher) {
        drawCatcher();
        current = nullptr;
    }
    glDepthMask(GL_FALSE);
    for (const DrawPlan& item : blended) {
        blendOver(draws[item.item].alpha);
        drawWithItsProgram(item);
    }
}

// Multi: the opaque items' depth and a black surface first, then a pass per light (and one for
// the environment) added where depth matches the pre-pass exactly (mesh.vert's gl_Position is
// invariant). A blended item darkens what is behind it by 1 - alpha in a black pass, and its
// light passes add alpha times theirs: the same "over" as one pass where the item does not
// cover itself (where it does, each pass adds every layer, not the layers over one another).
void Renderer::Frame::drawMultiPass(Items opaque, Items blended) const {
    const GlProgram& depthPrepass = s.prepass(maps, vertexColors).get();
    depthPrepass.use();
    prepare(depthPrepass);
    const DrawUniforms prepassUniforms(depthPrepass, mapTextures());
    for (const DrawPlan& item : opaque) {
        useItem(prepassUniforms, item);
        drawItem(item);
    }
    // The item's shading program, made current with its uniforms where it changes (another
    // BRDF model's, or after the pre-pass's).
    const GlProgram* current = nullptr;
    std::optional<DrawUniforms> uniforms;
    auto useShading = [&](const DrawPlan& item) {
        const ItemProgram program = programOf(item);
        if (program.program == current) {
            return;
        }
        current = program.program;
        useProgram(program);
        prepare(*current);
        uniforms.emplace(*current, mapTextures());
        // The passes add 0 to alpha, so the pre-pass's stamp (RenderTargets::SampleStamp) stays.
        glUniform1f(current->uniform("uSampleStamp"), 0.0f);
    };
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    for (const DrawPlan& item : opaque) {
        useShading(item);
        useItem(*uniforms, item);
        lightPasses(*current, item);
    }
    if (catcherPlan) {
        drawCatcher();
        current = nullptr;
    }
    glDepthFunc(GL_LESS);   // against the opaque items' depth; the blended ones write none
    for (const DrawPlan& item : blended) {
        const float alpha = draws[item.item].alpha;
        depthPrepass.use();
        current = nullptr;
        useItem(prepassUniforms, item);   // the pre-pass's stamp: the sample now holds a drawn value
        glBlendColor(0.0f, 0.0f, 0.0f, alpha);
        glBlendFuncSeparate(GL_ZERO, GL_ONE_MINUS_CONSTANT_ALPHA, GL_ONE, GL_ZERO);
        drawItem(item);
        useShading(item);
        glBlendFuncSeparate(GL_CONSTANT_ALPHA, GL_ONE, GL_ZERO, GL_ONE);
        useItem(*uniforms, item);
        lightPasses(*current, item);
    }
}

// One item's light passes, then the environment's, as in the single pass (the shading program
// in use; `lightIndex` its uLightIndex).
// Emission (with maps) comes in the first pass only.
void Renderer::Frame::lightPasses(const GlProgram& shading, const DrawPlan& item) const {
    const GLint lightIndex = shading.uniform("uLightIndex");
    const GLint emissionPass = maps ? shading.uniform("uEmissionPass") : -1;
    // A transmitting item adds the scene behind it in its first pass only (shade.frag).
    const GLint behindPlace = sceneBehind ? shading.uniform("uSceneBehindPlace") : -1;
    auto firstPass = [&](bool first) {
        glUniform1i(emissionPass, first ? 1 : 0);
        setSceneBehindPlace(behindPlace, first);
    };
    for (size_t i = 0; i < packed.size(); ++i) {
        firstPass(i == 0);
        glUniform1i(lightIndex, GLint(i));
        drawItem(item);
    }
    if (environment) {
        firstPass(packed.empty());
        glUniform1i(lightIndex, -1);
        drawItem(item);
    }
}

// The strip's targets made ready: the sample stamp advanced, the viewport and scissor set, the
// colours and depth cleared.
void Renderer::Frame::clearStrip(int top, const PixelRect& area) {
    glBindFramebuffer(GL_FRAMEBUFFER, t.shadingFramebuffer);
    if (plan.msaa) {
        if (t.sampleStamp.advance()) {
            const GLfloat clearStamp[4] = {0.0f, 0.0f, 0.0f, 0.0f};
            glClearBufferfv(GL_COLOR, 0, clearStamp);   // the whole strip: no scissor yet
        }
        stamp = t.sampleStamp.value;
    }
    // The whole image's viewport, moved down so rows [top, top + rows) land in the strip;
    // the scissor (which clears obey too) keeps to the area.
    glViewport(0, -top, w, h);
    glEnable(GL_SCISSOR_TEST);
    glScissor(area.x0, area.y0 - top, area.x1 - area.x0, area.y1 - area.y0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    // MSAA samples are stamped instead (RenderTargets::SampleStamp), but a blended item needs
    // the background's value beneath it where nothing else was drawn.
    if ((!plan.msaa && linear) || (plan.msaa && plan.blending)) {
        glClearBufferfv(GL_COLOR, 0, clearLinearOf(background).data());
    }
    if (plan.displayInPass) {
        glClearBufferfv(GL_COLOR, 1, clearDisplayOf(background, settings.channel).data());
    }
    if (plan.depthTest) {
        glEnable(GL_DEPTH_TEST);
        const GLfloat clearDepth = 1.0f;
        glClearBufferfv(GL_DEPTH, 0, &clearDepth);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
}

// The environment behind the mesh, over the whole strip.
void Renderer::Frame::drawBackground(int top) const {
    const GlProgram& program = *backgroundPass;
    glDisable(GL_DEPTH_TEST);
    program.use();
    environmentUniforms(program);
    glUniformMatrix4fv(program.uniform("uInverseViewProjection"), 1, GL_FALSE,
                       glm::value_ptr(glm::inverse(plan.transform)));
    glUniform3fv(program.uniform("uCameraPosition"), 1, glm::value_ptr(scene.camera.position));
    glUniform4f(program.uniform("uViewport"), 0.0f, float(-top), float(w), float(h));
    glUniform1f(program.uniform("uBlur"), scene.display.backgroundBlur);
    glUniform1f(program.uniform("uSampleStamp"), stamp);
    glUniform1f(program.uniform("uExposure"), scene.display.exposure);
    glUniform1i(program.uniform("uTonemap"), exposureTonemap);
    glBindVertexArray(s.emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    if (plan.depthTest) {
        glEnable(GL_DEPTH_TEST);
    }
}

// The display values of the strip starting at image row `top`, written within `area`.
void Renderer::Frame::displayStrip(int top, const PixelRect& area) const {
    glBindFramebuffer(GL_FRAMEBUFFER, t.displayFramebuffer);
    glViewport(0, 0, w, h);
    glEnable(GL_SCISSOR_TEST);
    glScissor(area.x0, area.y0, area.x1 - area.x0, area.y1 - area.y0);
    glDisable(GL_DEPTH_TEST);
    displayPass->use();
    glActiveTexture(GL_TEXTURE0);
    if (plan.msaa) {
        glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, t.samples.name);
        glUniform1i(displayPass->uniform("uSamples"), 0);
        glUniform1i(displayPass->uniform("uStripTop"), top);
        glUniform1f(displayPass->uniform("uSampleStamp"), stamp);
    } else {
        glBindTexture(GL_TEXTURE_2D, t.linear.name);
        glUniform1i(displayPass->uniform("uHdr"), 0);
    }
    glUniform3fv(displayPass->uniform("uBackground"), 1, glm::value_ptr(background));
    glUniform1f(displayPass->uniform("uExposure"), scene.display.exposure);
    glUniform1i(displayPass->uniform("uTonemap"), exposureTonemap);
    glBindVertexArray(s.emptyVertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_SCISSOR_TEST);
}

unsigned Renderer::draw(const PreparedScene& prepared, const RenderSettings& settings, RenderTarget& target) {
    State& s = *state_;
    // An error someone else left (the UI's own drawing, say) is not this draw's: take it off
    // the queue so the check at the end reports only what this draw did.
    while (glGetError() != GL_NO_ERROR) {
    }
    if (settings.width < 1 || settings.height < 1 || settings.width > s.maxSize ||
        settings.height > s.maxSize) {
        throw std::invalid_argument("image size " + std::to_string(settings.width) + "x" +
                                    std::to_string(settings.height) + " is outside 1.." +
                                    std::to_string(s.maxSize));
    }
    const ShadowMapSettings& maps = settings.shadowMaps;
    if (maps.size < 1 || maps.size > s.maxSize || !(maps.biasScale >= 0.0f) || !std::isfinite(maps.biasScale)) {
        throw std::invalid_argument("shadow maps of " + std::to_string(maps.size) + " texels (1.." +
                                    std::to_string(s.maxSize) + ") and a bias scale of " +
                                    std::to_string(maps.biasScale) + " (at least 0)");
    }
    const FramebufferKept kept;
    RenderTargets& t = *target.images_;
    // A channel is drawn by the single path, which has its code (PATINA_CHANNEL), one sample a
    // pixel: data is the value at the pixel's centre, not an average across an edge.
    const bool channel = settings.channel.channel >= 0;
    RenderSettings channelSettings;
    if (channel) {
        channelSettings = settings;
        channelSettings.path = RenderPath::Single;
        channelSettings.samples = 1;
    }
    Frame frame(s, prepared, channel ? channelSettings : settings, t);
    // One pair of queries in flight: a draw while the last pair is unread goes untimed.
    lastGpuMilliseconds();
    const bool timed = !s.timerPending;
    if (timed) {
        glQueryCounter(s.timerQueries[0], GL_TIMESTAMP);
        if (s.flushTimerStart) {
            glFlush();
        }
    }
    frame.draw();
    glViewport(0, 0, settings.width, settings.height);
    glDisable(GL_DEPTH_TEST);
    if (timed) {
        glQueryCounter(s.timerQueries[1], GL_TIMESTAMP);
        s.timerPending = true;
    }
    if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        throw std::runtime_error("OpenGL error " + std::to_string(error) + " while rendering");
    }
    t.drawn = true;
    t.hasLinear = frame.keepsLinear();
    return t.display.name;
}

RenderOutput Renderer::readBack(const RenderTarget& target, bool hdr) const {
    const RenderTargets& t = *target.images_;
    if (hdr && t.drawn && !t.hasLinear) {
        throw std::logic_error("the render target was drawn without its linear image (RenderSettings::readHdr)");
    }
    RenderOutput output;
    if (!t.drawn) {
        return output;   // never drawn, or the last draw failed
    }
    const FramebufferKept kept;
    const int w = t.display.width, h = t.display.height;
    // Straight into the outputs (no staging copies: a render's peak memory counts), then the
    // rows flipped in place, since GL's go bottom to top.
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, t.readFramebuffer);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    if (hdr) {
        output.hdr = {w, h, std::vector<float>(size_t(w) * h * 3)};
        glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t.linear.name, 0);
        glReadPixels(0, 0, w, h, GL_RGB, GL_FLOAT, output.hdr.rgb.data());
        flipRows(output.hdr.rgb, size_t(w) * 3, h);
    }
    // The display image is bytes already: a copy.
    output.ldr = {w, h, std::vector<uint8_t>(size_t(w) * h * 4)};
    glFramebufferTexture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, t.display.name, 0);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, output.ldr.rgba.data());
    flipRows(output.ldr.rgba, size_t(w) * 4, h);
    detach(t.readFramebuffer);
    return output;
}

double Renderer::timedDraw(const PreparedScene& scene, const RenderSettings& settings) {
    glFinish();
    lastGpuMilliseconds();   // collect a pending query so this draw is timed
    draw(scene, settings);
    glFinish();
    return lastGpuMilliseconds();
}

RenderOutput Renderer::render(const PreparedScene& scene, const RenderSettings& settings) {
    draw(scene, settings);
    return readBack(settings.readHdr);
}

}  // namespace patina
