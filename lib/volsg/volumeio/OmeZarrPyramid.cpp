#include <volsg/volumeio/OmeZarrPyramid.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

#include <volsg/core/Error.h>
#include <volsg/volumeio/VoxelPayload.h>
#include <volsg/volumeio/ZarrArray.h>
#include <volsg/volumeio/ZarrJson.h>

namespace volsg {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void writeBytes(const fs::path& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(static_cast<const char*>(data), std::streamsize(size));
    out.close();
    if (!out) throw Error("cannot write the file", path.string());
}

void writeText(const fs::path& path, const std::string& text) {
    writeBytes(path, text.data(), text.size());
}

glm::ivec3 halvingOf(glm::ivec3 dims) {
    return {dims.x > 1 ? 2 : 1, dims.y > 1 ? 2 : 1, dims.z > 1 ? 2 : 1};
}

// The value a voxel of `type` stores for `v` (v within the type's range).
double storedValue(VoxelType type, double v) {
    return type == VoxelType::Float ? double(float(v)) : std::nearbyint(v);
}

// Turns the planes of one level into the planes of the next: each output voxel reduces the
// (up to) 2x2x2 input voxels it covers.
class PlaneReducer {
public:
    PlaneReducer(glm::ivec3 from, glm::ivec3 to, VoxelType type, bool labels)
        : from_(from), to_(to), factor_(halvingOf(from)), type_(type), labels_(labels) {}

    // True when `out` holds a new output plane.
    bool add(const std::vector<double>& plane, std::vector<double>& out) {
        if (factor_.z == 1) {
            reduce(plane, nullptr, out);
            return true;
        }
        if (!hasPending_) {
            pending_ = plane;
            hasPending_ = true;
            return false;
        }
        reduce(pending_, &plane, out);
        hasPending_ = false;
        return true;
    }

    // The last output plane of an odd plane count.
    bool flush(std::vector<double>& out) {
        if (!hasPending_) return false;
        reduce(pending_, nullptr, out);
        hasPending_ = false;
        return true;
    }

private:
    void reduce(const std::vector<double>& a, const std::vector<double>* b,
                std::vector<double>& out) const {
        out.resize(std::size_t(to_.x) * std::size_t(to_.y));
        double samples[8];
        for (int y = 0; y < to_.y; ++y)
            for (int x = 0; x < to_.x; ++x) {
                int n = 0;
                for (int dy = 0; dy < factor_.y; ++dy)
                    for (int dx = 0; dx < factor_.x; ++dx) {
                        const int sx = x * factor_.x + dx, sy = y * factor_.y + dy;
                        if (sx >= from_.x || sy >= from_.y) continue;
                        const std::size_t i =
                            std::size_t(sy) * std::size_t(from_.x) + std::size_t(sx);
                        samples[n++] = a[i];
                        if (b) samples[n++] = (*b)[i];
                    }
                out[std::size_t(y) * std::size_t(to_.x) + std::size_t(x)] =
                    labels_ ? mode(samples, n) : storedValue(type_, mean(samples, n));
            }
    }

    static double mean(const double* v, int n) {
        double sum = 0.0;
        for (int i = 0; i < n; ++i)
            sum += v[i];
        return sum / n;
    }

    // The most frequent value; ties go to the smallest. At most 8 values: count each.
    static double mode(const double* v, int n) {
        double best = v[0];
        int bestCount = 0;
        for (int i = 0; i < n; ++i) {
            int count = 0;
            for (int j = 0; j < n; ++j)
                count += v[j] == v[i];
            if (count > bestCount || (count == bestCount && v[i] < best)) {
                best = v[i];
                bestCount = count;
            }
        }
        return best;
    }

    glm::ivec3 from_, to_, factor_;
    VoxelType type_;
    bool labels_;
    std::vector<double> pending_;
    bool hasPending_ = false;
};

// One level's array: collects its planes into a slab one chunk deep and writes the slab's
// chunks when it is full.
class LevelWriter {
public:
    LevelWriter(const fs::path& folder, glm::ivec3 dims, VoxelType type,
                const PyramidOptions& options)
        : folder_(folder), dims_(dims), chunk_(glm::min(dims, glm::ivec3(options.chunk))),
          type_(type), size_(voxelTypeSize(type)) {
        layout_.shape = {std::uint64_t(dims.z), std::uint64_t(dims.y), std::uint64_t(dims.x)};
        layout_.chunks = {std::uint64_t(chunk_.z), std::uint64_t(chunk_.y),
                          std::uint64_t(chunk_.x)};
        layout_.type = type;
        layout_.dimensionSeparator = '/';
        layout_.codec = options.codec;
        fs::create_directories(folder_);
        writeText(folder_ / ".zarray", layout_.toJson());
        slab_.resize(planeVoxels() * std::size_t(chunk_.z) * size_);
        chunkBuffer_.resize(std::size_t(chunk_.x) * std::size_t(chunk_.y) * std::size_t(chunk_.z) *
                            size_);
    }

