// volsg-view opens data files directly (no hand-written scene) under Xvfb: a gzip raw volume
// with its layout on the command line, a NRRD, a NIfTI and a DICOM series. The first image must
// show the volume, and the volume must show structure; ctrl+s saves the scene the viewer built
// as an .iv beside the data, which reads back. Then a turn, window/level and a preset change the
// image, and the saved transfer function has the windowed range.
//
// Measures on the scene-only screenshot, against the viewer's background (26, 26, 31):
// - not blank: at least 3% of the pixels differ from the background by more than 10/255;
// - not flat: among those pixels, the luminance spread between the 10th and the 90th
//   percentile is at least 0.08 (a flat grey box, or one uniform colour, has a spread near 0).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>

#include "ViewerTestSupport.h"

using namespace volsg;
namespace fs = std::filesystem;

namespace {

const glm::vec3 background = glm::vec3(26, 26, 31) / 255.0f;

struct Measures {
    double coverage = 0.0; ///< share of pixels away from the background
    double spread = 0.0;   ///< luminance p90 - p10 of those pixels
};

Measures measure(const Image& image) {
    std::vector<double> luminance;
    for (const glm::vec4& p : image.pixels) {
        const glm::vec3 d = glm::abs(glm::vec3(p) - background);
        if (std::max({d.r, d.g, d.b}) > 10.0f / 255.0f)
            luminance.push_back(0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b);
    }
    Measures m;
    m.coverage = double(luminance.size()) / double(image.pixels.size());
    if (luminance.size() >= 10) {
        std::sort(luminance.begin(), luminance.end());
        m.spread = luminance[luminance.size() * 9 / 10] - luminance[luminance.size() / 10];
    }
    return m;
}

// Opens `name` (a file or folder that `prepare` puts into a fresh folder, as a user's data
// would be) in volsg-view, takes the first image, saves with ctrl+s (the .iv beside the data)
// and checks both.
void openAndLook(const std::string& name, const std::function<void(const fs::path&)>& prepare,
                 const std::string& arguments, const std::string& savedName) {
    CAPTURE(name);
    const fs::path dir =
        fs::temp_directory_path() / ("volsg-view-open-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    prepare(dir);
    const std::string shot = (dir / "first.png").string();
    const std::string script = (dir / "script.txt").string();
    const std::string turned = (dir / "turned.png").string();
    const std::string edited = (dir / "edited.png").string();
    const std::string editedScene = (dir / "edited.iv").string();
    // The first image and ctrl+s; then a turn (a left drag), window/level (a ctrl+right drag:
    // 20% of the view to the right widens the function's range by 20% of the data's span) and
    // an opacity preset, saved again.
    std::ofstream(script) << "wait 1\nscreenshot " << shot << " scene\nkey s ctrl\nwait 1\n"
                          << "drag left view:3d:0.5,0.5 view:3d:0.7,0.5 4\nwait 2\n"
                          << "screenshot " << turned << " scene\n"
                          << "drag right view:3d:0.5,0.5 view:3d:0.7,0.5 4 ctrl\nwait 1\n"
                          << "preset opacity CT soft tissue\nwait 2\n"
                          << "screenshot " << edited << " scene\n"
                          << "save " << editedScene << "\nquit\n";
    std::string log;
    const int status = runViewerScript((dir / name).string(),
                                       "--size 360x300 --no-panels " + arguments, script, log);
    INFO("viewer output: " << log);
    REQUIRE(status == 0);

    const Measures m = measure(readPng(shot));
    MESSAGE(name << ": coverage " << m.coverage << ", luminance spread " << m.spread);
    CHECK(m.coverage > 0.03);
    CHECK(m.spread > 0.08);

    // ctrl+s wrote the scene the viewer built beside the data, never over it; it reads back
    // with the data's own range in its TransferFunction.
    const fs::path saved = dir / savedName;
    REQUIRE(fs::exists(saved));
    ref_ptr<Node> scene = readScene(saved.string());
    const auto volumes = findAll(*scene, VolumeData::classType());
    const auto transfers = findAll(*scene, TransferFunction::classType());
    REQUIRE(volumes.size() == 1);
    REQUIRE(transfers.size() == 1);
    const auto [lo, hi] = static_cast<VolumeData*>(volumes[0])->grid()->minMax();
    const glm::vec2 range = static_cast<TransferFunction*>(transfers[0])->dataRange();
    CHECK(range.x == float(lo));
    CHECK(range.y == float(hi));

    // The turn changed the image; window/level and the preset changed it again, and the saved
    // function has the widened range around the same level.
    const Image first = readPng(shot), afterTurn = readPng(turned), afterEdit = readPng(edited);
    const int pixels = first.width * first.height;
    CHECK(changedPixels(first, afterTurn, 10.0f / 255.0f) > pixels / 100);
    CHECK(changedPixels(afterTurn, afterEdit, 10.0f / 255.0f) > pixels / 100);
    ref_ptr<Node> editedRoot = readScene(editedScene);
    const auto editedTransfers = findAll(*editedRoot, TransferFunction::classType());
    REQUIRE(editedTransfers.size() == 1);
    const glm::vec2 windowed = static_cast<TransferFunction*>(editedTransfers[0])->dataRange();
    const double span = hi - lo;
    CAPTURE(windowed.x);
    CAPTURE(windowed.y);
    CHECK(std::abs((windowed.y - windowed.x) - 1.2 * span) < 0.02 * span);
    CHECK(std::abs(0.5 * (windowed.x + windowed.y) - 0.5 * (lo + hi)) < 0.02 * span);
    fs::remove_all(dir);
}

} // namespace

TEST_CASE("volsg-view opens a gzip raw volume, a NRRD, a NIfTI and a DICOM series directly") {
    if (!haveXvfbRun()) {
        MESSAGE("xvfb-run is not installed: the viewer end-to-end test is skipped");
        return;
    }
    const fs::path data = VOLSG_DATA_DIR;
    const auto copy = [](const fs::path& from) {
        return [from](const fs::path& dir) {
            fs::copy(from, dir / from.filename(), fs::copy_options::recursive);
        };
    };
    SUBCASE("gzip raw (head CT, int16)") {
        openAndLook("headsq_64x64x93_int16le.raw.gz",
                    copy(data / "vtkjs-headsq/headsq_64x64x93_int16le.raw.gz"),
                    "--dims 64 64 93 --type short --spacing 3.2 3.2 1.5",
                    "headsq_64x64x93_int16le.iv");
    }
    SUBCASE("NRRD (chest CT)") {
        const std::string raw = (data / "vtkjs-lidc2/lidc2_256x256x133_uint8.raw.gz").string();
        openAndLook(
            "chest.nhdr",
            [&](const fs::path& dir) {
                // The data beside the header: a header names files only inside its folder.
                fs::copy_file(raw, dir / "chest.raw.gz");
                std::ofstream(dir / "chest.nhdr")
                    << "NRRD0004\ntype: uint8\ndimension: 3\nspace: right-anterior-superior\n"
                       "sizes: 256 256 133\nspace directions: (1.40625,0,0) (0,1.40625,0) "
                       "(0,0,2.5)\nencoding: gzip\ndata file: chest.raw.gz\n";
            },
            "", "chest.iv");
    }
    SUBCASE("NIfTI") {
        openAndLook("headsq_32x32x24_int16.nii.gz",
                    copy(data / "derived/headsq_32x32x24_int16.nii.gz"), "",
                    "headsq_32x32x24_int16.iv");
    }
    SUBCASE("DICOM series") {
        openAndLook("headsq_dicom", copy(data / "derived/headsq_dicom"), "", "headsq_dicom.iv");
    }
}
