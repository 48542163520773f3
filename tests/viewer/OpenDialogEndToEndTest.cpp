// Opening files while volsg-view runs, under Xvfb: through the open dialog (typed folder,
// double-click on a file; raw voxels with the layout form), by a drop on the window, from the
// recent files (kept across runs in XDG_CONFIG_HOME, a corrupt list ignored), the question
// before unsaved edits are dropped, a file that does not open; and the patient axes of a NRRD
// whose space directions permute and flip the index axes.
//
// "The volume is shown" is measured on the scene-only screenshot against the viewer's
// background (26, 26, 31): at least 2% of the pixels differ from it by more than 10/255, and
// their luminance spread (90th minus 10th percentile) is at least 0.05, so neither a blank nor
// a flat image passes.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/gtc/quaternion.hpp>

#include <volsg/actions/SearchAction.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/Camera.h>

#include "ViewerTestSupport.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

const glm::vec3 background = glm::vec3(26, 26, 31) / 255.0f;

bool isBackground(const glm::vec4& p) {
    const glm::vec3 d = glm::abs(glm::vec3(p) - background);
    return std::max({d.r, d.g, d.b}) <= 10.0f / 255.0f;
}

struct Measures {
    double coverage = 0.0, spread = 0.0;
    glm::dvec2 centroid{0.0}; ///< of the non-background pixels, in [0, 1] (y down)
};

Measures measure(const Image& image) {
    std::vector<double> luminance;
    Measures m;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4 p = image.at(x, y);
            if (isBackground(p)) continue;
            luminance.push_back(0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b);
            m.centroid += glm::dvec2((x + 0.5) / image.width, (y + 0.5) / image.height);
        }
    m.coverage = double(luminance.size()) / double(image.pixels.size());
    if (!luminance.empty()) m.centroid /= double(luminance.size());
    if (luminance.size() >= 10) {
        std::sort(luminance.begin(), luminance.end());
        m.spread = luminance[luminance.size() * 9 / 10] - luminance[luminance.size() / 10];
    }
    return m;
}

void checkShowsVolume(const std::string& png) {
    const Measures m = measure(readPng(png));
    MESSAGE(png << ": coverage " << m.coverage << ", luminance spread " << m.spread);
    CHECK(m.coverage > 0.02);
    CHECK(m.spread > 0.05);
}

/// A fresh folder for one test.
fs::path folder(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("volsg-view-" + name + "-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

/// Voxels of a size.x x size.y x size.z uchar volume, x fastest.
using Voxels = std::vector<std::uint8_t>;

/// A ball with values falling from 250 in its middle to 40 at its edge: structure to see.
Voxels ball(const glm::ivec3& size, const glm::dvec3& centre, double radius) {
    Voxels v(std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z), 0);
    std::size_t n = 0;
    for (int z = 0; z < size.z; ++z)
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x, ++n) {
                const double r = glm::length(glm::dvec3(x, y, z) - centre) / radius;
                if (r < 1.0) v[n] = std::uint8_t(40.0 + 210.0 * (1.0 - r));
            }
    return v;
}

void writeRaw(const fs::path& path, const Voxels& voxels) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(voxels.data()), std::streamsize(voxels.size()));
}

/// A detached NRRD (`name`.nhdr and `name`.raw) in LPS with these space directions.
fs::path writeNrrd(const fs::path& dir, const std::string& name, const glm::ivec3& size,
                   const Voxels& voxels,
                   const std::string& directions = "(1,0,0) (0,1,0) (0,0,1)") {
    writeRaw(dir / (name + ".raw"), voxels);
    const fs::path header = dir / (name + ".nhdr");
    std::ofstream(header) << "NRRD0004\ntype: uint8\ndimension: 3\nspace: left-posterior-superior\n"
                          << "sizes: " << size.x << " " << size.y << " " << size.z
                          << "\nspace directions: " << directions
                          << "\nencoding: raw\ndata file: " << name << ".raw\n";
    return header;
}

int run(const fs::path& dir, const fs::path& start, const std::string& script, std::string& log,
        const std::string& configHome = testConfigHome()) {
    const std::string file = (dir / "script.txt").string();
    std::ofstream(file) << script;
    return runViewerScript(start.string(), "--size 480x360", file, log, configHome);
}

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

} // namespace

