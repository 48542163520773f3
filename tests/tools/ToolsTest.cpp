// The command-line tools and the embedding example, run as a user runs them.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <volsg/image/Image.h>

#include "../support/TempDir.h"

namespace fs = std::filesystem;

namespace {

struct Run {
    int status;
    std::string err;
};

// Runs a shell command with stderr captured; the exit status as the shell reports it.
Run run(const std::string& command) {
    const fs::path errFile = volsg::test::processScratch("volsg-tools-test") / "command.err";
    const int raw = std::system((command + " 2>" + errFile.string()).c_str());
    std::ifstream in(errFile);
    std::stringstream ss;
    ss << in.rdbuf();
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, ss.str()};
}

std::string tool(const char* name) {
    return std::string(VOLSG_BINARY_DIR) + "/viewer/" + name;
}
std::string example(const char* name) {
    return std::string(VOLSG_SOURCE_DIR) + "/examples/" + name;
}
fs::path scratch(const std::string& name) {
    return volsg::test::processScratch("volsg-tools-test") / name;
}

} // namespace

TEST_CASE("volsg-render renders every example on both offscreen backends") {
    int rendered = 0;
    for (const auto& entry : fs::directory_iterator(std::string(VOLSG_SOURCE_DIR) + "/examples")) {
        if (entry.path().extension() != ".iv") continue;
        for (const char* backend : {"osmesa", "egl"}) {
            const fs::path out = scratch(entry.path().stem().string() + "-" + backend + ".png");
            fs::remove(out);
            const Run r = run(tool("volsg-render") + " " + entry.path().string() + " -o " +
                              out.string() + " --size 96x64 --backend " + backend);
            INFO(entry.path().string(), " on ", backend, ": ", r.err);
            CHECK(r.status == 0);
            const volsg::Image image = volsg::readPng(out.string());
            CHECK(image.width == 96);
            CHECK(image.height == 64);
            // Something is drawn: not every pixel is the black background.
            bool drawn = false;
            for (const auto& p : image.pixels)
                drawn = drawn || p.r + p.g + p.b > 0.0f;
            CHECK(drawn);
            ++rendered;
        }
    }
    CHECK(rendered >= 6);
}

