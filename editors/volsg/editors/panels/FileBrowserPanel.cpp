#include <volsg/editors/panels/FileBrowserPanel.h>

#include <cstdio>
#include <cstring>

namespace volsg {

namespace {

void remember(FileBrowserPanelState& state, const std::string& name) {
    state.places[name] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
}

void showFolderInField(const FileBrowser& browser, FileBrowserPanelState& state) {
    std::snprintf(state.typed, sizeof state.typed, "%s", browser.folder().string().c_str());
}

std::string sizeText(std::uintmax_t bytes) {
    char text[32];
    if (bytes >= 1024 * 1024)
        std::snprintf(text, sizeof text, "%.1f MB", double(bytes) / 1048576.0);
    else
        std::snprintf(text, sizeof text, "%.1f kB", double(bytes) / 1024.0);
    return text;
}

} // namespace

std::string drawFileBrowserPanel(FileBrowser& browser, FileBrowserPanelState& state,
                                 float listHeight) {
    state.places.clear();
    std::string open;
    if (state.typedFollowsFolder) showFolderInField(browser, state);
    if (ImGui::ArrowButton("##up", ImGuiDir_Up) && browser.up()) state.typedFollowsFolder = true;
    remember(state, "up");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("up to the parent folder");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::InputText("##path", state.typed, sizeof state.typed,
                         ImGuiInputTextFlags_EnterReturnsTrue)) {
        std::string path;
        const FileBrowser::Typed typed = browser.typePath(state.typed, path);
        if (typed == FileBrowser::Typed::File) open = path;
        if (typed == FileBrowser::Typed::Folder) state.typedFollowsFolder = true;
    } else if (ImGui::IsItemActive()) {
        state.typedFollowsFolder = false; // the user is typing: keep what they type
    }
    remember(state, "path");

    bool activate = false;
    ImGui::BeginChild("##entries", ImVec2(0.0f, listHeight), true);
    const auto& entries = browser.entries();
    for (int i = 0; i < int(entries.size()); ++i) {
        const FileBrowser::Entry& e = entries[std::size_t(i)];
        const std::string label = (e.folder ? "[dir] " + e.name + "/" : e.name) + "##" + e.name;
        if (ImGui::Selectable(label.c_str(), browser.selected() == i,
                              ImGuiSelectableFlags_AllowDoubleClick |
                                  ImGuiSelectableFlags_SpanAllColumns)) {
            browser.select(i);
            if (ImGui::IsMouseDoubleClicked(0)) activate = true;
        }
        remember(state, e.name);
        if (!e.folder) {
            const std::string size = sizeText(e.bytes);
            ImGui::SameLine(ImGui::GetWindowContentRegionMax().x -
                            ImGui::CalcTextSize(size.c_str()).x);
            ImGui::TextDisabled("%s", size.c_str());
        }
    }
    if (entries.empty()) ImGui::TextDisabled("(no folders or files volsg opens here)");
    ImGui::EndChild();
    // Enter opens the selection, unless the path field has the keyboard.
    if (!ImGui::GetIO().WantTextInput && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)))
        activate = true;
    if (activate && browser.selected() >= 0) {
        const FileBrowser::Entry& e = entries[std::size_t(browser.selected())];
        if (e.folder) {
            if (browser.enter(e.name)) state.typedFollowsFolder = true;
        } else {
            open = browser.selectedPath();
        }
    }
    if (!browser.error().empty())
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s", browser.error().c_str());
    bool all = browser.showAll();
    if (ImGui::Checkbox("show all files", &all)) browser.setShowAll(all);
    remember(state, "showall");
    return open;
}

} // namespace volsg
