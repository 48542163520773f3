#pragma once
// A Zarr v2 array's metadata (its .zarray): what volsg reads and writes of it.

#include <cstdint>
#include <string>
#include <vector>

#include <volsg/volume/VolumeGrid.h>
#include <volsg/volumeio/ZarrCodec.h>

namespace volsg {

/// A .zarray of a 3- to 5-dimensional array whose last three axes are z, y, x. `shape` and
/// `chunks` are in the file's order (slowest first).
struct ZarrArrayLayout {
    std::vector<std::uint64_t> shape;
    std::vector<std::uint64_t> chunks;
    VoxelType type = VoxelType::UByte;
    bool bigEndian = false;
    double fillValue = 0.0;        ///< null is read as 0
    char dimensionSeparator = '.'; ///< '.' (Zarr's default) or '/'
    ZarrCodec codec;

    /// The chunk's key inside the array's folder: "2.0.1" or "2/0/1".
    std::string chunkKey(const std::vector<std::uint64_t>& index) const;
    std::uint64_t chunkElements() const; ///< product of `chunks`
    /// The .zarray text: zarr_format 2, order C, no filters, little-endian dtype.
    std::string toJson() const;
};

/// Reads `arrayFolder`/.zarray. Throws volsg::Error naming the .zarray for malformed JSON,
/// zarr_format other than 2, order F, filters, a dtype without a VoxelType (|u1 <u2 >u2 <i2 >i2
/// <f4 >f4), a rank outside 3..5, a shape or chunk entry < 1 or > limits::maxVolumeDimension,
/// chunks whose size overflows or exceeds `byteLimit`, a fill_value the dtype cannot hold, a
/// dimension_separator other than "." or "/", and a compressor it does not know.
ZarrArrayLayout readZarrArrayLayout(const std::string& arrayFolder, std::uint64_t byteLimit);

} // namespace volsg
