// The writer's format, DEF/USE sharing, and read -> write -> read round trips of random graphs
// and of the example scenes.
#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <volsg/core/Error.h>
#include <volsg/engines/Engine.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/io/Tokenizer.h>
#include <volsg/io/UnknownNode.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Transform.h>

#include "io/TestNodes.h"

using namespace volsg;

namespace {

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Writes, reads back and checks the graph is equal and the second write is identical.
ref_ptr<Node> roundTrip(const Node& original) {
    const std::string first = writeSceneToString(original);
    ref_ptr<Node> back = readSceneFromString(first, "first.iv");
    std::string why;
    CHECK_MESSAGE(graphsEqual(original, *back, &why), why, "\n", first);
    CHECK(writeSceneToString(*back) == first);
    return back;
}

// ---- random graphs -------------------------------------------------------------------------

/// Builds random graphs from every registered node type: random field values of each field's
/// type, random names (with clashes), random sharing through children and node fields.
class RandomGraphs {
public:
    explicit RandomGraphs(unsigned seed) : rng_(seed) {
        // Engines are not nodes of a graph: they are only the sources of connections.
        for (const NodeType* t : NodeRegistry::instance().all())
            if (!t->isAbstract() && !t->isDerivedFrom(Engine::classType())) types_.push_back(t);
        std::sort(types_.begin(), types_.end(), [](const NodeType* a, const NodeType* b) {
            return std::string_view(a->name()) < b->name();
        });
    }

    ref_ptr<Node> make() {
        finished_.clear();
        ref_ptr<Node> root = makeNode(0, true);
        return root;
    }

private:
    static constexpr int maxDepth = 5;

    ref_ptr<Node> makeNode(int depth, bool wantGroup = false) {
        ref_ptr<Node> node;
        if (!wantGroup && chance(0.08)) {
            node = makeUnknown();
        } else {
            for (int tries = 0; tries < 20; ++tries) {
                node = types_[pick(types_.size())]->create();
                if (!wantGroup || node->children()) break;
            }
        }
        if (chance(0.25)) node->setName(names_[pick(std::size(names_))]);
        for (std::size_t i = 0, n = node->fieldCount(); i < n; ++i)
            if (chance(0.5)) setRandom(*node->fieldAt(i), depth);
        if (auto* children = node->children(); children && depth < maxDepth) {
            const std::size_t count = pick(depth == 0 ? 8 : 5);
            for (std::size_t i = 0; i < count; ++i)
                children->push_back(childNode(depth + 1));
        }
        finished_.push_back(node);
        return node;
    }

    // A new node, or (sometimes) one already complete: shared, and never an ancestor.
    ref_ptr<Node> childNode(int depth) {
        if (!finished_.empty() && chance(0.3)) return finished_[pick(finished_.size())];
        return makeNode(depth, depth < maxDepth - 1 && chance(0.45));
    }

    ref_ptr<Node> makeUnknown() {
        static const char* fieldTypes[] = {"SFFloat", "MFVec3f", "SFEnum", "SFBitMask", "SFString",
                                           "MFInt32", "SFNode",  "SFName", "SFDouble",  "MFColor"};
        auto u = UnknownNode::create("Ext" + std::to_string(pick(3)));
        const std::size_t count = pick(4);
        for (std::size_t i = 0; i < count; ++i)
            u->addField(fieldTypes[pick(std::size(fieldTypes))], "f" + std::to_string(i));
        return u;
    }

