#include <volsg/series/SpillFile.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/shearwarp/VoxelObject.h>

namespace volsg {

namespace {

constexpr char kMagic[8] = {'V', 'S', 'G', 'S', 'P', 'I', 'L', 'L'};

/// Fixed-size head of a spill file, in the machine's own byte order (the file never leaves
/// the process that wrote it). The extracted arrays follow, then one list per bit of
/// `listMask` in axis order.
struct SpillHeader {
    char magic[8];
    std::uint32_t version;
    std::uint32_t listMask; ///< bit a: the RenderList of principal axis a follows
    std::int32_t dimensions[3];
    std::int32_t reserved;
    double spacing[3];
    double maxMagnitude;
    std::uint64_t voxelCount;
    std::uint64_t checksum; ///< of everything after the header
};
static_assert(sizeof(SpillHeader) == 80);

/// Head of one RenderList: its keys and sizes; packed, value12, gradientCode, magnitude8
/// (voxelCount each), the entries and the two contribution masks follow.
struct ListHeader {
    std::uint64_t clipKey, tableKey;
    std::int32_t axis;
    std::uint32_t entryCount;
    std::uint32_t unclippedMaskSize, clippedMaskSize;
    std::uint8_t unclippedLayout, clippedLayout, reserved[6];
};
static_assert(sizeof(ListHeader) == 40);

/// RenderListEntry without padding.
struct EntryRecord {
    std::uint32_t first, firstClipped, last, lastClipped, lastInSlice;
    std::uint16_t offset[3];
    std::uint8_t z, optimized;
};
static_assert(sizeof(EntryRecord) == 28);

constexpr std::uint64_t kArrayBytesPerVoxel = 5 * sizeof(std::uint16_t) + sizeof(std::uint8_t);
constexpr std::uint64_t kListBytesPerVoxel =
    sizeof(std::uint32_t) + 2 * sizeof(std::uint16_t) + sizeof(std::uint8_t);

/// FNV-1a over 8-byte words (bytes for the tail): a few GB/s, enough to tell a damaged file.
class Checksum {
public:
    void add(const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        std::size_t i = 0;
        for (; i + 8 <= bytes; i += 8) {
            std::uint64_t word;
            std::memcpy(&word, p + i, 8);
            hash_ = (hash_ ^ word) * kPrime;
        }
        for (; i < bytes; ++i)
            hash_ = (hash_ ^ p[i]) * kPrime;
        hash_ = (hash_ ^ bytes) * kPrime;
    }
    std::uint64_t value() const { return hash_; }

private:
    static constexpr std::uint64_t kPrime = 0x100000001b3ULL;
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

class SpillWriter {
public:
    explicit SpillWriter(std::ofstream& out) : out_(out) {}
    void bytes(const void* data, std::size_t n) {
        out_.write(static_cast<const char*>(data), std::streamsize(n));
        checksum_.add(data, n);
        written_ += n;
    }
    template <class T> void array(const std::vector<T>& v) {
        bytes(v.data(), v.size() * sizeof(T));
    }
    std::uint64_t checksum() const { return checksum_.value(); }
    std::size_t written() const { return written_; }

private:
    std::ofstream& out_;
    Checksum checksum_;
    std::size_t written_ = 0;
};

/// Reads what the header promises, never allocating more than the file holds.
class SpillReader {
public:
    SpillReader(std::ifstream& in, std::uint64_t remaining, const std::string& path)
        : in_(in), remaining_(remaining), path_(path) {}
    void need(std::uint64_t count, std::uint64_t size) const {
        if (size != 0 && count > remaining_ / size)
            throw Error("series disk cache file has the wrong size for its contents (truncated?)",
                        path_);
    }
    void bytes(void* data, std::size_t n) {
        need(n, 1);
        in_.read(static_cast<char*>(data), std::streamsize(n));
        if (!in_) throw Error("series disk cache file is truncated", path_);
        checksum_.add(data, n);
        remaining_ -= n;
    }
    template <class T> void array(std::vector<T>& v, std::uint64_t count) {
        need(count, sizeof(T));
        v.resize(std::size_t(count));
        bytes(v.data(), v.size() * sizeof(T));
    }
    std::uint64_t remaining() const { return remaining_; }
    std::uint64_t checksum() const { return checksum_.value(); }

private:
    std::ifstream& in_;
    std::uint64_t remaining_;
    const std::string& path_;
    Checksum checksum_;
};

void writeList(SpillWriter& out, const RenderList& list) {
    std::lock_guard lock(list.mutex);
    ListHeader head{};
    head.clipKey = list.clipKey;
    head.tableKey = list.tableKey;
    head.axis = list.axis;
    head.entryCount = std::uint32_t(list.entries.size());
    head.unclippedMaskSize = std::uint32_t(list.contributesUnclipped.size());
    head.clippedMaskSize = std::uint32_t(list.contributesClipped.size());
    head.unclippedLayout = std::uint8_t(list.unclippedLayout);
    head.clippedLayout = std::uint8_t(list.clippedLayout);
    out.bytes(&head, sizeof head);
    out.array(list.packed);
    out.array(list.value12);
    out.array(list.gradientCode);
    out.array(list.magnitude8);
    std::vector<EntryRecord> records(list.entries.size());
    for (std::size_t e = 0; e < records.size(); ++e) {
        const RenderListEntry& from = list.entries[e];
        EntryRecord& to = records[e];
        to = EntryRecord{}; // no stray bytes
        to.first = from.first;
        to.firstClipped = from.firstClipped;
        to.last = from.last;
        to.lastClipped = from.lastClipped;
        to.lastInSlice = from.lastInSlice;
        for (int c = 0; c < 3; ++c)
            to.offset[c] = from.offset[c];
        to.z = from.z;
        to.optimized = from.optimized ? 1 : 0;
    }
    out.array(records);
    out.array(list.contributesUnclipped);
    out.array(list.contributesClipped);
}

std::unique_ptr<RenderList> readList(SpillReader& in, int axis, std::uint64_t voxelCount,
                                     const std::string& path) {
    ListHeader head{};
    in.bytes(&head, sizeof head);
    if (head.axis != axis)
        throw Error("series disk cache file: RenderList axes out of order", path);
    auto list = std::make_unique<RenderList>();
    list->axis = axis;
    list->clipKey = head.clipKey;
    list->tableKey = head.tableKey;
    list->unclippedLayout = PackedLayout(head.unclippedLayout);
    list->clippedLayout = PackedLayout(head.clippedLayout);
    in.need(voxelCount, kListBytesPerVoxel);
    in.array(list->packed, voxelCount);
    in.array(list->value12, voxelCount);
    in.array(list->gradientCode, voxelCount);
    in.array(list->magnitude8, voxelCount);
    std::vector<EntryRecord> records;
    in.array(records, head.entryCount);
    list->entries.resize(records.size());
    for (std::size_t e = 0; e < records.size(); ++e) {
        const EntryRecord& from = records[e];
        RenderListEntry& to = list->entries[e];
        to.first = from.first;
        to.firstClipped = from.firstClipped;
        to.last = from.last;
        to.lastClipped = from.lastClipped;
        to.lastInSlice = from.lastInSlice;
        to.offset = glm::u16vec3(from.offset[0], from.offset[1], from.offset[2]);
        to.z = from.z;
        to.optimized = from.optimized != 0;
    }
    in.array(list->contributesUnclipped, head.unclippedMaskSize);
    in.array(list->contributesClipped, head.clippedMaskSize);
    return list;
}

} // namespace

std::size_t writeSpillFile(const std::string& path, VoxelObject& object, bool withRenderLists) {
    const VoxelObject::Arrays a = object.arrays();
    SpillHeader header{};
    std::memcpy(header.magic, kMagic, sizeof kMagic);
    header.version = kSpillFileVersion;
    for (int axis = 0; axis < 3; ++axis) {
        header.dimensions[axis] = a.dimensions[axis];
        header.spacing[axis] = a.spacing[axis];
        if (withRenderLists && object.hasRenderList(axis)) header.listMask |= 1u << axis;
    }
    header.maxMagnitude = a.maxMagnitude;
    header.voxelCount = a.i.size();
    const std::string temporary = path + ".tmp";
    std::size_t written = 0;
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw Error("cannot create series disk cache file", temporary);
        out.write(reinterpret_cast<const char*>(&header), sizeof header); // checksum below
        SpillWriter body(out);
        body.array(a.i);
        body.array(a.j);
        body.array(a.k);
        body.array(a.value12);
        body.array(a.gradientCode);
        body.array(a.magnitude8);
        for (int axis = 0; axis < 3; ++axis)
            if (header.listMask & (1u << axis)) writeList(body, object.renderList(axis));
        header.checksum = body.checksum();
        out.seekp(0);
        out.write(reinterpret_cast<const char*>(&header), sizeof header);
        out.flush();
        if (!out) {
            out.close();
            std::remove(temporary.c_str());
            throw Error("cannot write series disk cache file (disk full?)", temporary);
        }
        written = sizeof header + body.written();
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::remove(temporary.c_str());
        throw Error("cannot rename series disk cache file: " + error.message(), path);
    }
    return written;
}

ref_ptr<VoxelObject> readSpillFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw Error("cannot open series disk cache file", path);
    const auto fileSize = std::uint64_t(in.tellg());
    in.seekg(0);
    SpillHeader header{};
    in.read(reinterpret_cast<char*>(&header), sizeof header);
    if (!in || std::memcmp(header.magic, kMagic, sizeof kMagic) != 0)
        throw Error("not a series disk cache file", path);
    if (header.version != kSpillFileVersion)
        throw Error("series disk cache file has format version " + std::to_string(header.version) +
                        ", this build reads version " + std::to_string(kSpillFileVersion),
                    path);
    if (header.listMask > 7) throw Error("series disk cache file: bad RenderList mask", path);
    SpillReader body(in, fileSize - sizeof header, path);
    // The declared count must fit the file before anything is allocated.
    body.need(header.voxelCount, kArrayBytesPerVoxel);
    VoxelObject::Arrays a;
    for (int axis = 0; axis < 3; ++axis) {
        a.dimensions[axis] = header.dimensions[axis];
        a.spacing[axis] = header.spacing[axis];
    }
    a.maxMagnitude = header.maxMagnitude;
    const std::uint64_t n = header.voxelCount;
    body.array(a.i, n);
    body.array(a.j, n);
    body.array(a.k, n);
    body.array(a.value12, n);
    body.array(a.gradientCode, n);
    body.array(a.magnitude8, n);
    std::unique_ptr<RenderList> lists[3];
    for (int axis = 0; axis < 3; ++axis)
        if (header.listMask & (1u << axis)) lists[axis] = readList(body, axis, n, path);
    if (body.remaining() != 0)
        throw Error("series disk cache file has the wrong size for its contents", path);
    if (body.checksum() != header.checksum)
        throw Error("series disk cache file is damaged (checksum mismatch)", path);
    try {
        ref_ptr<VoxelObject> object = VoxelObject::fromArrays(std::move(a));
        for (auto& list : lists)
            if (list) object->adoptRenderList(std::move(list));
        return object;
    } catch (const Error& e) {
        throw Error(e.message(), path);
    }
}

} // namespace volsg
