#pragma once
// Generated volumes with known content, for tests, benchmarks and examples. All deterministic.

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// The Marschner-Lobb test signal (Marschner & Lobb 1994) at (x, y, z) in [-1, 1]^3:
/// `rho = (1 - sin(pi z / 2) + alpha (1 + rho_r(sqrt(x^2 + y^2)))) / (2 (1 + alpha))`,
/// `rho_r(r) = cos(2 pi fM cos(pi r / 2))`. Its values lie in [0, 1].
double marschnerLobb(double x, double y, double z, double fM = 6.0, double alpha = 0.25);

/// n^3 samples of marschnerLobb() (n >= 2; the classic is 41) at x_i = -1 + 2i/(n-1). The
/// spacing is 2/(n-1), so the voxel centres' local coordinates ARE the signal's coordinates.
/// UByte stores round(255 rho), UShort round(65535 rho), Short round(32767 rho), Float rho.
ref_ptr<VolumeGrid> makeMarschnerLobb(int n = 41, VoxelType type = VoxelType::UByte);

/// A ball with a linear radial falloff: `max(0, 1 - r / R)` with r the distance of the voxel
/// centre from the grid centre and R = 0.45 n (voxel units), scaled to the type as above.
ref_ptr<VolumeGrid> makeSoftSphere(int n, VoxelType type = VoxelType::UByte);

/// UByte 255 on the voxels whose centre lies within thickness/2 of the sphere of `radius`
/// (voxel units) around the grid centre, 0 elsewhere: a shell about `thickness` voxels thick
/// (1 to 2 is the interesting case for samplers).
ref_ptr<VolumeGrid> makeThinShell(int n, double radius, double thickness = 1.5);

/// UShort Gaussian blob (sigma = n/4 voxels) rescaled so that its smallest voxel is exactly 0
/// and its largest exactly 65535: a 16-bit volume that uses the type's full range.
ref_ptr<VolumeGrid> makeFullRange16(int n);

/// A soft sphere (UByte) with a UByte tag grid of four tags: 1 inside r < 0.25 n, 2 for
/// 0.25 n <= r < 0.4 n, 3 for the remaining voxels with k < n/4, 0 elsewhere.
struct LabelledVolume {
    ref_ptr<VolumeGrid> data;
    ref_ptr<VolumeGrid> tags;
};
LabelledVolume makeLabelledVolume(int n);

/// Every voxel = `value` (stored as the type stores it).
ref_ptr<VolumeGrid> makeConstant(glm::ivec3 dimensions, VoxelType type, double value,
                                 glm::dvec3 spacing = glm::dvec3(1.0));

/// Linear in the voxel index along `axis` (0, 1, 2): voxel i holds
/// `first + (last - first) * i / (N - 1)` (`first` when N = 1), constant across the other axes.
ref_ptr<VolumeGrid> makeRamp(glm::ivec3 dimensions, VoxelType type, int axis, double first,
                             double last, glm::dvec3 spacing = glm::dvec3(1.0));

} // namespace volsg
