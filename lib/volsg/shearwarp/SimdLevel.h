#pragma once
// Which vector instructions the shear-warp kernels use: chosen at run time by the caller
// (ShearWarpView::simd), so the library needs no -march flag and runs on any x86-64 (or other)
// CPU.

namespace volsg {

/// Implementations of one definition: every level gives the same results bit for bit (the
/// same IEEE operations per component, no fused multiply-add), so the level changes speed only.
enum class SimdLevel {
    Scalar, ///< one pixel or voxel a step (a vec4 per SSE/NEON instruction)
    Avx2,   ///< two a step in 256-bit registers, when the CPU has AVX2
};

/// Whether this CPU runs `level`.
bool simdLevelAvailable(SimdLevel level);

/// The widest level this CPU runs (the default of ShearWarpView::simd).
SimdLevel bestSimdLevel();

} // namespace volsg
