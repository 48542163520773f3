#include <volsg/voxelfile/VoxelFile.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <zlib.h>

#include <volsg/core/Error.h>
#include <volsg/io/AtomicFile.h>
#include <volsg/io/RegularFile.h>
#include <volsg/voxelfile/PositionCoding.h>

namespace volsg {

namespace {

// "VSGV", then CR LF SUB LF as PNG does: a transfer that rewrites line ends breaks the magic.
constexpr std::array<std::uint8_t, 8> kMagic{'V', 'S', 'G', 'V', '\r', '\n', 0x1A, '\n'};
constexpr std::size_t kFileHeaderBytes = 28;    // magic, version, sections, file size, CRC
constexpr std::size_t kSectionHeaderBytes = 24; // tag, stored size, raw size, CRC
constexpr std::uint64_t kZlibMaxRatio = 1032;   // deflate's largest expansion on inflate
constexpr char kSceneTag[4] = {'S', 'C', 'N', 'E'};
constexpr char kObjectTag[4] = {'V', 'O', 'X', 'L'};

// --- Little-endian writing ---

void putBytes(std::string& out, const void* data, std::size_t n) {
    out.append(static_cast<const char*>(data), n);
}
template <class T> void put(std::string& out, T value) {
    static_assert(std::is_integral_v<T>);
    for (std::size_t b = 0; b < sizeof(T); ++b)
        out.push_back(char(std::uint8_t(std::uint64_t(value) >> (8 * b))));
}
void putDouble(std::string& out, double value) {
    put(out, std::bit_cast<std::uint64_t>(value));
}

std::uint32_t crcOf(const void* data, std::size_t n, std::uint32_t crc = 0) {
    const auto* p = static_cast<const Bytef*>(data);
    while (n > 0) { // zlib's crc32 takes a uInt length
        const auto chunk = uInt(std::min<std::size_t>(n, 1u << 30));
        crc = std::uint32_t(crc32(crc, p, chunk));
        p += chunk;
        n -= chunk;
    }
    return crc;
}

/// Two 12-bit values in three bytes (the attributes' rendering precision).
void put12(std::string& out, const std::vector<std::uint16_t>& values) {
    for (std::size_t v = 0; v < values.size(); v += 2) {
        const unsigned a = values[v] & 0xFFFu;
        const unsigned b = v + 1 < values.size() ? values[v + 1] & 0xFFFu : 0u;
        out.push_back(char(a & 0xFF));
        out.push_back(char((a >> 8) | ((b & 0xF) << 4)));
        out.push_back(char(b >> 4));
    }
}
std::size_t packed12Bytes(std::uint64_t count) {
    return std::size_t((count + 1) / 2 * 3);
}
std::uint64_t packed4Bytes(std::uint64_t count) {
    return (count + 1) / 2;
}

/// The distinct values of `values` when there are at most 256 (a volume of 8-bit data has
/// no more), else empty: each voxel's value is then one byte, an index into them.
std::vector<std::uint16_t> valuePalette(const std::vector<std::uint16_t>& values) {
    std::vector<std::uint8_t> used(4096, 0);
    for (std::uint16_t v : values)
        used[v & 0xFFFu] = 1;
    std::vector<std::uint16_t> palette;
    for (unsigned v = 0; v < 4096; ++v)
        if (used[v]) palette.push_back(std::uint16_t(v));
    if (palette.size() > 256) palette.clear();
    return palette;
}

std::string deflateSection(const std::string& raw) {
    uLongf size = compressBound(uLong(raw.size()));
    std::string out(size, '\0');
    if (compress2(reinterpret_cast<Bytef*>(out.data()), &size,
                  reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()),
                  Z_DEFAULT_COMPRESSION) != Z_OK)
        throw Error("voxel file: zlib could not compress a section");
    out.resize(size);
    return out;
}

void putSection(std::string& out, const char (&tag)[4], const std::string& raw) {
    if (raw.size() > maxVoxelFileSectionBytes)
        throw Error("voxel file: a section of " + std::to_string(raw.size()) +
                    " bytes exceeds the limit of " + std::to_string(maxVoxelFileSectionBytes));
    const std::string stored = deflateSection(raw);
    const std::size_t start = out.size();
    putBytes(out, tag, 4);
    put<std::uint64_t>(out, stored.size());
    put<std::uint64_t>(out, raw.size());
    std::uint32_t crc = crcOf(out.data() + start, 20);
    crc = crcOf(stored.data(), stored.size(), crc);
    put<std::uint32_t>(out, crc);
    out += stored;
}

std::string objectRecord(const PackedObject& object) {
    const VoxelObject::Arrays a = object.voxels->arrays();
    std::string out;
    put<std::uint32_t>(out, object.volumeIndex);
    put<std::uint32_t>(out, object.objectIndex);
    const ExtractionRecord& e = object.extraction;
    put<std::uint8_t>(out, std::uint8_t(e.source.kind));
    put<std::uint8_t>(out, std::uint8_t(e.selection));
    put<std::uint16_t>(out, 0);
    put<std::int32_t>(out, e.source.tag);
    putDouble(out, e.source.low);
    putDouble(out, e.source.high);
    putDouble(out, e.gradientThreshold);
    putDouble(out, e.dataRange.x);
    putDouble(out, e.dataRange.y);
    for (int axis = 0; axis < 3; ++axis)
        put<std::int32_t>(out, a.dimensions[axis]);
    for (int axis = 0; axis < 3; ++axis)
        putDouble(out, a.spacing[axis]);
    putDouble(out, a.maxMagnitude);
    const std::string positions = encodePositions(a.dimensions, a.i, a.j, a.k);
    const std::vector<std::uint16_t> palette = valuePalette(a.value12);
    put<std::uint64_t>(out, a.i.size());
    put<std::uint64_t>(out, positions.size());
    put<std::uint16_t>(out, std::uint16_t(palette.size()));
    out += positions;
    if (palette.empty()) {
        put12(out, a.value12);
    } else {
        put12(out, palette);
        std::array<std::uint8_t, 4096> index{};
        for (std::size_t p = 0; p < palette.size(); ++p)
            index[palette[p]] = std::uint8_t(p);
        for (std::uint16_t v : a.value12)
            out.push_back(char(index[v & 0xFFFu]));
    }
    put12(out, a.gradientCode);
    // The renderer reads the top 4 bits of the magnitude code only (RenderList::derivePacked).
    for (std::size_t v = 0; v < a.magnitude8.size(); v += 2)
        out.push_back(char((a.magnitude8[v] >> 4) |
                           (v + 1 < a.magnitude8.size() ? a.magnitude8[v + 1] & 0xF0 : 0)));
    return out;
}

// --- Reading ---

/// A bounds-checked little-endian cursor; errors name the file, the section and the offset.
class ByteReader {
public:
    /// `base`: the offset of `data` in the file, so messages give file offsets.
    ByteReader(const std::uint8_t* data, std::size_t size, std::string where,
               const std::string& file, std::size_t base = 0)
        : data_(data), size_(size), base_(base), where_(std::move(where)), file_(file) {}