    void setRandom(Field& f, int depth) {
        if (auto* e = dynamic_cast<SFEnum*>(&f)) {
            const auto& entries = e->names().entries;
            if (!entries.empty()) e->setValue(entries[pick(entries.size())].second);
        } else if (auto* b = dynamic_cast<SFBitMask*>(&f)) {
            int v = 0;
            for (const auto& entry : b->names().entries)
                if (chance(0.4)) v |= entry.second;
            b->setValue(v);
        } else if (auto* sn = dynamic_cast<SFNode*>(&f)) {
            sn->setValue(chance(0.2) || depth >= maxDepth ? nullptr : childNode(depth + 1));
        } else if (auto* mn = dynamic_cast<MFNode*>(&f)) {
            std::vector<ref_ptr<Node>> v;
            if (depth < maxDepth)
                for (std::size_t i = 0, n = pick(3); i < n; ++i)
                    v.push_back(childNode(depth + 1));
            mn->setValues(std::move(v));
        } else if (!(trySet<FloatTraits>(f) || trySet<Int32Traits>(f) || trySet<UInt32Traits>(f) ||
                     trySet<BoolTraits>(f) || trySet<StringTraits>(f) || trySet<Vec2fTraits>(f) ||
                     trySet<Vec3fTraits>(f) || trySet<Vec4fTraits>(f) || trySet<ColorTraits>(f) ||
                     trySet<RotationTraits>(f) || trySet<PlaneTraits>(f) ||
                     trySet<MatrixTraits>(f))) {
            setByText(f); // fields of unknown nodes and any other type: set through their text
        }
    }

    template <class Traits> bool trySet(Field& f) {
        if (auto* s = dynamic_cast<SField<Traits>*>(&f)) {
            s->setValue(value<typename Traits::Value>());
            return true;
        }
        if (auto* m = dynamic_cast<MField<Traits>*>(&f)) {
            std::vector<typename Traits::Value> v(pick(chance(0.1) ? 40 : 4));
            for (std::size_t i = 0; i < v.size(); ++i) // (not auto&: std::vector<bool>)
                v[i] = value<typename Traits::Value>();
            m->setValues(std::move(v));
            return true;
        }
        return false;
    }

    // Values for the fields of unknown nodes (and any type this test does not know), by text.
    void setByText(Field& f) {
        const std::string type = f.typeName();
        std::string text;
        if (type == "SFFloat" || type == "SFDouble")
            text = "2.5e-3";
        else if (type == "MFVec3f")
            text = "[ 1 2 3, 4 5 6 ]";
        else if (type == "SFEnum")
            text = "SOME_MODE";
        else if (type == "SFBitMask")
            text = "(X | Y)";
        else if (type == "SFString")
            text = "\"text \\\" here\"";
        else if (type == "MFInt32")
            text = "[ 1, -2, 0x30 ]";
        else if (type == "SFName")
            text = "aName";
        else if (type == "MFColor")
            text = "[ 0.5 0.25 1 ]";
        else
            return; // SFNode of an unknown node: left default
        struct Input final : FieldInput {
            Tokenizer t;
            explicit Input(const std::string& s) : t(s, "value") {}
            Tokenizer& tokens() override { return t; }
            ref_ptr<Node> readNode() override { return nullptr; }
        } in(text);
        f.read(in);
    }

    template <class V> V value() {
        if constexpr (std::is_same_v<V, float>) {
            if (chance(0.5)) return float(int(pick(2001)) - 1000) / 8.0f;
            while (true) { // any finite float, to test the shortest-text printing
                const float f = std::bit_cast<float>(std::uint32_t(rng_()));
                if (std::isfinite(f)) return f;
            }
        } else if constexpr (std::is_same_v<V, std::int32_t>) {
            return std::int32_t(rng_());
        } else if constexpr (std::is_same_v<V, std::uint32_t>) {
            return std::uint32_t(rng_());
        } else if constexpr (std::is_same_v<V, bool>) {
            return chance(0.5);
        } else if constexpr (std::is_same_v<V, std::string>) {
            static const char alphabet[] = "ab Z09_\"\\#{}[](),|\n\t\xC3\xA9";
            std::string s(pick(12), ' ');
            for (char& c : s)
                c = alphabet[pick(sizeof(alphabet) - 1)];
            return s;
        } else if constexpr (std::is_same_v<V, Rotation>) {
            return Rotation{value<glm::vec3>(), value<float>()};
        } else if constexpr (std::is_same_v<V, Plane>) {
            return Plane{value<glm::vec3>(), value<float>()};
        } else if constexpr (std::is_same_v<V, glm::mat4>) {
            glm::mat4 m;
            for (int i = 0; i < 16; ++i)
                m[i / 4][i % 4] = value<float>();
            return m;
        } else {
            V v;
            for (int i = 0; i < V::length(); ++i)
                v[i] = value<float>();
            return v;
        }
    }

