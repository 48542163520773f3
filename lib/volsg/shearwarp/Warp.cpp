// Stage 7 of a shear-warp frame (FrameStages.h): every output pixel samples the intermediate
// image bilinearly (and Surface depth at its nearest intermediate pixel).
#include <volsg/shearwarp/FrameStages.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <volsg/shearwarp/Lanes4.h>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define VOLSG_WARP_AVX2 1
#endif

namespace volsg::shearwarp {

namespace {

using lanes::loadV4;
using lanes::storeV4;

glm::vec4 fetch(const WarpJob& job, int u, int v) {
    const int W = job.factorisation->W, H = job.factorisation->H;
    if (u < 0 || v < 0 || u >= W || v >= H) return glm::vec4(0.0f);
    return job.image[std::size_t(v) * std::size_t(W) + std::size_t(u)];
}

/// The output columns [xBegin, xEnd) of row y whose bilinear footprint can meet job.reach, the
/// composited part of the intermediate image: false when none. (Along x, (u, v) moves by
/// perPixel; the box is widened by 2 for the clamping below, the footprint and rounding.)
bool warpSpan(const WarpJob& job, const glm::dvec2& rowStart, const glm::dvec2& perPixel,
              int& xBegin, int& xEnd) {
    const int width = job.factorisation->width;
    double xFrom = 0.0, xTo = width;
    for (int i = 0; i < 2; ++i) { // lo <= rowStart[i] + x perPixel[i] <= hi
        const double lo = job.reach[i], hi = job.reach[i + 2];
        if (std::abs(perPixel[i]) < 1e-12) {
            if (!(rowStart[i] >= lo && rowStart[i] <= hi)) xTo = -1.0;
            continue;
        }
        double a0 = (lo - rowStart[i]) / perPixel[i], a1 = (hi - rowStart[i]) / perPixel[i];
        if (a0 > a1) std::swap(a0, a1);
        xFrom = std::max(xFrom, a0);
        xTo = std::min(xTo, a1);
    }
    if (!(xFrom <= xTo)) return false; // also when either is NaN
    // Clamped in double before the conversion: an extreme view gives values no int holds.
    xBegin = int(std::clamp(std::floor(xFrom) - 1.0, 0.0, double(width)));
    xEnd = int(std::clamp(std::ceil(xTo) + 2.0, 0.0, double(width)));
    return xBegin < xEnd;
}

/// The bilinear sample at intermediate pixel p (u, v) with weights (wu, wv): p, p + 1, p + W
/// and p + W + 1 all inside the image.
inline void bilinear(glm::vec4& out, const glm::vec4* p, int W, float wu, float wv) {
    storeV4(out, (loadV4(p[0]) * (1 - wu) + loadV4(p[1]) * wu) * (1 - wv) +
                     (loadV4(p[W]) * (1 - wu) + loadV4(p[W + 1]) * wu) * wv);
}

/// Output pixels [xBegin, xEnd) of row y.
void warpRow(const WarpJob& job, int y, const glm::dvec2& rowStart, const glm::dvec2& perPixel,
             int xBegin, int xEnd) {
    const Factorisation& f = *job.factorisation;
    const int W = f.W, H = f.H;
    const double uLo = f.ua0, uHi = f.ua0 + (f.na - 1), vLo = f.vb0, vHi = f.vb0 + (f.nb - 1);
    const glm::vec4* image = job.image;
    glm::vec4* out = job.out + std::size_t(y) * std::size_t(f.width);
    for (int x = xBegin; x < xEnd; ++x) {
        glm::dvec2 uv = rowStart + double(x) * perPixel;
        out[x] = glm::vec4(0.0f); // when skipped below (it may hold the last frame's pixel)
        if (job.clampU) {
            if (uv.x < uLo - 0.5 || uv.x > uHi + 0.5) continue;
            uv.x = std::clamp(uv.x, uLo, uHi);
        }
        if (job.clampV) {
            if (uv.y < vLo - 0.5 || uv.y > vHi + 0.5) continue;
            uv.y = std::clamp(uv.y, vLo, vHi);
        }
        // Written so that NaN fails it: a NaN coordinate must never become an index.
        if (!(uv.x > -1.0 && uv.y > -1.0 && uv.x < W && uv.y < H)) continue;
        const int u = int(uv.x + 1.0) - 1, v = int(uv.y + 1.0) - 1; // floor, uv > -1
        const float wu = float(uv.x - u), wv = float(uv.y - v);
        if (u >= 0 && v >= 0 && u + 1 < W && v + 1 < H) { // inside: no bounds checks
            bilinear(out[x], image + std::size_t(v) * std::size_t(W) + std::size_t(u), W, wu, wv);
        } else {
            out[x] = (fetch(job, u, v) * (1 - wu) + fetch(job, u + 1, v) * wu) * (1 - wv) +
                     (fetch(job, u, v + 1) * (1 - wu) + fetch(job, u + 1, v + 1) * wu) * wv;
        }
        if (job.anySurface) {
            const int nu = int(std::lround(uv.x)), nv = int(std::lround(uv.y));
            if (nu >= 0 && nv >= 0 && nu < W && nv < H)
                job.windowDepth[std::size_t(y) * std::size_t(f.width) + std::size_t(x)] =
                    job.hitDepth[std::size_t(nv) * std::size_t(W) + std::size_t(nu)];
        }
    }
}

#ifdef VOLSG_WARP_AVX2
/// warpRow without clamping or depth (the usual frame): the coordinates of four pixels at once
/// in double, the same operations as warpRow's (no fused multiply-add), so the same pixels; a
/// group with a pixel outside the interior of the image goes through warpRow.
[[gnu::target("avx2")]] void warpRowAvx2(const WarpJob& job, int y, const glm::dvec2& rowStart,
                                         const glm::dvec2& perPixel, int xBegin, int xEnd) {
    const Factorisation& f = *job.factorisation;
    const int W = f.W, H = f.H;
    const glm::vec4* image = job.image;
    glm::vec4* out = job.out + std::size_t(y) * std::size_t(f.width);
    const __m256d startU = _mm256_set1_pd(rowStart.x), startV = _mm256_set1_pd(rowStart.y);
    const __m256d stepU = _mm256_set1_pd(perPixel.x), stepV = _mm256_set1_pd(perPixel.y);
    const __m256d one = _mm256_set1_pd(1.0), lane = _mm256_set_pd(3.0, 2.0, 1.0, 0.0);
    const __m256d lowest = _mm256_set1_pd(-1.0);
    const __m256d highU = _mm256_set1_pd(double(W)), highV = _mm256_set1_pd(double(H));
    const __m128i lastU = _mm_set1_epi32(W - 1), lastV = _mm_set1_epi32(H - 1);
    const __m128i minusOne = _mm_set1_epi32(-1);
    int x = xBegin;
    for (; x + 4 <= xEnd; x += 4) {
        const __m256d xs = _mm256_add_pd(_mm256_set1_pd(double(x)), lane); // exact integers
        const __m256d us = _mm256_add_pd(startU, _mm256_mul_pd(xs, stepU));
        const __m256d vs = _mm256_add_pd(startV, _mm256_mul_pd(xs, stepV));
        // warpRow's tests: uv in (-1, W) x (-1, H) (NaN fails), then its interior case
        // u = int(uv + 1) - 1 in [0, W - 2] (and v likewise).
        const __m256d inRange = _mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(us, lowest, _CMP_GT_OQ),
                                                            _mm256_cmp_pd(us, highU, _CMP_LT_OQ)),
                                              _mm256_and_pd(_mm256_cmp_pd(vs, lowest, _CMP_GT_OQ),
                                                            _mm256_cmp_pd(vs, highV, _CMP_LT_OQ)));
        if (_mm256_movemask_pd(inRange) != 0xF) {
            warpRow(job, y, rowStart, perPixel, x, x + 4);
            continue;
        }
        const __m128i iu =
            _mm_sub_epi32(_mm256_cvttpd_epi32(_mm256_add_pd(us, one)), _mm_set1_epi32(1));
        const __m128i iv =
            _mm_sub_epi32(_mm256_cvttpd_epi32(_mm256_add_pd(vs, one)), _mm_set1_epi32(1));
        const __m128i interior =
            _mm_and_si128(_mm_and_si128(_mm_cmpgt_epi32(iu, minusOne), _mm_cmplt_epi32(iu, lastU)),
                          _mm_and_si128(_mm_cmpgt_epi32(iv, minusOne), _mm_cmplt_epi32(iv, lastV)));
        if (_mm_movemask_ps(_mm_castsi128_ps(interior)) != 0xF) {
            warpRow(job, y, rowStart, perPixel, x, x + 4);
            continue;
        }
        const __m128 wus = _mm256_cvtpd_ps(_mm256_sub_pd(us, _mm256_cvtepi32_pd(iu)));
        const __m128 wvs = _mm256_cvtpd_ps(_mm256_sub_pd(vs, _mm256_cvtepi32_pd(iv)));
        alignas(16) int u[4], v[4];
        alignas(16) float wu[4], wv[4];
        _mm_store_si128(reinterpret_cast<__m128i*>(u), iu);
        _mm_store_si128(reinterpret_cast<__m128i*>(v), iv);
        _mm_store_ps(wu, wus);
        _mm_store_ps(wv, wvs);
        for (int i = 0; i < 4; ++i)
            bilinear(out[x + i], image + std::size_t(v[i]) * std::size_t(W) + std::size_t(u[i]), W,
                     wu[i], wv[i]);
    }
    if (x < xEnd) warpRow(job, y, rowStart, perPixel, x, xEnd);
}
#endif

