#pragma once
// The pure DVR row composite of the shear-warp renderer: one resampled intermediate row
// composited front to back ("under") into the image, with early ray termination.

#include <cstdint>

#include <glm/glm.hpp>

#include <volsg/shearwarp/SimdLevel.h>

namespace volsg {

/// One intermediate row of a pure DVR frame and what compositing into it updates.
struct UnderRow {
    glm::vec4* pixels;        ///< premultiplied colour and alpha, front to back
    std::int16_t* pickObject; ///< -1 until a sample of alpha >= kPickAlpha arrives
    float* pickSlice;
    std::int32_t* open; ///< opaque-pixel links: c while pixel c is open, later c + 1
    const float* limit; ///< null: no opaque geometry; else a sample counts when zSlice > limit
    int* opaqueCount;   ///< the row's stopped pixels (linked ones)
    std::int16_t object;
    float slice, zSlice;
};

struct UnderComposite {
    static constexpr float kOpaque = 0.999f;   ///< a pixel this opaque takes no more samples
    static constexpr float kPickAlpha = 0.02f; ///< a sample this opaque is what a click hits

    /// Composites the samples wa * a[c] + wb * b[c] (a or b may be null: absent) under the
    /// row's pixels for c in [lo, hi). A pixel whose alpha is already >= kOpaque takes nothing
    /// and is linked past (open[c] = c + 1) the first time it is met; a sample of alpha <= 0
    /// or behind the opaque limit is skipped; the first sample of alpha >= kPickAlpha at a
    /// pixel records the row's object and slice. The lines are only read. Every level gives the
    /// same pixels bit for bit.
    static void composite(SimdLevel level, const UnderRow& row, const glm::vec4* a, float wa,
                          const glm::vec4* b, float wb, int lo, int hi);
    /// The same on the columns of [lo, hi) that the lines' splats wrote (ColumnMask.h: a
    /// voxel's bit covers its column and the next; maskA belongs to line a, maskB to line b, and
    /// must be readable at word -1). Elsewhere both samples are 0, which changes no pixel: the
    /// pixels and picks are those of `composite` bit for bit; only an opaque pixel there is not
    /// linked now (a later slice links it where a voxel meets it).
    static void compositeWritten(SimdLevel level, const UnderRow& row, const glm::vec4* a, float wa,
                                 const std::uint64_t* maskA, const glm::vec4* b, float wb,
                                 const std::uint64_t* maskB, int lo, int hi);
};

} // namespace volsg