    bool chance(double p) { return std::uniform_real_distribution<double>(0, 1)(rng_) < p; }
    std::size_t pick(std::size_t n) { return n ? std::size_t(rng_() % n) : 0; }

    std::mt19937 rng_;
    std::vector<const NodeType*> types_;
    std::vector<ref_ptr<Node>> finished_;
    const char* names_[5] = {"a", "b", "cam", "a", "x_1"}; // "a" twice: clashes are common
};

} // namespace

TEST_CASE("the writer puts the header first, two spaces per level and only set fields") {
    auto root = Separator::create();
    auto xf = Transform::create();
    xf->translation = glm::vec3(1, 2, 3);
    auto cube = Cube::create();
    cube->width = 3.0f;
    root->addChild(xf);
    root->addChild(cube);
    CHECK(writeSceneToString(*root) == "#Inventor V2.1 ascii\n"
                                       "\n"
                                       "Separator {\n"
                                       "  Transform {\n"
                                       "    translation 1 2 3\n"
                                       "  }\n"
                                       "  Cube {\n"
                                       "    width 3\n"
                                       "  }\n"
                                       "}\n");
}

TEST_CASE("a node reached twice is written DEF then USE and read back shared") {
    auto root = Separator::create();
    auto shared = Cube::create();
    root->addChild(shared);
    root->addChild(Sphere::create());
    root->addChild(shared);
    const std::string text = writeSceneToString(*root);
    CHECK(contains(text, "  DEF +0 Cube {\n"));
    CHECK(contains(text, "  USE +0\n"));
    auto back = roundTrip(*root);
    CHECK(back->children()->at(0) == back->children()->at(2));
    CHECK(back->children()->at(0)->getName().empty());
}

TEST_CASE("named nodes keep their names, used once or shared") {
    auto root = Separator::create();
    auto cam = Cube::create();
    cam->setName("cam");
    auto once = Sphere::create();
    once->setName("ball");
    root->addChild(cam);
    root->addChild(once);
    root->addChild(cam);
    const std::string text = writeSceneToString(*root);
    CHECK(contains(text, "DEF cam Cube {"));
    CHECK(contains(text, "DEF ball Sphere {"));
    CHECK(contains(text, "USE cam"));
    roundTrip(*root);
}

TEST_CASE("a name that would hide a node still to be USEd gets a suffix") {
    auto root = Separator::create();
    auto first = Cube::create();
    auto second = Sphere::create();
    first->setName("a");
    second->setName("a");
    root->addChild(first);
    root->addChild(second); // DEF a here would make the USE below mean the sphere
    root->addChild(first);
    root->addChild(second);
    const std::string text = writeSceneToString(*root);
    CHECK(contains(text, "DEF a Cube"));
    CHECK(contains(text, "DEF a+0 Sphere"));
    auto back = roundTrip(*root);
    CHECK(back->children()->at(1)->getName() == "a");
    CHECK(back->children()->at(3) == back->children()->at(1));
}

TEST_CASE("a node inside a same-named node and used after it ends gets a suffix") {
    // Our reader binds a DEF name where its node ends, so the Group's name would take over
    // before the USE of the cube.
    auto root = Separator::create();
    auto group = Group::create();
    auto cube = Cube::create();
    group->setName("a");
    cube->setName("a");
    group->addChild(cube);
    root->addChild(group);
    root->addChild(cube);
    const std::string text = writeSceneToString(*root);
    CHECK(contains(text, "DEF a Group"));
    CHECK(contains(text, "DEF a+0 Cube"));
    auto back = roundTrip(*root);
    CHECK(back->children()->at(1) == back->children()->at(0)->children()->at(0));
}

