#include <volsg/sortlast/MpiCompositor.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <volsg/sortlast/PremultipliedOver.h>

namespace volsg {

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

/// MPI's user function: inout = in op inout, where `in` comes from the lower ranks, in front.
/// The datatype is one pixel (4 floats), so a segment never splits a pixel.
void overOperator(void* in, void* inout, int* length, MPI_Datatype*) {
    compositeOver(static_cast<const float*>(in), static_cast<float*>(inout), std::size_t(*length));
}

void nearestOperator(void* in, void* inout, int* length, MPI_Datatype*) {
    keepNearest(static_cast<const SurfacePixel*>(in), static_cast<SurfacePixel*>(inout),
                std::size_t(*length));
}

} // namespace

double compositeNearestEverywhere(std::vector<SurfacePixel>& pixels, MPI_Comm comm) {
    static_assert(sizeof(SurfacePixel) == 5 * sizeof(float));
    if (pixels.size() > std::size_t(1) << 30)
        throw std::invalid_argument("sort-last: an opaque image has at most 2^30 pixels");
    const auto started = std::chrono::steady_clock::now();
    MPI_Datatype pixel;
    MPI_Type_contiguous(5, MPI_FLOAT, &pixel);
    MPI_Type_commit(&pixel);
    MPI_Op nearest;
    // Not commutative: equal depths keep the lower rank's pixel, the same on every process.
    MPI_Op_create(&nearestOperator, 0, &nearest);
    MPI_Allreduce(MPI_IN_PLACE, pixels.data(), int(pixels.size()), pixel, nearest, comm);
    MPI_Op_free(&nearest);
    MPI_Type_free(&pixel);
    return millisecondsSince(started);
}

std::vector<float> compositeInVisibilityOrder(const std::vector<float>& partial, int position,
                                              MPI_Comm comm, int root, CompositeTiming* timing,
                                              CompositeMethod method) {
    if (partial.size() % 4 != 0 || partial.size() / 4 > std::size_t(1) << 30)
        throw std::invalid_argument("sort-last: a partial image is RGBA, at most 2^30 pixels");
    auto started = std::chrono::steady_clock::now();
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    MPI_Comm ordered;
    MPI_Comm_split(comm, 0, position, &ordered);
    // Where the root landed in the order.
    int orderedRank = 0, orderedRoot = 0;
    MPI_Comm_rank(ordered, &orderedRank);
    if (rank == root) orderedRoot = orderedRank;
    MPI_Bcast(&orderedRoot, 1, MPI_INT, root, comm);
    if (timing) timing->orderMilliseconds = millisecondsSince(started);

    started = std::chrono::steady_clock::now();
    MPI_Datatype pixel;
    MPI_Type_contiguous(4, MPI_FLOAT, &pixel);
    MPI_Type_commit(&pixel);
    MPI_Op over;
    MPI_Op_create(&overOperator, 0, &over);
    std::vector<float> result(rank == root ? partial.size() : 0);
    const std::size_t pixels = partial.size() / 4;
    if (method == CompositeMethod::Reduce) {
        MPI_Reduce(partial.data(), rank == root ? result.data() : nullptr, int(pixels), pixel, over,
                   orderedRoot, ordered);
    } else {
        // Block k of the image goes to ordered rank k, which the gather puts back at k; the
        // image is padded with transparent pixels to whole blocks.
        int size = 1;
        MPI_Comm_size(ordered, &size);
        const std::size_t block = (pixels + std::size_t(size) - 1) / std::size_t(size);
        const std::size_t padded = block * std::size_t(size);
        std::vector<float> padding;
        const float* send = partial.data();
        if (padded != pixels) {
            padding.assign(4 * padded, 0.0f);
            std::copy(partial.begin(), partial.end(), padding.begin());
            send = padding.data();
        }
        std::vector<float> mine(4 * block), gathered(rank == root ? 4 * padded : 0);
        MPI_Reduce_scatter_block(send, mine.data(), int(block), pixel, over, ordered);
        MPI_Gather(mine.data(), int(block), pixel, rank == root ? gathered.data() : nullptr,
                   int(block), pixel, orderedRoot, ordered);
        if (rank == root)
            std::copy(gathered.begin(), gathered.begin() + 4 * pixels, result.begin());
    }
    MPI_Op_free(&over);
    MPI_Type_free(&pixel);
    MPI_Comm_free(&ordered);
    if (timing) timing->reduceMilliseconds = millisecondsSince(started);
    return result;
}

} // namespace volsg