    void addPlane(const std::vector<double>& plane) {
        std::byte* to = slab_.data() + std::size_t(planesHeld_) * planeVoxels() * size_;
        switch (type_) {
        case VoxelType::UByte:
            store<std::uint8_t>(plane, to);
            break;
        case VoxelType::UShort:
            store<std::uint16_t>(plane, to);
            break;
        case VoxelType::Short:
            store<std::int16_t>(plane, to);
            break;
        case VoxelType::Float:
            store<float>(plane, to);
            break;
        }
        if (++planesHeld_ == chunk_.z) writeSlab();
    }

    void finish() {
        if (planesHeld_ > 0) writeSlab();
    }

    PyramidLevel summary;

private:
    std::size_t planeVoxels() const { return std::size_t(dims_.x) * std::size_t(dims_.y); }

    template <class T> static void store(const std::vector<double>& plane, std::byte* to) {
        for (std::size_t i = 0; i < plane.size(); ++i) {
            const T v = T(plane[i]);
            std::memcpy(to + i * sizeof(T), &v, sizeof(T));
        }
    }

    void writeSlab() {
        const int cz = slabIndex_++;
        for (int cy = 0; cy * chunk_.y < dims_.y; ++cy)
            for (int cx = 0; cx * chunk_.x < dims_.x; ++cx) {
                // Edge chunks are full-sized, padded with the fill value 0 (Zarr's rule).
                std::fill(chunkBuffer_.begin(), chunkBuffer_.end(), std::byte{0});
                const int x0 = cx * chunk_.x, y0 = cy * chunk_.y;
                const int x1 = std::min(x0 + chunk_.x, dims_.x),
                          y1 = std::min(y0 + chunk_.y, dims_.y);
                for (int z = 0; z < planesHeld_; ++z)
                    for (int y = y0; y < y1; ++y)
                        std::memcpy(chunkBuffer_.data() + ((std::size_t(z) * std::size_t(chunk_.y) +
                                                            std::size_t(y - y0)) *
                                                           std::size_t(chunk_.x)) *
                                                              size_,
                                    slab_.data() +
                                        (std::size_t(z) * planeVoxels() +
                                         std::size_t(y) * std::size_t(dims_.x) + std::size_t(x0)) *
                                            size_,
                                    std::size_t(x1 - x0) * size_);
                if (size_ > 1 && std::endian::native == std::endian::big)
                    swapElementBytes(chunkBuffer_.data(), chunkBuffer_.size(), size_);
                const std::vector<std::byte> stored =
                    encodeZarrChunk(layout_.codec, chunkBuffer_, size_);
                const fs::path path =
                    folder_ / std::to_string(cz) / std::to_string(cy) / std::to_string(cx);
                fs::create_directories(path.parent_path());
                writeBytes(path, stored.data(), stored.size());
                ++summary.chunkFiles;
                summary.storedBytes += stored.size();
            }
        planesHeld_ = 0;
    }

    fs::path folder_;
    glm::ivec3 dims_, chunk_;
    VoxelType type_;
    std::size_t size_;
    ZarrArrayLayout layout_;
    std::vector<std::byte> slab_, chunkBuffer_;
    int planesHeld_ = 0;
    int slabIndex_ = 0;
};

// Plane z of the grid as doubles (exact for every voxel type).
void gridPlane(const VolumeGrid& grid, int z, std::vector<double>& out) {
    const glm::ivec3 d = grid.dimensions();
    const std::size_t count = std::size_t(d.x) * std::size_t(d.y);
    const std::size_t first = grid.index(0, 0, z);
    out.resize(count);
    const auto copy = [&](auto values) {
        for (std::size_t i = 0; i < count; ++i)
            out[i] = double(values[first + i]);
    };
    switch (grid.type()) {
    case VoxelType::UByte:
        copy(grid.data<std::uint8_t>());
        break;
    case VoxelType::UShort:
        copy(grid.data<std::uint16_t>());
        break;
    case VoxelType::Short:
        copy(grid.data<std::int16_t>());
        break;
    case VoxelType::Float:
        copy(grid.data<float>());
        break;
    }
}

json multiscalesOf(const std::string& name, const std::vector<PyramidLevel>& levels,
                   const PyramidOptions& options, const VolumeGeometry& geometry) {
    json axes = json::array();
    for (const char* axis : {"z", "y", "x"}) {
        json a = {{"name", axis}, {"type", "space"}};
        if (!options.unit.empty()) a["unit"] = options.unit;
        axes.push_back(a);
    }
    json datasets = json::array();
    glm::dvec3 translation(0.0);
    for (std::size_t l = 0; l < levels.size(); ++l) {
        const glm::dvec3 s = levels[l].spacing;
        if (l > 0) // a coarse voxel's centre is the mean of the finer centres it covers
            translation += 0.5 * (s - levels[l - 1].spacing);
        datasets.push_back({{"path", std::to_string(l)},
                            {"coordinateTransformations",
                             {{{"type", "scale"}, {"scale", {s.z, s.y, s.x}}},
                              {{"type", "translation"},
                               {"translation", {translation.z, translation.y, translation.x}}}}}});
    }
    const std::string method = options.labels ? "mode" : "mean";
    json metadata = {{"method", "volsg 2x2x2 " + method},
                     {"description", options.labels ? "most frequent label, ties to the smallest"
                                                    : "mean, rounded to nearest for integers"}};
    // NGFF 0.4 cannot say where a scan lies in the patient; volsg keeps it beside the standard
    // metadata, so that a pyramid of a CT opens placed as its source file did.
    if (geometry.known) {
        const glm::dmat3& d = geometry.directions;
        metadata["volsg"] = {
            {"lpsDirections",
             {{d[0].x, d[0].y, d[0].z}, {d[1].x, d[1].y, d[1].z}, {d[2].x, d[2].y, d[2].z}}},
            {"lpsOrigin", {geometry.origin.x, geometry.origin.y, geometry.origin.z}}};
    }
    return {{"multiscales",
             {{{"version", "0.4"},
               {"name", name},
               {"axes", axes},
               {"datasets", datasets},
               {"type", method},
               {"metadata", metadata}}}}};
}

} // namespace