TEST_CASE("a name whose earlier node is no longer used is written again without a suffix") {
    auto root = Separator::create();
    auto first = Cube::create();
    auto second = Sphere::create();
    first->setName("a");
    second->setName("a");
    root->addChild(first);
    root->addChild(first);
    root->addChild(second);
    root->addChild(second);
    const std::string text = writeSceneToString(*root);
    CHECK(contains(text, "DEF a Cube"));
    CHECK(contains(text, "DEF a Sphere"));
    CHECK_FALSE(contains(text, "+"));
    roundTrip(*root);
}

TEST_CASE("names are written in a form a file can hold") {
    auto root = Separator::create();
    const char* names[] = {"my node", "3d", "USE", "a+b"};
    for (const char* name : names) {
        auto c = Cube::create();
        c->setName(name);
        root->addChild(c);
    }
    auto back = readSceneFromString(writeSceneToString(*root));
    CHECK(back->children()->at(0)->getName() == "my_node");
    CHECK(back->children()->at(1)->getName() == "_3d");
    CHECK(back->children()->at(2)->getName() == "USE_");
    CHECK(back->children()->at(3)->getName() == "a_b");
}

TEST_CASE("our own node types are written with their fields description") {
    test::registerTestNodeTypes();
    auto group = test::TestGroup::create();
    group->weight = 0.5f;
    group->addChild(Cube::create());
    CHECK(writeSceneToString(*group) == "#Inventor V2.1 ascii\n"
                                        "\n"
                                        "TestGroup {\n"
                                        "  fields [ SFFloat weight ]\n"
                                        "  weight 0.5\n"
                                        "  Cube {\n"
                                        "  }\n"
                                        "}\n");
    roundTrip(*group);
}

TEST_CASE("a self-described unknown node is written back unchanged") {
    const std::string text = "#Inventor V2.1 ascii\n"
                             "\n"
                             "Separator {\n"
                             "  DEF ext Foo {\n"
                             "    fields [ SFFloat a, MFVec3f b, SFEnum mode, SFBitMask parts, "
                             "SFNode n, SFString s ]\n"
                             "    a 1.5\n"
                             "    b [ 0 0 0, 1 2 3 ]\n"
                             "    mode FANCY\n"
                             "    parts (LEFT | RIGHT)\n"
                             "    n Cube {\n"
                             "      width 2\n"
                             "    }\n"
                             "    Sphere {\n"
                             "    }\n"
                             "  }\n"
                             "  USE ext\n"
                             "}\n";
    auto root = readSceneFromString(text);
    CHECK(writeSceneToString(*root) == text);
}

TEST_CASE("node field values are written where they read back") {
    test::registerTestNodeTypes();
    auto n = test::AllFieldsNode::create();
    auto shared = Cube::create();
    n->sfNode.setValue(shared);
    n->mfNode.setValues({shared, nullptr, Sphere::create()});
    const std::string text = writeSceneToString(*n);
    CHECK(contains(text, "  sfNode DEF +0 Cube {\n  }\n"));
    CHECK(contains(text, "  mfNode [\n    USE +0\n    NULL\n    Sphere {\n    } ]\n"));
    auto back = roundTrip(*n);
    auto* b = dynamic_cast<test::AllFieldsNode*>(back.get());
    REQUIRE(b);
    CHECK(b->mfNode.getValues()[0].get() == b->sfNode.getValue());
}

TEST_CASE("a value that cannot be written is an error naming the field") {
    auto cube = Cube::create();
    cube->width = std::nanf("");
    CHECK_THROWS_WITH_AS(writeSceneToString(*cube),
                         doctest::Contains("cannot write field 'width' of Cube"), Error);
}

