// tinygltf parses JSON, decodes base64 and images; everything it hands over is checked here
// before a byte of it is read, because tinygltf does not check accessors against their views.
#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/gltf/GltfLoader.h>
#include <volsg/io/ContainedFile.h>
#include <volsg/io/RegularFile.h>

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace volsg {

namespace {

/// Accessors without a bufferView are zeros (plus sparse values) that we allocate ourselves:
/// their count is bounded so a hostile count cannot ask for gigabytes.
constexpr std::size_t kMaxUnbackedCount = limits::maxGltfUnbackedCount;
/// Node trees deeper than this are refused (no real file comes near; recursion stays small).
constexpr int kMaxNodeDepth = limits::maxGltfNodeDepth;

const std::set<std::string>& supportedRequiredExtensions() {
    static const std::set<std::string> names{"KHR_materials_unlit", "KHR_mesh_quantization"};
    return names;
}

std::string indexed(const char* array, std::size_t i) {
    return std::string(array) + "[" + std::to_string(i) + "]";
}

/// One line of tinygltf's message (it ends lines with '\n' and may repeat itself).
std::string firstLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
        text.pop_back();
    const std::size_t end = text.find('\n');
    if (end != std::string::npos) text = text.substr(0, end) + " (...)";
    return text;
}

/// Reads one component as a double, normalized integers mapped as glTF says.
double readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        std::int8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? std::max(double(v) / 127.0, -1.0) : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        std::uint8_t v;
        std::memcpy(&v, p, 1);
        return normalized ? double(v) / 255.0 : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? std::max(double(v) / 32767.0, -1.0) : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? double(v) / 65535.0 : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_INT: {
        std::int32_t v;
        std::memcpy(&v, p, 4);
        return normalized ? std::max(double(v) / 2147483647.0, -1.0) : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        std::uint32_t v;
        std::memcpy(&v, p, 4);
        return normalized ? double(v) / 4294967295.0 : double(v);
    }
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p, 4);
        return double(v);
    }
    default: { // TINYGLTF_COMPONENT_TYPE_DOUBLE (checked before)
        double v;
        std::memcpy(&v, p, 8);
        return v;
    }
    }
}

int componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    case TINYGLTF_COMPONENT_TYPE_DOUBLE:
        return 8;
    default:
        return 0;
    }
}

int componentsInType(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return 1;
    case TINYGLTF_TYPE_VEC2:
        return 2;
    case TINYGLTF_TYPE_VEC3:
        return 3;
    case TINYGLTF_TYPE_VEC4:
    case TINYGLTF_TYPE_MAT2:
        return 4;
    case TINYGLTF_TYPE_MAT3:
        return 9;
    case TINYGLTF_TYPE_MAT4:
        return 16;
    default:
        return 0;
    }
}

/// A validated range of bytes: `count` elements of `elementSize` bytes, `stride` apart.
struct ByteRange {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
};

/// An accessor's values as doubles, `components` per element.
struct AccessorValues {
    std::vector<double> values;
    std::size_t count = 0;
    int components = 0;
};

class Loader {
public:
    Loader(const std::string& path, tinygltf::Model& model) : file_(path), m_(model) {}

    GltfAsset load();

private:
    [[noreturn]] void fail(const std::string& what) const { throw Error(what, file_); }

    void checkExtensions() const;
    void checkBufferViews() const;
    /// `count` elements of `elementSize` bytes from byte `offset` of bufferViews[view], with
    /// the view's stride (or tight packing); `what` names the element asking.
    ByteRange viewRange(int view, std::size_t offset, std::size_t count, std::size_t elementSize,
                        const std::string& what, bool strided) const;
    const AccessorValues& accessor(int index);
    std::vector<std::uint32_t> indexAccessor(int index, std::size_t vertexCount,
                                             const std::string& what);
    GltfPrimitive primitive(const tinygltf::Mesh& mesh, std::size_t meshIndex,
                            std::size_t primitiveIndex);
    GltfTextureRef textureRef(int index, int texCoord, double scale, const std::string& what) const;
    void materials(GltfAsset& out) const;
    void textures(GltfAsset& out);
    void nodes(GltfAsset& out) const;
    void addNode(GltfAsset& out, int node, const glm::dmat4& parent, int depth,
                 std::vector<char>& visited) const;

    std::string file_;
    tinygltf::Model& m_; ///< images are moved out of it
    std::vector<std::unique_ptr<AccessorValues>> accessorCache_;
    std::size_t accessorValues_ = 0; ///< decoded so far, all accessors (a per-file total)
};

