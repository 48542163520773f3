#pragma once
// Sort-last compositing on MPI: every process's partial image, combined in visibility order
// by one reduction with a non-commutative "over" operator (built only with MPI).

#include <vector>

#include <mpi.h>

#include <volsg/sortlast/NearestSurface.h>

namespace volsg {

/// How the partials are combined (lib/volsg/sortlast/README.md, the cost model).
enum class CompositeMethod {
    /// MPI_Reduce to the root: MPI's tree, each round moving and compositing whole images.
    Reduce,
    /// MPI_Reduce_scatter_block then MPI_Gather: each process composites 1/p of the image
    /// (binary swap / radix-k inside MPI), the root gathers the composited blocks.
    ReduceScatter,
};

/// Times of one composite, milliseconds on a steady clock.
struct CompositeTiming {
    double orderMilliseconds = 0.0;  ///< the communicator ordered by depth (MPI_Comm_split)
    double reduceMilliseconds = 0.0; ///< the reduction with "over" (and the gather)
};

/// Combines the premultiplied RGBA float images `partial` (width * height * 4 floats, the
/// same size on every process of `comm`) front to back: `position` is this process's place in
/// the visibility order (0 in front; the positions of the processes are 0 .. size-1, each
/// once). A communicator ranked by position makes MPI's reduction apply the operator in that
/// order: MPI_Op_create with commute = 0 promises only associativity, so the implementation
/// may group but never reorder. The result (front over ... over back) is returned on `root`
/// (a rank of `comm`); elsewhere it is empty. Collective: every process of `comm` calls it.
std::vector<float> compositeInVisibilityOrder(const std::vector<float>& partial, int position,
                                              MPI_Comm comm, int root,
                                              CompositeTiming* timing = nullptr,
                                              CompositeMethod method = CompositeMethod::Reduce);

/// The depth composite of every process's opaque image (its share of the scene's opaque
/// shapes, drawn with depth), in place and on every process of `comm`: one MPI_Allreduce with
/// keepNearest, so each process then holds the whole scene's opaque depth (which stops its
/// part of the volume) and colour. Collective. Returns the milliseconds it took.
double compositeNearestEverywhere(std::vector<SurfacePixel>& pixels, MPI_Comm comm);

} // namespace volsg
