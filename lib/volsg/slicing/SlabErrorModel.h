#pragma once
// The error model of the Volume slicer: how far its image is from the rendering model's
// (docs/SCENE-FORMAT.md section 4) for a given slab quadrature (plane spacing, samples per
// plane, pre-integration, peak sampling), and what the volume's transfer functions and data ask
// of the sampling. lib/volsg/slicing/README.md ("Error targets") has its validation.
//
// How it predicts: the error of slab sampling is that of a quadrature of the classified signal
// tau(v(s)), C(v(s)) along each ray, which depends on the transfer function's slopes and
// features composed with the data's variation along the view, on the slab length, opacity
// correction and the tables' quantisation. Rather than bounding that analytically (bounds on
// spikes and steps are loose by orders of magnitude), the model evaluates it on a sample of
// the volume's own rays: rays through the box around some of 96 directions (a view takes the
// nearest three, SlicingQuality's modelDirectionsOf), each integrated twice on the CPU, once
// finely (linear v segments, exact tau and colour integrals: the model) and once with the
// slicer's arithmetic (its planes, slabs, parts, opacity correction, its 4096-entry transfer
// table and 256 x 256 pre-integration table, tag cells, MIP's voxel-centre crossings and peak
// refinement). The per-ray RMSE scales to an image by the share of pixels the box covers.

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/slicing/PreIntegrationTable.h>
#include <volsg/slicing/TransferTable.h>
#include <volsg/volume/VolumeModel.h>

namespace volsg {

class EmptyCells;

/// A slab quadrature as the slicer draws it, with lengths in the volume's L0.
struct SlabQuadrature {
    double planeSpacingL0 = 0.5; ///< distance between planes along the view, in L0
    int samplesPerPlane = 1;
    bool preIntegrated = false; ///< DVR
    bool peaks = true;          ///< MIP, MINIP: the voxel-centre crossings (mipPeaks)
    bool refinePeaks = true;    ///< MIP, MINIP without peaks (refinePeaks)
    double samplesPerL0() const { return double(samplesPerPlane) / planeSpacingL0; }
    bool operator<(const SlabQuadrature& o) const;
};

/// What the transfer functions and the data ask of the sampling (reported, and where the
/// search for settings starts).
struct SignalNeeds {
    double narrowestFeature = 1.0; ///< in v: the narrowest linear piece of an opacity feature
    double steepestSlope = 0.0;    ///< of tau L0 over v
    double gradientPerL0 = 0.0;    ///< |grad v| L0 at the 90th percentile of visible voxels
    double visibleFraction = 0.0;  ///< of the sampled voxels that a table gives opacity
    /// Samples per L0 at which the narrowest feature, crossed at the 90th-percentile rate,
    /// gets two samples: 2 gradientPerL0 / narrowestFeature.
    double samplesPerL0 = 0.0;
};

/// Which grid a paged frame draws where: a lattice of cells over the model's box, each naming
/// one of `grids` (a level of the pyramid held whole; null: the model's own grid, which stands
/// for any level it cannot see).
struct GridCut {
    glm::dvec3 boxMin{0.0}, cellSize{1.0}; ///< local units
    glm::ivec3 cells{0};
    std::vector<std::uint8_t> cellGrid; ///< per cell (x fastest), an index into grids
    std::vector<const VolumeGrid*> grids;
    std::uint64_t key = 0; ///< the cut's identity, for the cache
    std::size_t indexOf(const glm::ivec3& c) const {
        return std::size_t(c.x) +
               std::size_t(cells.x) * (std::size_t(c.y) + std::size_t(cells.y) * std::size_t(c.z));
    }
};

/// A box of the volume (local coordinates) the model's rays are confined to.
struct ModelRegion {
    glm::dvec3 min{0.0}, max{0.0};
};

class SlabErrorModel {
public:
    static constexpr int kDirections = 96;

    /// Takes what the model needs of a volume: its data, tags, transfer functions and mode.
    /// Cheap (tables and a sample of voxels); rays are cast per direction when first asked.
    /// With a `region` (a sort-last process holding only its part: lib/volsg/sortlast), the
    /// rays cross only that box, their slabs ending at its faces as the process's do, and the
    /// data's needs are measured there; the planes stay laid over the whole box.
    /// `opacityUnit` (local units): the length the transfer functions' opacity is per, when
    /// not the grid's own L0 (a paged volume's stand-in: level 0's voxel).
    /// `measuredCells`: the cells of volume.data as measured already (EmptyCells::measure), or
    /// null to measure them when a DVR ray set first needs them.
    explicit SlabErrorModel(const RayCastVolume& volume, std::optional<ModelRegion> region = {},
                            double opacityUnit = 0.0, const EmptyCells* measuredCells = nullptr);
    ~SlabErrorModel();

