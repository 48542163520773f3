#pragma once
// The scene generator of the structure-aware scene fuzzer (FuzzSceneGraph.cpp): from fuzz
// bytes, a valid Inventor scene text whose nodes are of any registered type, each field set
// from a menu of extreme values, with DEF/USE sharing and USE chains that double instances.
// Types and fields come from the node registry and its field reflection, so a new node type
// or field is fuzzed without a change here.
//
// Scene text cannot hold NaN or infinity (the reader refuses them), but code can set them: a
// non-finite value picked for a field is written as 0 and kept as a Poke, which the fuzzer
// applies through the field after reading, as an application would.

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include <volsg/core/NodeType.h>
#include <volsg/engines/Engine.h>
#include <volsg/fields/Fields.h>
#include <volsg/io/ReaderSupport.h>

namespace volsg::fuzz {

/// The renderer path a generated scene is meant for (its core block draws through it).
enum class RenderPath { Volume, ShearWarp, Slices, Gltf, Reference };
inline constexpr int kRenderPathCount = 5;
inline constexpr const char* kRenderPathNames[kRenderPathCount] = {"volume", "shearwarp", "slices",
                                                                   "gltf", "reference"};

/// A non-finite value for component `component` of `field` of the node DEF'd `node`.
struct Poke {
    std::string node, field;
    std::size_t component;
    float value;
};

/// The files a generated scene may name (FuzzSceneGraph.cpp writes them into its scratch
/// folder, the scene's folder): small valid ones, a missing one, the folder, a device.
inline constexpr const char* kSceneFileMenu[] = {
    "tiny.nrrd", "tiny.gltf",    "tiny.png", "tiny.iv", "loop.iv",
    "data.raw",  "missing.nrrd", "",         ".",       "/dev/zero"};

/// The registered types the generator picks from, taken once (the reader registers the engine
/// and animated node types on first use: a list taken per input would change between runs).
struct SceneTypes {
    std::vector<const NodeType*> nodes;   ///< node types (children)
    std::vector<const NodeType*> engines; ///< engine types (connection sources only)

    static SceneTypes fromRegistry() {
        SceneTypes s;
        for (const NodeType* t : reader::registry().all())
            if (!t->isAbstract())
                (t->isDerivedFrom(Engine::classType()) ? s.engines : s.nodes).push_back(t);
        const auto byName = [](const NodeType* a, const NodeType* b) {
            return std::string_view(a->name()) < b->name();
        };
        std::sort(s.nodes.begin(), s.nodes.end(), byName);
        std::sort(s.engines.begin(), s.engines.end(), byName);
        return s;
    }
};

class SceneGenerator {
public:
    SceneGenerator(FuzzedDataProvider& in, RenderPath path, const SceneTypes& types)
        : in_(in), path_(path), types_(types.nodes), engines_(types.engines) {}

    /// The scene: a root Separator of random nodes with the path's core block among them.
    std::string generate() {
        text_ = "#Inventor V2.1 ascii\nSeparator {\n";
        const int before = in_.ConsumeIntegralInRange(0, 4);
        for (int i = 0; i < before; ++i)
            randomNode(1);
        if (in_.ConsumeIntegralInRange(0, 3) == 0) useChain();
        coreBlock();
        const int after = in_.ConsumeIntegralInRange(0, 3);
        for (int i = 0; i < after; ++i)
            randomNode(1);
        text_ += "}\n";
        return text_;
    }

    const std::vector<Poke>& pokes() const { return pokes_; }

private:
    static constexpr int kMaxDepth = 5;
    static constexpr int kMaxNodes = 80;
    static constexpr std::size_t kNumberBudget = 200000;             ///< numbers in all MF values
    static constexpr std::size_t kTextBudget = std::size_t(4) << 20; ///< bytes of scene text

    FuzzedDataProvider& in_;
    RenderPath path_;
    const std::vector<const NodeType*>& types_;
    const std::vector<const NodeType*>& engines_;
    std::string text_;
    std::vector<std::string> defined_; ///< DEF names of completed nodes (USE-able)
    std::vector<Poke> pokes_;
    int nodes_ = 0, chains_ = 0;
    std::size_t numbers_ = 0;

