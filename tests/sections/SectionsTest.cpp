// Planar sections (OrthoSlice, ObliqueSlice) against the double-precision sampling and
// classification of the same world point, their compositing with volumes and clipping, picking
// on them, and the Inventor nodes LightModel and ResetTransform.
#include "slicing/SlicingTestSupport.h"

#include <limits>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/io/GraphCompare.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/LightModel.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/ObliqueSlice.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/nodes/ResetTransform.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Transform.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/sections/SliceSampler.h>
#include <volsg/state/State.h>
#include <volsg/volumescene/ReferenceScene.h>
#include <volsg/volumescene/VolumeInScope.h>

using namespace volsg;
using namespace volsg::test;

namespace {

/// The transfer table's resolution in v (TransferTable::kEntries samples over [0, 1]).
constexpr double kTableStep = 1.0 / 4095.0;
const glm::vec3 kBackground(0.1f, 0.2f, 0.3f);

/// VolumeData (a generator) and one TransferFunction in a Separator; slices are added after.
struct SliceScene {
    ref_ptr<Separator> root = Separator::create();
    ref_ptr<VolumeData> data = VolumeData::create();
    ref_ptr<TransferFunction> transfer = TransferFunction::create();

    SliceScene(VolumeData::Generator generator, glm::vec3 dimensions,
               const TransferFunction1D& function) {
        data->generator = generator;
        data->dimensions = dimensions;
        setNodeFields(*transfer, function);
        root->addChild(data);
        root->addChild(transfer);
    }
    /// The slice's volume as the node sees it (state at the end of the root's children).
    VolumeInScope volume() const {
        State state;
        for (const auto& child : *root->children())
            if (child->isA<Transform>())
                state.multModelMatrix(static_cast<const Transform&>(*child).matrix());
            else if (child->isA<VolumeData>() || child->isA<TransferFunction>())
                state.add(*child);
        auto v = gatherVolumeInScope(state);
        REQUIRE(v);
        return *v;
    }
};

Image render(Renderer& renderer, Node& root, Camera& camera, int size) {
    RenderOptions options;
    options.width = options.height = size;
    options.camera = ref_ptr<Camera>(&camera);
    options.background = kBackground;
    return renderer.render(root, options);
}

struct PixelComparison {
    int compared = 0;          ///< pixels whose ray meets the slice well inside its polygon
    int drawnBoth = 0;         ///< of these, drawn by GL and by the expectation
    int discardMismatches = 0; ///< drawn by one of them only
    double maxError = 0.0;     ///< largest RGB difference where both draw
    int worstX = -1, worstY = -1;
};

/// Every pixel whose ray (through its centre, as the reference casts it) meets the slice plane
/// inside the volume box, compared with SliceSampler at that local point: the slice's colour
/// (alpha 1 uses), blended over the background (ALPHA_AS_IS), or the background (discarded).
/// Pixels within `margin` of the polygon's rim, and with `skipCellFaces` those within 1e-3
/// voxels of a cell face (where NEAREST and tags switch voxel), are left out.
PixelComparison compareSlice(const Image& gl, const Camera& camera, const VolumeInScope& volume,
                             const SlicePlane& plane, const SliceStyle& style,
                             bool skipCellFaces = false, double margin = 0.01) {
    const RayCastCamera rays = rayCamera(camera, gl.width, gl.height);
    const glm::dmat4 toLocal = glm::inverse(volume.model);
    const SliceSampler sampler(volume, style);
    const glm::dvec3 half = volume.halfExtent();
    PixelComparison c;
    for (int y = 0; y < gl.height; ++y)
        for (int x = 0; x < gl.width; ++x) {
            const Ray local = ReferenceRayCaster::pixelRay(rays, x, y).transformed(toLocal);
            const auto t = plane.intersect(local, half * (1.0 - margin));
            if (!t) continue;
            const glm::dvec3 p = local.at(*t);
            if (skipCellFaces) {
                const glm::dvec3 u = (p + half) / volume.data->spacing();
                bool nearFace = false;
                for (int a = 0; a < 3; ++a)
                    nearFace |= std::abs(u[a] - std::round(u[a])) < 1e-3;
                if (nearFace) continue;
            }
            ++c.compared;
            const SliceSample s = sampler.sample(p);
            const glm::dvec3 pixel(gl.at(x, y));
            const bool glDrawn = glm::length(pixel - glm::dvec3(kBackground)) > 1e-6;
            if (s.discarded() || !glDrawn) {
                if (s.discarded() != !glDrawn) ++c.discardMismatches;
                continue;
            }
            ++c.drawnBoth;
            const glm::dvec3 expected =
                glm::dvec3(s.rgba) * s.rgba.a + glm::dvec3(kBackground) * (1.0 - s.rgba.a);
            const glm::dvec3 e = glm::abs(pixel - expected);
            const double err = std::max({e.x, e.y, e.z});
            if (err > c.maxError) {
                c.maxError = err;
                c.worstX = x;
                c.worstY = y;
            }
        }
    return c;
}

/// Renders `root` at 64 x 64 and compares its slice pixels (compareSlice), reporting the
/// comparison as a MESSAGE; the image is kept as `name` (keepImage).
PixelComparison renderAndCompare(Renderer& renderer, Node& root, Camera& camera,
                                 const VolumeInScope& volume, const SlicePlane& plane,
                                 const SliceStyle& style, const std::string& name,
                                 bool skipCellFaces = false) {
    const Image gl = render(renderer, root, camera, 64);
    keepImage(gl, name);
    const PixelComparison c = compareSlice(gl, camera, volume, plane, style, skipCellFaces);
    MESSAGE(name << ": compared " << c.compared << ", drawn " << c.drawnBoth << ", mismatched "
                 << c.discardMismatches << ", max " << c.maxError * 255 << "/255 ("
                 << c.maxError * 4095 << " table steps)");
    return c;
}

TransferFunction1D colourful(std::vector<PiecewiseLinear::Point> alpha) {
    return transferFunction(std::move(alpha), {{0, 0.1}, {1, 0.9}},
                            {{0, 0.8}, {0.5, 0.3}, {1, 0.6}}, {{0, 0.2}, {1, 1}});
}

} // namespace

