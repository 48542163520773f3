// The Volume node draws the volume in scope with the slicer (lib/volsg/slicing), its settings
// taken from its fields in one place.
#include <chrono>
#include <vector>

#include <volsg/nodes/Material.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/RenderAction.h>
#include <volsg/slicing/PagedBricks.h>
#include <volsg/slicing/VolumeSlicer.h>
#include <volsg/volumescene/ReferenceScene.h>
#include <volsg/volumescene/VolumeInScope.h>

namespace volsg {

namespace {

SlicingSettings slicingSettings(const Volume& volume, const State& state,
                                const RenderDebug& debug) {
    SlicingSettings settings;
    settings.numPlanes = volume.numPlanes();
    settings.interactivePlanes = volume.interactivePlanes();
    settings.samplesPerPlane = volume.samplesPerPlane();
    settings.mipPeaks = volume.mipPeaks();
    settings.refinePeaks = volume.refinePeaks();
    settings.skipEmptyCells = debug.skipEmptyCells;
    settings.nearest = volume.interpolation() == Volume::NEAREST;
    settings.preIntegrated = volume.preIntegrated();
    settings.lighting = volume.lighting();
    settings.textureBudget = volume.textureBudget();
    settings.lodPixels = volume.lodPixels() > 0.0f ? double(volume.lodPixels()) : 1.0;
    // Targets in 1/255; NaN and <= 0 mean none (the fixed rules), +infinity the cheapest.
    auto target = [](float t) { return t > 0.0f ? double(t) / 255.0 : 0.0; };
    settings.errorTarget = target(volume.errorTarget());
    settings.interactiveErrorTarget = target(volume.interactiveErrorTarget());
    settings.fixedSamplesPerPlane = !volume.samplesPerPlane.isDefault();
    settings.fixedPreIntegrated = !volume.preIntegrated.isDefault();
    settings.fixedMipPeaks = !volume.mipPeaks.isDefault();
    if (const Material* m = state.nearestNode<Material>()) {
        if (!m->specularColor.empty()) settings.specular = m->specularColor[0];
        if (!m->shininess.empty()) settings.shininess = m->shininess[0];
    }
    return settings;
}

void renderVolume(RenderAction& action, Volume& node) {
    action.needFloatTarget();
    if (action.pass() != RenderPass::Volume) return;
    action.countVolumeInstance();
    // The node's share of the per-frame CPU time: gathering its state (added to the slicer's).
    const auto started = std::chrono::steady_clock::now();
    const State& state = action.state();
    std::optional<VolumeInScope> scope = gatherVolumeInScope(state);
    if (!scope) return; // nothing to show
    const auto* series = static_cast<const VolumeData*>(scope->dataOwner)->isA<VolumeSeries>()
                             ? static_cast<const VolumeSeries*>(scope->dataOwner)
                             : nullptr;
    const RayCastVolume volume = describeVolume(node, std::move(*scope));
    FrameContext& frame = action.frame();
    const SlicingSettings settings = slicingSettings(node, state, frame.debug);
    thread_local std::vector<SceneLight> lights;
    lights.clear();
    if (settings.lighting) action.lightsInScope(lights);
    const double gathering =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    slicing::preparePagedGuard(volume, settings);
    SlicingStats stats;
    VolumeSlicer::draw(frame, node, volume, lights, settings, stats);
    stats.cpuMilliseconds += gathering;
    node.setSlicingStats(stats);
    // A series' next step, once prefetched, is staged for upload while this one is shown.
    if (series) {
        const SeriesStepVolume next = series->upcomingVolume();
        VolumeSlicer::stage(frame, node, next.data, next.tags);
    }
}

} // namespace

void addVolumeRenderMethods(ActionMethods& methods) {
    methods.add(&renderVolume);
}

} // namespace volsg