    // ---- nodes ----------------------------------------------------------------------------

    /// `DEF N<k> Type { fields children }`: any registered type, or a USE of an earlier node.
    void randomNode(int depth) {
        if (nodes_ >= kMaxNodes || depth > kMaxDepth || types_.empty()) return;
        if (!defined_.empty() && in_.ConsumeIntegralInRange(0, 7) == 0) {
            text_ += "USE " +
                     defined_[in_.ConsumeIntegralInRange<std::size_t>(0, defined_.size() - 1)] +
                     "\n";
            return;
        }
        const NodeType& type =
            *types_[in_.ConsumeIntegralInRange<std::size_t>(0, types_.size() - 1)];
        node(type, depth, 2, {}, [&](Node& prototype) {
            if (!prototype.children()) return;
            const int children = in_.ConsumeIntegralInRange(0, 5);
            for (int i = 0; i < children; ++i)
                randomNode(depth + 1);
        });
    }

    /// One node of `type`: each field (but `preset`, written first) set with probability
    /// 1/`oneIn`, then what `body` adds; DEF'd, and USE-able once complete.
    template <class Body>
    void node(const NodeType& type, int depth, int oneIn, const std::string& preset, Body body) {
        ++nodes_;
        const std::string name = "N" + std::to_string(nodes_);
        text_ += "DEF " + name + " " + type.name() + " {\n" + preset;
        const ref_ptr<Node> prototype = type.create();
        for (std::size_t i = 0; i < prototype->fieldCount(); ++i) {
            const Field& f = *prototype->fieldAt(i);
            if (preset.find(std::string(f.name()) + " ") != std::string::npos) continue;
            if (in_.ConsumeIntegralInRange(1, oneIn) != 1) continue;
            fieldValue(name, type, f, depth);
        }
        body(*prototype);
        text_ += "}\n";
        defined_.push_back(name);
    }

    void node(const char* typeName, int depth, const std::string& preset) {
        if (const NodeType* t = reader::registry().find(typeName))
            node(*t, depth, 4, preset, [](Node&) {});
    }

    /// `DEF C0 Separator { node }`, then `n` Separators each USEing the one before twice:
    /// 2^n instances of the node. At most 2^12: past the traversal's instance total (2^24) a
    /// scene is refused only after 2^24 visits, ~1 s at -O2 but over libFuzzer's timeout under
    /// ASan (HostileSceneTest keeps that refusal's regression test); and 2^14 instances of a few
    /// full-screen shapes draw in 6 s at -O2 but 45 s under ASan: bounded work, not a hang.
    void useChain() {
        const int n = in_.PickValueInArray({1, 2, 3, 5, 8, 10, 12});
        const std::string prefix = "C" + std::to_string(chains_++) + "_";
        text_ += "DEF " + prefix + "0 Separator {\n";
        randomNode(2);
        text_ += "}\n";
        for (int i = 1; i <= n; ++i)
            text_ += "DEF " + prefix + std::to_string(i) + " Separator { USE " + prefix +
                     std::to_string(i - 1) + " USE " + prefix + std::to_string(i - 1) + " }\n";
        defined_.push_back(prefix + std::to_string(n));
    }

    /// Small in-process volume data: a generator of at most 24^3 voxels, or the scratch NRRD.
    std::string volumeDataPreset() {
        if (in_.ConsumeIntegralInRange(0, 5) == 0) return "fileName \"tiny.nrrd\"\n";
        const char* generator = in_.PickValueInArray(
            {"SOFT_SPHERE", "MARSCHNER_LOBB", "THIN_SHELL", "RAMP16", "LABELLED"});
        const int n = in_.PickValueInArray({8, 2, 3, 5, 16, 24});
        return std::string("generator ") + generator + " dimensions " + std::to_string(n) + " " +
               std::to_string(n) + " " + std::to_string(n) + "\n";
    }