    const SignalNeeds& needs() const { return needs_; }
    VolumeRenderMode mode() const { return mode_; }
    double L0() const { return L0_; }
    /// Whether DVR rays skip the cells that cannot emit (default true; the same predictions
    /// either way, EmptyRunsTest). Set before the first prediction.
    void setSkipsEmptyCells(bool skips);
    /// Whether tagged transfer functions apply (the slicer's general, tag-cell path).
    bool tagged() const { return tagged_; }

    /// The direction (of kDirections over the half sphere, about 15 degrees apart) nearest to
    /// a local view direction, either way along it; `wide`: its ray set spread as a
    /// perspective view's rays (index + kDirections).
    static int nearestDirection(const glm::dvec3& localDirection, bool wide = false);
    /// The kNearDirections narrow directions nearest to a local view direction, nearest first.
    /// A view is predicted along all of them (SlicingQuality): the error of a spiky transfer
    /// function moves by up to 2.8x between neighbouring directions, with how the rays meet
    /// the grid, and one direction's value stood for the view by luck.
    static constexpr int kNearDirections = 3;
    static std::array<int, kNearDirections> nearestDirections(const glm::dvec3& localDirection);
    /// The RMSE per channel (0..1 units) over the rays through the box along direction `dir`
    /// (nearestDirection) drawn with quadrature `q`, against the model. Cached.
    double rayRmse(int dir, const SlabQuadrature& q);
    /// rayRmse(dir, q) if it is at most `limit`; otherwise some value above `limit` and at most
    /// the RMSE, found after as few rays as prove it (the rays are visited in a stratified
    /// order, so a quadrature far from the target is rejected after a small share of them).
    double rayRmseUpTo(int dir, const SlabQuadrature& q, double limit);
    /// The same for shear-warp (ShearWarpVolume, DVR of transfer-function objects): the
    /// volume classified per voxel, resampled bilinearly in the voxel slices perpendicular to
    /// the principal axis, one sample per slice, every `sliceStep`-th slice with opacity
    /// corrected for the step. Its floor is sliceStep 1.
    double preClassifiedRmse(int dir, int sliceStep);
    /// The RMSE per channel (0..1 units) between the model's image along direction `dir`'s
    /// rays and the same rays drawn from `cut`: each sample from the grid the cut names at its
    /// point, so a coarse level's error counts as far as rays cross it, behind what lies in
    /// front. Of 64 x 64 rays, those crossing a cell of another grid are found and up to 128
    /// of them integrated both ways (segments of at most a quarter voxel); the last few cuts cached
    /// by (dir, cut.key).
    double cutDifference(int dir, const GridCut& cut);
    /// Whether direction `dir`'s rays are cast already (rayRmse for it is then cheap).
    bool hasDirection(int dir) const;
    /// The direction a view is predicted along without casting rays for a new one: its own
    /// (nearestDirection) when cast, else the nearest cast within `maxDegrees` of the view
    /// (`wide`: among the wide sets); -1 when neither is.
    int castDirectionNear(const glm::dvec3& localDirection, bool wide, double maxDegrees) const;
    /// The unit vector of direction `dir` (narrow or wide: the same axis).
    static glm::dvec3 directionVector(int dir);
    /// Directions (narrow and wide sets) whose rays are cast.
    int directionsCast() const;
    /// The box's depth along direction `dir`, in L0.
    double depthL0(int dir) const;
    /// Threads a new direction's rays are integrated on (default: the machine's cores, at most
    /// 4). The predictions do not depend on it: each ray is integrated by one thread.
    void setThreads(int threads);
    /// The samples quadratures have taken on the model's rays so far (each visited ray's length
    /// in L0 times the quadrature's samples per L0): a deterministic measure of the work the
    /// search has done, unlike its time.
    double samplesEvaluated() const { return samplesEvaluated_; }
    /// The samples one evaluation of every ray of direction `dir` at `samplesPerL0` takes.
    double samplesOfFullEvaluation(int dir, double samplesPerL0);
    /// Rays cast and quadratures evaluated so far (a cost figure for tests and reports).
    int evaluations() const { return evaluations_; }

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
    SignalNeeds needs_;
    VolumeRenderMode mode_ = VolumeRenderMode::DVR;
    double L0_ = 1.0;
    bool tagged_ = false;
    /// An exact RMSE, or a lower bound where an evaluation stopped early.
    struct CachedRmse {
        double value = 0.0;
        bool exact = true;
    };
    std::map<std::pair<int, SlabQuadrature>, CachedRmse> cache_;
    std::map<std::pair<int, int>, double> preClassifiedCache_;
    std::vector<std::pair<std::pair<int, std::uint64_t>, double>> cutCache_; ///< newest last
    int evaluations_ = 0;
    double samplesEvaluated_ = 0.0;
};

} // namespace volsg
