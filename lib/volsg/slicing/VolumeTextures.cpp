// The Volume slicer's per-volume state brought up to date for a frame: grid, bricks, tables.
#include <volsg/slicing/VolumeTextures.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <utility>

#include <volsg/core/Error.h>
#include <volsg/core/KeyMixing.h>
#include <volsg/paging/PagedVolume.h>
#include <volsg/render/RenderCache.h>
#include <volsg/slicing/GridMeasures.h>
#include <volsg/slicing/SliceShared.h>

namespace volsg::slicing {

std::uint64_t textureKeyOf(const RayCastVolume& volume) {
    const std::uint64_t key =
        std::uint64_t(reinterpret_cast<std::uintptr_t>(volume.data.get())) ^
        (std::uint64_t(reinterpret_cast<std::uintptr_t>(volume.tags.get())) << 1);
    // A paged volume whose guard widened has other bricks (PagedVolume::widenGuard): its
    // textures start afresh, as new data's do.
    return volume.paged && volume.paged->wideGuard() ? mixKey(key, 1) : key;
}

void adoptGrid(RenderCache& cache, const Object& owner, std::uint64_t key, VolumeTextures& v,
               TextureStaging& staging, const RayCastVolume& volume) {
    if (!v.data && staging.next && staging.next->data() == volume.data.get() &&
        (!staging.next->tags() || staging.next->tags() == volume.tags.get()))
        v.staged = std::move(staging.next); // staged while the previous step was shown
    if (v.staged) {
        try {
            v.staged->finish();
        } catch (const Error&) {
            v.staged.reset(); // the buffer was lost: upload directly
        }
    }
    if (!v.data && staging.lastKey != 0 && staging.lastKey != key) {
        // A new grid for this node (a series step): the last grid's textures are refilled
        // instead of allocated anew. Its entry is dropped after this frame anyway.
        VolumeTextures& last = cache.get<VolumeTextures>(owner, staging.lastKey);
        for (BrickState& s : last.bricks)
            if (s.data) v.spareTextures.push_back(std::move(s.data));
        last.bricks.clear();
        last.residentBytes = 0;
    }
    staging.lastKey = key;
}

void prepareGrid(VolumeTextures& v, const RayCastVolume& volume) {
    if (v.data) return;
    v.data = volume.data;
    v.tags = volume.tags;
    v.format = dataFormatOf(v.data->type());
    if (const GridMeasures* m = stagedMeasures(v)) { // measured ahead, with the texels
        v.finiteMin = m->finiteMin;
        v.finiteMax = m->finiteMax;
    } else {
        std::tie(v.finiteMin, v.finiteMax) = v.data->minMax(); // finite values only
    }
    const auto [natLo, natHi] = v.data->naturalRange();
    v.naturalRange = {natLo, natHi};
}

BrickLayout::Limits layoutLimits(const VolumeGrid& data, const VolumeGrid* tags,
                                 const SliceShared& shared, std::uint64_t budget, int guard) {
    BrickLayout::Limits limits;
    limits.budgetBytes = budget;
    limits.maxTextureSize = shared.max3DTextureSize;
    limits.bytesPerVoxel = dataFormatOf(data.type()).texelBytes +
                           (tags ? (tags->type() == VoxelType::UShort ? 2 : 1) : 0);
    limits.guard = guard;
    return limits;
}

void prepareLayout(VolumeTextures& v, const SliceShared& shared, std::uint64_t budget, int guard) {
    if (v.hasLayout && v.layoutBudget == budget && v.layoutGuard == guard) return;
    for (std::size_t i = 0; i < v.bricks.size(); ++i)
        release(v, i);
    v.layout = BrickLayout(v.data->dimensions(), v.data->spacing(),
                           layoutLimits(*v.data, v.tags.get(), shared, budget, guard));
    v.bricks.clear();
    v.bricks.resize(v.layout.bricks().size());
    measureBricks(v);
    v.hasLayout = true;
    v.layoutBudget = budget;
    v.layoutGuard = guard;
    v.hasTable = false; // emptiness is decided with the table
}

void prepareTable(VolumeTextures& v, const RayCastVolume& volume, std::uint64_t key) {
    if (v.hasTable && v.tableKey == key) return;
    v.table.build(volume.transferFunctions, v.naturalRange);
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (v.table.rows() > maxSize)
        throw Error(std::to_string(v.table.rows() - 1) +
                    " tagged transfer functions apply to one volume; at most " +
                    std::to_string(maxSize - 1) + " fit its transfer table");
    if (!v.tableTexture) v.tableTexture = Texture(GL_TEXTURE_2D); // linear, clamped
    v.tableTexture.image2D(GL_RGBA32F, TransferTable::kWidth, v.table.rows(), GL_RGBA, GL_FLOAT,
                           v.table.texels().data());
    if (!v.tableRowTexture) v.tableRowTexture = Texture(GL_TEXTURE_1D); // linear, clamped
    v.tableRowTexture.image1D(GL_RGBA32F, TransferTable::kWidth, GL_RGBA, GL_FLOAT,
                              v.table.texels().data());
    if (v.table.rows() > 1) {
        if (!v.tagRowTexture) {
            v.tagRowTexture = Texture(GL_TEXTURE_2D);
            v.tagRowTexture.setFilter(GL_NEAREST, GL_NEAREST);
        }
        v.tagRowTexture.image2D(GL_R16UI, TransferTable::kTagMapSide, TransferTable::kTagMapSide,
                                GL_RED_INTEGER, GL_UNSIGNED_SHORT, v.table.tagRows().data());
    }
    const bool tagged = v.tags && v.table.rows() > 1;
    for (BrickState& s : v.bricks)
        s.mayEmit = v.table.mayEmit(s.dataMin, s.dataMax, tagged, s.tagMin, s.tagMax);
    v.hasTable = true;
    v.tableKey = key;
    v.hasPreIntegration = false;
    ++v.totals.transferTableBuilds;
}

void measureCells(VolumeTextures& v) {
    if (v.cells.measured()) return;
    if (const GridMeasures* m = stagedMeasures(v); m && m->cells.measured())
        v.cells = m->cells;
    else
        v.cells.measure(*v.data, v.tags.get(), v.finiteMin, v.finiteMax);
}

void prepareCells(VolumeTextures& v, int kind) {
    measureCells(v);
    if (v.cellKind == kind && v.cellTableKey == v.tableKey) return;
    const bool tagged = v.tags && v.table.rows() > 1;
    // Pre-integrated: padded as its lookups read, so a cell that cannot emit gives every
    // lookup of its values an optical depth of exactly 0.
    const double padV = kind == 2 ? PreIntegrationTable::kLookupPadV : 0.0;
    v.cells.classify(v.table, tagged, kind == 1, padV);
    if (!v.cellTexture) {
        v.cellTexture = Texture(GL_TEXTURE_3D);
        v.cellTexture.setFilter(GL_NEAREST, GL_NEAREST);
    }
    const glm::ivec3 n = v.cells.cells();
    v.cellTexture.image3D(GL_R8UI, n.x, n.y, n.z, GL_RED_INTEGER, GL_UNSIGNED_BYTE,
                          v.cells.flags().data());
    v.cellKind = kind;
    v.cellTableKey = v.tableKey;
}

void preparePreIntegration(VolumeTextures& v) {
    if (v.hasPreIntegration) return;
    // One table per row (tagged functions pre-integrate each tag-cell piece with its own),
    // stacked along y in one texture.
    const int rows = std::min(v.table.rows(), PreIntegrationTable::kMaxRows);
    v.preIntegration.resize(std::size_t(rows));
    std::vector<float> texels;
    texels.reserve(std::size_t(rows) * PreIntegrationTable::kSize * PreIntegrationTable::kSize * 4);
    for (int r = 0; r < rows; ++r) {
        v.preIntegration[std::size_t(r)].build(v.table.function(r));
        const std::vector<float>& t = v.preIntegration[std::size_t(r)].texels();
        texels.insert(texels.end(), t.begin(), t.end());
    }
    if (!v.preIntegrationTexture) v.preIntegrationTexture = Texture(GL_TEXTURE_2D);
    v.preIntegrationTexture.image2D(GL_RGBA32F, PreIntegrationTable::kSize,
                                    PreIntegrationTable::kSize * rows, GL_RGBA, GL_FLOAT,
                                    texels.data());
    v.hasPreIntegration = true;
    ++v.totals.preIntegrationBuilds;
}

bool planeOpacityMatters(const std::vector<PiecewiseLinear::Point>& points) {
    return std::any_of(points.begin(), points.end(),
                       [](const PiecewiseLinear::Point& p) { return p.y != 1.0; });
}

void preparePlaneOpacity(VolumeTextures& v, const std::vector<PiecewiseLinear::Point>& points) {
    if (v.planeOpacityTexture && v.planeOpacity == points) return;
    const PiecewiseLinear m(points);
    std::vector<float> samples(kPlaneOpacitySize);
    for (int i = 0; i < kPlaneOpacitySize; ++i)
        samples[std::size_t(i)] = float(std::max(0.0, m(double(i) / (kPlaneOpacitySize - 1))));
    if (!v.planeOpacityTexture) {
        v.planeOpacityTexture = Texture(GL_TEXTURE_1D);
        v.planeOpacityTexture.setFilter(GL_NEAREST, GL_NEAREST);
    }
    v.planeOpacityTexture.image1D(GL_R32F, kPlaneOpacitySize, GL_RED, GL_FLOAT, samples.data());
    v.planeOpacity = points;
}

void prepareFilter(VolumeTextures& v, bool nearest) {
    if (v.filterNearest == nearest) return;
    v.filterNearest = nearest;
    const GLenum filter = v.filterNearest ? GL_NEAREST : GL_LINEAR;
    for (BrickState& s : v.bricks)
        if (s.resident) s.data.setFilter(filter, filter);
}

} // namespace volsg::slicing
