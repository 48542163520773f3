// Planar sections draw the volume in scope on their plane (lib/volsg/sections).
#include <volsg/nodes/ObliqueSlice.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/render/BuiltinRendering.h>
#include <volsg/render/RenderAction.h>
#include <volsg/sections/SliceRenderer.h>
#include <volsg/volumescene/VolumeInScope.h>

namespace volsg {

namespace {

void renderOrthoSlice(RenderAction& action, OrthoSlice& slice) {
    action.needFloatTarget();
    // The slice itself is not clipped by its own plane: it draws before the plane is in scope.
    if (const auto volume = gatherVolumeInScope(action.state()))
        SliceRenderer::draw(action.frame(), *volume, slice.localPlane(*volume->data),
                            slice.style());
    slice.doAction(action);
}

void renderObliqueSlice(RenderAction& action, ObliqueSlice& slice) {
    action.needFloatTarget();
    const auto plane = slice.localPlane();
    if (!plane) return;
    if (const auto volume = gatherVolumeInScope(action.state()))
        SliceRenderer::draw(action.frame(), *volume, *plane, slice.style());
}

} // namespace

void addSliceRenderMethods(ActionMethods& methods) {
    methods.add(&renderOrthoSlice);
    methods.add(&renderObliqueSlice);
}

} // namespace volsg
