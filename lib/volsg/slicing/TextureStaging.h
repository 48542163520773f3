#pragma once
// Texture uploads staged ahead (issue #8): the brick textures of the grid a VolumeSeries shows
// next, written into a pixel unpack buffer while the current step is on screen, so that the
// step change uploads from a buffer that is ready (glTexImage3D with GL_PIXEL_UNPACK_BUFFER
// bound reads GL memory; a driver with DMA copies it without waiting for the CPU).

#include <cstddef>
#include <cstdint>
#include <future>
#include <memory>
#include <vector>

#include <volsg/core/Object.h>
#include <volsg/gl/Buffer.h>
#include <volsg/slicing/BrickLayout.h>
#include <volsg/slicing/GridMeasures.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// One grid's brick texels (and labels) in one pixel unpack buffer, in the layout's brick
/// order, each brick at a 16-byte aligned offset. The GL calls run on the GL thread (context
/// current); the texels are written into the mapped buffer by a helper thread meanwhile.
class StagedGrid {
public:
    /// Makes the buffer and maps it (write, invalidate); a helper thread then writes every
    /// brick of `layout` into it (BrickTexels.h; Float data with non-finite values replaced by
    /// the grid's finite minMax, as the direct upload does), while the GL thread goes on
    /// drawing. `tags` null: no label textures staged. Throws Error when it cannot map.
    StagedGrid(ref_ptr<const VolumeGrid> data, ref_ptr<const VolumeGrid> tags,
               const BrickLayout& layout);
    /// Waits for the helper thread if it is still writing (the buffer is deleted after).
    ~StagedGrid();
    StagedGrid(const StagedGrid&) = delete;
    StagedGrid& operator=(const StagedGrid&) = delete;

    /// Waits for the texels and unmaps the buffer (GL thread): before any upload from it.
    /// Throws Error when the buffer was lost while mapped.
    void finish();

    /// What the helper measured besides (finite range, brick ranges, empty cells); valid
    /// after finish().
    const GridMeasures& measures() const { return measures_; }

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
    bool mapped_ = false;
    GridMeasures measures_;    // written by the helper thread, read after finish()
    std::future<void> filled_; // the helper thread's writing
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
    std::uint64_t lastKey = 0;       ///< the grid the last frame drew (its textures' cache key)
};

} // namespace volsg
