// volsg-render across 1, 2 and 4 MPI processes (mpirun, oversubscribed on one machine) makes
// the image one process makes, within 1/255 per channel, for views whose brick and part
// order changes within the image. Built and registered only where MPI is found
// (tests/CMakeLists.txt); the launcher is VOLSG_MPIEXEC.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <support/TempDir.h>
#include <volsg/image/Image.h>
#include <volsg/volume/VolumeGrid.h>
#include <volsg/volumeio/OmeZarrPyramid.h>

namespace {

struct Run {
    int status;
    std::string out, err;
};

std::string readAll(const std::string& path) {
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

Run run(const volsg::test::TempDir& dir, const std::string& command) {
    const std::string out = dir.file("stdout.txt"), err = dir.file("stderr.txt");
    const int raw = std::system((command + " >" + out + " 2>" + err).c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, readAll(out), readAll(err)};
}

std::string render() {
    return std::string(VOLSG_BINARY_DIR) + "/viewer/volsg-render";
}

/// mpirun with N processes on this machine: more processes than cores, shared memory only
/// (a container has no network fabric; no single-copy transfers, which need ptrace rights a
/// container may not grant), as root in CI, without LeakSanitizer in the
/// processes it starts (under ASan: OpenMPI leaks at exit), and its session files in the
/// test's own folder (two mpiruns started at once raced to create /tmp/ompi.HOST.UID).
std::string mpirun(const volsg::test::TempDir& dir, int processes) {
    return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader "
           "OMPI_MCA_btl_vader_single_copy_mechanism=none "
           "ASAN_OPTIONS=detect_leaks=0 OMPI_MCA_orte_tmpdir_base=" +
           dir.path().string() + " " + VOLSG_MPIEXEC + " --oversubscribe -np " +
           std::to_string(processes) + " ";
}

/// A Marschner-Lobb volume (48^3, box about [-1, 1]^3) under `transform`, seen by `camera`,
/// with `extra` nodes before it (opaque shapes).
std::string scene(const std::string& camera, const std::string& transform,
                  const std::string& extra = "") {
    return "#Inventor V2.1 ascii\nSeparator {\n" + camera + "\n" + extra + "\n  Transform { " +
           transform +
           " }\n"
           "  VolumeData { generator MARSCHNER_LOBB dimensions 48 48 48 }\n"
           "  TransferFunction { red [ 0 0.9, 1 0.2 ] green [ 0 0.3, 1 0.8 ] blue [ 0 0.1, 1 1 ]\n"
           "    alpha [ 0 0, 0.3 0.02, 0.6 0.2, 1 0.6 ] }\n"
           "  Volume { }\n}\n";
}

float maxDifference(const volsg::Image& a, const volsg::Image& b) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    float worst = 0.0f;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(a.pixels[i][c] - b.pixels[i][c]));
    return worst;
}

/// Renders `text` in one plain process and with 1, 2 and 4 MPI processes; every MPI image
/// within 1/255 of the plain one, and the view not empty (a blank image would match too).
/// `prepare` writes what the scene reads into the folder; `timingSays`, when given, is what
/// --mpi-timing must print with 4 processes.
/// Returns what --mpi-timing printed for 1, 2 and 4 processes, in that order.
std::vector<std::string>
checkAcrossProcesses(const std::string& name, const std::string& text,
                     void (*prepare)(const volsg::test::TempDir&) = nullptr,
                     const std::string& timingSays = "", const std::string& options = "") {
    std::vector<std::string> printed;
    const volsg::test::TempDir dir("volsg-sortlast");
    if (prepare) prepare(dir);
    const std::string file = dir.file(name + ".iv");
    std::ofstream(file) << text;
    const std::string single = dir.file("single.pfm");
    const Run plain = run(dir, render() + " " + file + " -o " + single + " --size 97x81");
    REQUIRE_MESSAGE(plain.status == 0, plain.err);
    const volsg::Image reference = volsg::readPfm(single);
    float brightest = 0.0f;
    for (const glm::vec4& p : reference.pixels)
        brightest = std::max({brightest, p.r, p.g, p.b});
    CHECK(brightest > 0.2f);
    for (const int processes : {1, 2, 4}) {
        const std::string out = dir.file("mpi" + std::to_string(processes) + ".pfm");
        const Run r = run(dir, mpirun(dir, processes) + render() + " " + file + " -o " + out +
                                   " --size 97x81 --mpi-timing " + options);
        if (processes == 4 && !timingSays.empty())
            CHECK(r.out.find(timingSays) != std::string::npos);

        CAPTURE(name);
        CAPTURE(processes);
        REQUIRE_MESSAGE(r.status == 0, r.err);
        const float difference = maxDifference(volsg::readPfm(out), reference);
        MESSAGE(name << ", " << processes << " processes: max difference " << difference * 255.0f
                     << "/255");
        CHECK(difference <= 1.0f / 255.0f);
        printed.push_back(r.out);
    }
    return printed;
}

} // namespace

