#pragma once
// The declared maxima of every reader: one place to see (and change) how much untrusted input
// may make the library allocate, nest or count. Past a limit a reader throws volsg::Error
// naming the file, the place and the limit; it never allocates first and fails with
// std::bad_alloc, and never recurses without bound.

#include <cstddef>
#include <cstdint>

#include <unistd.h>

namespace volsg::limits {

// --- Scene files (io/SceneReader, io/Tokenizer, fields) ---

/// Largest scene file readScene() loads.
inline constexpr std::uintmax_t maxSceneFileSize = std::uintmax_t(1) << 30;
/// Deepest nesting of nodes (children and SFNode/MFNode values each count one level).
inline constexpr int maxSceneNestingDepth = 1000;
/// Most nodes one scene file may create (USE does not count: it shares a node).
inline constexpr std::size_t maxSceneNodes = std::size_t(1) << 22;
/// Most node instances one traversal of a scene may reach (every USE of a shared node counts
/// once per path to it): a graph of 40 groups each USEing the one before twice has 2^40.
/// 2^22: a million shapes under their own Separator, Transform and Material; 2^24 let a
/// fuzz-found scene queue 16 million annotation draws (1.6 GB).
inline constexpr std::uint64_t maxTraversalInstances = std::uint64_t(1) << 22;
/// Most volume nodes (Volume, ShearWarpVolume) one frame may draw, counting every USE.
inline constexpr std::uint64_t maxVolumeInstances = 256;
/// Most screen-text (Text2) characters one frame may lay out, counting every USE: each
/// instance is laid out again (16 screens full of 8-pixel characters at 3840x2160).
inline constexpr std::uint64_t maxFrameTextGlyphs = std::uint64_t(1) << 21;
/// Most vertex indices the shapes of one frame may draw, counting every USE (each instance is
/// drawn again) and each pass: 2^28, some 90 million triangles, minutes of a software
/// rasteriser's time (a 317 x 317 grid of Coin-tessellated spheres draws 126 million).
inline constexpr std::uint64_t maxFrameShapeIndices = std::uint64_t(1) << 28;
/// Most children of one node.
inline constexpr std::size_t maxSceneChildren = std::size_t(1) << 20;
/// Most values in one multiple-value field (MFFloat, MFVec3f, MFNode, ...).
inline constexpr std::size_t maxFieldValues = std::size_t(1) << 24;
/// Most fields an unknown node type may declare in its `fields [ ... ]` description.
inline constexpr std::size_t maxDeclaredFields = 1024;
/// Longest word (names and numbers).
inline constexpr std::size_t maxWordLength = std::size_t(1) << 20;
/// Longest quoted string, after unescaping.
inline constexpr std::size_t maxStringLength = std::size_t(64) << 20;

// --- Volume files (volumeio, volume::VolumeGrid) ---

/// The range of a voxel's size along an axis: within it single-precision GL keeps the digits a
/// volume needs (1e18-unit voxels overflow its squared lengths and show nothing).
inline constexpr double minVolumeSpacing = 1e-9;
inline constexpr double maxVolumeSpacing = 1e12;
/// Largest number of voxels along one axis of any volume (file, generator or GL upload).
inline constexpr int maxVolumeDimension = 1 << 16;
/// Largest voxel storage a grid may take unless the caller allows more (a bad header must give
/// an Error, not an out-of-memory kill). Also capped by physicalMemoryBytes().
inline constexpr std::uint64_t maxVolumeBytes = std::uint64_t(4) << 30;
/// Longest header line of a NRRD or MetaImage file.
inline constexpr std::size_t maxHeaderLineLength = std::size_t(64) << 10;
/// Longest NRRD or MetaImage header.
inline constexpr std::size_t maxHeaderLength = std::size_t(1) << 20;

// --- Volume rendering (slicing/, shearwarp/) ---
/// Most samples the Volume slicer takes along one ray: planes x samplesPerPlane (2 per voxel
/// across a 32768-voxel diagonal).
inline constexpr long maxSamplesPerRay = 65536;
/// Most pixels of a shear-warp intermediate image (one per voxel of a slice, sheared): 2^25
/// pixels is 512 MB of colour alone.
inline constexpr std::size_t maxShearWarpIntermediatePixels = std::size_t(1) << 25;
// --- glTF (gltf/GltfLoader) ---

/// Largest .gltf/.glb file, and largest external buffer or image file it names.
inline constexpr std::uintmax_t maxGltfFileSize = std::uintmax_t(1) << 30;
/// Deepest glTF node tree.
inline constexpr int maxGltfNodeDepth = 256;
/// Most elements an accessor without a bufferView (all zeros, sparse values only) may have.
inline constexpr std::size_t maxGltfUnbackedCount = std::size_t(1) << 24;
/// Most accessor values (elements x components) one glTF file may decode, all accessors
/// together: 2^27 values are 1 GB as doubles.
inline constexpr std::size_t maxGltfAccessorValues = std::size_t(1) << 27;
/// Most image pixels one glTF file may decode, all images together (1 GB as RGBA).
inline constexpr std::uint64_t maxGltfImagePixels = std::uint64_t(1) << 28;

// --- Images (image/Image: PNG, PFM; glTF textures) ---

/// Longest side of an image.
inline constexpr std::uint32_t maxImageSide = std::uint32_t(1) << 16;
/// Largest PNG or PFM file read.
inline constexpr std::uintmax_t maxImageFileSize = std::uintmax_t(1) << 30;
/// Most pixels of an image.
inline constexpr std::uint64_t maxImagePixels = std::uint64_t(1) << 28;

/// Bytes of physical memory of this machine (0 when unknown). A volume larger than this is
/// refused before allocation whatever limit the caller passed: it could only end in swapping
/// or the out-of-memory killer.
inline std::uint64_t physicalMemoryBytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long pageSize = ::sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return 0;
    return std::uint64_t(pages) * std::uint64_t(pageSize);
}

} // namespace volsg::limits
