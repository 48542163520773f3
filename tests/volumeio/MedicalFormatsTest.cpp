// NIfTI and DICOM readers, and the geometry of every reader that has one: the files in
// examples/data/derived were written by make_derived.py from the head CT with a known
// placement (spacing 6.4 x 6.4 x 6.0 mm, a 30-degree turn about z, origin (-100, -80, 20) mm in
// LPS); each reader must give back those numbers and the head CT's voxels. Malformed files are
// written by the test.

#include "support/TempDir.h"
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

#include <volsg/core/Error.h>
#include <volsg/volumeio/VolumeReader.h>

using namespace volsg;
namespace fs = std::filesystem;

namespace {

const std::string derived = std::string(VOLSG_DATA_DIR) + "/derived/";

// The placement make_derived.py wrote.
const glm::dvec3 writtenSpacing(6.4, 6.4, 6.0);
const glm::dvec3 writtenOrigin(-100.0, -80.0, 20.0);
const double c30 = std::sqrt(3.0) / 2.0, s30 = 0.5;
const glm::dmat3 writtenDirections(glm::dvec3(c30, s30, 0), glm::dvec3(-s30, c30, 0),
                                   glm::dvec3(0, 0, 1));

// The full head CT, from which the derived files sample every (2, 2, 4)th voxel.
ref_ptr<VolumeGrid> headCt() {
    static ref_ptr<VolumeGrid> grid = [] {
        RawVolumeLayout layout;
        layout.dimensions = {64, 64, 93};
        layout.type = VoxelType::Short;
        return readRawVolume(
            std::string(VOLSG_DATA_DIR) + "/vtkjs-headsq/headsq_64x64x93_int16le.raw.gz", layout);
    }();
    return grid;
}

// Every voxel of `grid` is the head CT's sample mapped by `value(stored)`.
template <class F> void checkHeadVoxels(const VolumeGrid& grid, F value) {
    REQUIRE(grid.dimensions() == glm::ivec3(32, 32, 24));
    const ref_ptr<VolumeGrid> head = headCt();
    int mismatches = 0;
    for (int k = 0; k < 24; ++k)
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 32; ++i)
                if (grid.value(i, j, k) != value(head->value(2 * i, 2 * j, 4 * k))) ++mismatches;
    CHECK(mismatches == 0);
}

void checkWrittenGeometry(const VolumeGrid& grid, double tolerance) {
    const VolumeGeometry& g = grid.geometry();
    CHECK(g.known);
    for (int a = 0; a < 3; ++a) {
        CHECK(grid.spacing()[a] == doctest::Approx(writtenSpacing[a]).epsilon(tolerance));
        CHECK(g.origin[a] == doctest::Approx(writtenOrigin[a]).epsilon(tolerance));
        for (int r = 0; r < 3; ++r)
            CHECK(g.directions[a][r] ==
                  doctest::Approx(writtenDirections[a][r]).epsilon(tolerance).scale(1.0));
    }
}

/// This file's temporary folders.
class TempDir : public volsg::test::TempDir {
public:
    TempDir() : volsg::test::TempDir("volsg-medical") {}
};

void writeBytes(const std::string& path, const std::vector<unsigned char>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    REQUIRE(out.good());
}

// A minimal valid little-endian NIfTI-1 header of a 2x2x2 uint8 volume (no placement).
std::vector<unsigned char> smallNifti() {
    std::vector<unsigned char> h(352 + 8, 0);
    const auto put16 = [&](std::size_t at, std::int16_t v) { std::memcpy(&h[at], &v, 2); };
    const auto putF = [&](std::size_t at, float v) { std::memcpy(&h[at], &v, 4); };
    const std::int32_t size = 348;
    std::memcpy(&h[0], &size, 4);
    const std::int16_t dim[8] = {3, 2, 2, 2, 1, 1, 1, 1};
    for (int i = 0; i < 8; ++i)
        put16(40 + 2 * std::size_t(i), dim[i]);
    put16(70, 2);
    put16(72, 8);
    for (int i = 1; i <= 3; ++i)
        putF(76 + 4 * std::size_t(i), 1.5f);
    putF(108, 352.0f);
    std::memcpy(&h[344], "n+1", 4);
    for (int i = 0; i < 8; ++i)
        h[352 + std::size_t(i)] = static_cast<unsigned char>(10 * i);
    return h;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

} // namespace