TEST_CASE("sort-last equals one process: orthographic, oblique") {
    checkAcrossProcesses("ortho", scene("  OrthographicCamera { position 0 0 4 height 2.6 }",
                                        "rotation 1 1 0.3 0.7"));
}

TEST_CASE("sort-last equals one process: perspective from outside, oblique") {
    checkAcrossProcesses("persp", scene("  PerspectiveCamera { position 0 0 4.5 "
                                        "heightAngle 0.6 nearDistance 1 farDistance 10 }",
                                        "rotation 0.3 1 0.2 0.9"));
}

TEST_CASE("sort-last equals one process: composited by reduce-scatter and gather") {
    // 97 x 81 pixels split into no whole number of blocks: the last is padded.
    checkAcrossProcesses("scatter",
                         scene("  PerspectiveCamera { position 0 0 4.5 heightAngle 0.6 "
                               "nearDistance 1 farDistance 10 }",
                               "rotation 0.3 1 0.2 0.9"),
                         nullptr, "composite by reduce-scatter and gather",
                         "--mpi-composite reduce-scatter");
}

TEST_CASE("sort-last equals one process: the eye within the box's extent along x and y") {
    // The eye faces the box's front face: the parts' order flips within the image along x and
    // y (bricks left of the eye are drawn right to left, those right of it left to right).
    checkAcrossProcesses("beside", scene("  PerspectiveCamera { position 0.15 -0.1 2.2 "
                                         "heightAngle 1.2 nearDistance 0.5 farDistance 10 }",
                                         "rotation 0 0 1 0"));
}

TEST_CASE("sort-last equals one process: the camera inside the volume") {
    checkAcrossProcesses("inside", scene("  PerspectiveCamera { position 0.2 0.1 0.4 "
                                         "heightAngle 1.2 nearDistance 0.05 farDistance 10 }",
                                         "rotation 0 1 0 0.4"));
}

TEST_CASE("sort-last equals one process: an opaque sphere inside stops the volume") {
    checkAcrossProcesses("mesh", scene("  PerspectiveCamera { position 0 0 4.5 heightAngle 0.6 "
                                       "nearDistance 1 farDistance 10 }\n"
                                       "  DirectionalLight { direction -0.3 -0.4 -1 }",
                                       "rotation 1 0.2 0 0.5",
                                       "  Separator { Material { diffuseColor 1 0.8 0.2 } "
                                       "Sphere { radius 0.45 } }"));
}

namespace {

/// The "opaque shapes" column of --mpi-timing's per-process table, by rank.
std::vector<int> opaqueShapesPerProcess(const std::string& printed) {
    std::vector<int> shapes;
    std::istringstream lines(printed);
    std::string line;
    bool inTable = false;
    while (std::getline(lines, line)) {
        if (line.find("opaque shapes") != std::string::npos) {
            inTable = true;
            continue;
        }
        if (!inTable) continue;
        std::istringstream fields(line);
        std::vector<std::string> columns;
        for (std::string f; fields >> f;)
            columns.push_back(f);
        if (columns.size() != 9) break;
        shapes.push_back(std::stoi(columns[7]));
    }
    return shapes;
}

} // namespace

