// The ShearWarpVolume node keeps its CPU engine, its last frame (for picking) and the
// idle-time optimizer; nodes/volsg/render/ShearWarpRendering.cpp gathers its objects and
// composites its frames.
#include <volsg/nodes/ShearWarpVolume.h>

#include <algorithm>
#include <cmath>

#include <volsg/actions/Action.h>
#include <volsg/io/ReadContext.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/shearwarp/VoxelListOptimizer.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

const EnumValues ShearWarpVolume::interObjectNames{{"DVR", DVR}, {"MIP", MIP}};

ShearWarpVolume::ShearWarpVolume() = default;

ShearWarpVolume::~ShearWarpVolume() = default;

VolumeObject& ShearWarpVolume::wholeVolumeObject() {
    if (!wholeVolume_) wholeVolume_ = VolumeObject::create();
    return *wholeVolume_;
}

void ShearWarpVolume::doAction(Action& action) {
    // The state nodes among the children apply to the objects only.
    action.state().push();
    Group::doAction(action);
    action.state().pop();
}

SlabErrorModel& ShearWarpVolume::errorModel(const RayCastVolume& volume, std::uint64_t key) {
    if (!errorModel_ || errorModelKey_ != key) {
        errorModel_ = std::make_unique<SlabErrorModel>(volume);
        errorModelKey_ = key;
    }
    return *errorModel_;
}

const ShearWarpVolume::Quality& ShearWarpVolume::lastQuality() const {
    if (pendingPrediction_ && errorModel_) {
        const PendingPrediction p = *pendingPrediction_;
        quality_.floorRmse = p.scale * preClassifiedRmseAlong(*errorModel_, p.directions, 1);
        quality_.predictedRmse =
            p.scale * preClassifiedRmseAlong(*errorModel_, p.directions, quality_.sliceStep);
        quality_.predicted = true;
    }
    pendingPrediction_.reset();
    return quality_;
}

int ShearWarpVolume::sliceStepFor(bool interactive, double interactivePlaneScale) const {
    constexpr int maximumStep = 16;
    if (!interactive) return 1;
    const double scale = interactivePlaneScale > 0.0 ? std::min(interactivePlaneScale, 1.0) : 1.0;
    const double step = std::max(1, interactiveSliceStep()) / scale;
    return int(std::clamp(std::lround(step), 1L, long(maximumStep)));
}

const ShearWarpFrame& ShearWarpVolume::renderFrame(std::vector<ShearWarpObject>& objects,
                                                   const ShearWarpView& view,
                                                   std::vector<VolumeObject*> sources,
                                                   const glm::dmat4& model) {
    if (lastFrame_) { // its buffers serve the new frame
        renderer_.recycle(std::move(*lastFrame_));
        lastFrame_.reset();
    }
    lastFrame_ = std::make_unique<ShearWarpFrame>(renderer_.render(objects, view));
    lastSources_ = std::move(sources);
    lastObjects_.clear();
    for (const ShearWarpObject& o : objects)
        lastObjects_.push_back(o.object);
    lastModel_ = model;
    if (optimize()) {
        std::vector<std::pair<ref_ptr<VoxelObject>, int>> lists;
        for (const ShearWarpObject& o : objects)
            lists.emplace_back(o.object, lastFrame_->stats.principalAxis);
        if (!optimizer_) optimizer_ = std::make_unique<VoxelListOptimizer>(); // its thread
        optimizer_->schedule(std::move(lists));
    }
    return *lastFrame_;
}

std::optional<ShearWarpVolume::Pick> ShearWarpVolume::pickAt(int x, int y) const {
    if (!lastFrame_) return std::nullopt;
    const auto hit = ShearWarpRenderer::pick(*lastFrame_, x, y);
    if (!hit || hit->object < 0 || std::size_t(hit->object) >= lastSources_.size())
        return std::nullopt;
    Pick pick;
    pick.object = lastSources_[std::size_t(hit->object)];
    pick.worldPosition = glm::dvec3(lastModel_ * glm::dvec4(hit->localPosition, 1.0));
    return pick;
}

std::size_t ShearWarpVolume::voxelListBytes() const {
    std::size_t bytes = 0;
    for (const auto& object : lastObjects_)
        bytes += object->memoryBytes();
    return bytes;
}

void ShearWarpVolume::waitForOptimizer() {
    if (optimizer_) optimizer_->waitUntilIdle();
}

void ShearWarpVolume::readDone(const ReadContext& context) {
    directory_ = context.directory;
}

} // namespace volsg
