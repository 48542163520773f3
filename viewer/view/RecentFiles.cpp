#include "RecentFiles.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <volsg/core/Error.h>
#include <volsg/io/AtomicFile.h>

namespace volsg {

namespace fs = std::filesystem;

namespace {

bool plausiblePath(const std::string& line) {
    if (line.empty() || line[0] != '/' || line.size() > 4096) return false;
    return std::none_of(line.begin(), line.end(),
                        [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

} // namespace

std::string RecentFiles::defaultPath() {
    // The viewer's own setting, so the environment is read here, not in the library.
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && xdg[0] == '/')
        return (fs::path(xdg) / "volsg" / "recent").string();
    if (const char* home = std::getenv("HOME"); home && home[0] == '/')
        return (fs::path(home) / ".config" / "volsg" / "recent").string();
    return {};
}

void RecentFiles::load() {
    entries_.clear();
    if (path_.empty()) return;
    std::error_code ec;
    if (!fs::is_regular_file(path_, ec) || fs::file_size(path_, ec) > kMaxFileBytes || ec) return;
    std::ifstream in(path_, std::ios::binary);
    std::string line;
    while (entries_.size() < kMaxEntries && std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (plausiblePath(line) &&
            std::find(entries_.begin(), entries_.end(), line) == entries_.end())
            entries_.push_back(line);
    }
}

std::string RecentFiles::add(const std::string& file) {
    std::error_code ec;
    fs::path absolute = fs::absolute(file, ec);
    const std::string entry = (ec ? fs::path(file) : absolute.lexically_normal()).string();
    if (!plausiblePath(entry)) return "not kept in the recent files: " + file;
    entries_.erase(std::remove(entries_.begin(), entries_.end(), entry), entries_.end());
    entries_.insert(entries_.begin(), entry);
    if (entries_.size() > kMaxEntries) entries_.resize(kMaxEntries);
    if (path_.empty()) return "no HOME or XDG_CONFIG_HOME: the recent files are not kept";
    try {
        fs::create_directories(fs::path(path_).parent_path(), ec);
        std::string text;
        for (const std::string& e : entries_)
            text += e + "\n";
        writeFileAtomically(path_, text);
    } catch (const Error& e) {
        return std::string("cannot write the recent files: ") + e.what();
    }
    return {};
}

} // namespace volsg