TEST_CASE_FIXTURE(GlFixture,
                  "orthoslice pixels equal double precision sampling of the same world point") {
    SliceScene scene(VolumeData::MARSCHNER_LOBB, glm::vec3(32.0f), colourful({{0, 0.3}, {1, 1}}));
    auto slice = OrthoSlice::create();
    slice->axis = OrthoSlice::Y;
    slice->sliceNumber = 13;
    slice->alphaUse = OrthoSlice::ALPHA_OPAQUE;
    scene.root->addChild(slice);
    const VolumeInScope volume = scene.volume();
    auto camera = framing(*volume.data, {0.4f, 1.0f, 0.7f});
    for (int interpolation : {OrthoSlice::LINEAR, OrthoSlice::NEAREST}) {
        slice->interpolation = interpolation;
        const PixelComparison c = renderAndCompare(
            renderer, *scene.root, *camera, volume, SlicePlane::orthogonal(*volume.data, 1, 13),
            slice->style(), interpolation == OrthoSlice::LINEAR ? "ortho-linear" : "ortho-nearest",
            interpolation == OrthoSlice::NEAREST);
        CHECK(c.compared > 1000);
        CHECK(c.discardMismatches == 0);
        CHECK(c.maxError <= k8Bit);
    }
}

TEST_CASE("sliceNumber is clamped to the data and each axis cuts through voxel centres") {
    const auto grid = VolumeGrid::create({4, 6, 8}, VoxelType::UByte, {1.0, 0.5, 2.0});
    CHECK(SlicePlane::orthogonal(*grid, 0, 0).distance == doctest::Approx(-1.5).epsilon(1e-12));
    CHECK(SlicePlane::orthogonal(*grid, 1, 99).distance == doctest::Approx(1.25).epsilon(1e-12));
    CHECK(SlicePlane::orthogonal(*grid, 2, -5).distance == doctest::Approx(-7.0).epsilon(1e-12));
    CHECK(SlicePlane::orthogonal(*grid, 2, 3).normal == glm::dvec3(0, 0, 1));
}

