#pragma once
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "shading/brdf_model_id.h"
#include "gl/environment_method.h"
#include "gl/shader_specialisation.h"
#include "gl/program.h"

namespace patina {

// The shading programs of shaders/stages/shade.frag, one permutation per BRDF model and use, compiled
// on first use (a model nobody selects is never compiled), with the LightBlock attached and,
// for models with energy compensation, their E(NoV, r) table as a texture.
class ShadingPrograms {
public:
    // What single is compiled for: a loop only for each light type present (on llvmpipe an
    // empty type's loop still runs its body once with every lane off), and the point lights'
    // coefficients as a constant when all of them (and every sphere's and tube's) have
    // KARIS_ATTENUATION.
    struct SinglePass {
        bool points = true, directionals = true, hemispheres = true, spheres = true, tubes = true;
        bool karisPoints = false;
        // The scene's environment after the lights; the renderer sets it (singlePassFor sees
        // only packed lights, which hold no environment).
        bool environment = false;
        // An inspector channel (shaders/shared/channels.glsl) written instead of the radiance;
        // -1: the radiance.
        int channel = -1;
        // PATINA_SHADOWS: some light has a shadow map (PackedLight::shadowMap); with `catcher`,
        // PATINA_SHADOW_CATCHER, the shadow catcher's program (Ground::Shadow).
        bool shadows = false;
        bool catcher = false;
        std::vector<std::string> defines() const;
        auto operator<=>(const SinglePass&) const = default;
    };
    // The single pass for `lights` (packEnabledLights' list).
    static SinglePass singlePassFor(const std::vector<shader::PackedLight>& lights);
    // The other programs. Probe: single with every loop, one probe row per pixel.
    enum class Use { MultiPass, Probe };
    // What the fragment shader writes: the linear radiance, or also its display value
    // (PATINA_DISPLAY_OUTPUT, for a pass with nothing to resolve or sum afterwards).
    enum class Output { Linear, LinearAndDisplay };
    // What the surface is shaded with: the draw's factors alone, or also a model's texture maps
    // and emission (PATINA_TEXTURED: mesh.vert hands on UVs and tangents, surface_maps.glsl
    // reads the maps; docs/FORMATS.md, "glTF").
    // Either also with KHR_materials_clearcoat's coat (PATINA_CLEARCOAT, shaders/shared/
    // clearcoat.glsl) and with KHR_materials_sheen's sheen (PATINA_SHEEN, shaders/shared/
    // sheen.glsl), each compiled only for items whose material has one (hasClearcoat,
    // hasSheen), and with KHR_materials_transmission's and _volume's light through the surface
    // (PATINA_TRANSMISSION, shaders/shared/transmission.glsl; hasTransmission), and with the
    // ambient occlusion baked at its vertices (PATINA_AMBIENT_OCCLUSION: mesh.vert reads
    // attribute 5; only for an item drawn with one, SceneDraw::occlusion), with
    // KHR_materials_anisotropy's stretched lobe (PATINA_ANISOTROPY: mesh.vert hands on the
    // tangents; hasAnisotropy), and with Maps, the vertex colours (PATINA_VERTEX_COLOR: mesh.vert
    // reads attribute 6; in a frame where some item's mesh has them), and with
    // KHR_materials_specular's tint and weight (PATINA_SPECULAR; hasSpecularTint), and with
    // KHR_materials_iridescence's thin film (PATINA_IRIDESCENCE; hasIridescence). Bits: Maps,
    // Clearcoat, Sheen, Transmission, AmbientOcclusion, Anisotropy, VertexColors, Specular and
    // Iridescence combine (surfaceOf).
    enum class Surface {
        Factors = 0, Maps = 1, Clearcoat = 2, Sheen = 4, Transmission = 8, AmbientOcclusion = 16, Anisotropy = 32,
        VertexColors = 64, Specular = 128, Iridescence = 256
    };
    static Surface surfaceOf(bool maps, bool clearcoat, bool sheen, bool transmission = false,
                             bool ambientOcclusion = false, bool anisotropy = false, bool vertexColors = false,
                             bool specular = false, bool iridescence = false) {
        return Surface((maps ? int(Surface::Maps) : 0) | (clearcoat ? int(Surface::Clearcoat) : 0) |
                       (sheen ? int(Surface::Sheen) : 0) | (transmission ? int(Surface::Transmission) : 0) |
                       (ambientOcclusion ? int(Surface::AmbientOcclusion) : 0) |
                       (anisotropy ? int(Surface::Anisotropy) : 0) | (vertexColors ? int(Surface::VertexColors) : 0) |
                       (specular ? int(Surface::Specular) : 0) | (iridescence ? int(Surface::Iridescence) : 0));
    }
    static bool has(Surface surface, Surface part) { return (int(surface) & int(part)) != 0; }

