#include <volsg/slicing/TextureStaging.h>

#include <cstdint>
#include <tuple>

#include <volsg/core/Error.h>
#include <volsg/slicing/BrickTexels.h>

namespace volsg {

namespace {

std::size_t aligned(std::size_t bytes) {
    return (bytes + 15) & ~std::size_t(15);
}

} // namespace

StagedGrid::StagedGrid(ref_ptr<const VolumeGrid> data, ref_ptr<const VolumeGrid> tags,
                       const BrickLayout& layout)
    : data_(std::move(data)), tags_(std::move(tags)), buffer_(GL_PIXEL_UNPACK_BUFFER) {
    const std::size_t texelBytes = uploadTexelBytes(data_->type());
    const std::size_t labelBytes = tags_ ? uploadTexelBytes(tags_->type()) : 0;
    std::size_t total = 0;
    for (const Brick& b : layout.bricks()) {
        Part part{b.firstVoxel, b.voxelCount, total, 0};
        total += aligned(b.texels() * texelBytes);
        part.tagOffset = total;
        total += aligned(b.texels() * labelBytes);
        parts_.push_back(part);
    }
    buffer_.setData(nullptr, total, GL_STREAM_DRAW); // leaves it bound to its target
    void* mapped = glMapBufferRange(GL_PIXEL_UNPACK_BUFFER, 0, GLsizeiptr(total),
                                    GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    if (!mapped)
        throw Error("cannot map a pixel unpack buffer of " + std::to_string(total) +
                    " bytes to stage a volume's textures");
    mapped_ = true;
    // A mapped pointer is plain memory: another thread may fill it while GL draws on (the
    // buffer itself is used only after finish() unmapped it).
    filled_ =
        std::async(std::launch::async, [this, layout, bytes = static_cast<std::uint8_t*>(mapped)] {
            // The grid's CPU passes too (the step change would do them on the GL thread).
            measures_ = GridMeasures::of(*data_, tags_.get(), layout);
            const double lo = measures_.finiteMin, hi = measures_.finiteMax;
            const std::vector<Brick>& bricks = layout.bricks();
            for (std::size_t i = 0; i < parts_.size(); ++i) {
                writeBrickTexels(*data_, bricks[i], lo, hi, bytes + parts_[i].dataOffset);
                if (tags_) writeBrickLabels(*tags_, bricks[i], bytes + parts_[i].tagOffset);
            }
        });
}

StagedGrid::~StagedGrid() {
    if (filled_.valid()) filled_.wait(); // then the Buffer deletes (and so unmaps) the buffer
}

void StagedGrid::finish() {
    if (!mapped_) return;
    filled_.get(); // rethrows what the helper threw
    buffer_.bind();
    const GLboolean intact = glUnmapBuffer(GL_PIXEL_UNPACK_BUFFER);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    mapped_ = false;
    if (intact != GL_TRUE)
        throw Error("a staged volume texture buffer was lost while mapped (GL context event)");
}

bool StagedGrid::covers(std::size_t index, const Brick& brick, bool withTags) const {
    return index < parts_.size() && parts_[index].firstVoxel == brick.firstVoxel &&
           parts_[index].voxelCount == brick.voxelCount && bool(tags_) == withTags;
}

const void* StagedGrid::dataSource(std::size_t index) const {
    return reinterpret_cast<const void*>(parts_.at(index).dataOffset);
}

const void* StagedGrid::tagSource(std::size_t index) const {
    return reinterpret_cast<const void*>(parts_.at(index).tagOffset);
}

StagedGrid::Binding::Binding(const StagedGrid& staged) {
    staged.buffer_.bind();
}

StagedGrid::Binding::~Binding() {
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
}

} // namespace volsg
