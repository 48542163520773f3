// libFuzzer target: structure-aware scenes, rendered. The input's first byte picks the renderer
// path (VOLSG_FUZZ_PATH=volume|shearwarp|slices|gltf|reference fixes it), the rest drives
// SceneGenerator: a valid scene of registered node types with extreme field values and DEF/USE
// graphs, read back by readSceneFromString, given its non-finite values through the field API,
// and drawn at 48x48 by the GL Renderer or the CPU reference (renderReference), on one OSMesa
// context made at start. A volsg::Error is the documented outcome for a scene that cannot be
// drawn; a crash, another exception, a sanitizer report, a hang or an out-of-memory is a finding.
//
// VOLSG_FUZZ_PRINT=1 prints each generated scene and its outcome (to make seeds and debug).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/engines/Evaluator.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/render/Renderer.h>
#include <volsg/volumescene/ReferenceScene.h>

#include "FuzzScratch.h"
#include "SceneGenerator.h"

namespace {

using namespace volsg;
using fuzz::RenderPath;

struct FuzzWorld {
    std::unique_ptr<OSMesaContext> context;
    std::unique_ptr<Renderer> renderer;
    fuzz::SceneTypes types;
    std::optional<RenderPath> fixedPath;
    std::string sceneFile; ///< the scene's name: relative file names resolve beside it
    bool print = false;
};

/// Never destroyed: OSMesaDestroyContext from a static destructor deadlocks in llvmpipe, whose
/// threads Mesa's own exit handlers have already stopped (libFuzzer then hung after its run).
FuzzWorld& world() {
    static FuzzWorld* w = new FuzzWorld;
    return *w;
}

/// The files the generator's kSceneFileMenu names, in the scratch folder.
void writeSceneFiles(const fuzz::FuzzScratch& scratch) {
    std::string nrrd = "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 4 4\nencoding: raw\n\n";
    for (int i = 0; i < 64; ++i)
        nrrd += char(i * 4);
    scratch.write("tiny.nrrd", nrrd);
    // One textured triangle, its buffer inline.
    scratch.write(
        "tiny.gltf",
        R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "translation": [1, 0, 0], "children": [1]}, {"mesh": 0, "scale": [2, 2, 2]}], "buffers": [{"byteLength": 68, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAgD8="}], "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}, {"buffer": 0, "byteOffset": 44, "byteLength": 24}], "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}, {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}, {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "indices": 1, "material": 0}]}], "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 1]}, "alphaMode": "MASK", "doubleSided": true}]})");
    scratch.write("tiny.iv", "#Inventor V2.1 ascii\nSeparator { Cube { } }\n");
    scratch.write("loop.iv", "#Inventor V2.1 ascii\nSeparator { File { name \"loop.iv\" } }\n");
    writePng(scratch.write("tiny.png", ""), Image(2, 2, glm::vec4(0.5f, 0.25f, 1.0f, 1.0f)));
}

/// Component `c` of a value of a float-based field type.
void setComponent(float& v, std::size_t, float x) {
    v = x;
}
template <int N> void setComponent(glm::vec<N, float>& v, std::size_t c, float x) {
    v[int(c % N)] = x;
}
void setComponent(glm::mat4& m, std::size_t c, float x) {
    m[int(c % 16 / 4)][int(c % 4)] = x;
}
void setComponent(Rotation& r, std::size_t c, float x) {
    if (c % 4 == 3)
        r.angle = x;
    else
        r.axis[int(c % 4)] = x;
}
void setComponent(Plane& p, std::size_t c, float x) {
    if (c % 4 == 3)
        p.distance = x;
    else
        p.normal[int(c % 4)] = x;
}

template <class Traits, int Components> bool poke(Field& f, std::size_t c, float x) {
    if (auto* s = dynamic_cast<SField<Traits>*>(&f)) {
        auto v = s->getValue();
        setComponent(v, c, x);
        s->setValue(v);
        return true;
    }
    if (auto* m = dynamic_cast<MField<Traits>*>(&f)) {
        const std::size_t i = c / Components;
        if (i >= m->size()) return true;
        auto v = (*m)[i];
        setComponent(v, c % Components, x);
        m->set1Value(i, v);
        return true;
    }
    return false;
}

