#pragma once
// The transfer functions of one volume baked into plain tables for the GPU: one RGBA row per
// transfer function and a tag -> row map (the seed's tag-offset lookup, without its 256-entry
// limit).

#include <cstdint>
#include <map>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/volume/TransferFunction1D.h>

namespace volsg {

/// Rows over v in [0, 1]. Row 0 is the default (the tag -1 function, or the identity ramp
/// without one); rows 1.. are the functions of tags >= 0 in ascending tag order. A row holds
/// `kEntries` samples at v = i / (kEntries - 1) of (r, g, b, tau L0), where tau L0 =
/// -ln(1 - min(A, 1 - 1e-6)) is computed here in double (so the shader needs no logarithm
/// and loses nothing to 1 - A in float), interpolated linearly by the texture filter: a
/// piecewise-linear colour channel is exact except within 1/4095 of a control point. Then a
/// copy of the last sample (the filter's right neighbour at v = 1), then one texel (lo, hi,
/// 0, 0): the row's dataRange, so the shader normalises each sample with the range of its own
/// tag, in float, from the reconstructed data value (no precision lost to a pre-scaled 8-bit
/// index). `tagRows` maps every tag 0..65535 to its row (0 without its own function): a
/// 256 x 256 R16UI texture, so a transfer-function change rewrites only these tables and
/// never a volume texture.
class TransferTable {
public:
    static constexpr int kEntries = 4096;
    static constexpr int kRangeColumn = kEntries + 1;
    static constexpr int kWidth = kEntries + 2;
    static constexpr int kTagMapSide = 256;

    /// docs/SCENE-FORMAT.md section 4: A is clamped so that tau stays finite.
    static constexpr double kMaxOpacity = 1.0 - 1e-6;
    /// tau L0 = -ln(1 - min(A, 1 - 1e-6)), 0 for A <= 0.
    static double opticalDepthPerL0(double A);

    /// Bakes the rows. `naturalRange` is the data's range for functions without a dataRange
    /// (VolumeGrid::naturalRange()). Throws Error for a tag outside -1..65535.
    void build(const std::map<int, TransferFunction1D>& functions, glm::dvec2 naturalRange);

    int rows() const { return int(rows_.size()); }
    /// rows() * kWidth RGBA texels, row-major.
    const std::vector<float>& texels() const { return texels_; }
    /// 65536 rows, indexed by tag (x = tag & 255, y = tag >> 8 in the texture).
    const std::vector<std::uint16_t>& tagRows() const { return tagRows_; }
    const TransferFunction1D& function(int row) const { return rows_[std::size_t(row)].function; }
    glm::dvec2 dataRange(int row) const { return rows_[std::size_t(row)].range; }

    /// Whether a region whose trilinear data values lie in [dataMin, dataMax] and whose tags lie
    /// in [tagMin, tagMax] (ignored when `tagged` is false) can have a non-zero opacity under
    /// any row that applies to it. Conservative: the default row always counts for tagged data.
    /// `padV`: the normalised interval widened by this much each way (a table whose filtered
    /// lookups read entries that far beyond a value).
    bool mayEmit(double dataMin, double dataMax, bool tagged, int tagMin, int tagMax,
                 double padV = 0.0) const;

private:
    struct Row {
        int tag = -1;
        TransferFunction1D function;
        glm::dvec2 range{0.0, 1.0};
    };
    bool rowMayEmit(const Row& row, double dataMin, double dataMax, double padV) const;

    std::vector<Row> rows_;
    std::vector<float> texels_;
    std::vector<std::uint16_t> tagRows_;
};

} // namespace volsg