void Loader::checkExtensions() const {
    for (const std::string& name : m_.extensionsRequired)
        if (!supportedRequiredExtensions().count(name))
            fail("extensionsRequired: unsupported extension " + name);
}

void Loader::checkBufferViews() const {
    for (std::size_t i = 0; i < m_.bufferViews.size(); ++i) {
        const tinygltf::BufferView& v = m_.bufferViews[i];
        const std::string what = indexed("bufferViews", i);
        if (v.buffer < 0 || std::size_t(v.buffer) >= m_.buffers.size())
            fail(what + ": buffer " + std::to_string(v.buffer) + " does not exist");
        const std::size_t size = m_.buffers[std::size_t(v.buffer)].data.size();
        if (v.byteOffset > size || v.byteLength > size - v.byteOffset)
            fail(what + ": byteOffset " + std::to_string(v.byteOffset) + " + byteLength " +
                 std::to_string(v.byteLength) + " exceeds " + indexed("buffers", v.buffer) + " (" +
                 std::to_string(size) + " bytes)");
        if (v.byteStride != 0 && (v.byteStride < 4 || v.byteStride > 252 || v.byteStride % 4))
            fail(what + ": byteStride " + std::to_string(v.byteStride) +
                 " is not a multiple of 4 in [4, 252]");
    }
}

ByteRange Loader::viewRange(int view, std::size_t offset, std::size_t count,
                            std::size_t elementSize, const std::string& what, bool strided) const {
    if (view < 0 || std::size_t(view) >= m_.bufferViews.size())
        fail(what + ": bufferView " + std::to_string(view) + " does not exist");
    const tinygltf::BufferView& v = m_.bufferViews[std::size_t(view)];
    const std::size_t stride = strided && v.byteStride != 0 ? v.byteStride : elementSize;
    if (stride < elementSize)
        fail(what + ": byteStride " + std::to_string(stride) + " is smaller than an element (" +
             std::to_string(elementSize) + " bytes)");
    const std::size_t length = v.byteLength;
    // offset + (count - 1) * stride + elementSize <= length, without overflowing.
    bool fits = count >= 1 && offset <= length && elementSize <= length - offset;
    if (fits) fits = (count - 1) <= (length - offset - elementSize) / stride;
    if (!fits)
        fail(what + ": count " + std::to_string(count) + " at byteOffset " +
             std::to_string(offset) + " exceeds " + indexed("bufferViews", std::size_t(view)) +
             " (" + std::to_string(length) + " bytes)");
    const auto& buffer = m_.buffers[std::size_t(v.buffer)].data;
    return {buffer.data() + v.byteOffset + offset, stride};
}

