#include "jobs.h"

#include "editor_state.h"

namespace patina::editor {

namespace {
// The loaded environment becomes the scene's (one undo step), adding a light if there is none.
void applyEnvironment(EditorState& state, const std::string& source, std::shared_ptr<const Environment> environment,
                      const std::vector<std::string>& warnings) {
    if (state.environmentIndex() < 0) {
        addLight(state, LightType::Environment);
    }
    const int index = state.environmentIndex();
    applyEdit(state, [&](Document& d) {
        Light& light = d.scene.lights[size_t(index)];
        // The light is named after its image until the artist names it.
        if (light.name == environmentName(light.source) || light.name == lightTypeName(LightType::Environment)) {
            light.name = environmentName(source);
        }
        light.source = source;
        d.environment = std::move(environment);   // kept while disabled, for the checkbox
    });
    state.selectedLight = index;
    state.environmentFailed.clear();
    state.error.clear();   // a load that worked: an older error is no longer news
    // Replaced pixels (real HDRIs hold a few slightly negative ones) are worth a note, not an
    // error box over the toolbar.
    state.status = "Environment " + environmentName(source) + (warnings.empty() ? "" : ": " + joinLines(warnings));
}
}  // namespace

bool setEnvironmentSource(EditorState& state, const std::string& source) {
    state.environmentLoad.reset();   // a newer choice replaces one under way (cancelled)
    if (!source.starts_with("builtin:")) {
        state.environmentLoad = std::make_shared<EnvironmentLoad>(source, state.assets);
        state.status = "Preparing the environment " + environmentName(source) + "...";
        return true;
    }
    std::vector<std::string> warnings;
    try {
        applyEnvironment(state, source, state.assets->environment(source, warnings), warnings);
        return true;
    } catch (const std::exception& error) {
        state.error = error.what();   // the previous environment stays
        return false;
    }
}

bool finishEnvironmentLoad(EditorState& state, bool wait) {
    if (!state.environmentLoad || (!wait && !state.environmentLoad->ready())) {
        return false;
    }
    const std::shared_ptr<EnvironmentLoad> load = std::move(state.environmentLoad);
    try {
        EnvironmentLoad::Result result = load->take();
        if (!result.environment) {
            return false;   // cancelled
        }
        applyEnvironment(state, load->source(), std::move(result.environment), result.warnings);
        return true;
    } catch (const std::exception& error) {
        state.error = error.what();   // the previous environment stays
        state.status.clear();
        return false;
    }
}

void resolveEnvironmentShown(EditorState& state) {
    const int index = state.environmentIndex();
    if (index < 0) {
        return;
    }
    const std::string& source = state.scene.lights[size_t(index)].source;
    const std::shared_ptr<const Environment>& loaded = state.environment;
    if ((loaded && loaded->source == source) || state.environmentFailed == source) {
        return;
    }
    std::vector<std::string> warnings;
    try {
        state.environment = state.assets->environment(source, warnings);
        state.environmentFailed.clear();
    } catch (const std::exception& error) {
        state.error = error.what();
        state.environmentFailed = source;
    }
}

}  // namespace patina::editor
