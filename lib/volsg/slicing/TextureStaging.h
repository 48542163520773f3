#pragma once
// Texture uploads staged ahead (issue #8): the brick textures of the grid a VolumeSeries shows
// next, written into a pixel unpack buffer while the current step is on screen, so that the
// step change uploads from a buffer that is ready (glTexImage3D with GL_PIXEL_UNPACK_BUFFER
// bound reads GL memory; a driver with DMA copies it without waiting for the CPU).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <volsg/core/Object.h>
#include <volsg/gl/Buffer.h>
#include <volsg/slicing/BrickLayout.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// One grid's brick texels (and labels) in one pixel unpack buffer, in the layout's brick
/// order, each brick at a 16-byte aligned offset. GL thread, with the context current.
class StagedGrid {
public:
    /// Makes the buffer, maps it (write, invalidate) and writes every brick of `layout`
    /// (BrickTexels.h; `finiteMin`/`finiteMax` replace non-finite Float values). `tags` null:
    /// no label textures staged. Throws Error when the buffer cannot be mapped or unmapped.
    StagedGrid(ref_ptr<const VolumeGrid> data, ref_ptr<const VolumeGrid> tags,
               const BrickLayout& layout, double finiteMin, double finiteMax);

    const VolumeGrid* data() const { return data_.get(); }
    const VolumeGrid* tags() const { return tags_.get(); }
    std::size_t bytes() const { return buffer_.size(); }

    /// Whether brick `index` of the shown layout is staged with this geometry and with labels
    /// exactly when `withTags`.
    bool covers(std::size_t index, const Brick& brick, bool withTags) const;
    /// Offsets into the bound buffer, as the pointer argument of glTexImage3D takes them.
    const void* dataSource(std::size_t index) const;
    const void* tagSource(std::size_t index) const;

    /// Binds the buffer to GL_PIXEL_UNPACK_BUFFER for its scope (and unbinds it after, so no
    /// other upload reads from it).
    class Binding {
    public:
        explicit Binding(const StagedGrid& staged);
        ~Binding();
        Binding(const Binding&) = delete;
        Binding& operator=(const Binding&) = delete;
    };

private:
    ref_ptr<const VolumeGrid> data_, tags_;
    struct Part {
        glm::ivec3 firstVoxel, voxelCount;
        std::size_t dataOffset, tagOffset;
    };
    std::vector<Part> parts_;
    Buffer buffer_;
};

/// Per Volume node and context (in the RenderAction's cache): the grid staged for a coming
/// frame, and how the last frame laid out its bricks so the staged grid is laid out the same.
struct TextureStaging {
    std::unique_ptr<StagedGrid> next;
    bool hasFrame = false;           ///< the fields below describe a drawn frame
    std::uint64_t textureBudget = 0; ///< the last frame's SlicingSettings::textureBudget
    int guard = 0;                   ///< the last frame's guard voxels
    bool tagged = false;             ///< the last frame drew label textures
    std::uint64_t stagedGrids = 0;   ///< grids staged so far
};

} // namespace volsg
