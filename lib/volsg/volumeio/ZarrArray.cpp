#include <volsg/volumeio/ZarrArray.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/volumeio/InputFile.h>
#include <volsg/volumeio/ZarrJson.h>

namespace volsg {

using nlohmann::json;

nlohmann::json readZarrJson(const std::string& path) {
    InputFile file(path);
    if (file.size() > limits::maxHeaderLength)
        file.fail("metadata file of " + std::to_string(file.size()) + " bytes is larger than " +
                  std::to_string(limits::maxHeaderLength));
    std::string text(std::size_t(file.size()), '\0');
    if (file.read(text.data(), text.size()) != text.size()) file.fail("file ended while reading");
    // Zarr metadata is a few levels deep; deeper nesting is refused before parsing, since
    // printing such a value in a message would recurse once per level.
    constexpr int maxDepth = 32;
    int depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > maxDepth)
                file.fail("JSON nested deeper than " + std::to_string(maxDepth) + " levels");
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    try {
        return json::parse(text);
    } catch (const json::exception& e) {
        // what() starts with "[json.exception.parse_error.101] parse error at line..." (or
        // out_of_range.406 for a number beyond double's range).
        std::string what = e.what();
        const auto bracket = what.find("] ");
        if (bracket != std::string::npos) what.erase(0, bracket + 2);
        file.fail("malformed JSON: " + what);
    }
}

namespace {

class ZarrArrayParser {
public:
    ZarrArrayParser(std::string path, const json& root) : path_(std::move(path)), root_(root) {}

    [[noreturn]] void fail(const std::string& message) const { throw Error(message, path_); }

    const json& member(const char* name) const {
        const auto it = root_.find(name);
        if (it == root_.end()) fail(std::string("no \"") + name + "\"");
        return *it;
    }

    std::vector<std::uint64_t> extents(const char* name) const {
        const json& list = member(name);
        if (!list.is_array() || list.size() < 3 || list.size() > 5)
            fail(std::string("\"") + name +
                 "\" must list 3 to 5 sizes (t, c, z, y, x; volsg "
                 "reads 3D volumes), got " +
                 list.dump());
        std::vector<std::uint64_t> out;
        for (const json& n : list) {
            if (!n.is_number_integer() || n.get<std::int64_t>() < 1 ||
                n.get<std::int64_t>() > limits::maxVolumeDimension)
                fail(std::string("\"") + name + "\" entries must be whole numbers in 1.." +
                     std::to_string(limits::maxVolumeDimension) + ", got " + list.dump());
            out.push_back(n.get<std::uint64_t>());
        }
        return out;
    }

    void dtype(ZarrArrayLayout& layout) const {
        const json& d = member("dtype");
        const std::string text = d.is_string() ? d.get<std::string>() : d.dump();
        const auto unsupported = [&] {
            fail("unsupported dtype " + d.dump() +
                 " (volsg reads \"|u1\", \"<u2\", \">u2\", \"<i2\", \">i2\", \"<f4\", \">f4\")");
        };
        if (!d.is_string() || text.size() != 3) unsupported();
        const char order = text[0];
        const std::string kind = text.substr(1);
        if (kind == "u1")
            layout.type = VoxelType::UByte;
        else if (kind == "u2")
            layout.type = VoxelType::UShort;
        else if (kind == "i2")
            layout.type = VoxelType::Short;
        else if (kind == "f4")
            layout.type = VoxelType::Float;
        else
            unsupported();
        if (order == '>')
            layout.bigEndian = true;
        else if (order == '<' || (order == '|' && kind == "u1"))
            layout.bigEndian = false;
        else
            unsupported();
    }

    double fillValue(VoxelType type) const {
        const auto it = root_.find("fill_value");
        if (it == root_.end() || it->is_null()) return 0.0;
        const json& f = *it;
        if (type == VoxelType::Float) {
            if (f.is_number()) return f.get<double>();
            if (f == "NaN") return std::numeric_limits<double>::quiet_NaN();
            if (f == "Infinity") return std::numeric_limits<double>::infinity();
            if (f == "-Infinity") return -std::numeric_limits<double>::infinity();
            fail("fill_value " + f.dump() + " is not a number");
        }
        const double lo = type == VoxelType::Short ? -32768.0 : 0.0;
        const double hi = type == VoxelType::UByte    ? 255.0
                          : type == VoxelType::UShort ? 65535.0
                                                      : 32767.0;
        if (!f.is_number() || f.get<double>() != std::trunc(f.get<double>()) ||
            f.get<double>() < lo || f.get<double>() > hi)
            fail("fill_value " + f.dump() + " does not fit the dtype " + member("dtype").dump());
        return f.get<double>();
    }

