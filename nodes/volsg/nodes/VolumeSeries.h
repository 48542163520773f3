#pragma once
// VolumeSeries: a time series of volumes, one step shown at a time (RTVR's SwitchNode over
// simulation steps). It is a VolumeData: the Volume and ShearWarpVolume nodes after it in scope
// render its current step. Fields and cache: lib/volsg/series/README.md.
#include <memory>
#include <optional>
#include <string>

#include <volsg/fields/Fields.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/series/SeriesCache.h>

namespace volsg {

class VoxelObject;
struct ExtractionSpec;

class VolumeSeries : public Inherit<VolumeData, VolumeSeries> {
public:
    static constexpr const char* typeName = "VolumeSeries";
    /// A generated series (tests, benchmarks): NONE reads files.
    enum TimeGenerator { NO_TIME_GENERATOR, MOVING_SPHERE };
    static const EnumValues timeGeneratorNames;

    // Inherited from VolumeData: fileName (here a pattern such as "step_%04d.nrrd" when
    // timeSteps is set), the raw layout fields, spacing, tagFileName (a pattern too).
    MFString fileNames{this, "fileNames"};                 ///< explicit list: overrides fileName
    SFVec2f timeSteps{this, "timeSteps", glm::vec2(0.0f)}; ///< first last numbers, inclusive
    SFInt32 step{this, "step", 0};                         ///< shown step, 0 = the first
    SFEnum timeGenerator{this, "timeGenerator", timeGeneratorNames, NO_TIME_GENERATOR};
    SFFloat cacheMegabytes{this, "cacheMegabytes", 256.0f}; ///< memory budget of voxel lists
    SFInt32 prefetch{this, "prefetch", 2};                  ///< steps prepared ahead
    SFBool loop{this, "loop", true};                        ///< playing wraps around

    /// Steps in the series (throws Error for malformed patterns or ranges).
    int stepCount() const;
    /// The shown step: `step` clamped to 0 .. stepCount()-1.
    int shownStep() const;

    /// The shown step's voxels (VolumeData's interface: Volume, ShearWarpVolume, bounding box).
    ref_ptr<const VolumeGrid> grid() const override;
    ref_ptr<const VolumeGrid> tagGrid() const override;
    /// Series are never paged: their steps are in memory (or read one by one) whole.
    std::shared_ptr<PagedVolume> pagedVolume() const override { return nullptr; }
    /// The shown step's box without loading its grid when its lists (or an earlier step's
    /// extent) say it: browsing cached steps never waits for a grid.
    Box3 localBounds() const override;
    /// The grids of the step play shows next (direction of play, forward when paused) if they
    /// are in memory already (prefetched), else empty; never loads. The Volume node stages
    /// their texture upload.
    SeriesStepVolume upcomingVolume() const;
    /// The shown step's extracted voxels for `spec`, through the step cache.
    ref_ptr<VoxelObject> voxelObject(const ExtractionSpec& spec) const;
    /// The principal axis the shear-warp renderer drew last (prefetched lists get that list).
    void setViewAxis(int axis) const;
    /// The step cache, made (again) from the fields when they changed. Not thread-safe, as
    /// VolumeData: call from the render thread.
    SeriesCache& cache() const;

    void readDone(const ReadContext& context) override;
    void doAction(Action& action) override;

protected:
    ~VolumeSeries() override;

private:
    std::string directory_;
    mutable std::unique_ptr<SeriesCache> cache_;
    mutable std::uint64_t cacheVersion_ = 0, sourceKey_ = 0;
    mutable int lastShown_ = -1;
    mutable std::optional<glm::dvec3> lastExtent_; ///< of the step shown last
    std::uint64_t sourceKeyOfFields() const;
    void showCurrent() const;
};

} // namespace volsg
