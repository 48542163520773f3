// Stage 6 of a shear-warp frame (FrameStages.h) for pure MIP: RTVR's value-sorted voxels, each
// stored into its nearest intermediate pixel from the lowest value shown upwards, so the last
// store is the maximum.
#include <volsg/shearwarp/FrameStages.h>

#include <algorithm>
#include <cmath>

namespace volsg::shearwarp {

std::vector<std::int64_t> valueSortedOffsets(const Factorisation& f, const FrameObject& object) {
    // Nearest intermediate pixel of voxel (a, b) of slice k: a + round(tu), b + round(tv), as
    // one offset per slice; slices left out while interacting have none.
    std::vector<std::int64_t> offset(static_cast<std::size_t>(f.nc));
    for (int k = 0; k < f.nc; ++k)
        offset[std::size_t(k)] = k % object.sliceStep != object.slicePhase
                                     ? kSkipSlice
                                     : std::int64_t(std::lround(f.vb0 - f.sb * k)) * f.W +
                                           std::int64_t(std::lround(f.ua0 - f.sa * k));
    return offset;
}

std::uint32_t firstShownVoxel(const FrameObject& object, const ValueSortedVoxels& sorted) {
    // Values below the first one the table shows cannot be a shown maximum.
    int firstShown = 0;
    while (firstShown < 4096 && !(object.mipTable[std::size_t(firstShown)].w > 0.0f))
        ++firstShown;
    return sorted.start[std::size_t(firstShown)];
}

std::uint64_t drawValueSortedRun(const ValueSortedRun& run, int t) {
    // Each thread a run of the order, into its own buffers: later runs hold larger values, so
    // the merge takes the last thread that wrote a pixel.
    const Factorisation& f = *run.job->factorisation;
    const ValueSortedVoxels& sorted = *run.sorted;
    const std::size_t pixels = std::size_t(f.W) * std::size_t(f.H);
    std::vector<std::uint16_t>& value = run.scratch->mipValue[std::size_t(t)];
    std::vector<std::uint16_t>& slice = run.scratch->mipSlice[std::size_t(t)];
    value.assign(pixels, 0);
    slice.resize(pixels);
    const std::uint32_t begin = run.begin, end = run.end;
    const auto threads = std::uint64_t(run.threads);
    const std::uint32_t from =
        begin + std::uint32_t(std::uint64_t(end - begin) * std::uint64_t(t) / threads);
    const std::uint32_t to =
        begin + std::uint32_t(std::uint64_t(end - begin) * std::uint64_t(t + 1) / threads);
    const int bits[3] = {0, ValueSortedVoxels::kBitsI,
                         ValueSortedVoxels::kBitsI + ValueSortedVoxels::kBitsJ};
    const std::uint32_t masks[3] = {(1u << ValueSortedVoxels::kBitsI) - 1,
                                    (1u << ValueSortedVoxels::kBitsJ) - 1,
                                    (1u << ValueSortedVoxels::kBitsK) - 1};
    const std::uint32_t* position = sorted.position.data();
    const std::int64_t* sliceOffset = run.sliceOffset;
    const int W = f.W;
    std::uint64_t drawn = 0;
    const int shiftA = bits[f.a], shiftB = bits[f.b], shiftC = bits[f.c];
    const std::uint32_t maskA = masks[f.a], maskB = masks[f.b], maskC = masks[f.c];
    int m = int(std::upper_bound(sorted.start.begin(), sorted.start.end(), from) -
                sorted.start.begin()) -
            1;
    for (std::uint32_t i = from; i < to;) {
        while (sorted.start[std::size_t(m) + 1] <= i)
            ++m;
        const std::uint32_t stop = std::min(to, sorted.start[std::size_t(m) + 1]);
        const auto stored = std::uint16_t(m + 1);
        for (; i < stop; ++i) {
            const std::uint32_t pos = position[i];
            const unsigned kc = (pos >> shiftC) & maskC;
            const std::int64_t offset = sliceOffset[kc];
            if (offset == kSkipSlice) continue;
            ++drawn;
            const std::size_t p = std::size_t(std::int64_t((pos >> shiftB) & maskB) * W +
                                              std::int64_t((pos >> shiftA) & maskA) + offset);
            value[p] = stored;
            slice[p] = std::uint16_t(kc);
        }
    }
    return drawn;
}

void mergeValueSortedRows(const ValueSortedRun& run, int t) {
    const Factorisation& f = *run.job->factorisation;
    const FrameBuffers& m = run.job->buffers;
    const FrameObject& object = run.job->objects[run.object];
    const int threads = run.threads;
    const std::size_t p0 = std::size_t(f.H * t / threads) * std::size_t(f.W);
    const std::size_t p1 = std::size_t(f.H * (t + 1) / threads) * std::size_t(f.W);
    for (std::size_t p = p0; p < p1; ++p) {
        int best = 0, bestSlice = 0;
        for (int u = threads - 1; u >= 0 && best == 0; --u)
            if (const std::uint16_t v = run.scratch->mipValue[std::size_t(u)][p]; v != 0) {
                best = v;
                bestSlice = run.scratch->mipSlice[std::size_t(u)][p];
            }
        if (best == 0) continue;
        const glm::vec4 layer = object.mipTable[std::size_t(best - 1)];
        glm::vec4& g = m.global[p];
        if (layer.w >= TwoLevelComposite::kPickAlpha && layer.w > g.w) {
            m.pickObject[p] = std::int16_t(run.object);
            m.pickSlice[p] = float(bestSlice);
        }
        g = glm::max(g, layer);
    }
}

} // namespace volsg::shearwarp
