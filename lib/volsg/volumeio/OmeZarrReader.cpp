// readOmeZarr: one level of an OME-NGFF multiscale image over Zarr v2 arrays.
#include <volsg/volumeio/VolumeReader.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/volumeio/InputFile.h>
#include <volsg/volumeio/OmeZarrLevels.h>
#include <volsg/volumeio/VoxelPayload.h>
#include <volsg/volumeio/ZarrArray.h>
#include <volsg/volumeio/ZarrJson.h>

namespace volsg {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

class MultiscalesParser {
public:
    MultiscalesParser(std::string path, const json& root) : path_(std::move(path)) {
        if (!root.is_object() || !root.contains("multiscales"))
            fail("no \"multiscales\": not an OME-Zarr image");
        const json& list = root["multiscales"];
        if (!list.is_array() || list.empty() || !list[0].is_object())
            fail("\"multiscales\" must be a list of at least one object");
        image_ = &list[0]; // the first image, as NGFF says readers should
        const auto datasets = image_->find("datasets");
        if (datasets == image_->end() || !datasets->is_array() || datasets->empty())
            fail("multiscales[0] has no \"datasets\"");
        datasets_ = &*datasets;
    }

    [[noreturn]] void fail(const std::string& message) const { throw Error(message, path_); }

    std::size_t levelCount() const { return datasets_->size(); }

    // The dataset whose "path" is `name`, or -1.
    int levelNamed(const std::string& name) const {
        for (std::size_t i = 0; i < datasets_->size(); ++i) {
            const json& d = (*datasets_)[i];
            if (d.is_object() && d.contains("path") && d["path"] == name) return int(i);
        }
        return -1;
    }

    OmeZarrLevel level(int index) const {
        if (index < 0 || std::size_t(index) >= levelCount())
            fail("level " + std::to_string(index) + " asked for, the pyramid has levels 0.." +
                 std::to_string(levelCount() - 1));
        const json& dataset = (*datasets_)[std::size_t(index)];
        if (!dataset.is_object() || !dataset.contains("path") || !dataset["path"].is_string())
            fail("datasets[" + std::to_string(index) + "] has no \"path\"");
        OmeZarrLevel level;
        level.axisCount = axisCount();
        level.arrayFolder = InputFile::resolveBeside(path_, dataset["path"].get<std::string>());
        // Dataset scale times the image's own (NGFF 0.4 applies that one after).
        glm::dvec3 scale =
            scaleOf(dataset, "datasets[" + std::to_string(index) + "]", level.axisCount);
        if (image_->contains("coordinateTransformations"))
            scale *= scaleOf(*image_, "multiscales[0]", level.axisCount);
        level.spacing = scale;
        level.geometry = geometryOf(dataset);
        return level;
    }

private:
    // 3 to 5 axes, the last three spatial (z, y, x) and the others time or channel.
    std::size_t axisCount() const {
        const auto axes = image_->find("axes");
        if (axes == image_->end()) return 0; // NGFF before 0.3: z, y, x last
        if (!axes->is_array() || axes->size() < 3 || axes->size() > 5)
            fail("\"axes\" must list 3 to 5 axes, got " + axes->dump());
        for (std::size_t i = 0; i < axes->size(); ++i) {
            const json& a = (*axes)[i];
            const json name = a.is_object() ? a.value("name", json()) : a;
            const std::string type =
                a.is_object() && a.contains("type") && a["type"].is_string() ? a["type"] : "";
            const bool spatial =
                type == "space" || (type.empty() && (name == "z" || name == "y" || name == "x"));
            if (spatial != (i + 3 >= axes->size()))
                fail("axes " + axes->dump() +
                     ": volsg reads images whose last three axes (and only those) are spatial");
        }
        return axes->size();
    }

