#pragma once
// The render methods of the library's node types, one file per family
// (nodes/volsg/render/*Rendering.cpp).

#include <volsg/actions/ActionMethods.h>

namespace volsg {

void addShapeRenderMethods(ActionMethods& methods);
void addSeparatorRenderMethods(ActionMethods& methods);
/// Whether nodes of `type` draw with the shapes' render method (ShapeRendering.cpp).
bool rendersAsShape(const NodeType& type);
void addVolumeRenderMethods(ActionMethods& methods);
void addShearWarpRenderMethods(ActionMethods& methods);
void addSliceRenderMethods(ActionMethods& methods);
void addGltfRenderMethods(ActionMethods& methods);
void addInventorRenderMethods(ActionMethods& methods);
void addTextRenderMethods(ActionMethods& methods);

inline void addBuiltinRenderMethods(ActionMethods& methods) {
    addShapeRenderMethods(methods);
    addSeparatorRenderMethods(methods);
    addVolumeRenderMethods(methods);
    addShearWarpRenderMethods(methods);
    addSliceRenderMethods(methods);
    addGltfRenderMethods(methods);
    addInventorRenderMethods(methods);
    addTextRenderMethods(methods);
}

} // namespace volsg
