// The open dialog's model (FileBrowser.h): folders first and the listed kinds of file, "show
// all", up and into folders, typed paths, and a folder that cannot be listed.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <volsg/editors/FileBrowser.h>

using namespace volsg;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> names(const FileBrowser& b) {
    std::vector<std::string> out;
    for (const auto& e : b.entries())
        out.push_back(e.name + (e.folder ? "/" : ""));
    return out;
}

} // namespace

TEST_CASE("file browser: lists folders and the files it opens, navigates, reads typed paths") {
    const fs::path dir = fs::temp_directory_path() / ("volsg-browser-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "zeta");
    fs::create_directories(dir / "alpha");
    fs::create_directories(dir / ".hidden");
    for (const char* name : {"b.nrrd", "A.NII.GZ", "notes.txt", "c.raw.gz", ".dot.nrrd"})
        std::ofstream(dir / name) << "1234";

    FileBrowser b({".nrrd", ".nii.gz", ".raw.gz"});
    REQUIRE(b.setFolder(dir));
    CHECK(names(b) ==
          std::vector<std::string>{"alpha/", "zeta/", "A.NII.GZ", "b.nrrd", "c.raw.gz"});
    CHECK(b.entries()[3].bytes == 4);
    b.setShowAll(true);
    CHECK(names(b) == std::vector<std::string>{".hidden/", "alpha/", "zeta/", ".dot.nrrd",
                                               "A.NII.GZ", "b.nrrd", "c.raw.gz", "notes.txt"});
    b.setShowAll(false);

    b.select(3);
    CHECK(b.selectedPath() == (dir / "b.nrrd").string());
    b.refresh(); // the selection stays on the same name
    CHECK(b.selectedPath() == (dir / "b.nrrd").string());
    b.select(99);
    CHECK(b.selected() == -1);

    REQUIRE(b.enter("zeta"));
    CHECK(b.folder() == dir / "zeta");
    CHECK(b.entries().empty());
    REQUIRE(b.up());
    CHECK(b.folder() == dir);

    std::string path;
    CHECK(b.typePath("alpha/", path) == FileBrowser::Typed::Folder);
    CHECK(b.folder() == dir / "alpha");
    CHECK(b.typePath("  ../b.nrrd ", path) == FileBrowser::Typed::File);
    CHECK(path == (dir / "b.nrrd").string());
    CHECK(b.typePath((dir / "nothing").string(), path) == FileBrowser::Typed::Missing);
    CHECK(b.error().find("nothing") != std::string::npos);
    CHECK(b.typePath("", path) == FileBrowser::Typed::Missing);

    // A file is not a folder: the listing stays, the error names it.
    CHECK_FALSE(b.setFolder(dir / "b.nrrd"));
    CHECK(b.folder() == dir / "alpha");
    CHECK(b.error().find("b.nrrd") != std::string::npos);
    fs::remove_all(dir);
}