    // The patient placement volsg-pyramid keeps in multiscales[0].metadata.volsg, moved to
    // this level's voxel (0,0,0) by its translation; unknown without it.
    VolumeGeometry geometryOf(const json& dataset) const {
        VolumeGeometry geometry;
        const json* volsg = nullptr;
        if (const auto m = image_->find("metadata"); m != image_->end() && m->is_object())
            if (const auto v = m->find("volsg"); v != m->end()) volsg = &*v;
        if (!volsg) return geometry;
        const auto numbers = [&](const json& list, std::size_t count) {
            if (!list.is_array() || list.size() != count) return false;
            for (const json& n : list)
                if (!n.is_number() || !std::isfinite(n.get<double>())) return false;
            return true;
        };
        const json directions = volsg->value("lpsDirections", json());
        const json origin = volsg->value("lpsOrigin", json());
        if (!numbers(origin, 3) || !directions.is_array() || directions.size() != 3 ||
            !numbers(directions[0], 3) || !numbers(directions[1], 3) || !numbers(directions[2], 3))
            fail("metadata.volsg must hold lpsDirections (3 lists of 3 finite numbers) and "
                 "lpsOrigin (3 finite numbers)");
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r)
                geometry.directions[c][r] =
                    directions[std::size_t(c)][std::size_t(r)].get<double>();
        geometry.origin = {origin[0].get<double>(), origin[1].get<double>(),
                           origin[2].get<double>()};
        geometry.origin += geometry.directions * translationOf(dataset);
        geometry.known = true;
        return geometry;
    }

    // The dataset's translation as x, y, z (0 where there is none), checked by scaleOf.
    static glm::dvec3 translationOf(const json& dataset) {
        glm::dvec3 shift(0.0);
        const auto found = dataset.find("coordinateTransformations");
        if (found == dataset.end() || !found->is_array()) return shift;
        for (const json& t : *found)
            if (t.is_object() && t.value("type", json()) == "translation" &&
                t.contains("translation")) {
                const json& v = t["translation"];
                const std::size_t n = v.size();
                shift = {v[n - 1].get<double>(), v[n - 2].get<double>(), v[n - 3].get<double>()};
            }
        return shift;
    }

    // The "scale" of an object's coordinateTransformations as x, y, z (1 where there is none).
    // `axisCount` 0: not named, at least three entries.
    glm::dvec3 scaleOf(const json& owner, const std::string& where, std::size_t axisCount) const {
        glm::dvec3 scale(1.0);
        const auto found = owner.find("coordinateTransformations");
        if (found == owner.end()) return scale; // NGFF before 0.4
        const json& transforms = *found;
        if (!transforms.is_array()) fail(where + ".coordinateTransformations must be a list");
        for (const json& t : transforms) {
            if (!t.is_object() || !t.contains("type"))
                fail(where + ": a transformation has no type");
            const std::string kind = t["type"].is_string() ? t["type"] : "";
            if (kind == "identity") continue;
            if (kind != "scale" && kind != "translation")
                fail(where + ": transformation type " + t["type"].dump() +
                     " (NGFF 0.4 has scale and translation)");
            if (!t.contains(kind))
                fail(where + ": " + kind + " given by a \"path\" or missing (volsg reads lists)");
            const json& values = t[kind];
            if (!values.is_array() || values.size() < 3 ||
                (axisCount != 0 && values.size() != axisCount))
                fail(where + ": " + kind + " " + values.dump() + " must have one entry per axis");
            for (const json& v : values)
                if (!v.is_number() || !std::isfinite(v.get<double>()) ||
                    (kind == "scale" && !(v.get<double>() > 0.0)))
                    fail(where + ": " + kind + " " + values.dump() +
                         (kind == "scale" ? " must be finite and > 0" : " must be finite"));
            if (kind == "scale") {
                const std::size_t n = values.size();
                scale = {values[n - 1].get<double>(), values[n - 2].get<double>(),
                         values[n - 3].get<double>()};
            }
        }
        return scale;
    }

    std::string path_;
    const json* image_ = nullptr;
    const json* datasets_ = nullptr;
};

