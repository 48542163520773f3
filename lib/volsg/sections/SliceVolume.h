#pragma once
// What a planar section shows: the VolumeData and TransferFunctions in scope at a slice node,
// gathered from the State as the Volume node gathers them.

#include <cstdint>
#include <map>
#include <optional>

#include <glm/glm.hpp>

#include <volsg/core/Object.h>
#include <volsg/volume/TransferFunction1D.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

class State;
class VolumeData;

/// A slice's volume: data, optional tags, the nearest TransferFunction of each tag (-1: the
/// default), and the model matrix at the slice (the volume box is centred on the local origin
/// with extent dimensions * spacing, VolumeGrid).
struct SliceVolume {
    const VolumeData* node = nullptr; ///< keys the shared GPU copy of the data
    ref_ptr<const VolumeGrid> data;
    ref_ptr<const VolumeGrid> tags;
    std::map<int, TransferFunction1D> transferFunctions;
    /// Changes whenever the set of transfer functions or one of them changes.
    std::uint64_t transferKey = 0;
    glm::dmat4 model{1.0};

    glm::dvec3 halfExtent() const { return 0.5 * data->extent(); }

    /// The volume in scope, or nothing without a VolumeData (or with an empty one). Loads the
    /// data (VolumeData::grid() throws Error naming the file on failure).
    static std::optional<SliceVolume> fromState(const State& state);
};

} // namespace volsg
