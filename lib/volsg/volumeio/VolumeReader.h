#pragma once
// Readers for volume files: raw (plain or gzip), NRRD (.nrrd/.nhdr), MetaImage (.mhd/.mha),
// NIfTI-1/2 (.nii, .nii.gz, .hdr/.img), DICOM series (a folder, or one file of the series) and
// OME-Zarr multiscale images (a .zarr folder).

#include <cstdint>
#include <string>

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// What a raw file cannot say about itself (docs/SCENE-FORMAT.md section 3, VolumeData's raw
/// fields).
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
/// `spacings` or, failing that, from the lengths of the `space directions` vectors. The
/// directions with `space origin` and `space` (RAS, LAS, LPS; others taken as they are) give
/// the grid's geometry(), in LPS. `kinds` and other informational fields are ignored.
ref_ptr<VolumeGrid> readNrrd(const std::string& path,
                             std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// A MetaImage volume: `.mhd` with `ElementDataFile = file` (relative to the header's folder) or
/// `.mha` with `ElementDataFile = LOCAL` (data right after that line). NDims 3, ElementType
/// MET_UCHAR/MET_USHORT/MET_SHORT/MET_FLOAT, ElementSpacing (or ElementSize),
/// BinaryDataByteOrderMSB / ElementByteOrderMSB, CompressedData (a zlib stream;
/// CompressedDataSize optional), HeaderSize (-1: the data is at the end of the file).
/// Offset and TransformMatrix (also spelt Position/Origin, Rotation/Orientation) give the
/// grid's geometry() (MetaIO's space is LPS).
ref_ptr<VolumeGrid> readMetaImage(const std::string& path,
                                  std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// A NIfTI-1 (348-byte header) or NIfTI-2 (540-byte header) volume, either byte order: `.nii`,
/// `.nii.gz` (the whole file gzip), or a `.hdr` with magic ni1/ni2 and its voxels in the
/// `.img` (or `.img.gz`) beside it. dim[0] 3 (or more with dims 4.. equal to 1); datatypes
/// uint8, int16, uint16 and float32. Spacing and geometry() come from the sform when
/// sform_code > 0, else the qform when qform_code > 0 (quaternion, qfac in pixdim[0]), else
/// pixdim alone (no geometry); NIfTI's RAS becomes LPS, metres and microns become mm. A
/// scl_slope other than 0 or 1 (or a scl_inter) turns the voxels into FLOAT
/// stored * slope + inter.
ref_ptr<VolumeGrid> readNifti(const std::string& path,
                              std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// A DICOM series through GDCM: `path` is a folder (its largest series) or one file (its
/// series, from the files in its folder with the same Series Instance UID). Single-frame,
/// single-sample slices of 8 or 16 bits, any transfer syntax GDCM decodes. The slices are
/// ordered by Image Position (Patient) along the normal of Image Orientation (Patient) and
/// must share size, pixel format, orientation and Pixel Spacing and be evenly spaced (1%).
/// Rescale Slope/Intercept are applied: an integer intercept with slope 1 gives SHORT (CT in
/// HU), other rescales FLOAT, none the stored type. geometry() is the first slice's position
/// with the row, column and normal directions (LPS, as DICOM).
ref_ptr<VolumeGrid> readDicomSeries(const std::string& path,
                                    std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// One level of an OME-Zarr image (OME-NGFF 0.4 `multiscales` over Zarr v2 arrays;
/// lib/volsg/volumeio/OMEZARR.md): `path` is the image's folder (with .zattrs) and `level` 0 the
/// finest, or `path` is one level's array folder (with .zarray; `level` must then be 0), whose
/// spacing comes from the image around it when that lists it. Arrays of 3 axes (z, y, x) or 4
/// or 5 (t, c, z, y, x): the volume is t = 0, c = 0. dtypes |u1 <u2 >u2 <i2 >i2 <f4 >f4;
/// order C; compressor null, zlib, gzip, zstd or blosc; dimension_separator "." or "/". A
/// missing chunk file holds fill_value (Zarr's rule). Spacing is the level's scale (times the
/// image's), in the axes' unit. geometry() is known only for pyramids volsg wrote from a placed
/// volume (multiscales[0].metadata.volsg, moved to the level by its translation). Errors name the
/// .zattrs, .zarray or chunk file: malformed JSON, unsupported metadata, a chunk that does
/// not decompress to exactly the chunk's bytes, a chunk file outside the declared shape.
ref_ptr<VolumeGrid> readOmeZarr(const std::string& path, int level = 0,
                                std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// The voxels from `first` (x, y, z) of `count` voxels of one level of an OME-Zarr image, as
/// readOmeZarr reads them, opening only the chunks that meet that box: how a process of a
/// sort-last render (lib/volsg/sortlast/README.md), or anything else that shows a part, loads
/// only its own data. Spacing as readOmeZarr; no geometry (the box is not placed). Throws
/// Error naming the .zarray for a box not inside the level, and as readOmeZarr.
ref_ptr<VolumeGrid> readOmeZarrRegion(const std::string& path, int level, glm::ivec3 first,
                                      glm::ivec3 count,
                                      std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// The voxels (x, y, z) of one level of an OME-Zarr image, from its metadata alone.
glm::ivec3 readOmeZarrDimensions(const std::string& path, int level = 0);

/// The whole level as readOmeZarr reads it (size, spacing, geometry), but with only the chunks
/// that meet the box from `first` of `count` voxels read: the other voxels hold the array's
/// fill value. A sort-last process's grid: its own part and ghost voxels, nothing else read.
ref_ptr<VolumeGrid> readOmeZarrWithin(const std::string& path, int level, glm::ivec3 first,
                                      glm::ivec3 count,
                                      std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

/// True when `path` is a folder named *.zarr or holding .zattrs, .zgroup or .zarray.
bool isZarrFolder(const std::string& path);

/// True when `path` is a DICOM Part 10 file ("DICM" after the 128-byte preamble).
bool isDicomFile(const std::string& path);

/// Picks the reader: a Zarr folder (isZarrFolder) is OME-Zarr at level 0; another folder or a
/// DICOM file (by its magic, or .dcm) is a DICOM series;
/// .nrrd .nhdr .mhd .mha .nii .nii.gz (.hdr with a NIfTI magic) by extension,
/// case-insensitive; any other file is raw and needs `rawLayout`.
ref_ptr<VolumeGrid> readVolume(const std::string& path, const RawVolumeLayout* rawLayout = nullptr,
                               std::uint64_t byteLimit = VolumeGrid::defaultByteLimit);

} // namespace volsg