TEST_CASE("the sampler replaces non-finite float voxels by the finite extremes") {
    auto grid = VolumeGrid::create({2, 1, 1}, VoxelType::Float);
    grid->setValue(0, 0, 0, std::numeric_limits<double>::quiet_NaN());
    grid->setValue(1, 0, 0, 4.0);
    auto other = VolumeGrid::create({3, 1, 1}, VoxelType::Float);
    other->setValue(0, 0, 0, -2.0);
    other->setValue(1, 0, 0, std::numeric_limits<double>::infinity());
    other->setValue(2, 0, 0, 6.0);
    VolumeInScope volume;
    volume.data = grid;
    const SliceSampler sampler(volume, SliceStyle{true, SliceAlphaUse::Opaque});
    // NaN becomes the finite minimum (4), so the data is 4 everywhere, not NaN.
    const SliceSample s = sampler.sample({-0.5, 0.0, 0.0}); // voxel 0's centre
    CHECK(s.value == 4.0);
    CHECK(std::isnan(s.voxelValue));
    volume.data = other;
    const SliceSampler second(volume, SliceStyle{true, SliceAlphaUse::Opaque});
    // Halfway between voxel 0 (-2) and voxel 1 (+Inf -> 6): 2; v = (2 + 2) / 8 = 0.5.
    const SliceSample t = second.sample({-0.5, 0.0, 0.0});
    CHECK(t.value == doctest::Approx(2.0).epsilon(1e-12));
    CHECK(t.voxel == glm::ivec3(1, 0, 0)); // x = -0.5 is voxel 1's cell face: it starts there
    CHECK(t.rgba.r == doctest::Approx(0.5).epsilon(1e-12));
}

TEST_CASE_FIXTURE(GlFixture,
                  "obliqueslice is trilinear with anisotropic spacing under a transform") {
    SliceScene scene(VolumeData::SOFT_SPHERE, glm::vec3(24.0f), colourful({{0, 0.3}, {1, 1}}));
    scene.data->spacing = glm::vec3(1.0f, 1.5f, 0.75f);
    auto transform = Transform::create();
    transform->translation = glm::vec3(2.0f, -1.0f, 0.5f);
    transform->rotation = Rotation{glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)), 0.6f};
    transform->scaleFactor = glm::vec3(1.2f, 0.8f, 1.0f);
    scene.root->insertChild(transform, 0);
    auto slice = ObliqueSlice::create();
    slice->plane = Plane{glm::vec3(1.0f, 2.0f, 3.0f), 4.0f};
    slice->alphaUse = OrthoSlice::ALPHA_OPAQUE;
    scene.root->addChild(slice);
    const VolumeInScope volume = scene.volume();
    auto camera = framing(*volume.data, {0.3f, -0.5f, 1.0f}, 2.2f);
    camera->position = camera->position.getValue() + glm::vec3(2.0f, -1.0f, 0.5f);
    const PixelComparison c = renderAndCompare(renderer, *scene.root, *camera, volume,
                                               *slice->localPlane(), slice->style(), "oblique");
    CHECK(c.compared > 800);
    CHECK(c.discardMismatches == 0);
    CHECK(c.maxError <= k8Bit);
}

