#include "state/jobs.h"

#include "state/editor_state.h"
#include "environment/builtin_environments.h"

namespace patina::editor {

namespace {
// The loaded environment becomes the scene's (one undo step), adding a light if there is none.
void applyEnvironment(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts,
                      const std::string& source, std::shared_ptr<const Environment> environment,
                      const std::vector<std::string>& warnings) {
    if (document.environmentIndex() < 0) {
        addLight(document, interaction, prompts, LightType::Environment);
    }
    const int index = document.environmentIndex();
    applyEdit(document, [&](Document& d) {
        Light& light = d.scene.lights[size_t(index)];
        // The light is named after its image until the artist names it.
        if (light.name == environmentName(light.source) || light.name == lightTypeName(LightType::Environment)) {
            light.name = environmentName(source);
        }
        light.source = source;
        d.environment = std::move(environment);   // kept while disabled, for the checkbox
    });
    interaction.selectedLight = index;
    jobs.environmentFailed.clear();
    prompts.error.clear();   // a load that worked: an older error is no longer news
    // Replaced pixels (real HDRIs hold a few slightly negative ones) are worth a note, not an
    // error box over the toolbar.
    prompts.status = "Environment " + environmentName(source) + (warnings.empty() ? "" : ": " + joinLines(warnings));
}
}  // namespace

bool setEnvironmentSource(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts,
                          const std::string& source) {
    jobs.environmentLoad.reset();   // a newer choice replaces one under way (cancelled)
    if (!builtinName(source)) {
        jobs.environmentLoad = std::make_shared<EnvironmentLoad>(source, jobs.assets);
        prompts.status = "Preparing the environment " + environmentName(source) + "...";
        return true;
    }
    std::vector<std::string> warnings;
    try {
        applyEnvironment(document, interaction, jobs, prompts, source,
                         jobs.assets->environment(source, warnings, {}, {}, jobs.uiPrefilter), warnings);
        return true;
    } catch (const std::exception& error) {
        prompts.error = error.what();   // the previous environment stays
        return false;
    }
}

bool finishEnvironmentLoad(Document& document, Interaction& interaction, Jobs& jobs, Prompts& prompts, bool wait) {
    if (!jobs.environmentLoad || (!wait && !jobs.environmentLoad->ready())) {
        return false;
    }
    const std::shared_ptr<EnvironmentLoad> load = std::move(jobs.environmentLoad);
    try {
        EnvironmentLoad::Result result = load->take();
        if (!result.environment) {
            return false;   // cancelled
        }
        applyEnvironment(document, interaction, jobs, prompts, load->source(), std::move(result.environment),
                         result.warnings);
        return true;
    } catch (const std::exception& error) {
        prompts.error = error.what();   // the previous environment stays
        prompts.status.clear();
        return false;
    }
}

void resolveEnvironmentShown(Document& document, Jobs& jobs, Prompts& prompts) {
    const int index = document.environmentIndex();
    if (index < 0) {
        return;
    }
    const std::string& source = document.scene.lights[size_t(index)].source;
    const std::shared_ptr<const Environment>& loaded = document.environment;
    if ((loaded && loaded->source == source) || jobs.environmentFailed == source) {
        return;
    }
    std::vector<std::string> warnings;
    try {
        document.environment = jobs.assets->environment(source, warnings, {}, {}, jobs.uiPrefilter);
        jobs.environmentFailed.clear();
    } catch (const std::exception& error) {
        prompts.error = error.what();
        jobs.environmentFailed = source;
    }
}

namespace {
// A bake no longer wanted ends on its own; dropping it never waits for it.
void dropOcclusionBake(Jobs& jobs) {
    std::erase_if(jobs.droppedOcclusionBakes, [](const auto& bake) { return bake->ready(); });
    if (jobs.occlusionBake) {
        jobs.droppedOcclusionBakes.push_back(std::move(jobs.occlusionBake));
    }
}
}  // namespace

void resolveAmbientOcclusion(Document& document, Jobs& jobs, Prompts& prompts, bool wait) {
    Scene& scene = document.scene;
    const bool file = !scene.meshFile.empty();
    if (!scene.display.ambientOcclusion || (file && !document.fileModel)) {   // off, or its model still loading
        document.occlusion.reset();
        dropOcclusionBake(jobs);
        return;
    }
    const AssetCache::Shape shape{file ? document.mesh() : builtinMesh(scene.mesh), file ? document.model : nullptr,
                                  file ? document.fileModel : nullptr};
    if ((document.occlusion = jobs.assets->heldAmbientOcclusion(scene, shape))) {
        dropOcclusionBake(jobs);
        return;
    }
    const bool ground = scene.display.ground != Ground::None;
    if (!jobs.occlusionBake || !jobs.occlusionBake->bakes(shape.mesh.get(), ground)) {
        dropOcclusionBake(jobs);
        jobs.occlusionBake = std::make_shared<OcclusionBake>(jobs.assets, scene, shape);
    }
    if (!wait && !jobs.occlusionBake->ready()) {
        return;
    }
    try {
        document.occlusion = std::exchange(jobs.occlusionBake, nullptr)->take();
    } catch (const std::exception& error) {
        prompts.error = std::string("Ambient occlusion is off: ") + error.what();
        scene.display.ambientOcclusion = false;
        document.occlusion.reset();
    }
}

}  // namespace patina::editor
