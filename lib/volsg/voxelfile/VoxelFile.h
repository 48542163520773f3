#pragma once
// The compact voxel-list file (.vsgv): a visualization of ShearWarpVolume objects that is
// viewed and edited without the volume it was extracted from (RTVR section 5). Layout, coding
// and limits: lib/volsg/voxelfile/README.md.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/shearwarp/VoxelObject.h>

namespace volsg {

/// What selected an object's voxels: the fields of its VolumeObject that a new extraction
/// would need the volume for, and the data range its 12-bit values were normalised by.
struct ExtractionRecord {
    ObjectSource source;
    VoxelSelection selection = VoxelSelection::Visible;
    double gradientThreshold = 0.05;
    glm::dvec2 dataRange{0.0, 1.0}; ///< the transfer function's resolved data range
};

/// One extracted object: the `objectIndex`-th VolumeObject child of the `volumeIndex`-th
/// ShearWarpVolume of the scene (depth-first order, each node counted once).
struct PackedObject {
    std::uint32_t volumeIndex = 0, objectIndex = 0;
    ExtractionRecord extraction;
    ref_ptr<VoxelObject> voxels;
};

/// The whole file: the scene (Inventor text, every visualization parameter) and the objects.
struct VoxelFileContent {
    std::string sceneText;
    std::vector<PackedObject> objects;
};

/// The file's bytes. Throws Error when an object's arrays cannot be stored (too large).
std::string encodeVoxelFile(const VoxelFileContent& content);

/// Reads a .vsgv from memory: the one entry point for untrusted bytes (the fuzz target's).
/// Every malformed input (truncated, corrupt, wrong magic or version, declared sizes beyond
/// the file or the limits) throws volsg::Error naming `nameForErrors`, the byte offset and the
/// section; sizes are checked before anything is allocated.
VoxelFileContent readVoxelFile(std::span<const std::byte> bytes, const std::string& nameForErrors);

/// Reads the file at `path` (at most maxVoxelFileSize bytes).
VoxelFileContent readVoxelFileFromPath(const std::string& path);

/// Writes atomically (temporary file and rename): a failure leaves the old file as it was.
void writeVoxelFile(const std::string& path, const VoxelFileContent& content);

/// True when `bytes` start with the .vsgv magic (to tell it from a scene file).
bool hasVoxelFileMagic(std::span<const std::byte> bytes);

/// Format version written and the only one read.
inline constexpr std::uint32_t voxelFileVersion = 1;
/// Largest .vsgv file read.
inline constexpr std::uint64_t maxVoxelFileSize = std::uint64_t(2) << 30;
/// Largest uncompressed section (scene text or one object's record).
inline constexpr std::uint64_t maxVoxelFileSectionBytes = std::uint64_t(1) << 30;
/// Most sections in one file.
inline constexpr std::uint32_t maxVoxelFileSections = 1u << 16;

} // namespace volsg