const AccessorValues& Loader::accessor(int index) {
    if (index < 0 || std::size_t(index) >= m_.accessors.size())
        fail("accessor " + std::to_string(index) + " does not exist");
    auto& cached = accessorCache_[std::size_t(index)];
    if (cached) return *cached;

    const tinygltf::Accessor& a = m_.accessors[std::size_t(index)];
    const std::string what = indexed("accessors", std::size_t(index));
    const int size = componentSize(a.componentType);
    const int components = componentsInType(a.type);
    if (size == 0) fail(what + ": componentType " + std::to_string(a.componentType) + " unknown");
    if (components == 0) fail(what + ": type " + std::to_string(a.type) + " unknown");
    if (a.count == 0) fail(what + ": count 0 (must be at least 1)");
    if (a.bufferView < 0 && a.count > kMaxUnbackedCount)
        fail(what + ": count " + std::to_string(a.count) + " without a bufferView exceeds " +
             std::to_string(kMaxUnbackedCount));

    auto out = std::make_unique<AccessorValues>();
    out->count = a.count;
    out->components = components;
    const std::size_t elementSize = std::size_t(size) * std::size_t(components);
    // A total over the file, after the view's own bounds: many accessors sharing one buffer
    // must not add up past it.
    const auto countValues = [&] {
        const std::size_t values = a.count * std::size_t(components);
        if (values / std::size_t(components) != a.count ||
            values > limits::maxGltfAccessorValues - accessorValues_)
            fail(what + ": the file's accessors decode more than " +
                 std::to_string(limits::maxGltfAccessorValues) + " values in all");
        accessorValues_ += values;
    };
    if (a.bufferView >= 0) {
        const ByteRange r = viewRange(a.bufferView, a.byteOffset, a.count, elementSize, what, true);
        countValues();
        out->values.resize(a.count * std::size_t(components));
        double* dst = out->values.data();
        for (std::size_t e = 0; e < a.count; ++e) {
            const unsigned char* p = r.data + e * r.stride;
            for (int c = 0; c < components; ++c)
                *dst++ = readComponent(p + std::size_t(c * size), a.componentType, a.normalized);
        }
    } else {
        countValues();
        out->values.assign(a.count * std::size_t(components), 0.0);
    }

    if (a.sparse.isSparse) {
        const auto& s = a.sparse;
        const std::string swhat = what + ".sparse";
        if (s.count < 1 || std::size_t(s.count) > a.count)
            fail(swhat + ": count " + std::to_string(s.count) + " not in [1, " +
                 std::to_string(a.count) + "]");
        const int indexSize = componentSize(s.indices.componentType);
        if (s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            s.indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(swhat + ".indices: componentType " + std::to_string(s.indices.componentType) +
                 " is not an unsigned integer type");
        if (s.indices.byteOffset < 0 || s.values.byteOffset < 0)
            fail(swhat + ": negative byteOffset");
        const std::size_t n = std::size_t(s.count);
        const ByteRange ir = viewRange(s.indices.bufferView, std::size_t(s.indices.byteOffset), n,
                                       std::size_t(indexSize), swhat + ".indices", false);
        const ByteRange vr = viewRange(s.values.bufferView, std::size_t(s.values.byteOffset), n,
                                       elementSize, swhat + ".values", false);
        for (std::size_t k = 0; k < n; ++k) {
            const double target =
                readComponent(ir.data + k * ir.stride, s.indices.componentType, false);
            if (!(target < double(a.count)))
                fail(swhat + ".indices[" + std::to_string(k) +
                     "]: " + std::to_string(std::uint64_t(target)) + " is not below count " +
                     std::to_string(a.count));
            double* dst = out->values.data() + std::size_t(target) * std::size_t(components);
            for (int c = 0; c < components; ++c)
                dst[c] = readComponent(vr.data + k * vr.stride + std::size_t(c * size),
                                       a.componentType, a.normalized);
        }
    }
    cached = std::move(out);
    return *cached;
}

std::vector<std::uint32_t> Loader::indexAccessor(int index, std::size_t vertexCount,
                                                 const std::string& what) {
    if (index < 0 || std::size_t(index) >= m_.accessors.size())
        fail(what + ": indices accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& a = m_.accessors[std::size_t(index)];
    const std::string awhat = indexed("accessors", std::size_t(index));
    if (a.type != TINYGLTF_TYPE_SCALAR) fail(what + ": indices " + awhat + " is not SCALAR");
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        fail(what + ": indices " + awhat + " has componentType " + std::to_string(a.componentType) +
             ", not an unsigned integer type");
    // Exact integers up to 2^32 survive the trip through double.
    const AccessorValues& values = accessor(index);
    std::vector<std::uint32_t> out(values.count);
    for (std::size_t i = 0; i < values.count; ++i) {
        const double v = values.values[i];
        if (!(v < double(vertexCount)))
            fail(what + ": index " + std::to_string(std::uint64_t(v)) + " (" + awhat + "[" +
                 std::to_string(i) + "]) is not below the vertex count " +
                 std::to_string(vertexCount));
        out[i] = std::uint32_t(v);
    }
    return out;
}

/// Copies an accessor's values into glm vectors of N components, padding with `fill`.
template <int N>
std::vector<glm::vec<N, float>> toVectors(const AccessorValues& a, float fill = 0.0f) {
    std::vector<glm::vec<N, float>> out(a.count, glm::vec<N, float>(fill));
    const int n = std::min(N, a.components);
    for (std::size_t i = 0; i < a.count; ++i)
        for (int c = 0; c < n; ++c)
            out[i][c] = float(a.values[i * std::size_t(a.components) + std::size_t(c)]);
    return out;
}

/// The element indices of a primitive's draw as lists (strips, fans and loops unrolled as the
/// glTF specification numbers their triangles and lines).
std::vector<std::uint32_t> unrolled(int mode, const std::vector<std::uint32_t>& in,
                                    GltfPrimitive::Kind& kind) {
    std::vector<std::uint32_t> out;
    const std::size_t n = in.size();
    switch (mode) {
    case TINYGLTF_MODE_POINTS:
        kind = GltfPrimitive::Kind::Points;
        return in;
    case TINYGLTF_MODE_LINE:
        kind = GltfPrimitive::Kind::Lines;
        out.assign(in.begin(), in.begin() + std::ptrdiff_t(n - n % 2));
        return out;
    case TINYGLTF_MODE_LINE_LOOP:
    case TINYGLTF_MODE_LINE_STRIP:
        kind = GltfPrimitive::Kind::Lines;
        for (std::size_t i = 0; i + 1 < n; ++i)
            out.insert(out.end(), {in[i], in[i + 1]});
        if (mode == TINYGLTF_MODE_LINE_LOOP && n > 2) out.insert(out.end(), {in[n - 1], in[0]});
        return out;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
        kind = GltfPrimitive::Kind::Triangles;
        for (std::size_t i = 0; i + 2 < n; ++i) // {v_i, v_i+(1+i%2), v_i+(2-i%2)}
            out.insert(out.end(), {in[i], in[i + 1 + i % 2], in[i + 2 - i % 2]});
        return out;
    case TINYGLTF_MODE_TRIANGLE_FAN:
        kind = GltfPrimitive::Kind::Triangles;
        for (std::size_t i = 0; i + 2 < n; ++i) // {v_i+1, v_i+2, v_0}
            out.insert(out.end(), {in[i + 1], in[i + 2], in[0]});
        return out;
    default: // TRIANGLES (the mode was checked)
        kind = GltfPrimitive::Kind::Triangles;
        out.assign(in.begin(), in.begin() + std::ptrdiff_t(n - n % 3));
        return out;
    }
}

GltfPrimitive Loader::primitive(const tinygltf::Mesh& mesh, std::size_t meshIndex,
                                std::size_t primitiveIndex) {
    const tinygltf::Primitive& p = mesh.primitives[primitiveIndex];
    const std::string what =
        indexed("meshes", meshIndex) + "." + indexed("primitives", primitiveIndex);
    GltfPrimitive out;
    if (p.material >= 0 && std::size_t(p.material) >= m_.materials.size())
        fail(what + ": material " + std::to_string(p.material) + " does not exist");
    out.material = p.material;
    if (p.mode < TINYGLTF_MODE_POINTS || p.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        fail(what + ": mode " + std::to_string(p.mode) + " unknown");

    // Checks an attribute's accessor type and count; returns its values.
    auto attribute = [&](const std::string& name, std::initializer_list<int> types,
                         std::size_t count) -> const AccessorValues* {
        const auto it = p.attributes.find(name);
        if (it == p.attributes.end()) return nullptr;
        const AccessorValues& values = accessor(it->second);
        const tinygltf::Accessor& a = m_.accessors[std::size_t(it->second)];
        if (std::find(types.begin(), types.end(), a.type) == types.end())
            fail(what + ": attribute " + name + " (" +
                 indexed("accessors", std::size_t(it->second)) + ") has the wrong type");
        if (count != 0 && values.count != count)
            fail(what + ": attribute " + name + " has " + std::to_string(values.count) +
                 " elements, POSITION has " + std::to_string(count));
        return &values;
    };

    const AccessorValues* position = attribute("POSITION", {TINYGLTF_TYPE_VEC3}, 0);
    if (!position) return out; // glTF: a primitive without positions is not drawn
    const std::size_t count = position->count;
    out.positions = toVectors<3>(*position);
    if (const auto* a = attribute("NORMAL", {TINYGLTF_TYPE_VEC3}, count))
        out.normals = toVectors<3>(*a);
    if (const auto* a = attribute("TANGENT", {TINYGLTF_TYPE_VEC4}, count))
        out.tangents = toVectors<4>(*a);
    if (const auto* a = attribute("TEXCOORD_0", {TINYGLTF_TYPE_VEC2}, count))
        out.texCoords0 = toVectors<2>(*a);
    if (const auto* a = attribute("TEXCOORD_1", {TINYGLTF_TYPE_VEC2}, count))
        out.texCoords1 = toVectors<2>(*a);
    if (const auto* a = attribute("COLOR_0", {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, count))
        out.colors = toVectors<4>(*a, 1.0f);

    // Morph targets at the mesh's default weights (absent weights are 0).
    for (std::size_t t = 0; t < p.targets.size(); ++t) {
        const double weight = t < mesh.weights.size() ? mesh.weights[t] : 0.0;
        if (weight == 0.0) continue;
        for (const auto& [name, index] : p.targets[t]) {
            std::vector<glm::vec3>* target = name == "POSITION" ? &out.positions
                                             : name == "NORMAL" ? &out.normals
                                                                : nullptr;
            const bool tangent = name == "TANGENT" && !out.tangents.empty();
            if ((!target || target->empty()) && !tangent) continue;
            const AccessorValues& d = accessor(index);
            if (d.count != count || d.components != 3)
                fail(what + ": morph target " + std::to_string(t) + " " + name +
                     " does not have one VEC3 per vertex");
            for (std::size_t i = 0; i < count; ++i) {
                const glm::vec3 delta(float(d.values[3 * i]), float(d.values[3 * i + 1]),
                                      float(d.values[3 * i + 2]));
                if (tangent)
                    out.tangents[i] += glm::vec4(float(weight) * delta, 0.0f);
                else
                    (*target)[i] += float(weight) * delta;
            }
        }
    }

    std::vector<std::uint32_t> elements;
    if (p.indices >= 0) {
        elements = indexAccessor(p.indices, count, what);
    } else {
        elements.resize(count);
        for (std::size_t i = 0; i < count; ++i)
            elements[i] = std::uint32_t(i);
    }
    if (p.mode == TINYGLTF_MODE_TRIANGLES && elements.size() % 3 != 0)
        fail(what + ": " + std::to_string(elements.size()) +
             " vertices do not make whole triangles");
    out.indices = unrolled(p.mode, elements, out.kind);
    for (const glm::vec3& v : out.positions) {
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            fail(what + ": POSITION holds a value that is not finite");
        out.bounds.extendBy(glm::dvec3(v));
    }
    return out;
}

GltfTextureRef Loader::textureRef(int index, int texCoord, double scale,
                                  const std::string& what) const {
    GltfTextureRef ref;
    if (index < 0) return ref;
    if (std::size_t(index) >= m_.textures.size())
        fail(what + ": texture " + std::to_string(index) + " does not exist");
    if (texCoord < 0 || texCoord > 1)
        fail(what + ": texCoord " + std::to_string(texCoord) +
             " is not supported (TEXCOORD_0 and TEXCOORD_1 are)");
    ref.texture = index;
    ref.texCoord = texCoord;
    ref.scale = float(scale);
    return ref;
}

void Loader::materials(GltfAsset& out) const {
    for (std::size_t i = 0; i < m_.materials.size(); ++i) {
        const tinygltf::Material& s = m_.materials[i];
        const std::string what = indexed("materials", i);
        GltfMaterial mat;
        mat.name = s.name;
        const auto& pbr = s.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() == 4)
            mat.baseColorFactor =
                glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                          float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3]));
        mat.metallicFactor = float(pbr.metallicFactor);
        mat.roughnessFactor = float(pbr.roughnessFactor);
        mat.baseColorTexture =
            textureRef(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, 1.0, what);
        mat.metallicRoughnessTexture = textureRef(pbr.metallicRoughnessTexture.index,
                                                  pbr.metallicRoughnessTexture.texCoord, 1.0, what);
        mat.normalTexture = textureRef(s.normalTexture.index, s.normalTexture.texCoord,
                                       s.normalTexture.scale, what);
        mat.occlusionTexture = textureRef(s.occlusionTexture.index, s.occlusionTexture.texCoord,
                                          s.occlusionTexture.strength, what);
        mat.emissiveTexture =
            textureRef(s.emissiveTexture.index, s.emissiveTexture.texCoord, 1.0, what);
        if (s.emissiveFactor.size() == 3)
            mat.emissiveFactor = glm::vec3(float(s.emissiveFactor[0]), float(s.emissiveFactor[1]),
                                           float(s.emissiveFactor[2]));
        if (s.alphaMode.empty() || s.alphaMode == "OPAQUE")
            mat.alphaMode = GltfAlphaMode::Opaque;
        else if (s.alphaMode == "MASK")
            mat.alphaMode = GltfAlphaMode::Mask;
        else if (s.alphaMode == "BLEND")
            mat.alphaMode = GltfAlphaMode::Blend;
        else
            fail(what + ": alphaMode " + s.alphaMode + " unknown");
        mat.alphaCutoff = float(s.alphaCutoff);
        mat.doubleSided = s.doubleSided;
        mat.unlit = s.extensions.count("KHR_materials_unlit") > 0;
        out.materials.push_back(std::move(mat));
    }
}

