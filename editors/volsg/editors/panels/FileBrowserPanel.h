#pragma once
// The Dear ImGui panel of a FileBrowser: the folder's path (editable: Enter goes to a typed
// folder or opens a typed file), an up button, the list of folders and files (click selects,
// double-click or Enter enters a folder or opens a file), "show all files", and the caller's
// buttons below it.

#include <map>
#include <string>

#include <imgui.h>

#include <volsg/editors/FileBrowser.h>

namespace volsg {

struct FileBrowserPanelState {
    char typed[1024] = "";          ///< the path field
    bool typedFollowsFolder = true; ///< the field shows the folder until the user types
    /// Where each row and control was drawn this frame (window pixels), by name: a listed
    /// entry's name, "up", "path", "showall", for scripted input.
    std::map<std::string, std::pair<ImVec2, ImVec2>> places;
};

/// Draws the browser into the current window (its last item is the "show all files" box, so
/// the caller may add items on the same line), `listHeight` pixels of list. Returns the path to
/// open (a file double-clicked, Enter on a selected file, or a typed file path and Enter), or
/// "" when nothing is to be opened this frame.
std::string drawFileBrowserPanel(FileBrowser& browser, FileBrowserPanelState& state,
                                 float listHeight);

} // namespace volsg
