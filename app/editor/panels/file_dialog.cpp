#include "panels/file_dialog.h"

#include <algorithm>
#include <cstdio>
#include <system_error>

#include <imgui.h>
#include <imgui_internal.h>

#include "storage/shown_path.h"
#include "views/text_match.h"
#include "window/ui_scale.h"
#include "window/widgets.h"

namespace patina::editor {

namespace {
// The folder part and the name part of what is typed: "a/b/go" is ("a/b", "go"), "a/b/" is
// ("a/b", ""), "go" is (".", "go").
std::pair<std::filesystem::path, std::string> splitTyped(const std::string& typed) {
    const size_t slash = typed.rfind('/');
    if (slash == std::string::npos) {
        return {".", typed};
    }
    return {slash == 0 ? std::filesystem::path("/") : std::filesystem::path(typed.substr(0, slash)),
            typed.substr(slash + 1)};
}

// Runs the action the dialog was opened for on `path`.
void confirm(EditorState& state, EditorServices& services, const std::filesystem::path& path) {
    switch (state.pathDialog) {
    case Prompts::PathDialog::Open: requestOpen(state, path); break;
    case Prompts::PathDialog::SaveAs: saveMaterial(state, state, state, path); break;
    case Prompts::PathDialog::SaveSceneAs: saveScene(state, state, state, path); break;
    case Prompts::PathDialog::SavePreset: saveAsPreset(state, state, state, state, path); break;
    case Prompts::PathDialog::ExportComparison: services.exportComparison(state, state, state, path); break;
    case Prompts::PathDialog::ExportGltf: exportGltfFile(state, state, path); break;
    case Prompts::PathDialog::ReplaceMap:
        replaceMap(state, *state.assets, state, state.replacedMaterial, state.replacedMap, path);
        break;
    case Prompts::PathDialog::None: break;
    }
}

// Characters typed before the path field has the keys (with the key that opened the dialog, and
// in the hidden frame a dialog's first opening sizes itself in) were lost: they are the path's
// start, replacing the path offered as typing over its selection does. Returns whether any were
// taken, so that the field's cursor goes after them when it takes the keys.
bool takeEarlyKeys(Prompts& prompts) {
    ImVector<ImWchar>& queue = ImGui::GetIO().InputQueueCharacters;
    if (prompts.pathFieldTaken || queue.empty()) {
        return false;
    }
    if (!prompts.pathTypedEarly) {
        prompts.pathDialogText.clear();
        prompts.pathTypedEarly = true;
    }
    for (ImWchar c : queue) {
        if (c >= 32 && c != 127) {
            char utf8[5];
            prompts.pathDialogText += ImTextCharToUtf8(utf8, c);
        }
    }
    queue.resize(0);
    return true;
}

// The folder's entries under its path, from the home folder where it is inside it (a relative
// one is in `base`, or the editor's working folder): a click on a folder enters it, on a file
// takes its path.
void drawListing(Prompts& prompts, const std::filesystem::path& base, ImVec2 size) {
    std::error_code error;
    const std::filesystem::path folder = typedFolder(prompts.pathDialogText, base);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + size.x);
    ImGui::TextDisabled("In %s", shownPath(folder).c_str());
    ImGui::PopTextWrapPos();
    recordItem("path:folder", "The folder listed below, where a relative path is");
    ImGui::BeginChild("listing", size, true);
    if (ImGui::Selectable("../")) {
        prompts.pathDialogText =
            (std::filesystem::absolute(folder, error).lexically_normal().parent_path() / "").string();
    }
    recordItem("path:up", "The folder above");
    for (const ListedEntry& entry : listForDialog(prompts.pathDialogText, prompts.pathDialog, base)) {
        const std::string name = entry.path.filename().string() + (entry.folder ? "/" : "");
        if (ImGui::Selectable(name.c_str())) {
            prompts.pathDialogText = entry.folder ? (entry.path / "").string() : entry.path.string();
        }
        recordItem("path:entry " + name, entry.folder ? "Open this folder" : "Choose this file");
    }
    ImGui::EndChild();
}
}  // namespace

