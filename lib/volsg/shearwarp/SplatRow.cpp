#include <volsg/shearwarp/SplatRow.h>

#include <algorithm>
#include <limits>

#include <volsg/shearwarp/ColumnMask.h>
#include <volsg/shearwarp/Lanes4.h>
#include <volsg/shearwarp/PackedVoxel.h>

namespace volsg {

namespace {

using lanes::loadV4;
using lanes::storeV4;
using lanes::V4;

/// The first column >= c of a row whose pixel is still open (`width`: none; null row: width + 1,
/// stopped everywhere). Stopped pixels link to a later column; the walk halves the paths it
/// follows (Lacroute's opaque-pixel links).
int firstOpen(std::int32_t* open, int c, int width) {
    if (!open) return width + 1;
    while (c < width && open[c] != c) {
        const int next = open[c];
        if (next < width) open[c] = open[next];
        c = next;
    }
    return c;
}

/// The scalar kernel, one function per (fresh line, hidden-voxel skipping, lookup): the
/// invariant branches leave the per-voxel loop and its values are locals kept in registers.
/// A fresh line is written without reloading it: the share a voxel gives its right column waits
/// in `pending` until the next voxel adds its own share (0 + x + y, as accumulating in the line
/// would give) or a gap stores it.
template <bool Fresh, bool SkipHidden, SplatLookup Lookup>
[[gnu::noinline]] void splatScalar(const SplatRow& in, SplatLine& out, SplatSkip& skip) {
    const SplatRow row = in; // locals: through `in` the pointers were reloaded after each store
    const std::uint32_t* const packed = row.packed;
    glm::vec4* const line = out.pixels;
    const int colBase = row.colBase;
    const unsigned edgeA0 = row.edgeA0, edgeA1 = row.edgeA1;
    const float edgeA0Weight = row.fu <= 0.5f ? 1.0f : 0.0f;
    const float edgeA1Weight = row.fu >= 0.5f ? 1.0f : 0.0f;
    const V4 left = V4{} + (1.0f - row.fu), right = V4{} + row.fu; // broadcast
    const V4 edge0 = V4{} + edgeA0Weight, edge1 = V4{} + edgeA1Weight;
    // Voxels with innerLo <= a <= innerLo + innerSpan are no face's.
    const int lowest = edgeA0 == 0 ? 1 : 0;
    const int highest = edgeA1 < 256u ? int(edgeA1) - 1 : 255;
    const unsigned innerLo = highest >= lowest ? unsigned(lowest) : 512u;
    const unsigned innerSpan = highest >= lowest ? unsigned(highest - lowest) : 0u;
    int hiddenBefore = skip.hiddenBefore, visibleThrough = skip.visibleThrough;
    std::uint64_t hidden = skip.hidden;
    V4 pending{};
    int pendingCol = -2;
    int firstCol = std::numeric_limits<int>::max(), lastCol = -1;
    columns::Word* const written = out.written;
    int marked = 0;
    for (std::uint32_t i = row.begin; i < row.end; ++i) {
        const std::uint32_t v = packed[i];
        const unsigned va = PackedVoxel::a(v);
        const int col = int(va) + colBase;
        if constexpr (SkipHidden) {   // before the lookup: a hidden voxel costs its position only
            if (col < hiddenBefore) { // so are the next ones below hiddenBefore (sorted by a)
                std::uint32_t j = i + 1;
                while (j < row.end && int(PackedVoxel::a(packed[j])) + colBase < hiddenBefore)
                    ++j;
                hidden += j - i;
                i = j - 1;
                continue;
            }
            if (col > visibleThrough) {
                const std::int32_t* openA = row.openA;
                const std::int32_t* openB = row.openB;
                const bool anyOpen = (openA && (openA[col] == col || openA[col + 1] == col + 1)) ||
                                     (openB && (openB[col] == col || openB[col + 1] == col + 1));
                if (!anyOpen) {
                    ++hidden;
                    hiddenBefore = std::min(firstOpen(row.openA, col, row.width),
                                            firstOpen(row.openB, col, row.width)) -
                                   1;
                    continue;
                }
                visibleThrough = col;
            }
        }
        V4 colour;
        if constexpr (Lookup == SplatLookup::MipValue)
            colour = V4{float(row.values[i]) * (1.0f / 4095.0f), 0.0f, 0.0f, 1.0f};
        else if constexpr (Lookup == SplatLookup::Direct)
            colour = loadV4(row.rgba[PackedVoxel::attributes16(v) & row.mask]);
        else
            colour =
                loadV4(row.rgba[(PackedVoxel::second4(v) << 8) | row.lut2[PackedVoxel::main12(v)]]);
        // A transparent voxel adds zero shares: only the accumulating part and hidden-voxel
        // skipping (its range must not grow) need to leave it out.
        if ((!Fresh || SkipHidden) && colour[3] <= 0.0f) continue;
        columns::mark(written, col);
        ++marked;
        // Its shares of the two columns; face voxels (only a row's first or last: sorted by a)
        // weigh their own.
        V4 share0 = left * colour, share1 = right * colour;
        if (va - innerLo > innerSpan) [[unlikely]] {
            if (va == edgeA0) share0 = edge0 * colour;
            if (va == edgeA1) share1 = edge1 * colour;
        }
        if constexpr (Fresh) {
            if (col == pendingCol) {
                storeV4(line[col], pending + share0);
            } else {
                if (pendingCol >= 0)
                    storeV4(line[pendingCol], pending);
                else
                    firstCol = col; // ascending: the row's first
                storeV4(line[col], share0);
            }
            pending = share1;
            pendingCol = col + 1;
        } else {
            firstCol = std::min(firstCol, col);
            lastCol = col;
            storeV4(line[col], loadV4(line[col]) + share0);
            storeV4(line[col + 1], loadV4(line[col + 1]) + share1);
        }
    }
    out.voxels += marked;
    if (pendingCol >= 0) {
        storeV4(line[pendingCol], pending);
        lastCol = pendingCol - 1;
    }
    if (lastCol >= 0) {
        out.lo = std::min(out.lo, firstCol);
        out.hi = std::max(out.hi, lastCol + 2);
    }
    skip.hiddenBefore = hiddenBefore;
    skip.visibleThrough = visibleThrough;
    skip.hidden = hidden;
}

template <bool Fresh, bool SkipHidden>
void dispatchLookup(const SplatRow& row, SplatLine& line, SplatSkip& skip) {
    switch (row.lookup) {
    case SplatLookup::MipValue:
        splatScalar<Fresh, SkipHidden, SplatLookup::MipValue>(row, line, skip);
        return;
    case SplatLookup::Direct:
        splatScalar<Fresh, SkipHidden, SplatLookup::Direct>(row, line, skip);
        return;
    case SplatLookup::TwoStage:
        splatScalar<Fresh, SkipHidden, SplatLookup::TwoStage>(row, line, skip);
        return;
    }
}

} // namespace

void RowSplat::splat(SimdLevel level, const SplatRow& row, SplatLine& line, SplatSkip& skip) {
    (void)level; // Scalar and Avx2 alike: the scalar kernel (see the header)
    if (row.fresh) {
        if (row.skipHidden)
            dispatchLookup<true, true>(row, line, skip);
        else
            dispatchLookup<true, false>(row, line, skip);
    } else {
        if (row.skipHidden)
            dispatchLookup<false, true>(row, line, skip);
        else
            dispatchLookup<false, false>(row, line, skip);
    }
}

} // namespace volsg