TEST_CASE_FIXTURE(GlFixture, "a 16-bit slice matches within the transfer table resolution") {
    TransferFunction1D tf = colourful({{0, 0.5}, {1, 1}});
    tf.setDataRange(10000.0, 50000.0);
    SliceScene scene(VolumeData::RAMP16, glm::vec3(40.0f, 16.0f, 16.0f), tf);
    auto slice = OrthoSlice::create();
    slice->sliceNumber = 7;
    slice->alphaUse = OrthoSlice::ALPHA_OPAQUE;
    scene.root->addChild(slice);
    const VolumeInScope volume = scene.volume();
    REQUIRE(volume.data->type() == VoxelType::UShort);
    auto camera = framing(*volume.data, {0.2f, 0.3f, 1.0f});
    const PixelComparison c =
        renderAndCompare(renderer, *scene.root, *camera, volume,
                         SlicePlane::orthogonal(*volume.data, 2, 7), slice->style(), "ramp16");
    CHECK(c.compared > 1000);
    CHECK(c.discardMismatches == 0);
    // Colour slopes are at most 1 per unit v: one table step of v.
    CHECK(c.maxError <= kTableStep);
}

TEST_CASE_FIXTURE(GlFixture, "a float slice matches with the data's own range") {
    SliceScene scene(VolumeData::SOFT_SPHERE, glm::vec3(24.0f), colourful({{0, 0.5}, {1, 1}}));
    scene.data->dataType = VolumeData::FLOAT;
    auto slice = ObliqueSlice::create();
    slice->plane = Plane{glm::vec3(0.2f, -0.3f, 1.0f), 1.5f};
    slice->alphaUse = OrthoSlice::ALPHA_OPAQUE;
    scene.root->addChild(slice);
    const VolumeInScope volume = scene.volume();
    REQUIRE(volume.data->type() == VoxelType::Float);
    auto camera = framing(*volume.data, {0.1f, -0.2f, 1.0f});
    const PixelComparison c = renderAndCompare(renderer, *scene.root, *camera, volume,
                                               *slice->localPlane(), slice->style(), "float");
    CHECK(c.compared > 1000);
    CHECK(c.discardMismatches == 0);
    CHECK(c.maxError <= kTableStep);
}

TEST_CASE_FIXTURE(GlFixture, "a tagged slice uses the transfer function of each voxel's tag") {
    SliceScene scene(VolumeData::LABELLED, glm::vec3(24.0f), colourful({{0, 0.4}, {1, 1}}));
    auto inner = TransferFunction::create();
    inner->tag = 1;
    setNodeFields(*inner, transferFunction({{0, 1}, {1, 1}}, {{0, 1}, {1, 1}}, {{0, 0}, {1, 0.5}},
                                           {{0, 0}, {1, 0}}));
    auto corner = TransferFunction::create();
    corner->tag = 3;
    setNodeFields(*corner, transferFunction({{0, 0}, {1, 0}}, {{0, 0}}, {{0, 0}}, {{0, 1}}));
    scene.root->addChild(inner);
    scene.root->addChild(corner);
    // Across y: the slice meets tags 1 and 2 (inner spheres), 3 (k < n/4) and 0.
    auto slice = OrthoSlice::create();
    slice->axis = OrthoSlice::Y;
    slice->sliceNumber = 12;
    slice->interpolation = OrthoSlice::NEAREST;
    scene.root->addChild(slice); // ALPHA_BINARY: tag 3 has alpha 0 and is discarded
    const VolumeInScope volume = scene.volume();
    REQUIRE(volume.tags);
    auto camera = framing(*volume.data, {0.1f, 1.0f, 0.3f});
    const PixelComparison c = renderAndCompare(renderer, *scene.root, *camera, volume,
                                               SlicePlane::orthogonal(*volume.data, 1, 12),
                                               slice->style(), "tagged", true);
    CHECK(c.compared > 1000);
    CHECK(c.drawnBoth < c.compared); // some voxels are tag 3 or transparent
    CHECK(c.discardMismatches == 0);
    CHECK(c.maxError <= k8Bit);
}

