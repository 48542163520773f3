// The Volume slicer's frame as a list of stages, and the staging of a series' next grid.
#include <volsg/slicing/VolumeSlicer.h>

#include <algorithm>
#include <chrono>
#include <memory>

#include <volsg/core/Error.h>
#include <volsg/paging/PagedVolume.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/slicing/BrickLayout.h>
#include <volsg/slicing/LevelOfDetailError.h>
#include <volsg/slicing/PagedBricks.h>
#include <volsg/slicing/SliceDraw.h>
#include <volsg/slicing/SliceGeometry.h>
#include <volsg/slicing/SlicePlan.h>
#include <volsg/slicing/SliceShared.h>
#include <volsg/slicing/SlicingQuality.h>
#include <volsg/slicing/TextureStaging.h>
#include <volsg/slicing/VolumeTextures.h>
#include <volsg/sortlast/KdVolumeSplit.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

using namespace slicing;

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

void checkVolume(const RayCastVolume& volume) {
    if (!volume.data) throw Error("Volume: no data to render");
    if (volume.tags) {
        if (volume.tags->dimensions() != volume.data->dimensions())
            throw Error("Volume: the tag grid's dimensions differ from the data's");
        if (!volume.tags->isLabelType())
            throw Error("Volume: the tag grid must be UByte or UShort");
    }
}

/// Decides how this frame draws the volume and brings the volume's bricks and tables up to
/// date for that; records the layout in `staging` for a grid staged next.
SliceMethod prepareVolume(VolumeTextures& v, const SliceShared& shared, TextureStaging& staging,
                          const RayCastVolume& volume, const SlicingSettings& settings) {
    SliceMethod m;
    m.mode = modeOf(volume.mode);
    m.lighting = settings.lighting && m.mode == kDvr;
    // Lighting, pre-integration and tag-cell splitting sample up to a voxel (or half a slab)
    // beyond the point drawn: bricks then carry a guard voxel, so seams stay invisible.
    const bool sampleAround = m.lighting || settings.preIntegrated || volume.tags;
    if (!volume.paged) // a paged volume's bricks are chosen per frame (PagedBricks.h)
        prepareLayout(v, shared, settings.textureBudget, sampleAround ? 1 : 0);
    prepareTable(v, volume, volume.transferKey);
    m.tagged = v.tags && v.table.rows() > 1;
    staging.hasFrame = true; // a grid staged next is laid out as this one
    staging.textureBudget = settings.textureBudget;
    staging.guard = sampleAround ? 1 : 0;
    staging.tagged = m.tagged;
    m.preIntegrated =
        settings.preIntegrated && m.mode == kDvr && v.table.rows() <= PreIntegrationTable::kMaxRows;
    if (m.preIntegrated) preparePreIntegration(v);
    // Empty cells are skipped (rows left out of the geometry, one-sample fragments discarded)
    // where that is exact: DVR of one row (not split at tag cells), each part sampled at one
    // point or pre-integrated between the data at its ends (cells classified for that table's
    // filter; the rows reach over the whole slab, and no fragment is discarded by its point,
    // since its segment spans the slab); MIP of one row (tags would let a skipped sample's row
    // matter). MINIP and AVERAGE see every sample.
    m.skipCells =
        settings.skipEmptyCells && !volume.paged && !m.tagged && (m.mode == kDvr || m.mode == kMip);
    if (m.skipCells) prepareCells(v, m.mode == kMip ? 1 : m.preIntegrated ? 2 : 0);
    m.hasPlaneOpacity = m.mode == kDvr && planeOpacityMatters(volume.planeOpacity);
    if (m.hasPlaneOpacity) preparePlaneOpacity(v, volume.planeOpacity);
    prepareFilter(v, settings.nearest);
    m.slabSamples = m.mode != kAverage ? std::clamp(settings.samplesPerPlane, 1, 256) : 1;
    // The lean program when every sample of a slab counts alike (several of them, no tags, no
    // BoxClip; DVR without planeOpacity, lighting or pre-integration; MIP/MINIP with or
    // without the voxel-centre crossings, a variant each).
    m.lean = m.slabSamples > 1 && !m.tagged && !volume.boxClip &&
             (m.mode == kDvr ? !m.lighting && !m.preIntegrated && !m.hasPlaneOpacity
                             : m.mode == kMip || m.mode == kMinip);
    m.leanPeaks = m.lean && m.mode != kDvr && settings.mipPeaks;
    return m;
}

