// Blender 3.4's export of every layer (tests/data/layers/layers.glb; issue 36, item 6) as Patina
// draws it: each layered sphere differs from its twin's material drawn in its place (an edit of
// its material, as the editor makes) where its layer should show, in the direction the layer
// goes, under the studio environment alone.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "gl/renderer.h"
#include "gltf/blender_layers.h"
#include "gltf/model_import.h"
#include "common/luminance.h"
#include "test_support.h"

namespace patina {
namespace {

using test::BlenderLayer;

constexpr int kWidth = 256, kHeight = 128;

// The grid seen straight on from far away (nearly orthographic: every sphere seen alike), lit by
// the default scene's studio environment only.
Scene gridScene(const Model& model) {
    Scene scene = defaultScene();
    scene.meshFile = test::blenderLayersFile().string();
    std::erase_if(scene.lights, [](const Light& light) { return light.type != LightType::Environment; });
    const glm::vec3 first(model.draws.front().transform[3]), last(model.draws.back().transform[3]);
    const glm::vec3 centre = 0.5f * (first + last);
    scene.camera.target = centre;
    scene.camera.position = centre + glm::vec3(0.0f, 0.0f, 60.0f);
    scene.camera.fovYDegrees = 6.0f;
    return scene;
}

// The sphere's front seen at a grid of points within 0.8 of its radius, in one order for all.
std::vector<glm::vec3> front(const HdrImage& image, const Camera& camera, glm::vec3 centre) {
    std::vector<glm::vec3> seen;
    for (float x = -0.8f; x <= 0.81f; x += 0.1f) {
        for (float y = -0.8f; y <= 0.81f; y += 0.1f) {
            if (x * x + y * y <= 0.64f) {
                const glm::vec3 point = centre + glm::vec3(x, y, std::sqrt(1.0f - x * x - y * y));
                const glm::ivec2 at = test::pixelOf(camera, point, image.width, image.height);
                seen.push_back(test::pixel(image, at.x, at.y));
            }
        }
    }
    return seen;
}

struct Difference {
    glm::vec3 meanAbsolute{0.0f};   // per channel, over the points
    glm::vec3 meanSigned{0.0f};     // a minus b
};
Difference differenceOf(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
    Difference d;
    for (size_t i = 0; i < a.size(); ++i) {
        d.meanAbsolute += glm::abs(a[i] - b[i]) / float(a.size());
        d.meanSigned += (a[i] - b[i]) / float(a.size());
    }
    return d;
}

RenderSettings settings() { return test::renderSettings(kWidth, kHeight, RenderPath::Specialised, 1); }

class BlenderLayersRender : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        test::glContext();
        model_ = new Model(importGltfModel(test::blenderLayersFile()));
        scene_ = new Scene(gridScene(*model_));
        Renderer renderer;
        image_ = new HdrImage(renderer.render(test::prepared(*scene_), settings()).hdr);
    }
    static void TearDownTestSuite() {
        delete image_;
        delete scene_;
        delete model_;
    }
    static std::vector<glm::vec3> sphere(BlenderLayer layer, const HdrImage& image) {
        return front(image, scene_->camera, glm::vec3(model_->draws[size_t(layer)].transform[3]));
    }
    // The grid again with `layer`'s material made its twin's (an edit, as the editor makes):
    // the sphere in its own place, so that only the layer differs.
    static HdrImage withTwinAt(BlenderLayer layer, BlenderLayer twin) {
        Scene scene = *scene_;
        ModelMaterialEdit edit;
        edit.index = layer;
        static_cast<MaterialParameters&>(edit.material) = model_->materials[size_t(twin)].factors;
        edit.material.name = model_->materials[size_t(layer)].name;
        scene.modelMaterials = {edit};
        Renderer renderer;
        return renderer.render(test::prepared(scene), settings()).hdr;
    }
    // The layered sphere against its twin drawn in its place.
    static Difference against(BlenderLayer layer, BlenderLayer twin) {
        const HdrImage twinned = withTwinAt(layer, twin);
        // Nothing else changes.
        const BlenderLayer other = layer == test::kPlain ? test::kVolume : test::kPlain;
        EXPECT_EQ(differenceOf(sphere(other, *image_), sphere(other, twinned)).meanAbsolute, glm::vec3(0.0f));
        return differenceOf(sphere(layer, *image_), sphere(layer, twinned));
    }
    static inline Model* model_ = nullptr;
    static inline Scene* scene_ = nullptr;
    static inline HdrImage* image_ = nullptr;
};

