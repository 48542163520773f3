// What every reader does when the name does not lead to a readable regular file: a missing
// file, a folder, a FIFO (which would block a plain open), a device, a symbolic link loop, a
// file without read permission. Each must be a volsg::Error naming the file, at once.
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "robustness/RobustnessSupport.h"

using namespace volsg;
using namespace volsg::test;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> extensions = {".iv",   ".nrrd", ".nhdr", ".mha", ".mhd",
                                             ".gltf", ".glb",  ".png",  ".pfm", ".raw"};

void checkRefused(const fs::path& path, const std::string& expected) {
    CAPTURE(path.string());
    const std::string message = loadError(path);
    CAPTURE(message);
    // VOLSG_PRINT_BAD_INPUT=1 lists what the user sees (tests/BAD-INPUT.md is made from it).
    if (std::getenv("VOLSG_PRINT_BAD_INPUT"))
        std::printf("| `%s` | `%s` |\n", path.filename().string().c_str(), message.c_str());
    CHECK(!message.empty());
    CHECK(message.find(path.filename().string()) != std::string::npos);
    CHECK(message.find(expected) != std::string::npos);
}

} // namespace

TEST_CASE("a missing file is an error naming it for every format") {
    const fs::path dir = robustnessScratch("missing");
    for (const std::string& ext : extensions)
        checkRefused(dir / ("absent" + ext), "");
}

TEST_CASE("a folder instead of a file is an error for every format") {
    const fs::path dir = robustnessScratch("folder");
    for (const std::string& ext : extensions) {
        fs::create_directory(dir / ("folder" + ext));
        checkRefused(dir / ("folder" + ext), "");
    }
}

TEST_CASE("a FIFO instead of a file is refused without blocking for every format") {
    const fs::path dir = robustnessScratch("fifo");
    for (const std::string& ext : extensions) {
        const fs::path fifo = dir / ("pipe" + ext);
        REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
        checkRefused(fifo, ""); // opening it for reading would wait for a writer forever
    }
}

TEST_CASE("a device instead of a file is refused for every format") {
    const fs::path dir = robustnessScratch("device");
    for (const std::string& ext : extensions) {
        const fs::path link = dir / ("zero" + ext);
        fs::create_symlink("/dev/zero", link); // endless zeros if read as a stream
        checkRefused(link, "");
    }
}

TEST_CASE("a symbolic link loop is an error for every format") {
    const fs::path dir = robustnessScratch("loop");
    for (const std::string& ext : extensions) {
        const fs::path a = dir / ("a" + ext), b = dir / ("b" + ext);
        fs::create_symlink(b, a);
        fs::create_symlink(a, b);
        checkRefused(a, "");
    }
}

TEST_CASE("an empty file is an error for every format") {
    const fs::path dir = robustnessScratch("empty");
    for (const std::string& ext : extensions) {
        std::ofstream(dir / ("empty" + ext)).close();
        checkRefused(dir / ("empty" + ext), "");
    }
}

TEST_CASE("a file without read permission is an error for every format") {
    if (::geteuid() == 0) {
        MESSAGE("running as root: permissions do not stop root, nothing to check");
        return;
    }
    const fs::path dir = robustnessScratch("permission");
    for (const std::string& ext : extensions) {
        const fs::path file = dir / ("locked" + ext);
        std::ofstream(file) << "#Inventor V2.1 ascii\n";
        fs::permissions(file, fs::perms::none);
        checkRefused(file, "");
    }
}
