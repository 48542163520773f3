#pragma once
// What the OME-Zarr tests share: a temporary folder, file bytes, patterned grids and the one
// line an Error says.

#include "support/TempDir.h"
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include <unistd.h>

#include <volsg/core/Error.h>
#include <volsg/volume/VolumeGrid.h>

namespace zarrtest {

namespace fs = std::filesystem;

/// This file's temporary folders.
class TempDir : public volsg::test::TempDir {
public:
    TempDir() : volsg::test::TempDir("volsg-zarr") {}
};

inline void writeFile(const std::string& path, const std::string& bytes) {
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    REQUIRE(out.good());
}

// No assertion inside: the text may be an assertion's message, which doctest builds while it
// reports (an assertion there would wait on the reporter's lock for ever).
inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "(cannot read " + path + ")";
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Values that use every byte of the type and vary along every axis.
inline double patternValue(volsg::VoxelType type, int x, int y, int z) {
    const long n = long(x) * 7 + long(y) * 131 + long(z) * 1031;
    switch (type) {
    case volsg::VoxelType::UByte:
        return double((n * 37 + 11) % 256);
    case volsg::VoxelType::UShort:
        return double((n * 4099 + 513) % 65536);
    case volsg::VoxelType::Short:
        return double((n * 4099 + 513) % 65536 - 32768);
    case volsg::VoxelType::Float:
        return double(float(n) * 0.75f - 20.125f);
    }
    return 0.0;
}

inline volsg::ref_ptr<volsg::VolumeGrid> patternGrid(glm::ivec3 dims, volsg::VoxelType type,
                                                     glm::dvec3 spacing = glm::dvec3(1.0)) {
    auto grid = volsg::VolumeGrid::create(dims, type, spacing);
    for (int z = 0; z < dims.z; ++z)
        for (int y = 0; y < dims.y; ++y)
            for (int x = 0; x < dims.x; ++x)
                grid->setValue(x, y, z, patternValue(type, x, y, z));
    return grid;
}

// How many voxels differ (0 when equal), with the first difference for the message.
inline std::size_t countDifferences(const volsg::VolumeGrid& got, const volsg::VolumeGrid& want,
                                    std::string& first) {
    if (got.dimensions() != want.dimensions() || got.type() != want.type()) {
        first = "dimensions or type differ";
        return got.voxelCount() + 1;
    }
    std::size_t count = 0;
    for (std::size_t i = 0; i < got.voxelCount(); ++i)
        if (got.value(i) != want.value(i) && count++ == 0)
            first = "voxel " + std::to_string(i) + ": " + std::to_string(got.value(i)) +
                    " instead of " + std::to_string(want.value(i));
    return count;
}

// The one line an Error says, or what else happened.
inline std::string errorOf(const std::function<void()>& run) {
    try {
        run();
    } catch (const volsg::Error& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("not a volsg::Error: ") + e.what();
    }
    return "no error was thrown";
}

inline bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

#define CHECK_HAS(text, part)                                                                      \
    CHECK_MESSAGE(zarrtest::has(text, part), "'" << (text) << "' lacks '" << (part) << "'")

} // namespace zarrtest
