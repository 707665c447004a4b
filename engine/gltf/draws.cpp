#include "gltf/draws.h"

#include <map>

#include <glm/mat3x3.hpp>

#include "gltf/cameras.h"
#include "gltf/nodes.h"
#include "gltf/primitives.h"
#include "files/input_error.h"
#include "model/placement.h"

namespace patina::gltf {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& what) {
    throw InputError(source + ": " + what);
}

[[noreturn]] void tooLarge(const std::string& source) {
    fail(source, "the scene has more than " + std::to_string(kGltfMaxVertices) + " vertices or " +
                     std::to_string(kGltfMaxTriangles) + " triangles (Patina's limit)");
}

constexpr int kUnseen = -1, kSkipped = -2;

// The primitives not drawn, by why: one note for each reason.
struct Skipped {
    size_t count = 0;
    std::string first;
};

class GeometryBuilder {
public:
    GeometryBuilder(const tinygltf::Model& document, const std::string& source)
        : document_(document), source_(source), slots_(document.meshes.size()) {}

    // Every primitive of the instance's mesh: planned the first time it is met, drawn if it can be.
    void addInstance(const MeshInstance& instance) {
        std::vector<int>& slots = slots_[size_t(instance.mesh)];
        slots.resize(document_.meshes[size_t(instance.mesh)].primitives.size(), kUnseen);
        for (size_t p = 0; p < slots.size(); ++p) {
            if (slots[p] == kUnseen) {
                slots[p] = plan(instance.mesh, int(p));
            }
            if (slots[p] != kSkipped) {
                addDraw(instance, slots[p]);
            }
        }
    }

    Model finish() {
        if (triangles_ == 0) {
            fail(source_, "the scene has no triangles");
        }
        for (const auto& [why, skipped] : skipped_) {
            model_.notes.push_back(skipped.first + (skipped.count > 1 ? " and " + std::to_string(skipped.count - 1) +
                                                                            " more" : "") +
                                   ": " + why + ", not drawn" + (why == "no POSITION" ? "" : " (Patina draws triangles)"));
        }
        model_.primitives.reserve(plans_.size());
        for (const PrimitivePlan& plan : plans_) {
            model_.primitives.push_back(readPrimitive(plan, source_));
        }
        // Flat normals may have copied vertices: counted again.
        size_t vertices = 0;
        for (const DrawItem& draw : model_.draws) {
            vertices += model_.primitives[size_t(draw.primitive)].positions.size();
        }
        if (vertices > kGltfMaxVertices) {
            tooLarge(source_);
        }
        return std::move(model_);
    }

private:
    int plan(int mesh, int primitive) {
        const std::string where = "/meshes/" + std::to_string(mesh) + "/primitives/" + std::to_string(primitive);
        const std::string why = whyNotDrawn(document_.meshes[size_t(mesh)].primitives[size_t(primitive)], where, source_);
        if (!why.empty()) {
            Skipped& skipped = skipped_[why];
            skipped.first = skipped.count++ == 0 ? where : skipped.first;
            return kSkipped;
        }
        plans_.push_back(planPrimitive(document_, mesh, primitive, source_));
        return int(plans_.size()) - 1;
    }

    void addDraw(const MeshInstance& instance, int slot) {
        if (model_.draws.size() == kGltfMaxPrimitives) {
            fail(source_, "the scene draws more than " + std::to_string(kGltfMaxPrimitives) +
                              " mesh primitives (Patina's limit)");
        }
        const PrimitivePlan& plan = plans_[size_t(slot)];
        vertices_ += plan.positions.count;
        triangles_ += plan.triangles;
        if (vertices_ > kGltfMaxVertices || triangles_ > kGltfMaxTriangles) {
            tooLarge(source_);
        }
        DrawItem draw;
        draw.primitive = slot;
        draw.material = plan.material;
        draw.transform = glm::mat4(instance.world);
        draw.node = nodeName(document_, instance.node);
        // Of the float matrix the renderer gets, in double: it grows as the cube of the scale.
        draw.mirrored = mirrors(draw.transform);
        model_.draws.push_back(std::move(draw));
    }

    const tinygltf::Model& document_;
    const std::string& source_;
    std::vector<std::vector<int>> slots_;   // per mesh and primitive: its plan, kUnseen or kSkipped
    std::vector<PrimitivePlan> plans_;
    std::map<std::string, Skipped> skipped_;
    size_t vertices_ = 0, triangles_ = 0;
    Model model_;
};

}  // namespace

Model modelGeometry(const tinygltf::Model& document, const std::string& source) {
    GeometryBuilder builder(document, source);
    const SceneInstances instances = sceneInstances(document, source);
    for (const MeshInstance& instance : instances.meshes) {
        builder.addInstance(instance);
    }
    Model model = builder.finish();
    model.cameras = modelCameras(document, instances.cameras, model.notes);
    return model;
}

}  // namespace patina::gltf