/// The box of this process's part when it holds only its part's voxels (sort-last,
/// VolumePartition::ownDataOnly); none otherwise.
std::optional<ModelRegion> ownPartRegion(const RayCastVolume& volume,
                                         const VolumePartition& partition) {
    if (partition.parts <= 1 || !partition.ownDataOnly) return std::nullopt;
    const KdVolumeSplit split(volume.data->dimensions(), volume.data->spacing(), partition.parts);
    const KdVolumeSplit::Part& part = split.part(partition.part);
    if (part.empty) return ModelRegion{}; // a point: no rays, the cheapest choice
    return ModelRegion{part.boxMin, part.boxMax};
}

/// Sort-last with each process judging its own part: all take the costliest of the processes'
/// choices (the one the most demanding part needs), so every part meets the target and the
/// plane layout is one.
void agreeOnCostliest(QualityChoice& choice, const QualityView& view, const SlabErrorModel& model,
                      const VolumePartition& partition) {
    const SlabQuadrature& q = choice.quadrature;
    const double cost = quadratureCost(q, view.depthL0, model.mode(), model.tagged());
    double values[7] = {q.planeSpacingL0,          double(q.samplesPerPlane),
                        double(q.preIntegrated),   double(q.peaks),
                        double(q.refinePeaks),     choice.predictedRmse,
                        double(choice.meetsTarget)};
    if (partition.fromSmallest) partition.fromSmallest(-cost, values, 7);
    choice.quadrature.planeSpacingL0 = values[0];
    choice.quadrature.samplesPerPlane = int(values[1]);
    choice.quadrature.preIntegrated = values[2] != 0.0;
    choice.quadrature.peaks = values[3] != 0.0;
    choice.quadrature.refinePeaks = values[4] != 0.0;
    choice.predictedRmse = values[5];
    choice.meetsTarget = values[6] != 0.0;
}

/// How far (degrees) an interactive frame's view may be from a direction the error model has
/// cast for the frame to be predicted along that one (two steps of its lattice, 15 degrees).
constexpr double kInteractiveReuseDegrees = 30.0;

/// What a frame's quality was chosen for, and the model's prediction (SlicingStats).
struct FrameQuality {
    bool predicted = false;
    double target = 0.0;
    QualityChoice choice;
    QualityView view;
    double milliseconds = 0.0;
    int modelDirections = 0; ///< SlicingStats::modelDirections
};

