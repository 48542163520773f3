#include <volsg/shearwarp/UnderComposite.h>

#include <cstring>

#include <volsg/shearwarp/ColumnMask.h>
#include <volsg/shearwarp/Lanes4.h>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define VOLSG_UNDER_AVX2 1
#endif

namespace volsg {

namespace {

constexpr float kOpaque = UnderComposite::kOpaque;
constexpr float kPickAlpha = UnderComposite::kPickAlpha;

using lanes::loadV4;
using lanes::storeV4;
using lanes::V4;

/// Pixel c of the row: the definition every kernel follows.
template <bool HasA, bool HasB, bool HasLimit>
inline void underPixel(const UnderRow& row, const glm::vec4* a, float wa, const glm::vec4* b,
                       float wb, int c) {
    V4 sample;
    if constexpr (HasA && HasB)
        sample = wa * loadV4(a[c]) + wb * loadV4(b[c]);
    else if constexpr (HasA)
        sample = wa * loadV4(a[c]);
    else
        sample = wb * loadV4(b[c]);
    glm::vec4* const g = row.pixels;
    const float alpha = g[c].w; // a load of its own: from the vector GCC went via the stack
    if (alpha >= kOpaque) {
        // Terminated (by an earlier slice): linked the first time it is met here, off the
        // path of the pixels still open.
        if (row.open[c] == c) {
            row.open[c] = c + 1;
            ++*row.opaqueCount;
        }
        return;
    }
    if (sample[3] <= 0.0f) return;
    if (HasLimit && !(row.zSlice > row.limit[c])) return; // behind geometry
    storeV4(g[c], loadV4(g[c]) + (1.0f - alpha) * sample);
    if (sample[3] >= kPickAlpha && row.pickObject[c] < 0) {
        row.pickObject[c] = row.object;
        row.pickSlice[c] = row.slice;
    }
}

/// The columns a kernel visits: [lo, hi) whole (no masks), or the runs in it that the lines'
/// masks cover (columns::Runs).
struct Columns {
    const columns::Word* maskA;
    const columns::Word* maskB;
    int lo, hi;
};

/// A function of its own per line combination (not inlined into the band loop) so the compiler
/// keeps the loop's values in registers: inlined, it went through the stack for every pixel.
template <bool HasA, bool HasB, bool HasLimit>
[[gnu::noinline]] void underScalar(const UnderRow& row, const glm::vec4* a, float wa,
                                   const glm::vec4* b, float wb, const Columns& columns) {
    const UnderRow local = row; // read through `row` the pointers were reloaded after every store
    int lo = 0, hi = 0;
    for (columns::Runs runs(columns.maskA, columns.maskB, columns.lo, columns.hi);
         runs.next(lo, hi);)
        for (int c = lo; c < hi; ++c)
            underPixel<HasA, HasB, HasLimit>(local, a, wa, b, wb, c);
}

#ifdef VOLSG_UNDER_AVX2
/// The constants of the AVX2 kernel, broadcast once a row.
struct Avx2Weights {
    __m256 wa, wb, one, zero, pickAlpha, opaque;
};

/// Pixels c and c + 1 in one 256-bit register: the same operations per component as underPixel
/// (no fused multiply-add), so the same pixels. Pixels that are opaque already, or whose pick
/// is due, go through underPixel (each once a frame: rare on the hot path).
template <bool HasA, bool HasB>
[[gnu::always_inline, gnu::target("avx2")]] inline void
underPairAvx2(const UnderRow& row, const Avx2Weights& k, const glm::vec4* a, float wa,
              const glm::vec4* b, float wb, int c) {
    glm::vec4* const g = row.pixels;
    const __m256 pixels = _mm256_loadu_ps(&g[c].x);
    if (_mm256_movemask_ps(_mm256_cmp_ps(pixels, k.opaque, _CMP_GE_OQ)) & 0x88) {
        underPixel<HasA, HasB, false>(row, a, wa, b, wb, c);
        underPixel<HasA, HasB, false>(row, a, wa, b, wb, c + 1);
        return;
    }
    __m256 sample;
    if constexpr (HasA && HasB)
        sample = _mm256_add_ps(_mm256_mul_ps(k.wa, _mm256_loadu_ps(&a[c].x)),
                               _mm256_mul_ps(k.wb, _mm256_loadu_ps(&b[c].x)));
    else if constexpr (HasA)
        sample = _mm256_mul_ps(k.wa, _mm256_loadu_ps(&a[c].x));
    else
        sample = _mm256_mul_ps(k.wb, _mm256_loadu_ps(&b[c].x));
    const __m256 alpha = _mm256_permute_ps(pixels, 0xFF);       // each pixel's w, broadcast
    const __m256 sampleAlpha = _mm256_permute_ps(sample, 0xFF); // likewise the sample's
    const __m256 under = _mm256_add_ps(pixels, _mm256_mul_ps(_mm256_sub_ps(k.one, alpha), sample));
    const __m256 shown = _mm256_cmp_ps(sampleAlpha, k.zero, _CMP_GT_OQ);
    _mm256_storeu_ps(&g[c].x, _mm256_blendv_ps(pixels, under, shown));
    // Picks due: sample alpha >= kPickAlpha (lanes 3 and 7) at a pixel without one yet.
    const int heavy = _mm256_movemask_ps(_mm256_cmp_ps(sample, k.pickAlpha, _CMP_GE_OQ));
    std::uint32_t objects;
    std::memcpy(&objects, row.pickObject + c, sizeof objects);
    const unsigned due = (((unsigned(heavy) >> 3) & 1u) | ((unsigned(heavy) >> 6) & 2u)) &
                         (((objects >> 15) & 1u) | ((objects >> 30) & 2u));
    if (due) [[unlikely]] {
        for (int i = 0; i < 2; ++i)
            if (due & (1u << i)) {
                row.pickObject[c + i] = row.object;
                row.pickSlice[c + i] = row.slice;
            }
    }
}

/// Four pixels a step (two pairs, interleaved by the compiler), then the rest, per span.
template <bool HasA, bool HasB>
[[gnu::noinline, gnu::target("avx2")]] void underAvx2(const UnderRow& row, const glm::vec4* a,
                                                      float wa, const glm::vec4* b, float wb,
                                                      const Columns& columns) {
    const UnderRow local = row;
    const Avx2Weights k{_mm256_set1_ps(wa),  _mm256_set1_ps(wb),         _mm256_set1_ps(1.0f),
                        _mm256_setzero_ps(), _mm256_set1_ps(kPickAlpha), _mm256_set1_ps(kOpaque)};
    int lo = 0, hi = 0;
    for (columns::Runs runs(columns.maskA, columns.maskB, columns.lo, columns.hi);
         runs.next(lo, hi);) {
        int c = lo;
        for (; c + 4 <= hi; c += 4) {
            underPairAvx2<HasA, HasB>(local, k, a, wa, b, wb, c);
            underPairAvx2<HasA, HasB>(local, k, a, wa, b, wb, c + 2);
        }
        if (c + 2 <= hi) {
            underPairAvx2<HasA, HasB>(local, k, a, wa, b, wb, c);
            c += 2;
        }
        if (c < hi) underPixel<HasA, HasB, false>(local, a, wa, b, wb, c);
    }
}

#endif

template <bool HasA, bool HasB>
void dispatch(SimdLevel level, const UnderRow& row, const glm::vec4* a, float wa,
              const glm::vec4* b, float wb, const Columns& columns) {
    if (row.limit) {
        underScalar<HasA, HasB, true>(row, a, wa, b, wb, columns);
        return;
    }
#ifdef VOLSG_UNDER_AVX2
    if (level == SimdLevel::Avx2) {
        underAvx2<HasA, HasB>(row, a, wa, b, wb, columns);
        return;
    }
#else
    (void)level;
#endif
    underScalar<HasA, HasB, false>(row, a, wa, b, wb, columns);
}

void compositeColumns(SimdLevel level, const UnderRow& row, const glm::vec4* a, float wa,
                      const glm::vec4* b, float wb, const Columns& columns) {
    if (!simdLevelAvailable(level)) level = SimdLevel::Scalar;
    if (a && b)
        dispatch<true, true>(level, row, a, wa, b, wb, columns);
    else if (a)
        dispatch<true, false>(level, row, a, wa, b, wb, columns);
    else if (b)
        dispatch<false, true>(level, row, a, wa, b, wb, columns);
}

} // namespace

void UnderComposite::composite(SimdLevel level, const UnderRow& row, const glm::vec4* a, float wa,
                               const glm::vec4* b, float wb, int lo, int hi) {
    compositeColumns(level, row, a, wa, b, wb, Columns{nullptr, nullptr, lo, hi});
}

void UnderComposite::compositeWritten(SimdLevel level, const UnderRow& row, const glm::vec4* a,
                                      float wa, const std::uint64_t* maskA, const glm::vec4* b,
                                      float wb, const std::uint64_t* maskB, int lo, int hi) {
    if (!a) maskA = nullptr;
    if (!b) maskB = nullptr;
    if (!maskA && !maskB) return; // no line: nothing written
    compositeColumns(level, row, a, wa, b, wb, Columns{maskA, maskB, lo, hi});
}

} // namespace volsg