    /// What the path draws, its fields fuzzed less often than a random node's so that
    /// most scenes get as far as drawing.
    void coreBlock() {
        if (path_ == RenderPath::Gltf) {
            node("GltfModel", 1, "fileName \"tiny.gltf\"\n");
            return;
        }
        node("VolumeData", 1, volumeDataPreset());
        node("TransferFunction", 1, "");
        if (in_.ConsumeIntegralInRange(0, 3) == 0) node("BoxClip", 1, "");
        switch (path_) {
        case RenderPath::Volume:
        case RenderPath::Reference:
            node("Volume", 1, "");
            break;
        case RenderPath::ShearWarp:
            if (const NodeType* t = reader::registry().find("ShearWarpVolume"))
                node(*t, 1, 4, "", [&](Node&) {
                    const int objects = in_.ConsumeIntegralInRange(1, 3);
                    for (int i = 0; i < objects; ++i)
                        node("VolumeObject", 2, "");
                });
            break;
        case RenderPath::Slices:
            node(in_.ConsumeBool() ? "ObliqueSlice" : "OrthoSlice", 1, "");
            if (in_.ConsumeBool()) node("OrthoSlice", 1, "");
            break;
        case RenderPath::Gltf:
            break;
        }
    }

    // ---- field values ---------------------------------------------------------------------

    void fieldValue(const std::string& nodeName, const NodeType& type, const Field& f, int depth) {
        const std::string_view t = f.typeName();
        const std::string head = std::string(f.name()) + " ";
        if (const auto* e = dynamic_cast<const SFEnum*>(&f)) {
            const auto& entries = e->names().entries;
            if (entries.empty()) return;
            text_ += head +
                     entries[in_.ConsumeIntegralInRange<std::size_t>(0, entries.size() - 1)].first;
        } else if (const auto* b = dynamic_cast<const SFBitMask*>(&f)) {
            text_ += head + bitMask(b->names());
        } else if (t == "SFNode") {
            text_ += head;
            nodeValue(depth);
        } else if (t == "MFNode") {
            text_ += head + "[\n";
            const int n = in_.ConsumeIntegralInRange(0, 3);
            for (int i = 0; i < n; ++i)
                nodeValue(depth);
            text_ += "]";
        } else if (t == "SFImage") {
            text_ += head + image();
        } else if (!engines_.empty() && depth < kMaxDepth &&
                   in_.ConsumeIntegralInRange(0, 31) == 0) {
            text_ += head + "= ";
            engineSource(depth);
        } else if (t.size() > 2 && (t[0] == 'S' || t[0] == 'M') && t[1] == 'F') {
            const bool list = t[0] == 'M';
            const std::string_view value = t.substr(2);
            const int components = componentsOf(value);
            if (components == 0) return; // a type no node of the library has: left default
            const bool fileField = std::string_view(f.name()).find("ile") != std::string::npos ||
                                   std::string_view(type.name()) == "File";
            text_ += head;
            if (list) {
                listValue(nodeName, f.name(), value, components, fileField);
            } else {
                for (int c = 0; c < components; ++c) {
                    if (c) text_ += ' ';
                    text_ += scalar(nodeName, f.name(), value, std::size_t(c), fileField);
                }
            }
        } else {
            return;
        }
        text_ += "\n";
    }

    /// Values a field type has per element; 0 for types the generator leaves alone.
    static int componentsOf(std::string_view value) {
        if (value == "Float" || value == "Int32" || value == "UInt32" || value == "Bool" ||
            value == "String" || value == "Double" || value == "Time" || value == "Short" ||
            value == "UShort" || value == "Name")
            return 1;
        if (value == "Vec2f") return 2;
        if (value == "Vec3f" || value == "Color") return 3;
        if (value == "Vec4f" || value == "Rotation" || value == "Plane") return 4;
        if (value == "Matrix") return 16;
        return 0;
    }