// The level at `path`: an image folder (with .zattrs) and a level number, or one array's
// folder (with .zarray), whose spacing comes from the image around it when that lists it.
OmeZarrLevel findLevel(const fs::path& folder, int level) {
    if (fs::exists(folder / ".zarray")) {
        if (level != 0)
            throw Error("level " + std::to_string(level) +
                            " asked for, but this folder is one Zarr array (one level)",
                        folder.string());
        const fs::path parent = folder.parent_path();
        const fs::path attrs = parent / ".zattrs";
        if (fs::exists(attrs)) {
            const json root = readZarrJson(attrs.string());
            if (root.is_object() && root.contains("multiscales")) {
                const MultiscalesParser image(attrs.string(), root);
                const int index = image.levelNamed(folder.filename().string());
                if (index >= 0) return image.level(index);
            }
        }
        OmeZarrLevel bare;
        bare.arrayFolder = folder.string();
        bare.axisCount = 0;
        return bare;
    }
    const fs::path attrs = folder / ".zattrs";
    if (!fs::exists(attrs))
        throw Error("neither .zattrs nor .zarray: not an OME-Zarr image or Zarr array",
                    folder.string());
    const json root = readZarrJson(attrs.string());
    return MultiscalesParser(attrs.string(), root).level(level);
}

// A chunk file outside the array's chunk grid means the .zarray's shape is not the shape the
// array was written with.
void checkChunkKeys(const std::string& arrayFolder, const ZarrArrayLayout& layout,
                    const std::string& zarrayPath) {
    const std::size_t rank = layout.shape.size();
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(arrayFolder, ec);
         !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (it.depth() >= int(rank)) {
            it.disable_recursion_pending();
            continue;
        }
        if (!it->is_regular_file(ec)) continue;
        std::string key = fs::relative(it->path(), arrayFolder, ec).generic_string();
        if (key.empty() || key[0] == '.') continue;
        std::replace(key.begin(), key.end(), '/', layout.dimensionSeparator);
        std::vector<std::uint64_t> index;
        std::size_t start = 0;
        bool isChunk = true;
        while (isChunk && start <= key.size()) {
            const std::size_t end =
                std::min(key.find(layout.dimensionSeparator, start), key.size());
            const std::string part = key.substr(start, end - start);
            isChunk =
                !part.empty() && part.size() < 10 &&
                std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; });
            if (isChunk) index.push_back(std::stoull(part));
            start = end + 1;
        }
        if (!isChunk || index.size() != rank) continue;
        for (std::size_t a = 0; a < rank; ++a) {
            const std::uint64_t count = (layout.shape[a] + layout.chunks[a] - 1) / layout.chunks[a];
            if (index[a] >= count)
                throw Error("chunk " + key + " lies outside shape " + json(layout.shape).dump() +
                                " with chunks " + json(layout.chunks).dump() +
                                ": the .zarray does not describe the array that was written",
                            zarrayPath);
        }
    }
}

} // namespace

// findLevel, with a JSON read the parsers' checks missed as the same one-line error.
OmeZarrLevel findOmeZarrLevel(const std::string& path, int level) {
    const fs::path folder = fs::path(path).lexically_normal();
    try {
        return findLevel(folder, level);
    } catch (const json::exception& e) {
        throw Error(std::string("unexpected multiscales metadata: ") + e.what(), folder.string());
    }
}

int omeZarrLevelCount(const std::string& path) {
    const fs::path folder = fs::path(path).lexically_normal();
    if (fs::exists(folder / ".zarray")) return 1;
    const fs::path attrs = folder / ".zattrs";
    if (!fs::exists(attrs))
        throw Error("neither .zattrs nor .zarray: not an OME-Zarr image or Zarr array",
                    folder.string());
    try {
        const json root = readZarrJson(attrs.string());
        return int(MultiscalesParser(attrs.string(), root).levelCount());
    } catch (const json::exception& e) {
        throw Error(std::string("unexpected multiscales metadata: ") + e.what(), attrs.string());
    }
}