TEST_CASE("volsg-view opens files through the open dialog, drops and the recent files") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer open-dialog test is skipped");
        return;
    }
    const fs::path dir = folder("open-dialog");
    const glm::ivec3 size(24, 20, 16);
    const fs::path a = writeNrrd(dir, "a", size, ball(size, {6, 6, 8}, 6.0));
    fs::create_directories(dir / "sub");
    const fs::path b = writeNrrd(dir / "sub", "b", size, ball(size, {12, 10, 8}, 9.0));
    std::string log;

    SUBCASE("the dialog: type a folder, double-click a file") {
        const int status = run(dir, a,
                               "wait 1\n"
                               "screenshot " +
                                   (dir / "before.png").string() +
                                   " scene\n"
                                   "key o ctrl\nwait 1\n"
                                   "click left dialog:path\nkey a ctrl\n"
                                   "type " +
                                   (dir / "sub").string() +
                                   "\nkey enter\nwait 1\n"
                                   "click left dialog:b.nhdr\n"
                                   "screenshot " +
                                   (dir / "dialog.png").string() +
                                   "\n"
                                   "click left dialog:b.nhdr\n" // the second click: a double-click
                                   "wait 1\n"
                                   "screenshot " +
                                   (dir / "first.png").string() + " scene\nquit\n",
                               log);
        INFO("viewer output: " << log);
        REQUIRE(status == 0);
        CHECK(log.find("opened " + b.string()) != std::string::npos);
        checkShowsVolume((dir / "first.png").string());
        // Another volume than the first one: the ball is larger and elsewhere.
        CHECK(changedPixels(readPng((dir / "before.png").string()),
                            readPng((dir / "first.png").string()), 0.1f) > 480 * 360 / 50);
    }
    SUBCASE("a drop: the first dropped file opens") {
        const int status = run(dir, a,
                               "wait 1\ndrop " + b.string() + " " + a.string() +
                                   "\nwait 1\n"
                                   "screenshot " +
                                   (dir / "dropped.png").string() +
                                   "\n"
                                   "screenshot " +
                                   (dir / "first.png").string() + " scene\nquit\n",
                               log);
        INFO("viewer output: " << log);
        REQUIRE(status == 0);
        CHECK(log.find("opening the first of 2 dropped files") != std::string::npos);
        CHECK(log.find("opened " + b.string()) != std::string::npos);
        checkShowsVolume((dir / "first.png").string());
    }
    SUBCASE("raw voxels: the dialog asks their layout") {
        writeRaw(dir / "c.raw", ball(size, {12, 10, 8}, 8.0));
        const int status = run(dir, a,
                               "wait 1\nopen " + (dir / "c.raw").string() +
                                   "\nwait 1\n"
                                   "dialog raw 24 20 16 uchar 1 1 1\nwait 1\n"
                                   "screenshot " +
                                   (dir / "raw-dialog.png").string() +
                                   "\n"
                                   "click left dialog:open\nwait 1\n"
                                   "screenshot " +
                                   (dir / "first.png").string() + " scene\nquit\n",
                               log);
        INFO("viewer output: " << log);
        REQUIRE(status == 0);
        CHECK(log.find("opened " + (dir / "c.raw").string()) != std::string::npos);
        checkShowsVolume((dir / "first.png").string());
    }
    SUBCASE("unsaved edits ask first; a file that does not open is one line") {
        const std::string missing = (dir / "missing.nrrd").string();
        std::string script = "wait 1\nopen " + missing + "\nwait 1\n";
        script += "preset opacity alpha step\nopen " + b.string() + "\nwait 1\n";
        script += "screenshot " + (dir / "question.png").string() + "\n";
        script += "confirm cancel\nwait 1\nopen " + b.string() + "\nwait 1\n";
        script += "confirm discard\nwait 1\n";
        script += "screenshot " + (dir / "first.png").string() + " scene\n";
        // Edited again: "save, then open" writes b's scene beside it before a opens.
        script += "preset opacity alpha step\nopen " + a.string() + "\nwait 1\n";
        script += "confirm save\nwait 1\nquit\n";
        const int status = run(dir, a, script, log);
        INFO("viewer output: " << log);
        REQUIRE(status == 0);
        CHECK(log.find("not opened " + b.string() + ": the edited scene stays") !=
              std::string::npos);
        // The missing file is named, the viewer goes on (b opens after it).
        CHECK(log.find("cannot open missing.nrrd: ") != std::string::npos);
        CHECK(log.find((dir / "missing.nrrd").string()) != std::string::npos);
        CHECK(log.find("opened " + b.string()) != std::string::npos);
        checkShowsVolume((dir / "first.png").string());
        CHECK(fs::exists(dir / "sub" / "b.iv"));
        CHECK(log.find("saved " + (dir / "sub" / "b.iv").string()) <
              log.rfind("opened " + a.string()));
    }
    SUBCASE("the dialog opens a folder as a DICOM series") {
        fs::copy(fs::path(VOLSG_DATA_DIR) / "derived/headsq_dicom", dir / "headsq_dicom");
        const int status = run(dir, a,
                               "wait 1\nkey o ctrl\nwait 1\nclick left dialog:headsq_dicom\n"
                               "wait 1\nclick left dialog:open\nwait 1\n"
                               "screenshot " +
                                   (dir / "first.png").string() + " scene\nquit\n",
                               log);
        INFO("viewer output: " << log);
        REQUIRE(status == 0);
        CHECK(log.find("opened " + (dir / "headsq_dicom").string()) != std::string::npos);
        checkShowsVolume((dir / "first.png").string());
    }
    SUBCASE("recent files: kept across runs, a corrupt list ignored") {
        const fs::path config = dir / "config";
        const fs::path recent = config / "volsg" / "recent";
        REQUIRE(run(dir, a, "wait 1\nopen " + b.string() + "\nwait 2\nquit\n", log,
                    config.string()) == 0);
        CHECK(readAll(recent) == b.string() + "\n" + a.string() + "\n");
        // A second run, started on a: b is the second recent file now.
        REQUIRE(run(dir, a, "wait 1\nrecent 2\nwait 2\nquit\n", log, config.string()) == 0);
        CHECK(log.find("opened " + b.string()) != std::string::npos);
        CHECK(readAll(recent) == b.string() + "\n" + a.string() + "\n");

        // Binary junk, a relative path and an overlong line are dropped; b's line is kept.
        std::ofstream(recent, std::ios::binary)
            << std::string("\0\x01\xff junk\n", 8) << "relative/path.nrrd\n"
            << std::string(5000, '/') << "\n"
            << b.string() << "\n";
        REQUIRE(run(dir, a, "wait 1\nrecent 2\nwait 2\nquit\n", log, config.string()) == 0);
        CHECK(log.find("opened " + b.string()) != std::string::npos);
        CHECK(readAll(recent) == b.string() + "\n" + a.string() + "\n");

        // Larger than 64 kB: not read at all (only a, opened now, is listed).
        std::ofstream(recent, std::ios::binary) << std::string(70000, 'x');
        REQUIRE(run(dir, a, "wait 1\nrecent 2\nwait 1\nquit\n", log, config.string()) == 0);
        CHECK(log.find("no recent file 2 (there are 1)") != std::string::npos);
        CHECK(readAll(recent) == a.string() + "\n");
    }
    fs::remove_all(dir);
}