void Loader::textures(GltfAsset& out) {
    for (std::size_t i = 0; i < m_.samplers.size(); ++i) {
        const tinygltf::Sampler& s = m_.samplers[i];
        GltfSampler sampler;
        auto check = [&](int value, std::initializer_list<int> allowed, const char* field) {
            if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
                fail(indexed("samplers", i) + ": " + field + " " + std::to_string(value) +
                     " unknown");
            return value;
        };
        if (s.magFilter != -1) sampler.magFilter = check(s.magFilter, {9728, 9729}, "magFilter");
        if (s.minFilter != -1)
            sampler.minFilter =
                check(s.minFilter, {9728, 9729, 9984, 9985, 9986, 9987}, "minFilter");
        sampler.wrapS = check(s.wrapS, {33071, 33648, 10497}, "wrapS");
        sampler.wrapT = check(s.wrapT, {33071, 33648, 10497}, "wrapT");
        out.samplers.push_back(sampler);
    }
    for (std::size_t i = 0; i < m_.images.size(); ++i) {
        tinygltf::Image& s = m_.images[i];
        const std::string what = indexed("images", i);
        GltfImage image;
        image.name = s.name;
        if (s.width <= 0 || s.height <= 0 || s.image.empty())
            fail(what + ": no decoded pixels (missing or undecodable image)");
        if (s.component < 1 || s.component > 4 || (s.bits != 8 && s.bits != 16))
            fail(what + ": " + std::to_string(s.component) + " channels of " +
                 std::to_string(s.bits) + " bits are not supported");
        const std::size_t bytesPer = std::size_t(s.bits / 8);
        const std::size_t pixels = std::size_t(s.width) * std::size_t(s.height);
        if (s.image.size() != pixels * std::size_t(s.component) * bytesPer)
            fail(what + ": decoded size does not match " + std::to_string(s.width) + "x" +
                 std::to_string(s.height));
        image.width = s.width;
        image.height = s.height;
        if (s.component == 4 && bytesPer == 1) {
            image.rgba = std::move(s.image); // tinygltf's usual output: taken as it is
        } else {
            // Plain loops per layout: this runs over millions of texels.
            image.rgba.resize(pixels * 4);
            std::vector<std::uint8_t> eight(pixels * std::size_t(s.component));
            if (bytesPer == 1) {
                std::memcpy(eight.data(), s.image.data(), eight.size());
            } else { // 16 bits, little endian: the nearest 8-bit value
                for (std::size_t i = 0; i < eight.size(); ++i) {
                    const unsigned v = unsigned(s.image[2 * i]) | unsigned(s.image[2 * i + 1]) << 8;
                    eight[i] = std::uint8_t((v * 255u + 32767u) / 65535u);
                }
            }
            std::uint8_t* dst = image.rgba.data();
            const std::uint8_t* src = eight.data();
            switch (s.component) {
            case 1: // grey
                for (std::size_t p = 0; p < pixels; ++p, dst += 4)
                    dst[0] = dst[1] = dst[2] = src[p], dst[3] = 255;
                break;
            case 2: // grey and alpha
                for (std::size_t p = 0; p < pixels; ++p, dst += 4)
                    dst[0] = dst[1] = dst[2] = src[2 * p], dst[3] = src[2 * p + 1];
                break;
            case 3:
                for (std::size_t p = 0; p < pixels; ++p, dst += 4)
                    dst[0] = src[3 * p], dst[1] = src[3 * p + 1], dst[2] = src[3 * p + 2],
                    dst[3] = 255;
                break;
            default:
                std::memcpy(dst, src, pixels * 4);
                break;
            }
        }
        out.images.push_back(std::move(image));
    }
    for (std::size_t i = 0; i < m_.textures.size(); ++i) {
        const tinygltf::Texture& s = m_.textures[i];
        const std::string what = indexed("textures", i);
        if (s.source < 0 || std::size_t(s.source) >= m_.images.size())
            fail(what + ": source image " + std::to_string(s.source) + " does not exist");
        if (s.sampler >= 0 && std::size_t(s.sampler) >= m_.samplers.size())
            fail(what + ": sampler " + std::to_string(s.sampler) + " does not exist");
        out.textures.push_back({s.source, s.sampler});
    }
}