// The opaque row on one red base: a coat and a whitish sheen add white light (green and blue
// rise, where the red base has little). Measured: the coat adds 0.017 to green on average, the
// sheen 0.042 (linear radiance, the sphere's front within 0.8 of its radius). The specular's F0
// (0.134, 0.058, 0.052) against the twin's 0.04 (S9) reflects red above all, while its diffuse
// keeps 1 - the red channel's F (max_value): red rises (0.0068), green and blue far less.
TEST_F(BlenderLayersRender, EachOpaqueLayerAddsItsWhiteLightToTheRedTwin) {
    for (BlenderLayer layer : {test::kClearcoat, test::kSheen}) {
        const Difference d = against(layer, test::kPlain);
        SCOPED_TRACE(test::kBlenderLayerNames[layer]);
        EXPECT_GT(d.meanSigned.g, 0.005f);
        EXPECT_GT(d.meanSigned.b, 0.005f);
    }
    const Difference specular = against(test::kSpecular, test::kPlain);
    EXPECT_GT(specular.meanSigned.r, 0.004f);
    EXPECT_GT(specular.meanSigned.r, 4.0f * std::abs(specular.meanSigned.g));
}

// The row that passes light, against the smooth clear transmission: a rougher one blurs what
// is seen through (here brighter: the studio's bright windows spread across it); IOR 2.4
// (F0 0.17) reflects more and passes less; the volume's attenuation colour
// (1, 0.6, 0.2) takes blue most, green less, red none. Measured: 0.160, 0.019 and
// (0.000, -0.151, -0.191) apart.
TEST_F(BlenderLayersRender, EachTransmissiveLayerChangesWhatIsSeenThrough) {
    const Difference rough = against(test::kRoughTransmission, test::kTransmission);
    EXPECT_GT(luminance(rough.meanAbsolute), 0.01f);
    const Difference ior = against(test::kIor, test::kTransmission);
    EXPECT_GT(luminance(ior.meanAbsolute), 0.005f);
    const Difference volume = against(test::kVolume, test::kTransmission);
    EXPECT_LT(volume.meanSigned.b, volume.meanSigned.g);
    EXPECT_LT(volume.meanSigned.g, -0.02f);
    EXPECT_LT(std::abs(volume.meanSigned.r), 0.5f * std::abs(volume.meanSigned.b));
}

// The clear transmission against itself made opaque (an edit of its transmission to 0): what
// the wall passes is the environment behind, not its white diffuse.
TEST_F(BlenderLayersRender, TheTransmissionShowsWhatIsBehindInsteadOfItsDiffuse) {
    Scene opaque = *scene_;
    ModelMaterialEdit edit;
    edit.index = test::kTransmission;
    static_cast<MaterialParameters&>(edit.material) = model_->materials[test::kTransmission].factors;
    edit.material.name = model_->materials[test::kTransmission].name;
    edit.material.transmission = 0.0f;
    opaque.modelMaterials = {edit};
    Renderer renderer;
    const HdrImage image = renderer.render(test::prepared(opaque), settings()).hdr;
    const Difference d = differenceOf(sphere(test::kTransmission, *image_), sphere(test::kTransmission, image));
    EXPECT_GT(luminance(d.meanAbsolute), 0.05f);
    // The other spheres are drawn as before.
    EXPECT_EQ(differenceOf(sphere(test::kPlain, *image_), sphere(test::kPlain, image)).meanAbsolute, glm::vec3(0.0f));
}

}  // namespace
}  // namespace patina