TEST_CASE("sort-last shares the opaque shapes: each process draws its own, composited by depth") {
    // Nine opaque shapes in and around the volume, and a glTF model: each process draws its
    // share with depth; one depth composite gives every process the whole scene's depth,
    // which stops its part of the volume. The image is one process's within 1/255.
    std::string shapes = "  DirectionalLight { direction -0.3 -0.4 -1 }\n"
                         "  Separator { Transform { scaleFactor 0.005 0.005 0.005 } "
                         "GltfModel { fileName \"" VOLSG_SOURCE_DIR
                         "/examples/data/gltf/Duck/glTF-Binary/Duck.glb\" } }\n";
    for (int i = 0; i < 9; ++i) {
        const double x = -0.9 + 0.45 * (i % 5), y = i < 5 ? -0.5 : 0.45, z = 0.3 * (i % 3) - 0.3;
        const char* shape = i % 3 == 0   ? "Sphere { radius 0.2 }"
                            : i % 3 == 1 ? "Cube { width 0.3 height 0.25 depth 0.35 }"
                                         : "Cone { bottomRadius 0.18 height 0.4 }";
        shapes += "  Separator { Translation { translation " + std::to_string(x) + " " +
                  std::to_string(y) + " " + std::to_string(z) + " } Material { diffuseColor " +
                  std::to_string(0.2 + 0.08 * i) + " 0.7 0.3 } " + shape + " }\n";
    }
    const std::vector<std::string> printed = checkAcrossProcesses(
        "shapes", scene("  PerspectiveCamera { position 0 0 4.5 heightAngle 0.7 nearDistance 1 "
                        "farDistance 10 }",
                        "rotation 1 0.2 0 0.5", shapes));
    REQUIRE(printed.size() == 3);
    const std::vector<int> one = opaqueShapesPerProcess(printed[0]);
    REQUIRE(one.size() == 1);
    CHECK(one[0] >= 10); // the nine shapes and the model's primitives
    for (const std::size_t processes : {std::size_t(2), std::size_t(4)}) {
        const std::vector<int> each = opaqueShapesPerProcess(printed[processes == 2 ? 1 : 2]);
        CAPTURE(processes);
        REQUIRE(each.size() == processes);
        int sum = 0;
        for (const int n : each) {
            CHECK(n >= one[0] / int(processes)); // round robin: a fair share each
            CHECK(n <= one[0] / int(processes) + 1);
            sum += n;
        }
        CHECK(sum == one[0]);
    }
}

namespace {

/// A 16-bit volume (values 3000 .. 23000: its natural range is not the type's) as an
/// OME-Zarr image of 8^3 chunks, ml.zarr in the test's folder.
void writeSixteenBitImage(const volsg::test::TempDir& dir) {
    const glm::ivec3 dims(40, 36, 32);
    auto grid = volsg::VolumeGrid::create(dims, volsg::VoxelType::UShort, glm::dvec3(0.05));
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x) {
                const glm::dvec3 p = (glm::dvec3(x, y, z) + 0.5) / glm::dvec3(dims) - 0.5;
                const double shell = std::exp(-std::pow((glm::length(p) - 0.3) * 12.0, 2.0));
                const double ripple = 0.5 + 0.5 * std::sin(20.0 * p.x) * std::cos(17.0 * p.y);
                grid->setValue(x, y, z, 3000.0 + 20000.0 * shell * ripple);
            }
    volsg::PyramidOptions options;
    options.chunk = 8;
    volsg::writeOmeZarrPyramid(*grid, dir.file("ml.zarr"), options);
}

std::string zarrScene(const std::string& volumeFields, const std::string& dataFields = "") {
    return "#Inventor V2.1 ascii\nSeparator {\n"
           "  PerspectiveCamera { position 0.3 0.2 3 heightAngle 0.7 nearDistance 0.5 "
           "farDistance 10 }\n"
           "  Transform { rotation 1 1 0 0.5 }\n"
           "  VolumeData { fileName \"ml.zarr\" " +
           dataFields +
           " }\n"
           "  TransferFunction { red [ 0 0.2, 1 1 ] green [ 0 0.8, 1 0.4 ] blue [ 0 1, 1 0.1 ]\n"
           "    alpha [ 0 0, 0.2 0.05, 1 0.8 ] }\n"
           "  Volume { " +
           volumeFields + " }\n}\n";
}

} // namespace

TEST_CASE("sort-last equals one process when each process reads only its own chunks") {
    // Fixed plane rules (errorTarget 0): slabs of one sample, two planes a voxel, as one
    // process draws them; each process reads its part and ghost of the OME-Zarr image, and
    // the processes agree on the data's range (16-bit: its own min and max).
    checkAcrossProcesses("own-chunks", zarrScene("errorTarget 0"), writeSixteenBitImage,
                         "each process read only its part and 4 ghost voxels");
}

