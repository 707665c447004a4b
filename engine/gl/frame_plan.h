#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>

#include "geometry/hidden_faces.h"
#include "geometry/mesh.h"
#include "scene/scene.h"
#include "scene/view.h"
#include "gl/renderer.h"

namespace patina {

// Rows per strip of an MSAA draw of `samples` samples: as many as settings.maxTargetBytes of
// multisampled colour allows, but never more than 16 strips (each draws the whole mesh); the
// whole height when maxTargetBytes is 0.
int stripRowsFor(const RenderSettings& settings, int samples);

// How many of `slots` lights a specialised draw takes as flat inputs under `mode`: with
// WherePaying, all where flatLightsPay (shader_specialisation.h) says so for the pixels of
// `meshBox` (what the mesh can cover) and the mesh's triangles drawn once per strip of
// `stripRows` rows that meets `drawnArea` (the scissored area), otherwise none.
size_t flatLightSlotsFor(RenderSettings::FlatLights mode, size_t slots, const PixelRect& meshBox,
                         const PixelRect& drawnArea, int stripRows, size_t triangles);

// What a draw needs to know of a mesh (MeshBuffers keeps it for each uploaded one).
struct MeshFacts {
    BoundingBox bounds;
    FaceCulling culling;
    size_t triangles = 0;
};

// One draw item as the plan sees it (scene/prepared_scene.h's SceneDraw): its primitive's
// facts, in the primitive's own space, and how it is placed and drawn.
struct DrawFacts {
    MeshFacts mesh;
    glm::mat4 transform{1.0f};
    bool doubleSided = true;   // false: back faces culled (glTF 2.0 §3.9.5)
    bool blend = false;        // drawn after the opaque items, back to front
};

// How one item is drawn.
struct DrawPlan {
    size_t item = 0;   // its index in the draw list
    // The faces left out, by the primitive's own winding: its back faces when single-sided,
    // else the side a closed mesh hides from an eye outside it (hidden_faces.h), else none.
    HiddenFaces culled = HiddenFaces::None;
    // A mirroring transform (negative determinant): the primitive's front faces wind clockwise
    // on screen (glTF 2.0 §3.7.2.1), so GL's front face is GL_CW for it.
    bool frontClockwise = false;
};

// What one draw does, decided from its settings, camera, mesh and the GL's limits before any
// GL call; Renderer::draw carries it out. No GL here, so each decision is tested on its own.
struct FramePlan {
    int samples = 0;   // the settings' count, clamped to what the GL offers
    bool msaa = false;
    // Without MSAA, single and specialised write display values in the shading pass; multi
    // must sum its passes first, MSAA must resolve first (tone mapping is not linear), and a
    // blended item must be composited over what is behind it in linear light first.
    bool displayInPass = false;
    // The full-size linear image: asked for (RenderSettings::readHdr), or multi's sum
    // without MSAA.
    bool keepLinear = false;
    int stripRows = 0;   // rows per MSAA strip; the height without MSAA
    glm::mat4 transform{1.0f};
    PixelRect meshBox;    // every pixel an item can cover: the union of their boxes
    PixelRect meshArea;   // the pixels shaded: the items' box with MSAA and cropToMesh, else all
    // Every item in drawing order: the opaque ones in the list's order, then the blended ones
    // back to front (by the view depth of their transformed bounds' centres).
    std::vector<DrawPlan> items;
    bool blending = false;   // some item blends
    bool depthTest = true;
    size_t flatLightCount = 0;   // lights a specialised draw takes as flat inputs
};
FramePlan planFrame(const RenderSettings& settings, const Camera& camera, std::span<const DrawFacts> items,
                    int maxSamples, size_t flatLightSlots);
// One mesh drawn where it is, both sides: a built-in mesh's draw.
FramePlan planFrame(const RenderSettings& settings, const Camera& camera, const MeshFacts& mesh,
                    int maxSamples, size_t flatLightSlots);

}  // namespace patina