/// The settings this frame draws with: those the node left automatic chosen as the cheapest
/// whose predicted error meets the frame's target (still or interactive), the others as given.
/// No target (0), AVERAGE and NEAREST keep the fixed rules (the model covers neither).
SlicingSettings settingsForFrame(VolumeTextures& v, const RayCastVolume& volume,
                                 const LocalView& local, const FrameContext& frame,
                                 const SlicingSettings& settings, FrameQuality& quality) {
    const double target =
        frame.interactive ? settings.interactiveErrorTarget : settings.errorTarget;
    // A paged volume's model is made on its stand-in (the whole volume at a coarser level);
    // preparePaged carries the choice to the finest level drawn (PagedBricks.h).
    if (!(target > 0.0) || volume.mode == VolumeRenderMode::AVERAGE || settings.nearest)
        return settings;
    // What the model leaves out (BoxClip, clip planes, planeOpacity, opaque geometry ending
    // rays, a near plane cutting the box: the camera inside) adds boundaries inside slabs and
    // silhouettes it does not sample: the model is asked for half the target there (README,
    // "Error targets": what this does and does not cover).
    const bool nearCutsBox = local.clipDepth.x > local.boxDepth.x;
    const bool outsideModel = volume.boxClip || !volume.clipPlanes.empty() ||
                              planeOpacityMatters(volume.planeOpacity) ||
                              frame.shapes.drawsLastFrame() > 0 || nearCutsBox;
    const double modelTarget = outsideModel ? 0.5 * target : target;
    const auto started = std::chrono::steady_clock::now();
    // A sort-last process holding only its part judges the rays through its part.
    const std::optional<ModelRegion> region = ownPartRegion(volume, frame.partition);
    if (!v.errorModel || v.errorModelKey != volume.transferKey ||
        v.errorModelMode != int(volume.mode) || v.errorModelRegion != region.has_value()) {
        // The model skips the cells that cannot emit (its own classification of the ranges).
        const bool sameGrid = v.data.get() == volume.data.get();
        if (sameGrid) measureCells(v);
        v.errorModel = std::make_unique<SlabErrorModel>(
            volume, region, volume.paged ? volume.paged->finestSpacing() : 0.0,
            sameGrid ? &v.cells : nullptr);
        v.errorModelKey = volume.transferKey;
        v.errorModelMode = int(volume.mode);
        v.errorModelRegion = region.has_value();
    }
    QualityRequest request;
    request.errorTarget = modelTarget;
    if (frame.interactive && settings.interactivePlanes > 0)
        request.numPlanes = settings.interactivePlanes;
    else if (settings.numPlanes > 0)
        request.numPlanes =
            frame.interactive ? std::max(1, (settings.numPlanes + 3) / 4) : settings.numPlanes;
    // As the drawing clamps them (a negative count from a file made the model loop for ever).
    if (settings.fixedSamplesPerPlane)
        request.samplesPerPlane = std::clamp(settings.samplesPerPlane, 1, 256);
    if (settings.fixedPreIntegrated) request.preIntegrated = settings.preIntegrated;
    if (settings.fixedMipPeaks) request.peaks = settings.mipPeaks;
    request.refinePeaks = settings.refinePeaks;
    // A paged volume's opacity unit is level 0's voxel, not its stand-in's (preparePaged).
    LocalView modelled = local;
    if (volume.paged) modelled.L0 = volume.paged->finestSpacing();
    quality.view = qualityView(modelled, frame.view);
    // An interactive frame whose view direction is new to the model takes the nearest one cast
    // within kInteractiveReuseDegrees: casting a direction costs 14-18 ms on the node suite's
    // volumes, the frame 20-40 ms. A drag meets new directions all the time; the still frame
    // after it casts its own.
    if (frame.interactive)
        quality.view.directions =
            castDirectionsNear(*v.errorModel, quality.view, kInteractiveReuseDegrees);
    quality.choice = chooseQuality(*v.errorModel, quality.view, request);
    if (region) agreeOnCostliest(quality.choice, quality.view, *v.errorModel, frame.partition);
    quality.predicted = true;
    quality.target = target;
    quality.modelDirections = v.errorModel->directionsCast();

    SlicingSettings chosen = settings;
    chosen.planeSpacingL0 = quality.choice.quadrature.planeSpacingL0;
    chosen.samplesPerPlane = quality.choice.quadrature.samplesPerPlane;
    chosen.preIntegrated = quality.choice.quadrature.preIntegrated;
    chosen.mipPeaks = quality.choice.quadrature.peaks;
    quality.milliseconds = millisecondsSince(started);
    return chosen;
}

/// The last-frame counters known before anything is cut.
SlicingStats layoutStats(const VolumeTextures& v, const SlicePlan& plan,
                         const SlicingSettings& settings, const FrameQuality& quality) {
    SlicingStats drawn;
    drawn.samplesPerPlane = plan.method.slabSamples;
    drawn.preIntegrated = plan.method.preIntegrated;
    drawn.mipPeaks = plan.method.mode != kDvr && plan.method.mode != kAverage && settings.mipPeaks;
    const double localPerEyeAxis = glm::length(plan.local.eyeToLocal3 * glm::dvec3(0.0, 0.0, -1.0));
    drawn.planeSpacingL0 = plan.layout.spacing * localPerEyeAxis / plan.local.L0;
    if (quality.predicted) {
        drawn.errorTarget = quality.target;
        drawn.predictedRmse = drawn.quadratureRmse = quality.choice.predictedRmse;
        drawn.meetsTarget = quality.choice.meetsTarget;
        drawn.coverage = quality.view.coverage;
        drawn.qualityMilliseconds = quality.milliseconds;
        drawn.modelDirections = quality.modelDirections;
    }
    drawn.bricksTotal = int(v.bricks.size());
    drawn.brickGrid = v.layout.grid();
    drawn.brickTexels = v.layout.largestTexture();
    drawn.planes = plan.layout.count;
    drawn.planeSpacing = plan.layout.spacing;
    drawn.emptyCells = plan.method.skipCells ? v.cells.emptyFraction() : 0.0;
    return drawn;
}

