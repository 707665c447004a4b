#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "gl/environment_method.h"
#include "state/part_picking.h"
#include "gl/render_path.h"
#include "scene/channel.h"
#include "scene/scene.h"
#include "state/turntable.h"

namespace patina::editor {

struct Document;
struct Prompts;

enum class CompareView { Single, Split, SideBySide };
// What a viewport drag holds of a light: a point's or a sphere's position (a tube's middle,
// moving both ends), or one end of a tube.
enum class LightHandle { Position, TubeStart, TubeEnd };

// The lobe panel's views: the polar plot in the plane of incidence, and BRDF Explorer's (Burley
// 2012) image slice, albedo against theta_v and 3D lobe.
enum class LobeView { Polar, Slice, Albedo, Lobe3d };

struct LobeSettings {
    LobeView view = LobeView::Polar;
    float thetaInDegrees = 45.0f;
    bool followFirstDirectional = false;
    bool luminance = false;       // else per channel
    bool logScale = false;
    bool multiplyByCosine = false;
    // The slice: phi_d (Burley's default 90), exposure in stops, log scale, which lobe.
    float phiDDegrees = 90.0f;
    float sliceExposure = 0.0f;
    bool sliceLog = true;
    int sliceLobe = 0;   // SliceLobe: total, diffuse, specular, transmitted
    // The 3D lobe's orbit, degrees.
    float yawDegrees = 35.0f, pitchDegrees = 25.0f;
};

// The interaction: what the user is looking at and holding, which is no part of the document
// (not saved, not undone) and not kept between sessions: the selection, solo, the viewport's
// drags, the A/B comparison and how it is viewed, and how the picture is made.
struct Interaction {
    int selectedLight = 0;
    int selectedModelMaterial = 0;           // of the shown model: the one the Material panel edits
    PartOutlineCachePtr partOutline;         // its outline, kept while the eye stays (part_picking.h)
    std::string partFilter;                  // the Parts list's search box
    int partScrolledTo = -1;                 // the selection the Parts list last scrolled into view
    // The preset last applied to each part of the shown model, and the part's material as it
    // made it (labelledMaterial names a part with it while its values are still those).
    std::map<int, std::pair<std::string, Material>> partPresets;
    int soloLight = -1;                      // -1: all enabled lights
    // The toolbar's Camera list: the view last chosen there (or framing a model just opened),
    // named while the scene's camera stays on it; a drag leaves it "free".
    std::string cameraName;
    Camera cameraView;
    std::string bookmarkName;                // typed in the Camera list, for Save view
    Turntable turntable;                     // View > Turntable
    RenderPath renderPath = RenderPath::Single;

    std::optional<Material> compareA;        // "Set A"; B is the current material
    CompareView compareView = CompareView::Single;
    float splitPosition = 0.5f;              // split wipe divider, fraction of the width
    // The viewport's drags in progress: the light whose gizmo is held (-1: none), the divider.
    int draggedLight = -1;
    LightHandle draggedHandle = LightHandle::Position;   // which part of it
    bool draggingDivider = false;

    // How the environment is shaded in the viewport and screenshots (Advanced; not saved).
    EnvironmentShading environmentShading;
    LobeSettings lobe;
    // View > Channel: a debug channel the viewport shows instead of the picture (scene/channel.h;
    // channel -1: the picture). Screenshots stay the picture.
    ChannelRequest channel;
    // View > PBR validation overlay: the picture with the pbr-validation channel's flagged pixels
    // striped over it (channel.strictPbr: which ranges); the status line counts them.
    bool pbrOverlay = false;
    // View > Pixel read-out: hovering the picture (either side of a comparison) tells the pixel's story; a
    // click pins it, where in the picture as fractions of its size, so a pin stays on its
    // spot when the viewport is resized.
    bool pixelReadOut = false;
    std::vector<glm::vec2> pins;
};

void toggleSolo(Interaction& interaction, int index);
// The light a channel shows was renamed, removed or switched off: the picture again, and the
// status says why. The viewport calls it before it draws, after every panel that changes lights.
void keepChannelShowable(const Document& document, Interaction& interaction, Prompts& prompts);
// Whether solo leaves this light out of the picture (the list and the gizmos grey it out).
bool soloedOut(const Document& document, const Interaction& interaction, int index);
// The scene as rendered: solo applied.
Scene renderedScene(const Document& document, const Interaction& interaction);
// The material the Material panel edits: the selected one of a shown model (its tuning or the
// file's factors), else the scene's own.
Material editedMaterial(const Document& document, const Interaction& interaction);
// The same, named as the comparison labels and captions show it: a model's part that holds a
// preset as it was applied is named with it, "Texture (copper)" (a preset keeps the part's name,
// and both halves read "Texture"); once its values change, the part's name alone.
Material labelledMaterial(const Document& document, const Interaction& interaction);
// `material`'s values as the edited material of `scene` (a model's keeps the file's name).
void setEditedMaterial(const Document& document, const Interaction& interaction, Scene& scene,
                       const Material& material);
// The scene as rendered with another material in the edited one's place (a side of the
// comparison).
Scene withMaterial(const Document& document, const Interaction& interaction, const Material& material);

}  // namespace patina::editor