TEST_CASE("volsg-view labels a NRRD whose space directions permute and flip its axes") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer patient-axes test is skipped");
        return;
    }
    // Index axes in LPS: i runs to the feet (inferior), j to the patient's left, k to the
    // front (anterior). A bright cube sits at the patient's right, superior, anterior corner:
    // low i, low j, high k.
    const fs::path dir = folder("patient-axes");
    const glm::ivec3 size(24, 20, 16);
    Voxels voxels(std::size_t(size.x * size.y * size.z), 0);
    for (int k = 10; k < 16; ++k)
        for (int j = 0; j < 6; ++j)
            for (int i = 0; i < 6; ++i)
                voxels[std::size_t(i + size.x * (j + size.y * k))] =
                    std::uint8_t(200 + 8 * (i % 3));
    const fs::path file = writeNrrd(dir, "oblique", size, voxels, "(0,0,-2) (1.5,0,0) (0,-1.5,0)");
    std::string log;
    const int status = run(dir, file,
                           "wait 1\nview anterior\nwait 1\n"
                           "screenshot " +
                               (dir / "anterior.png").string() +
                               " scene\n"
                               "save " +
                               (dir / "anterior.iv").string() +
                               "\n"
                               "view superior\nwait 1\n"
                               "screenshot " +
                               (dir / "superior.png").string() +
                               " scene\n"
                               "layout four\nwait 1\n"
                               "screenshot " +
                               (dir / "four.png").string() + "\nquit\n",
                           log);
    INFO("viewer output: " << log);
    REQUIRE(status == 0);

    // The camera of "anterior" in the world the scene is in (LPS, the file's patient space):
    // it looks from the front to the back (+y), head (+z) up, within 1e-4.
    ref_ptr<Node> saved = readScene((dir / "anterior.iv").string());
    const auto cameras = findAll(*saved, Camera::classType());
    REQUIRE(cameras.size() == 1);
    const glm::dquat turn = static_cast<Camera*>(cameras[0])->orientation().quat();
    const glm::dvec3 forward = turn * glm::dvec3(0, 0, -1), up = turn * glm::dvec3(0, 1, 0);
    CAPTURE(forward);
    CAPTURE(up);
    CHECK(glm::length(forward - glm::dvec3(0, 1, 0)) < 1e-4);
    CHECK(glm::length(up - glm::dvec3(0, 0, 1)) < 1e-4);

    // The cube in the images: from the front, the patient's right is on the screen's left and
    // the head up, so it shows top left; from above (anterior up), top right.
    const Measures anterior = measure(readPng((dir / "anterior.png").string()));
    const Measures superior = measure(readPng((dir / "superior.png").string()));
    MESSAGE("cube centre from the front " << anterior.centroid.x << ", " << anterior.centroid.y
                                          << "; from above " << superior.centroid.x << ", "
                                          << superior.centroid.y);
    REQUIRE(anterior.coverage > 0.002);
    REQUIRE(superior.coverage > 0.002);
    CHECK(anterior.centroid.x < 0.4);
    CHECK(anterior.centroid.y < 0.4);
    CHECK(superior.centroid.x > 0.6);
    CHECK(superior.centroid.y < 0.4);
    fs::remove_all(dir);
}