    std::size_t offset() const { return at_; }
    std::size_t remaining() const { return size_ - at_; }
    const std::uint8_t* take(std::size_t n, const char* what) {
        if (n > remaining())
            fail(std::string("ends inside ") + what + " (needs " + std::to_string(n) + " bytes, " +
                 std::to_string(remaining()) + " left)");
        const std::uint8_t* p = data_ + at_;
        at_ += n;
        return p;
    }
    template <class T> T get(const char* what) {
        const std::uint8_t* p = take(sizeof(T), what);
        std::uint64_t v = 0;
        for (std::size_t b = 0; b < sizeof(T); ++b)
            v |= std::uint64_t(p[b]) << (8 * b);
        return T(v);
    }
    double getDouble(const char* what) { return std::bit_cast<double>(get<std::uint64_t>(what)); }
    [[noreturn]] void fail(const std::string& message) const {
        throw Error(where_ + " at byte " + std::to_string(base_ + at_) + ": " + message, file_);
    }
    const std::string& where() const { return where_; }

private:
    const std::uint8_t* data_;
    std::size_t size_, base_, at_ = 0;
    std::string where_;
    const std::string& file_;
};

void get12(ByteReader& in, std::size_t count, std::vector<std::uint16_t>& out, const char* what) {
    const std::uint8_t* p = in.take(packed12Bytes(count), what);
    out.resize(count);
    for (std::size_t v = 0; v < count; v += 2, p += 3) {
        out[v] = std::uint16_t(p[0] | ((p[1] & 0xF) << 8));
        if (v + 1 < count) out[v + 1] = std::uint16_t((p[1] >> 4) | (p[2] << 4));
    }
}

PackedObject parseObject(const std::uint8_t* raw, std::size_t size, const std::string& where,
                         const std::string& file) {
    ByteReader in(raw, size, where + " (uncompressed record)", file);
    PackedObject object;
    object.volumeIndex = in.get<std::uint32_t>("the volume index");
    object.objectIndex = in.get<std::uint32_t>("the object index");
    ExtractionRecord& e = object.extraction;
    const auto source = in.get<std::uint8_t>("the source");
    const auto selection = in.get<std::uint8_t>("the voxel selection");
    if (source > ObjectSource::Threshold) in.fail("unknown source " + std::to_string(source));
    if (selection > std::uint8_t(VoxelSelection::Gradient))
        in.fail("unknown voxel selection " + std::to_string(selection));
    e.source.kind = ObjectSource::Kind(source);
    e.selection = VoxelSelection(selection);
    if (in.get<std::uint16_t>("the reserved bytes") != 0) in.fail("reserved bytes are not zero");
    e.source.tag = in.get<std::int32_t>("the tag");
    e.source.low = in.getDouble("the threshold");
    e.source.high = in.getDouble("the threshold");
    e.gradientThreshold = in.getDouble("the gradient threshold");
    e.dataRange.x = in.getDouble("the data range");
    e.dataRange.y = in.getDouble("the data range");

    VoxelObject::Arrays a;
    for (int axis = 0; axis < 3; ++axis) {
        a.dimensions[axis] = in.get<std::int32_t>("the dimensions");
        if (a.dimensions[axis] < 1 || a.dimensions[axis] > 65535)
            in.fail("dimension " + std::to_string(a.dimensions[axis]) + " outside 1..65535");
    }
    for (int axis = 0; axis < 3; ++axis) {
        a.spacing[axis] = in.getDouble("the spacing");
        if (!(a.spacing[axis] > 0.0) || !std::isfinite(a.spacing[axis]))
            in.fail("spacing is not a positive finite number");
    }
    a.maxMagnitude = in.getDouble("the largest gradient magnitude");
    if (!(a.maxMagnitude >= 0.0) || !std::isfinite(a.maxMagnitude))
        in.fail("largest gradient magnitude is not a finite number >= 0");
    const auto count = in.get<std::uint64_t>("the voxel count");
    const auto positionBytes = in.get<std::uint64_t>("the position code size");
    const auto paletteSize = in.get<std::uint16_t>("the value palette size");
    if (paletteSize > 256) in.fail("value palette of " + std::to_string(paletteSize) + " > 256");
    const std::uint64_t cells = std::uint64_t(a.dimensions.x) * std::uint64_t(a.dimensions.y) *
                                std::uint64_t(a.dimensions.z);
    if (count > cells)
        in.fail("declares " + std::to_string(count) + " voxels in a volume of " +
                std::to_string(cells) + " cells");
    // Declared sizes against what the record holds, before any allocation.
    const std::uint64_t valueBytes =
        paletteSize == 0 ? packed12Bytes(count) : packed12Bytes(paletteSize) + count;
    const std::uint64_t attributeBytes = valueBytes + packed12Bytes(count) + packed4Bytes(count);
    if (positionBytes > in.remaining() || in.remaining() - positionBytes != attributeBytes)
        in.fail("declared sizes (" + std::to_string(count) + " voxels, " +
                std::to_string(positionBytes) + " position bytes) do not match the record's " +
                std::to_string(in.remaining()) + " remaining bytes");
    const std::uint8_t* code = in.take(std::size_t(positionBytes), "the position code");
    decodePositions(code, std::size_t(positionBytes), a.dimensions, std::size_t(count), a.i, a.j,
                    a.k, file + ": " + in.where());
    if (paletteSize == 0) {
        get12(in, std::size_t(count), a.value12, "the values");
    } else {
        std::vector<std::uint16_t> palette;
        get12(in, paletteSize, palette, "the value palette");
        const std::uint8_t* index = in.take(std::size_t(count), "the value indices");
        a.value12.resize(std::size_t(count));
        for (std::size_t v = 0; v < count; ++v) {
            if (index[v] >= paletteSize) in.fail("a value index beyond the palette");
            a.value12[v] = palette[index[v]];
        }
    }
    get12(in, std::size_t(count), a.gradientCode, "the gradient codes");
    const std::uint8_t* magnitudes =
        in.take(std::size_t(packed4Bytes(count)), "the gradient magnitudes");
    a.magnitude8.resize(std::size_t(count));
    for (std::size_t v = 0; v < count; ++v)
        a.magnitude8[v] = std::uint8_t(v % 2 ? magnitudes[v / 2] & 0xF0 : magnitudes[v / 2] << 4);
    object.voxels = VoxelObject::fromArrays(std::move(a));
    return object;
}

} // namespace