glm::dmat4 localMatrix(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        glm::dmat4 m;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                m[c][r] = n.matrix[std::size_t(c * 4 + r)];
        return m;
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (n.translation.size() == 3)
        t[3] = glm::dvec4(n.translation[0], n.translation[1], n.translation[2], 1.0);
    if (n.rotation.size() == 4) { // x y z w
        glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
        const double length = glm::length(q);
        if (length > 0.0) r = glm::mat4_cast(q / length);
    }
    if (n.scale.size() == 3)
        s = glm::scale(glm::dmat4(1.0), glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    return t * r * s;
}

void Loader::addNode(GltfAsset& out, int node, const glm::dmat4& parent, int depth,
                     std::vector<char>& visited) const {
    if (node < 0 || std::size_t(node) >= m_.nodes.size())
        fail("node " + std::to_string(node) + " does not exist");
    const std::string what = indexed("nodes", std::size_t(node));
    if (visited[std::size_t(node)])
        fail(what + ": reached twice (a cycle, or a child of two parents)");
    if (depth > kMaxNodeDepth)
        fail(what + ": the node tree is deeper than " + std::to_string(kMaxNodeDepth));
    visited[std::size_t(node)] = 1;
    const tinygltf::Node& n = m_.nodes[std::size_t(node)];
    const glm::dmat4 matrix = parent * localMatrix(n);
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(matrix[c][r])) fail(what + ": transform is not finite");
    if (n.mesh >= 0) {
        if (std::size_t(n.mesh) >= m_.meshes.size())
            fail(what + ": mesh " + std::to_string(n.mesh) + " does not exist");
        out.instances.push_back({node, n.mesh, matrix});
    }
    for (int child : n.children)
        addNode(out, child, matrix, depth + 1, visited);
}

