// The Volume slicer's bricks on the GPU: their ranges, uploads, and eviction under the budget.
#include <volsg/slicing/VolumeTextures.h>

#include <optional>
#include <utility>

#include <volsg/slicing/BrickTexels.h>
#include <volsg/slicing/GridMeasures.h>
#include <volsg/slicing/SliceShared.h>

namespace volsg::slicing {

namespace {

/// A spare texture of this size and format (moved out of v.spareTextures), else a new one.
Texture spareTexture(VolumeTextures& v, GLenum internalFormat, const glm::ivec3& size) {
    for (auto it = v.spareTextures.begin(); it != v.spareTextures.end(); ++it)
        if (it->internalFormat() == internalFormat && it->width() == size.x &&
            it->height() == size.y && it->depth() == size.z) {
            Texture t = std::move(*it);
            v.spareTextures.erase(it);
            return t;
        }
    return Texture(GL_TEXTURE_3D);
}

/// Uploads brick i's textures: from the staged buffer when the grid was staged with this
/// brick (the same bytes, BrickTexels.h), else from the grid's memory or converted texels.
void uploadBrick(VolumeTextures& v, std::size_t i, const Brick& b, BrickState& s, bool withTags) {
    const VolumeGrid& grid = *v.data;
    const bool staged = v.staged && v.staged->covers(i, b, withTags);
    std::optional<StagedGrid::Binding> binding;
    if (staged) binding.emplace(*v.staged); // the pointers below are offsets into the buffer
    auto converted = [&](std::size_t texelBytes, auto write) -> const void* {
        v.scratch.resize((b.texels() * texelBytes + 3) / 4);
        write(static_cast<void*>(v.scratch.data()));
        return v.scratch.data();
    };
    // From the buffer the source is an offset, and the first brick's is 0: a null pointer.
    const void* pixels = staged ? v.staged->dataSource(i) : directBrickTexels(grid, b);
    if (!staged && !pixels)
        pixels = converted(uploadTexelBytes(grid.type()), [&](void* out) {
            writeBrickTexels(grid, b, v.finiteMin, v.finiteMax, out);
        });
    if (!s.data) s.data = spareTexture(v, v.format.internalFormat, b.voxelCount);
    if (s.data.internalFormat() == v.format.internalFormat && s.data.width() == b.voxelCount.x &&
        s.data.height() == b.voxelCount.y && s.data.depth() == b.voxelCount.z) {
        ++v.totals.refilledTextures;
        s.data.subImage(0, 0, 0, b.voxelCount.x, b.voxelCount.y, b.voxelCount.z, GL_RED,
                        v.format.type, pixels);
    } else {
        s.data.image3D(v.format.internalFormat, b.voxelCount.x, b.voxelCount.y, b.voxelCount.z,
                       GL_RED, v.format.type, pixels);
    }
    const GLenum filter = v.filterNearest ? GL_NEAREST : GL_LINEAR;
    s.data.setFilter(filter, filter);
    std::size_t bytes = b.texels() * v.format.texelBytes;

    if (withTags) {
        const VolumeGrid& tags = *v.tags;
        const bool wide = tags.type() == VoxelType::UShort;
        const void* labels = staged ? v.staged->tagSource(i) : directBrickLabels(tags, b);
        if (!staged && !labels)
            labels = converted(wide ? 2 : 1, [&](void* out) { writeBrickLabels(tags, b, out); });
        if (!s.tags) {
            s.tags = Texture(GL_TEXTURE_3D);
            s.tags.setFilter(GL_NEAREST, GL_NEAREST); // integer textures are never filtered
        }
        s.tags.image3D(wide ? GL_R16UI : GL_R8UI, b.voxelCount.x, b.voxelCount.y, b.voxelCount.z,
                       GL_RED_INTEGER, wide ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE, labels);
        bytes += b.texels() * (wide ? 2 : 1);
    } else {
        s.tags = Texture();
    }
    s.resident = true;
    v.residentBytes += bytes;
    ++v.totals.brickUploads;
    v.totals.uploadedBytes += bytes;
    if (staged) ++v.totals.stagedUploads;
}

std::size_t residentBytesOf(const VolumeTextures& v, const Brick& b, const BrickState& s) {
    std::size_t bytes = b.texels() * v.format.texelBytes;
    if (s.tags) bytes += b.texels() * (v.tags->type() == VoxelType::UShort ? 2 : 1);
    return bytes;
}

} // namespace

const GridMeasures* stagedMeasures(const VolumeTextures& v) {
    return v.staged && v.staged->data() == v.data.get() && v.staged->tags() == v.tags.get()
               ? &v.staged->measures()
               : nullptr;
}

void measureBricks(VolumeTextures& v) {
    std::vector<BrickRange> measured;
    if (const GridMeasures* m = stagedMeasures(v); m && m->sameBricks(v.layout))
        measured = m->ranges;
    else
        measured = measureBrickRanges(*v.data, v.tags.get(), v.layout, v.finiteMin, v.finiteMax);
    for (std::size_t i = 0; i < v.bricks.size(); ++i) {
        BrickState& s = v.bricks[i];
        s.dataMin = measured[i].dataMin;
        s.dataMax = measured[i].dataMax;
        s.tagMin = measured[i].tagMin;
        s.tagMax = measured[i].tagMax;
    }
}

void release(VolumeTextures& v, std::size_t i) {
    BrickState& s = v.bricks[i];
    if (!s.resident) return;
    v.residentBytes -= residentBytesOf(v, v.layout.bricks()[i], s);
    s.data = Texture();
    s.tags = Texture();
    s.resident = false;
}

void makeResident(VolumeTextures& v, std::size_t i, std::uint64_t budget, bool withTags) {
    BrickState& s = v.bricks[i];
    if (s.resident && bool(s.tags) != withTags) release(v, i);
    if (!s.resident) {
        activateUploadUnit();
        const Brick& b = v.layout.bricks()[i];
        const std::size_t need =
            b.texels() *
            (v.format.texelBytes + (withTags ? (v.tags->type() == VoxelType::UShort ? 2 : 1) : 0));
        while (budget > 0 && v.residentBytes + need > budget) {
            std::size_t victim = v.bricks.size();
            for (std::size_t j = 0; j < v.bricks.size(); ++j)
                if (j != i && v.bricks[j].resident &&
                    (victim == v.bricks.size() || v.bricks[j].lastUse < v.bricks[victim].lastUse))
                    victim = j;
            if (victim == v.bricks.size()) break;
            release(v, victim);
        }
        uploadBrick(v, i, b, s, withTags);
    }
    s.lastUse = ++v.useCounter;
}

} // namespace volsg::slicing
