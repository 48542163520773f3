#include <volsg/volumescene/SceneForFile.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>

#include <glm/gtc/quaternion.hpp>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/core/Error.h>
#include <volsg/io/ReadContext.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/GltfModel.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/MatrixTransform.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/volume/DataHistogram.h>
#include <volsg/voxelfile/VoxelFile.h>
#include <volsg/voxelfile/VoxelFileScene.h>

namespace volsg {

namespace {

std::string lowerName(const std::string& path) {
    std::string name = std::filesystem::path(path).filename().string();
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return name;
}

bool endsWith(const std::string& name, std::string_view tail) {
    return name.size() >= tail.size() &&
           name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
}

// The first bytes of a regular file (fewer for a short one).
std::string headOf(const std::string& path, std::size_t count) {
    std::ifstream in(path, std::ios::binary);
    std::string head(count, '\0');
    in.read(head.data(), std::streamsize(count));
    head.resize(std::size_t(std::max<std::streamsize>(0, in.gcount())));
    return head;
}

int dataTypeOf(VoxelType type) {
    switch (type) {
    case VoxelType::UShort:
        return VolumeData::USHORT;
    case VoxelType::Short:
        return VolumeData::SHORT;
    case VoxelType::Float:
        return VolumeData::FLOAT;
    default:
        return VolumeData::UBYTE;
    }
}

std::vector<glm::vec2> pointsOf(const PiecewiseLinear& channel) {
    std::vector<glm::vec2> out;
    for (const auto& p : channel.points())
        out.emplace_back(float(p.x), float(p.y));
    return out;
}

// A camera looking along `forward` with `up`, framing `box`.
ref_ptr<PerspectiveCamera> framingCamera(const Box3& box, const glm::dvec3& forward,
                                         const glm::dvec3& up) {
    auto camera = PerspectiveCamera::create();
    // The rotation taking the camera's -z to `forward` and +y to `up`.
    const glm::dvec3 back = -glm::normalize(forward);
    const glm::dvec3 right = glm::normalize(glm::cross(up, back));
    const glm::dmat3 basis(right, glm::cross(back, right), back);
    const glm::dquat q = glm::quat_cast(basis);
    const double angle = glm::angle(q);
    const glm::dvec3 axis = angle > 1e-12 ? glm::axis(q) : glm::dvec3(0, 0, 1);
    camera->orientation = Rotation{glm::vec3(axis), float(angle)};
    if (!box.isEmpty()) camera->viewAll(box, 1.0);
    return camera;
}

const char* const kVolumeSuffixes[] = {".nrrd",   ".nhdr", ".mhd",    ".mha", ".nii",
                                       ".nii.gz", ".hdr",  ".hdr.gz", ".dcm"};

} // namespace

const std::vector<std::string>& openableFileSuffixes() {
    static const std::vector<std::string> suffixes = [] {
        std::vector<std::string> out{".iv", ".wrl", ".vsgv", ".gltf", ".glb", ".raw", ".raw.gz"};
        out.insert(out.end(), std::begin(kVolumeSuffixes), std::end(kVolumeSuffixes));
        return out;
    }();
    return suffixes;
}

bool needsRawLayout(const std::string& path) {
    const std::string name = lowerName(path);
    if (endsWith(name, ".raw") || endsWith(name, ".raw.gz")) return true;
    if (!endsWith(name, ".gz")) return false;
    for (const char* tail : kVolumeSuffixes)
        if (endsWith(name, tail)) return false;
    return true;
}

FileKind fileKindOf(const std::string& path, const OpenFileOptions& options) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return FileKind::Volume; // a DICOM series
    if (!std::filesystem::exists(path, ec))
        throw Error("cannot open file: No such file or directory", path);
    // Never open a FIFO or device to sniff it: the read would block or never end.
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error("cannot open file: not a regular file or folder", path);
    const std::string name = lowerName(path);
    const std::string head = headOf(path, 132);
    if (endsWith(name, ".vsgv") ||
        hasVoxelFileMagic(std::as_bytes(std::span<const char>(head.data(), head.size()))))
        return FileKind::VoxelFile;
    if (head.rfind("#Inventor", 0) == 0 || head.rfind("#VRML", 0) == 0 || endsWith(name, ".iv"))
        return FileKind::Scene;
    if (endsWith(name, ".gltf") || endsWith(name, ".glb")) return FileKind::Gltf;
    for (const char* tail : kVolumeSuffixes)
        if (endsWith(name, tail)) return FileKind::Volume;
    if (head.size() == 132 && head.compare(128, 4, "DICM") == 0) return FileKind::Volume;
    if (options.raw) return FileKind::Volume;
    if (endsWith(name, ".raw") || endsWith(name, ".raw.gz") || endsWith(name, ".gz"))
        throw Error("a raw volume needs its layout: give --dims X Y Z --type "
                    "uchar|ushort|short|float (and --spacing SX SY SZ)",
                    path);
    throw Error("not a file volsg opens: not a scene (no '#Inventor' header), and not a volume "
                "(.nrrd .nhdr .mhd .mha .nii .nii.gz, DICOM), .gltf/.glb or .vsgv by its name; "
                "for raw voxels give --dims X Y Z --type T",
                path);
}