void Loader::nodes(GltfAsset& out) const {
    std::vector<int> roots;
    if (!m_.scenes.empty()) {
        int scene = m_.defaultScene >= 0 ? m_.defaultScene : 0;
        if (std::size_t(scene) >= m_.scenes.size())
            fail("scene " + std::to_string(scene) + " does not exist");
        roots = m_.scenes[std::size_t(scene)].nodes;
    } else {
        // No scene: every node that is no node's child is a root.
        std::vector<char> isChild(m_.nodes.size(), 0);
        for (const auto& n : m_.nodes)
            for (int c : n.children)
                if (c >= 0 && std::size_t(c) < m_.nodes.size()) isChild[std::size_t(c)] = 1;
        for (std::size_t i = 0; i < m_.nodes.size(); ++i)
            if (!isChild[i]) roots.push_back(int(i));
    }
    std::vector<char> visited(m_.nodes.size(), 0);
    for (int root : roots)
        addNode(out, root, glm::dmat4(1.0), 0, visited);
}

GltfAsset Loader::load() {
    checkExtensions();
    checkBufferViews();
    accessorCache_.resize(m_.accessors.size());
    GltfAsset out;
    out.fileName = file_;
    materials(out);
    textures(out);
    out.meshes.resize(m_.meshes.size());
    for (std::size_t i = 0; i < m_.meshes.size(); ++i) {
        const tinygltf::Mesh& mesh = m_.meshes[i];
        out.meshes[i].name = mesh.name;
        for (std::size_t j = 0; j < mesh.primitives.size(); ++j)
            out.meshes[i].primitives.push_back(primitive(mesh, i, j));
    }
    nodes(out);
    for (const GltfInstance& instance : out.instances)
        for (const GltfPrimitive& p : out.meshes[std::size_t(instance.mesh)].primitives)
            for (const glm::vec3& v : p.positions)
                out.bounds.extendBy(glm::dvec3(instance.matrix * glm::dvec4(glm::dvec3(v), 1.0)));
    return out;
}

} // namespace