ZarrChunkLoader::ZarrChunkLoader(const std::string& zarrayPath, const ZarrArrayLayout& layout)
    : zarrayPath_(zarrayPath), layout_(layout),
      buffer_(std::size_t(layout.chunkElements()) * voxelTypeSize(layout.type)) {}

std::span<const std::byte> ZarrChunkLoader::load(const std::vector<std::uint64_t>& index) {
    // Inside the array's folder, as every data file a header names (io/ContainedFile.h).
    const std::string path = InputFile::resolveBeside(zarrayPath_, layout_.chunkKey(index));
    std::error_code ec;
    if (!fs::exists(path, ec)) return fillChunk();
    InputFile file(path);
    if (file.size() > maxStoredChunkBytes(buffer_.size()))
        file.fail("chunk file of " + std::to_string(file.size()) +
                  " bytes is larger than any stored chunk of " + std::to_string(buffer_.size()) +
                  " bytes can be");
    stored_.resize(std::size_t(file.size()));
    if (file.read(stored_.data(), stored_.size()) != stored_.size())
        file.fail("file ended while reading the chunk");
    decodeZarrChunk(layout_.codec, stored_, buffer_, path);
    const std::size_t size = voxelTypeSize(layout_.type);
    if (size > 1 && layout_.bigEndian != (std::endian::native == std::endian::big))
        swapElementBytes(buffer_.data(), buffer_.size(), size);
    return buffer_;
}

std::span<const std::byte> ZarrChunkLoader::fillChunk() {
    if (fill_.empty()) {
        // One voxel of the fill value in host order, repeated.
        auto one = VolumeGrid::create({1, 1, 1}, layout_.type);
        one->setValue(0, layout_.fillValue);
        const std::span<const std::byte> bytes = std::as_const(*one).bytes();
        fill_.resize(buffer_.size());
        for (std::size_t i = 0; i < fill_.size(); i += bytes.size())
            std::memcpy(fill_.data() + i, bytes.data(), bytes.size());
    }
    return fill_;
}

bool isZarrFolder(const std::string& path) {
    std::error_code ec;
    if (!fs::is_directory(path, ec)) return false;
    fs::path folder = fs::path(path).lexically_normal();
    if (folder.filename().empty()) folder = folder.parent_path(); // "x.zarr/"
    std::string name = folder.filename().string();
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (name.size() > 5 && name.compare(name.size() - 5, 5, ".zarr") == 0) return true;
    return fs::exists(folder / ".zattrs", ec) || fs::exists(folder / ".zgroup", ec) ||
           fs::exists(folder / ".zarray", ec);
}

