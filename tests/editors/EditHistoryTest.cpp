// Field values as text, and undo/redo of edits through the EditHistory.
#include <doctest/doctest.h>

#include <volsg/core/Error.h>
#include <volsg/editors/EditHistory.h>
#include <volsg/editors/FieldText.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>

using namespace volsg;

TEST_CASE("field values round-trip through their scene-file text") {
    auto tf = TransferFunction::create();
    tf->alpha = {glm::vec2(0.0f, 0.25f), glm::vec2(0.5f, 1.0f)};
    const std::string text = fieldValueText(tf->alpha);
    auto other = TransferFunction::create();
    setFieldFromText(other->alpha, text);
    CHECK(other->alpha.getValues() == tf->alpha.getValues());

    auto volume = Volume::create();
    setFieldFromText(volume->renderMode, "MIP");
    CHECK(volume->renderMode() == Volume::MIP);
    CHECK(fieldValueText(volume->renderMode) == "MIP");
    setFieldFromText(volume->numPlanes, "12");
    CHECK(volume->numPlanes() == 12);
}

TEST_CASE("bad field text is an error that leaves the field unchanged") {
    auto volume = Volume::create();
    CHECK_THROWS_AS(setFieldFromText(volume->numPlanes, "twelve"), Error);
    CHECK_THROWS_AS(setFieldFromText(volume->numPlanes, "1 2"), Error);
    CHECK(volume->numPlanes() == 0);
    CHECK(volume->numPlanes.isDefault());
    CHECK_THROWS_AS(setFieldFromText(volume->renderMode, "SHINY"), Error);
    CHECK(volume->renderMode() == Volume::DVR);
    CHECK(volume->renderMode.isDefault());
}

TEST_CASE("undo and redo restore values and whether a field was set") {
    EditHistory history;
    auto material = Material::create();
    history.begin("colour", {&material->diffuseColor});
    material->diffuseColor = {glm::vec3(1.0f, 0.0f, 0.0f)};
    history.commit();
    history.begin("transparency", {&material->transparency});
    material->transparency = {0.5f};
    history.commit();
    CHECK(history.size() == 2);
    CHECK(history.undoLabel() == "transparency");

    REQUIRE(history.undo());
    CHECK(material->transparency[0] == 0.0f);
    CHECK(material->transparency.isDefault()); // never set before: not written to a file again
    REQUIRE(history.undo());
    CHECK(material->diffuseColor[0] == glm::vec3(0.8f));
    CHECK_FALSE(history.undo());
    REQUIRE(history.redo());
    CHECK(material->diffuseColor[0] == glm::vec3(1.0f, 0.0f, 0.0f));
    CHECK_FALSE(material->diffuseColor.isDefault());

    // A new edit after an undo drops what could have been redone.
    history.begin("shininess", {&material->shininess});
    material->shininess = {0.9f};
    history.commit();
    CHECK_FALSE(history.canRedo());
    CHECK(history.size() == 2);
}

TEST_CASE("an edit that changes nothing is not recorded and cancel puts values back") {
    EditHistory history;
    auto material = Material::create();
    history.begin("nothing", {&material->shininess});
    history.commit();
    CHECK(history.size() == 0);
    history.begin("cancelled", {&material->shininess});
    material->shininess = {0.7f};
    history.cancel();
    CHECK(material->shininess[0] == doctest::Approx(0.2f));
    CHECK(history.size() == 0);
}
