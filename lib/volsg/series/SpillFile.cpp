#include <volsg/series/SpillFile.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/shearwarp/VoxelObject.h>

namespace volsg {

namespace {

constexpr char kMagic[8] = {'V', 'S', 'G', 'S', 'P', 'I', 'L', '1'};

/// Fixed-size head of a spill file, in the machine's own byte order (the file never leaves
/// the process that wrote it).
struct SpillHeader {
    char magic[8];
    std::int32_t dimensions[3];
    std::int32_t reserved;
    double spacing[3];
    double maxMagnitude;
    std::uint64_t voxelCount;
};

template <class T> void writeArray(std::ofstream& out, const std::vector<T>& v) {
    out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(T)));
}

template <class T>
void readArray(std::ifstream& in, std::vector<T>& v, std::size_t count, const std::string& path) {
    v.resize(count);
    in.read(reinterpret_cast<char*>(v.data()), std::streamsize(count * sizeof(T)));
    if (!in) throw Error("series disk cache file is truncated", path);
}

} // namespace

std::size_t writeSpillFile(const std::string& path, const VoxelObject& object) {
    const VoxelObject::Arrays a = object.arrays();
    SpillHeader header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    for (int axis = 0; axis < 3; ++axis) {
        header.dimensions[axis] = a.dimensions[axis];
        header.spacing[axis] = a.spacing[axis];
    }
    header.maxMagnitude = a.maxMagnitude;
    header.voxelCount = a.i.size();
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("cannot create series disk cache file", temporary);
        out.write(reinterpret_cast<const char*>(&header), sizeof header);
        writeArray(out, a.i);
        writeArray(out, a.j);
        writeArray(out, a.k);
        writeArray(out, a.value12);
        writeArray(out, a.gradientCode);
        writeArray(out, a.magnitude8);
        out.flush();
        if (!out) {
            out.close();
            std::remove(temporary.c_str());
            throw Error("cannot write series disk cache file (disk full?)", temporary);
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::remove(temporary.c_str());
        throw Error("cannot rename series disk cache file: " + error.message(), path);
    }
    return sizeof header + a.i.size() * (5 * sizeof(std::uint16_t) + sizeof(std::uint8_t));
}

ref_ptr<VoxelObject> readSpillFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw Error("cannot open series disk cache file", path);
    const auto fileSize = std::uint64_t(in.tellg());
    in.seekg(0);
    SpillHeader header{};
    in.read(reinterpret_cast<char*>(&header), sizeof header);
    if (!in || std::memcmp(header.magic, kMagic, sizeof kMagic) != 0)
        throw Error("not a series disk cache file", path);
    // The declared count must match the file before anything is allocated.
    const std::uint64_t perVoxel = 5 * sizeof(std::uint16_t) + sizeof(std::uint8_t);
    if (header.voxelCount > (fileSize - sizeof header) / perVoxel ||
        sizeof header + header.voxelCount * perVoxel != fileSize)
        throw Error("series disk cache file has the wrong size for its voxel count", path);
    VoxelObject::Arrays a;
    for (int axis = 0; axis < 3; ++axis) {
        a.dimensions[axis] = header.dimensions[axis];
        a.spacing[axis] = header.spacing[axis];
    }
    a.maxMagnitude = header.maxMagnitude;
    const auto n = std::size_t(header.voxelCount);
    readArray(in, a.i, n, path);
    readArray(in, a.j, n, path);
    readArray(in, a.k, n, path);
    readArray(in, a.value12, n, path);
    readArray(in, a.gradientCode, n, path);
    readArray(in, a.magnitude8, n, path);
    try {
        return VoxelObject::fromArrays(std::move(a));
    } catch (const Error& e) {
        throw Error(e.message(), path);
    }
}

} // namespace volsg