ref_ptr<VolumeGrid> readOmeZarr(const std::string& path, int level, std::uint64_t byteLimit) {
    std::error_code ec;
    if (!fs::is_directory(path, ec))
        throw Error(std::string("cannot open OME-Zarr image: ") +
                        (fs::exists(path, ec) ? "not a folder" : "no such folder"),
                    path);
    const OmeZarrLevel where = findOmeZarrLevel(path, level);
    const std::string zarrayPath = (fs::path(where.arrayFolder) / ".zarray").string();
    const ZarrArrayLayout layout = readZarrArrayLayout(where.arrayFolder, byteLimit);
    const std::size_t rank = layout.shape.size();
    if (where.axisCount != 0 && where.axisCount != rank)
        throw Error("shape " + json(layout.shape).dump() + " has " + std::to_string(rank) +
                        " axes, the multiscales metadata names " + std::to_string(where.axisCount),
                    zarrayPath);
    const glm::ivec3 dims(int(layout.shape[rank - 1]), int(layout.shape[rank - 2]),
                          int(layout.shape[rank - 3]));
    checkedGridBytes(zarrayPath, 0, dims, layout.type, where.spacing, byteLimit);
    checkChunkKeys(where.arrayFolder, layout, zarrayPath);

    ref_ptr<VolumeGrid> grid;
    try {
        grid = VolumeGrid::create(dims, layout.type, where.spacing, byteLimit);
    } catch (const Error& e) {
        throw Error(e.message(), zarrayPath);
    }
    grid->setGeometry(where.geometry);
    const std::span<std::byte> out = grid->bytes();
    const std::size_t size = voxelTypeSize(layout.type);
    const glm::ivec3 chunk(int(layout.chunks[rank - 1]), int(layout.chunks[rank - 2]),
                           int(layout.chunks[rank - 3]));
    ZarrChunkLoader loader(zarrayPath, layout);
    // Leading axes (t, c) stay at chunk 0: their first element is the volume read.
    std::vector<std::uint64_t> index(rank, 0);
    for (int cz = 0; cz * chunk.z < dims.z; ++cz)
        for (int cy = 0; cy * chunk.y < dims.y; ++cy)
            for (int cx = 0; cx * chunk.x < dims.x; ++cx) {
                index[rank - 3] = std::uint64_t(cz);
                index[rank - 2] = std::uint64_t(cy);
                index[rank - 1] = std::uint64_t(cx);
                const std::span<const std::byte> voxels = loader.load(index);
                const glm::ivec3 first = glm::ivec3(cx, cy, cz) * chunk;
                const glm::ivec3 last = glm::min(first + chunk, dims);
                const std::size_t row = std::size_t(last.x - first.x) * size;
                for (int z = first.z; z < last.z; ++z)
                    for (int y = first.y; y < last.y; ++y) {
                        const std::size_t from = (std::size_t(z - first.z) * std::size_t(chunk.y) +
                                                  std::size_t(y - first.y)) *
                                                 std::size_t(chunk.x) * size;
                        std::memcpy(out.data() + grid->index(first.x, y, z) * size,
                                    voxels.data() + from, row);
                    }
            }
    return grid;
}

namespace {

/// One level's array, opened for reading parts of it.
struct OpenLevel {
    OmeZarrLevel where;
    std::string zarrayPath;
    ZarrArrayLayout layout;
    glm::ivec3 dims{0};
};

OpenLevel openLevel(const std::string& path, int level, std::uint64_t byteLimit) {
    std::error_code ec;
    if (!fs::is_directory(path, ec))
        throw Error(std::string("cannot open OME-Zarr image: ") +
                        (fs::exists(path, ec) ? "not a folder" : "no such folder"),
                    path);
    OpenLevel open;
    open.where = findOmeZarrLevel(path, level);
    open.zarrayPath = (fs::path(open.where.arrayFolder) / ".zarray").string();
    open.layout = readZarrArrayLayout(open.where.arrayFolder, byteLimit);
    const std::size_t rank = open.layout.shape.size();
    open.dims = glm::ivec3(int(open.layout.shape[rank - 1]), int(open.layout.shape[rank - 2]),
                           int(open.layout.shape[rank - 3]));
    return open;
}

void checkRegion(const OpenLevel& open, glm::ivec3 first, glm::ivec3 count) {
    const glm::ivec3 end = first + count;
    if (glm::any(glm::lessThan(first, glm::ivec3(0))) ||
        glm::any(glm::lessThan(count, glm::ivec3(1))) || glm::any(glm::greaterThan(end, open.dims)))
        throw Error("the region from voxel (" + std::to_string(first.x) + ", " +
                        std::to_string(first.y) + ", " + std::to_string(first.z) + ") of " +
                        std::to_string(count.x) + " x " + std::to_string(count.y) + " x " +
                        std::to_string(count.z) + " voxels is not inside the level's " +
                        std::to_string(open.dims.x) + " x " + std::to_string(open.dims.y) + " x " +
                        std::to_string(open.dims.z),
                    open.zarrayPath);
}

/// Copies the voxels first .. first + count of the level into `grid`, voxel v of the level at
/// grid voxel v - origin, reading only the chunks that meet the box.
void readChunksOfRegion(const OpenLevel& open, glm::ivec3 first, glm::ivec3 count, VolumeGrid& grid,
                        glm::ivec3 origin) {
    const ZarrArrayLayout& layout = open.layout;
    const std::size_t rank = layout.shape.size();
    const std::span<std::byte> out = grid.bytes();
    const std::size_t size = voxelTypeSize(layout.type);
    const glm::ivec3 chunk(int(layout.chunks[rank - 1]), int(layout.chunks[rank - 2]),
                           int(layout.chunks[rank - 3]));
    const glm::ivec3 end = first + count;
    ZarrChunkLoader loader(open.zarrayPath, layout);
    std::vector<std::uint64_t> index(rank, 0);
    const glm::ivec3 firstChunk = first / chunk, lastChunk = (end - 1) / chunk;
    for (int cz = firstChunk.z; cz <= lastChunk.z; ++cz)
        for (int cy = firstChunk.y; cy <= lastChunk.y; ++cy)
            for (int cx = firstChunk.x; cx <= lastChunk.x; ++cx) {
                index[rank - 3] = std::uint64_t(cz);
                index[rank - 2] = std::uint64_t(cy);
                index[rank - 1] = std::uint64_t(cx);
                const std::span<const std::byte> voxels = loader.load(index);
                const glm::ivec3 chunkFirst = glm::ivec3(cx, cy, cz) * chunk;
                const glm::ivec3 from = glm::max(chunkFirst, first);
                const glm::ivec3 to = glm::min(chunkFirst + chunk, end);
                const std::size_t row = std::size_t(to.x - from.x) * size;
                for (int z = from.z; z < to.z; ++z)
                    for (int y = from.y; y < to.y; ++y) {
                        const std::size_t in =
                            ((std::size_t(z - chunkFirst.z) * std::size_t(chunk.y) +
                              std::size_t(y - chunkFirst.y)) *
                                 std::size_t(chunk.x) +
                             std::size_t(from.x - chunkFirst.x)) *
                            size;
                        const glm::ivec3 at = glm::ivec3(from.x, y, z) - origin;
                        std::memcpy(out.data() + grid.index(at.x, at.y, at.z) * size,
                                    voxels.data() + in, row);
                    }
            }
}

} // namespace

