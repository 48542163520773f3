// The patient axes of a volume from its file's geometry (PatientOrientation.h): LPS directions
// that permute and flip the index axes give the right letters, the inverse map, and sections
// that each slice along the local axis nearest their patient normal, seen the right way round.
#include <doctest/doctest.h>

#include <cmath>

#include <volsg/io/SceneReader.h>

#include "view/SectionViews.h"

using namespace volsg;

namespace {

// i to the feet, j to the patient's left, k to the front (LPS columns).
const glm::dmat3 kLps(glm::dvec3(0, 0, -1), glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0));

bool near(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::length(a - b) < 1e-9;
}

} // namespace

TEST_CASE("patient axes from LPS directions that permute and flip the index axes") {
    PatientAxes axes;
    axes.fromFile = PatientAxes::fromLpsDirections(kLps);
    // RAS of each local axis: i inferior, j left (RAS -x), k anterior (LPS -y is RAS +y).
    CHECK(near(axes.toRas({1, 0, 0}), {0, 0, -1}));
    CHECK(near(axes.toRas({0, 1, 0}), {-1, 0, 0}));
    CHECK(near(axes.toRas({0, 0, 1}), {0, 1, 0}));
    CHECK(axes.letter(0, true) == 'I');
    CHECK(axes.letter(1, true) == 'L');
    CHECK(axes.letter(2, true) == 'A');
    CHECK(axes.letter(2, false) == 'P');
    // toLocal inverts toRas.
    for (const glm::dvec3 ras : {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0.3, -2, 5)})
        CHECK(near(axes.toRas(axes.toLocal(ras)), ras));
    // Sagittal (normal R) slices along j, coronal (A) along k, axial (S) along i.
    CHECK(axes.localAxisOfRas() == glm::ivec3(1, 2, 0));
    // A reversal box flips that local axis on top of the file's map.
    axes.signs = {1, -1, 1};
    CHECK(axes.letter(1, true) == 'R');
    // An oblique acquisition (30 degrees about S): each RAS axis still finds its own local axis.
    const double c = std::cos(0.5236), s = std::sin(0.5236);
    PatientAxes oblique;
    oblique.fromFile = glm::dmat3(glm::dvec3(c, s, 0), glm::dvec3(-s, c, 0), glm::dvec3(0, 0, 1));
    CHECK(oblique.localAxisOfRas() == glm::ivec3(0, 1, 2));
    // A degenerate map (a broken file) gives finite directions, never NaN.
    PatientAxes broken;
    broken.fromFile = glm::dmat3(0.0);
    CHECK(std::isfinite(glm::length(broken.toLocal({1, 2, 3}))));
}

TEST_CASE("section views of a permuted volume slice along the right axes, head up") {
    // The scene as volsg-view builds it for such a file: the volume placed in LPS by a
    // MatrixTransform holding the directions.
    auto root = readSceneFromString(R"(#Inventor V2.1 ascii
Separator {
  MatrixTransform { matrix 0 0 -1 0  1 0 0 0  0 -1 0 0  0 0 0 1 }
  VolumeData { generator RAMP16 dimensions 24 20 16 }
  TransferFunction { dataRange 0 65535 }
}
)");
    SectionViews views;
    REQUIRE(views.attach(*root));
    PatientAxes axes;
    axes.fromFile = PatientAxes::fromLpsDirections(kLps);
    views.setPatientAxes(axes);
    CHECK(views.axisOf(SectionViews::Sagittal) == 1);
    CHECK(views.axisOf(SectionViews::Coronal) == 2);
    CHECK(views.axisOf(SectionViews::Axial) == 0);
    // World is LPS here. Each camera looks along its section's patient normal (radiological:
    // sagittal from the left, coronal from the front, axial from the feet) with the head (axial:
    // anterior) up.
    const glm::dvec3 lpsAnterior(0, -1, 0), lpsSuperior(0, 0, 1), lpsLeft(1, 0, 0);
    struct Expect {
        int section;
        glm::dvec3 forward, up;
    };
    for (const Expect& e : {Expect{SectionViews::Sagittal, -lpsLeft, lpsSuperior},
                            Expect{SectionViews::Coronal, -lpsAnterior, lpsSuperior},
                            Expect{SectionViews::Axial, lpsSuperior, lpsAnterior}}) {
        CAPTURE(e.section);
        const ref_ptr<Camera> camera = views.camera(e.section, 1.0);
        const glm::dquat turn = camera->orientation().quat();
        CHECK(glm::length(turn * glm::dvec3(0, 0, -1) - e.forward) < 1e-5);
        CHECK(glm::length(turn * glm::dvec3(0, 1, 0) - e.up) < 1e-5);
    }
    // The cursor's sagittal plane is its j: setting it moves the view's slice along j.
    views.setCursor({3, 7, 11});
    const glm::dvec3 world = views.worldOf({3, 7, 11});
    CHECK(views.voxelAtWorld(world) == glm::ivec3(3, 7, 11));
}