ref_ptr<Node> sceneForVolumeFile(const std::string& path, const OpenFileOptions& options) {
    const ref_ptr<VolumeGrid> grid = readVolume(path, options.raw ? &*options.raw : nullptr);
    std::filesystem::path file(path);
    if (file.filename().empty()) file = file.parent_path(); // "head.zarr/" names head.zarr

    auto data = VolumeData::create();
    data->fileName = file.filename().string();
    if (options.raw) {
        const RawVolumeLayout& raw = *options.raw;
        data->dimensions = glm::vec3(raw.dimensions);
        data->dataType.setValue(dataTypeOf(raw.type));
        data->byteOrder.setValue(raw.bigEndian ? VolumeData::BIG_ENDIAN_ORDER
                                               : VolumeData::LITTLE_ENDIAN_ORDER);
        data->headerSkip = std::uint32_t(raw.headerSkip);
        data->spacing = glm::vec3(raw.spacing);
    }
    data->adoptLoaded(grid, file.parent_path().string());

    const TransferFunction1D chosen = transferFunctionFromHistogram(histogramOf(*grid));
    auto transfer = TransferFunction::create();
    transfer->dataRange = glm::vec2(*chosen.dataRange());
    transfer->red = pointsOf(chosen.channel(TransferFunction1D::Red));
    transfer->green = pointsOf(chosen.channel(TransferFunction1D::Green));
    transfer->blue = pointsOf(chosen.channel(TransferFunction1D::Blue));
    transfer->alpha = pointsOf(chosen.channel(TransferFunction1D::Alpha));

    // The box in the world the scene draws it in: the patient's, when the file says where.
    Box3 local;
    local.extendBy(-0.5 * grid->extent());
    local.extendBy(0.5 * grid->extent());
    const VolumeGeometry& g = grid->geometry();
    const glm::dmat4 placement =
        g.known ? g.localToPatient(grid->dimensions(), grid->spacing()) : glm::dmat4(1.0);
    Box3 world;
    world.extendBy(local, placement);

    auto root = Separator::create();
    // From the patient's front (LPS: anterior is -y), head up (+z).
    root->addChild(framingCamera(world, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}));
    if (g.known) {
        auto transform = MatrixTransform::create();
        transform->matrix = glm::mat4(placement);
        root->addChild(transform);
    }
    root->addChild(data);
    root->addChild(transfer);
    root->addChild(Volume::create());
    return root;
}

ref_ptr<Node> sceneForGltfFile(const std::string& path) {
    const std::filesystem::path file(path);
    auto model = GltfModel::create();
    model->fileName = file.filename().string();
    model->readDone(ReadContext{path, file.parent_path().string()});
    model->asset(); // read now: a broken file is an error here, naming it
    auto light = DirectionalLight::create();
    light->direction = glm::vec3(-0.3f, -0.4f, -1.0f);
    auto root = Separator::create();
    root->addChild(light);
    root->addChild(model);
    const Box3 box = computeBoundingBox(*root);
    root->insertChild(framingCamera(box, {0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}), 0);
    return root;
}

ref_ptr<Node> readSceneForFile(const std::string& path, const OpenFileOptions& options) {
    switch (fileKindOf(path, options)) {
    case FileKind::Volume:
        return sceneForVolumeFile(path, options);
    case FileKind::Gltf:
        return sceneForGltfFile(path);
    default:
        return readSceneOrVoxelFile(path);
    }
}

std::string scenePathForSaving(const std::string& path, const OpenFileOptions& options) {
    FileKind kind;
    try {
        kind = fileKindOf(path, options);
    } catch (const Error&) {
        return path;
    }
    if (kind == FileKind::Scene) return path;
    std::filesystem::path p(path);
    std::error_code ec;
    if (std::filesystem::is_directory(p, ec)) {
        if (p.filename().empty()) p = p.parent_path(); // "series/" -> "series"
    } else {
        while (p.has_extension() && p.extension() != ".iv")
            p.replace_extension(); // chest.raw.gz -> chest
    }
    return p.string() + ".iv";
}

} // namespace volsg