/// Sets a non-finite value through the field, as code may (the reader refuses them in text).
void applyPoke(Field& f, std::size_t c, float x) {
    (void)(poke<FloatTraits, 1>(f, c, x) || poke<Vec2fTraits, 2>(f, c, x) ||
           poke<Vec3fTraits, 3>(f, c, x) || poke<ColorTraits, 3>(f, c, x) ||
           poke<Vec4fTraits, 4>(f, c, x) || poke<RotationTraits, 4>(f, c, x) ||
           poke<PlaneTraits, 4>(f, c, x) || poke<MatrixTraits, 16>(f, c, x));
}

/// Every node reachable from `node` (children and node-valued fields), each once.
void collectNodes(Node& node, std::unordered_set<Node*>& seen) {
    if (!seen.insert(&node).second) return;
    if (const auto* children = node.children())
        for (const ref_ptr<Node>& child : *children)
            if (child) collectNodes(*child, seen);
    for (std::size_t i = 0; i < node.fieldCount(); ++i) {
        Field* f = node.fieldAt(i);
        if (auto* sf = dynamic_cast<SFNode*>(f)) {
            if (sf->getValue()) collectNodes(*sf->getValue(), seen);
        } else if (auto* mf = dynamic_cast<MFNode*>(f)) {
            for (const ref_ptr<Node>& n : mf->getValues())
                if (n) collectNodes(*n, seen);
        }
    }
}

void applyPokes(Node& root, const std::vector<fuzz::Poke>& pokes) {
    if (pokes.empty()) return;
    std::unordered_set<Node*> nodes;
    collectNodes(root, nodes);
    for (Node* n : nodes)
        for (const fuzz::Poke& p : pokes)
            if (n->getName() == p.node)
                if (Field* f = n->field(p.field)) applyPoke(*f, p.component, p.value);
}

void render(Node& root, RenderPath path) {
    RenderOptions options;
    options.width = options.height = 48;
    if (path == RenderPath::Reference) {
        RayCastOptions rays;
        rays.tolerance = 1e-2;
        (void)renderReference(root, options, nullptr, rays);
    } else {
        (void)world().renderer->render(root, options);
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    FuzzWorld& w = world();
    w.types = fuzz::SceneTypes::fromRegistry();
    if (const char* p = std::getenv("VOLSG_FUZZ_PATH")) {
        for (int i = 0; i < fuzz::kRenderPathCount; ++i)
            if (std::strcmp(p, fuzz::kRenderPathNames[i]) == 0) w.fixedPath = RenderPath(i);
        if (!w.fixedPath) {
            std::fprintf(stderr,
                         "VOLSG_FUZZ_PATH must be volume, shearwarp, slices, gltf or "
                         "reference, not '%s'\n",
                         p);
            std::exit(2);
        }
    }
    w.print = std::getenv("VOLSG_FUZZ_PRINT") != nullptr;
    const fuzz::FuzzScratch& scratch = fuzz::FuzzScratch::instance();
    writeSceneFiles(scratch);
    w.sceneFile = scratch.write("scene.iv", "");
    w.context = std::make_unique<OSMesaContext>();
    w.renderer = std::make_unique<Renderer>();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    FuzzWorld& w = world();
    const RenderPath path =
        w.fixedPath ? *w.fixedPath : RenderPath(data[0] % fuzz::kRenderPathCount);
    FuzzedDataProvider in(data + 1, size - 1);
    fuzz::SceneGenerator generator(in, path, w.types);
    const std::string text = generator.generate();
    if (w.print) {
        std::fprintf(stderr, "---- %s scene\n%s", fuzz::kRenderPathNames[int(path)], text.c_str());
        for (const fuzz::Poke& p : generator.pokes())
            std::fprintf(stderr, "---- poke %s.%s[%zu] = %g\n", p.node.c_str(), p.field.c_str(),
                         p.component, double(p.value));
    }
    try {
        const ref_ptr<Node> root = readSceneFromString(text, w.sceneFile);
        applyPokes(*root, generator.pokes());
        evaluateConnections(*root, 0.0);
        render(*root, path);
        if (w.print) std::fprintf(stderr, "---- drawn\n");
    } catch (const Error& e) {
        // The documented outcome for a scene that cannot be drawn.
        if (w.print) std::fprintf(stderr, "---- refused: %s\n", e.what());
    }
    return 0;
}
