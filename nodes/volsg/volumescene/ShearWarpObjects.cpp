#include <volsg/volumescene/ShearWarpObjects.h>

#include <map>

#include <volsg/core/Error.h>
#include <volsg/core/KeyMixing.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/state/State.h>
#include <volsg/volumescene/VolumeInScope.h>
#include <volsg/voxelfile/PackedVolume.h>

namespace volsg {

namespace {

VoxelRenderMode modeOf(int mode) {
    switch (mode) {
    case VolumeObject::SHADED:
        return VoxelRenderMode::Shaded;
    case VolumeObject::GRADIENT_OPACITY:
        return VoxelRenderMode::GradientOpacity;
    case VolumeObject::CONTOUR:
        return VoxelRenderMode::Contour;
    case VolumeObject::COLORED_CONTOUR:
        return VoxelRenderMode::ColoredContour;
    default:
        return VoxelRenderMode::TF;
    }
}

/// A transfer function in scope of an object and the key of its content.
struct ScopedTransfer {
    TransferFunction1D function; ///< the identity ramp without one
    std::uint64_t key = 0x9e3779b97f4a7c15ULL;
};

/// What each VolumeObject sees: the volume's scope, then the state nodes among the children
/// before it.
struct ObjectScope {
    VolumeObject* object;
    ScopedTransfer transfer;
    std::optional<RayCastBoxClip> box;
};

std::vector<ObjectScope> scopesOf(ShearWarpVolume& node, const VolumeInScope& volume) {
    std::map<int, ScopedTransfer> transfers;
    for (const auto& [tag, function] : volume.transferFunctions)
        transfers[tag] = {function, volume.transferKeys.at(tag)};
    std::optional<RayCastBoxClip> box = volume.boxClip;
    std::vector<ObjectScope> out;
    for (const auto& child : *node.children()) {
        if (!child) continue;
        if (child->isA<TransferFunction>()) {
            const auto& tf = static_cast<const TransferFunction&>(*child);
            if (tf.tag() < -1)
                throw Error("TransferFunction tag must be -1 (every voxel) or >= 0, got " +
                            std::to_string(tf.tag()));
            transfers[tf.tag()] = {tf.function(), transferFunctionKey(tf)};
        } else if (child->isA<BoxClip>()) {
            box = static_cast<const BoxClip&>(*child).describe(volume.model);
        } else if (child->isA<VolumeObject>()) {
            auto* object = static_cast<VolumeObject*>(child.get());
            ScopedTransfer transfer;
            if (object->source() == VolumeObject::TAG && transfers.count(object->tag()))
                transfer = transfers[object->tag()];
            else if (transfers.count(-1))
                transfer = transfers[-1];
            out.push_back({object, std::move(transfer), box});
        }
    }
    // No VolumeObject: the whole volume, as a Volume draws it (docs/SCENE-FORMAT.md 3.6).
    if (out.empty()) {
        ScopedTransfer transfer;
        if (transfers.count(-1)) transfer = transfers[-1];
        out.push_back({&node.wholeVolumeObject(), std::move(transfer), box});
    }
    return out;
}

} // namespace

std::vector<ShearWarpObject> gatherShearWarpObjects(ShearWarpVolume& node, const State& state,
                                                    std::vector<VolumeObject*>* sources,
                                                    ref_ptr<const VolumeGrid> levelGrid) {
    std::vector<ShearWarpObject> out;
    if (sources) sources->clear();
    const VolumeInScope volume = gatherScopeWithoutData(state);
    // A voxelFile replaces the VolumeData: its stored objects stand for the extraction.
    std::optional<PackedVolume> packed;
    if (!node.voxelFile().empty()) packed = PackedVolume::load(node.voxelFile(), node.directory());
    const auto* data = packed ? nullptr : static_cast<const VolumeData*>(volume.dataOwner);
    if (!data && !packed) return out;
    // A series hands out each step's lists from its step cache (which reads the grids).
    const VolumeSeries* series =
        data && data->isA<VolumeSeries>() ? static_cast<const VolumeSeries*>(data) : nullptr;
    const ref_ptr<const VolumeGrid> grid =
        data && !series ? (levelGrid ? levelGrid : data->grid()) : nullptr;
    if (!grid && !packed && !series) return out;
    const ref_ptr<const VolumeGrid> tags = data && !series ? data->tagGrid() : nullptr;
    const glm::dmat4& model = volume.model;
    const glm::dmat4 worldToLocal = glm::inverse(model);

    // Clip planes in local coordinates: a world plane p (keeping p.xyz . x >= p.w) is
    // (n, -d) . (x, 1) >= 0; with x = M l that is (M^T (n, -d)) . (l, 1) >= 0.
    std::vector<glm::dvec4> localPlanes;
    std::uint64_t planeKey = 0xcbf29ce484222325ULL;
    for (const glm::dvec4& p : volume.clipPlanes) {
        const glm::dvec4 h = glm::transpose(model) * glm::dvec4(glm::dvec3(p), -p.w);
        localPlanes.push_back(glm::dvec4(glm::dvec3(h), -h.w));
        for (int i = 0; i < 4; ++i)
            planeKey = mixKey(planeKey, bitsOf(p[i]));
    }

    for (ObjectScope& scope : scopesOf(node, volume)) {
        VolumeObject& vo = *scope.object;
        ShearWarpObject o;
        o.transferFunction = std::move(scope.transfer.function);
        const std::uint64_t transferKey = scope.transfer.key;
        o.object = packed   ? packed->voxels(out.size(), vo.extractionSpec(o.transferFunction))
                   : series ? series->voxelObject(vo.extractionSpec(o.transferFunction))
                            : vo.voxelObject(*grid, tags.get(), o.transferFunction, transferKey);
        o.compositing = vo.compositing() == VolumeObject::MIP           ? ObjectCompositing::MIP
                        : vo.compositing() == VolumeObject::SURFACE_HIT ? ObjectCompositing::Surface
                                                                        : ObjectCompositing::DVR;
        o.unclipped = {modeOf(vo.renderMode()), vo.opacity()};
        o.clipped = {modeOf(vo.clippedRenderMode()), vo.clippedOpacity()};
        o.contourColor = vo.contourColor();
        o.contourSharpness = vo.contourSharpness();
        o.shininess = vo.shininess();
        o.thinLayer = vo.voxels() == VolumeObject::SURFACE;
        o.clipPlanes = localPlanes;
        std::uint64_t clipKey = volume.clipPlanes.empty() ? 0 : planeKey;
        if (scope.box) {
            ShearWarpBox box;
            box.localToBox = glm::inverse(*scope.box->model) * model;
            box.origin = scope.box->origin;
            box.extent = scope.box->extent;
            o.box = box;
            clipKey = clipKey == 0 ? 0xcbf29ce484222325ULL : clipKey;
            for (int i = 0; i < 3; ++i)
                clipKey = mixKey(mixKey(clipKey, bitsOf(box.origin[i])), bitsOf(box.extent[i]));
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    clipKey = mixKey(clipKey, bitsOf(box.localToBox[c][r]));
        }
        // Also re-split when the model matrix moves the volume against world clip planes.
        if (clipKey != 0)
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r)
                    clipKey = mixKey(clipKey, bitsOf(worldToLocal[c][r]));
        o.clipKey = clipKey;
        o.tableKey = mixKey(mixKey(vo.version(), transferKey), 1);
        out.push_back(std::move(o));
        if (sources) sources->push_back(&vo);
    }
    if (packed) packed->checkObjectCount(out.size());
    return out;
}

