#include <volsg/series/MovingSphere.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <volsg/core/Error.h>

namespace volsg {

ref_ptr<VolumeGrid> makeMovingSphere(int n, double t) {
    if (n < 1) throw Error("the moving sphere series needs at least 1 voxel a side");
    if (!(t >= 0.0 && t <= 1.0)) throw Error("the moving sphere series needs a time in [0, 1]");
    ref_ptr<VolumeGrid> grid = VolumeGrid::create({n, n, n}, VoxelType::UByte);
    const glm::dvec3 centre(n * (0.35 + 0.3 * t), 0.5 * n, 0.5 * n);
    const double radius = n * (0.2 + 0.1 * t);
    const auto voxels = grid->data<std::uint8_t>();
    // Only the sphere's bounding box can be non-zero (the grid starts zeroed).
    const auto lowest = [&](double c) { return std::clamp(int(std::floor(c - radius)), 0, n); };
    const auto highest = [&](double c) { return std::clamp(int(std::ceil(c + radius)), 0, n); };
    for (int k = lowest(centre.z); k < highest(centre.z); ++k)
        for (int j = lowest(centre.y); j < highest(centre.y); ++j) {
            std::uint8_t* row = voxels.data() + grid->index(0, j, k);
            const double dy = j + 0.5 - centre.y, dz = k + 0.5 - centre.z;
            for (int i = lowest(centre.x); i < highest(centre.x); ++i) {
                const double dx = i + 0.5 - centre.x;
                const double unit = 1.0 - std::sqrt(dx * dx + dy * dy + dz * dz) / radius;
                if (unit > 0.0) row[i] = std::uint8_t(std::lround(255.0 * unit));
            }
        }
    return grid;
}

} // namespace volsg
