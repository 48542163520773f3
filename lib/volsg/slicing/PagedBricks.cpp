// The Volume slicer's bricks of a paged volume: chosen per frame, uploaded under the budget.
#include <volsg/slicing/PagedBricks.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <volsg/paging/LodSelection.h>
#include <volsg/paging/PagedVolume.h>
#include <volsg/slicing/BrickTexels.h>
#include <volsg/slicing/EmptyCells.h>
#include <volsg/slicing/SliceShared.h>
#include <volsg/sortlast/KdVolumeSplit.h>

namespace volsg::slicing {

void preparePagedGuard(const RayCastVolume& volume, const SlicingSettings& settings) {
    if (volume.paged && volume.mode == VolumeRenderMode::DVR &&
        (settings.lighting || settings.preIntegrated))
        volume.paged->widenGuard();
}

namespace {

/// Texture bytes a frame may upload for bricks new to the GPU: the first frame and the
/// interactive ones stay quick (a brick beyond it counts as not yet at hand), still frames
/// converge in a few.
constexpr std::uint64_t kFirstFrameUploads = std::uint64_t(8) << 20;
constexpr std::uint64_t kInteractiveUploads = std::uint64_t(16) << 20;
constexpr std::uint64_t kStillUploads = std::uint64_t(64) << 20;

std::uint64_t textureBytesOf(const PagedLayout& layout, const BrickKey& key,
                             std::size_t texelBytes) {
    glm::ivec3 first, count;
    layout.texels(key, first, count);
    return std::uint64_t(count.x) * count.y * count.z * texelBytes;
}

/// The slicer's Brick for `key`: its region, its level's texels and voxel size.
Brick brickOf(const PagedLayout& layout, const BrickKey& key) {
    Brick b;
    b.index = key.index;
    layout.texels(key, b.firstVoxel, b.voxelCount);
    layout.box(key, b.boxMin, b.boxMax);
    b.levelSpacing = layout.spacingOf(key.level);
    b.levelDimensions = layout.level(key.level).dimensions;
    return b;
}

/// Frees the least recently used slot not drawn this frame; false when every slot is drawn.
bool evictOne(PagedSlots& slots, VolumeTextures& v, const std::set<std::size_t>& drawn) {
    std::size_t victim = v.bricks.size();
    for (std::size_t i = 0; i < v.bricks.size(); ++i)
        if (v.bricks[i].resident && !drawn.count(i) &&
            (victim == v.bricks.size() || v.bricks[i].lastUse < v.bricks[victim].lastUse))
            victim = i;
    if (victim == v.bricks.size()) return false;
    // Not release(): v.layout is last frame's, and the slot may have been refilled with a
    // brick of another size since (an edge brick): its bytes are those of the brick it holds.
    BrickState& s = v.bricks[victim];
    v.residentBytes -= slots.bricks[victim].texels() * v.format.texelBytes;
    s.data = Texture();
    s.tags = Texture();
    s.resident = false;
    slots.slotOf.erase(slots.keyOf[victim]);
    slots.freeSlots.push_back(victim);
    ++slots.evictions;
    return true;
}

/// Uploads the host brick into slot i's texture, as uploadBrick does a grid's brick.
void upload(VolumeTextures& v, std::size_t i, const HostBrick& host, std::uint64_t bytes) {
    BrickState& s = v.bricks[i];
    const VolumeGrid& grid = *host.voxels;
    Brick whole;
    whole.voxelCount = grid.dimensions();
    const void* pixels = directBrickTexels(grid, whole);
    if (!pixels) {
        v.scratch.resize((whole.texels() * uploadTexelBytes(grid.type()) + 3) / 4);
        writeBrickTexels(grid, whole, v.finiteMin, v.finiteMax, v.scratch.data());
        pixels = v.scratch.data();
    }
    activateUploadUnit();
    s.data = Texture(GL_TEXTURE_3D);
    s.data.image3D(v.format.internalFormat, whole.voxelCount.x, whole.voxelCount.y,
                   whole.voxelCount.z, GL_RED, v.format.type, pixels);
    const GLenum filter = v.filterNearest ? GL_NEAREST : GL_LINEAR;
    s.data.setFilter(filter, filter);
    s.tags = Texture();
    s.resident = true;
    s.dataMin = host.minimum;
    s.dataMax = host.maximum;
    // Its empty-space cells, so that its slices leave out the air it holds (cutBricks).
    s.cells = std::make_shared<EmptyCells>();
    s.cells->measure(grid, nullptr, v.finiteMin, v.finiteMax);
    s.cellsTableKey = ~std::uint64_t(0);
    s.mayEmit = !v.hasTable || v.table.mayEmit(s.dataMin, s.dataMax, false, 0, 0);
    v.residentBytes += bytes;
    ++v.totals.brickUploads;
    v.totals.uploadedBytes += bytes;
}

/// Uploads the brick into a free slot (or a new one); returns its key.
BrickKey place(PagedSlots& slots, VolumeTextures& v, const PagedLayout& layout, const BrickKey& key,
               const HostBrick& host, std::uint64_t bytes) {
    std::size_t slot;
    if (!slots.freeSlots.empty()) {
        slot = slots.freeSlots.back();
        slots.freeSlots.pop_back();
    } else {
        slot = v.bricks.size();
        v.bricks.emplace_back();
        slots.keyOf.emplace_back();
        slots.bricks.emplace_back();
    }
    slots.keyOf[slot] = key;
    slots.bricks[slot] = brickOf(layout, key);
    upload(v, slot, host, bytes);
    ++slots.uploads;
    slots.slotOf.emplace(key, slot);
    return key;
}

/// Sort-last (lib/volsg/sortlast/README.md): this process draws only the fragments whose plane
/// point lies in its part of the volume box, so it needs (and loads) only the bricks meeting
/// that part: the selection's region becomes the part, within a BoxClip's region if any.
void keepToPart(const RayCastVolume& volume, const VolumePartition& partition,
                LodRequest& request) {
    // The split the slicer draws by (partitionVolume), of the grid it is given: the stand-in.
    const KdVolumeSplit split(volume.data->dimensions(), volume.data->spacing(), partition.parts);
    const KdVolumeSplit::Part& part = split.part(partition.part);
    constexpr double kNowhere = std::numeric_limits<double>::infinity();
    glm::dvec3 lo = part.boxMin, hi = part.boxMax;
    if (request.regionMin.x <= request.regionMax.x) { // a BoxClip's region too
        lo = glm::max(lo, request.regionMin);
        hi = glm::min(hi, request.regionMax);
    }
    // An empty part or intersection meets no brick (min > max would mean the whole volume).
    if (part.empty || glm::any(glm::greaterThanEqual(lo, hi))) lo = hi = glm::dvec3(kNowhere);
    request.regionMin = lo;
    request.regionMax = hi;
}

} // namespace

PagingStats preparePagedBricks(FrameContext& frame, PagedSlots& slots, VolumeTextures& v,
                               PagedVolume& paged, const LocalView& local,
                               std::uint64_t textureBudget, double pixelBudget,
                               const RayCastVolume& volume) {
    const PagedLayout& layout = paged.layout();
    const std::size_t texelBytes = v.format.texelBytes;
    const std::uint64_t budget = textureBudget > 0 ? textureBudget : kDefaultPagedTextureBudget;

    // The bricks asked for last frame that arrived since go to the GPU before choosing: the
    // choice refines a brick only when all its children are at hand, and the GPU keeps them
    // whatever the host cache evicts meanwhile (a host budget smaller than a brick's children
    // of every parent would otherwise never have all of them at once).
    const std::uint64_t allowance = slots.slotOf.empty() ? kFirstFrameUploads
                                    : frame.interactive  ? kInteractiveUploads
                                                         : kStillUploads;
    std::uint64_t uploading = 0; // bytes this frame uploads or has promised to
    bool heldBack = false;       // a brick at hand waits for a later frame's uploads
    for (const BrickKey& key : slots.wanted) {
        if (slots.slotOf.count(key)) continue;
        // Half the allowance at most: the rest is the choice's, which may need a fallback.
        if (uploading + textureBytesOf(layout, key, texelBytes) > allowance / 2) {
            heldBack = true;
            break;
        }
        const std::shared_ptr<const HostBrick> host = paged.find(key);
        if (!host) continue;
        // Into free room only: evicting for a brick not yet chosen made textures thrash (the
        // 2048^3 run uploaded 7840 bricks and evicted 6448 without converging).
        const std::uint64_t bytes = textureBytesOf(layout, key, texelBytes);
        if (v.residentBytes + bytes > budget) break;
        place(slots, v, layout, key, *host, bytes);
        uploading += bytes;
    }

    LodView view;
    view.modelView = local.modelView;
    view.projection = frame.view.projection;
    view.viewportHeight = std::max(frame.view.height, 1);
    view.orthographic = local.orthographic;
    LodRequest request;
    request.pixelBudget = pixelBudget;
    request.textureBudget = budget;
    const int rootLevel = layout.levelCount() - 1;
    request.available = [&](const BrickKey& key) {
        if (slots.slotOf.count(key)) return true;
        if (!paged.available(key)) return false;
        if (key.level == rootLevel) return true; // the roots are drawn whatever it costs
        const std::uint64_t bytes = textureBytesOf(layout, key, texelBytes);
        if (uploading > 0 && uploading + bytes > allowance) {
            heldBack = true;
            return false;
        }
        uploading += bytes;
        return true;
    };
    request.bytes = [&](const BrickKey& key) { return textureBytesOf(layout, key, texelBytes); };
    if (volume.boxClip && volume.boxClip->outsideOpacity <= 0.0) {
        // The BoxClip's box in local coordinates (its corners through its own model, as the
        // shader's uLocalToBox maps them), bounded by an axis-aligned box.
        const RayCastBoxClip& b = *volume.boxClip;
        const glm::dmat4 boxToLocal =
            b.model ? glm::inverse(volume.model) * *b.model : glm::dmat4(1.0);
        request.regionMin = glm::dvec3(std::numeric_limits<double>::infinity());
        request.regionMax = -request.regionMin;
        for (int c = 0; c < 8; ++c) {
            const glm::dvec3 corner =
                b.origin + b.extent * glm::dvec3(c & 1, (c >> 1) & 1, (c >> 2) & 1);
            const glm::dvec3 p = glm::dvec3(boxToLocal * glm::dvec4(corner, 1.0));
            request.regionMin = glm::min(request.regionMin, p);
            request.regionMax = glm::max(request.regionMax, p);
        }
    }
    if (frame.partition.parts > 1) keepToPart(volume, frame.partition, request);
    LodSelection chosen = selectBricks(layout, view, request);
    // A brick that could not be read stays coarse (its parent drawn) and is wanted no more:
    // the frame converges without it, and the error is reported.
    std::erase_if(chosen.wanted, [&](const BrickKey& key) { return paged.failed(key); });
    paged.request(chosen.wanted); // never waited for: the next frames draw what arrived

    // Textures for the chosen bricks, evicting those this frame does not draw.
    // The drawn bricks and their refined ancestors (the fallbacks) are never evicted for them.
    std::set<std::size_t> drawnSlots;
    for (const auto* keys : {&chosen.drawn, &chosen.refined})
        for (const BrickKey& key : *keys)
            if (const auto it = slots.slotOf.find(key); it != slots.slotOf.end())
                drawnSlots.insert(it->second);
    v.order.clear();
    std::vector<BrickKey> drawnKeys;
    for (const BrickKey& key : chosen.drawn) {
        auto it = slots.slotOf.find(key);
        if (it == slots.slotOf.end()) {
            const std::shared_ptr<const HostBrick> host = paged.find(key);
            if (!host) continue; // evicted from host memory since it was chosen: next frame
            const std::uint64_t bytes = textureBytesOf(layout, key, texelBytes);
            while (v.residentBytes + bytes > budget && evictOne(slots, v, drawnSlots)) {
            }
            it = slots.slotOf.find(place(slots, v, layout, key, *host, bytes));
            drawnSlots.insert(it->second);
        }
        v.bricks[it->second].lastUse = ++v.useCounter;
        v.order.push_back(int(it->second));
        drawnKeys.push_back(key);
    }
    slots.wanted = chosen.wanted;
    v.layout = BrickLayout::fromBricks(slots.bricks, layout.level(0).dimensions, layout.spacing(),
                                       texelBytes);
    v.hasLayout = true;

    PagingStats stats;
    stats.paged = true;
    stats.levels = layout.levelCount();
    stats.bricksDrawn = int(drawnKeys.size());
    stats.finestLevel = layout.levelCount() - 1;
    stats.finestDrawnVoxel = std::numeric_limits<double>::infinity();
    for (const BrickKey& key : drawnKeys) {
        stats.finestLevel = std::min(stats.finestLevel, key.level);
        stats.coarsestLevel = std::max(stats.coarsestLevel, key.level);
        const glm::dvec3 s = layout.spacingOf(key.level);
        stats.finestDrawnVoxel = std::min({stats.finestDrawnVoxel, s.x, s.y, s.z});
    }
    if (drawnKeys.empty()) stats.finestDrawnVoxel = paged.finestSpacing();
    stats.worstVoxelPixels = chosen.worstPixels;
    stats.pixelBudget = pixelBudget;
    stats.coarserBricks = chosen.coarser;
    stats.budgetLimited = chosen.budgetLimited;
    stats.wanted = int(chosen.wanted.size());
    stats.converged = chosen.converged() && !heldBack && drawnKeys.size() == chosen.drawn.size();
    v.pagedDrawn = std::move(drawnKeys); // LevelOfDetailError reads the levels drawn
    const BrickCacheStats host = paged.cache().stats();
    stats.hostBytes = paged.hostBytes();
    stats.hostBudget = paged.options().hostBudget;
    stats.textureBytes = v.residentBytes;
    stats.textureBudget = budget;
    stats.hostBricks = host.resident;
    stats.textureBricks = int(slots.slotOf.size());
    stats.loading = host.loading;
    stats.queued = host.queued;
    stats.bricksLoaded = host.loaded;
    stats.bytesLoaded = host.loadedBytes;
    stats.hostEvictions = host.evicted;
    stats.loadFailures = host.failed;
    stats.loadMilliseconds = host.loadMilliseconds;
    stats.textureUploads = slots.uploads;
    stats.textureEvictions = slots.evictions;
    if (host.failed > 0) {
        const std::vector<std::string> errors = paged.cache().errors();
        if (!errors.empty()) stats.firstError = errors.front();
    }
    return stats;
}

PagingStats preparePaged(FrameContext& frame, const Object& owner, std::uint64_t key,
                         VolumeTextures& v, const RayCastVolume& volume, LocalView& local,
                         SlicingSettings& settings) {
    PagedVolume& paged = *volume.paged;
    local.L0 = paged.finestSpacing();
    PagedSlots& slots = frame.cache.get<PagedSlots>(owner, key);
    PagingStats stats = preparePagedBricks(frame, slots, v, paged, local, settings.textureBudget,
                                           settings.lodPixels, volume);
    if (settings.numPlanes <= 0) {
        // Sort-last: the planes of every process follow the finest level any of them draws,
        // as one process drawing all the parts would (a part drawing nothing has no say).
        double finest = stats.bricksDrawn > 0 ? stats.finestDrawnVoxel
                                              : std::numeric_limits<double>::infinity();
        finest = frame.partition.smallest(finest);
        if (!std::isfinite(finest)) finest = stats.finestDrawnVoxel;
        // An error target's choice was made on the stand-in (settingsForFrame; in level 0's
        // L0): the finest level drawn gets as many planes per voxel of its own as the stand-in
        // got per voxel of its own (finer detail needs no fewer). Without a target, the fixed
        // rule: two planes per voxel, one while interacting.
        const double standInVoxel = volume.data->smallestSpacing();
        const double perVoxel = settings.planeSpacingL0 > 0.0
                                    ? settings.planeSpacingL0 * local.L0 / standInVoxel
                                : frame.interactive ? 1.0
                                                    : 0.5;
        settings.planeSpacingL0 = perVoxel * finest / local.L0;
    }
    return stats;
}

} // namespace volsg::slicing
