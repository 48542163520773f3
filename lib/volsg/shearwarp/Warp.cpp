// Stage 7 of a shear-warp frame (FrameStages.h): every output pixel samples the intermediate
// image bilinearly (and Surface depth at its nearest intermediate pixel).
#include <volsg/shearwarp/FrameStages.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include <volsg/shearwarp/Lanes4.h>

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
            const glm::vec4* p = image + std::size_t(v) * std::size_t(W) + std::size_t(u);
            storeV4(out[x], (loadV4(p[0]) * (1 - wu) + loadV4(p[1]) * wu) * (1 - wv) +
                                (loadV4(p[W]) * (1 - wu) + loadV4(p[W + 1]) * wu) * wv);
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
        warpRow(job, y, rowStart, perPixel, xBegin, xEnd);
    }
    return drawn;
}

} // namespace volsg::shearwarp
