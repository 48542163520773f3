#pragma once
// Writes small glTF files for the tests: a binary buffer built from typed arrays, JSON around
// it, saved as .gltf (base64 data URI or an external .bin) or .glb.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "../../examples/gltf/ExampleMesh.h" // packGlb

#include "../support/TempDir.h"

namespace volsg::test {

/// A folder of this process for scratch files (ctest runs cases in parallel).
inline std::filesystem::path gltfScratch() {
    return processScratch("volsg-gltf-test");
}

inline std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t b0 = bytes[i];
        const std::uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0;
        const std::uint32_t b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
        const std::uint32_t v = b0 << 16 | b1 << 8 | b2;
        out += digits[v >> 18 & 63];
        out += digits[v >> 12 & 63];
        out += i + 1 < bytes.size() ? digits[v >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

inline void writeBytes(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

/// glTF component type numbers.
enum Component : int {
    kByte = 5120,
    kUByte = 5121,
    kShort = 5122,
    kUShort = 5123,
    kUInt = 5125,
    kFloat = 5126
};

class GltfBuilder {
public:
    /// Appends raw bytes (4-byte aligned) as a new bufferView; returns its index.
    int addView(const void* data, std::size_t bytes, int stride = 0) {
        while (bin_.size() % 4)
            bin_.push_back(0);
        const std::size_t offset = bin_.size();
        bin_.resize(offset + bytes);
        if (bytes) std::memcpy(bin_.data() + offset, data, bytes);
        std::string v = "{\"buffer\":0,\"byteOffset\":" + std::to_string(offset) +
                        ",\"byteLength\":" + std::to_string(bytes);
        if (stride) v += ",\"byteStride\":" + std::to_string(stride);
        views_.push_back(v + "}");
        return int(views_.size() - 1);
    }
    template <class T> int addView(const std::vector<T>& values, int stride = 0) {
        return addView(values.data(), values.size() * sizeof(T), stride);
    }
    /// An accessor as raw JSON (for broken ones); returns its index.
    int addAccessorJson(const std::string& json) {
        accessors_.push_back(json);
        return int(accessors_.size() - 1);
    }
    /// An accessor over a whole new view of `values`.
    template <class T>
    int addAccessor(const std::vector<T>& values, int componentType, const char* type,
                    std::size_t count, bool normalized = false, const std::string& extra = "") {
        const int view = addView(values);
        return addAccessorJson("{\"bufferView\":" + std::to_string(view) +
                               ",\"componentType\":" + std::to_string(componentType) +
                               ",\"count\":" + std::to_string(count) + ",\"type\":\"" + type +
                               "\"" + (normalized ? ",\"normalized\":true" : "") + extra + "}");
    }
    int addPositions(const std::vector<glm::vec3>& p) {
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (const auto& v : p) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
        const std::string minmax = ",\"min\":[" + num(lo.x) + "," + num(lo.y) + "," + num(lo.z) +
                                   "],\"max\":[" + num(hi.x) + "," + num(hi.y) + "," + num(hi.z) +
                                   "]";
        return addAccessor(p, kFloat, "VEC3", p.size(), false, minmax);
    }
    const std::vector<std::uint8_t>& bin() const { return bin_; }

    /// The whole JSON; `rest` holds the other top-level members ("meshes":[...],...).
    /// bufferUri: empty = a base64 data URI; otherwise that URI; glb = no URI at all.
    std::string json(const std::string& rest, const std::string& bufferUri = "",
                     bool glb = false) const {
        std::string s = "{\"asset\":{\"version\":\"2.0\"}";
        if (!bin_.empty() || glb) {
            s += ",\"buffers\":[{\"byteLength\":" + std::to_string(bin_.size());
            if (!glb)
                s += ",\"uri\":\"" +
                     (bufferUri.empty() ? "data:application/octet-stream;base64," + base64(bin_)
                                        : bufferUri) +
                     "\"";
            s += "}]";
        }
        s += ",\"bufferViews\":[" + join(views_) + "],\"accessors\":[" + join(accessors_) + "]";
        if (!rest.empty()) s += "," + rest;
        return s + "}";
    }
    /// Writes `name` as .gltf with an embedded buffer; returns the path.
    std::string writeGltf(const std::string& name, const std::string& rest) const {
        const auto path = gltfScratch() / name;
        writeText(path, json(rest));
        return path.string();
    }
    /// Writes `name` as .glb (JSON and BIN chunks); returns the path.
    std::string writeGlb(const std::string& name, const std::string& rest) const {
        const auto path = gltfScratch() / name;
        writeBytes(path, example::packGlb(json(rest, "", true), bin_));
        return path.string();
    }

    static std::string num(double v) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.9g", v);
        return buf;
    }

private:
    static std::string join(const std::vector<std::string>& items) {
        std::string s;
        for (std::size_t i = 0; i < items.size(); ++i)
            s += (i ? "," : "") + items[i];
        return s;
    }
    std::vector<std::uint8_t> bin_;
    std::vector<std::string> views_, accessors_;
};

/// A quad in the z = 0 plane from (-h,-h) to (h,h) facing +z, two triangles, with UVs that put
/// the image's first row at the top (+y) and TEXCOORD u along +x.
struct Quad {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint16_t> indices{0, 1, 2, 0, 2, 3};
    explicit Quad(float h = 1.0f)
        : positions{{-h, -h, 0}, {h, -h, 0}, {h, h, 0}, {-h, h, 0}},
          normals(4, glm::vec3(0, 0, 1)), uvs{{0, 1}, {1, 1}, {1, 0}, {0, 0}} {}
};

/// One node with mesh 0 in scene 0.
inline const char* kOneNodeScene = "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],"
                                   "\"scene\":0";

} // namespace volsg::test
