#include <volsg/editors/FileBrowser.h>

#include <algorithm>
#include <cctype>

namespace volsg {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

// A folder holding more is listed in part: the list stays responsive.
constexpr std::size_t kMaxEntries = 20000;

} // namespace

FileBrowser::FileBrowser(std::vector<std::string> suffixes) : suffixes_(std::move(suffixes)) {
    for (std::string& s : suffixes_)
        s = lower(s);
}

bool FileBrowser::listed(const std::string& name) const {
    const std::string n = lower(name);
    return std::any_of(suffixes_.begin(), suffixes_.end(), [&](const std::string& s) {
        return n.size() > s.size() && n.compare(n.size() - s.size(), s.size(), s) == 0;
    });
}

bool FileBrowser::setFolder(const fs::path& folder) {
    std::error_code ec;
    fs::path absolute = fs::absolute(folder, ec);
    if (!ec) absolute = absolute.lexically_normal();
    if (absolute.has_filename() == false && absolute != absolute.root_path())
        absolute = absolute.parent_path(); // "a/b/" -> "a/b"
    if (ec || !fs::is_directory(absolute, ec)) {
        error_ = "not a folder: " + folder.string();
        return false;
    }
    std::vector<Entry> entries;
    fs::directory_iterator it(absolute, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        error_ = "cannot list " + absolute.string() + ": " + ec.message();
        return false;
    }
    for (; it != fs::directory_iterator() && entries.size() < kMaxEntries; it.increment(ec)) {
        if (ec) break;
        const std::string name = it->path().filename().string();
        if (!showAll_ && !name.empty() && name[0] == '.') continue;
        std::error_code entryError;
        Entry e{name, it->is_directory(entryError), 0};
        if (!e.folder) {
            if (!showAll_ && !listed(name)) continue;
            e.bytes = it->is_regular_file(entryError) ? it->file_size(entryError) : 0;
            if (entryError) e.bytes = 0;
        }
        entries.push_back(std::move(e));
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        if (a.folder != b.folder) return a.folder;
        return a.name < b.name;
    });
    const std::string previous = selected_ >= 0 && folder_ == absolute
                                     ? entries_[std::size_t(selected_)].name
                                     : std::string();
    folder_ = absolute;
    entries_ = std::move(entries);
    selected_ = -1;
    for (std::size_t i = 0; i < entries_.size(); ++i)
        if (!previous.empty() && entries_[i].name == previous) selected_ = int(i);
    error_.clear();
    return true;
}

bool FileBrowser::up() {
    if (folder_ == folder_.root_path()) return false;
    return setFolder(folder_.parent_path());
}

bool FileBrowser::enter(const std::string& name) {
    return setFolder(folder_ / name);
}

void FileBrowser::setShowAll(bool all) {
    if (all == showAll_) return;
    showAll_ = all;
    refresh();
}

void FileBrowser::select(int index) {
    selected_ = index >= 0 && index < int(entries_.size()) ? index : -1;
}

std::string FileBrowser::selectedPath() const {
    if (selected_ < 0) return {};
    return (folder_ / entries_[std::size_t(selected_)].name).string();
}

FileBrowser::Typed FileBrowser::typePath(const std::string& text, std::string& path) {
    std::string trimmed = text;
    while (!trimmed.empty() && std::isspace(static_cast<unsigned char>(trimmed.back())))
        trimmed.pop_back();
    while (!trimmed.empty() && std::isspace(static_cast<unsigned char>(trimmed.front())))
        trimmed.erase(trimmed.begin());
    fs::path p(trimmed);
    if (p.is_relative()) p = folder_ / p;
    p = p.lexically_normal();
    std::error_code ec;
    if (trimmed.empty() || !fs::exists(p, ec)) {
        error_ = "no such file or folder: " + (trimmed.empty() ? std::string("(empty)") : trimmed);
        return Typed::Missing;
    }
    error_.clear();
    if (fs::is_directory(p, ec)) {
        if (!setFolder(p)) return Typed::Missing;
        path = folder_.string();
        return Typed::Folder;
    }
    path = p.string();
    return Typed::File;
}

} // namespace volsg