std::vector<glm::ivec3> pyramidLevelDimensions(glm::ivec3 dimensions, int chunk) {
    std::vector<glm::ivec3> levels{dimensions};
    while (std::max({levels.back().x, levels.back().y, levels.back().z}) > chunk) {
        const glm::ivec3 d = levels.back();
        levels.push_back((d + halvingOf(d) - 1) / halvingOf(d));
    }
    return levels;
}

std::vector<PyramidLevel> writeOmeZarrPyramid(
    glm::ivec3 dimensions, VoxelType type, glm::dvec3 spacing, const VolumeGeometry& geometry,
    const std::function<void(int, std::vector<double>&)>& plane, const std::string& folder,
    const PyramidOptions& options, const std::function<void(double)>& progress) {
    if (options.chunk < 1 || options.chunk > 4096)
        throw Error("chunk size must be 1..4096, got " + std::to_string(options.chunk));
    const fs::path root(folder);
    std::error_code ec;
    if (fs::exists(root, ec) && !(fs::is_directory(root, ec) && fs::is_empty(root, ec)))
        throw Error("output already exists (volsg writes a pyramid into a new folder)", folder);
    fs::create_directories(root, ec);
    if (ec) throw Error("cannot create the folder: " + ec.message(), folder);
    writeText(root / ".zgroup", "{\n    \"zarr_format\": 2\n}\n");

    const std::vector<glm::ivec3> dims = pyramidLevelDimensions(dimensions, options.chunk);
    std::vector<std::unique_ptr<LevelWriter>> writers;
    std::vector<std::unique_ptr<PlaneReducer>> reducers(dims.size());
    for (std::size_t l = 0; l < dims.size(); ++l) {
        writers.push_back(
            std::make_unique<LevelWriter>(root / std::to_string(l), dims[l], type, options));
        writers[l]->summary.dimensions = dims[l];
        writers[l]->summary.spacing =
            l == 0 ? spacing : writers[l - 1]->summary.spacing * glm::dvec3(halvingOf(dims[l - 1]));
        if (l > 0)
            reducers[l] =
                std::make_unique<PlaneReducer>(dims[l - 1], dims[l], type, options.labels);
    }

    // A plane of level l goes into its array and on to the next level's reducer.
    std::vector<std::vector<double>> planes(dims.size());
    std::function<void(std::size_t)> push = [&](std::size_t l) {
        writers[l]->addPlane(planes[l]);
        if (l + 1 < dims.size() && reducers[l + 1]->add(planes[l], planes[l + 1])) push(l + 1);
    };
    for (int z = 0; z < dims[0].z; ++z) {
        planes[0].resize(std::size_t(dims[0].x) * std::size_t(dims[0].y));
        plane(z, planes[0]);
        push(0);
        if (progress) progress(double(z + 1) / dims[0].z);
    }
    for (std::size_t l = 1; l < dims.size(); ++l)
        if (reducers[l]->flush(planes[l])) push(l);

    std::vector<PyramidLevel> levels;
    for (auto& writer : writers) {
        writer->finish();
        levels.push_back(writer->summary);
    }
    // Last: an interrupted run leaves no image metadata that promises levels it lacks.
    writeText(
        root / ".zattrs",
        multiscalesOf(fs::absolute(root).filename().string(), levels, options, geometry).dump(4) +
            "\n");
    return levels;
}

std::vector<PyramidLevel> writeOmeZarrPyramid(const VolumeGrid& grid, const std::string& folder,
                                              const PyramidOptions& options,
                                              const std::function<void(double)>& progress) {
    return writeOmeZarrPyramid(
        grid.dimensions(), grid.type(), grid.spacing(), grid.geometry(),
        [&](int z, std::vector<double>& out) { gridPlane(grid, z, out); }, folder, options,
        progress);
}

} // namespace volsg
