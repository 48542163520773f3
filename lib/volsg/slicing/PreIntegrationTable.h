#pragma once
// Pre-integrated classification (Engel, Kraus, Ertl 2001): what a slab contributes when the
// normalised value v runs linearly from v_front to v_back across it, tabulated over both.

#include <vector>

#include <glm/glm.hpp>

#include <volsg/volume/TransferFunction1D.h>

namespace volsg {

/// A kSize x kSize table over (v_front, v_back) at v = i / (kSize - 1), each entry
/// (Cmean.rgb, Dmean):
/// - Dmean = (1 / (v_b - v_f)) * integral over [v_f, v_b] of tau(v) L0 dv, the mean optical
///   depth per reference length L0 along the segment (tau L0 = -ln(1 - min(A, 1 - 1e-6)));
/// - Cmean = the tau-weighted mean colour over the segment.
///
/// A slab of local length ds then has optical depth D = Dmean * ds / L0 (exact for linear v)
/// and emits Cmean * (1 - e^-D): exact whenever the colour is constant over the segment, for
/// any opacity profile, since then integral C tau T = C (1 - T_end). Unlike Engel's table for
/// one slab length, this one does not depend on the slab length, so it is rebuilt only when
/// the transfer function changes, not when the view changes the plane spacing; perspective
/// rays (longer slabs off axis) and planeOpacity/BoxClip multipliers scale D exactly.
/// Integrals use a cumulative table of 16384 trapezoids per channel in double.
class PreIntegrationTable {
public:
    static constexpr int kSize = 256;
    static constexpr int kIntegrationSteps = 16384;
    /// Transfer-table rows that get a table (the slicer stacks them in one 2D texture of
    /// kSize x kSize * rows, 1 MB each); a volume with more tagged functions is not
    /// pre-integrated.
    static constexpr int kMaxRows = 64;
    /// How far (in v) a lookup of a value reads around it: one table entry, whose integral is
    /// of trapezoids kIntegrationSteps wide (two of them). Where the transfer function is
    /// transparent that far either side of a value, every lookup of it has optical depth 0
    /// (EmptyCells' pad for pre-integration; it covers the 4096-entry table's filter too).
    static constexpr double kLookupPadV = 1.0 / (kSize - 1) + 2.0 / kIntegrationSteps;

    void build(const TransferFunction1D& function);
    /// kSize * kSize RGBA texels, row = v_back index, column = v_front index.
    const std::vector<float>& texels() const { return texels_; }
    /// The exact entry for any (v_front, v_back) in [0, 1] (what the texels sample).
    glm::dvec4 segment(double vFront, double vBack) const;
    /// segment() where the segment absorbs (Dmean > 1e-12), and all zero where it does not: a
    /// ray integral never uses a transparent segment's colour, and skipping it saves the
    /// transfer function's evaluation on the empty space that most rays cross.
    glm::dvec4 absorbingSegment(double vFront, double vBack) const;

private:
    glm::dvec4
    cumulativeAt(double v) const;       ///< integrals from 0 to v of (tau r, tau g, tau b, tau)
    glm::dvec4 pointAt(double v) const; ///< (r, g, b, tau) at v

    TransferFunction1D function_;
    std::vector<glm::dvec4> cumulative_; ///< kIntegrationSteps + 1 entries
    std::vector<float> texels_;
};

} // namespace volsg