const PathDialogKind& pathDialogKind(Prompts::PathDialog dialog) {
    static const PathDialogKind open{
        "Open", "Open a material or scene (.json), a Patina screenshot (.png), a glTF model (.gltf, .glb) "
                "or an environment image (.hdr, .exr):",
        "Open", {".json", ".png", ".gltf", ".glb", ".hdr", ".exr"}, true};
    static const PathDialogKind saveMaterial{"Save material as", "Save the material (.json) as:", "Save", {".json"}};
    static const PathDialogKind saveScene{
        "Save scene as", "Save the scene (lights, camera, display, the material inline) as .json:", "Save", {".json"}};
    static const PathDialogKind savePreset{
        "Save as preset",
        "Save the material in your presets (a name alone goes into your presets folder); the file's name becomes "
        "the material's name:",
        "Save",
        {".json"}};
    static const PathDialogKind exportComparison{
        "Export comparison", "Export A and B side by side, captioned, as a PNG:", "Export", {".png"}};
    static const PathDialogKind exportGltf{
        "Export as glTF",
        "Export the model with its materials as tuned and its maps (or the built-in mesh with the material) as "
        ".glb, or as .gltf with its images beside it:",
        "Export", {".glb", ".gltf"}};
    static const PathDialogKind replaceMap{
        "Replace map",
        "Draw an image (.png, .jpg, .webp) in place of the map: it keeps the map's UV set, sampling and transform, and "
        "is saved with the scene and exported with the model:",
        "Replace", {".png", ".jpg", ".jpeg", ".webp"}, true};
    switch (dialog) {
    case Prompts::PathDialog::ReplaceMap: return replaceMap;
    case Prompts::PathDialog::ExportGltf: return exportGltf;
    case Prompts::PathDialog::SaveAs: return saveMaterial;
    case Prompts::PathDialog::SaveSceneAs: return saveScene;
    case Prompts::PathDialog::SavePreset: return savePreset;
    case Prompts::PathDialog::ExportComparison: return exportComparison;
    case Prompts::PathDialog::Open:
    case Prompts::PathDialog::None: break;
    }
    return open;
}

std::filesystem::path relativeBase(const Preferences& preferences, Prompts::PathDialog dialog) {
    return dialog == Prompts::PathDialog::SavePreset ? preferences.userPresetFolder : std::filesystem::path();
}

std::filesystem::path typedFolder(const std::string& typed, const std::filesystem::path& base) {
    const std::filesystem::path folder = splitTyped(typed).first;
    return base.empty() || folder.is_absolute() ? folder : base / folder;
}

std::vector<ListedEntry> listForDialog(const std::string& typed, Prompts::PathDialog dialog,
                                       const std::filesystem::path& base) {
    const std::filesystem::path folder = typedFolder(typed, base);
    const std::string name = splitTyped(typed).second;
    const PathDialogKind& kind = pathDialogKind(dialog);
    const std::string wanted = kind.filterByName ? name : "";
    const std::vector<std::string>& extensions = kind.extensions;
    std::vector<ListedEntry> entries;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
        const bool isFolder = entry.is_directory(error);
        const std::string extension = lowered(entry.path().extension().string());
        const bool listed = isFolder || std::find(extensions.begin(), extensions.end(), extension) != extensions.end();
        if (listed && containsAnyCase(entry.path().filename().string(), wanted)) {
            entries.push_back({entry.path(), isFolder});
        }
    }
    std::sort(entries.begin(), entries.end(), [](const ListedEntry& a, const ListedEntry& b) {
        return a.folder != b.folder ? a.folder : a.path.filename() < b.path.filename();
    });
    return entries;
}

bool enterFolder(std::string* typed, const std::filesystem::path& base) {
    std::error_code error;
    const std::filesystem::path path = *typed;
    if (typed->empty() || !std::filesystem::is_directory(base.empty() || path.is_absolute() ? path : base / path, error)) {
        return false;
    }
    if (typed->back() != '/') {
        *typed += '/';
    }
    return true;
}