TEST_CASE("writeSceneToFile replaces the file, and a failed write leaves the old one") {
    const auto dir = std::filesystem::temp_directory_path() / "volsg-io-writer";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto path = (dir / "scene.iv").string();

    auto good = Cube::create();
    good->width = 4.0f;
    writeSceneToFile(path, *good);
    const std::string before = slurp(path);
    CHECK(contains(before, "width 4"));

    auto bad = Cube::create();
    bad->width = INFINITY;
    CHECK_THROWS_AS(writeSceneToFile(path, *bad), Error);
    CHECK(slurp(path) == before);
    CHECK_FALSE(std::filesystem::exists(path + ".tmp"));

    CHECK_THROWS_AS(writeSceneToFile((dir / "no/such/folder/x.iv").string(), *good), Error);
    std::filesystem::remove_all(dir);
}

TEST_CASE("graphsEqual tells differing values, names and sharing apart") {
    auto a = Separator::create();
    auto b = Separator::create();
    auto c1 = Cube::create();
    auto c2 = Cube::create();
    a->addChild(c1);
    a->addChild(c1);
    b->addChild(c2);
    b->addChild(Cube::create());
    std::string why;
    CHECK_FALSE(graphsEqual(*a, *b, &why));
    CHECK(contains(why, "sharing differs"));
    b->removeChild(1);
    b->addChild(c2);
    CHECK(graphsEqual(*a, *b));
    c2->width = 5.0f;
    CHECK_FALSE(graphsEqual(*a, *b, &why));
    CHECK(contains(why, "width"));
    c1->width = 5.0f;
    c1->setName("n");
    CHECK_FALSE(graphsEqual(*a, *b, &why));
    CHECK(contains(why, "name"));
}

TEST_CASE("200 random graphs round-trip to equal graphs") {
    test::registerTestNodeTypes();
    RandomGraphs graphs(7);
    std::size_t nodes = 0, uses = 0, suffixed = 0;
    for (int i = 0; i < 200; ++i) {
        ref_ptr<Node> graph = graphs.make();
        const std::string first = writeSceneToString(*graph);
        nodes += std::size_t(std::count(first.begin(), first.end(), '{'));
        for (std::size_t at = first.find("USE "); at != std::string::npos;
             at = first.find("USE ", at + 1))
            ++uses;
        for (std::size_t at = first.find("DEF a+"); at != std::string::npos;
             at = first.find("DEF a+", at + 1))
            ++suffixed;
        ref_ptr<Node> back = readSceneFromString(first, "random.iv");
        std::string why;
        if (!graphsEqual(*graph, *back, &why)) FAIL("graph " << i << ": " << why << "\n" << first);
        if (writeSceneToString(*back) != first) FAIL("graph " << i << " wrote differently");
    }
    MESSAGE("round-tripped 200 random graphs: " << nodes << " written nodes, " << uses << " USEs, "
                                                << suffixed
                                                << " clashing names written with a suffix");
    // Graphs shrink as leaf types join the registry (groups are picked less often): 1358 nodes
    // with the text and NURBS types.
    CHECK(nodes > 1000);
    CHECK(uses > 100);
    CHECK(suffixed > 0);
}

TEST_CASE("every example scene round-trips to an equal graph") {
    const std::filesystem::path examples = std::filesystem::path(VOLSG_SOURCE_DIR) / "examples";
    std::vector<std::filesystem::path> files;
    if (std::filesystem::exists(examples))
        for (const auto& entry : std::filesystem::recursive_directory_iterator(examples))
            if (entry.is_regular_file() && entry.path().extension() == ".iv")
                files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) MESSAGE("no .iv files in " << examples.string() << ": nothing to check");
    for (const auto& file : files) {
        INFO(file.string());
        ref_ptr<Node> root = readScene(file.string());
        roundTrip(*root);
    }
    MESSAGE("checked " << files.size() << " example scenes");
}