TEST_CASE("NIfTI-1 gzip with a qform: the head CT's voxels, spacing, orientation and origin") {
    const ref_ptr<VolumeGrid> grid = readVolume(derived + "headsq_32x32x24_int16.nii.gz");
    CHECK(grid->type() == VoxelType::Short);
    checkHeadVoxels(*grid, [](double v) { return v; });
    // The qform is stored in float32: its quaternion and offset carry about 1e-7 relative error.
    checkWrittenGeometry(*grid, 1e-5);
}

TEST_CASE("NIfTI-2 big-endian with an sform and scl_slope: FLOAT stored * 0.5 + 10") {
    const ref_ptr<VolumeGrid> grid = readNifti(derived + "headsq_32x32x24_nifti2_be_scaled.nii.gz");
    CHECK(grid->type() == VoxelType::Float);
    checkHeadVoxels(*grid, [](double v) { return double(float(v * 0.5 + 10.0)); });
    checkWrittenGeometry(*grid, 1e-12); // doubles in NIfTI-2
}

TEST_CASE("DICOM series from its folder or one file: sorted by position, rescaled to SHORT HU") {
    for (const std::string& path :
         {derived + "headsq_dicom", derived + "headsq_dicom/slice-010.dcm"}) {
        CAPTURE(path);
        const ref_ptr<VolumeGrid> grid = readVolume(path);
        CHECK(grid->type() == VoxelType::Short); // 12-bit unsigned with intercept -1024
        // Files are named in reverse slice order: a reader that sorts by name flips z.
        checkHeadVoxels(*grid, [](double v) { return v - 1024.0; });
        checkWrittenGeometry(*grid, 1e-5); // positions written with 4 decimals
    }
}

TEST_CASE("localToPatient puts each voxel centre where the file's geometry says") {
    const ref_ptr<VolumeGrid> grid = readVolume(derived + "headsq_dicom");
    const glm::dmat4 m = grid->geometry().localToPatient(grid->dimensions(), grid->spacing());
    for (const glm::ivec3 ijk : {glm::ivec3(0), glm::ivec3(31, 0, 0), glm::ivec3(5, 17, 23)}) {
        const glm::dvec3 local = grid->voxelCenter(ijk.x, ijk.y, ijk.z);
        const glm::dvec3 patient = glm::dvec3(m * glm::dvec4(local, 1.0));
        const glm::dvec3 expected =
            writtenOrigin + writtenDirections * (writtenSpacing * glm::dvec3(ijk));
        CHECK(glm::length(patient - expected) < 1e-3);
    }
}

TEST_CASE("NRRD space directions, space origin and a RAS space give LPS geometry") {
    const ref_ptr<VolumeGrid> grid =
        readVolume(std::string(VOLSG_DATA_DIR) + "/vtkjs-lidc2/lidc2_chest.nhdr");
    CHECK(grid->dimensions() == glm::ivec3(256, 256, 133));
    CHECK(grid->spacing() == glm::dvec3(1.40625, 1.40625, 2.5));
    CHECK(grid->geometry().known);
    CHECK(grid->geometry().directions ==
          glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1)));
}

TEST_CASE("MetaImage Offset and TransformMatrix give the geometry") {
    TempDir dir;
    std::ofstream(dir.file("v.mhd")) << "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\n"
                                        "ElementType = MET_UCHAR\nElementSpacing = 1 2 3\n"
                                        "Offset = 5 -6 7\nTransformMatrix = 0 1 0 -1 0 0 0 0 1\n"
                                        "ElementDataFile = v.raw\n";
    writeBytes(dir.file("v.raw"), std::vector<unsigned char>(8, 1));
    const ref_ptr<VolumeGrid> grid = readVolume(dir.file("v.mhd"));
    CHECK(grid->geometry().known);
    CHECK(grid->geometry().origin == glm::dvec3(5, -6, 7));
    CHECK(grid->geometry().directions[0] == glm::dvec3(0, 1, 0));
    CHECK(grid->geometry().directions[1] == glm::dvec3(-1, 0, 0));
    CHECK(readRawVolume(dir.file("v.raw"), RawVolumeLayout{{2, 2, 2}}) != nullptr);
    CHECK_FALSE(readRawVolume(dir.file("v.raw"), RawVolumeLayout{{2, 2, 2}})->geometry().known);
}