/// A paged frame's predicted error: the quadrature's (made on the stand-in) and the level of
/// detail's (LevelOfDetailError.h), as independent parts of one image RMSE.
void foldLevelOfDetail(SlabErrorModel& model, const FrameQuality& quality, const PagedVolume& paged,
                       const std::vector<BrickKey>& drawnBricks, PagingStats& paging,
                       SlicingStats& drawn) {
    const auto started = std::chrono::steady_clock::now();
    const LevelOfDetailError lod =
        predictLevelOfDetailError(model, quality.view, paged, drawnBricks);
    drawn.qualityMilliseconds += millisecondsSince(started);
    paging.lodRmse = lod.rmse;
    paging.measuredFrom = lod.measuredFrom;
    if (!(lod.rmse >= 0.0)) return;
    drawn.predictedRmse = std::hypot(drawn.quadratureRmse, lod.rmse);
    drawn.meetsTarget = drawn.predictedRmse <= quality.target;
}

/// Sort-last (lib/volsg/sortlast/README.md): the box of this process's part of a k-d split of
/// the volume, and where the part lies front to back for this view. Only DVR's "over" is
/// composited across processes (MIP's partial would need its raw extreme values, not colours).
void partitionVolume(const RayCastVolume& volume, const VolumePartition& partition, SlicePlan& plan,
                     SlicingStats& drawn) {
    if (partition.parts <= 1) {
        drawn.partLastVoxel = volume.data->dimensions() - 1;
        return;
    }
    if (volume.mode != VolumeRenderMode::DVR)
        throw Error("Volume: rendering across processes (sort-last) composites DVR only, not "
                    "MIP, MINIP or AVERAGE");
    const KdVolumeSplit split(volume.data->dimensions(), volume.data->spacing(), partition.parts);
    const KdVolumeSplit::Part& part = split.part(partition.part);
    // An empty part (more processes than cells) draws nothing: an empty box.
    plan.partMin = part.empty ? glm::dvec3(0.0) : part.boxMin;
    plan.partMax = part.empty ? glm::dvec3(0.0) : part.boxMax;
    const std::vector<int> order = split.frontToBack(plan.local.viewer, plan.local.orthographic);
    drawn.partPosition = int(std::find(order.begin(), order.end(), partition.part) - order.begin());
    drawn.partFirstVoxel = part.firstVoxel;
    drawn.partLastVoxel = part.lastVoxel;
}

/// After the draws: drops what only this grid's first frame needed, and counts.
void finishFrame(VolumeTextures& v, SlicingStats& drawn) {
    v.staged.reset(); // its bricks are uploaded; skipped (empty) ones upload directly later
    v.spareTextures.clear();
    for (const BrickState& s : v.bricks)
        if (s.resident) ++drawn.bricksResident;
    drawn.textureBytes = v.residentBytes;
    ++v.totals.frames;
    drawn.frames = v.totals.frames;
    drawn.brickUploads = v.totals.brickUploads;
    drawn.uploadedBytes = v.totals.uploadedBytes;
    drawn.transferTableBuilds = v.totals.transferTableBuilds;
    drawn.preIntegrationBuilds = v.totals.preIntegrationBuilds;
    drawn.stagedUploads = v.totals.stagedUploads;
    drawn.refilledTextures = v.totals.refilledTextures;
}

} // namespace