TEST_CASE_FIXTURE(
    GlFixture,
    "alpha binary discards transparent pixels and alpha as is blends over the background") {
    // Alpha 0 below v = 0.4 (a kink): binary draws only where the data exceeds it.
    SliceScene scene(VolumeData::SOFT_SPHERE, glm::vec3(24.0f),
                     colourful({{0, 0}, {0.4, 0}, {1, 0.8}}));
    auto slice = OrthoSlice::create();
    slice->sliceNumber = 11;
    scene.root->addChild(slice);
    const VolumeInScope volume = scene.volume();
    auto camera = framing(*volume.data, {0.0f, 0.4f, 1.0f});
    const SlicePlane plane = SlicePlane::orthogonal(*volume.data, 2, 11);
    for (int use : {OrthoSlice::ALPHA_BINARY, OrthoSlice::ALPHA_AS_IS}) {
        slice->alphaUse = use;
        const PixelComparison c =
            renderAndCompare(renderer, *scene.root, *camera, volume, plane, slice->style(),
                             use == OrthoSlice::ALPHA_BINARY ? "binary" : "as-is");
        CHECK(c.drawnBoth > 200);
        CHECK(c.compared - c.drawnBoth > 200);
        // Only where v is within a table step of the kink can the table's linear
        // interpolation disagree about alpha > 0.
        CHECK(c.discardMismatches <= c.compared / 100);
        CHECK(c.maxError <= k8Bit);
    }
}

TEST_CASE_FIXTURE(GlFixture,
                  "a slice inside a volume is covered in front and hides the volume behind it") {
    const ref_ptr<Node> root = readSceneFromString(R"(#Inventor V2.1 ascii
Separator {
  PerspectiveCamera { position 0.6 0.5 2.0 orientation -0.6 0.8 0 0.35 heightAngle 0.75
                      nearDistance 0.5 farDistance 5 }
  VolumeData { generator SOFT_SPHERE dimensions 24 24 24 spacing 0.05 0.05 0.05 }
  TransferFunction { red [ 0 0.2, 1 1 ] green [ 0 0.6, 1 0.3 ] blue [ 0 1, 1 0.2 ]
                     alpha [ 0 0.02, 1 0.35 ] }
  Volume { }
  TransferFunction { red [ 0 1, 1 0 ] green [ 0 0, 1 1 ] blue [ 0 0.2 ] alpha [ 0 1 ] }
  OrthoSlice { axis X sliceNumber 9 alphaUse ALPHA_OPAQUE }
}
)");
    RenderOptions options;
    options.width = options.height = 48;
    options.background = kBackground;
    // renderReference takes opaque geometry (the slice, drawn in the opaque pass) from GL and
    // ends the reference rays at its depth.
    Image gl;
    checkDifference(compareScene(renderer, *root, options, "inside", &gl), 0.3, 4.0);

    // Without the volume in front the slice shows brighter; the volume dims it and adds its
    // own colour, so the composited centre differs from the bare slice.
    auto* group = static_cast<Separator*>(root.get());
    auto bare = Separator::create();
    for (const auto& child : *group->children())
        if (!child->isA<Volume>()) bare->addChild(child);
    const Image sliceAlone = renderer.render(*bare, options);
    const glm::vec4 a = gl.at(24, 24), b = sliceAlone.at(24, 24);
    CHECK(glm::length(glm::vec3(a) - glm::vec3(b)) > 0.05f);
}

