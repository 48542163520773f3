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

class State;
class Volume;

/// Every Volume node a render would draw, as the reference ray caster describes it (in
/// traversal order), from the state at the node:
/// - data and tags: the nearest VolumeData in scope; model: the model matrix at the Volume;
/// - transferFunctions: every TransferFunction in scope by tag (a later one for the same tag
///   replaces an earlier one; Separators scope them as any property);
/// - mode and planeOpacity: the Volume's renderMode and planeOpacity fields;
/// - boxClip: the nearest BoxClip, its box in the BoxClip's own coordinates (its model matrix
///   is RayCastBoxClip::model), so a Transform between BoxClip and Volume moves the volume,
///   not the box;
/// - clipPlanes: every ClipPlane in scope that is on, in world coordinates.
/// Throws Error for a Volume with no VolumeData in scope ("Volume without VolumeData in
/// scope": the GL path has nothing to draw either, and silently dropping it would hide a
/// broken scene from the error measurement), when a volume's data cannot be loaded, and for
/// an invalid TransferFunction.
std::vector<RayCastVolume> collectVolumes(Node& root);

/// One Volume node as collectVolumes() describes it, from the state at the node (after its
/// doAction): for whatever else walks a graph and needs the reference's view of a volume, such
/// as picking a volume by its content. Throws Error as collectVolumes() does.
RayCastVolume describeVolume(const Volume& volume, const State& state);
/// The Volume's description from the volume in scope at it (gatherVolumeInScope): its mode
/// and planeOpacity added.
RayCastVolume describeVolume(const Volume& volume, VolumeInScope scope);

/// The camera of a render of `root` with these options, as the ray caster takes it: the
/// options' camera or findOrMakeCamera(), with Camera::projectionMatrix(width / height) as
/// the GL Renderer uses, and rays clipped to near and far as GL clips. Throws Error for an
/// empty size.
RayCastCamera referenceCamera(Node& root, const RenderOptions& options);

/// The reference image of a scene: opaque geometry from the GL renderer (colour and depth,
/// volumes left out), then the volumes by ReferenceRayCaster over it, on referenceCamera().
/// Transparent geometry is NOT included (a documented limitation: compare scenes without it).
/// Planar sections with ALPHA_OPAQUE or ALPHA_BINARY are opaque geometry, so they are in it
/// (GL-drawn, ending the rays at their depth; their own colour is checked against SliceSampler,
/// lib/volsg/sections/README.md); ALPHA_AS_IS sections, being transparent, are not. A clipping
/// OrthoSlice clips the volumes here as in GL (it puts a ClipPlane in scope).
/// Needs a current GL context. `details` receives the caster's result (error bound, ...).
Image renderReference(Node& root, const RenderOptions& options, RayCastResult* details = nullptr,
                      const RayCastOptions& rayOptions = {});

} // namespace volsg