void startPathDialog(Prompts& prompts, Prompts::PathDialog kind, const std::filesystem::path& initial) {
    prompts.pathDialog = kind;
    prompts.pathDialogText = initial.string();
    prompts.pathFieldTaken = prompts.pathTypedEarly = false;
}

// The path field, `width` wide, with the keys typed before it had them; true when Enter let go
// of it (or came before it had the keys: Ctrl+Alt+S, Enter takes the name offered at once).
bool pathFieldEntered(Prompts& prompts, float width) {
    ImGui::SetNextItemWidth(width);
    if (ImGui::IsWindowAppearing()) {
        ImGui::SetKeyboardFocusHere();
    }
    // Written as typed, so the list follows; Enter lets go of the field (single-line fields do).
    // After Enter on a folder the field takes the keys again, its cursor after the new '/'.
    prompts.pathCursorToEnd = takeEarlyKeys(prompts) || prompts.pathCursorToEnd;
    char buffer[1024];
    std::snprintf(buffer, sizeof buffer, "%s", prompts.pathDialogText.c_str());
    const auto moveCursor = [](ImGuiInputTextCallbackData* data) {
        bool& toEnd = *static_cast<bool*>(data->UserData);
        if (toEnd) {
            data->CursorPos = data->SelectionStart = data->SelectionEnd = data->BufTextLen;
            toEnd = false;
        }
        return 0;
    };
    ImGui::PushID(prompts.pathDialogOpenings);
    if (ImGui::InputText("##path", buffer, sizeof buffer, ImGuiInputTextFlags_CallbackAlways, moveCursor,
                         &prompts.pathCursorToEnd)) {
        prompts.pathDialogText = buffer;
    }
    ImGui::PopID();
    // Enter lets go of the field, or comes before the field had the keys (Ctrl+Alt+S, Enter: the
    // name offered, at once).
    const bool early = !prompts.pathFieldTaken;
    prompts.pathFieldTaken = prompts.pathFieldTaken || ImGui::IsItemActive();
    return (ImGui::IsItemDeactivated() || early) && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
                                                     ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter)));
}

void drawPathDialog(EditorState& state, EditorServices& services) {
    const PathDialogKind& kind = pathDialogKind(state.pathDialog);
    // One popup whatever the action ("###path"), titled by it.
    const std::string title = std::string(kind.title) + "###path";
    // Each opening's path field is a new widget (Prompts::pathDialogOpenings).
    if (state.pathDialog != Prompts::PathDialog::None && !ImGui::IsPopupOpen("###path")) {
        ImGui::OpenPopup(title.c_str());
        ++state.pathDialogOpenings;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const float width = std::min(px(560), display.x - px(40));
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title.c_str(), nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        return;
    }
    ImGui::PushTextWrapPos(width);
    ImGui::TextUnformatted(kind.prompt);
    ImGui::PopTextWrapPos();
    bool entered = pathFieldEntered(state, width);
    recordItem("path:text", "The file's path; Enter on a folder opens it, the list below follows what you type");
    const std::filesystem::path base = relativeBase(state, state.pathDialog);
    if (entered && enterFolder(&state.pathDialogText, base)) {
        entered = false;   // into the folder, the dialog stays
        ImGui::SetKeyboardFocusHere(-1);
        state.pathCursorToEnd = true;
    }
    drawListing(state, base, ImVec2(width, std::min(px(240), display.y * 0.4f)));
    const bool confirmed = ImGui::Button(kind.verb);
    recordItem("path:confirm", kind.prompt);
    if (confirmed || entered) {
        confirm(state, services, state.pathDialogText);
        state.pathDialog = Prompts::PathDialog::None;
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
        state.pathDialog = Prompts::PathDialog::None;
        ImGui::CloseCurrentPopup();
    }
    recordItem("path:cancel", "Close without doing anything (Escape)");
    ImGui::EndPopup();
}

}  // namespace patina::editor
