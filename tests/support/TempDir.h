#pragma once
// A fresh folder per test under the system's temporary folder, removed afterwards.

#include <atomic>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <system_error>

#include <unistd.h>

namespace volsg::test {

class TempDir {
public:
    /// `prefix` names the folder (with the process id and a counter), so a left-over folder
    /// says which tests made it.
    explicit TempDir(const std::string& prefix = "volsg-test") {
        static std::atomic<int> counter{0};
        path_ = std::filesystem::temp_directory_path() /
                (prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

/// A folder this process's test cases share (ctest may run a source's cases in one process),
/// made on first use and removed when the process exits.
inline std::filesystem::path processScratch(const std::string& prefix) {
    static std::map<std::string, std::unique_ptr<TempDir>> folders; // destroyed at exit
    std::unique_ptr<TempDir>& folder = folders[prefix];
    if (!folder) folder = std::make_unique<TempDir>(prefix);
    std::filesystem::create_directories(folder->path()); // (a case may have removed it)
    return folder->path();
}

} // namespace volsg::test
