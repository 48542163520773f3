// Saving never destroys the previous file: every failure of writeFileAtomically and of the
// writers built on it (scene, PNG, PFM) leaves the old file byte for byte and no temporary
// file behind.
#include <doctest/doctest.h>

#include <cmath>
#include <csignal>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>

#include <sys/resource.h>
#include <sys/stat.h>

#include <volsg/io/AtomicFile.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Separator.h>

#include "robustness/RobustnessSupport.h"

using namespace volsg;
using namespace volsg::test;
namespace fs = std::filesystem;

namespace {

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Only `expected` files are in `dir`: no temporary file was left behind.
void checkOnlyFiles(const fs::path& dir, std::size_t expected) {
    std::size_t count = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        CAPTURE(entry.path().string());
        CHECK(entry.path().string().find(".tmp") == std::string::npos);
        ++count;
    }
    CHECK(count == expected);
}

/// Lowers the file size limit of this process for its lifetime; writes past it fail with
/// EFBIG (SIGXFSZ ignored), as on a full disk, midway through the file.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &saved_);
        previous_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit lowered = saved_;
        lowered.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &lowered);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &saved_);
        std::signal(SIGXFSZ, previous_);
    }

private:
    rlimit saved_{};
    void (*previous_)(int) = nullptr;
};

Image smallImage() {
    Image image(4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            image.at(x, y) = glm::vec4(x / 4.0f, y / 3.0f, 0.5f, 1.0f);
    return image;
}

} // namespace

TEST_CASE("a save replaces the whole file and keeps its permissions") {
    const fs::path dir = robustnessScratch("replace");
    const fs::path file = dir / "scene.iv";
    std::ofstream(file) << "old contents that are longer than the new ones\n";
    ::chmod(file.c_str(), 0640);
    writeFileAtomically(file.string(), "new\n");
    CHECK(contents(file) == "new\n");
    CHECK((fs::status(file).permissions() & fs::perms::all) ==
          (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
    checkOnlyFiles(dir, 1);
}

TEST_CASE("a save into a missing folder fails and creates nothing") {
    const fs::path dir = robustnessScratch("nofolder");
    const fs::path file = dir / "absent" / "scene.iv";
    CHECK_THROWS_WITH_AS(writeFileAtomically(file.string(), "x"),
                         doctest::Contains("cannot create a temporary file"), Error);
    CHECK(!fs::exists(file));
    checkOnlyFiles(dir, 0);
}

TEST_CASE("a save whose folder is a file fails and leaves that file intact") {
    const fs::path dir = robustnessScratch("notfolder");
    std::ofstream(dir / "plain") << "keep";
    CHECK_THROWS_AS(writeFileAtomically((dir / "plain" / "scene.iv").string(), "x"), Error);
    CHECK(contents(dir / "plain") == "keep");
}

TEST_CASE("a save over a folder fails and leaves the folder") {
    const fs::path dir = robustnessScratch("overfolder");
    fs::create_directory(dir / "scene.iv");
    CHECK_THROWS_WITH_AS(writeFileAtomically((dir / "scene.iv").string(), "x"),
                         doctest::Contains("this is a folder"), Error);
    CHECK(fs::is_directory(dir / "scene.iv"));
    checkOnlyFiles(dir, 1);
}

TEST_CASE("a save into an unwritable folder keeps the old file") {
    if (::geteuid() == 0) {
        MESSAGE("running as root: folder permissions do not stop root, nothing to check");
        return;
    }
    const fs::path dir = robustnessScratch("readonly");
    std::ofstream(dir / "scene.iv") << "old";
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
    CHECK_THROWS_AS(writeFileAtomically((dir / "scene.iv").string(), "new"), Error);
    fs::permissions(dir, fs::perms::owner_all);
    CHECK(contents(dir / "scene.iv") == "old");
}

TEST_CASE("a write error midway keeps the old file and removes the partial one") {
    const fs::path dir = robustnessScratch("midway");
    const fs::path file = dir / "big.iv";
    const std::string old = "#Inventor V2.1 ascii\nCube {}\n";
    std::ofstream(file) << old;
    const std::string huge(256 * 1024, 'x');
    {
        const FileSizeLimit limit(64 * 1024); // the write stops a quarter of the way
        CHECK_THROWS_WITH_AS(writeFileAtomically(file.string(), huge),
                             doctest::Contains("write error after 65536 of 262144 bytes"), Error);
    }
    CHECK(contents(file) == old);
    checkOnlyFiles(dir, 1);
}

TEST_CASE("a scene that cannot be written keeps the old scene file") {
    const fs::path dir = robustnessScratch("badscene");
    const fs::path file = dir / "scene.iv";
    std::ofstream(file) << "#Inventor V2.1 ascii\nSphere {}\n";
    auto root = Separator::create();
    auto cube = Cube::create();
    cube->width = std::numeric_limits<float>::quiet_NaN(); // cannot be written
    root->addChild(Cube::create());
    root->addChild(cube);
    CHECK_THROWS_AS(writeSceneToFile(file.string(), *root), Error);
    CHECK(contents(file) == "#Inventor V2.1 ascii\nSphere {}\n");
    checkOnlyFiles(dir, 1);
    // And a scene that can be written replaces it completely.
    cube->width = 3.0f;
    writeSceneToFile(file.string(), *root);
    CHECK(readScene(file.string())->children()->size() == 2);
}

TEST_CASE("a PNG or PFM save that fails midway keeps the old image") {
    const fs::path dir = robustnessScratch("image");
    for (const char* name : {"old.png", "old.pfm"}) {
        const fs::path file = dir / name;
        writeImage(file.string(), smallImage());
        const std::string before = contents(file);
        Image large(512, 512); // noisy: even compressed far larger than the limit below
        for (int y = 0; y < 512; ++y)
            for (int x = 0; x < 512; ++x)
                large.at(x, y) = glm::vec4(float((x * 7919 + y * 104729) % 251) / 251.0f,
                                           float(x) / 512.0f, float(y) / 512.0f, 1.0f);
        {
            const FileSizeLimit limit(before.size() + 16);
            CHECK_THROWS_AS(writeImage(file.string(), large), Error);
        }
        CHECK(contents(file) == before);
    }
    checkOnlyFiles(dir, 2);
}

TEST_CASE("a save through a symbolic link replaces the target and keeps the link") {
    const fs::path dir = robustnessScratch("symlink");
    std::ofstream(dir / "target.iv") << "old";
    fs::create_symlink("target.iv", dir / "link.iv");
    writeFileAtomically((dir / "link.iv").string(), "new");
    CHECK(fs::is_symlink(dir / "link.iv"));
    CHECK(contents(dir / "target.iv") == "new");
    checkOnlyFiles(dir, 2);
}
