#pragma once
// The two-level row composite of the shear-warp renderer (every frame that is neither pure DVR
// nor value-sorted MIP): resampled samples composited into the run of the object a ray is in,
// and runs merged into the global buffer when the ray meets another object or ends.

#include <cstdint>

#include <glm/glm.hpp>

#include <volsg/shearwarp/ShearWarpScene.h>
#include <volsg/shearwarp/SimdLevel.h>

namespace volsg {

/// What a run of one object needs at its merge.
struct TwoLevelObject {
    ObjectCompositing compositing;
    const glm::vec4* mipTable; ///< MIP: 4096 premultiplied colours by value (C(v) A(v))
};

/// One intermediate row (or, for TwoLevelComposite::flush, a run of rows) of a two-level
/// frame: the two buffers and what compositing into them updates.
struct TwoLevelRow {
    glm::vec4* global;         ///< the layers merged so far (inter-object mode)
    glm::vec4* local;          ///< DVR, Surface runs: premultiplied colour, front over back
    float* localValue;         ///< MIP runs: the largest resampled value (-1: none)
    float* localDepth;         ///< Surface runs: the depth of their front-most dense sample
    std::int16_t* localObject; ///< the object of the run (-1: none)
    float* hitDepth;           ///< Surface hits drawn opaque: window depth (1: none)
    std::int16_t* pickObject;  ///< the front-most object that gave a sample of alpha >= kPickAlpha
    float* pickSlice;
    const float* limit; ///< null: no opaque geometry; else a sample counts when zSlice > limit
    const TwoLevelObject* objects; ///< by object index (the flush reads the run's object)
    InterObjectCompositing inter;
    std::int16_t object; ///< the object whose samples arrive
    float slice, zSlice;
    /// Surface depth of pixel c: sliceDepth + float(depthScale * (zu * c + zvRow)).
    float sliceDepth;
    double depthScale, zu, zvRow;
};

struct TwoLevelComposite {
    static constexpr float kPickAlpha = 0.02f;   ///< as UnderComposite::kPickAlpha
    static constexpr float kSurfaceAlpha = 0.5f; ///< a Surface run this opaque is drawn opaque
    static constexpr float kSurfaceDepthAlpha = 0.25f; ///< a Surface sample this opaque gives depth

    /// Composites the samples wa * a[c] + wb * b[c] (a or b may be null: absent) of the row's
    /// object for c in [lo, hi): a sample of alpha <= 0 or behind the opaque limit is skipped;
    /// a pixel whose run belongs to another object is flushed first. Then by the object's
    /// compositing: DVR and Surface put the sample over the run (the frame runs back to
    /// front), a sample of alpha >= kPickAlpha records the object and slice for picking, Surface
    /// keeps the depth of samples of alpha >= kSurfaceDepthAlpha; MIP keeps the largest value
    /// (the sample's red channel), recorded for picking when its table alpha is >= kPickAlpha.
    /// Every level gives the same buffers bit for bit (all run the scalar kernel).
    static void composite(SimdLevel level, const TwoLevelRow& row, const glm::vec4* a, float wa,
                          const glm::vec4* b, float wb, int lo, int hi);

    /// Merges the runs of pixels [lo, hi) into the global buffer and empties them: the run's
    /// layer (MIP: the table at its value, interpolated; Surface with alpha >= kSurfaceAlpha:
    /// opaque, colour / alpha, its depth to hitDepth) goes over the global pixel (inter DVR) or
    /// takes the per-channel maximum with it (inter MIP).
    static void flush(const TwoLevelRow& row, int lo, int hi);
};

} // namespace volsg