std::string encodeVoxelFile(const VoxelFileContent& content) {
    std::string out;
    putBytes(out, kMagic.data(), kMagic.size());
    put<std::uint32_t>(out, voxelFileVersion);
    put<std::uint32_t>(out, std::uint32_t(1 + content.objects.size()));
    put<std::uint64_t>(out, 0); // the file size, set below
    put<std::uint32_t>(out, 0); // the header CRC, set below
    putSection(out, kSceneTag, content.sceneText);
    for (const PackedObject& object : content.objects) {
        if (!object.voxels) throw Error("voxel file: an object without voxels");
        putSection(out, kObjectTag, objectRecord(object));
    }
    std::string size;
    put<std::uint64_t>(size, out.size());
    out.replace(16, 8, size);
    std::string crc;
    put<std::uint32_t>(crc, crcOf(out.data(), 24));
    out.replace(24, 4, crc);
    return out;
}

bool hasVoxelFileMagic(std::span<const std::byte> bytes) {
    return bytes.size() >= kMagic.size() && std::memcmp(bytes.data(), kMagic.data(), 8) == 0;
}

VoxelFileContent readVoxelFile(std::span<const std::byte> bytes, const std::string& name) {
    const auto* data = reinterpret_cast<const std::uint8_t*>(bytes.data());
    ByteReader in(data, bytes.size(), "header", name);
    if (bytes.size() < kMagic.size() || std::memcmp(data, kMagic.data(), kMagic.size()) != 0)
        in.fail("not a volsg voxel file (.vsgv): wrong magic");
    if (bytes.size() < kFileHeaderBytes)
        in.fail("truncated: " + std::to_string(bytes.size()) + " bytes, the header alone is " +
                std::to_string(kFileHeaderBytes));
    in.take(kMagic.size(), "the magic");
    const auto version = in.get<std::uint32_t>("the version");
    const auto sections = in.get<std::uint32_t>("the section count");
    const auto fileSize = in.get<std::uint64_t>("the file size");
    const auto headerCrc = in.get<std::uint32_t>("the header checksum");
    if (headerCrc != crcOf(data, 24)) in.fail("header checksum mismatch (corrupt file)");
    if (version != voxelFileVersion)
        in.fail("format version " + std::to_string(version) + ", this program reads version " +
                std::to_string(voxelFileVersion));
    if (fileSize != bytes.size())
        in.fail(fileSize > bytes.size()
                    ? "truncated: the header declares " + std::to_string(fileSize) +
                          " bytes, the file has " + std::to_string(bytes.size())
                    : "the header declares " + std::to_string(fileSize) + " bytes, the file has " +
                          std::to_string(bytes.size()) + " (trailing bytes)");
    if (sections < 1 || sections > maxVoxelFileSections ||
        std::uint64_t(sections) * kSectionHeaderBytes > in.remaining())
        in.fail("section count " + std::to_string(sections) +
                " does not fit the file or the limit of " + std::to_string(maxVoxelFileSections));

    VoxelFileContent content;
    std::string raw;
    for (std::uint32_t s = 0; s < sections; ++s) {
        const std::size_t start = in.offset();
        const std::string where = "section " + std::to_string(s);
        ByteReader header(data + start, bytes.size() - start, where, name, start);
        const std::uint8_t* tag = header.take(4, "the section header");
        const auto stored = header.get<std::uint64_t>("the section header");
        const auto rawSize = header.get<std::uint64_t>("the section header");
        const auto crc = header.get<std::uint32_t>("the section header");
        const std::string label =
            where + " '" + std::string(reinterpret_cast<const char*>(tag), 4) + "'";
        auto fail = [&](const std::string& message) {
            throw Error(label + " at byte " + std::to_string(start) + ": " + message, name);
        };
        if (stored > header.remaining())
            fail("truncated: declares " + std::to_string(stored) + " bytes, " +
                 std::to_string(header.remaining()) + " remain in the file");
        if (rawSize > maxVoxelFileSectionBytes || rawSize > stored * kZlibMaxRatio + 64)
            fail("declared size " + std::to_string(rawSize) + " is beyond the limit of " +
                 std::to_string(maxVoxelFileSectionBytes) + " bytes or what " +
                 std::to_string(stored) + " compressed bytes can hold");
        const std::uint8_t* payload = header.take(std::size_t(stored), "the section");
        if (crcOf(payload, std::size_t(stored), crcOf(tag, 20)) != crc)
            fail("checksum mismatch (corrupt file)");
        const bool isScene = std::memcmp(tag, kSceneTag, 4) == 0;
        const bool isObject = std::memcmp(tag, kObjectTag, 4) == 0;
        if (!isScene && !isObject) fail("unknown section type");
        if (isScene != (s == 0)) fail("the scene must be the first section, and only it");
        raw.assign(std::size_t(rawSize), '\0');
        uLongf rawLength = uLongf(rawSize);
        if (uncompress(reinterpret_cast<Bytef*>(raw.data()), &rawLength, payload, uLong(stored)) !=
                Z_OK ||
            rawLength != rawSize)
            fail("zlib data is corrupt or does not hold the declared " + std::to_string(rawSize) +
                 " bytes");
        if (isScene) {
            content.sceneText = raw;
        } else {
            content.objects.push_back(parseObject(reinterpret_cast<const std::uint8_t*>(raw.data()),
                                                  raw.size(), label, name));
            const PackedObject& o = content.objects.back();
            for (std::size_t p = 0; p + 1 < content.objects.size(); ++p)
                if (content.objects[p].volumeIndex == o.volumeIndex &&
                    content.objects[p].objectIndex == o.objectIndex)
                    fail("a second object " + std::to_string(o.objectIndex) + " of volume " +
                         std::to_string(o.volumeIndex));
        }
        in.take(kSectionHeaderBytes + std::size_t(stored), "the section");
    }
    return content;
}

VoxelFileContent readVoxelFileFromPath(const std::string& path) {
    // Checked before opening: a FIFO would block the open until a writer came.
    regularFileSize(path, "cannot read voxel file", maxVoxelFileSize);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw Error("cannot open voxel file", path);
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw Error("cannot read the size of the voxel file: " + ec.message(), path);
    if (size > maxVoxelFileSize)
        throw Error("voxel file of " + std::to_string(size) + " bytes exceeds the limit of " +
                        std::to_string(maxVoxelFileSize),
                    path);
    std::vector<std::byte> bytes(static_cast<std::size_t>(size));
    if (!file.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        throw Error("cannot read the voxel file", path);
    return readVoxelFile(bytes, path);
}

void writeVoxelFile(const std::string& path, const VoxelFileContent& content) {
    writeFileAtomically(path, encodeVoxelFile(content));
}

} // namespace volsg