    /// `[ ... ]` of a count from the menu (within the scene's number budget): a few values
    /// from the menu repeated, so long lists stay cheap to make but hostile.
    void listValue(const std::string& nodeName, const char* fieldName, std::string_view value,
                   int components, bool fileField) {
        std::size_t count =
            in_.PickValueInArray<std::size_t>({0, 1, 2, 3, 4, 5, 8, 17, 100, 1000, 10000, 70000});
        const std::size_t left = kNumberBudget - std::min(numbers_, kNumberBudget);
        count = std::min(count, left / std::size_t(components));
        numbers_ += count * std::size_t(components);
        const std::size_t distinct = std::min<std::size_t>(count, 6);
        std::vector<std::string> pattern;
        for (std::size_t i = 0; i < distinct * std::size_t(components); ++i)
            pattern.push_back(scalar(nodeName, fieldName, value, pattern.size(), fileField));
        // Long strings repeated make long text: the list stays within the scene's text budget.
        std::size_t patternBytes = 0;
        for (const std::string& p : pattern)
            patternBytes += p.size() + 1;
        const std::size_t elementBytes = patternBytes / std::max<std::size_t>(distinct, 1) + 1;
        const std::size_t textLeft = kTextBudget - std::min(text_.size(), kTextBudget);
        count = std::min(count, textLeft / elementBytes);
        text_ += "[";
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t first = (i % std::max<std::size_t>(distinct, 1)) * components;
            for (int c = 0; c < components; ++c) {
                text_ += ' ';
                text_ += pattern[first + std::size_t(c)];
            }
            if (i + 1 < count) text_ += ',';
        }
        text_ += " ]";
    }

    /// One number, bool or string of a value type. A non-finite pick becomes a Poke (for a
    /// list: of the first element using this pattern entry).
    std::string scalar(const std::string& nodeName, const char* fieldName, std::string_view value,
                       std::size_t component, bool fileField) {
        if (value == "Bool") return in_.ConsumeBool() ? "TRUE" : "FALSE";
        if (value == "String" || value == "Name") return quoted(text(fileField));
        if (value == "Int32" || value == "Short") return std::to_string(int32());
        if (value == "UInt32" || value == "UShort") return std::to_string(uint32());
        const float v = float32();
        if (!std::isfinite(v)) {
            pokes_.push_back(Poke{nodeName, fieldName, component, v});
            return "0";
        }
        char buffer[32];
        const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
        return std::string(buffer, result.ptr);
    }

    float float32() {
        constexpr float inf = std::numeric_limits<float>::infinity();
        switch (in_.ConsumeIntegralInRange(0, 3)) {
        case 0: // ordinary values keep most scenes drawable
            return in_.PickValueInArray({0.0f, 1.0f, 0.5f, 2.0f, -1.0f, 0.25f, 3.0f, 10.0f});
        case 1:
            return in_.PickValueInArray({0.0f, -0.0f, 1e-38f, -1e-38f, 1e38f, -1e38f, FLT_MAX,
                                         -FLT_MAX, 1e-45f, 1e6f, -1e6f, 1e-6f, 65536.0f,
                                         16777217.0f, -2147483648.0f, 4294967296.0f});
        case 2:
            return in_.PickValueInArray(
                {std::numeric_limits<float>::quiet_NaN(), inf, -inf, 0.0f, 1.0f});
        default: {
            const float v = in_.ConsumeFloatingPoint<float>();
            return std::isfinite(v) ? v : 0.0f;
        }
        }
    }

    std::int32_t int32() {
        if (in_.ConsumeIntegralInRange(0, 3) == 0) return in_.ConsumeIntegral<std::int32_t>();
        return in_.PickValueInArray<std::int32_t>({0, 1, -1, 2, 3, 4, 8, 16, 255, 256, 65535, 65536,
                                                   -2, INT_MAX, INT_MIN, 1 << 20, 1 << 24, 1000000,
                                                   7});
    }

    std::uint32_t uint32() {
        if (in_.ConsumeIntegralInRange(0, 3) == 0) return in_.ConsumeIntegral<std::uint32_t>();
        return in_.PickValueInArray<std::uint32_t>(
            {0u, 1u, 2u, 3u, 16u, 255u, 65536u, UINT_MAX, 1u << 31, 1u << 20, 1000u});
    }

