// The Volume node gathers its state (data, transfer functions per tag, BoxClip, ClipPlanes,
// transform) into the rendering model's description and hands it to the slicer.
#include <volsg/nodes/Volume.h>

#include <chrono>
#include <map>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/core/KeyMixing.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/render/RenderAction.h>
#include <volsg/slicing/VolumeSlicer.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

const EnumValues Volume::renderModeNames{
    {"DVR", DVR}, {"MIP", MIP}, {"MINIP", MINIP}, {"AVERAGE", AVERAGE}};
const EnumValues Volume::interpolationNames{{"LINEAR", LINEAR}, {"NEAREST", NEAREST}};

VolumeRenderMode Volume::mode() const {
    switch (renderMode()) {
    case MIP:
        return VolumeRenderMode::MIP;
    case MINIP:
        return VolumeRenderMode::MINIP;
    case AVERAGE:
        return VolumeRenderMode::AVERAGE;
    default:
        return VolumeRenderMode::DVR;
    }
}

void Volume::render(RenderAction& action) {
    if (action.pass() != RenderPass::Volume) return;
    // The node's share of the per-frame CPU time: gathering its state (added to the slicer's).
    const auto started = std::chrono::steady_clock::now();
    const State& state = action.state();
    const VolumeData* data = state.nearestNode<VolumeData>();
    if (!data) return; // nothing to show

    RayCastVolume volume;
    volume.data = data->grid();
    if (!volume.data) return;
    volume.tags = data->tagGrid();
    volume.model = state.modelMatrix();
    volume.mode = mode();

    // The nearest TransferFunction of each tag applies. The key follows the nodes' versions,
    // so the slicer rebuilds its tables exactly when one of them (or the set) changes.
    std::map<int, const TransferFunction*> byTag;
    for (const StateEntry& e : state.entries())
        if (e.node->isA<TransferFunction>()) {
            const auto* tf = static_cast<const TransferFunction*>(e.node);
            byTag[tf->tag()] = tf;
        }
    std::uint64_t transferKey = 0xcbf29ce484222325ULL;
    for (const auto& [tag, tf] : byTag) {
        volume.transferFunctions.emplace(tag, tf->function());
        transferKey = mixKey(transferKey, std::uint64_t(std::int64_t(tag)));
        transferKey = mixKey(transferKey, std::uint64_t(reinterpret_cast<std::uintptr_t>(tf)));
        transferKey = mixKey(transferKey, tf->version());
    }

    for (const glm::vec2& p : planeOpacity.getValues())
        volume.planeOpacity.push_back({double(p.x), double(p.y)});
    if (const StateEntry* e = state.nearest<BoxClip>()) // in the BoxClip's own coordinates
        volume.boxClip = static_cast<const BoxClip&>(*e->node).describe(e->model);
    action.clipPlanesInScope(volume.clipPlanes);

    SlicingSettings settings;
    settings.numPlanes = numPlanes();
    settings.interactivePlanes = interactivePlanes();
    settings.samplesPerPlane = samplesPerPlane();
    settings.mipPeaks = mipPeaks();
    settings.refinePeaks = refinePeaks();
    settings.nearest = interpolation() == NEAREST;
    settings.preIntegrated = preIntegrated();
    settings.lighting = lighting();
    settings.textureBudget = textureBudget();
    if (const Material* m = state.nearestNode<Material>()) {
        if (!m->specularColor.empty()) settings.specular = m->specularColor[0];
        if (!m->shininess.empty()) settings.shininess = m->shininess[0];
    }
    const double gathering =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    VolumeSlicer::draw(action, *this, volume, transferKey, settings, slicingStats_);
    slicingStats_.cpuMilliseconds += gathering;
    // A series' next step, once prefetched, is staged for upload while this one is shown.
    if (data->isA<VolumeSeries>()) {
        const SeriesStepVolume next = static_cast<const VolumeSeries*>(data)->upcomingVolume();
        VolumeSlicer::stage(action, *this, next.data, next.tags);
    }
}

void Volume::getBoundingBox(BoundingBoxAction& action) {
    if (const VolumeData* data = action.state().nearestNode<VolumeData>())
        data->extendBoundingBox(action);
}

} // namespace volsg
