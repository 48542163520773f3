#pragma once
// Readers for volume files: raw (plain or gzip), NRRD (.nrrd/.nhdr) and MetaImage (.mhd/.mha).

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// What a raw file cannot say about itself (docs/SCENE-FORMAT.md section 3, VolumeData's raw fields).
struct RawVolumeLayout {
    glm::ivec3 dimensions{0};
    VoxelType type = VoxelType::UByte;
    bool bigEndian = false;
    std::uint64_t headerSkip = 0; ///< bytes before the voxels (decompressed bytes for gzip)
    glm::dvec3 spacing{1.0};
};

// Every reader below takes untrusted input. It throws volsg::Error naming the file (and the
// header line where there is one) for a missing file, an unsupported type or encoding, data
// whose size disagrees with the dimensions, a grid larger than `byteLimit` (checked before
// anything is allocated), malformed or absurd header values, and truncated or oversized
// compressed streams. Voxels are read straight into the grid's storage and byte-swapped in
// place; the only other memory used is a bounded header and a fixed-size inflate buffer.
// Label (tag) volumes use the same functions: a UByte or UShort grid is a label grid.

/// A headerless volume. A file that starts with the gzip magic (1f 8b) is decompressed
/// transparently (`.gz`, `.raw.gz`); the file (or the decompressed stream) must then hold
/// exactly `headerSkip` + dimensions x voxel-size bytes.
ref_ptr<VolumeGrid> readRawVolume(const std::string& path, const RawVolumeLayout& layout,
                                  std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// A NRRD volume: attached (`.nrrd`) or detached (`.nhdr` with `data file:` / `datafile:`
/// relative to the header's folder). Dimension 3 only; encodings raw and gzip (`gz`); types
/// uchar, ushort, short and float under any of their NRRD spellings; `endian` little or big;
/// `byte skip` (-1 for raw: data at the end of the file) and `line skip`. Spacing comes from
/// `spacings` or, failing that, from the lengths of the `space directions` vectors: the
/// orientation of non-axis-aligned directions is ignored (the grid is axis-aligned).
/// `kinds`, `space origin` and other informational fields are ignored.
ref_ptr<VolumeGrid> readNrrd(const std::string& path,
                             std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// A MetaImage volume: `.mhd` with `ElementDataFile = file` (relative to the header's folder) or
/// `.mha` with `ElementDataFile = LOCAL` (data right after that line). NDims 3, ElementType
/// MET_UCHAR/MET_USHORT/MET_SHORT/MET_FLOAT, ElementSpacing (or ElementSize),
/// BinaryDataByteOrderMSB / ElementByteOrderMSB, CompressedData (a zlib stream;
/// CompressedDataSize optional), HeaderSize (-1: the data is at the end of the file).
/// Offset and TransformMatrix are ignored (the grid is axis-aligned and centred).
ref_ptr<VolumeGrid> readMetaImage(const std::string& path,
                                  std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// Picks the reader by extension (.nrrd .nhdr .mhd .mha, case-insensitive); any other file is
/// raw and needs `rawLayout`.
ref_ptr<VolumeGrid> readVolume(const std::string& path, const RawVolumeLayout* rawLayout = nullptr,
                               std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

} // namespace volsg