RayCastVolume describeShearWarpVolume(ShearWarpVolume& node, const State& state) {
    std::vector<VolumeObject*> sources;
    const std::vector<ShearWarpObject> objects = gatherShearWarpObjects(node, state, &sources);
    const std::optional<VolumeInScope> volume = gatherVolumeInScope(state);
    if (!volume) throw Error("ShearWarpVolume without VolumeData in scope");
    RayCastVolume out;
    static_cast<VolumeInScope&>(out) = *volume;
    out.transferFunctions.clear();
    out.boxClip.reset();
    bool allMip = !objects.empty(), anyWhole = false;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const VolumeObject& vo = *sources[i];
        if (objects[i].compositing != ObjectCompositing::MIP) allMip = false;
        const int key = vo.source() == VolumeObject::TAG ? vo.tag() : -1;
        if (key == -1) anyWhole = true;
        out.transferFunctions.insert_or_assign(key, objects[i].transferFunction);
    }
    if (!anyWhole) { // voxels of no object are not drawn
        TransferFunction1D none;
        none.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}});
        out.transferFunctions.insert_or_assign(-1, none);
    }
    out.mode = allMip ? VolumeRenderMode::MIP : VolumeRenderMode::DVR;
    if (!objects.empty() && objects.front().box) {
        RayCastBoxClip box;
        box.origin = objects.front().box->origin;
        box.extent = objects.front().box->extent;
        box.model = out.model * glm::inverse(objects.front().box->localToBox);
        box.insideOpacity = 1.0;
        box.outsideOpacity = objects.front().clipped.opacity;
        out.boxClip = box;
    }
    return out;
}

} // namespace volsg
