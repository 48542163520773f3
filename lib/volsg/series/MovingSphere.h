#pragma once
// A generated time series for tests and benchmarks: a soft sphere that moves and grows.
#include <volsg/core/Object.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// UByte n^3 grid at time t in [0, 1]: the soft sphere of makeSoftSphere() (255 (1 - r/R) at
/// distance r from its centre, 0 beyond R) whose centre moves along x from 0.35 n to 0.65 n
/// (voxel units, y and z at n/2) while R grows from 0.2 n to 0.3 n. Spacing 1. Each step
/// differs, so every step has its own voxel lists. Throws Error for n < 1 or t outside [0, 1].
ref_ptr<VolumeGrid> makeMovingSphere(int n, double t);

} // namespace volsg
