#include "SortLastRender.h"
#include "OwnPartLoading.h"
#include "VolumeReport.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <thread>
#include <vector>

#include <mpi.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/core/Error.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Volume.h>
#include <volsg/sortlast/MpiCompositor.h>
#include <volsg/sortlast/MpiSession.h>
#include <volsg/sortlast/PremultipliedOver.h>

namespace volsg::cli {

namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// What one process did, gathered on rank 0 for --mpi-timing.
struct RankTimes {
    double opaqueMilliseconds = 0.0;         ///< its share of the opaque shapes, read back
    double opaqueShapes = 0.0;               ///< the opaque shapes it drew (of the scene's)
    double depthCompositeMilliseconds = 0.0; ///< the opaque images' depth composite
    double partialMilliseconds = 0.0;        ///< the partial image, read back
    double voxels = 0.0;                     ///< voxels its part spans
    double position = 0.0;                   ///< its place front to back
    double readMilliseconds = 0.0;           ///< reading its own part (0: the scene read it all)
    double voxelsRead = 0.0;                 ///< voxels of its own part and ghost read
    // A paged volume: what this process paged in, over the frames it took to converge.
    double pagedBricks = 0.0;
    double pagedMegabytes = 0.0;
    double hostMegabytes = 0.0; ///< its bricks in host memory at the end
    double frames = 1.0;
    double paged = 0.0; ///< 1: the Volume is paged from its pyramid
};

/// The whole volume's natural range from the parts' own (VolumeGrid::naturalRange: 16-bit data
/// spanning no range takes its type's).
glm::dvec2 agreedRange(const OwnPartLoad& load) {
    double lo = load.ownRange.x, hi = load.ownRange.y;
    MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (load.type == VoxelType::Float) return lo <= hi ? glm::dvec2(lo, hi) : glm::dvec2(0.0);
    if (lo < hi) return {lo, hi};
    return load.type == VoxelType::UShort ? glm::dvec2(0.0, 65535.0)
                                          : glm::dvec2(-32768.0, 32767.0);
}

/// VolumePartition::fromSmallest: the values of the process with the smallest key.
void fromSmallest(double key, double* values, int count) {
    struct {
        double key;
        int rank;
    } mine{std::isnan(key) ? HUGE_VAL : key, 0}, smallest{};
    MPI_Comm_rank(MPI_COMM_WORLD, &mine.rank);
    MPI_Allreduce(&mine, &smallest, 1, MPI_DOUBLE_INT, MPI_MINLOC, MPI_COMM_WORLD);
    MPI_Bcast(values, count, MPI_DOUBLE, smallest.rank, MPI_COMM_WORLD);
}

/// Collective: whether any process's paged volume still waits for bricks, and every process
/// is within the wait (rank 0's clock decides, so all stop together).
bool pagingGoesOn(Node& root, double waitedSeconds, double maxSeconds) {
    int state[2] = {volumesRefining(root) ? 1 : 0, waitedSeconds < maxSeconds ? 1 : 0};
    MPI_Bcast(&state[1], 1, MPI_INT, 0, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &state[0], 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return state[0] == 1 && state[1] == 1;
}

/// The one Volume a sort-last render splits; null when the scene has none (the partials are
/// then empty and rank 0's opaque image is the frame). Throws Error for what it cannot split.
Volume* splitVolumeOf(Node& root, int processes) {
    if (!findAll(root, ShearWarpVolume::classType(), true).empty() && processes > 1)
        throw Error("rendering across processes splits a Volume node; this scene draws a "
                    "ShearWarpVolume, which renders in one process only");
    const std::vector<Node*> volumes = findAll(root, Volume::classType(), true);
    if (volumes.size() > 1 && processes > 1)
        throw Error("rendering across processes splits one Volume node; this scene has " +
                    std::to_string(volumes.size()));
    return volumes.empty() ? nullptr : static_cast<Volume*>(volumes.front());
}

std::vector<float> pixelsOf(const Image& image) {
    const float* first = &image.pixels.data()->x;
    return std::vector<float>(first, first + 4 * image.pixels.size());
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

void printTiming(const std::vector<RankTimes>& ranks, const std::vector<CompositeTiming>& runs,
                 double finalOverMilliseconds, const Image& frame, const OwnPartLoad& load,
                 CompositeMethod method) {
    std::printf("sort-last: %d processes, %d x %d pixels (%.1f MB of RGBA float per partial)\n",
                int(ranks.size()), frame.width, frame.height,
                16.0 * double(frame.width) * double(frame.height) / 1e6);
    if (load.paged)
        std::printf("  each process paged in only the bricks of its part (OME-Zarr pyramid)\n");
    else if (load.loaded)
        std::printf("  each process read only its part and %d ghost voxels (OME-Zarr chunks)\n",
                    kOwnPartGhost);
    else if (ranks.size() > 1)
        std::printf("  every process read the whole volume: %s\n", load.whyNot.c_str());
    std::printf("  rank  position  voxels  read voxels  read ms  partial ms  opaque ms  "
                "opaque shapes  depth composite ms\n");
    for (std::size_t r = 0; r < ranks.size(); ++r)
        std::printf("  %4zu  %8d  %6.3gM  %10.3gM  %7.1f  %10.1f  %9.1f  %13d  %18.2f\n", r,
                    int(ranks[r].position), ranks[r].voxels / 1e6, ranks[r].voxelsRead / 1e6,
                    ranks[r].readMilliseconds, ranks[r].partialMilliseconds,
                    ranks[r].opaqueMilliseconds, int(ranks[r].opaqueShapes),
                    ranks[r].depthCompositeMilliseconds);
    if (ranks.front().paged > 0.0) {
        std::printf("  rank  frames  bricks paged in  MB paged in  MB held\n");
        for (std::size_t r = 0; r < ranks.size(); ++r)
            std::printf("  %4zu  %6d  %15d  %11.2f  %7.2f\n", r, int(ranks[r].frames),
                        int(ranks[r].pagedBricks), ranks[r].pagedMegabytes, ranks[r].hostMegabytes);
    }
    std::vector<double> order, reduce, total;
    for (const CompositeTiming& t : runs) {
        order.push_back(t.orderMilliseconds);
        reduce.push_back(t.reduceMilliseconds);
        total.push_back(t.orderMilliseconds + t.reduceMilliseconds);
    }
    std::printf("  composite by %s (median of %zu): order %.2f ms, reduce %.2f ms, total %.2f ms "
                "(fastest %.2f ms); over the opaque image %.2f ms\n",
                method == CompositeMethod::Reduce ? "reduce" : "reduce-scatter and gather",
                runs.size(), median(order), median(reduce), median(total),
                *std::min_element(total.begin(), total.end()), finalOverMilliseconds);
}

} // namespace

void agreeOnFailure(const MpiSession& mpi, bool failed, const std::string& why) {
    int reporter = failed ? mpi.rank() : mpi.size();
    MPI_Allreduce(MPI_IN_PLACE, &reporter, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (reporter == mpi.size()) return;
    if (reporter == mpi.rank()) throw Error(why);
    throw ReportedElsewhere{};
}

Image renderSortLast(Renderer& renderer, Node& root, const RenderOptions& options,
                     const MpiSession& mpi, const SortLastReport& report) {
    const int rank = mpi.rank(), size = mpi.size();
    RankTimes mine;
    Image opaque, partial;
    std::string why;
    Volume* volume = nullptr;
    OwnPartLoad load;
    try {
        volume = splitVolumeOf(root, size);
        if (volume && size > 1)
            load = loadOwnPart(root, report.sceneFile, rank, size, report.ownChunksUnderTarget);
    } catch (const std::exception& e) {
        why = e.what();
    }
    agreeOnFailure(mpi, !why.empty(), why);
    mine.readMilliseconds = load.milliseconds;
    mine.voxelsRead = load.voxelsRead;
    // Every process loaded its part, or none did (the same scene and options decide it).
    if (load.loaded && load.needsRange) useDataRange(root, agreedRange(load));

    // The background and the opaque shapes, what the volume parts composite onto: each
    // process draws its share of the shapes with depth, and the depth composite gives every
    // process the whole (its depth stops that process's part of the volume).
    std::vector<float> opaqueDepth;
    int drewOpaque = 0;
    try {
        RenderOptions opaqueOptions = options;
        opaqueOptions.opaqueOnly = true;
        opaqueOptions.shapeShareIndex = rank;
        opaqueOptions.shapeShareCount = size;
        const auto started = Clock::now();
        renderer.render(root, opaqueOptions, opaque);
        opaqueDepth = renderer.readWindowDepth();
        mine.opaqueMilliseconds = millisecondsSince(started);
        const RenderStats& stats = renderer.stats();
        mine.opaqueShapes = double(stats.opaqueShapes - stats.sharedOutShapes);
        drewOpaque = stats.shapeDraws > 0 ? 1 : 0;
    } catch (const std::exception& e) {
        why = e.what();
    }
    agreeOnFailure(mpi, !why.empty(), why);
    if (report.timing) MPI_Barrier(MPI_COMM_WORLD);
    std::vector<SurfacePixel> surfaces = surfacePixels(opaque.pixels, opaqueDepth);
    mine.depthCompositeMilliseconds = compositeNearestEverywhere(surfaces, MPI_COMM_WORLD);
    splitSurfacePixels(surfaces, opaque.pixels, opaqueDepth);
    // Volumes treat a frame with opaque draws apart (the error model's target halves), so the
    // partials are told whether any process drew one, as one process would know.
    MPI_Allreduce(MPI_IN_PLACE, &drewOpaque, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (!drewOpaque) opaqueDepth.clear();

    try {
        RenderOptions partialOptions = options;
        partialOptions.volumePartial = true;
        partialOptions.partition = {rank, size, load.loaded, fromSmallest};
        partialOptions.opaqueDepth = &opaqueDepth;
        auto started = Clock::now();
        partial = renderer.render(root, partialOptions);
        mine.partialMilliseconds = millisecondsSince(started);
        // A paged volume draws what is loaded and asks for the rest: draw again until every
        // process's part has converged (all draw the same number of frames, as the partials'
        // plane spacing is agreed in each).
        const auto waitStarted = Clock::now();
        while (pagingGoesOn(root, millisecondsSince(waitStarted) / 1000.0,
                            report.maxPagingWaitSeconds)) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            started = Clock::now();
            partial = renderer.render(root, partialOptions);
            mine.partialMilliseconds = millisecondsSince(started);
            ++mine.frames;
        }
        if (volume) {
            const PagingStats& paging = volume->slicingStats().paging;
            mine.paged = paging.paged ? 1.0 : 0.0;
            mine.pagedBricks = double(paging.bricksLoaded);
            mine.pagedMegabytes = double(paging.bytesLoaded) / 1e6;
            mine.hostMegabytes = double(paging.hostBytes) / 1e6;
        }
        mine.position = volume ? volume->slicingStats().partPosition : rank;
        if (volume) {
            const SlicingStats& stats = volume->slicingStats();
            const glm::ivec3 span = stats.partLastVoxel - stats.partFirstVoxel + 1;
            mine.voxels = double(span.x) * double(span.y) * double(span.z);
        }
    } catch (const std::exception& e) {
        why = e.what();
    }
    agreeOnFailure(mpi, !why.empty(), why);

    // The positions are a permutation of the ranks when every process drew its part of the
    // Volume; when none drew it (under a Switch, say) every partial is empty and any order is.
    std::vector<RankTimes> all(static_cast<std::size_t>(size));
    constexpr int kTimes = int(sizeof(RankTimes) / sizeof(double));
    MPI_Allgather(&mine, kTimes, MPI_DOUBLE, all.data(), kTimes, MPI_DOUBLE, MPI_COMM_WORLD);
    std::vector<char> seen(static_cast<std::size_t>(size), 0);
    bool permutation = true;
    for (const RankTimes& t : all) {
        const int p = int(t.position);
        if (p < 0 || p >= size || seen[std::size_t(p)]) permutation = false;
        if (p >= 0 && p < size) seen[std::size_t(p)] = 1;
    }
    const int position = permutation ? int(mine.position) : rank;

    const std::vector<float> pixels = pixelsOf(partial);
    std::vector<CompositeTiming> runs(1);
    // Timed, every composite starts together: the wait for the slowest renderer (load
    // imbalance) is not compositing.
    if (report.timing) MPI_Barrier(MPI_COMM_WORLD);
    std::vector<float> volumePart =
        compositeInVisibilityOrder(pixels, position, MPI_COMM_WORLD, 0, &runs[0], report.method);
    for (int k = 1; report.timing && k < report.compositeRepeats; ++k) {
        runs.emplace_back();
        MPI_Barrier(MPI_COMM_WORLD);
        compositeInVisibilityOrder(pixels, position, MPI_COMM_WORLD, 0, &runs.back(),
                                   report.method);
    }
    if (rank != 0) return Image();

    const auto started = Clock::now();
    compositeOver(volumePart.data(), &opaque.pixels.data()->x, opaque.pixels.size());
    const double finalOver = millisecondsSince(started);
    if (report.timing) printTiming(all, runs, finalOver, opaque, load, report.method);
    return opaque;
}

} // namespace volsg::cli