TEST_CASE("volsg-render gives the same pixels on osmesa and egl") {
    const fs::path a = scratch("still-osmesa.pfm"), b = scratch("still-egl.pfm");
    REQUIRE(run(tool("volsg-render") + " " + example("still-life.iv") + " -o " + a.string() +
                " --size 64x64 --backend osmesa")
                .status == 0);
    REQUIRE(run(tool("volsg-render") + " " + example("still-life.iv") + " -o " + b.string() +
                " --size 64x64 --backend egl")
                .status == 0);
    const volsg::Image ia = volsg::readPfm(a.string()), ib = volsg::readPfm(b.string());
    REQUIRE(ia.pixels.size() == ib.pixels.size());
    float maxDiff = 0.0f;
    for (std::size_t i = 0; i < ia.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            maxDiff = std::max(maxDiff, std::abs(ia.pixels[i][c] - ib.pixels[i][c]));
    CHECK(maxDiff == 0.0f);
}

TEST_CASE("volsg-render fills the background colour it is given") {
    const fs::path out = scratch("background.pfm");
    const fs::path scene = scratch("empty.iv");
    std::ofstream(scene) << "#Inventor V2.1 ascii\nSeparator { }\n";
    REQUIRE(run(tool("volsg-render") + " " + scene.string() + " -o " + out.string() +
                " --size 8x4 --background 0.25,0.5,1")
                .status == 0);
    const volsg::Image image = volsg::readPfm(out.string());
    REQUIRE(image.width == 8);
    for (const auto& p : image.pixels) {
        CHECK(p.r == doctest::Approx(0.25f).epsilon(1e-6));
        CHECK(p.g == doctest::Approx(0.5f).epsilon(1e-6));
        CHECK(p.b == doctest::Approx(1.0f).epsilon(1e-6));
    }
}

TEST_CASE("volsg-render --time runs the scene's engines and animated nodes to that time") {
    // A Rotor at a quarter turn per second under a bar along x: at 1 s the bar stands along y.
    const fs::path scene = scratch("rotor.iv");
    std::ofstream(scene) << "#Inventor V2.1 ascii\nSeparator {\n"
                            "OrthographicCamera { position 0 0 5 height 4 }\n"
                            "LightModel { model BASE_COLOR } BaseColor { rgb 1 0 0 }\n"
                            "Rotor { rotation 0 0 1 0 speed 0.25 }\n"
                            "Cube { width 3 height 0.5 depth 0.5 } }\n";
    const auto red = [&](double seconds, int column, int row) {
        const fs::path out = scratch("rotor.pfm");
        REQUIRE(run(tool("volsg-render") + " " + scene.string() + " -o " + out.string() +
                    " --size 32x32 --time " + std::to_string(seconds))
                    .status == 0);
        return volsg::readPfm(out.string()).at(column, row).r > 0.5f;
    };
    // 8 pixels per unit: world (1.2, 0) is pixel (25, 16), world (0, 1.2) pixel (16, 6).
    CHECK(red(0.0, 25, 16));
    CHECK_FALSE(red(0.0, 16, 6));
    CHECK(red(1.0, 16, 6));
    CHECK_FALSE(red(1.0, 25, 16));
    CHECK(run(tool("volsg-render") + " " + scene.string() + " -o x.png --time -1").status != 0);
}

TEST_CASE("volsg-render writes a scene back when the output is .iv") {
    const fs::path out = scratch("every-node.iv");
    const Run r =
        run(tool("volsg-render") + " " + example("every-node.iv") + " -o " + out.string());
    CHECK(r.status == 0);
    std::ifstream in(out);
    std::string header;
    std::getline(in, header);
    CHECK(header == "#Inventor V2.1 ascii");
}

TEST_CASE("volsg-render reports bad input in one line naming the file") {
    const fs::path scene = scratch("broken.iv");
    std::ofstream(scene) << "#Inventor V2.1 ascii\nSeparator {\n  Cube { width }\n";
    const Run r =
        run(tool("volsg-render") + " " + scene.string() + " -o " + scratch("x.png").string());
    CHECK(r.status != 0);
    CHECK(r.err.find("broken.iv:") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);

    const Run missing =
        run(tool("volsg-render") + " /nonexistent/scene.iv -o " + scratch("y.png").string());
    CHECK(missing.status != 0);
    CHECK(missing.err.find("/nonexistent/scene.iv") != std::string::npos);

    const Run badSize = run(tool("volsg-render") + " " + example("still-life.iv") + " -o " +
                            scratch("z.png").string() + " --size 0x10");
    CHECK(badSize.status != 0);
    CHECK(badSize.err.find("--size") != std::string::npos);
}

TEST_CASE("the embedding example renders its three spheres and cone") {
    const fs::path out = scratch("embed.png");
    fs::remove(out);
    const Run r =
        run(std::string(VOLSG_BINARY_DIR) + "/examples/volsg-embed-example " + out.string());
    INFO(r.err);
    REQUIRE(r.status == 0);
    const volsg::Image image = volsg::readPng(out.string());
    CHECK(image.width == 480);
    CHECK(image.height == 320);
    // The corner is the background it set (0.1, 0.1, 0.15), to 8-bit rounding.
    CHECK(image.at(0, 0).r == doctest::Approx(26 / 255.0f).epsilon(1e-6));
    CHECK(image.at(0, 0).b == doctest::Approx(38 / 255.0f).epsilon(1e-6));
    // viewAll frames the scene: the middle sphere is above the centre (the cone's tip is at
    // it), lit orange, red above blue.
    const glm::vec4 c = image.at(240, 100);
    CHECK(c.r > c.b + 0.2f);
}
