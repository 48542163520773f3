#include <volsg/sections/SlicePick.h>

#include <volsg/actions/PickAction.h>

namespace volsg {

void pickSlice(PickAction& action, const SliceVolume& volume, const SlicePlane& plane,
               const SliceStyle& style) {
    const Ray localRay = action.worldRay().transformed(glm::inverse(volume.model));
    const auto t = plane.intersect(localRay, volume.halfExtent());
    if (!t) return;
    const glm::dvec3 local = localRay.at(*t);
    const SliceSample s = SliceSampler(volume, style).sample(local);
    if (s.discarded()) return;
    action.addLocalHit(local, plane.normal, 0, PickedVoxel{s.voxel, s.voxelValue, s.value, s.tag});
}

} // namespace volsg
