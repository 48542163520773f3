#pragma once
// The lookup tables of one object part for one view: LUT1/LUT2/LUT3 of RTVR figure 5, with
// the view-dependent opacity correction folded in.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/shearwarp/RenderList.h>
#include <volsg/shearwarp/ShearWarpScene.h>

namespace volsg {

/// Two kernels cover the five modes:
/// - Direct (TF, GradientOpacity): rgba = table[attributes16 & mask], LUT1 (4-bit) and LUT3
///   (12-bit) combined into one table per view;
/// - TwoStage (Shaded, Contour, ColoredContour): I = lut2[main12] (the shading table,
///   quantised to 8 bits), rgba = table[second4 * 256 + I] (LUT1 by the 4-bit value, LUT3 by
///   I).
/// rgba is premultiplied; for DVR and Surface compositing the alpha is opacity-corrected for
/// the sample spacing, `1 - (1 - A)^(opacity * ds / L0)`.
struct VoxelTables {
    enum class Kernel { Direct, TwoStage };
    Kernel kernel = Kernel::Direct;
    std::uint32_t mask = 0xFFF;
    std::vector<glm::vec4> rgba;
    std::vector<std::uint8_t> lut2;

    /// `stepRatio` = ds / L0; `localToEye` and `light` as ShadingTable takes them.
    static VoxelTables build(const ShearWarpObject& object, const VoxelLook& look, double stepRatio,
                             const glm::dmat3& localToEye, const glm::dvec3& light);
    /// Which packed attributes a mode reads.
    static PackedLayout layoutFor(VoxelRenderMode mode);
    /// Per attribute value, whether a voxel can contribute under these modes and transfer
    /// function at any view (shading tables are not a criterion: they change with the view).
    static std::vector<std::uint8_t> contributionMask(const ShearWarpObject& object,
                                                      const VoxelLook& look);
};

} // namespace volsg