namespace {

/// What tinygltf may read for one file: the file itself and the files its URIs name, all
/// inside the glTF file's folder (no `..`, no absolute paths, no symbolic link leading out,
/// no working-directory fallback) and each at most limits::maxGltfFileSize bytes.
struct GltfFileAccess {
    std::filesystem::path folder; ///< canonical
    std::string refused;          ///< the first file refused, for the error message
    std::string refusedWhy;
};

bool allowedFileExists(const std::string& path, void* user) {
    auto& access = *static_cast<GltfFileAccess*>(user);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return false;
    if (!isInsideFolder(access.folder, path)) {
        if (access.refused.empty()) {
            access.refused = path;
            access.refusedWhy = "outside the folder of the glTF file";
        }
        return false;
    }
    if (!std::filesystem::is_regular_file(path, ec)) {
        if (access.refused.empty()) {
            access.refused = path;
            access.refusedWhy = "not a regular file";
        }
        return false;
    }
    return true;
}

std::string unexpandedPath(const std::string& path, void*) {
    return path; // no ~ or $VARIABLE expansion: a URI is a name, not a shell word
}

bool readAllowedFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
    auto& access = *static_cast<GltfFileAccess*>(user);
    if (!allowedFileExists(path, user)) {
        if (err) *err += "refused to read " + path + ": outside the glTF file's folder\n";
        return false;
    }
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size > limits::maxGltfFileSize) {
        if (access.refused.empty()) {
            access.refused = path;
            access.refusedWhy = ec ? ec.message()
                                   : std::to_string(size) + " bytes, more than the limit of " +
                                         std::to_string(limits::maxGltfFileSize);
        }
        if (err) *err += "cannot read " + path + "\n";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out->resize(std::size_t(size));
    if (!in || !in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) {
        if (err) *err += "cannot read " + path + "\n";
        return false;
    }
    return true;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "the glTF loader does not write files\n";
    return false;
}

