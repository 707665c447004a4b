#pragma once
#include <cstddef>

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

// What a draw needs to know of its mesh (MeshBuffers keeps it for the uploaded one).
struct MeshFacts {
    BoundingBox bounds;
    FaceCulling culling;
    size_t triangles = 0;
};

// What one draw does, decided from its settings, camera, mesh and the GL's limits before any
// GL call; Renderer::draw carries it out. No GL here, so each decision is tested on its own.
struct FramePlan {
    int samples = 0;   // the settings' count, clamped to what the GL offers
    bool msaa = false;
    // Without MSAA, single and specialised write display values in the shading pass; multi
    // must sum its passes first, and MSAA must resolve first (tone mapping is not linear).
    bool displayInPass = false;
    // The full-size linear image: asked for (RenderSettings::readHdr), or multi's sum
    // without MSAA.
    bool keepLinear = false;
    int stripRows = 0;   // rows per MSAA strip; the height without MSAA
    glm::mat4 transform{1.0f};
    PixelRect meshBox;    // every pixel the mesh can cover
    PixelRect meshArea;   // the pixels shaded: the mesh's box with MSAA and cropToMesh, else all
    HiddenFaces culled = HiddenFaces::None;   // the faces left out
    bool depthTest = true;
    size_t flatLightCount = 0;   // lights a specialised draw takes as flat inputs
};
FramePlan planFrame(const RenderSettings& settings, const Camera& camera, const MeshFacts& mesh,
                    int maxSamples, size_t flatLightSlots);

}  // namespace patina
