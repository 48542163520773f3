#pragma once
// Reads a .gltf (external or embedded buffers and images) or .glb file into a GltfAsset.

#include <string>

#include <volsg/gltf/GltfAsset.h>

namespace volsg {

/// Loads `path` through tinygltf (the container is told by the "glTF" magic, not the name)
/// and checks everything the data will be used for before touching it: buffer views inside
/// their buffers, accessors inside their views (stride, offset and count, without overflow),
/// sparse indices below the count, vertex indices below the vertex count, attribute types
/// and counts, every material, texture, image, sampler, mesh and node index, and a node tree
/// without cycles or shared children. Bad input throws Error naming the file and the element
/// ("accessors[3]: count 4294967295 exceeds bufferViews[1]"); tinygltf's own complaints are
/// passed on the same way.
///
/// Covered: every node transform (matrix or TRS) down the default scene's tree, meshes with
/// several primitives, every component type (normalized integers divided out), sparse
/// accessors (with or without a bufferView), morph targets with the mesh's default weights
/// (POSITION, NORMAL, TANGENT), triangle strips and fans (made lists), line loops and strips
/// (made lists), points; metallic-roughness materials with all five textures, alpha modes,
/// double-sidedness and KHR_materials_unlit; KHR_mesh_quantization is accepted (any
/// component type is read). Not covered: skins and animations (the bind pose is drawn),
/// node `weights` (mesh weights apply), cameras and KHR_lights_punctual in the file (the
/// scene's Inventor camera and lights apply), other extensions (an unknown *required*
/// extension is an error; unknown optional ones are ignored).
GltfAsset loadGltf(const std::string& path);

} // namespace volsg
