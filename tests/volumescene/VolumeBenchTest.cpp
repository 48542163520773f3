// volsg-bench's speed-versus-error output and the volume examples, run as a user runs them.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <volsg/context/Context.h>
#include <volsg/io/SceneReader.h>
#include <volsg/volumescene/ReferenceScene.h>

#include "../support/TempDir.h"

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
    return volsg::test::processScratch("volsg-volume-bench-test") / name;
}

// Runs a command with stdout and stderr captured in one file; the exit status.
int run(const std::string& command, std::string& output) {
    const fs::path log = scratch("command.log");
    const int raw = std::system((command + " >" + log.string() + " 2>&1").c_str());
    std::stringstream ss;
    ss << std::ifstream(log).rdbuf();
    output = ss.str();
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string bench() {
    return std::string(VOLSG_BINARY_DIR) + "/viewer/volsg-bench";
}

std::string slurp(const fs::path& path) {
    std::stringstream ss;
    ss << std::ifstream(path).rdbuf();
    return ss.str();
}

// CSV lines as cells: commas separate, double quotes enclose cells holding commas ("" is a
// quote).
std::vector<std::vector<std::string>> readCsv(const fs::path& path) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> cells(1);
        bool quoted = false;
        for (std::size_t i = 0; i < line.size(); ++i) {
            const char c = line[i];
            if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                cells.back() += '"';
                ++i;
            } else if (c == '"')
                quoted = !quoted;
            else if (c == ',' && !quoted)
                cells.emplace_back();
            else
                cells.back() += c;
        }
        rows.push_back(cells);
    }
    return rows;
}

} // namespace

TEST_CASE("volsg-bench --error reports the error of a scene's frames against the reference") {
    const fs::path scene = scratch("bench-scene.iv"), csv = scratch("bench-scene.csv"),
                   svg = scratch("bench-scene.svg");
    std::ofstream(scene) << "#Inventor V2.1 ascii\nSeparator {\n"
                            "VolumeData { generator SOFT_SPHERE dimensions 16 16 16 }\n"
                            "TransferFunction { alpha [ 0 0, 1 0.2 ] }\nVolume { }\n}\n";
    fs::remove(csv);
    fs::remove(svg);
    std::string out;
    const int status = run(bench() + " " + scene.string() + " --frames 3 --size 24x24 --error " +
                               "--error-frames 2 --csv " + csv.string() + " --plot " + svg.string(),
                           out);
    INFO(out);
    REQUIRE(status == 0);
    CHECK(out.find("error vs reference") != std::string::npos);
    const auto rows = readCsv(csv);
    REQUIRE(rows.size() == 3); // header, the GL row, the reference row
    REQUIRE(rows[0].size() == 13);
    CHECK(rows[0][6] == "rmse");
    REQUIRE(rows[1].size() == 13);
    CHECK(rows[1][1] == "gl");
    CHECK(rows[1][9] == "2"); // error frames
    const double rmse = std::stod(rows[1][6]), psnr = std::stod(rows[1][7]);
    const double maxAbs = std::stod(rows[1][8]);
    CHECK(std::isfinite(rmse));
    CHECK(rmse >= 0.0);
    CHECK(rmse <= maxAbs + 1e-12); // a mean never exceeds the largest term
    if (rmse > 0.0) CHECK(psnr == doctest::Approx(-20.0 * std::log10(rmse)).epsilon(1e-4));
    CHECK(rows[2][1] == "reference");
    CHECK(slurp(svg).find("<svg") != std::string::npos);
}

