#include <volsg/volumescene/VolumeInScope.h>

#include <cmath>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/core/KeyMixing.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/state/State.h>

namespace volsg {

std::uint64_t transferFunctionKey(const TransferFunction& node) {
    const std::uint64_t own =
        mixKey(0x9e3779b97f4a7c15ULL, std::uint64_t(reinterpret_cast<std::uintptr_t>(&node)));
    return mixKey(own, node.version());
}

std::optional<VolumeInScope> gatherVolumeInScope(const State& state) {
    const VolumeData* node = state.nearestNode<VolumeData>();
    if (!node) return std::nullopt;
    ref_ptr<const VolumeGrid> data = node->grid();
    if (!data) return std::nullopt;
    VolumeInScope out = gatherScopeWithoutData(state);
    out.data = std::move(data);
    out.tags = node->tagGrid();
    out.paged = node->pagedVolume();
    return out;
}

VolumeInScope gatherScopeWithoutData(const State& state) {
    VolumeInScope out;
    out.dataOwner = state.nearestNode<VolumeData>();
    out.model = state.modelMatrix();
    // Every volume path maps rays into the volume through the inverse: a flattening or
    // non-finite transform is refused alike by all of them (the reference always did).
    bool finite = true;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            finite = finite && std::isfinite(out.model[c][r]);
    const double det = glm::determinant(glm::dmat3(out.model));
    if (!finite || !std::isfinite(det) || det == 0.0)
        throw Error("the transform above the volume is singular or not finite (a zero or "
                    "non-finite scale)");

    // Outermost first, so a later TransferFunction of the same tag replaces an earlier one.
    // The keys follow the nodes and their versions, so tables are rebuilt exactly when one of
    // them (or the set) changes.
    std::map<int, const TransferFunction*> byTag;
    for (const StateEntry& e : state.entries()) {
        if (e.node->isA<TransferFunction>()) {
            const auto* tf = static_cast<const TransferFunction*>(e.node);
            if (tf->tag() < -1)
                throw Error("TransferFunction tag must be -1 (every voxel) or >= 0, got " +
                            std::to_string(tf->tag()));
            byTag[tf->tag()] = tf;
        } else if (e.node->isA<ClipPlane>()) { // ClipPlane::doAction adds only planes that are on
            out.clipPlanes.push_back(
                ClipPlane::worldPlane(static_cast<const ClipPlane&>(*e.node).plane(), e.model));
        }
    }
    std::uint64_t key = 0xcbf29ce484222325ULL;
    for (const auto& [tag, tf] : byTag) {
        out.transferFunctions.emplace(tag, tf->function());
        out.transferKeys.emplace(tag, transferFunctionKey(*tf));
        key = mixKey(key, std::uint64_t(std::int64_t(tag)));
        key = mixKey(key, std::uint64_t(reinterpret_cast<std::uintptr_t>(tf)));
        key = mixKey(key, tf->version());
    }
    out.transferKey = key;

    // The box is in the BoxClip's own coordinates, which its model matrix maps to world.
    if (const StateEntry* e = state.nearest<BoxClip>())
        out.boxClip = static_cast<const BoxClip&>(*e->node).describe(e->model);
    return out;
}

} // namespace volsg