TEST_CASE("NIfTI without qform or sform: pixdim spacing, no geometry, .hdr/.img pairs") {
    TempDir dir;
    writeBytes(dir.file("small.nii"), smallNifti());
    const ref_ptr<VolumeGrid> grid = readVolume(dir.file("small.nii"));
    CHECK(grid->spacing() == glm::dvec3(1.5));
    CHECK_FALSE(grid->geometry().known);
    CHECK(grid->value(1, 1, 1) == 70.0);

    std::vector<unsigned char> header = smallNifti();
    std::memcpy(&header[344], "ni1", 4);
    const float zero = 0.0f;
    std::memcpy(&header[108], &zero, 4);
    writeBytes(dir.file("pair.hdr"),
               std::vector<unsigned char>(header.begin(), header.begin() + 348));
    writeBytes(dir.file("pair.img"),
               std::vector<unsigned char>(header.begin() + 352, header.end()));
    CHECK(readVolume(dir.file("pair.hdr"))->value(1, 0, 0) == 10.0);
}

TEST_CASE("malformed NIfTI files are refused with one line naming the file") {
    TempDir dir;
    const std::string path = dir.file("bad.nii");
    const auto refuse = [&](std::vector<unsigned char> bytes, const std::string& expected) {
        writeBytes(path, bytes);
        const std::string message = errorOf([&] { readVolume(path); });
        CAPTURE(message);
        CHECK(message.find(path) != std::string::npos);
        CHECK(message.find(expected) != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
    };
    refuse({1, 2, 3}, "not a NIfTI file");
    std::vector<unsigned char> h = smallNifti();
    refuse(std::vector<unsigned char>(h.begin(), h.begin() + 200), "truncated NIfTI-1 header");
    h = smallNifti();
    std::memcpy(&h[344], "xyz", 4);
    refuse(h, "magic");
    h = smallNifti();
    h[40] = 5; // dim[0] 5 with dim[4], dim[5] = 1: fine; then dim[5] = 7: a vector volume
    h[50] = 7;
    refuse(h, "only single 3D volumes");
    h = smallNifti();
    h[70] = 64; // float64
    refuse(h, "unsupported NIfTI datatype 64");
    h = smallNifti();
    const std::int16_t huge = 32000;
    for (int a = 1; a <= 3; ++a)
        std::memcpy(&h[40 + 2 * std::size_t(a)], &huge, 2); // 32000^3 bytes: over the limit
    refuse(h, "volume of 32000 x 32000 x 32000");
    h = smallNifti();
    h.pop_back();
    refuse(h, "expected 8 bytes of data");
    h = smallNifti();
    const float inside = 100.0f;
    std::memcpy(&h[108], &inside, 4);
    refuse(h, "lies inside the header");
}

TEST_CASE("malformed DICOM series are refused naming the file") {
    TempDir dir;
    // A series with a slice missing in the middle: the gap is twice the others.
    for (const auto& entry : fs::directory_iterator(derived + "headsq_dicom"))
        if (entry.path().filename() != "slice-012.dcm")
            fs::copy_file(entry.path(), dir.path() / entry.path().filename());
    std::string message = errorOf([&] { readVolume(dir.path().string()); });
    CAPTURE(message);
    CHECK(message.find("not evenly spaced") != std::string::npos);
    // Named where the slice is missing: slice k = 12 (file 012) is gone, k = 13 (file 011)
    // comes after a gap of two spacings.
    CHECK(message.find("slice-011.dcm") != std::string::npos);
    // Twice the spacing (positions are written to 4 decimals: 11.99999 or 12.00001).
    CHECK((message.find("a gap of 11.99") != std::string::npos ||
           message.find("a gap of 12.00") != std::string::npos));

    TempDir empty;
    std::ofstream(empty.file("README")) << "no images here\n";
    message = errorOf([&] { readVolume(empty.path().string()); });
    CHECK(message.find("no DICOM files") != std::string::npos);

    writeBytes(empty.file("fake.dcm"), std::vector<unsigned char>(300, 0));
    message = errorOf([&] { readVolume(empty.file("fake.dcm")); });
    CAPTURE(message);
    CHECK(message.find("fake.dcm") != std::string::npos);
}
