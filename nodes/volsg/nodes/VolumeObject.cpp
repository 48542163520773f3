#include <volsg/nodes/VolumeObject.h>

#include <cstring>

#include <volsg/core/KeyMixing.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

const EnumValues VolumeObject::sourceNames{
    {"WHOLE", WHOLE}, {"TAG", TAG}, {"THRESHOLD", THRESHOLD}};
const EnumValues VolumeObject::voxelsNames{
    {"VISIBLE", VISIBLE}, {"SURFACE", SURFACE}, {"GRADIENT", GRADIENT}};
const EnumValues VolumeObject::renderModeNames{{"TF", TF},
                                               {"SHADED", SHADED},
                                               {"GRADIENT_OPACITY", GRADIENT_OPACITY},
                                               {"CONTOUR", CONTOUR},
                                               {"COLORED_CONTOUR", COLORED_CONTOUR}};
const EnumValues VolumeObject::compositingNames{
    {"DVR", DVR}, {"MIP", MIP}, {"SURFACE", SURFACE_HIT}};

namespace {

constexpr std::size_t kCachedGrids = 8;

} // namespace

ExtractionSpec VolumeObject::extractionSpec(const TransferFunction1D& transferFunction) const {
    ExtractionSpec spec;
    switch (source()) {
    case TAG:
        spec.source.kind = ObjectSource::Tag;
        break;
    case THRESHOLD:
        spec.source.kind = ObjectSource::Threshold;
        break;
    default:
        spec.source.kind = ObjectSource::Whole;
        break;
    }
    spec.source.tag = tag();
    spec.source.low = threshold().x;
    spec.source.high = threshold().y;
    spec.selection = voxels() == SURFACE    ? VoxelSelection::Surface
                     : voxels() == GRADIENT ? VoxelSelection::Gradient
                                            : VoxelSelection::Visible;
    spec.gradientThreshold = gradientThreshold();
    spec.transferFunction = transferFunction;
    return spec;
}

ref_ptr<VoxelObject> VolumeObject::voxelObject(const VolumeGrid& grid, const VolumeGrid* tags,
                                               const TransferFunction1D& transferFunction,
                                               std::uint64_t transferKey) {
    // Only the fields that decide which voxels are taken (not the looks) key the extraction.
    std::uint64_t key = 0xcbf29ce484222325ULL;
    key = mixKey(key, std::uint64_t(source()));
    key = mixKey(key, std::uint64_t(std::int64_t(tag())));
    key = mixKey(key, bitsOf(threshold().x));
    key = mixKey(key, bitsOf(threshold().y));
    key = mixKey(key, std::uint64_t(voxels()));
    key = mixKey(key, bitsOf(gradientThreshold()));
    // The transfer function decides which voxels are taken only for VISIBLE selection or a
    // WHOLE region; otherwise only its data range (the normalisation of v) matters, so editing
    // its colours or opacities keeps the lists (the optimizer follows such edits).
    if (voxels() == VISIBLE || source() == WHOLE) {
        key = mixKey(key, transferKey);
    } else if (const auto& range = transferFunction.dataRange()) {
        key = mixKey(mixKey(key, bitsOf(range->x)), bitsOf(range->y));
    }
    for (auto it = cache_.begin(); it != cache_.end(); ++it)
        if (it->grid.get() == &grid && it->tags.get() == tags && it->key == key) {
            cache_.splice(cache_.begin(), cache_, it);
            return cache_.front().voxels;
        }
    // A new extraction replaces the entries of the same grid (stale keys) and the oldest.
    cache_.remove_if([&](const CacheEntry& e) { return e.grid.get() == &grid; });
    CacheEntry entry;
    entry.grid = ref_ptr<const VolumeGrid>(&grid);
    entry.tags = ref_ptr<const VolumeGrid>(tags);
    entry.key = key;
    entry.voxels = VoxelObject::extract(grid, tags, extractionSpec(transferFunction));
    cache_.push_front(entry);
    if (cache_.size() > kCachedGrids) cache_.pop_back();
    return cache_.front().voxels;
}

} // namespace volsg
