#pragma once
// The viewer's recent files: the last 10 paths opened, newest first, kept in
// $XDG_CONFIG_HOME/volsg/recent (or ~/.config/volsg/recent), one absolute path a line, written
// atomically. A missing, unreadable or oversized file is an empty list; lines that are not an
// absolute path of printable characters are dropped, so a corrupt file never stops the viewer.

#include <string>
#include <vector>

namespace volsg {

class RecentFiles {
public:
    static constexpr std::size_t kMaxEntries = 10;
    static constexpr std::size_t kMaxFileBytes = 64 * 1024; ///< larger: ignored as corrupt

    /// Where the list lives: from XDG_CONFIG_HOME, else HOME; "" when neither is set.
    static std::string defaultPath();

    explicit RecentFiles(std::string path) : path_(std::move(path)) {}
    /// Reads the file (a missing or corrupt one gives an empty list, see above).
    void load();
    /// `file` (made absolute) to the front, once; the list is cut to kMaxEntries and written.
    /// Returns "" or why it could not be written (the list in memory is kept either way).
    std::string add(const std::string& file);
    const std::vector<std::string>& entries() const { return entries_; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::vector<std::string> entries_;
};

} // namespace volsg