namespace {

/// The RMSE per channel of two images' colours.
double rmse(const volsg::Image& a, const volsg::Image& b) {
    REQUIRE(a.pixels.size() == b.pixels.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            sum +=
                double(a.pixels[i][c] - b.pixels[i][c]) * double(a.pixels[i][c] - b.pixels[i][c]);
    return std::sqrt(sum / (3.0 * double(a.pixels.size())));
}

} // namespace

TEST_CASE("sort-last with an error target (the default): every process reads the OME-Zarr "
          "image whole, and the image is one process's") {
    // Slabs of the chosen quadrature may reach across the parts' faces: holding the whole
    // image, each process draws its fragments as one process does (within 1/255 of it).
    checkAcrossProcesses("target-whole", zarrScene(""), writeSixteenBitImage,
                         "every process read the whole volume: the Volume draws to an error "
                         "target");
}

TEST_CASE("sort-last with an error target and --mpi-own-chunks: each process reads its own "
          "chunks, and the image meets the target") {
    // The Volume's default (errorTarget 0.5/255). Each process reads its part and ghost, ends
    // its slabs at its part's faces (as at brick seams), judges the error on the rays through
    // its part, and all draw the costliest of the processes' choices. The image meets the
    // target against the reference ray caster, as one process's does. It is close to one
    // process drawing what the processes drew, not bit for bit (the slabs are cut at the parts'
    // faces); one process choosing for itself may draw other settings (its prediction on the
    // whole box is not the parts').
    const volsg::test::TempDir dir("volsg-sortlast");
    writeSixteenBitImage(dir);
    const std::string file = dir.file("target.iv");
    std::ofstream(file) << zarrScene("");
    const std::string size = " --size 97x81";
    const Run reference =
        run(dir, render() + " " + file + " -o " + dir.file("ref.pfm") + size + " --reference");
    REQUIRE_MESSAGE(reference.status == 0, reference.err);
    const Run plain = run(dir, render() + " " + file + " -o " + dir.file("one.pfm") + size);
    REQUIRE_MESSAGE(plain.status == 0, plain.err);
    const volsg::Image exact = volsg::readPfm(dir.file("ref.pfm"));
    const double target = 0.5 / 255.0;
    const double oneAgainstReference = rmse(volsg::readPfm(dir.file("one.pfm")), exact);
    CHECK(oneAgainstReference <= target);
    for (const int processes : {2, 4}) {
        CAPTURE(processes);
        const std::string out = dir.file("mpi" + std::to_string(processes) + ".pfm");
        const Run r = run(dir, mpirun(dir, processes) + render() + " " + file + " -o " + out +
                                   size + " --mpi-timing --mpi-own-chunks --verbose");
        REQUIRE_MESSAGE(r.status == 0, r.err);
        CHECK(r.out.find("each process read only its part and 4 ghost voxels") !=
              std::string::npos);
        // What the processes drew (rank 0's --verbose line), drawn by one process.
        const std::size_t line = r.out.find("Volume #1: ");
        REQUIRE_MESSAGE(line != std::string::npos, r.out);
        int planes = 0, samples = 0;
        REQUIRE(std::sscanf(r.out.c_str() + line, "Volume #1: %d planes x %d samples", &planes,
                            &samples) == 2);
        const bool preIntegrated = r.out.find("pre-integrated", line) < r.out.find('\n', line);
        const std::string drawn = dir.file("drawn" + std::to_string(processes) + ".iv");
        std::ofstream(drawn) << zarrScene("numPlanes " + std::to_string(planes) +
                                          " samplesPerPlane " + std::to_string(samples) +
                                          (preIntegrated ? " preIntegrated TRUE" : ""));
        const std::string drawnOut = dir.file("drawn" + std::to_string(processes) + ".pfm");
        const Run alone = run(dir, render() + " " + drawn + " -o " + drawnOut + size);
        REQUIRE_MESSAGE(alone.status == 0, alone.err);
        const volsg::Image one = volsg::readPfm(drawnOut);
        const volsg::Image image = volsg::readPfm(out);
        const double againstReference = rmse(image, exact), againstOne = rmse(image, one);
        MESSAGE(processes << " processes: RMSE " << againstReference * 255.0
                          << "/255 against the reference (one process: "
                          << oneAgainstReference * 255.0 << "), " << planes << " planes x "
                          << samples << ": " << againstOne * 255.0
                          << "/255 against one process drawing that, at most "
                          << maxDifference(image, one) * 255.0 << "/255 apart");
        CHECK(againstReference <= target);
        CHECK(againstOne <= 0.5 * target);
        CHECK(maxDifference(image, one) <= 2.0f / 255.0f);
    }
}

namespace {

/// The bricks each process paged in, from --mpi-timing's table.
std::vector<int> bricksPagedIn(const std::string& printed) {
    std::vector<int> bricks;
    const std::size_t table = printed.find("bricks paged in");
    if (table == std::string::npos) return bricks;
    std::istringstream rows(printed.substr(printed.find('\n', table) + 1));
    std::string line;
    while (std::getline(rows, line)) {
        int rank = 0, frames = 0, count = 0;
        if (std::sscanf(line.c_str(), "%d %d %d", &rank, &frames, &count) != 3) break;
        bricks.push_back(count);
    }
    return bricks;
}

} // namespace

TEST_CASE("sort-last of a paged pyramid: each process pages in only its part's bricks") {
    // paging ON: the 16-bit image's pyramid (8^3 chunks, 100 bricks at level 0) is drawn
    // brick by brick. Each process selects and loads only the bricks meeting its part; the
    // processes agree on the plane spacing (the finest level any draws) and draw until all
    // have converged: the image of one process converged.
    const std::vector<std::string> printed = checkAcrossProcesses(
        "paged", zarrScene("lodPixels 0.1", "paging ON memoryBudget 1"), writeSixteenBitImage,
        "each process paged in only the bricks of its part");
    REQUIRE(printed.size() == 3);
    const std::vector<int> one = bricksPagedIn(printed[0]), four = bricksPagedIn(printed[2]);
    REQUIRE(one.size() == 1);
    REQUIRE(four.size() == 4);
    int sum = 0;
    for (const int bricks : four) {
        CHECK(bricks > 0);
        CHECK(bricks < one[0] * 3 / 4); // a part and the bricks its seams cut, not the whole
        sum += bricks;
    }
    MESSAGE("bricks paged in: one process " << one[0] << ", four " << four[0] << " + " << four[1]
                                            << " + " << four[2] << " + " << four[3]);
    CHECK(sum < 2 * one[0]);
}

TEST_CASE("sort-last with more processes than the volume has cells: the empty parts add nothing") {
    // A 2^3 volume is one cell, which is not cut: three of the four processes draw nothing.
    const volsg::test::TempDir dir("volsg-sortlast");
    const std::string file = dir.file("tiny.iv");
    std::ofstream(file) << "#Inventor V2.1 ascii\nSeparator {\n"
                           "  PerspectiveCamera { position 0 0 6 heightAngle 0.6 }\n"
                           "  Transform { rotation 1 1 0 0.6 }\n"
                           "  VolumeData { generator SOFT_SPHERE dimensions 2 2 2 }\n"
                           "  TransferFunction { alpha [ 0 0.3, 1 0.9 ] }\n  Volume { }\n}\n";
    const Run plain =
        run(dir, render() + " " + file + " -o " + dir.file("a.pfm") + " --size 64x64");
    REQUIRE_MESSAGE(plain.status == 0, plain.err);
    const Run r = run(dir, mpirun(dir, 4) + render() + " " + file + " -o " + dir.file("b.pfm") +
                               " --size 64x64 --mpi-timing");
    REQUIRE_MESSAGE(r.status == 0, r.err);
    CHECK(maxDifference(volsg::readPfm(dir.file("a.pfm")), volsg::readPfm(dir.file("b.pfm"))) <=
          1.0f / 255.0f);
    // --mpi-timing: one row per process, the three empty ones with no bricks.
    CHECK(r.out.find("sort-last: 4 processes") != std::string::npos);
    CHECK(r.out.find("composite by reduce (median of 15)") != std::string::npos);
}

TEST_CASE("sort-last refuses what it cannot split, in one line from one process") {
    const volsg::test::TempDir dir("volsg-sortlast");
    const std::string file = dir.file("mip.iv");
    std::ofstream(file) << "#Inventor V2.1 ascii\nSeparator {\n"
                           "  VolumeData { generator SOFT_SPHERE dimensions 16 16 16 }\n"
                           "  TransferFunction { alpha [ 0 0.3, 1 0.9 ] }\n"
                           "  Volume { renderMode MIP }\n}\n";
    const Run r = run(dir, mpirun(dir, 2) + render() + " " + file + " -o " + dir.file("m.png"));
    CHECK(r.status != 0);
    CHECK(r.err.rfind("volsg-render: ", 0) == 0); // the tool's one line comes first
    CHECK(r.err.find("mip.iv:5:3: Volume: rendering across processes (sort-last) composites "
                     "DVR only") != std::string::npos);
    // Said once, by one process.
    const std::size_t first = r.err.find("composites DVR only");
    CHECK(r.err.find("composites DVR only", first + 1) == std::string::npos);
}

TEST_CASE("the sort-last options outside mpirun are refused in one line") {
    const volsg::test::TempDir dir("volsg-sortlast");
    const std::string file = dir.file("one.iv");
    std::ofstream(file) << zarrScene("");
    for (const char* option :
         {"--mpi-timing", "--mpi-own-chunks", "--mpi-composite reduce-scatter"}) {
        CAPTURE(option);
        const Run r = run(dir, render() + " " + file + " -o " + dir.file("o.png") + " " + option);
        CHECK(r.status != 0);
        CHECK(r.err.find("apply to a run under mpirun") != std::string::npos);
    }
}
