#include "OwnPartLoading.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <vector>

#include <volsg/actions/SearchAction.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/sortlast/KdVolumeSplit.h>
#include <volsg/volumeio/VolumeReader.h>

namespace volsg::cli {

namespace fs = std::filesystem;

OwnPartLoad loadOwnPart(Node& root, const std::string& sceneFile, int part, int parts,
                        bool underTarget) {
    OwnPartLoad load;
    const std::vector<Node*> data = findAll(root, VolumeData::classType(), true);
    if (data.size() != 1) {
        load.whyNot = "the scene has " + std::to_string(data.size()) + " VolumeData nodes";
        return load;
    }
    VolumeData& node = *static_cast<VolumeData*>(data.front());
    if (node.isA<VolumeSeries>() || node.generator() != VolumeData::NONE ||
        node.fileName().empty()) {
        load.whyNot = "the VolumeData reads no single file";
        return load;
    }
    if (!node.tagFileName().empty()) {
        load.whyNot = "the VolumeData has labels (read whole, with the data)";
        return load;
    }
    fs::path path(node.fileName());
    if (path.is_relative()) path = fs::path(sceneFile).parent_path() / path;
    if (!isZarrFolder(path.string())) {
        load.whyNot = "the VolumeData's file is not an OME-Zarr image";
        return load;
    }
    if (node.pagesFromPyramid()) {
        load.paged = true;
        return load;
    }
    for (const Node* v : findAll(root, Volume::classType(), true))
        if (static_cast<const Volume*>(v)->errorTarget() > 0.0f && !underTarget) {
            load.whyNot = "the Volume draws to an error target, whose slabs may reach across the "
                          "parts: every process reads the image whole, so the frame is one "
                          "process's (--mpi-own-chunks reads only each part, and meets the target "
                          "without being one process's within 1/255)";
            return load;
        }
    const auto started = std::chrono::steady_clock::now();
    const glm::ivec3 dims = readOmeZarrDimensions(path.string());
    // The split the slicer will make (FrameContext::partition) from the grid's dimensions and
    // spacing: the level's, or the scene's where it sets one (as VolumeData's own reading).
    glm::dvec3 spacing = glm::dvec3(node.spacing());
    if (node.spacing.isDefault())
        spacing = readOmeZarrRegion(path.string(), 0, glm::ivec3(0), glm::ivec3(1))->spacing();
    const KdVolumeSplit split(dims, spacing, parts);
    glm::ivec3 first, count;
    split.voxelsWithGhost(part, kOwnPartGhost, first, count);
    ref_ptr<VolumeGrid> grid;
    if (count.x > 0) {
        grid = readOmeZarrWithin(path.string(), 0, first, count);
    } else {
        // An empty part draws nothing: one voxel keeps the grid's size, spacing and geometry.
        grid = readOmeZarrWithin(path.string(), 0, glm::ivec3(0), glm::ivec3(1));
        count = glm::ivec3(1);
    }
    load.voxelsRead = double(count.x) * double(count.y) * double(count.z);
    load.type = grid->type();
    load.needsRange = grid->type() != VoxelType::UByte;
    if (load.needsRange) {
        // The box's own range (the rest of the grid is fill, not data).
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (int z = first.z; z < first.z + count.z; ++z)
            for (int y = first.y; y < first.y + count.y; ++y)
                for (int x = first.x; x < first.x + count.x; ++x) {
                    const double v = grid->value(x, y, z);
                    if (!std::isfinite(v)) continue;
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                }
        load.ownRange = {lo, hi};
    }
    grid->setSpacing(spacing);
    node.adoptLoaded(grid, fs::path(sceneFile).parent_path().string());
    load.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started)
            .count();
    load.loaded = true;
    return load;
}

void useDataRange(Node& root, glm::dvec2 range) {
    for (Node* node : findAll(root, TransferFunction::classType(), true)) {
        TransferFunction& function = *static_cast<TransferFunction*>(node);
        if (!function.dataRange.isDefault()) continue;
        function.dataRange.setValue(glm::vec2(range));
        function.dataRange.setDefault(false);
    }
}

} // namespace volsg::cli
