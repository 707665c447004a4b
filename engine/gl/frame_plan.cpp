#include "gl/frame_plan.h"

#include <algorithm>

#include "gl/shader_specialisation.h"
#include "model/placement.h"

namespace patina {

int stripRowsFor(const RenderSettings& settings, int samples) {
    const int h = settings.height;
    if (settings.maxTargetBytes == 0) {
        return h;
    }
    constexpr int kMaxStrips = 16;
    const size_t bytesPerRow = size_t(settings.width) * size_t(samples) * 4 * sizeof(float);
    return std::max(int(std::clamp<size_t>(settings.maxTargetBytes / bytesPerRow, 1, size_t(h))),
                    (h + kMaxStrips - 1) / kMaxStrips);
}

size_t flatLightSlotsFor(RenderSettings::FlatLights mode, size_t slots, const PixelRect& meshBox,
                         const PixelRect& drawnArea, int stripRows, size_t triangles) {
    if (mode != RenderSettings::FlatLights::WherePaying) {
        return mode == RenderSettings::FlatLights::Always ? slots : 0;
    }
    if (meshBox.empty() || drawnArea.empty()) {
        return 0;
    }
    const int draws = (drawnArea.y1 - 1) / stripRows - drawnArea.y0 / stripRows + 1;
    const double pixels = double(meshBox.x1 - meshBox.x0) * double(meshBox.y1 - meshBox.y0);
    return flatLightsPay(pixels, double(triangles) * draws) ? slots : 0;
}

namespace {
PixelRect unite(const PixelRect& a, const PixelRect& b) {
    if (a.empty() || b.empty()) {
        return a.empty() ? b : a;
    }
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

// The faces `item` leaves out, seen through `clip` (the view-projection times its transform).
HiddenFaces culledFaces(const RenderSettings& settings, const glm::mat4& clip, const DrawFacts& item) {
    if (!item.doubleSided) {
        return HiddenFaces::Back;   // glTF 2.0 §3.9.5: back-face culling is on
    }
    // A box beyond the near plane holds the whole mesh, so the eye is outside it. Each item's
    // own faces hide its culled side, whatever else is drawn.
    return settings.cullHiddenFaces && beyondNearPlane(clip, item.mesh.bounds) ? item.mesh.culling.hidden
                                                                              : HiddenFaces::None;
}

// The view depth (clip w) of the centre of `item`'s transformed bounds: what orders the
// blended items, farthest first.
float viewDepth(const glm::mat4& viewProjection, const DrawFacts& item) {
    const glm::vec3 centre = 0.5f * (item.mesh.bounds.low + item.mesh.bounds.high);
    return (viewProjection * (item.transform * glm::vec4(centre, 1.0f))).w;
}

// Each item's plan, in drawing order, and the union of their boxes on screen.
void planItems(FramePlan& plan, const RenderSettings& settings, std::span<const DrawFacts> items) {
    std::vector<std::pair<float, DrawPlan>> blended;
    for (size_t i = 0; i < items.size(); ++i) {
        const glm::mat4 clip = plan.transform * items[i].transform;
        plan.meshBox = unite(plan.meshBox, screenBounds(clip, items[i].mesh.bounds, settings.width, settings.height));
        const DrawPlan item{i, culledFaces(settings, clip, items[i]), mirrors(items[i].transform)};
        if (items[i].blend) {
            blended.push_back({viewDepth(plan.transform, items[i]), item});
        } else {
            plan.items.push_back(item);
        }
    }
    std::stable_sort(blended.begin(), blended.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    for (const auto& [depth, item] : blended) {
        plan.items.push_back(item);
    }
    plan.blending = !blended.empty();
}
}  // namespace

FramePlan planFrame(const RenderSettings& settings, const Camera& camera, std::span<const DrawFacts> items,
                    int maxSamples, size_t flatLightSlots) {
    FramePlan plan;
    const int w = settings.width, h = settings.height;
    plan.samples = std::clamp(settings.samples, 0, maxSamples);
    plan.msaa = plan.samples > 1;
    plan.transform = viewProjection(camera, float(w) / float(h));
    planItems(plan, settings, items);
    plan.displayInPass = !plan.msaa && settings.path != RenderPath::Multi && !plan.blending;
    plan.keepLinear = settings.readHdr || (!plan.msaa && !plan.displayInPass);
    // Without MSAA the shading pass draws into the full-size images: strips would save nothing.
    plan.stripRows = plan.msaa ? stripRowsFor(settings, plan.samples) : h;
    // With MSAA, samples only where the mesh can be: most of a frame is often background, and
    // there a sample costs a store and a resolve for nothing.
    const PixelRect whole{0, 0, w, h};
    plan.meshArea = plan.msaa && settings.cropToMesh ? plan.meshBox : whole;
    // One convex part with a side culled: no two faces share a sample, so the depth test
    // decides nothing, and its clear and per-sample test are saved (llvmpipe, 4x MSAA: a
    // 512x512 frame of the default sphere 17.5 ms against 13.5). Only for one item: two
    // items' faces may share a sample.
    plan.depthTest = !(items.size() == 1 && plan.items[0].culled != HiddenFaces::None && items[0].mesh.culling.convex);
    size_t triangles = 0;
    for (const DrawFacts& item : items) {
        triangles += item.mesh.triangles;
    }
    plan.flatLightCount = flatLightSlotsFor(settings.flatLightUse, flatLightSlots, plan.meshBox, plan.meshArea,
                                            plan.stripRows, triangles);
    return plan;
}

FramePlan planFrame(const RenderSettings& settings, const Camera& camera, const MeshFacts& mesh,
                    int maxSamples, size_t flatLightSlots) {
    const DrawFacts item{mesh};
    return planFrame(settings, camera, std::span(&item, 1), maxSamples, flatLightSlots);
}

}  // namespace patina
