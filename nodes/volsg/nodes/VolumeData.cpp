#include <volsg/nodes/VolumeData.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/io/ReadContext.h>
#include <volsg/paging/PagedVolume.h>
#include <volsg/volume/AttractorBasin.h>
#include <volsg/volume/TestVolumes.h>
#include <volsg/volume/VolumeGrid.h>
#include <volsg/volumeio/VolumeReader.h>

namespace volsg {

const EnumValues VolumeData::dataTypeNames{
    {"UBYTE", UBYTE}, {"USHORT", USHORT}, {"SHORT", SHORT}, {"FLOAT", FLOAT}};
const EnumValues VolumeData::tagDataTypeNames{{"UBYTE", UBYTE}, {"USHORT", USHORT}};
// The file names are Inventor's; the C++ names avoid libc's LITTLE_ENDIAN/BIG_ENDIAN macros.
const EnumValues VolumeData::byteOrderNames{{"LITTLE_ENDIAN", LITTLE_ENDIAN_ORDER},
                                            {"BIG_ENDIAN", BIG_ENDIAN_ORDER}};
const EnumValues VolumeData::generatorNames{{"NONE", NONE},
                                            {"MARSCHNER_LOBB", MARSCHNER_LOBB},
                                            {"SOFT_SPHERE", SOFT_SPHERE},
                                            {"THIN_SHELL", THIN_SHELL},
                                            {"RAMP16", RAMP16},
                                            {"LABELLED", LABELLED},
                                            {"ATTRACTOR_BASIN", ATTRACTOR_BASIN}};
const EnumValues VolumeData::pagingNames{{"AUTO", AUTO}, {"ON", ON}, {"OFF", OFF}};

namespace {

/// Side of a generated volume when `dimensions` is left at 0.
constexpr int defaultGeneratedSide = 64;

VoxelType voxelTypeOf(int dataType) {
    switch (dataType) {
    case VolumeData::USHORT:
        return VoxelType::UShort;
    case VolumeData::SHORT:
        return VoxelType::Short;
    case VolumeData::FLOAT:
        return VoxelType::Float;
    default:
        return VoxelType::UByte;
    }
}

/// The dimensions field as whole voxel counts; all zero means "not given".
glm::ivec3 wholeDimensions(const glm::vec3& d) {
    glm::ivec3 out(0);
    for (int a = 0; a < 3; ++a) {
        if (!std::isfinite(d[a]) || d[a] < 0.0f || d[a] != std::floor(d[a]) || d[a] > 1e9f)
            throw Error("VolumeData dimensions must be whole numbers >= 1, got " +
                        std::to_string(d.x) + " " + std::to_string(d.y) + " " +
                        std::to_string(d.z));
        out[a] = int(d[a]);
    }
    if (out != glm::ivec3(0) && (out.x < 1 || out.y < 1 || out.z < 1))
        throw Error("VolumeData dimensions must be >= 1 each (or all 0 for a generator's default)");
    return out;
}

/// The side of a cubic generated volume: the dimensions field (which must then be cubic), or
/// the default.
int cubicSide(const glm::ivec3& d, const char* generator) {
    if (d == glm::ivec3(0)) return defaultGeneratedSide;
    if (d.x != d.y || d.y != d.z)
        throw Error(std::string("VolumeData generator ") + generator +
                    " makes cubic volumes: give equal dimensions");
    return d.x;
}

/// Reads one volume file (data or labels) by its extension: NRRD and MetaImage headers say
/// everything; any other file is raw and takes the node's raw fields (a label file takes
/// tagDataType, the same dimensions and byte order, and no header skip).
ref_ptr<VolumeGrid> readVolumeFile(const VolumeData& node, const std::string& path,
                                   const glm::ivec3& dims, bool labels) {
    RawVolumeLayout raw;
    raw.dimensions = dims;
    raw.type =
        labels ? (node.tagDataType() == VolumeData::USHORT ? VoxelType::UShort : VoxelType::UByte)
               : voxelTypeOf(node.dataType());
    raw.bigEndian = node.byteOrder() == VolumeData::BIG_ENDIAN_ORDER;
    raw.headerSkip = labels ? 0 : node.headerSkip();
    raw.spacing = glm::dvec3(node.spacing());
    // Without dimensions there is no raw layout: readVolume() then says a raw file needs one.
    ref_ptr<VolumeGrid> grid = readVolume(path, dims == glm::ivec3(0) ? nullptr : &raw);
    if (labels && !grid->isLabelType())
        throw Error("tag volume must hold UBYTE or USHORT labels, not " +
                        std::string(voxelTypeName(grid->type())),
                    path);
    return grid;
}

/// The host budget of a paged volume, in bytes.
std::uint64_t hostBudgetOf(const VolumeData& node) {
    return std::uint64_t(node.memoryBudget()) << 20;
}

/// The OME-Zarr folder to page the data from, when fileName is one that paging asks to page
/// (AUTO: level 0 larger than memoryBudget); else empty. Reads the pyramid's metadata only.
std::string pagedPath(const VolumeData& node, const std::string& directory) {
    if (node.fileName().empty() || node.paging() == VolumeData::OFF || !node.tagFileName().empty())
        return "";
    const std::string path = ReadContext{{}, directory}.resolve(node.fileName());
    if (!isZarrFolder(path)) return "";
    if (node.paging() == VolumeData::AUTO) {
        const PyramidSource source(path, 0);
        const glm::ivec3 d = source.level(0).dimensions;
        const std::uint64_t bytes = std::uint64_t(d.x) * std::uint64_t(d.y) * std::uint64_t(d.z) *
                                    voxelTypeSize(source.type());
        if (bytes <= hostBudgetOf(node)) return "";
    }
    return path;
}

/// The pyramid to page the data from (pagedPath), or null.
std::shared_ptr<PagedVolume> openPaged(const VolumeData& node, const std::string& directory) {
    const std::string path = pagedPath(node, directory);
    if (path.empty()) return nullptr;
    PagedVolumeOptions options;
    options.hostBudget = hostBudgetOf(node);
    // A small budget keeps a smaller stand-in and chunk cache, leaving most of it to bricks.
    options.standInBytes = std::min(options.standInBytes, options.hostBudget / 16);
    options.chunkCacheBytes = std::min(options.chunkCacheBytes, options.hostBudget / 8);
    return std::make_shared<PagedVolume>(path, options);
}

/// The data (and label) volumes named by fileName and tagFileName, relative names resolved
/// against the scene file's folder.
ref_ptr<VolumeGrid> loadFromFiles(const VolumeData& node, const std::string& directory,
                                  const glm::ivec3& dims, ref_ptr<VolumeGrid>& tags) {
    if (node.fileName().empty()) throw Error("VolumeData has neither a fileName nor a generator");
    const ReadContext where{{}, directory};
    ref_ptr<VolumeGrid> data = readVolumeFile(node, where.resolve(node.fileName()), dims, false);
    // A header's own spacing stands unless the scene sets one (raw files took it already).
    if (!node.spacing.isDefault()) data->setSpacing(glm::dvec3(node.spacing()));
    if (!node.tagFileName().empty()) {
        tags = readVolumeFile(node, where.resolve(node.tagFileName()), dims, true);
        tags->setSpacing(data->spacing()); // labels name the data's cells
    }
    return data;
}

} // namespace

VolumeData::~VolumeData() = default;

void VolumeData::readDone(const ReadContext& context) {
    directory_ = context.directory;
}

void VolumeData::adoptLoaded(ref_ptr<const VolumeGrid> data, const std::string& directory) {
    directory_ = directory;
    grid_ = std::move(data);
    tags_ = nullptr;
    paged_ = nullptr;
    loadedVersion_ = version();
}

void VolumeData::doAction(Action& action) {
    action.state().add(*this);
}

Box3 VolumeData::localBounds() const {
    const ref_ptr<const VolumeGrid> data = grid();
    Box3 box;
    if (!data) return box;
    const glm::dvec3 half = 0.5 * data->extent();
    box.extendBy(-half);
    box.extendBy(half);
    return box;
}

void VolumeData::loadIfChanged() const {
    if (loadedVersion_ == version()) return;
    try {
        load();
    } catch (const Error& e) {
        // Said of this node where it stands in the scene file (the error itself may name the
        // data file), wherever the traversal that needed the data was.
        if (e.namesSceneNode() || !sourcePlace().file) throw;
        throw Error::atSceneNode(e, description(), *sourcePlace().file, sourcePlace().line,
                                 sourcePlace().column);
    }
}

ref_ptr<const VolumeGrid> VolumeData::grid() const {
    loadIfChanged();
    return grid_;
}

std::shared_ptr<PagedVolume> VolumeData::pagedVolume() const {
    loadIfChanged();
    return paged_;
}

bool VolumeData::pagesFromPyramid() const {
    if (generator() != NONE) return false;
    return !pagedPath(*this, directory_).empty();
}

ref_ptr<const VolumeGrid> VolumeData::tagGrid() const {
    loadIfChanged();
    return tags_;
}

void VolumeData::load() const {
    // Drop what was loaded before, so a failed reload never leaves stale data behind.
    grid_ = nullptr;
    tags_ = nullptr;
    paged_ = nullptr;
    ref_ptr<VolumeGrid> data, tags;
    const glm::ivec3 dims = wholeDimensions(dimensions());

    switch (generator()) {
    case MARSCHNER_LOBB:
        data = makeMarschnerLobb(cubicSide(dims, "MARSCHNER_LOBB"), voxelTypeOf(dataType()));
        break;
    case SOFT_SPHERE:
        data = makeSoftSphere(cubicSide(dims, "SOFT_SPHERE"), voxelTypeOf(dataType()));
        break;
    case THIN_SHELL: {
        const int n = cubicSide(dims, "THIN_SHELL");
        data = makeThinShell(n, 0.35 * n, 1.5);
        break;
    }
    case RAMP16: {
        // 0 at the first voxel along x to 65535 at the last: every 16-bit value in use.
        const glm::ivec3 d = dims == glm::ivec3(0) ? glm::ivec3(defaultGeneratedSide) : dims;
        data = makeRamp(d, VoxelType::UShort, 0, 0.0, 65535.0);
        break;
    }
    case LABELLED: {
        LabelledVolume labelled = makeLabelledVolume(cubicSide(dims, "LABELLED"));
        data = labelled.data;
        tags = labelled.tags;
        break;
    }
    case ATTRACTOR_BASIN: {
        AttractorBasinVolume generated = makeAttractorBasin(cubicSide(dims, "ATTRACTOR_BASIN"));
        data = generated.data;
        tags = generated.tags;
        break;
    }
    default:
        if ((paged_ = openPaged(*this, directory_))) {
            if (!spacing.isDefault())
                throw Error("VolumeData: a paged volume takes its spacing from its pyramid; "
                            "leave spacing unset or set paging OFF");
            grid_ = paged_->standIn();
            loadedVersion_ = version();
            return;
        }
        data = loadFromFiles(*this, directory_, dims, tags);
        break;
    }

    // Generators have their own spacing; a spacing written in the scene replaces it.
    if (generator() != NONE && !spacing.isDefault()) {
        data->setSpacing(glm::dvec3(spacing()));
        if (tags) tags->setSpacing(glm::dvec3(spacing()));
    }
    // Every path normalises values by (v - min) / (max - min) in single precision: finite
    // FLOAT values whose span is not finite there would all map to 0 (a blank image).
    if (data->type() == VoxelType::Float) {
        const auto [low, high] = data->minMax();
        if (!(high - low <= double(std::numeric_limits<float>::max()))) {
            char text[96];
            std::snprintf(text, sizeof text, "FLOAT voxel values span %.3g to %.3g", low, high);
            throw Error(std::string(text) +
                        ", wider than single precision holds (3.4e38): rescale the data");
        }
    }
    if (tags && tags->dimensions() != data->dimensions())
        throw Error("VolumeData tag volume '" + tagFileName() +
                    "' does not have the dimensions of the data volume");
    grid_ = data;
    tags_ = tags;
    loadedVersion_ = version();
}

} // namespace volsg
