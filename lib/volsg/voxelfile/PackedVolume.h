#pragma once
// The objects of one ShearWarpVolume as a .vsgv file stores them: what the node draws instead
// of extracting from a VolumeData when its voxelFile field is set.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <volsg/math/Box3.h>
#include <volsg/voxelfile/VoxelFile.h>

namespace volsg {

class PackedVolume {
public:
    /// The volume named by a voxelFile value: "path" (volume 0) or "path#k" (volume k), a
    /// relative path resolved against `directory`. Files are read once and kept while their
    /// size and modification time stay the same (a rewritten file is read again). Throws Error
    /// for a missing or malformed file or a volume the file does not hold.
    static PackedVolume load(const std::string& reference, const std::string& directory);

    /// The stored voxels of the `index`-th VolumeObject. `current` is that object's extraction
    /// spec from its fields now: when it asks for other voxels than the stored ones (source,
    /// tag, threshold, voxels, gradientThreshold, or its transfer function's explicit
    /// dataRange changed) this throws Error naming the object and the field, since a new
    /// extraction needs the original volume. Transfer-function colours and opacities do not
    /// count: they apply to the stored voxels (a VISIBLE object keeps the voxels that were
    /// visible when the file was written).
    ref_ptr<VoxelObject> voxels(std::size_t index, const ExtractionSpec& current) const;
    /// The stored record of the `index`-th object (throws Error past the end).
    const PackedObject& object(std::size_t index) const;
    /// Throws Error when the scene has another number of VolumeObjects than the file.
    void checkObjectCount(std::size_t count) const;
    std::size_t objectCount() const { return objects_.size(); }

    /// The volume's box in local coordinates (docs/SCENE-FORMAT.md section 4), from the stored
    /// dimensions and spacing.
    Box3 localBounds() const;

    const std::string& fileName() const { return fileName_; }
    std::uint32_t volumeIndex() const { return volume_; }

private:
    std::shared_ptr<const VoxelFileContent> file_;
    std::string fileName_;
    std::uint32_t volume_ = 0;
    std::vector<const PackedObject*> objects_; ///< by object index
    std::string describe(std::size_t index) const;
};

/// The file at `path` through the cache PackedVolume::load uses (read once per size and
/// modification time).
std::shared_ptr<const VoxelFileContent> loadVoxelFileCached(const std::string& path);

} // namespace volsg