ref_ptr<VolumeGrid> readOmeZarrRegion(const std::string& path, int level, glm::ivec3 first,
                                      glm::ivec3 count, std::uint64_t byteLimit) {
    const OpenLevel open = openLevel(path, level, byteLimit);
    checkRegion(open, first, count);
    checkedGridBytes(open.zarrayPath, 0, count, open.layout.type, open.where.spacing, byteLimit);
    ref_ptr<VolumeGrid> grid;
    try {
        grid = VolumeGrid::create(count, open.layout.type, open.where.spacing, byteLimit);
    } catch (const Error& e) {
        throw Error(e.message(), open.zarrayPath);
    }
    readChunksOfRegion(open, first, count, *grid, first);
    return grid;
}

glm::ivec3 readOmeZarrDimensions(const std::string& path, int level) {
    return openLevel(path, level, VolumeGrid::defaultByteLimit).dims;
}

ref_ptr<VolumeGrid> readOmeZarrWithin(const std::string& path, int level, glm::ivec3 first,
                                      glm::ivec3 count, std::uint64_t byteLimit) {
    const OpenLevel open = openLevel(path, level, byteLimit);
    checkRegion(open, first, count);
    checkedGridBytes(open.zarrayPath, 0, open.dims, open.layout.type, open.where.spacing,
                     byteLimit);
    ref_ptr<VolumeGrid> grid;
    try {
        grid = VolumeGrid::create(open.dims, open.layout.type, open.where.spacing, byteLimit);
    } catch (const Error& e) {
        throw Error(e.message(), open.zarrayPath);
    }
    grid->setGeometry(open.where.geometry);
    if (open.layout.fillValue != 0.0) // a new grid holds zeros
        for (std::size_t i = 0; i < grid->voxelCount(); ++i)
            grid->setValue(i, open.layout.fillValue);
    readChunksOfRegion(open, first, count, *grid, glm::ivec3(0));
    return grid;
}

} // namespace volsg
