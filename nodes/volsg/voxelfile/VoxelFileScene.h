#pragma once
// Scenes and .vsgv files: packing a scene's ShearWarpVolume objects into one (volsg-pack),
// and opening one as a scene (volsg-render, volsg-view).

#include <string>

#include <volsg/core/Node.h>
#include <volsg/voxelfile/VoxelFile.h>

namespace volsg {

/// Extracts the objects of every ShearWarpVolume the scene draws (the state at each, as a
/// render sees it) and keeps the scene with every visualization parameter: cameras, lights,
/// transforms, transfer functions, clipping, the nodes' fields. In the stored scene the
/// VolumeData nodes are removed (their files are not shipped) and the k-th ShearWarpVolume
/// (depth first, each node once) gets `voxelFile "#k"`: volume k of the same file. Throws Error
/// when a ShearWarpVolume is not drawn (an inactive Switch child), has no VolumeData in scope
/// or draws from a voxelFile already (pack the original scene instead).
VoxelFileContent packScene(Node& root);

/// The scene of a .vsgv with each ShearWarpVolume's voxelFile "#k" made to name the file
/// itself (relative: "name.vsgv#k"), so it draws the stored objects. Throws Error for a
/// malformed file or scene.
ref_ptr<Node> readVoxelFileScene(const std::string& path);

/// A .vsgv (told by its magic, whatever the extension) through readVoxelFileScene, anything
/// else through readScene.
ref_ptr<Node> readSceneOrVoxelFile(const std::string& path);

/// The stored scene text with "#k" references replaced by `voxelFileReference + "#k"`: a
/// plain scene file next to the .vsgv that draws it.
std::string companionSceneText(const VoxelFileContent& content,
                               const std::string& voxelFileReference);

} // namespace volsg