TEST_CASE_FIXTURE(GlFixture,
                  "a clipping orthoslice cuts the volume after it on its clipping side") {
    const std::string scene = R"(#Inventor V2.1 ascii
Separator {
  PerspectiveCamera { position 0.4 0.8 2.0 orientation -1 0.3 0 0.4 heightAngle 0.75
                      nearDistance 0.5 farDistance 5 }
  VolumeData { generator SOFT_SPHERE dimensions 24 24 24 spacing 0.05 0.05 0.05 }
  TransferFunction { red [ 0 0.2, 1 1 ] green [ 0 0.6, 1 0.3 ] blue [ 0 1, 1 0.2 ]
                     alpha [ 0 0.05, 1 0.5 ] }
  OrthoSlice { axis Y sliceNumber 14 clipping TRUE clippingSide SIDE alphaUse ALPHA_OPAQUE }
  Volume { }
}
)";
    RenderOptions options;
    options.width = options.height = 48;
    options.background = kBackground;
    // Voxel centre 14 of 24 at spacing 0.05: y = -0.6 + 14.5 * 0.05 = 0.125.
    for (const char* side : {"BACK", "FRONT"}) {
        std::string text = scene;
        text.replace(text.find("SIDE"), 4, side);
        const ref_ptr<Node> root = readSceneFromString(text);
        const std::vector<RayCastVolume> volumes = collectVolumes(*root);
        REQUIRE(volumes.size() == 1);
        REQUIRE(volumes[0].clipPlanes.size() == 1);
        const glm::dvec4 plane = volumes[0].clipPlanes[0];
        const double sign = std::string(side) == "BACK" ? 1.0 : -1.0;
        CHECK(plane.y == doctest::Approx(sign).epsilon(1e-6));
        CHECK(std::abs(plane.x) + std::abs(plane.z) < 1e-6);
        CHECK(plane.w == doctest::Approx(sign * 0.125).epsilon(1e-6));

        const Image gl = renderer.render(*root, options);
        const Image ref = renderReference(*root, options);
        keepImage(gl, std::string("clipping-") + side);
        checkDifference(difference(gl, ref), 0.3, 4.0, std::string(side) + ": ");
    }
}

TEST_CASE("picking a slice reports the voxel index and the data value there") {
    SliceScene scene(VolumeData::MARSCHNER_LOBB, glm::vec3(20.0f), colourful({{0, 0.3}, {1, 1}}));
    auto slice = OrthoSlice::create();
    slice->sliceNumber = 6;
    scene.root->addChild(slice);
    const VolumeInScope volume = scene.volume();
    const VolumeGrid& grid = *volume.data;
    // A ray straight down -Z through the centre of voxel (3, 15) of slice 6, nudged inside
    // the cell so the nearest voxel is unambiguous.
    const glm::dvec3 target =
        grid.voxelCenter(3, 15, 6) + glm::dvec3(0.2, -0.1, 0.0) * grid.spacing();
    PickAction pick;
    pick.setRay(Ray{target + glm::dvec3(0, 0, 10), glm::dvec3(0, 0, -1)});
    pick.apply(*scene.root);
    REQUIRE(pick.picked());
    const PickedPoint& hit = *pick.picked();
    REQUIRE(hit.voxel);
    CHECK(hit.voxel->index == glm::ivec3(3, 15, 6));
    CHECK(hit.voxel->voxelValue == grid.value(3, 15, 6));
    CHECK(hit.point.z == doctest::Approx(grid.voxelCenter(0, 0, 6).z).epsilon(1e-12));
    // Bilinear in the slice plane between the four voxels around the point.
    const double fx = 0.2, fy = 0.9; // from voxel 3 towards 4 in x; from 14 towards 15 in y
    const double v00 = grid.value(3, 14, 6), v10 = grid.value(4, 14, 6);
    const double v01 = grid.value(3, 15, 6), v11 = grid.value(4, 15, 6);
    const double bilinear =
        (v00 * (1 - fx) + v10 * fx) * (1 - fy) + (v01 * (1 - fx) + v11 * fx) * fy;
    CHECK(hit.voxel->value == doctest::Approx(bilinear).epsilon(1e-9));
    CHECK(hit.path.back() == slice.get());
}

