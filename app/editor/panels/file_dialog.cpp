#include "file_dialog.h"

#include <algorithm>
#include <cstdio>
#include <system_error>

#include <imgui.h>
#include <imgui_internal.h>

#include "shown_path.h"
#include "text_match.h"
#include "ui_scale.h"
#include "widgets.h"

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
    case EditorState::PathDialog::Open: requestOpen(state, path); break;
    case EditorState::PathDialog::SaveAs: saveMaterial(state, path); break;
    case EditorState::PathDialog::SaveSceneAs: saveScene(state, path); break;
    case EditorState::PathDialog::SavePreset: saveAsPreset(state, path); break;
    case EditorState::PathDialog::ExportComparison: services.exportComparison(state, path); break;
    case EditorState::PathDialog::ExportGltf: exportGltfFile(state, path); break;
    case EditorState::PathDialog::ReplaceMap: replaceMap(state, state.replacedMaterial, state.replacedMap, path); break;
    case EditorState::PathDialog::None: break;
    }
}

// Characters typed before the path field has the keys (with the key that opened the dialog, and
// in the hidden frame a dialog's first opening sizes itself in) were lost: they are the path's
// start, replacing the path offered as typing over its selection does. Returns whether any were
// taken, so that the field's cursor goes after them when it takes the keys.
bool takeEarlyKeys(EditorState& state) {
    ImVector<ImWchar>& queue = ImGui::GetIO().InputQueueCharacters;
    if (state.pathFieldTaken || queue.empty()) {
        return false;
    }
    if (!state.pathTypedEarly) {
        state.pathDialogText.clear();
        state.pathTypedEarly = true;
    }
    for (ImWchar c : queue) {
        if (c >= 32 && c != 127) {
            char utf8[5];
            state.pathDialogText += ImTextCharToUtf8(utf8, c);
        }
    }
    queue.resize(0);
    return true;
}

// The folder's entries under its path, from the home folder where it is inside it (a relative
// one is in `base`, or the editor's working folder): a click on a folder enters it, on a file
// takes its path.
void drawListing(EditorState& state, const std::filesystem::path& base, ImVec2 size) {
    std::error_code error;
    const std::filesystem::path folder = typedFolder(state.pathDialogText, base);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + size.x);
    ImGui::TextDisabled("In %s", shownPath(folder).c_str());
    ImGui::PopTextWrapPos();
    recordItem("path:folder", "The folder listed below, where a relative path is");
    ImGui::BeginChild("listing", size, true);
    if (ImGui::Selectable("../")) {
        state.pathDialogText = (std::filesystem::absolute(folder, error).lexically_normal().parent_path() / "").string();
    }
    recordItem("path:up", "The folder above");
    for (const ListedEntry& entry : listForDialog(state.pathDialogText, state.pathDialog, base)) {
        const std::string name = entry.path.filename().string() + (entry.folder ? "/" : "");
        if (ImGui::Selectable(name.c_str())) {
            state.pathDialogText = entry.folder ? (entry.path / "").string() : entry.path.string();
        }
        recordItem("path:entry " + name, entry.folder ? "Open this folder" : "Choose this file");
    }
    ImGui::EndChild();
}
}  // namespace

const PathDialogKind& pathDialogKind(EditorState::PathDialog dialog) {
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
        "Draw an image (.png, .jpg) in place of the map: it keeps the map's UV set, sampling and transform, and "
        "is saved with the scene and exported with the model:",
        "Replace", {".png", ".jpg", ".jpeg"}, true};
    switch (dialog) {
    case EditorState::PathDialog::ReplaceMap: return replaceMap;
    case EditorState::PathDialog::ExportGltf: return exportGltf;
    case EditorState::PathDialog::SaveAs: return saveMaterial;
    case EditorState::PathDialog::SaveSceneAs: return saveScene;
    case EditorState::PathDialog::SavePreset: return savePreset;
    case EditorState::PathDialog::ExportComparison: return exportComparison;
    case EditorState::PathDialog::Open:
    case EditorState::PathDialog::None: break;
    }
    return open;
}