/// The last frame's pixels of row y outside the columns [xBegin, xEnd) the warp writes: image
/// 0; its depth (all of the row's stale part: the warp writes depth only where a Surface hit
/// lies) 1.
void clearStale(const WarpJob& job, int y, int xBegin, int xEnd) {
    const glm::ivec4 r = job.stale.rect;
    if (y < r.y || y >= r.w) return;
    const std::size_t row = std::size_t(y) * std::size_t(job.factorisation->width);
    glm::vec4* out = job.out + row;
    if (xBegin >= xEnd) xBegin = xEnd = r.z; // nothing written: all of it
    std::fill(out + r.x, out + std::max(r.x, std::min(r.z, xBegin)), glm::vec4(0.0f));
    std::fill(out + std::min(r.z, std::max(r.x, xEnd)), out + r.z, glm::vec4(0.0f));
    if (job.stale.depth) std::fill(job.windowDepth + row + r.x, job.windowDepth + row + r.z, 1.0f);
}

} // namespace

glm::ivec4 warpRows(const WarpJob& job, int y0, int y1) {
    const Factorisation& f = *job.factorisation;
    const glm::dvec2 perPixel(f.unwarp[0]); // (u, v) per output pixel along x
    glm::ivec4 drawn(f.width, f.height, 0, 0);
    for (int y = y0; y < y1; ++y) {
        const glm::dvec2 rowStart(f.unwarp * glm::dvec3(0.0, y, 1.0));
        int xBegin = 0, xEnd = 0;
        if (!f.warpValid || !warpSpan(job, rowStart, perPixel, xBegin, xEnd)) {
            clearStale(job, y, 0, 0);
            continue;
        }
        clearStale(job, y, xBegin, xEnd);
        drawn = glm::ivec4(std::min(drawn.x, xBegin), std::min(drawn.y, y), std::max(drawn.z, xEnd),
                           std::max(drawn.w, y + 1));
#ifdef VOLSG_WARP_AVX2
        if (job.simd == SimdLevel::Avx2 && simdLevelAvailable(SimdLevel::Avx2) && !job.clampU &&
            !job.clampV && !job.anySurface) {
            warpRowAvx2(job, y, rowStart, perPixel, xBegin, xEnd);
            continue;
        }
#endif
        warpRow(job, y, rowStart, perPixel, xBegin, xEnd);
    }
    return drawn;
}

} // namespace volsg::shearwarp
