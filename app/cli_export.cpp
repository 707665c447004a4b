#include <iostream>
#include <memory>

#include "cli.h"
#include "gltf/export.h"
#include "gltf/model_export.h"
#include "io/file_kinds.h"
#include "files/input_error.h"
#include "inputs.h"
#include "shading/brdf_models.h"

namespace patina::cli {

namespace {
// glTF keeps no BRDF model: whatever shaded a material here, an engine shows the exported factors
// with glTF's own BRDF (Appendix B, Patina's `gltf`). Said where one was shaded otherwise.
void noteOtherModels(const Scene& scene, const Model* model) {
    std::vector<std::string> names;
    auto other = [&](const Material& material) {
        const BrdfModelId shown = model && scene.modelBrdf ? *scene.modelBrdf : material.model;
        if (shown != BrdfModelId::Gltf) {
            names.push_back("\"" + material.name + "\" (" + std::string(brdfModel(shown).name) + ")");
        }
    };
    if (!model) {
        other(scene.material);
    } else {
        for (size_t i = 0; i < model->materials.size(); ++i) {
            Material part;
            static_cast<MaterialParameters&>(part) = tunedMaterial(scene, int(i), model->materials[i]).factors;
            part.name = model->materials[i].name;
            other(part);
        }
    }
    if (!names.empty()) {
        std::cerr << "export: shaded here with another model than glTF's own BRDF, which every glTF viewer uses: "
                  << names.front() << (names.size() > 1 ? " and " + std::to_string(names.size() - 1) + " more" : "")
                  << "; the factors are written as they are (open the export, or choose the model gltf, to see "
                     "them as a viewer will)\n";
    }
}
}  // namespace

Command addExportCommand(CLI::App& app) {
    struct Options {
        SceneInputs inputs;
        std::string out;
        bool binFile = false;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand(
        "export", "Write a mesh with a material, or a glTF model with its tuned materials, as glTF 2.0 (.gltf or .glb)");
    options->inputs.addOptions(*command, true, true);
    command->add_option("--out", options->out, "Output .gltf or .glb")
        ->required()
        ->check(CLI::Validator(
            [](const std::string& path) {
                return gltfExtension(path).empty() ? std::string("must end in .gltf or .glb") : std::string();
            },
            "F.gltf|F.glb"));
    command->add_flag("--bin", options->binFile, "With .gltf: the buffer in F.bin beside it, not a data: URI");
    return [options] {
        Scene scene = options->inputs.load();
        options->inputs.replaceMesh(scene);   // no camera nor lights in the file: nothing to fit
        const GltfBuffer buffer = options->binFile ? GltfBuffer::BinFile : GltfBuffer::Embedded;
        AssetCache assets;
        try {
            if (scene.meshFile.empty()) {
                options->inputs.putMaterialOnParts(scene, nullptr);   // refuses a --part
                exportGltf(options->out, *assets.mesh(scene), scene.material, buffer);
                noteOtherModels(scene, nullptr);
            } else {
                // The whole model: every part with its maps, as the scene tunes it.
                const std::shared_ptr<const Model> model = assets.shape(scene).model;   // its maps replaced
                printWarnings(model->notes);   // what the import left out stays out of the export
                options->inputs.putMaterialOnParts(scene, model.get());
                exportGltfModel(options->out, tunedModel(*model, scene), buffer);
                noteOtherModels(scene, model.get());
            }
        } catch (const InputError&) {
            throw;
        } catch (const std::runtime_error& error) {
            throw InputError(error.what());   // an unwritable path, as for every command
        }
    };
}

}  // namespace patina::cli