TEST_CASE("a pick misses a slice where it is discarded and hits the nearer of slice and shape") {
    // Alpha 0 everywhere below v = 0.5: the binary slice is discarded where data is low.
    SliceScene scene(VolumeData::SOFT_SPHERE, glm::vec3(16.0f),
                     colourful({{0, 0}, {0.5, 0}, {0.6, 1}}));
    auto slice = OrthoSlice::create();
    slice->sliceNumber = 8;
    scene.root->addChild(slice);
    const VolumeInScope volume = scene.volume();
    const SliceSampler sampler(volume, slice->style());
    const double z = volume.data->voxelCenter(0, 0, 8).z;
    const glm::dvec3 corner = volume.data->voxelCenter(0, 0, 8); // low data
    const glm::dvec3 centre = volume.data->voxelCenter(8, 8, 8); // high data
    REQUIRE(sampler.sample(corner).discarded());
    REQUIRE(!sampler.sample(centre).discarded());
    auto pickAt = [&](const glm::dvec3& p) {
        PickAction pick;
        pick.setRay(Ray{glm::dvec3(p.x, p.y, z + 20.0), glm::dvec3(0, 0, -1)});
        pick.apply(*scene.root);
        return pick.picked();
    };
    CHECK(!pickAt(corner));
    REQUIRE(pickAt(centre));
    CHECK(pickAt(centre)->voxel->index == glm::ivec3(8, 8, 8));

    // A cube in front of the slice takes the pick; behind it, the slice keeps it.
    auto front = Separator::create();
    auto move = Transform::create();
    move->translation = glm::vec3(float(centre.x), float(centre.y), float(z + 3.0));
    front->addChild(move);
    front->addChild(Cube::create());
    scene.root->addChild(front);
    REQUIRE(pickAt(centre));
    CHECK(!pickAt(centre)->voxel);
    move->translation = glm::vec3(float(centre.x), float(centre.y), float(z - 3.0));
    REQUIRE(pickAt(centre));
    CHECK(pickAt(centre)->voxel);
}

TEST_CASE_FIXTURE(
    GlFixture,
    "LightModel BASE_COLOR draws shapes unlit in their diffuse colour within its scope") {
    auto root = Separator::create();
    auto camera = perspectiveAt({0.0f, 0.0f, 6.0f}, 0.8f, 1.0f, 20.0f);
    root->addChild(camera);
    auto light = DirectionalLight::create();
    light->direction = glm::vec3(-0.3f, -0.5f, -1.0f);
    root->addChild(light);
    auto material = Material::create();
    material->diffuseColor = {glm::vec3(0.2f, 0.5f, 0.7f)};
    material->emissiveColor = {glm::vec3(0.1f, 0.0f, 0.0f)};
    material->specularColor = {glm::vec3(0.5f)};
    root->addChild(material);
    auto scoped = Separator::create();
    auto model = LightModel::create();
    model->model = LightModel::BASE_COLOR;
    auto left = Transform::create();
    left->translation = glm::vec3(-1.2f, 0.0f, 0.0f);
    scoped->addChild(model);
    scoped->addChild(left);
    scoped->addChild(Sphere::create());
    root->addChild(scoped);
    auto right = Transform::create();
    right->translation = glm::vec3(1.2f, 0.0f, 0.0f);
    root->addChild(right);
    root->addChild(Sphere::create());

    RenderOptions options;
    options.width = 96;
    options.height = 48;
    const Image image = renderer.render(*root, options);
    keepImage(image, "light-model");
    // Left sphere: flat diffuse everywhere, exactly. Right sphere (out of scope): lit, so it
    // varies and has the emissive red.
    for (int x : {32, 35, 38, 41})
        for (int y : {20, 24, 28}) {
            const glm::vec4 p = image.at(x, y);
            CHECK(std::abs(p.r - 0.2f) < 1e-6f);
            CHECK(std::abs(p.g - 0.5f) < 1e-6f);
            CHECK(std::abs(p.b - 0.7f) < 1e-6f);
        }
    const glm::vec4 a = image.at(55, 20), b = image.at(64, 29);
    CHECK(std::abs(a.g - b.g) > 0.01f);
    CHECK(std::abs(a.g - 0.5f) > 0.01f);
}

