#include <volsg/shearwarp/TwoLevelComposite.h>

#include <algorithm>
#include <cstddef>

#include <volsg/shearwarp/Lanes4.h>

namespace volsg {

namespace {

using lanes::loadV4;
using lanes::toVec4;
using lanes::V4;

constexpr float kSurfaceAlpha = TwoLevelComposite::kSurfaceAlpha;
constexpr float kSurfaceDepthAlpha = TwoLevelComposite::kSurfaceDepthAlpha;

/// The MIP table at a value in [0, 1], linearly interpolated between its 4096 entries.
glm::vec4 mipLookup(const glm::vec4* table, float value) {
    const float x = std::clamp(value, 0.0f, 1.0f) * 4095.0f;
    const int i = std::min(int(x), 4094);
    const float f = x - float(i);
    return table[std::size_t(i)] * (1.0f - f) + table[std::size_t(i) + 1] * f;
}

/// Pixel c's run merged into the global buffer, then emptied.
void flushPixel(const TwoLevelRow& row, int c) {
    const int oi = row.localObject[c];
    if (oi < 0) return;
    const TwoLevelObject& o = row.objects[oi];
    glm::vec4 layer = row.local[c];
    if (o.compositing == ObjectCompositing::MIP)
        layer =
            row.localValue[c] >= 0.0f ? mipLookup(o.mipTable, row.localValue[c]) : glm::vec4(0.0f);
    if (o.compositing == ObjectCompositing::Surface && layer.w >= kSurfaceAlpha) {
        layer = glm::vec4(glm::vec3(layer) / layer.w, 1.0f);
        if (row.localDepth[c] < 1.0f) row.hitDepth[c] = row.localDepth[c];
    }
    glm::vec4& g = row.global[c];
    if (row.inter == InterObjectCompositing::DVR)
        g = layer + (1.0f - layer.w) * g;
    else
        g = glm::max(g, layer);
    row.localObject[c] = -1;
    row.local[c] = glm::vec4(0.0f);
    row.localValue[c] = -1.0f;
    row.localDepth[c] = 1.0f;
}

/// One sample of the row's object at pixel c (alpha > 0).
template <ObjectCompositing Mode, bool HasLimit>
inline void compositePixel(const TwoLevelRow& row, int c, const glm::vec4& sample) {
    if (HasLimit && !(row.zSlice > row.limit[c])) return; // behind opaque geometry
    if (row.localObject[c] != row.object) {
        flushPixel(row, c);
        row.localObject[c] = row.object;
    }
    if constexpr (Mode == ObjectCompositing::MIP) {
        if (sample.x > row.localValue[c]) {
            row.localValue[c] = sample.x;
            if (mipLookup(row.objects[row.object].mipTable, sample.x).w >=
                TwoLevelComposite::kPickAlpha) {
                row.pickObject[c] = row.object;
                row.pickSlice[c] = row.slice;
            }
        }
        return;
    }
    // DVR and Surface: accumulated within the run; a Surface run is drawn opaque at the flush
    // when its alpha reaches kSurfaceAlpha, at the depth of its front-most dense sample.
    row.local[c] = sample + (1.0f - sample.w) * row.local[c];
    if (sample.w >= TwoLevelComposite::kPickAlpha) {
        row.pickObject[c] = row.object;
        row.pickSlice[c] = row.slice;
    }
    if constexpr (Mode == ObjectCompositing::Surface)
        if (sample.w >= kSurfaceDepthAlpha)
            row.localDepth[c] =
                row.sliceDepth + float(row.depthScale * (row.zu * double(c) + row.zvRow));
}

/// The scalar kernel, one function per (compositing, lines present, opaque limit).
template <ObjectCompositing Mode, bool HasA, bool HasB, bool HasLimit>
[[gnu::noinline]] void twoLevelScalar(const TwoLevelRow& in, const glm::vec4* a, float wa,
                                      const glm::vec4* b, float wb, int lo, int hi) {
    const TwoLevelRow row = in; // locals, not reloaded after every store
    for (int c = lo; c < hi; ++c) {
        // The resampled sample, as glm computes the sum of the weighted lines.
        V4 sample;
        if constexpr (HasA && HasB)
            sample = wa * loadV4(a[c]) + wb * loadV4(b[c]);
        else if constexpr (HasA)
            sample = wa * loadV4(a[c]);
        else
            sample = wb * loadV4(b[c]);
        if (sample[3] <= 0.0f) continue;
        compositePixel<Mode, HasLimit>(row, c, toVec4(sample));
    }
}

template <ObjectCompositing Mode, bool HasA, bool HasB>
void dispatchLimit(const TwoLevelRow& row, const glm::vec4* a, float wa, const glm::vec4* b,
                   float wb, int lo, int hi) {
    if (row.limit)
        twoLevelScalar<Mode, HasA, HasB, true>(row, a, wa, b, wb, lo, hi);
    else
        twoLevelScalar<Mode, HasA, HasB, false>(row, a, wa, b, wb, lo, hi);
}

template <ObjectCompositing Mode>
void dispatchLines(const TwoLevelRow& row, const glm::vec4* a, float wa, const glm::vec4* b,
                   float wb, int lo, int hi) {
    if (a && b)
        dispatchLimit<Mode, true, true>(row, a, wa, b, wb, lo, hi);
    else if (a)
        dispatchLimit<Mode, true, false>(row, a, wa, b, wb, lo, hi);
    else if (b)
        dispatchLimit<Mode, false, true>(row, a, wa, b, wb, lo, hi);
}

} // namespace

void TwoLevelComposite::composite(SimdLevel level, const TwoLevelRow& row, const glm::vec4* a,
                                  float wa, const glm::vec4* b, float wb, int lo, int hi) {
    (void)level; // every level runs the scalar kernel
    switch (row.objects[row.object].compositing) {
    case ObjectCompositing::DVR:
        dispatchLines<ObjectCompositing::DVR>(row, a, wa, b, wb, lo, hi);
        return;
    case ObjectCompositing::MIP:
        dispatchLines<ObjectCompositing::MIP>(row, a, wa, b, wb, lo, hi);
        return;
    case ObjectCompositing::Surface:
        dispatchLines<ObjectCompositing::Surface>(row, a, wa, b, wb, lo, hi);
        return;
    }
}

void TwoLevelComposite::flush(const TwoLevelRow& row, int lo, int hi) {
    for (int c = lo; c < hi; ++c)
        flushPixel(row, c);
}

} // namespace volsg
