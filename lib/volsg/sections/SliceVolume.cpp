#include <volsg/sections/SliceVolume.h>

#include <volsg/core/KeyMixing.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/state/State.h>

namespace volsg {

std::optional<SliceVolume> SliceVolume::fromState(const State& state) {
    const VolumeData* node = state.nearestNode<VolumeData>();
    if (!node) return std::nullopt;
    SliceVolume out;
    out.node = node;
    out.data = node->grid();
    if (!out.data) return std::nullopt;
    out.tags = node->tagGrid();
    out.model = state.modelMatrix();
    // Outermost first, so a later TransferFunction of the same tag replaces an earlier one;
    // the key follows the nodes and their versions, as the Volume node's does.
    std::map<int, const TransferFunction*> byTag;
    for (const StateEntry* entry : state.all<TransferFunction>()) {
        const auto* tf = static_cast<const TransferFunction*>(entry->node);
        byTag[tf->tag()] = tf;
    }
    std::uint64_t key = 0xcbf29ce484222325ULL;
    for (const auto& [tag, tf] : byTag) {
        out.transferFunctions.emplace(tag, tf->function());
        key = mixKey(key, std::uint64_t(std::int64_t(tag)));
        key = mixKey(key, std::uint64_t(reinterpret_cast<std::uintptr_t>(tf)));
        key = mixKey(key, tf->version());
    }
    out.transferKey = key;
    return out;
}

} // namespace volsg
