#include <volsg/voxelfile/PackedVolume.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>

#include <volsg/core/Error.h>
#include <volsg/io/ReadContext.h>

namespace volsg {

namespace {

struct CachedFile {
    std::uintmax_t size = 0;
    std::filesystem::file_time_type time;
    std::shared_ptr<const VoxelFileContent> content;
};

std::string pairText(double a, double b) {
    std::ostringstream out;
    out << a << ' ' << b;
    return out.str();
}

const char* sourceName(ObjectSource::Kind kind) {
    return kind == ObjectSource::Tag         ? "TAG"
           : kind == ObjectSource::Threshold ? "THRESHOLD"
                                             : "WHOLE";
}

const char* selectionName(VoxelSelection selection) {
    return selection == VoxelSelection::Surface    ? "SURFACE"
           : selection == VoxelSelection::Gradient ? "GRADIENT"
                                                   : "VISIBLE";
}

} // namespace

std::shared_ptr<const VoxelFileContent> loadVoxelFileCached(const std::string& path) {
    static std::mutex mutex;
    static std::map<std::string, CachedFile> cache;
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
    const std::string key = ec ? path : absolute.lexically_normal().string();
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error("cannot open voxel file: " + ec.message(), path);
    const auto time = std::filesystem::last_write_time(path, ec);
    {
        std::lock_guard lock(mutex);
        const auto it = cache.find(key);
        if (it != cache.end() && it->second.size == size && it->second.time == time)
            return it->second.content;
    }
    auto content = std::make_shared<const VoxelFileContent>(readVoxelFileFromPath(path));
    std::lock_guard lock(mutex);
    cache[key] = {size, time, content};
    return content;
}

PackedVolume PackedVolume::load(const std::string& reference, const std::string& directory) {
    std::string path = reference;
    std::uint32_t volume = 0;
    const std::size_t hash = reference.rfind('#');
    if (hash != std::string::npos && hash + 1 < reference.size() &&
        reference.find_first_not_of("0123456789", hash + 1) == std::string::npos &&
        reference.size() - hash - 1 <= 9) {
        path = reference.substr(0, hash);
        volume = std::uint32_t(std::stoul(reference.substr(hash + 1)));
    }
    if (path.empty()) throw Error("ShearWarpVolume voxelFile '" + reference + "' names no file");
    PackedVolume out;
    out.fileName_ = ReadContext{{}, directory}.resolve(path);
    out.volume_ = volume;
    out.file_ = loadVoxelFileCached(out.fileName_);
    for (const PackedObject& o : out.file_->objects)
        if (o.volumeIndex == volume) {
            if (o.objectIndex >= out.file_->objects.size())
                throw Error("object index " + std::to_string(o.objectIndex) + " of volume " +
                                std::to_string(volume) + " is beyond the file's objects",
                            out.fileName_);
            if (out.objects_.size() <= o.objectIndex) out.objects_.resize(o.objectIndex + 1);
            out.objects_[o.objectIndex] = &o;
        }
    if (out.objects_.empty())
        throw Error("the file holds no objects of volume " + std::to_string(volume) +
                        " (ShearWarpVolume voxelFile '" + reference + "')",
                    out.fileName_);
    for (std::size_t i = 0; i < out.objects_.size(); ++i)
        if (!out.objects_[i])
            throw Error("volume " + std::to_string(volume) + " lacks object " + std::to_string(i),
                        out.fileName_);
    return out;
}

std::string PackedVolume::describe(std::size_t index) const {
    return "VolumeObject " + std::to_string(index) + " of ShearWarpVolume voxelFile volume " +
           std::to_string(volume_);
}

const PackedObject& PackedVolume::object(std::size_t index) const {
    if (index >= objects_.size())
        throw Error("the scene has more VolumeObjects than the " + std::to_string(objects_.size()) +
                        " stored for volume " + std::to_string(volume_) +
                        ": a new object needs a new extraction from the original volume",
                    fileName_);
    return *objects_[index];
}

ref_ptr<VoxelObject> PackedVolume::voxels(std::size_t index, const ExtractionSpec& current) const {
    const PackedObject& stored = object(index);
    const ExtractionRecord& e = stored.extraction;
    auto changed = [&](const std::string& field, const std::string& now, const std::string& then) {
        throw Error(describe(index) + ": field '" + field + "' is " + now +
                        " but the stored voxels were extracted with " + then +
                        "; a new extraction needs the original volume (without it only "
                        "transfer functions, render modes, compositing, opacities, clipping and "
                        "the camera can change)",
                    fileName_);
    };
    if (current.source.kind != e.source.kind)
        changed("source", sourceName(current.source.kind), sourceName(e.source.kind));
    if (e.source.kind == ObjectSource::Tag && current.source.tag != e.source.tag)
        changed("tag", std::to_string(current.source.tag), std::to_string(e.source.tag));
    if (e.source.kind == ObjectSource::Threshold &&
        (current.source.low != e.source.low || current.source.high != e.source.high))
        changed("threshold", pairText(current.source.low, current.source.high),
                pairText(e.source.low, e.source.high));
    if (current.selection != e.selection)
        changed("voxels", selectionName(current.selection), selectionName(e.selection));
    if (e.selection == VoxelSelection::Gradient && current.gradientThreshold != e.gradientThreshold)
        changed("gradientThreshold", std::to_string(current.gradientThreshold),
                std::to_string(e.gradientThreshold));
    // The 12-bit values were normalised over this range: another one would shift them all.
    if (const auto& range = current.transferFunction.dataRange(); range && *range != e.dataRange)
        changed("dataRange' of its TransferFunction (the values' normalisation)",
                pairText(range->x, range->y), pairText(e.dataRange.x, e.dataRange.y));
    return stored.voxels;
}

void PackedVolume::checkObjectCount(std::size_t count) const {
    if (count != objects_.size())
        throw Error("the scene's ShearWarpVolume has " + std::to_string(count) +
                        " VolumeObjects, the file stores " + std::to_string(objects_.size()) +
                        " for volume " + std::to_string(volume_) +
                        ": adding or removing objects needs a new extraction from the volume",
                    fileName_);
}

Box3 PackedVolume::localBounds() const {
    const VoxelObject& first = *objects_.front()->voxels;
    const glm::dvec3 half = 0.5 * glm::dvec3(first.dimensions()) * first.spacing();
    Box3 box;
    box.extendBy(-half);
    box.extendBy(half);
    return box;
}

} // namespace volsg
