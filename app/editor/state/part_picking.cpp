#include "state/part_picking.h"

#include <cmath>
#include <string>

#include <glm/matrix.hpp>

#include "state/editor_state.h"
#include "geometry/silhouette.h"
#include "model/pick.h"
#include "scene/view.h"

namespace patina::editor {

struct PartOutlineCache {
    std::shared_ptr<const Model> model;
    int material = -1;
    std::vector<std::pair<glm::mat4, EdgeFaces>> draws;   // the part's draws: transform, edges
    glm::vec3 eye{NAN};
    std::vector<Segment> segments;
};

bool pickPart(const Document& document, Interaction& interaction, Prompts& prompts, glm::vec2 ndc, float aspect) {
    if (!document.model) {
        return false;
    }
    // The ray through the pixel: its points on the near and far planes, back through the view.
    const glm::mat4 inverse = glm::inverse(viewProjection(document.scene.camera, aspect));
    const glm::vec4 nearPoint = inverse * glm::vec4(ndc, -1.0f, 1.0f), farPoint = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 origin = glm::vec3(nearPoint) / nearPoint.w;
    const DrawHit hit = firstDrawHit(*document.model, origin, glm::vec3(farPoint) / farPoint.w - origin);
    if (hit.draw < 0) {
        return false;
    }
    const DrawItem& item = document.model->draws[size_t(hit.draw)];
    if (item.material < 0) {
        prompts.status =
            "That part (" + item.node + ") has glTF's default material, which the file gives no values to tune";
        return false;
    }
    interaction.selectedModelMaterial = item.material;
    prompts.status =
        "Selected the part \"" + document.model->materials[size_t(item.material)].name + "\" (" + item.node + ")";
    return true;
}

const std::vector<Segment>& partOutline(const Document& document, Interaction& interaction) {
    static const std::vector<DrawItem> kNoDraws;   // without a model (a reference: no copy of the draws)
    if (!interaction.partOutline) {
        interaction.partOutline = std::make_shared<PartOutlineCache>();
    }
    PartOutlineCache& cache = *interaction.partOutline;
    if (cache.model != document.model || cache.material != interaction.selectedModelMaterial) {
        cache = PartOutlineCache{};
        cache.model = document.model;
        cache.material = interaction.selectedModelMaterial;
        for (const DrawItem& item : document.model ? document.model->draws : kNoDraws) {
            if (item.material == cache.material && size_t(item.primitive) < document.model->primitives.size()) {
                cache.draws.emplace_back(item.transform, edgeFaces(document.model->primitives[size_t(item.primitive)]));
            }
        }
    }
    const glm::vec3 eye = document.scene.camera.position;
    if (eye != cache.eye) {
        cache.eye = eye;
        cache.segments.clear();
        for (const auto& [transform, edges] : cache.draws) {
            for (const auto& [a, b] : silhouetteEdges(edges, glm::vec3(glm::inverse(transform) * glm::vec4(eye, 1.0f)))) {
                cache.segments.emplace_back(glm::vec3(transform * glm::vec4(a, 1.0f)),
                                            glm::vec3(transform * glm::vec4(b, 1.0f)));
            }
        }
    }
    return cache.segments;
}

}  // namespace patina::editor