std::filesystem::path relativeBase(const EditorState& state, EditorState::PathDialog dialog) {
    return dialog == EditorState::PathDialog::SavePreset ? state.userPresetFolder : std::filesystem::path();
}

std::filesystem::path typedFolder(const std::string& typed, const std::filesystem::path& base) {
    const std::filesystem::path folder = splitTyped(typed).first;
    return base.empty() || folder.is_absolute() ? folder : base / folder;
}

std::vector<ListedEntry> listForDialog(const std::string& typed, EditorState::PathDialog dialog,
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

void startPathDialog(EditorState& state, EditorState::PathDialog kind, const std::filesystem::path& initial) {
    state.pathDialog = kind;
    state.pathDialogText = initial.string();
    state.pathFieldTaken = state.pathTypedEarly = false;
}

void drawPathDialog(EditorState& state, EditorServices& services) {
    const PathDialogKind& kind = pathDialogKind(state.pathDialog);
    // One popup whatever the action ("###path"), titled by it.
    const std::string title = std::string(kind.title) + "###path";
    // Each opening's path field is a new widget: ImGui keeps a field's cursor and selection by
    // its ID, and the last opening's cursor, inside the new text, took what was typed there.
    static int openings = 0;
    if (state.pathDialog != EditorState::PathDialog::None && !ImGui::IsPopupOpen("###path")) {
        ImGui::OpenPopup(title.c_str());
        ++openings;
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
    ImGui::SetNextItemWidth(width);
    if (ImGui::IsWindowAppearing()) {
        ImGui::SetKeyboardFocusHere();
    }
    // Written as typed, so the list follows; Enter lets go of the field (single-line fields do).
    // After Enter on a folder the field takes the keys again, its cursor after the new '/'.
    static bool cursorToEnd = false;
    cursorToEnd = takeEarlyKeys(state) || cursorToEnd;
    char buffer[1024];
    std::snprintf(buffer, sizeof buffer, "%s", state.pathDialogText.c_str());
    const auto moveCursor = [](ImGuiInputTextCallbackData* data) {
        bool& toEnd = *static_cast<bool*>(data->UserData);
        if (toEnd) {
            data->CursorPos = data->SelectionStart = data->SelectionEnd = data->BufTextLen;
            toEnd = false;
        }
        return 0;
    };
    ImGui::PushID(openings);
    if (ImGui::InputText("##path", buffer, sizeof buffer, ImGuiInputTextFlags_CallbackAlways, moveCursor, &cursorToEnd)) {
        state.pathDialogText = buffer;
    }
    ImGui::PopID();
    // Enter lets go of the field, or comes before the field had the keys (Ctrl+Alt+S, Enter: the
    // name offered, at once).
    const bool early = !state.pathFieldTaken;
    state.pathFieldTaken = state.pathFieldTaken || ImGui::IsItemActive();
    bool entered = (ImGui::IsItemDeactivated() || early) && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
                                                              ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter)));
    recordItem("path:text", "The file's path; Enter on a folder opens it, the list below follows what you type");
    const std::filesystem::path base = relativeBase(state, state.pathDialog);
    if (entered && enterFolder(&state.pathDialogText, base)) {
        entered = false;   // into the folder, the dialog stays
        ImGui::SetKeyboardFocusHere(-1);
        cursorToEnd = true;
    }
    drawListing(state, base, ImVec2(width, std::min(px(240), display.y * 0.4f)));
    const bool confirmed = ImGui::Button(kind.verb);
    recordItem("path:confirm", kind.prompt);
    if (confirmed || entered) {
        confirm(state, services, state.pathDialogText);
        state.pathDialog = EditorState::PathDialog::None;
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
        state.pathDialog = EditorState::PathDialog::None;
        ImGui::CloseCurrentPopup();
    }
    recordItem("path:cancel", "Close without doing anything (Escape)");
    ImGui::EndPopup();
}

}  // namespace patina::editor