TEST_CASE("volsg-bench --suite volumes prints, writes CSV and plots every path and setting") {
    const fs::path csv = scratch("suite.csv"), svg = scratch("suite.svg"), keep = scratch("keep");
    fs::remove(csv);
    fs::remove(svg);
    fs::remove_all(keep);
    std::string out;
    const int status = run(bench() + " --suite volumes --size 16x16 --frames 2 " +
                               "--error-frames 1 --volume-side 12 --csv " + csv.string() +
                               " --plot " + svg.string() + " --keep " + keep.string(),
                           out);
    INFO(out);
    REQUIRE(status == 0);
    const auto rows = readCsv(csv);
    // 4 scenes x (3 reference rows + the node's default still and interactive + 4 plane
    // counts x 2 pre-integration x 2 modes + the orthographic truth for shear-warp + 2 thread
    // counts x optimizer off and on + the interactive shear-warp row).
    REQUIRE(rows.size() == 1 + 4 * (3 + 2 + 16 + 1 + 4 + 1));
    int truthRows = 0, referenceRows = 0, slicingRows = 0, shearWarpRows = 0, interactiveRows = 0,
        defaultRows = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const auto& r = rows[i];
        REQUIRE(r.size() == 13);
        if (r[1] == "reference" && r[2].find("truth") != std::string::npos) {
            ++truthRows;
            CHECK(r[6].empty()); // the truth has no error of its own
            CHECK(r[11] == "rss");
        } else if (r[1] == "reference") {
            ++referenceRows;
            // The coarser reference is close to the truth: its tolerance is at most 1e-2.
            CHECK(std::stod(r[6]) < 0.05);
        } else if (r[1] == "shear-warp") {
            ++shearWarpRows;
            if (r[2].find("interactive (slice step 2)") != std::string::npos) ++interactiveRows;
            CHECK(std::isfinite(std::stod(r[6])));
            CHECK(std::stod(r[4]) > 0.0);
        } else {
            CHECK(r[1] == "slicing");
            ++slicingRows;
            if (r[2].rfind("default", 0) == 0) {
                ++defaultRows;
                // The default meets its target (errorTarget 0.5/255 still, 2/255
                // interactive) within the model's spread.
                const double target = r[2].find("interactive") != std::string::npos ? 2.0 : 0.5;
                CHECK(std::stod(r[6]) * 255.0 <= 2.0 * target);
            }
            if (r[3] == "yes") {
                CHECK(std::isfinite(std::stod(r[6])));
                CHECK(std::stod(r[4]) > 0.0);
            }
        }
    }
    CHECK(truthRows == 8); // perspective for slicing, orthographic for shear-warp
    CHECK(referenceRows == 8);
    CHECK(slicingRows == 72);
    CHECK(defaultRows == 8);
    CHECK(shearWarpRows == 20);
    CHECK(interactiveRows == 4);
    const std::string plot = slurp(svg);
    CHECK(plot.find("<svg") != std::string::npos);
    CHECK(plot.find("milliseconds per frame") != std::string::npos);
    CHECK(plot.find("marschner-lobb-12-spiky") != std::string::npos);
    int kept = 0;
    for (const auto& entry : fs::directory_iterator(keep))
        kept += entry.path().extension() == ".iv";
    CHECK(kept == 4);
}

TEST_CASE("every volume example renders with the reference") {
    auto context = volsg::Context::createOffscreen();
    int rendered = 0;
    for (const auto& entry :
         fs::directory_iterator(std::string(VOLSG_SOURCE_DIR) + "/examples/volumes")) {
        if (entry.path().extension() != ".iv") continue;
        INFO(entry.path().string());
        auto root = volsg::readScene(entry.path().string());
        CHECK(!volsg::collectVolumes(*root).empty());
        volsg::RenderOptions options;
        options.width = 24;
        options.height = 24;
        volsg::RayCastOptions rayOptions;
        rayOptions.tolerance = 1e-3;
        volsg::RayCastResult details;
        const volsg::Image image = volsg::renderReference(*root, options, &details, rayOptions);
        float brightest = 0.0f;
        for (const auto& p : image.pixels)
            brightest = std::max({brightest, p.r, p.g, p.b});
        CHECK(brightest > 0.05f); // the volume shows over the black background
        CHECK(details.errorBound <= 1e-3);
        ++rendered;
    }
    CHECK(rendered >= 5);
}
