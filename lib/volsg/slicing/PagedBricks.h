#pragma once
// The Volume slicer's part of out-of-core rendering: this frame's bricks of a paged volume
// chosen, uploaded under the texture budget, and handed to the slicer as its bricks.

#include <cstdint>
#include <map>
#include <vector>

#include <volsg/paging/BrickKey.h>
#include <volsg/paging/PagingStats.h>
#include <volsg/render/FrameContext.h>
#include <volsg/slicing/BrickLayout.h>
#include <volsg/slicing/SlicePlan.h>
#include <volsg/slicing/VolumeSlicer.h>
#include <volsg/slicing/VolumeTextures.h>

namespace volsg {

class PagedVolume;

namespace slicing {

/// Texture bytes a paged volume takes when its Volume sets no textureBudget.
constexpr std::uint64_t kDefaultPagedTextureBudget = std::uint64_t(512) << 20;

/// Before VolumeSlicer::draw of a paged volume (the Volume node calls it, as must whoever
/// draws a RayCastVolume with `paged` directly): widens its bricks' guard
/// (PagedVolume::widenGuard) when the frame samples around its points, as the slicer's own
/// bricks get a guard voxel for (prepareVolume): lighting's central differences, one voxel
/// either side, and pre-integration's slab ends (half a plane spacing on: past the narrow
/// guard only for oblique rays at one plane per voxel). DVR only: no other mode does either;
/// tags are not paged.
void preparePagedGuard(const RayCastVolume& volume, const SlicingSettings& settings);

/// Which brick each texture slot (an entry of VolumeTextures::bricks) holds, kept across
/// frames in the render cache beside the volume's textures.
struct PagedSlots {
    std::map<BrickKey, std::size_t> slotOf;
    std::vector<BrickKey> keyOf;
    std::vector<Brick> bricks; ///< per slot: its region and texels (BrickLayout::fromBricks)
    std::vector<std::size_t> freeSlots;
    std::vector<BrickKey> wanted; ///< the last frame's missing bricks
    std::uint64_t uploads = 0, evictions = 0;
};

/// Chooses the bricks of `paged` this frame draws (selectBricks: refined by `pixelBudget`
/// where finer bricks are at hand, the missing ones requested from the loaders, never
/// waited for), uploads those not yet on the GPU (evicting textures the frame does not draw,
/// least recently used first, to stay within `textureBudget`), and sets v.layout and v.order
/// to them, back to front. The textures are uploaded as the slicer's own bricks are.
PagingStats preparePagedBricks(FrameContext& frame, PagedSlots& slots, VolumeTextures& v,
                               PagedVolume& paged, const LocalView& local,
                               std::uint64_t textureBudget, double pixelBudget,
                               const RayCastVolume& volume);

/// A paged volume's frame, between prepareVolume and planeLayout: L0 becomes level 0's (the
/// opacity unit is the full-resolution volume's, whichever level draws), the bricks are
/// chosen and uploaded (preparePagedBricks, their slots kept in the render cache beside the
/// textures), and unless numPlanes fixes them the planes follow the finest drawn level: two
/// per voxel of it along the view, one while interacting.
/// A BoxClip that removes everything outside it (outsideOpacity 0, in local coordinates)
/// limits the bricks to those meeting its box.
PagingStats preparePaged(FrameContext& frame, const Object& owner, std::uint64_t key,
                         VolumeTextures& v, const RayCastVolume& volume, LocalView& local,
                         SlicingSettings& settings);

} // namespace slicing
} // namespace volsg
