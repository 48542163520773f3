#pragma once
// Opening any file volsg reads as a scene: scene files as they are, and data files (volumes,
// glTF models) wrapped in the scene that shows them, so `volsg-view FILE` and
// `volsg-render FILE` need no hand-written scene (docs/SCENE-FORMAT.md section 3.8).

#include <optional>
#include <string>
#include <vector>

#include <volsg/core/Node.h>
#include <volsg/volumeio/VolumeReader.h>

namespace volsg {

/// What a data file cannot say about itself.
struct OpenFileOptions {
    /// The layout of a headerless raw volume (`--dims X Y Z --type T --spacing SX SY SZ`);
    /// with it, a file of any name that is not recognised otherwise opens as raw voxels.
    std::optional<RawVolumeLayout> raw;
};

/// How a file is opened, told by its name and its first bytes (never by parsing it as a scene,
/// so a binary file's bytes never appear in a message).
enum class FileKind {
    Scene,     ///< Inventor or VRML 1.0 text or binary (.iv, or a '#Inventor'/'#VRML' header)
    VoxelFile, ///< .vsgv written by volsg-pack
    Volume,    ///< a volume file or DICOM folder VolumeReader reads (raw with options.raw)
    Gltf,      ///< .gltf or .glb
};

/// The kind of `path`; throws Error naming the file when it is none of them (a file of unknown
/// name that is not a scene: the message says how to open it as raw voxels).
FileKind fileKindOf(const std::string& path, const OpenFileOptions& options = {});

/// The name endings (lower case) of the files volsg opens: scenes, .vsgv, the volume formats,
/// glTF, and raw voxels (.raw, .raw.gz, which need a layout: needsRawLayout). A file browser
/// lists these; fileKindOf decides by name and content.
const std::vector<std::string>& openableFileSuffixes();

/// Whether `path` is named as raw voxels (.raw, .raw.gz, or .gz not of a known format), which
/// open only with a RawVolumeLayout.
bool needsRawLayout(const std::string& path);

/// The scene that shows a volume file (any FileKind::Volume): a camera that frames it from the
/// patient's front (anterior, superior up: the view from -y with +z up), a MatrixTransform
/// placing the grid in patient space (LPS, mm) when the file has a geometry, the VolumeData
/// naming the file (relative to its folder) with the raw layout when there is one, a
/// TransferFunction chosen from the data's histogram with dataRange the data's minimum and
/// maximum (transferFunctionFromHistogram), and a Volume. The file is read once: the
/// VolumeData keeps the grid read here. Throws Error naming the file for a file that cannot
/// be read.
ref_ptr<Node> sceneForVolumeFile(const std::string& path, const OpenFileOptions& options = {});

/// The scene that shows a glTF model: a camera framing it from +z, a headlight-like
/// DirectionalLight and the GltfModel.
ref_ptr<Node> sceneForGltfFile(const std::string& path);

/// Any file volsg opens, as a scene: scene files and .vsgv files as readSceneOrVoxelFile reads
/// them, data files through the two functions above.
ref_ptr<Node> readSceneForFile(const std::string& path, const OpenFileOptions& options = {});

/// Where a viewer saves the scene it opened from `path`: the scene file itself, or for a data
/// file a new `.iv` beside it (`chest.nii.gz` -> `chest.iv`, a DICOM folder `series` ->
/// `series.iv` beside the folder) whose VolumeData names the data file relatively.
std::string scenePathForSaving(const std::string& path, const OpenFileOptions& options = {});

} // namespace volsg
