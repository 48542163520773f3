#pragma once
// volsg-render across MPI processes (sort-last): each renders its share of the opaque shapes
// and its part of the volume; rank 0 composites the parts over the opaque image.
// lib/volsg/sortlast/README.md.

#include <string>

#include <volsg/core/Node.h>
#include <volsg/image/Image.h>
#include <volsg/render/Renderer.h>
#include <volsg/sortlast/MpiCompositor.h>

namespace volsg {
class MpiSession;
}

namespace volsg::cli {

/// An error another process reported already: this one exits with failure and says nothing.
struct ReportedElsewhere {};

struct SortLastReport {
    CompositeMethod method = CompositeMethod::Reduce;
    std::string sceneFile; ///< where the scene's relative file names resolve
    bool timing = false;   ///< rank 0 prints each process's times and the compositing times
    /// With timing: composites timed this many times (median and fastest: on a loaded machine
    /// the fastest is the cost, the median what a frame may see).
    int compositeRepeats = 15;
    /// A paged volume's partial is drawn again as bricks arrive until every process's has
    /// converged, or this long.
    double maxPagingWaitSeconds = 600.0;
    /// Under an error target, each process still reads only its part of an OME-Zarr volume
    /// (loadOwnPart): the frame meets the target, but is not one process's within 1/255.
    bool ownChunksUnderTarget = false;
};

/// Renders `root` across the processes of `mpi`: every process draws its share of the opaque
/// shapes (round robin in traversal order) with depth, and one depth composite gives every
/// process the whole scene's opaque depth and colour; each then draws its part of the Volume's
/// bricks, stopped by that depth, into a partial image; the partials are composited in
/// visibility order onto the opaque image on rank 0. Returns the frame on rank 0 (an empty
/// Image elsewhere). Collective. A failure on any process fails all: the lowest failing rank
/// throws its Error, the others throw ReportedElsewhere.
Image renderSortLast(Renderer& renderer, Node& root, const RenderOptions& options,
                     const MpiSession& mpi, const SortLastReport& report);

/// Collective: when any process `failed`, the lowest failing rank throws Error(why) and the
/// others throw ReportedElsewhere, so all exit with one line on stderr and none is left
/// waiting in a reduction the failed one never joins.
void agreeOnFailure(const MpiSession& mpi, bool failed, const std::string& why);

} // namespace volsg::cli