    std::string text(bool fileField) {
        if (fileField) return in_.PickValueInArray(kSceneFileMenu);
        switch (in_.ConsumeIntegralInRange(0, 5)) {
        case 0:
            return "";
        case 1:
            return std::string(text_.size() < kTextBudget / 2
                                   ? in_.PickValueInArray<std::size_t>({1000, 10000, 100000})
                                   : 10,
                               'W');
        case 2:
            return "\xc3\xa9\xe2\x82\xac\xf0\x9f\x98\x80 \xff\xfe";
        case 3:
            return types_.empty()
                       ? "Node"
                       : types_[in_.ConsumeIntegralInRange<std::size_t>(0, types_.size() - 1)]
                             ->name();
        case 4:
            return in_.ConsumeRandomLengthString(64);
        default:
            return "volsg";
        }
    }

    static std::string quoted(const std::string& s) {
        std::string out = "\"";
        for (char c : s) {
            if (c == '"' || c == '\\') out += '\\';
            out += c;
        }
        return out + "\"";
    }

    std::string bitMask(const EnumValues& names) {
        const auto& entries = names.entries;
        if (entries.empty()) return "()";
        const int n = in_.ConsumeIntegralInRange(1, int(std::min<std::size_t>(entries.size(), 4)));
        std::string out = "(";
        for (int i = 0; i < n; ++i) {
            if (i) out += " | ";
            out += entries[in_.ConsumeIntegralInRange<std::size_t>(0, entries.size() - 1)].first;
        }
        return out + ")";
    }

    /// `width height components` and the pixels when there are few; a huge size goes without
    /// them (the reader must refuse it before allocating).
    std::string image() {
        const int w = in_.PickValueInArray({0, 1, 2, 3, 16, 65536, 65537, -1, INT_MAX});
        const int h = in_.PickValueInArray({0, 1, 2, 3, 16, 65536, -1});
        const int c = in_.PickValueInArray({0, 1, 2, 3, 4, 5, -1});
        std::string out = std::to_string(w) + " " + std::to_string(h) + " " + std::to_string(c);
        if (w >= 0 && h >= 0 && std::int64_t(w) * h <= 4096) {
            const std::uint32_t pixel = uint32();
            for (std::int64_t i = 0; i < std::int64_t(w) * h; ++i)
                out += " " + std::to_string(pixel + std::uint32_t(i));
        }
        return out;
    }

    /// A connection's source: `Engine { inputs } . output` (any engine and output; the
    /// evaluator converts the value or refuses the types).
    void engineSource(int depth) {
        const NodeType& type =
            *engines_[in_.ConsumeIntegralInRange<std::size_t>(0, engines_.size() - 1)];
        const ref_ptr<Node> prototype = type.create();
        auto& engine = static_cast<Engine&>(*prototype);
        ++nodes_;
        const std::string name = "E" + std::to_string(nodes_);
        text_ += std::string(type.name()) + " {\n";
        for (std::size_t i = 0; i < prototype->fieldCount(); ++i)
            if (in_.ConsumeBool()) fieldValue(name, type, *prototype->fieldAt(i), depth + 1);
        text_ += "} . ";
        const std::size_t outputs = engine.outputCount();
        text_ +=
            outputs == 0
                ? "output"
                : engine.outputAt(in_.ConsumeIntegralInRange<std::size_t>(0, outputs - 1))->name();
    }

    /// An SFNode/MFNode value: NULL, a USE, or a new node.
    void nodeValue(int depth) {
        const int choice = in_.ConsumeIntegralInRange(0, 2);
        if (choice == 0 || depth >= kMaxDepth || nodes_ >= kMaxNodes) {
            text_ += "NULL\n";
        } else if (choice == 1 && !defined_.empty()) {
            text_ += "USE " +
                     defined_[in_.ConsumeIntegralInRange<std::size_t>(0, defined_.size() - 1)] +
                     "\n";
        } else {
            const std::size_t before = text_.size();
            randomNode(depth + 1);
            if (text_.size() == before) text_ += "NULL\n";
        }
    }
};

} // namespace volsg::fuzz
