// The viewer's recent files (RecentFiles.h): newest first, no duplicates, at most 10, written
// atomically and read back; a corrupt or oversized file is ignored line by line or whole.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "view/RecentFiles.h"

using namespace volsg;
namespace fs = std::filesystem;

TEST_CASE("recent files: newest first, at most 10, kept in a file") {
    const fs::path dir = fs::temp_directory_path() / ("volsg-recent-" + std::to_string(getpid()));
    fs::remove_all(dir);
    const std::string file = (dir / "volsg" / "recent").string();
    RecentFiles recent(file);
    recent.load(); // missing: empty, no error
    CHECK(recent.entries().empty());
    for (int i = 0; i < 12; ++i)
        CHECK(recent.add("/data/f" + std::to_string(i) + ".nrrd") == "");
    CHECK(recent.add("/data/f5.nrrd") == ""); // again: moves to the front, once
    REQUIRE(recent.entries().size() == RecentFiles::kMaxEntries);
    CHECK(recent.entries()[0] == "/data/f5.nrrd");
    CHECK(recent.entries()[1] == "/data/f11.nrrd");
    CHECK(recent.entries()[9] == "/data/f2.nrrd"); // f5 moved out of the middle

    RecentFiles again(file);
    again.load();
    CHECK(again.entries() == recent.entries());
    // Only the list is in the folder: the temporary file was renamed over it.
    CHECK(std::distance(fs::directory_iterator(dir / "volsg"), fs::directory_iterator()) == 1);

    // Corrupt lines are dropped, good ones kept.
    std::ofstream(file, std::ios::binary) << std::string("\0\x7f\n", 3) << "not/absolute\n"
                                          << "/ok/one.nii\r\n/ok/one.nii\n/ok/two.iv\n";
    again.load();
    CHECK(again.entries() == std::vector<std::string>{"/ok/one.nii", "/ok/two.iv"});
    // Oversized, or a folder where the file should be: nothing.
    std::ofstream(file, std::ios::binary) << std::string(RecentFiles::kMaxFileBytes + 1, '/');
    again.load();
    CHECK(again.entries().empty());
    fs::remove(file);
    fs::create_directories(file);
    again.load();
    CHECK(again.entries().empty());
    // Not writable there: the list in memory is kept, and the answer says why.
    CHECK(again.add("/ok/three.iv") != "");
    CHECK(again.entries() == std::vector<std::string>{"/ok/three.iv"});
    // A relative name is kept as an absolute one.
    RecentFiles relative((dir / "r").string());
    CHECK(relative.add("rel.nrrd") == "");
    CHECK(relative.entries()[0] == (fs::current_path() / "rel.nrrd").string());
    fs::remove_all(dir);
}