    ShadingPrograms() = default;
    ~ShadingPrograms();
    ShadingPrograms(const ShadingPrograms&) = delete;
    ShadingPrograms& operator=(const ShadingPrograms&) = delete;

    // Makes the program current (with its energy table, and with `environment` its environment
    // BRDF table, bound) and returns it. Multi with `environment` shades the environment when
    // uLightIndex < 0.
    // `shadows`: PATINA_SHADOWS (multi: a light's pass reads its shadow map, if it has one).
    const GlProgram& use(BrdfModelId model, Use use, Output output = Output::Linear, bool environment = false,
                         Surface surface = Surface::Factors, bool shadows = false);
    // Texture units of the environment's cube maps and BRDF table (unit 0 is the display pass's,
    // 1 the energy table's).
    static constexpr int kEnvironmentMapUnit = 2;
    static constexpr int kEnvironmentBrdfUnit = 3;
    static constexpr int kEnvironmentSourceUnit = 4;       // the stochastic mode's source chain
    static constexpr int kEnvironmentIrradianceUnit = 5;   // the irradiance map
    static constexpr int kFirstMapUnit = 6;                // Surface::Maps: the maps' units (SurfaceMap order)
    // The sheen's albedo table (Surface::Sheen), after the maps' seventeen units: 16 and up are
    // beyond GL 3.3's least GL_MAX_TEXTURE_IMAGE_UNITS (16) but within every GL 4 desktop
    // driver's (32: Mesa, NVIDIA, AMD, Intel), and a program binds only the units it reads.
    static constexpr int kSheenTableUnit = 23;
    static constexpr int kShadowMapUnit = 24;   // PATINA_SHADOWS: the shadow maps (gl/shadow_maps.h)
    static constexpr int kSceneBehindUnit = 25;   // PATINA_TRANSMISSION: gl/scene_behind.h's image
    static constexpr int kShadowDepthUnit = 26;   // PATINA_SHADOWS: the same maps' raw depths (PCSS)
    // How programs with an environment shade it from now on; a change drops the programs
    // compiled for another (the editor changes it rarely, benchmarks once per method).
    void setEnvironmentShading(const EnvironmentShading& shading);
    const EnvironmentShading& environmentShading() const { return environmentShading_; }
    const GlProgram& useSingle(BrdfModelId model, const SinglePass& pass, Output output = Output::Linear,
                               Surface surface = Surface::Factors);
    // The single-pass program specialised to `key`, compiled on first use. The least recently
    // used of more than kSpecialisedCapacity is deleted: an artist adding and removing lights
    // makes a new key each time. Never one used since beginFrame: a frame of items with many
    // map sets holds a program for each while it draws.
    const GlProgram& useSpecialised(BrdfModelId model, const ShaderSpecialisation& key,
                                    Output output = Output::Linear, Surface surface = Surface::Factors);
    static constexpr size_t kSpecialisedCapacity = 16;
    // Makes `program`, one that use, useSingle or useSpecialised returned for `model`, current
    // again with that model's tables bound: a frame whose items have several BRDF models
    // switches between their programs (each model has its own tables on the same units).
    const GlProgram& bind(BrdfModelId model, const GlProgram& program, bool environment);
    // From here on the programs useSpecialised returns are the frame's, and stay.
    void beginFrame() { frameStart_ = useCount_ + 1; }
    size_t specialisedCount() const { return specialised_.size(); }

private:
    struct Specialised {
        std::unique_ptr<GlProgram> program;
        unsigned long long lastUse = 0;
    };
    std::map<std::tuple<BrdfModelId, Use, Output, bool, Surface, bool>, std::unique_ptr<GlProgram>> programs_;
    // 48 shapes at most (with no point, sphere or tube light, karisPoints is always true), each
    // with and without the environment.
    std::map<std::tuple<BrdfModelId, SinglePass, Output, Surface>, std::unique_ptr<GlProgram>> singles_;
    std::map<std::tuple<BrdfModelId, ShaderSpecialisation, Output, Surface>, Specialised> specialised_;
    unsigned long long useCount_ = 0;
    unsigned long long frameStart_ = ~0ull;   // uses from here on are the current frame's (none before a frame)
    EnvironmentShading environmentShading_;
    std::map<BrdfModelId, unsigned> energyTextures_, environmentBrdfTextures_;
    unsigned sheenTexture_ = 0;   // sheen_table.h's, made on the first sheened program's use

    unsigned energyTexture(BrdfModelId model);
    unsigned sheenTexture();
    unsigned environmentBrdfTexture(BrdfModelId model);
    std::unique_ptr<GlProgram> build(BrdfModelId model, Output output, Surface surface,
                                     const std::vector<const char*>& vertexParts, std::vector<std::string> defines);
};

}  // namespace patina
