// Stage 6 of a shear-warp frame (FrameStages.h) for pure DVR and two-level frames: bands of
// intermediate rows, each composited over every slice and object by the thread that took it.
//
// band -> slice k (back to front; pure DVR front to back) -> object -> RenderListEntry ->
// voxel row b: each part's voxels splatted into a line (RowSplat), and intermediate row
// b + rowBase composited from line b and line b - 1 with the slice's weights (UnderComposite for
// pure DVR, TwoLevelComposite otherwise).
#include <volsg/shearwarp/FrameStages.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include <volsg/shearwarp/ColumnMask.h>
#include <volsg/shearwarp/PackedVoxel.h>
#include <volsg/shearwarp/SplatRow.h>
#include <volsg/shearwarp/UnderComposite.h>

namespace volsg::shearwarp {

namespace {

/// One band of intermediate rows [r0, r1), as its thread composites it.
struct BandState {
    int r0 = 0, r1 = 0, rows = 0;
    glm::ivec4 touched{0}; ///< the pixels composited: (u0, v0, u1, v1)
    BandScratch* scratch = nullptr;
};

/// Slice k: its shift onto the intermediate image and its depth.
struct SliceState {
    int k = 0;
    int iu0 = 0, iv0 = 0;       ///< integer part of the shift (tu, tv)
    float fu = 0.0f, fv = 0.0f; ///< fractional part: the bilinear weights
    float zSlice = 0.0f;        ///< eye z of the slice, less that of pixel (u, v) at slice 0
    float depth = 0.0f;         ///< window depth of intermediate pixel (0, 0) on the slice
};

/// What the rows of one entry composite into: band, slice and object.
struct RowTarget {
    const BandJob* job;
    BandState* band;
    const SliceState* slice;
    std::int16_t object;
};

/// The voxels of one RenderListEntry whose two intermediate rows (row, row + 1) meet the band:
/// per part [at, end), and where the entry lies on the intermediate image.
struct EntryRows {
    const FrameObject* object = nullptr;
    const std::uint32_t* packed = nullptr;
    const std::uint16_t* values = nullptr;
    int rowBase = 0, colBase = 0; ///< band row and column of voxel (a, b) = (0, 0)
    /// In-piece coordinates of the volume's side faces (256: not in this piece).
    unsigned edgeA0 = 256, edgeA1 = 256, edgeB0 = 256, edgeB1 = 256;
    std::uint32_t at[2] = {0, 0}, end[2] = {0, 0};
    std::uint32_t rowLength[2] = {0, 0}; ///< of each part's last row drawn
};

constexpr int kEmptyLo = std::numeric_limits<int>::max();

/// First index in [begin, end) whose packed b is >= b (voxels sorted by b). (A branch-free
/// halving measured 10% slower frames on the sphere: the predicted branches let loads run ahead.)
std::uint32_t lowerRow(const std::uint32_t* packed, std::uint32_t begin, std::uint32_t end, int b) {
    if (b <= 0) return begin;
    return std::uint32_t(
        std::partition_point(packed + begin, packed + end,
                             [b](std::uint32_t v) { return int(PackedVoxel::b(v)) < b; }) -
        packed);
}

/// The end of voxel row b that starts at `begin` (voxels sorted by b; the row ends by
/// `limit`; empty when the voxel at `begin` is of a later row). Neighbouring rows are mostly about
/// as long: the end is looked for a few voxels either side of `guess` (the previous row's length)
/// before a search.
std::uint32_t rowEnd(const std::uint32_t* packed, std::uint32_t begin, std::uint32_t limit,
                     unsigned b, std::uint32_t guess) {
    constexpr std::uint32_t kNear = 8;
    if (PackedVoxel::b(packed[begin]) != b) return begin;          // this part has no row b
    std::uint32_t e = std::clamp(begin + guess, begin + 1, limit); // the row has a voxel
    if (PackedVoxel::b(packed[e - 1]) == b) {                      // the row reaches e
        for (const std::uint32_t far = std::min(limit, e + kNear); e < far; ++e)
            if (PackedVoxel::b(packed[e]) != b) return e;
        return e == limit ? e : lowerRow(packed, e, limit, int(b) + 1);
    }
    for (const std::uint32_t near = std::max(begin + 1, e > kNear ? e - kNear : 0); e > near;)
        if (PackedVoxel::b(packed[--e - 1]) == b) return e;
    return lowerRow(packed, begin + 1, e, int(b) + 1);
}

/// Per intermediate pixel of row v: a sample at slice k is in front of the opaque surface when
/// zk * k > limit (eye z grows towards the viewer); -inf where no geometry was drawn.
void initLimitRow(const BandJob& job, int v) {
    const Factorisation& f = *job.factorisation;
    const glm::dmat4& P = f.projection;
    float* limit = job.buffers.limit + std::size_t(v) * std::size_t(f.W);
    for (int u = 0; u < f.W; ++u) {
        limit[u] = -std::numeric_limits<float>::infinity();
        const glm::dvec3 px = f.warp * glm::dvec3(u, v, 1.0);
        const int x = int(std::lround(px.x)), y = int(std::lround(px.y));
        if (x < 0 || y < 0 || x >= f.width || y >= f.height) continue;
        const float d =
            job.opaqueWindowDepth[std::size_t(y) * std::size_t(f.width) + std::size_t(x)];
        if (d >= 1.0f) continue;
        const double zOpaque = ((2.0 * d - 1.0) - P[3][2]) / P[2][2];
        limit[u] = float(zOpaque - (f.z0 + f.zu * u + f.zv * v));
    }
}

SliceState sliceState(const BandJob& job, int stepIndex) {
    const Factorisation& f = *job.factorisation;
    SliceState s;
    // Back to front; pure DVR runs front to back for early ray termination.
    s.k = (f.ascending != job.pureDvr) ? stepIndex : f.nc - 1 - stepIndex;
    const double tu = f.ua0 - f.sa * s.k, tv = f.vb0 - f.sb * s.k;
    s.iu0 = int(std::floor(tu));
    s.iv0 = int(std::floor(tv));
    s.fu = float(tu - s.iu0);
    s.fv = float(tv - s.iv0);
    s.zSlice = float(f.zk * s.k);
    s.depth = f.windowDepthOf(f.z0 + f.zk * s.k); // plus zu*u + zv*v per pixel
    return s;
}

/// The entry's drawn parts restricted to the band; false when none of its voxels is.
bool entryRows(const RowTarget& t, const RenderListEntry& e, EntryRows& rows) {
    const FrameObject& f = t.job->objects[t.object];
    const Factorisation& fac = *t.job->factorisation;
    rows.object = &f;
    rows.packed = f.list->packed.data();
    rows.values = f.list->value12.data();
    rows.rowBase = int(e.offset.y) + t.slice->iv0 - t.band->r0;
    rows.colBase = int(e.offset.x) + t.slice->iu0;
    // Data is clamped to the edge up to the box face, half a voxel out, and nothing lies beyond
    // (docs/SCENE-FORMAT.md section 4): the pixel on a face voxel's outer side takes its full value
    // inside the face, none outside.
    rows.edgeA0 = e.offset.x == 0 ? 0u : 256u;
    rows.edgeB0 = e.offset.y == 0 ? 0u : 256u;
    const unsigned lastA = unsigned(fac.na - 1 - int(e.offset.x));
    const unsigned lastB = unsigned(fac.nb - 1 - int(e.offset.y));
    rows.edgeA1 = lastA < 256u ? lastA : 256u;
    rows.edgeB1 = lastB < 256u ? lastB : 256u;
    const std::uint32_t ranges[2][2] = {{e.first, e.last}, {e.firstClipped, e.lastClipped}};
    for (int part = 0; part < 2; ++part) {
        if (!f.parts[part].draw || ranges[part][0] >= ranges[part][1]) continue;
        rows.at[part] = lowerRow(rows.packed, ranges[part][0], ranges[part][1], -1 - rows.rowBase);
        rows.end[part] =
            lowerRow(rows.packed, rows.at[part], ranges[part][1], t.band->rows - rows.rowBase);
        t.band->scratch->voxels += rows.end[part] - rows.at[part];
    }
    return rows.at[0] != rows.end[0] || rows.at[1] != rows.end[1];
}

/// Weight of voxel row b's line in its own intermediate row and in the next.
float ownWeight(const EntryRows& rows, float fv, unsigned b) {
    return b == rows.edgeB0 ? (fv <= 0.5f ? 1.0f : 0.0f) : 1.0f - fv;
}
float nextWeight(const EntryRows& rows, float fv, unsigned b) {
    return b == rows.edgeB1 ? (fv >= 0.5f ? 1.0f : 0.0f) : fv;
}

/// Zeros the runs of columns the line wrote (a memset each, not a store per pixel) and its
/// marks, then empty.
void clearLine(SplatLine* line) {
    if (!line) return;
    if (line->lo < line->hi) {
        int begin = 0, end = 0;
        if (4 * line->voxels >= 3 * (line->hi - line->lo)) // mostly written: one memset
            std::memset(static_cast<void*>(line->pixels + line->lo), 0,
                        std::size_t(line->hi - line->lo) * sizeof(glm::vec4));
        else
            for (columns::Runs runs(line->written, nullptr, line->lo, line->hi);
                 runs.next(begin, end);)
                std::memset(static_cast<void*>(line->pixels + begin), 0,
                            std::size_t(end - begin) * sizeof(glm::vec4));
        std::fill(line->written + (line->lo >> 6), line->written + ((line->hi - 1) >> 6) + 1,
                  columns::Word(0));
    }
    line->lo = kEmptyLo;
    line->hi = 0;
    line->voxels = 0;
}

/// Composites band row `row` from line a (weight wa) and line b (weight wb; either may be
/// absent), then clears line b: every caller is done with it.
void compositeRow(const RowTarget& t, int row, const SplatLine* a, float wa, SplatLine* b,
                  float wb) {
    const BandJob& job = *t.job;
    const int W = job.factorisation->W;
    BandState& band = *t.band;
    const int lo = std::min(a ? a->lo : W, b ? b->lo : W);
    const int hi = std::max(a ? a->hi : 0, b ? b->hi : 0);
    if (row < 0 || row >= band.rows || lo >= hi) {
        clearLine(b);
        return;
    }
    const int v = row + band.r0;
    band.touched = glm::ivec4(std::min(band.touched.x, lo), std::min(band.touched.y, v),
                              std::max(band.touched.z, hi), std::max(band.touched.w, v + 1));
    const std::size_t rowStart = std::size_t(v) * std::size_t(W);
    const glm::vec4* pa = a ? a->pixels : nullptr;
    const glm::vec4* pb = b ? b->pixels : nullptr;
    const FrameBuffers& m = job.buffers;
    const float* limit = job.hasLimit ? m.limit + rowStart : nullptr;
    const float slice = float(t.slice->k);
    if (job.pureDvr) { // the hot path: front to back ("under")
        const UnderRow target{m.global + rowStart,
                              m.pickObject + rowStart,
                              m.pickSlice + rowStart,
                              m.nextOpen + rowStart,
                              limit,
                              m.opaqueCount + v,
                              t.object,
                              slice,
                              t.slice->zSlice};
        // Only the columns the lines wrote: a row of scattered voxels costs its voxels. Rows
        // whose voxels fill most of [lo, hi) take the plain loop (the same pixels).
        const int voxels = std::max(a ? a->voxels : 0, b ? b->voxels : 0);
        if (4 * voxels >= 3 * (hi - lo))
            UnderComposite::composite(job.simd, target, pa, wa, pb, wb, lo, hi);
        else
            UnderComposite::compositeWritten(job.simd, target, pa, wa, a ? a->written : nullptr, pb,
                                             wb, b ? b->written : nullptr, lo, hi);
    } else {
        const Factorisation& f = *job.factorisation;
        const TwoLevelRow target{m.global + rowStart,
                                 m.local + rowStart,
                                 m.localValue + rowStart,
                                 m.localDepth + rowStart,
                                 m.localObject + rowStart,
                                 job.anySurface ? m.hitDepth + rowStart : nullptr,
                                 m.pickObject + rowStart,
                                 m.pickSlice + rowStart,
                                 limit,
                                 job.twoLevelObjects,
                                 job.inter,
                                 t.object,
                                 slice,
                                 t.slice->zSlice,
                                 t.slice->depth,
                                 0.5 * f.projection[2][2],
                                 f.zu,
                                 f.zv * double(v)};
        TwoLevelComposite::composite(job.simd, target, pa, wa, pb, wb, lo, hi);
    }
    clearLine(b);
}

/// Line b: every voxel of row b of both parts, split between its two columns (with early ray
/// termination, those whose four pixels have all stopped are skipped).
void splatRow(const RowTarget& t, EntryRows& rows, unsigned b, SplatLine& line) {
    const BandJob& job = *t.job;
    const BandState& band = *t.band;
    const int W = job.factorisation->W;
    // Only rows that both have stopped pixels can hide a voxel.
    const int rowA = int(b) + rows.rowBase, rowB = rowA + 1;
    const bool inA = rowA >= 0 && rowA < band.rows;
    const bool inB = rowB >= 0 && rowB < band.rows;
    const int* opaqueCount = job.buffers.opaqueCount;
    const bool skipHidden = job.pureDvr && (!inA || opaqueCount[rowA + band.r0] > 0) &&
                            (!inB || opaqueCount[rowB + band.r0] > 0);
    std::int32_t* links = job.buffers.nextOpen;
    SplatRow in{};
    in.packed = rows.packed;
    in.values = rows.values;
    in.colBase = rows.colBase;
    in.fu = t.slice->fu;
    in.edgeA0 = rows.edgeA0;
    in.edgeA1 = rows.edgeA1;
    in.skipHidden = skipHidden;
    in.openA = skipHidden && inA ? links + std::size_t(rowA + band.r0) * std::size_t(W) : nullptr;
    in.openB = skipHidden && inB ? links + std::size_t(rowB + band.r0) * std::size_t(W) : nullptr;
    in.width = W;
    const bool mip = rows.object->source->compositing == ObjectCompositing::MIP;
    SplatSkip skip;
    for (int part = 0; part < 2; ++part) {
        if (rows.at[part] >= rows.end[part]) continue;
        const VoxelTables& tables = rows.object->parts[part].tables;
        in.rgba = tables.rgba.data();
        in.lut2 = tables.lut2.data();
        in.mask = tables.mask;
        in.lookup = mip                                            ? SplatLookup::MipValue
                    : tables.kernel == VoxelTables::Kernel::Direct ? SplatLookup::Direct
                                                                   : SplatLookup::TwoStage;
        // Part 0 writes into the empty line, part 1 adds onto part 0's shares.
        in.fresh = part == 0;
        // Row b ends within 256 voxels (one per a): found once, not tested per voxel;
        // neighbouring rows are mostly as long.
        in.begin = rows.at[part];
        in.end = rowEnd(rows.packed, in.begin, std::min(rows.end[part], in.begin + 256u), b,
                        rows.rowLength[part]);
        rows.rowLength[part] = in.end - in.begin;
        RowSplat::splat(job.simd, in, line, skip);
        rows.at[part] = in.end;
    }
    band.scratch->hidden += skip.hidden;
}

/// The next voxel row of the entry: the smaller b of the parts' next voxels.
unsigned nextRow(const EntryRows& rows) {
    unsigned b = 256;
    for (int part = 0; part < 2; ++part)
        if (rows.at[part] < rows.end[part])
            b = std::min(b, PackedVoxel::b(rows.packed[rows.at[part]]));
    return b;
}

/// Row by row: voxel row b is resampled along a into a line; intermediate row b + rowBase
/// blends line b and line b - 1 with the slice's weights. Lines keep the columns they touched.
void drawEntry(const RowTarget& t, const RenderListEntry& e) {
    EntryRows rows;
    if (!entryRows(t, e, rows)) return;
    ++t.band->scratch->entries;
    const float fv = t.slice->fv;
    BandScratch& scratch = *t.band->scratch;
    SplatLine cur{scratch.lines[0].data(), kEmptyLo, 0, scratch.written[0].data() + 1};
    SplatLine prev{scratch.lines[1].data(), kEmptyLo, 0, scratch.written[1].data() + 1};
    int prevB = -2;
    while (rows.at[0] < rows.end[0] || rows.at[1] < rows.end[1]) {
        const unsigned b = nextRow(rows);
        if (prevB >= 0 && prevB != int(b) - 1) { // a gap: prev's next row alone
            compositeRow(t, prevB + 1 + rows.rowBase, nullptr, 0.0f, &prev,
                         nextWeight(rows, fv, unsigned(prevB)));
            prevB = -2;
        }
        splatRow(t, rows, b, cur);
        compositeRow(t, int(b) + rows.rowBase, &cur, ownWeight(rows, fv, b),
                     prevB >= 0 ? &prev : nullptr,
                     prevB >= 0 ? nextWeight(rows, fv, unsigned(prevB)) : 0.0f);
        std::swap(cur, prev);
        prevB = int(b);
    }
    if (prevB >= 0)
        compositeRow(t, prevB + 1 + rows.rowBase, nullptr, 0.0f, &prev,
                     nextWeight(rows, fv, unsigned(prevB)));
}

/// One object's entries of one slice (when the object draws the slice).
void drawSliceObject(const BandJob& job, BandState& band, const SliceState& slice, int object) {
    const FrameObject& f = job.objects[object];
    const int k = slice.k;
    if (k % f.sliceStep != f.slicePhase) return;
    const std::uint32_t e0 = f.sliceStart[std::size_t(k)];
    const std::uint32_t e1 = f.sliceStart[std::size_t(k) + 1];
    const RowTarget target{&job, &band, &slice, std::int16_t(object)};
    for (std::uint32_t ei = e0; ei < e1; ++ei)
        drawEntry(target, f.list->entries[ei]);
}

/// Band `band`: its rows cleared, every slice and object composited, the runs flushed.
glm::ivec4 compositeBand(const BandJob& job, int band, BandScratch& scratch) {
    const Factorisation& f = *job.factorisation;
    BandState state;
    state.r0 = f.H * band / job.bandCount;
    state.r1 = f.H * (band + 1) / job.bandCount;
    state.rows = state.r1 - state.r0;
    state.touched = glm::ivec4(f.W, f.H, 0, 0);
    state.scratch = &scratch;
    initRows(job, state.r0, state.r1);
    for (int stepIndex = 0; stepIndex < f.nc; ++stepIndex) {
        const SliceState slice = sliceState(job, stepIndex);
        for (int object = 0; object < job.objectCount; ++object)
            drawSliceObject(job, state, slice, object);
    }
    if (job.twoLevel) {
        const std::size_t p0 = std::size_t(state.r0) * std::size_t(f.W);
        const FrameBuffers& m = job.buffers;
        TwoLevelRow rows{};
        rows.global = m.global + p0;
        rows.local = m.local + p0;
        rows.localValue = m.localValue + p0;
        rows.localDepth = m.localDepth + p0;
        rows.localObject = m.localObject + p0;
        rows.hitDepth = job.anySurface ? m.hitDepth + p0 : nullptr;
        rows.objects = job.twoLevelObjects;
        rows.inter = job.inter;
        TwoLevelComposite::flush(rows, 0, state.rows * f.W);
    }
    return state.touched;
}

} // namespace

void initRows(const BandJob& job, int r0, int r1) {
    const int W = job.factorisation->W;
    const FrameBuffers& m = job.buffers;
    const auto p0 = std::ptrdiff_t(r0) * W, p1 = std::ptrdiff_t(r1) * W;
    std::fill(m.global + p0, m.global + p1, glm::vec4(0.0f));
    if (job.twoLevel) {
        std::fill(m.local + p0, m.local + p1, glm::vec4(0.0f));
        std::fill(m.localValue + p0, m.localValue + p1, -1.0f);
        std::fill(m.localDepth + p0, m.localDepth + p1, 1.0f);
        std::fill(m.localObject + p0, m.localObject + p1, std::int16_t(-1));
    }
    if (job.anySurface) std::fill(m.hitDepth + p0, m.hitDepth + p1, 1.0f);
    std::fill(m.pickObject + p0, m.pickObject + p1, std::int16_t(-1));
    std::fill(m.pickSlice + p0, m.pickSlice + p1, 0.0f);
    for (int v = r0; v < r1; ++v) {
        if (job.pureDvr) {
            std::int32_t* open = m.nextOpen + std::size_t(v) * std::size_t(W);
            for (int u = 0; u < W; ++u)
                open[u] = u;
        }
        if (job.hasLimit) initLimitRow(job, v);
    }
}

void compositeBands(const BandJob& job, std::atomic<int>& nextBand, BandScratch& scratch,
                    glm::ivec4* touched) {
    const std::size_t lineLength = std::size_t(job.factorisation->W) + 1;
    scratch.lines[0].assign(lineLength, glm::vec4(0.0f));
    scratch.lines[1].assign(lineLength, glm::vec4(0.0f));
    // One word before the first (read as the carry into word 0) and one after the last.
    const std::size_t words = lineLength / 64 + 3;
    scratch.written[0].assign(words, 0);
    scratch.written[1].assign(words, 0);
    scratch.voxels = 0;
    scratch.hidden = 0;
    scratch.entries = 0;
    for (int band = nextBand++; band < job.bandCount; band = nextBand++)
        touched[band] = compositeBand(job, band, scratch);
}

} // namespace volsg::shearwarp