TEST_CASE_FIXTURE(
    GlFixture,
    "ResetTransform TRANSFORM resets the model matrix for render, pick and bounding box") {
    auto root = Separator::create();
    auto camera = perspectiveAt({0.0f, 0.0f, 8.0f}, 0.8f, 1.0f, 20.0f);
    root->addChild(camera);
    auto away = Transform::create();
    away->translation = glm::vec3(50.0f, 0.0f, 0.0f);
    away->scaleFactor = glm::vec3(3.0f);
    root->addChild(away);
    root->addChild(ResetTransform::create());
    root->addChild(Cube::create());

    const Box3 box = computeBoundingBox(*root);
    CHECK(box.min == glm::dvec3(-1.0));
    CHECK(box.max == glm::dvec3(1.0));

    PickAction pick;
    pick.setRay(Ray{glm::dvec3(0.3, 0.2, 10.0), glm::dvec3(0, 0, -1)});
    pick.apply(*root);
    REQUIRE(pick.picked());
    CHECK(pick.picked()->point.z == doctest::Approx(1.0).epsilon(1e-12));

    RenderOptions options;
    options.width = options.height = 32;
    const Image image = renderer.render(*root, options);
    CHECK(glm::length(glm::vec3(image.at(16, 16)) - options.background) > 0.1f);
}

TEST_CASE("ResetTransform BBOX empties only the box accumulated in its Separator") {
    // Outer: a cube at x = 10. Inner Separator: a cube at x = -20, then BBOX (the transform
    // stays), then a sphere at x = -10. The inner cube is forgotten, the outer one is not.
    const ref_ptr<Node> root = readSceneFromString(R"(#Inventor V2.1 ascii
Separator {
  Separator { Transform { translation 10 0 0 } Cube { } }
  Separator {
    Transform { translation -20 0 0 } Cube { }
    ResetTransform { whatToReset BBOX }
    Transform { translation 10 0 0 } Sphere { }
  }
}
)");
    const Box3 box = computeBoundingBox(*root);
    CHECK(box.min.x == doctest::Approx(-11.0).epsilon(1e-12));
    CHECK(box.max.x == doctest::Approx(11.0).epsilon(1e-12));
    CHECK(box.min.y == doctest::Approx(-1.0).epsilon(1e-12));
}

TEST_CASE("the section and Inventor nodes round trip through the writer and reader") {
    auto root = Separator::create();
    auto lightModel = LightModel::create();
    lightModel->model = LightModel::BASE_COLOR;
    auto reset = ResetTransform::create();
    reset->whatToReset.setValue(ResetTransform::TRANSFORM | ResetTransform::BBOX);
    auto ortho = OrthoSlice::create();
    ortho->sliceNumber = 17;
    ortho->axis = OrthoSlice::X;
    ortho->interpolation = OrthoSlice::NEAREST;
    ortho->alphaUse = OrthoSlice::ALPHA_AS_IS;
    ortho->clipping = true;
    ortho->clippingSide = OrthoSlice::FRONT;
    auto oblique = ObliqueSlice::create();
    oblique->plane = Plane{glm::vec3(0.0f, 0.6f, 0.8f), -0.25f};
    oblique->alphaUse = OrthoSlice::ALPHA_OPAQUE;
    for (const ref_ptr<Node>& n :
         std::vector<ref_ptr<Node>>{lightModel, reset, ortho, oblique, OrthoSlice::create()})
        root->addChild(n);

    const std::string text = writeSceneToString(*root);
    const ref_ptr<Node> back = readSceneFromString(text, "sections.iv");
    std::string why;
    CHECK_MESSAGE(graphsEqual(*root, *back, &why), why, "\n", text);
    CHECK(writeSceneToString(*back) == text);
    // Inventor builtins are written bare; our slices describe their fields for other readers.
    CHECK(text.find("LightModel {\n") != std::string::npos);
    CHECK(text.find("model BASE_COLOR") != std::string::npos);
    CHECK(text.find("whatToReset (TRANSFORM | BBOX)") != std::string::npos);
    CHECK(text.find("OrthoSlice {\n    fields [") != std::string::npos);
    CHECK(text.find("ObliqueSlice {\n    fields [") != std::string::npos);
    const auto& children = *back->children();
    REQUIRE(children.size() == 5);
    CHECK(children[2]->isA<OrthoSlice>());
    CHECK(static_cast<const OrthoSlice&>(*children[2]).clippingSide() == OrthoSlice::FRONT);
}
