#pragma once
// The exact value of a planar section at a point, in double precision: what the GL slice
// approximates, and what picking reports.

#include <optional>

#include <glm/glm.hpp>

#include <volsg/volume/VolumeModel.h>

namespace volsg {

/// How a slice's alpha is made from its transfer function's (VolumeViz semantics).
enum class SliceAlphaUse {
    AsIs,   ///< the transfer function's A (clamped to TransferTable::kMaxOpacity as volumes)
    Opaque, ///< 1 everywhere
    Binary  ///< 1 where A > 0, else 0
};

struct SliceStyle {
    bool linear = true; ///< trilinear between voxel centres; else the nearest voxel
    SliceAlphaUse alphaUse = SliceAlphaUse::Binary;
};

/// One point of a slice.
struct SliceSample {
    glm::ivec3 voxel{0};     ///< the nearest voxel (the one whose cell holds the point)
    double voxelValue = 0.0; ///< its raw value (as stored, NaN included)
    double value = 0.0;      ///< the value the slice shows (trilinear or nearest)
    int tag = -1;            ///< the nearest voxel's tag, -1 without tags
    glm::dvec4 rgba{0.0};    ///< classified, with the slice's alpha use
    bool discarded() const { return !(rgba.a > 0.0); } ///< fully transparent: not drawn
};

/// docs/SCENE-FORMAT.md section 4's sampling and classification of one volume: data trilinear
/// between voxel centres and clamped to the edge beyond the outermost ones, non-finite Float
/// voxels replaced by the grid's finite minimum (NaN, -Inf) or maximum (+Inf) first, tags
/// nearest; the transfer function of the voxel's tag (else tag -1's, else the identity ramp),
/// its dataRange or the data type's natural range.
class SliceSampler {
public:
    SliceSampler(const VolumeInScope& volume, SliceStyle style);

    /// The slice at local point p (anywhere; it is clamped into the data).
    SliceSample sample(const glm::dvec3& local) const;

private:
    double finiteValue(int i, int j, int k) const;

    const VolumeInScope& volume_;
    SliceStyle style_;
    glm::dvec3 halfExtent_;
    double lowest_ = 0.0, highest_ = 0.0;
    glm::dvec2 naturalRange_{0.0, 1.0};
    TransferFunction1D identity_;
};

} // namespace volsg
