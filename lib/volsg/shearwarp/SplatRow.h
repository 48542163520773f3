#pragma once
// The splat of the shear-warp renderer: the voxels of one row of a slice classified by their
// tables and split between two columns of a line buffer with the slice's bilinear weights (the
// resampling of the slice along a; ShearWarpRenderer blends two lines into an intermediate row).

#include <cstdint>

#include <glm/glm.hpp>

#include <volsg/shearwarp/SimdLevel.h>

namespace volsg {

/// How a packed voxel becomes premultiplied colour and opacity (VoxelTables.h).
enum class SplatLookup : std::uint8_t {
    MipValue, ///< MIP objects: (value12 / 4095, 0, 0, 1) from the value array (no table)
    Direct,   ///< rgba[attributes16 & mask]
    TwoStage, ///< rgba[second4 * 256 + lut2[main12]]
};

/// The voxels [begin, end) of one row b of one object part (PackedVoxel words sorted by a, at
/// most one per a) and how they are drawn: what a row's splat reads.
struct SplatRow {
    const std::uint32_t* packed; ///< the part's packed voxels (indexed by begin..end)
    const std::uint16_t* values; ///< MipValue: 12-bit values beside `packed`
    const glm::vec4* rgba;       ///< Direct, TwoStage: the part's premultiplied table
    const std::uint8_t* lut2;    ///< TwoStage: main12 -> shading intensity
    std::uint32_t mask;          ///< Direct: the attribute bits the table reads
    std::uint32_t begin, end;
    SplatLookup lookup;
    /// The line is zero everywhere (the row's first part): shares are stored, not added, and
    /// transparent voxels need no test (they add zeros). Otherwise they are added to the line.
    bool fresh;
    int colBase; ///< line column of a = 0: voxel a splats into columns a + colBase and the next
    float fu;    ///< the slice's fractional shift along a: weights 1 - fu (left) and fu (right)
    /// a of the volume's side faces in this piece (256: not in it). A face voxel's outer column
    /// takes its full value when the face lies within that pixel (fu <= 0.5 on the low face, fu
    /// >= 0.5 on the high one) and nothing otherwise: the data is clamped up to the box face.
    unsigned edgeA0, edgeA1;
    /// Early ray termination: skip the voxels whose four pixels (columns c, c + 1 of the two
    /// intermediate rows the row blends into) have all stopped. openA, openB: those rows'
    /// opaque-pixel links (UnderRow::open), null for a row outside the band (counts as
    /// stopped); they are only read and path-compressed.
    bool skipHidden;
    std::int32_t* openA;
    std::int32_t* openB;
    int width; ///< pixels of an intermediate row (the links' length)
};

/// The line a row is splatted into: premultiplied colour and alpha per column, and the columns
/// written so far, [lo, hi) (lo = INT_MAX, hi = 0: none), and bit by bit in `written`
/// (ColumnMask.h: the left column of each voxel splatted; readable at word -1). Outside the
/// columns `written` covers the line is 0.
struct SplatLine {
    glm::vec4* pixels;
    int lo, hi;
    std::uint64_t* written;
    int voxels = 0; ///< voxels splatted into it (marked)
};

/// The hidden-voxel state of one voxel row, carried from its first part to its second: voxels
/// in columns below hiddenBefore are hidden, those up to visibleThrough were found visible.
struct SplatSkip {
    int hiddenBefore = -1, visibleThrough = -1;
    std::uint64_t hidden = 0; ///< voxels skipped as hidden
};

struct RowSplat {
    /// Splats voxels begin..end-1 in order: voxel a with colour C adds (1 - fu) C to column
    /// a + colBase and fu C to the next (face voxels: the weights above on their outer column),
    /// widens [lo, hi) to both columns and marks its left column in `written`. With skipHidden,
    /// hidden voxels are left out and counted before their colour is looked up (a run of them
    /// below hiddenBefore without reading more than their positions). Transparent voxels (alpha
    /// <= 0) are left out, except on a fresh line without skipHidden (there they add zeros, and
    /// still widen [lo, hi) and mark). Every level gives the same line bit for bit. Levels: Scalar
    /// (a vec4 per SSE/NEON instruction); Avx2 runs the scalar kernel (a splat of voxel pairs in
    /// 256-bit registers measured no faster: README.md).
    static void splat(SimdLevel level, const SplatRow& row, SplatLine& line, SplatSkip& skip);
};

} // namespace volsg