std::uint32_t bigEndian32(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

/// Width and height from a PNG or JPEG header; false for anything else or a broken header.
bool imageHeaderSize(const unsigned char* bytes, std::size_t size, std::uint32_t& width,
                     std::uint32_t& height) {
    static constexpr unsigned char pngMagic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (size >= 24 && std::memcmp(bytes, pngMagic, 8) == 0 &&
        std::memcmp(bytes + 12, "IHDR", 4) == 0) {
        width = bigEndian32(bytes + 16);
        height = bigEndian32(bytes + 20);
        return true;
    }
    if (size < 4 || bytes[0] != 0xFF || bytes[1] != 0xD8) return false;
    // JPEG: walk the marker segments to the first start-of-frame (SOF0..SOF15 but DHT, JPG, DAC).
    std::size_t pos = 2;
    while (pos + 4 <= size) {
        if (bytes[pos] != 0xFF) return false;
        const unsigned char marker = bytes[pos + 1];
        if (marker == 0xFF) {
            ++pos; // fill byte
            continue;
        }
        const std::size_t length = std::size_t(bytes[pos + 2]) << 8 | bytes[pos + 3];
        if (length < 2) return false;
        if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 &&
            marker != 0xCC) {
            if (pos + 9 > size) return false;
            height = std::uint32_t(bytes[pos + 5]) << 8 | bytes[pos + 6];
            width = std::uint32_t(bytes[pos + 7]) << 8 | bytes[pos + 8];
            return true;
        }
        pos += 2 + length;
    }
    return false;
}

/// tinygltf's decoder (stb_image) behind a size check: an image header declaring more than
/// limits::maxImageSide / maxImagePixels is refused before the decoder allocates its pixels.
bool loadCheckedImage(tinygltf::Image* image, const int index, std::string* err, std::string* warn,
                      int requiredWidth, int requiredHeight, const unsigned char* bytes, int size,
                      void* user) {
    std::uint32_t width = 0, height = 0;
    const std::string what = "images[" + std::to_string(index) + "]";
    if (size <= 0 || !imageHeaderSize(bytes, std::size_t(size), width, height)) {
        if (err) *err += what + ": not a PNG or JPEG image (or its header is broken)\n";
        return false;
    }
    if (width == 0 || height == 0 || width > limits::maxImageSide ||
        height > limits::maxImageSide || std::uint64_t(width) * height > limits::maxImagePixels) {
        if (err)
            *err += what + ": " + std::to_string(width) + "x" + std::to_string(height) +
                    " pixels exceeds the image limit (" + std::to_string(limits::maxImageSide) +
                    " per side, " + std::to_string(limits::maxImagePixels) + " in all)\n";
        return false;
    }
    // And the file's images together (eight large images may share one small file).
    auto& decoded = *static_cast<std::uint64_t*>(user);
    const std::uint64_t pixels = std::uint64_t(width) * height;
    if (pixels > limits::maxGltfImagePixels - decoded) {
        if (err)
            *err += what + ": the file's images hold more than " +
                    std::to_string(limits::maxGltfImagePixels) + " pixels in all\n";
        return false;
    }
    decoded += pixels;
    return tinygltf::LoadImageData(image, index, err, warn, requiredWidth, requiredHeight, bytes,
                                   size, nullptr);
}

} // namespace

GltfAsset loadGltf(const std::string& path) {
    regularFileSize(path, "cannot read glTF file", limits::maxGltfFileSize);
    std::error_code ec;
    char magic[4] = {};
    {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw Error("cannot open the file", path);
        in.read(magic, 4);
    }
    const bool binary = std::memcmp(magic, "glTF", 4) == 0;

    GltfFileAccess access;
    access.folder = std::filesystem::canonical(path, ec).parent_path();
    if (ec) throw Error("cannot resolve the file's folder: " + ec.message(), path);
    tinygltf::Model model;
    tinygltf::TinyGLTF parser;
    parser.SetFsCallbacks(
        {&allowedFileExists, &unexpandedPath, &readAllowedFile, &refuseWrite, &access});
    std::uint64_t decodedPixels = 0;
    parser.SetImageLoader(&loadCheckedImage, &decodedPixels);
    std::string err, warn;
    const bool ok = binary ? parser.LoadBinaryFromFile(&model, &err, &warn, path)
                           : parser.LoadASCIIFromFile(&model, &err, &warn, path);
    if (!access.refused.empty())
        throw Error("refused to read '" + access.refused + "': " + access.refusedWhy, path);
    if (!ok || !err.empty())
        throw Error(err.empty() ? std::string("tinygltf could not read the file")
                                : "tinygltf: " + firstLine(err),
                    path);
    return Loader(path, model).load();
}

} // namespace volsg
