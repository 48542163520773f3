#pragma once
// The bridge from a scene graph to the reference ray caster: which volumes a render of the
// graph contains (with their state: data, transfer functions, clip planes, BoxClip, model
// matrix), and the reference image of the whole scene.

#include <vector>

#include <volsg/core/Node.h>
#include <volsg/image/Image.h>
#include <volsg/reference/ReferenceRayCaster.h>
#include <volsg/render/Renderer.h>

namespace volsg {

/// Every Volume node a render would draw, as the reference ray caster describes it (in
/// traversal order). Throws Error when a volume's data cannot be loaded.
std::vector<RayCastVolume> collectVolumes(Node& root);

/// The reference image of a scene: opaque geometry from the GL renderer (colour and depth,
/// volumes left out), then the volumes by ReferenceRayCaster over it, then transparent
/// geometry is NOT included (documented limitation). Needs a current GL context.
Image renderReference(Node& root, const RenderOptions& options, RayCastResult* details = nullptr,
                      const RayCastOptions& rayOptions = {});

} // namespace volsg
