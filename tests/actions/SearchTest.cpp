// SearchAction and its helpers: by type (derived or exact), by name, First/Last/All, Switch.
#include <doctest/doctest.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Switch.h>
#include <volsg/nodes/Transform.h>

using namespace volsg;

namespace {

/// root(Separator "root")
///   Transform "move"
///   Separator "left":  Material, Cube "box"
///   Switch "choice" (whichChild 0):  Sphere "ball", Cone "hidden"
///   Cube "box2"
struct Scene {
    ref_ptr<Separator> root = Separator::create();
    ref_ptr<Transform> move = Transform::create();
    ref_ptr<Separator> left = Separator::create();
    ref_ptr<Material> material = Material::create();
    ref_ptr<Cube> box = Cube::create();
    ref_ptr<Switch> choice = Switch::create();
    ref_ptr<Sphere> ball = Sphere::create();
    ref_ptr<Cone> hidden = Cone::create();
    ref_ptr<Cube> box2 = Cube::create();

    Scene() {
        root->setName("root");
        move->setName("move");
        left->setName("left");
        box->setName("box");
        choice->setName("choice");
        ball->setName("ball");
        hidden->setName("hidden");
        box2->setName("box2");
        root->addChild(move);
        left->addChild(material);
        left->addChild(box);
        root->addChild(left);
        choice->addChild(ball);
        choice->addChild(hidden);
        choice->whichChild = 0;
        root->addChild(choice);
        root->addChild(box2);
    }
};

std::vector<Node*> ends(const SearchAction& search) {
    std::vector<Node*> out;
    for (const auto& path : search.paths())
        out.push_back(path.back());
    return out;
}

} // namespace

TEST_CASE("search by type finds derived types unless exact is asked") {
    Scene s;
    SearchAction search;
    search.setType(&Shape::classType(), true);
    search.setInterest(SearchAction::Interest::All);
    search.apply(*s.root);
    CHECK(ends(search) == std::vector<Node*>{s.box.get(), s.ball.get(), s.box2.get()});

    search.setType(&Shape::classType(), false); // Shape itself is abstract: nothing is exactly one
    search.apply(*s.root);
    CHECK(search.paths().empty());

    search.setType(&Group::classType(), true); // Separator and Switch derive from Group
    search.apply(*s.root);
    CHECK(ends(search) == std::vector<Node*>{s.root.get(), s.left.get(), s.choice.get()});

    search.setType(&Separator::classType(), false);
    search.apply(*s.root);
    CHECK(ends(search) == std::vector<Node*>{s.root.get(), s.left.get()});
}

TEST_CASE("search paths run from the root to the found node") {
    Scene s;
    SearchAction search;
    search.setType(&Cube::classType());
    search.apply(*s.root);
    REQUIRE(search.paths().size() == 1);
    CHECK(search.paths()[0] == std::vector<Node*>{s.root.get(), s.left.get(), s.box.get()});
}

TEST_CASE("search interest first last and all") {
    Scene s;
    SearchAction search;
    search.setType(&Cube::classType());

    search.setInterest(SearchAction::Interest::First);
    search.apply(*s.root);
    CHECK(ends(search) == std::vector<Node*>{s.box.get()});
    CHECK(search.isTerminated());

    search.setInterest(SearchAction::Interest::Last);
    search.apply(*s.root);
    REQUIRE(search.paths().size() == 1);
    CHECK(search.paths()[0] == std::vector<Node*>{s.root.get(), s.box2.get()});

    search.setInterest(SearchAction::Interest::All);
    search.apply(*s.root);
    CHECK(ends(search) == std::vector<Node*>{s.box.get(), s.box2.get()});
}

TEST_CASE("search by name and by name and type together") {
    Scene s;
    SearchAction search;
    search.setName("ball");
    search.apply(*s.root);
    CHECK(ends(search) == std::vector<Node*>{s.ball.get()});

    search.setName("box2");
    search.setType(&Sphere::classType());
    search.apply(*s.root);
    CHECK(search.paths().empty()); // named box2 but not a Sphere

    search.setType(&Cube::classType());
    search.apply(*s.root);
    CHECK(ends(search) == std::vector<Node*>{s.box2.get()});

    search.setName("nobody");
    search.setType(nullptr);
    search.apply(*s.root);
    CHECK(search.paths().empty());
}

TEST_CASE("search without criteria matches every node in traversal order") {
    Scene s;
    SearchAction search;
    search.setInterest(SearchAction::Interest::All);
    search.apply(*s.root);
    CHECK(ends(search) == std::vector<Node*>{s.root.get(), s.move.get(), s.left.get(),
                                             s.material.get(), s.box.get(), s.choice.get(),
                                             s.ball.get(), s.box2.get()});
}

TEST_CASE("search under a switch sees only the selected child unless searching all") {
    Scene s;
    SearchAction search;
    search.setType(&Cone::classType());
    search.apply(*s.root);
    CHECK(search.paths().empty());

    search.setSearchingAll(true);
    search.apply(*s.root);
    REQUIRE(search.paths().size() == 1);
    CHECK(search.paths()[0] == std::vector<Node*>{s.root.get(), s.choice.get(), s.hidden.get()});

    search.setSearchingAll(false);
    s.choice->whichChild = 1;
    search.apply(*s.root);
    CHECK(ends(search) == std::vector<Node*>{s.hidden.get()});
    s.choice->whichChild = Switch::SWITCH_NONE;
    search.setType(&Sphere::classType());
    search.apply(*s.root);
    CHECK(search.paths().empty());
}

TEST_CASE("a node USEd twice gives two paths but findAll lists it once") {
    Scene s;
    auto second = Separator::create();
    second->addChild(s.box); // the same Cube under another parent
    s.root->addChild(second);

    SearchAction search;
    search.setName("box");
    search.setInterest(SearchAction::Interest::All);
    search.apply(*s.root);
    REQUIRE(search.paths().size() == 2);
    CHECK(search.paths()[0] == std::vector<Node*>{s.root.get(), s.left.get(), s.box.get()});
    CHECK(search.paths()[1] == std::vector<Node*>{s.root.get(), second.get(), s.box.get()});

    CHECK(findAll(*s.root, Cube::classType()) == std::vector<Node*>{s.box.get(), s.box2.get()});
}

TEST_CASE("findAll and findByName conveniences") {
    Scene s;
    CHECK(findAll(*s.root, Shape::classType()) ==
          std::vector<Node*>{s.box.get(), s.ball.get(), s.box2.get()});
    CHECK(findAll(*s.root, Shape::classType(), true) ==
          std::vector<Node*>{s.box.get(), s.ball.get(), s.hidden.get(), s.box2.get()});
    CHECK(findAll(*s.root, Camera::classType()).empty());

    CHECK(findByName(*s.root, "move") == s.move.get());
    CHECK(findByName(*s.root, "root") == s.root.get());
    CHECK(findByName(*s.root, "hidden") == s.hidden.get()); // names ignore Switch selection
    CHECK(findByName(*s.root, "missing") == nullptr);
    CHECK(findByName(*s.root, "") == nullptr);
}
