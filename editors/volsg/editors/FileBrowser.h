#pragma once
// The model of an in-window file browser (its Dear ImGui panel: panels/FileBrowserPanel.h): a
// current folder, its folders and the files a program opens (told by name suffixes; "show all"
// lists every file), navigation up and into folders and to a typed path, and a selection. UI
// free, so its tests need no window.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace volsg {

class FileBrowser {
public:
    struct Entry {
        std::string name;
        bool folder = false;
        std::uintmax_t bytes = 0; ///< files only
    };

    /// `suffixes`: lower-case name endings of the files listed when showAll is off (".nrrd",
    /// ".nii.gz", ...); matched case-insensitively.
    explicit FileBrowser(std::vector<std::string> suffixes);

    /// Lists `folder` (made absolute and normal). False, with error() naming it, when it is
    /// not a readable folder; the listing then stays as it was.
    bool setFolder(const std::filesystem::path& folder);
    const std::filesystem::path& folder() const { return folder_; }
    bool up();                           ///< to the parent folder (false at the root)
    bool enter(const std::string& name); ///< into a listed folder
    void refresh() { setFolder(folder_); }

    /// Folders first, then files, each sorted by name; hidden (dot) names only with showAll.
    const std::vector<Entry>& entries() const { return entries_; }
    bool showAll() const { return showAll_; }
    void setShowAll(bool all);
    /// Whether `name` ends with one of the suffixes.
    bool listed(const std::string& name) const;

    /// The selected entry's index, or -1.
    int selected() const { return selected_; }
    void select(int index);
    /// The selected entry's full path ("" when none).
    std::string selectedPath() const;

    /// What a typed path means: a folder goes there (Folder), anything else is to be opened
    /// (File, with its absolute path in `path`); Missing when nothing exists there (error()
    /// says so).
    enum class Typed { Folder, File, Missing };
    Typed typePath(const std::string& text, std::string& path);

    /// Why the last setFolder or typePath failed ("" when it did not).
    const std::string& error() const { return error_; }

private:
    std::vector<std::string> suffixes_;
    std::filesystem::path folder_;
    std::vector<Entry> entries_;
    bool showAll_ = false;
    int selected_ = -1;
    std::string error_;
};

} // namespace volsg
