#pragma once
// What is under the mouse: the nearest shape (PickAction) or visible volume content along a
// world ray, so that clicking selects any object of the scene, volumes included (RTVR's "click
// an object to make it active").

#include <optional>
#include <vector>

#include <volsg/core/Node.h>
#include <volsg/math/Ray.h>

namespace volsg {

struct ScenePick {
    Node* node = nullptr;    ///< the shape or Volume hit
    std::vector<Node*> path; ///< from the root to it
    glm::dvec3 point{0.0};   ///< world coordinates
    double distance = 0.0;   ///< along the (unit) world ray
    bool isVolume = false;
};

/// The nearest hit along `worldRay` (its direction need not be unit) among shapes and the
/// content of Volume and ShearWarpVolume nodes, between near and far. A volume is hit where it
/// first becomes visible: where the opacity of its classified, trilinearly sampled data (the
/// transfer functions in scope, tags honoured, BoxClip opacity and ClipPlanes applied) over one
/// smallest voxel spacing reaches ReferenceRayCaster::kPickOpacity (0.02), as
/// ReferenceRayCaster::firstVisibleDistance() defines it. A ray through the volume's box that
/// meets only transparent voxels misses the volume and hits what lies behind.
std::optional<ScenePick> pickScene(Node& root, const Ray& worldRay, double nearDistance = 0.0,
                                   double farDistance = 1e300);

/// The node of type T nearest in scope at the first place `target` is reached in traversal
/// order (what a render uses for it: e.g. the TransferFunction of a Volume), or null.
Node* nearestInScope(Node& root, const Node& target, const NodeType& type);

} // namespace volsg