    ZarrCodec codec() const {
        const json& c = member("compressor");
        ZarrCodec codec;
        if (c.is_null()) return codec;
        if (!c.is_object() || !c.contains("id") || !c["id"].is_string())
            fail("compressor must be null or an object with an \"id\", got " + c.dump());
        const std::string id = c["id"].get<std::string>();
        if (id == "zlib")
            codec.kind = ZarrCodec::Kind::Zlib;
        else if (id == "gzip")
            codec.kind = ZarrCodec::Kind::Gzip;
        else if (id == "zstd")
            codec.kind = ZarrCodec::Kind::Zstd;
        else if (id == "blosc")
            codec.kind = ZarrCodec::Kind::Blosc;
        else
            fail("unknown compressor \"" + id + "\" (volsg reads null, zlib, gzip, zstd, blosc)");
        // Levels and blosc's settings matter only for writing; blosc's header says the rest.
        if (c.contains("level") && c["level"].is_number_integer()) codec.level = c["level"];
        if (c.contains("clevel") && c["clevel"].is_number_integer()) codec.level = c["clevel"];
        if (c.contains("cname") && c["cname"].is_string()) codec.bloscInner = c["cname"];
        if (c.contains("shuffle") && c["shuffle"].is_number_integer())
            codec.bloscShuffle = c["shuffle"];
        return codec;
    }

private:
    std::string path_;
    const json& root_;
};

ZarrArrayLayout interpretZarray(const std::string& path, const json& root,
                                std::uint64_t byteLimit) {
    const ZarrArrayParser parser(path, root);
    if (!root.is_object()) parser.fail("a .zarray must be a JSON object");
    if (parser.member("zarr_format") != 2)
        parser.fail("zarr_format " + parser.member("zarr_format").dump() +
                    " is not 2 (volsg reads Zarr v2)");
    ZarrArrayLayout layout;
    layout.shape = parser.extents("shape");
    layout.chunks = parser.extents("chunks");
    if (layout.chunks.size() != layout.shape.size())
        parser.fail("\"chunks\" has " + std::to_string(layout.chunks.size()) +
                    " entries, \"shape\" " + std::to_string(layout.shape.size()));
    parser.dtype(layout);
    // Five entries of up to 2^16 can overflow 64 bits: each step is checked against the limit.
    std::uint64_t chunkBytes = voxelTypeSize(layout.type);
    for (std::uint64_t c : layout.chunks) {
        if (chunkBytes > byteLimit / c)
            parser.fail("a chunk of " + root["chunks"].dump() + " is larger than the limit of " +
                        std::to_string(byteLimit) + " bytes");
        chunkBytes *= c;
    }
    if (root.contains("order") && root["order"] != "C")
        parser.fail("order " + root["order"].dump() + " is not \"C\" (volsg reads C order)");
    if (root.contains("filters") && !root["filters"].is_null() &&
        !(root["filters"].is_array() && root["filters"].empty()))
        parser.fail("filters " + root["filters"].dump() + " are not supported");
    if (root.contains("dimension_separator")) {
        const json& s = root["dimension_separator"];
        if (s != "." && s != "/")
            parser.fail("dimension_separator " + s.dump() + " must be \".\" or \"/\"");
        layout.dimensionSeparator = s.get<std::string>()[0];
    }
    layout.fillValue = parser.fillValue(layout.type);
    layout.codec = parser.codec();
    return layout;
}

} // namespace

std::string ZarrArrayLayout::chunkKey(const std::vector<std::uint64_t>& index) const {
    std::string key;
    for (std::size_t a = 0; a < index.size(); ++a) {
        if (a) key += dimensionSeparator;
        key += std::to_string(index[a]);
    }
    return key;
}

std::uint64_t ZarrArrayLayout::chunkElements() const {
    std::uint64_t n = 1;
    for (std::uint64_t c : chunks)
        n *= c;
    return n;
}

std::string ZarrArrayLayout::toJson() const {
    static const char* const dtypes[] = {"|u1", "<u2", "<i2", "<f4"};
    json compressor = nullptr;
    switch (codec.kind) {
    case ZarrCodec::Kind::None:
        break;
    case ZarrCodec::Kind::Zlib:
    case ZarrCodec::Kind::Gzip:
    case ZarrCodec::Kind::Zstd:
        compressor = {{"id", codec.id()}, {"level", codec.level}};
        break;
    case ZarrCodec::Kind::Blosc:
        compressor = {{"id", "blosc"},
                      {"cname", codec.bloscInner},
                      {"clevel", codec.level},
                      {"shuffle", codec.bloscShuffle},
                      {"blocksize", 0}};
        break;
    }
    const json root = {
        {"zarr_format", 2},
        {"shape", shape},
        {"chunks", chunks},
        {"dtype", dtypes[int(type)]},
        {"compressor", compressor},
        {"fill_value", type == VoxelType::Float ? json(fillValue) : json(std::int64_t(fillValue))},
        {"order", "C"},
        {"filters", nullptr},
        {"dimension_separator", std::string(1, dimensionSeparator)}};
    return root.dump(4) + "\n";
}

ZarrArrayLayout readZarrArrayLayout(const std::string& arrayFolder, std::uint64_t byteLimit) {
    const std::string path = (std::filesystem::path(arrayFolder) / ".zarray").string();
    const json root = readZarrJson(path);
    // The parser checks each member's type before reading it; this turns any read it missed
    // into the same one-line error.
    try {
        return interpretZarray(path, root, byteLimit);
    } catch (const json::exception& e) {
        throw Error(std::string("unexpected metadata: ") + e.what(), path);
    }
}

} // namespace volsg