void VolumeSlicer::draw(FrameContext& frame, const Object& owner, const RayCastVolume& volume,
                        std::span<const SceneLight> lights, const SlicingSettings& settings,
                        SlicingStats& stats) {
    if (frame.pass != RenderPass::Volume) return;
    const auto started = std::chrono::steady_clock::now();
    checkVolume(volume);
    // Before the textures' key, which a paged volume's guard is part of.
    preparePagedGuard(volume, settings);
    SliceShared& shared = sliceSharedOf(frame);
    const std::uint64_t key = textureKeyOf(volume);
    VolumeTextures& v = frame.cache.get<VolumeTextures>(owner, key);
    TextureStaging& staging = frame.cache.get<TextureStaging>(owner);
    adoptGrid(frame.cache, owner, key, v, staging, volume);
    prepareGrid(v, volume);

    SlicePlan plan;
    plan.local = localView(frame.view, volume.model, *volume.data);
    FrameQuality quality;
    SlicingSettings chosen = settingsForFrame(v, volume, plan.local, frame, settings, quality);
    plan.method = prepareVolume(v, shared, staging, volume, chosen);
    PagingStats paging;
    if (volume.paged) paging = preparePaged(frame, owner, key, v, volume, plan.local, chosen);
    plan.layout = planeLayout(plan.local, chosen, plan.method.slabSamples, frame);
    SlicingStats drawn = layoutStats(v, plan, chosen, quality);
    if (volume.paged && quality.predicted && v.errorModel)
        foldLevelOfDetail(*v.errorModel, quality, *volume.paged, v.pagedDrawn, paging, drawn);
    drawn.paging = paging;
    plan.clipPlanes = localClipPlanes(volume);
    plan.rows = planRows(v, plan, chosen);
    // A process holding only its part ends slabs at the part's faces as at seams.
    plan.slabsEndAtPart = frame.partition.parts > 1 && frame.partition.ownDataOnly;
    plan.slabsEndAtBricks = slabsEndAtBricks(
        plan.method, plan.slabsEndAtPart ? 2 : v.layout.bricks().size(),
        plan.layout.spacing * glm::length(plan.local.eyeToLocal3 * glm::dvec3(0.0, 0.0, 1.0)),
        plan.local.L0);
    partitionVolume(volume, frame.partition, plan, drawn);
    cutBricks(v, *volume.data, plan, drawn);

    const auto prepared = std::chrono::steady_clock::now();
    drawn.cpuMilliseconds = std::chrono::duration<double, std::milli>(prepared - started).count();
    if (!v.vertices.empty()) drawSlices(frame, shared, v, volume, lights, chosen, plan, drawn);
    finishFrame(v, drawn);
    drawn.submitMilliseconds = millisecondsSince(prepared);
    stats = drawn;
}

void VolumeSlicer::stage(FrameContext& frame, const Object& owner,
                         const ref_ptr<const VolumeGrid>& data,
                         const ref_ptr<const VolumeGrid>& tags) {
    if (frame.pass != RenderPass::Volume || !data) return;
    if (!frame.debug.textureStaging) return; // the direct upload of every step (volsg-bench)
    TextureStaging& staging = frame.cache.get<TextureStaging>(owner);
    if (!staging.hasFrame) return; // no frame drawn yet: how to lay the grid out is unknown
    const ref_ptr<const VolumeGrid> labels = staging.tagged ? tags : nullptr;
    if (staging.next && staging.next->data() == data.get() && staging.next->tags() == labels.get())
        return;                                                   // staged already
    if (tags && tags->dimensions() != data->dimensions()) return; // drawing it will say why
    if (labels && !labels->isLabelType()) return;
    const SliceShared& shared = frame.cache.shared<SliceShared>();
    const BrickLayout layout(
        data->dimensions(), data->spacing(),
        layoutLimits(*data, tags.get(), shared, staging.textureBudget, staging.guard));
    staging.next.reset(); // one staged grid at a time: its memory before the new one's
    staging.next = std::make_unique<StagedGrid>(data, labels, layout);
    ++staging.stagedGrids;
}

} // namespace volsg
