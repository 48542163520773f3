// The shear-warp engine without GL: packing, extraction, RenderLists, every rendering mode and
// compositing mode on small analytic volumes, clipping, the optimizer, depth, picking, and
// the plain transfer-function modes against the reference ray caster.
#include <doctest/doctest.h>

#include <volsg/core/Error.h>
#include <volsg/reference/ReferenceRayCaster.h>
#include <volsg/shearwarp/GradientCode.h>
#include <volsg/shearwarp/PackedVoxel.h>
#include <volsg/shearwarp/ShearWarpRenderer.h>
#include <volsg/shearwarp/VoxelListOptimizer.h>
#include <volsg/shearwarp/VoxelObject.h>
#include <volsg/volume/TestVolumes.h>
#include <volsg/volume/VolumeGrid.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <tuple>

using namespace volsg;

namespace {

TransferFunction1D constantTf(glm::vec3 colour, double alpha) {
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Red, {{0.0, colour.r}});
    tf.setChannel(TransferFunction1D::Green, {{0.0, colour.g}});
    tf.setChannel(TransferFunction1D::Blue, {{0.0, colour.b}});
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, alpha}});
    return tf;
}

/// An orthographic view of the box [-half, half]^2 looking down -z after rotating the
/// volume by `angleY` about y (and `angleX` about x).
ShearWarpView orthoView(int size, double half, double angleY = 0.0, double angleX = 0.0) {
    ShearWarpView view;
    view.modelView = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -10.0)) *
                     glm::rotate(glm::dmat4(1.0), angleX, glm::dvec3(1, 0, 0)) *
                     glm::rotate(glm::dmat4(1.0), angleY, glm::dvec3(0, 1, 0));
    view.projection = glm::ortho(-half, half, -half, half, 1.0, 20.0);
    view.width = view.height = size;
    return view;
}

ShearWarpObject objectOf(const VolumeGrid& grid, const TransferFunction1D& tf,
                         ObjectSource source = {},
                         VoxelSelection selection = VoxelSelection::Visible,
                         const VolumeGrid* tags = nullptr) {
    ExtractionSpec spec;
    spec.source = source;
    spec.selection = selection;
    spec.transferFunction = tf;
    ShearWarpObject o;
    o.object = VoxelObject::extract(grid, tags, spec);
    o.transferFunction = tf;
    return o;
}

/// Marschner-Lobb's test colours: a blue-to-orange ramp, alpha 0 to 0.2.
TransferFunction1D smoothColourRamp() {
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Red, {{0.0, 0.1}, {0.5, 0.9}, {1.0, 1.0}});
    tf.setChannel(TransferFunction1D::Green, {{0.0, 0.3}, {0.5, 0.6}, {1.0, 0.9}});
    tf.setChannel(TransferFunction1D::Blue, {{0.0, 1.0}, {0.5, 0.4}, {1.0, 0.1}});
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}, {1.0, 0.2}});
    return tf;
}

glm::vec4 centre(const ShearWarpFrame& f) {
    return f.image.at(f.image.width / 2, f.image.height / 2);
}

RayCastScene referenceScene(const ShearWarpView& view, const VolumeGrid& grid,
                            const TransferFunction1D& tf, VolumeRenderMode mode) {
    RayCastScene scene;
    scene.camera.view = view.modelView;
    scene.camera.projection = view.projection;
    scene.camera.width = view.width;
    scene.camera.height = view.height;
    RayCastVolume v;
    v.data = ref_ptr<const VolumeGrid>(&grid);
    v.transferFunctions[-1] = tf;
    v.mode = mode;
    scene.volumes.push_back(v);
    return scene;
}

double rmse(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::dvec3 d = glm::dvec3(a.pixels[i]) - glm::dvec3(b.pixels[i]);
        sum += glm::dot(d, d) / 3.0;
    }
    return std::sqrt(sum / double(a.pixels.size()));
}

} // namespace

TEST_CASE("packed voxels round trip position and attributes") {
    for (unsigned a : {0u, 1u, 127u, 255u})
        for (unsigned b : {0u, 3u, 200u, 255u})
            for (unsigned m : {0u, 1u, 2048u, 4095u})
                for (unsigned s : {0u, 7u, 15u}) {
                    const std::uint32_t v = PackedVoxel::pack(a, b, m, s);
                    CHECK(PackedVoxel::a(v) == a);
                    CHECK(PackedVoxel::b(v) == b);
                    CHECK(PackedVoxel::main12(v) == m);
                    CHECK(PackedVoxel::second4(v) == s);
                    CHECK(PackedVoxel::attributes16(v) == ((s << 12) | m));
                    const std::uint32_t w = PackedVoxel::withAttributes(v, 4095 - m, 15 - s);
                    CHECK(PackedVoxel::a(w) == a);
                    CHECK(PackedVoxel::b(w) == b);
                    CHECK(PackedVoxel::main12(w) == 4095 - m);
                }
}

TEST_CASE("gradient codes decode within 3 degrees of the encoded direction") {
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {
        // A deterministic spread of directions over the sphere (golden spiral).
        const double z = 1.0 - 2.0 * (i + 0.5) / 2000.0;
        const double phi = i * 2.399963229728653;
        const glm::vec3 d(float(std::sqrt(1 - z * z) * std::cos(phi)),
                          float(std::sqrt(1 - z * z) * std::sin(phi)), float(z));
        const glm::vec3 back = GradientCode::decode(GradientCode::encode(d));
        worst = std::max(worst, std::acos(std::clamp(double(glm::dot(back, d)), -1.0, 1.0)));
    }
    CHECK(worst * 180.0 / M_PI < 3.6);
}

TEST_CASE("objects wider than 256 voxels are split into pieces with offsets") {
    auto grid = makeConstant({300, 3, 2}, VoxelType::UByte, 200.0);
    auto object = VoxelObject::extract(*grid, nullptr, ExtractionSpec{});
    REQUIRE(object->voxelCount() == 300u * 3u * 2u);
    const RenderList& list = object->renderList(2);
    // Per slice (k = 0, 1): one entry for x < 256 and one for x >= 256.
    REQUIRE(list.entries.size() == 4u);
    CHECK(list.entries[0].offset.x == 0);
    CHECK(list.entries[1].offset.x == 256);
    CHECK(list.entries[1].lastInSlice - list.entries[1].first == 44u * 3u);
    std::set<std::tuple<int, int, int>> seen;
    for (const RenderListEntry& e : list.entries)
        for (std::uint32_t i = e.first; i < e.lastInSlice; ++i) {
            const glm::ivec3 p = list.position(e, i);
            seen.insert({p.x, p.y, p.z});
            CHECK(list.value12[i] == 3212); // round(200 / 255 * 4095)
        }
    CHECK(seen.size() == 300u * 3u * 2u);
    // Along x (axis 0) there are 300 slices of 3 x 2 voxels, the slice index above 255 in
    // the offset.
    const RenderList& alongX = object->renderList(0);
    CHECK(alongX.entries.size() == 300u);
    CHECK(alongX.entries[299].offset.z == 256);
    CHECK(alongX.entries[299].z == 43);
    CHECK(alongX.position(alongX.entries[299], alongX.entries[299].first).x == 299);
}

TEST_CASE("render lists are built only for the axes a view needs") {
    auto grid = makeSoftSphere(16);
    ShearWarpObject o = objectOf(*grid, TransferFunction1D());
    std::vector<ShearWarpObject> objects{o};
    ShearWarpRenderer renderer;
    renderer.render(objects, orthoView(32, 1.0 * 16 / 1.5));
    CHECK(o.object->hasRenderList(2));
    CHECK_FALSE(o.object->hasRenderList(0));
    CHECK_FALSE(o.object->hasRenderList(1));
}

TEST_CASE("extraction takes visible, surface, gradient, tag and threshold voxels") {
    const int n = 12;
    auto grid = makeConstant({n, n, n}, VoxelType::UByte, 0.0);
    auto tags = makeConstant({n, n, n}, VoxelType::UByte, 0.0);
    // A 4^3 cube of 255 (tag 1) inside zeros.
    for (int k = 4; k < 8; ++k)
        for (int j = 4; j < 8; ++j)
            for (int i = 4; i < 8; ++i) {
                grid->setValue(i, j, k, 255.0);
                tags->setValue(i, j, k, 1.0);
            }
    TransferFunction1D tf; // alpha = v: zeros are invisible
    ExtractionSpec spec;
    spec.transferFunction = tf;
    CHECK(VoxelObject::extract(*grid, nullptr, spec)->voxelCount() == 64u);
    spec.selection = VoxelSelection::Surface;
    CHECK(VoxelObject::extract(*grid, nullptr, spec)->voxelCount() == 64u - 8u);
    spec.source.kind = ObjectSource::Threshold;
    spec.source.low = 100.0;
    spec.source.high = 255.0;
    CHECK(VoxelObject::extract(*grid, nullptr, spec)->voxelCount() == 56u);
    spec.source.kind = ObjectSource::Tag;
    spec.source.tag = 0;
    spec.selection = VoxelSelection::Visible; // tag 0 is all zeros: invisible under alpha = v
    CHECK(VoxelObject::extract(*grid, tags.get(), spec)->voxelCount() == 0u);
    spec.source.tag = 1;
    CHECK(VoxelObject::extract(*grid, tags.get(), spec)->voxelCount() == 64u);
    CHECK_THROWS_AS(VoxelObject::extract(*grid, nullptr, spec), Error);
    // Gradient: the whole grid; a voxel's central difference is nonzero next to the cube's
    // faces only: the 6^3 block around it minus the cube's 2^3 core and the block's 8 corners
    // and 12 edges... counted directly instead.
    spec.source.kind = ObjectSource::Whole;
    spec.selection = VoxelSelection::Gradient;
    spec.gradientThreshold = 0.01;
    spec.transferFunction = constantTf(glm::vec3(1.0f), 1.0); // Whole region: every voxel
    std::size_t expected = 0;
    auto v = [&](int i, int j, int k) {
        i = std::clamp(i, 0, n - 1), j = std::clamp(j, 0, n - 1), k = std::clamp(k, 0, n - 1);
        return grid->value(i, j, k);
    };
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (v(i + 1, j, k) != v(i - 1, j, k) || v(i, j + 1, k) != v(i, j - 1, k) ||
                    v(i, j, k + 1) != v(i, j, k - 1))
                    ++expected;
    CHECK(VoxelObject::extract(*grid, nullptr, spec)->voxelCount() == expected);
}

TEST_CASE("a constant cube has the analytic opacity straight on and oblique") {
    const int n = 16;
    auto grid = makeConstant({n, n, n}, VoxelType::UByte, 255.0);
    const double a = 0.1;
    std::vector<ShearWarpObject> objects{objectOf(*grid, constantTf({1.0f, 0.5f, 0.25f}, a))};
    ShearWarpRenderer renderer;
    for (double angle : {0.0, 0.3, 0.6}) {
        const ShearWarpFrame f = renderer.render(objects, orthoView(64, 16.0, angle));
        // The centre ray crosses the cube's z faces: path length n / cos(angle) voxels.
        const double expected = 1.0 - std::pow(1.0 - a, n / std::cos(angle));
        const glm::vec4 c = centre(f);
        CHECK(c.a == doctest::Approx(expected).epsilon(0.002));
        CHECK(c.r == doctest::Approx(expected).epsilon(0.002));
        CHECK(c.g == doctest::Approx(0.5 * expected).epsilon(0.002));
        CHECK(f.stats.fastPath);
    }
    CHECK_THROWS_AS(
        [&] {
            ShearWarpView v = orthoView(8, 16.0);
            v.projection = glm::perspective(0.8, 1.0, 1.0, 20.0);
            renderer.render(objects, v);
        }(),
        Error);
}

TEST_CASE("early ray termination skips hidden voxels and stops within 0.001 of opaque") {
    const int n = 32;
    auto grid = makeConstant({n, n, n}, VoxelType::UByte, 255.0);
    std::vector<ShearWarpObject> objects{objectOf(*grid, constantTf(glm::vec3(1.0f), 0.5))};
    ShearWarpRenderer renderer;
    const ShearWarpFrame f = renderer.render(objects, orthoView(32, 20.0, 0.3));
    // 1 - 0.5^32 is 1 to 1e-9; rays stop at 0.999 after about 10 of the 32 slices.
    CHECK(centre(f).a >= 0.999f);
    CHECK(centre(f).a <= 1.0f);
    MESSAGE("voxels read " << f.stats.voxelsTouched << ", hidden " << f.stats.voxelsHidden);
    CHECK(f.stats.voxelsHidden > f.stats.voxelsTouched / 2);
}

TEST_CASE("threads give the same image as one thread") {
    auto grid = makeMarschnerLobb(24);
    std::vector<ShearWarpObject> objects{objectOf(*grid, constantTf(glm::vec3(0.8f), 0.2))};
    objects[0].transferFunction.setChannel(TransferFunction1D::Alpha, {{0.3, 0.0}, {1.0, 0.4}});
    ShearWarpRenderer renderer;
    ShearWarpView view = orthoView(48, 1.8, 0.7, 0.4);
    view.threads = 1;
    const ShearWarpFrame one = renderer.render(objects, view);
    view.threads = 2;
    const ShearWarpFrame two = renderer.render(objects, view);
    CHECK(one.image.pixels == two.image.pixels);
    CHECK(one.stats.voxelsTouched > 0u);
}

TEST_CASE("every SIMD level renders the same frame bit for bit") {
    // The view's setting picks the kernels' vector instructions; the default is the widest the
    // CPU runs, and a level it does not run is taken as Scalar.
    CHECK(ShearWarpView{}.simd == bestSimdLevel());
    auto grid = makeMarschnerLobb(32);
    TransferFunction1D opaque = smoothColourRamp();
    opaque.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}, {0.4, 0.9}, {1.0, 1.0}});
    for (const TransferFunction1D& tf : {smoothColourRamp(), opaque}) {
        std::vector<ShearWarpObject> objects{objectOf(*grid, tf)};
        ShearWarpRenderer renderer;
        ShearWarpView view = orthoView(64, 1.8, 0.5, 0.3);
        view.simd = SimdLevel::Scalar;
        const ShearWarpFrame scalar = renderer.render(objects, view);
        view.simd = SimdLevel::Avx2;
        const ShearWarpFrame avx2 = renderer.render(objects, view);
        CHECK(scalar.stats.fastPath); // pure DVR: the row composite has an AVX2 kernel
        CHECK(scalar.stats.voxelsTouched > 0u);
        REQUIRE(scalar.image.pixels.size() == avx2.image.pixels.size());
        CHECK(std::memcmp(scalar.image.pixels.data(), avx2.image.pixels.data(),
                          scalar.image.pixels.size() * sizeof(glm::vec4)) == 0);
        CHECK(scalar.pickObject == avx2.pickObject);
        REQUIRE(scalar.pickSlice.size() == avx2.pickSlice.size());
        CHECK(std::memcmp(scalar.pickSlice.data(), avx2.pickSlice.data(),
                          scalar.pickSlice.size() * sizeof(float)) == 0);
        CHECK(scalar.stats.voxelsHidden == avx2.stats.voxelsHidden);
    }
}

TEST_CASE("plain transfer-function DVR and MIP converge to the reference") {
    // Marschner-Lobb 32^3, oblique view, 64 x 64: measured RMSE 0.012 (DVR) and 0.008 (MIP),
    // mostly along the slanted silhouette, which the intermediate image resolves to one voxel.
    auto grid = makeMarschnerLobb(32);
    const TransferFunction1D tf = smoothColourRamp();
    const ShearWarpView view = orthoView(64, 1.8, 0.5, 0.3);
    ShearWarpRenderer renderer;
    std::vector<ShearWarpObject> objects{objectOf(*grid, tf)};

    RayCastOptions options;
    options.tolerance = 1e-3;
    const Image dvrReference = ReferenceRayCaster(options)
                                   .render(referenceScene(view, *grid, tf, VolumeRenderMode::DVR))
                                   .image;
    const ShearWarpFrame dvr = renderer.render(objects, view);
    const double dvrError = rmse(dvr.image, dvrReference);
    MESSAGE("DVR RMSE versus the reference: " << dvrError);
    CHECK(dvrError < 0.02);

    objects[0].compositing = ObjectCompositing::MIP;
    objects[0].tableKey = 2;
    const Image mipReference = ReferenceRayCaster(options)
                                   .render(referenceScene(view, *grid, tf, VolumeRenderMode::MIP))
                                   .image;
    const ShearWarpFrame mip = renderer.render(objects, view);
    const double mipError = rmse(mip.image, mipReference);
    MESSAGE("MIP RMSE versus the reference: " << mipError);
    CHECK(mipError < 0.02);
}

TEST_CASE("anisotropic spacing folded into the factorisation matches the reference") {
    // The chest CT's kind of spacing (1.40625, 1.40625, 2.5), on a soft sphere 32 x 32 x 18,
    // with a model matrix that rotates and moves it.
    auto grid = VolumeGrid::create({32, 32, 18}, VoxelType::UByte, {1.40625, 1.40625, 2.5});
    auto ball = makeSoftSphere(32);
    for (int k = 0; k < 18; ++k)
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 32; ++i)
                grid->setValue(i, j, k, ball->value(i, j, 7 + k));
    TransferFunction1D tf = constantTf({0.9f, 0.7f, 0.4f}, 0.0);
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}, {1.0, 0.3}});
    ShearWarpView view = orthoView(64, 30.0, 0.7, -0.4);
    // Far enough that the whole box (half-diagonal 39) is in front of the camera.
    view.modelView = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -90.0)) * view.modelView *
                     glm::translate(glm::dmat4(1.0), glm::dvec3(2.0, -1.0, 0.5));
    std::vector<ShearWarpObject> objects{objectOf(*grid, tf)};
    ShearWarpRenderer renderer;
    const ShearWarpFrame f = renderer.render(objects, view);
    RayCastScene scene = referenceScene(view, *grid, tf, VolumeRenderMode::DVR);
    RayCastOptions options;
    options.tolerance = 1e-3;
    const double error = rmse(f.image, ReferenceRayCaster(options).render(scene).image);
    MESSAGE("anisotropic RMSE versus the reference: " << error);
    CHECK(error < 0.006); // measured 0.0034
}

namespace {

/// A 16^3 grid with a solid 8^3 cube of 255 in the middle (zeros around it), seen face on.
ref_ptr<VolumeGrid> solidCube() {
    auto grid = makeConstant({16, 16, 16}, VoxelType::UByte, 0.0);
    for (int k = 4; k < 12; ++k)
        for (int j = 4; j < 12; ++j)
            for (int i = 4; i < 12; ++i)
                grid->setValue(i, j, k, 255.0);
    return grid;
}

ShearWarpObject cubeSurface(const VolumeGrid& grid, VoxelRenderMode mode) {
    TransferFunction1D tf; // colours: identity ramp (of the shading intensity); alpha = 1
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, 1.0}});
    ObjectSource threshold;
    threshold.kind = ObjectSource::Threshold;
    threshold.low = 128.0;
    threshold.high = 255.0;
    ShearWarpObject o = objectOf(grid, tf, threshold, VoxelSelection::Surface);
    o.unclipped.mode = mode;
    o.compositing = ObjectCompositing::Surface;
    return o;
}

} // namespace

TEST_CASE("shaded mode gives the Phong intensity of the face towards the viewer") {
    auto grid = solidCube();
    std::vector<ShearWarpObject> objects{cubeSurface(*grid, VoxelRenderMode::Shaded)};
    ShearWarpRenderer renderer;
    ShearWarpView view = orthoView(32, 16.0);
    // Headlight: n = l = h = +z, I = 0.15 + 0.65 + 0.2 = 1.
    glm::vec4 c = centre(renderer.render(objects, view));
    CHECK(c.a == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(c.r == doctest::Approx(1.0).epsilon(0.01));
    // Light 60 degrees off the normal: 0.15 + 0.65 cos 60 + 0.2 cos(30)^20 = 0.4863.
    view.lightDirection = glm::dvec3(std::sin(M_PI / 3), 0.0, std::cos(M_PI / 3));
    c = centre(renderer.render(objects, view));
    CHECK(c.r == doctest::Approx(0.4863).epsilon(0.03));
    CHECK(c.g == doctest::Approx(c.r).epsilon(1e-6));
}

namespace {

/// The boundary voxels of the ball v >= 0.3 of a 32^3 soft sphere (radius 0.7 * 14.4 = 10.08
/// voxels), whose smooth field gives radial gradients; seen at 2 pixels per voxel.
ShearWarpObject ballSurface(const VolumeGrid& grid, VoxelRenderMode mode) {
    TransferFunction1D tf; // grey ramp over the shading intensity
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, 1.0}});
    ShearWarpObject o =
        objectOf(grid, tf, {ObjectSource::Threshold, 0, 77.0, 255.0}, VoxelSelection::Surface);
    o.unclipped.mode = mode;
    return o;
}

} // namespace

TEST_CASE("contour mode is transparent face on and bright at the silhouette") {
    auto grid = makeSoftSphere(32);
    std::vector<ShearWarpObject> objects{ballSurface(*grid, VoxelRenderMode::Contour)};
    ShearWarpRenderer renderer;
    const ShearWarpFrame f = renderer.render(objects, orthoView(64, 16.0));
    // Centre: both walls face the viewer, contour (1 - |n.v|)^4 ~ 0: nearly transparent.
    CHECK(centre(f).a < 0.05f);
    // 9.75 voxels out on a ball of radius 10.08: |n.v| = 0.25, contour 0.75^4 = 0.32, twice.
    const glm::vec4 rim = f.image.at(32 + 19, 32);
    CHECK(rim.a > 0.3f);
    CHECK(rim.r / rim.a > 0.25f); // the contour intensity indexes the colour ramp
}

TEST_CASE("coloured contours draw the contour colour at the silhouette and Phong inside") {
    auto grid = makeSoftSphere(32);
    ShearWarpObject o = ballSurface(*grid, VoxelRenderMode::ColoredContour);
    o.compositing = ObjectCompositing::Surface;
    o.contourColor = glm::vec3(1.0f, 0.0f, 0.0f);
    o.contourSharpness = 1.0f; // contour where (1 - |n.v|) >= 0.5: beyond 60 degrees
    std::vector<ShearWarpObject> objects{o};
    ShearWarpRenderer renderer;
    const ShearWarpFrame f = renderer.render(objects, orthoView(64, 16.0));
    const glm::vec4 c = centre(f);
    CHECK(c.r == doctest::Approx(c.b).epsilon(0.02)); // grey: Phong, face on, intensity ~1
    CHECK(c.r > 0.9f);
    const glm::vec4 rim = f.image.at(32 + 19, 32); // |n.v| = 0.25: a contour
    REQUIRE(rim.a > 0.5f);                         // (the warp blends the silhouette's edge)
    CHECK(rim.r / rim.a > 0.9f);
    CHECK(rim.g / rim.a < 0.1f);
    const glm::vec4 between = f.image.at(32 + 8, 32); // 4.25 voxels out: |n.v| = 0.9, Phong
    CHECK(between.g == doctest::Approx(between.r).epsilon(0.02));
    CHECK(between.g == doctest::Approx(0.15 + 0.65 * 0.9 + 0.2 * std::pow(0.9, 20)).epsilon(0.05));
}

TEST_CASE("gradient-magnitude opacity follows the magnitude channel") {
    // A ramp along x has one gradient magnitude everywhere (the maximum: 4-bit code 15, weight
    // 1): the image equals the plain TF image. A constant volume has none: transparent.
    auto ramp = makeRamp({16, 16, 16}, VoxelType::UByte, 0, 0.0, 255.0);
    TransferFunction1D tf = constantTf(glm::vec3(0.2f, 0.9f, 0.4f), 0.2);
    ShearWarpObject plain = objectOf(*ramp, tf, {}, VoxelSelection::Gradient);
    ShearWarpRenderer renderer;
    std::vector<ShearWarpObject> objects{plain};
    // The ramp's border voxels have one-sided differences (the same slope): all voxels kept.
    REQUIRE(plain.object->voxelCount() == 16u * 16u * 16u);
    const ShearWarpFrame reference = renderer.render(objects, orthoView(32, 16.0, 0.2));
    objects[0].unclipped.mode = VoxelRenderMode::GradientOpacity;
    objects[0].tableKey = 2;
    const ShearWarpFrame weighted = renderer.render(objects, orthoView(32, 16.0, 0.2));
    CHECK(centre(weighted).a == doctest::Approx(centre(reference).a).epsilon(1e-6));
    CHECK(centre(weighted).a > 0.5f);

    auto flat = makeConstant({16, 16, 16}, VoxelType::UByte, 255.0);
    std::vector<ShearWarpObject> flatObjects{objectOf(*flat, tf)};
    flatObjects[0].unclipped.mode = VoxelRenderMode::GradientOpacity;
    CHECK(centre(renderer.render(flatObjects, orthoView(32, 16.0))).a == 0.0f);
}

TEST_CASE("two-level compositing puts a MIP object over a DVR object") {
    // 8 x 8 x 16 along z: k < 8 is tag 2 (DVR, blue, alpha 0.1 per voxel), k >= 8 is tag 1
    // (MIP, red, alpha = v) with values 100 except one voxel column value 200 at k = 12.
    auto grid = makeConstant({8, 8, 16}, VoxelType::UByte, 100.0);
    auto tags = makeConstant({8, 8, 16}, VoxelType::UByte, 1.0);
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) {
                tags->setValue(i, j, k, 2.0);
                grid->setValue(i, j, k, 255.0);
            }
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i)
            grid->setValue(i, j, 12, 200.0);
    TransferFunction1D red = constantTf({1.0f, 0.0f, 0.0f}, 0.0);
    red.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}, {1.0, 1.0}});
    const TransferFunction1D blue = constantTf({0.0f, 0.0f, 1.0f}, 0.1);
    ObjectSource tag1{ObjectSource::Tag, 1}, tag2{ObjectSource::Tag, 2};
    std::vector<ShearWarpObject> objects{
        objectOf(*grid, red, tag1, VoxelSelection::Visible, tags.get()),
        objectOf(*grid, blue, tag2, VoxelSelection::Visible, tags.get())};
    objects[0].compositing = ObjectCompositing::MIP;
    ShearWarpRenderer renderer;
    ShearWarpView view = orthoView(16, 8.0); // straight down z: no shear, exact weights
    const double m = 200.0 / 255.0, d = 1.0 - std::pow(0.9, 8);
    ShearWarpFrame f = renderer.render(objects, view);
    CHECK_FALSE(f.stats.fastPath);
    glm::vec4 c = centre(f);
    CHECK(c.r == doctest::Approx(m).epsilon(1e-3)); // C(vmax) A(vmax), C = 1, A(v) = v
    CHECK(c.b == doctest::Approx((1.0 - m) * d).epsilon(1e-3));
    CHECK(c.a == doctest::Approx(m + (1.0 - m) * d).epsilon(1e-3));

    view.interObject = InterObjectCompositing::MIP; // per-channel maximum of the two layers
    c = centre(renderer.render(objects, view));
    CHECK(c.r == doctest::Approx(m).epsilon(1e-3));
    CHECK(c.b == doctest::Approx(d).epsilon(1e-3));
    CHECK(c.a == doctest::Approx(std::max(m, d)).epsilon(1e-3));
}

TEST_CASE("clipped voxels are drawn with their own opacity and mode") {
    const int n = 16;
    auto grid = makeConstant({n, n, n}, VoxelType::UByte, 255.0);
    const double a = 0.1;
    std::vector<ShearWarpObject> objects{objectOf(*grid, constantTf(glm::vec3(1.0f), a))};
    objects[0].clipPlanes = {glm::dvec4(1.0, 0.0, 0.0, 0.0)}; // keep x >= 0
    objects[0].clipKey = 7;
    ShearWarpRenderer renderer;
    const ShearWarpView view = orthoView(32, 16.0);
    ShearWarpFrame f = renderer.render(objects, view);
    const double full = 1.0 - std::pow(1.0 - a, n);
    CHECK(f.image.at(11, 16).a == 0.0f);                                // clipped: removed
    CHECK(f.image.at(20, 16).a == doctest::Approx(full).epsilon(1e-3)); // kept
    // Clipped part at half opacity (extinction halved) and drawn by its own mode.
    objects[0].clipped = {VoxelRenderMode::TF, 0.5f};
    objects[0].tableKey = 2;
    f = renderer.render(objects, view);
    CHECK(f.image.at(11, 16).a == doctest::Approx(1.0 - std::pow(1.0 - a, 0.5 * n)).epsilon(1e-3));
    CHECK(f.image.at(20, 16).a == doctest::Approx(full).epsilon(1e-3));
    objects[0].clipped = {VoxelRenderMode::GradientOpacity, 1.0f}; // no gradient: transparent
    objects[0].tableKey = 3;
    f = renderer.render(objects, view);
    CHECK(f.image.at(11, 16).a == 0.0f);
    CHECK(f.image.at(20, 16).a == doctest::Approx(full).epsilon(1e-3));
}

TEST_CASE("the optimizer never changes the image and cuts the voxels touched") {
    auto grid = makeSoftSphere(32);
    TransferFunction1D wide; // extraction: every voxel with v > 0
    ShearWarpObject o = objectOf(*grid, wide);
    // Now only v > 0.5 is visible: half the list cannot contribute.
    o.transferFunction.setChannel(TransferFunction1D::Alpha, {{0.5, 0.0}, {1.0, 0.3}});
    o.clipPlanes = {glm::dvec4(0.0, 1.0, 0.0, -4.0)};
    o.clipKey = 5;
    o.clipped = {VoxelRenderMode::TF, 0.4f};
    std::vector<ShearWarpObject> objects{o};
    ShearWarpRenderer renderer;
    const ShearWarpView view = orthoView(48, 16.0, 0.4, 0.2);
    const ShearWarpFrame before = renderer.render(objects, view);
    RenderList& list = o.object->renderList(before.stats.principalAxis);
    CHECK(VoxelListOptimizer::pendingEntries(list) > 0u);
    {
        VoxelListOptimizer optimizer; // the background thread
        optimizer.schedule({{o.object, before.stats.principalAxis}});
        optimizer.waitUntilIdle();
    }
    CHECK(VoxelListOptimizer::pendingEntries(list) == 0u);
    const ShearWarpFrame after = renderer.render(objects, view);
    CHECK(after.image.pixels == before.image.pixels);
    MESSAGE("voxels touched: " << before.stats.voxelsTouched << " before, "
                               << after.stats.voxelsTouched << " after optimizing");
    CHECK(after.stats.voxelsTouched < before.stats.voxelsTouched * 3 / 4);
    // A table change marks entries for re-optimisation and still draws the same image.
    objects[0].transferFunction.setChannel(TransferFunction1D::Alpha, {{0.2, 0.0}, {1.0, 0.3}});
    objects[0].tableKey = 9;
    const ShearWarpFrame changed = renderer.render(objects, view);
    CHECK(VoxelListOptimizer::pendingEntries(list) > 0u);
    while (VoxelListOptimizer::optimize(list, 5) > 0) {
    }
    CHECK(renderer.render(objects, view).image.pixels == changed.image.pixels);
}

TEST_CASE("opaque depth hides the voxels behind it") {
    const int n = 16;
    auto grid = makeConstant({n, n, n}, VoxelType::UByte, 255.0);
    const double a = 0.1;
    std::vector<ShearWarpObject> objects{objectOf(*grid, constantTf(glm::vec3(1.0f), a))};
    ShearWarpRenderer renderer;
    ShearWarpView view = orthoView(32, 16.0);
    // An opaque plane through the cube's centre (eye z = -10): window depth of z = -10 in
    // ortho(1, 20): (10 - 1) / 19.
    view.opaqueWindowDepth.assign(32 * 32, 1.0f);
    for (int y = 0; y < 32; ++y)
        for (int x = 16; x < 32; ++x)
            view.opaqueWindowDepth[std::size_t(y * 32 + x)] = 9.0f / 19.0f;
    const ShearWarpFrame f = renderer.render(objects, view);
    CHECK(f.image.at(11, 16).a == doctest::Approx(1.0 - std::pow(1.0 - a, n)).epsilon(1e-3));
    CHECK(f.image.at(20, 16).a == doctest::Approx(1.0 - std::pow(1.0 - a, n / 2)).epsilon(1e-3));
}

TEST_CASE("a surface hit writes depth and picking returns the object and position") {
    auto grid = solidCube();
    std::vector<ShearWarpObject> objects{cubeSurface(*grid, VoxelRenderMode::Shaded)};
    ShearWarpRenderer renderer;
    const ShearWarpFrame f = renderer.render(objects, orthoView(32, 16.0));
    // The cube's front face voxels have centres at z = 3.5 (local): eye z = -6.5.
    const double expected = ((6.5 - 1.0) / 19.0);
    CHECK(f.windowDepth[16 * 32 + 16] == doctest::Approx(expected).epsilon(1e-4));
    CHECK(f.windowDepth[2 * 32 + 2] == 1.0f); // outside the cube
    const auto hit = ShearWarpRenderer::pick(f, 16, 16);
    REQUIRE(hit);
    CHECK(hit->object == 0);
    CHECK(hit->localPosition.z == doctest::Approx(3.5).epsilon(1e-6));
    CHECK(std::abs(hit->localPosition.x) < 1.0);
    CHECK_FALSE(ShearWarpRenderer::pick(f, 1, 1));
}

TEST_CASE("a slice step keeps the analytic opacity and cuts the voxels read in proportion") {
    // 16 slices of alpha 0.1: steps 2 and 4 draw 8 and 4 slices standing for 2 and 4 each,
    // so the opacity-corrected total is the same optical depth (float tables: 0.2% limit).
    const int n = 16;
    auto grid = makeConstant({n, n, n}, VoxelType::UByte, 255.0);
    const double a = 0.1;
    std::vector<ShearWarpObject> objects{objectOf(*grid, constantTf({1.0f, 0.5f, 0.25f}, a))};
    ShearWarpRenderer renderer;
    for (double angle : {0.0, 0.4}) {
        ShearWarpView view = orthoView(64, 16.0, angle);
        const ShearWarpFrame full = renderer.render(objects, view);
        const double expected = 1.0 - std::pow(1.0 - a, n / std::cos(angle));
        for (int step : {2, 4}) {
            view.sliceStep = step;
            const ShearWarpFrame f = renderer.render(objects, view);
            CHECK(f.stats.sliceStep == step);
            CHECK(centre(f).a == doctest::Approx(expected).epsilon(0.002));
            CHECK(centre(f).r == doctest::Approx(expected).epsilon(0.002));
            CHECK(f.stats.voxelsTouched * std::uint64_t(step) == full.stats.voxelsTouched);
        }
    }
    ShearWarpView view = orthoView(16, 16.0);
    view.sliceStep = 1000; // clamped to the slice count: one slice for the whole depth
    const ShearWarpFrame one = renderer.render(objects, view);
    CHECK(one.stats.sliceStep == n);
    CHECK(centre(one).a == doctest::Approx(1.0 - std::pow(1.0 - a, n)).epsilon(0.002));
}

TEST_CASE("a slice step of 2 stays near the reference on a smooth volume, MIP included") {
    // Marschner-Lobb 32^3 as in the convergence test. Limits: twice the error of every slice
    // plus 0.01 (measured in the messages).
    auto grid = makeMarschnerLobb(32);
    const TransferFunction1D tf = smoothColourRamp();
    ShearWarpView view = orthoView(64, 1.8, 0.5, 0.3);
    ShearWarpRenderer renderer;
    std::vector<ShearWarpObject> objects{objectOf(*grid, tf)};
    RayCastOptions options;
    options.tolerance = 1e-3;
    for (VolumeRenderMode mode : {VolumeRenderMode::DVR, VolumeRenderMode::MIP}) {
        objects[0].compositing =
            mode == VolumeRenderMode::MIP ? ObjectCompositing::MIP : ObjectCompositing::DVR;
        objects[0].tableKey += 1;
        const Image reference =
            ReferenceRayCaster(options).render(referenceScene(view, *grid, tf, mode)).image;
        view.sliceStep = 1;
        const ShearWarpFrame full = renderer.render(objects, view);
        view.sliceStep = 2;
        const ShearWarpFrame half = renderer.render(objects, view);
        const double fullError = rmse(full.image, reference);
        const double halfError = rmse(half.image, reference);
        MESSAGE((mode == VolumeRenderMode::MIP ? "MIP" : "DVR")
                << " RMSE versus the reference, every slice " << fullError << ", every second "
                << halfError << ", between them " << rmse(full.image, half.image));
        CHECK(halfError < 2.0 * fullError + 0.01);
        CHECK(half.stats.voxelsTouched < full.stats.voxelsTouched * 6 / 10);
    }
}

TEST_CASE("thin layers keep every slice when the view skips slices") {
    // A SURFACE selection is a one-voxel shell: skipping slices would punch holes into it.
    auto grid = makeSoftSphere(32);
    TransferFunction1D tf = constantTf(glm::vec3(0.9f), 0.0);
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}, {0.5, 0.0}, {0.51, 0.6}, {1.0, 0.6}});
    std::vector<ShearWarpObject> objects{objectOf(*grid, tf, {}, VoxelSelection::Surface)};
    objects[0].thinLayer = true;
    ShearWarpRenderer renderer;
    ShearWarpView view = orthoView(64, 20.0, 0.3, 0.2);
    const ShearWarpFrame full = renderer.render(objects, view);
    view.sliceStep = 4;
    const ShearWarpFrame thin = renderer.render(objects, view);
    CHECK(thin.image.pixels == full.image.pixels);
    CHECK(thin.stats.voxelsTouched == full.stats.voxelsTouched);
    objects[0].thinLayer = false; // the control: skipping changes what the shell shows
    objects[0].tableKey += 1;
    const ShearWarpFrame skipped = renderer.render(objects, view);
    CHECK(skipped.stats.voxelsTouched < full.stats.voxelsTouched / 2);
    CHECK(rmse(skipped.image, full.image) > 0.01);
}

TEST_CASE("a recycled frame renders the same image, depth and picks as a fresh one") {
    auto grid = solidCube();
    std::vector<ShearWarpObject> objects{cubeSurface(*grid, VoxelRenderMode::Shaded)};
    ShearWarpRenderer fresh, recycling;
    // Views whose drawn rectangles differ (zoomed in, then out), so stale pixels would show.
    const ShearWarpView views[] = {orthoView(32, 8.0, 0.3), orthoView(32, 16.0, 0.9, 0.2),
                                   orthoView(32, 12.0, -0.4), orthoView(24, 16.0)};
    ShearWarpFrame last;
    for (const ShearWarpView& view : views) {
        const ShearWarpFrame expected = fresh.render(objects, view);
        recycling.recycle(std::move(last));
        last = recycling.render(objects, view);
        CHECK(last.image.pixels == expected.image.pixels); // bit for bit
        CHECK(last.windowDepth == expected.windowDepth);   // bit for bit
        CHECK(last.pickObject == expected.pickObject);
        CHECK(last.drawn == expected.drawn);
    }
    CHECK(last.wroteDepth);
}

TEST_CASE(
    "a recycled DVR frame (the vector warp, stale pixels cleared by it) matches a fresh one") {
    // Without depth the warp takes four pixels a step and clears what the last frame drew only
    // where it does not write: zoomed in, out, turned, then smaller.
    auto grid = makeMarschnerLobb(24);
    std::vector<ShearWarpObject> objects{objectOf(*grid, smoothColourRamp())};
    ShearWarpRenderer fresh, recycling;
    const ShearWarpView views[] = {orthoView(40, 1.2, 0.3), orthoView(40, 3.0, 0.9, 0.2),
                                   orthoView(40, 2.0, -0.4), orthoView(40, 1.0, 1.3, -0.5)};
    ShearWarpFrame last;
    for (const ShearWarpView& view : views) {
        const ShearWarpFrame expected = fresh.render(objects, view);
        recycling.recycle(std::move(last));
        last = recycling.render(objects, view);
        REQUIRE(last.image.pixels.size() == expected.image.pixels.size());
        CHECK(std::memcmp(last.image.pixels.data(), expected.image.pixels.data(),
                          last.image.pixels.size() * sizeof(glm::vec4)) == 0);
        CHECK(last.drawn == expected.drawn);
        CHECK_FALSE(last.wroteDepth);
    }
}

TEST_CASE("pure MIP takes the value-sorted path, close to the general path and the reference") {
    // RTVR 3.4: voxels sorted by value, drawn lowest first onto their nearest intermediate
    // pixel, each overwriting it. The general path resamples each slice bilinearly; nearest
    // pixels cost a little accuracy (measured: RMSE 0.0087 against 0.0081 here).
    auto grid = makeMarschnerLobb(32);
    const TransferFunction1D tf = smoothColourRamp();
    ShearWarpView view = orthoView(64, 1.8, 0.5, 0.3);
    view.interObject = InterObjectCompositing::MIP;
    std::vector<ShearWarpObject> objects{objectOf(*grid, tf)};
    objects[0].compositing = ObjectCompositing::MIP;
    RayCastOptions options;
    options.tolerance = 1e-3;
    const Image reference = ReferenceRayCaster(options)
                                .render(referenceScene(view, *grid, tf, VolumeRenderMode::MIP))
                                .image;
    ShearWarpRenderer renderer;
    const ShearWarpFrame sorted = renderer.render(objects, view);
    view.valueSortedMip = false;
    const ShearWarpFrame general = renderer.render(objects, view);
    view.valueSortedMip = true;
    const double sortedError = rmse(sorted.image, reference);
    const double generalError = rmse(general.image, reference);
    MESSAGE("MIP RMSE versus the reference: value-sorted " << sortedError << ", general "
                                                           << generalError);
    CHECK(sorted.stats.valueSortedMip);
    CHECK_FALSE(general.stats.valueSortedMip);
    CHECK(sortedError < 0.02);
    CHECK(sortedError < 1.25 * generalError + 0.002);
    CHECK(rmse(sorted.image, general.image) < 0.01);
    CHECK(sorted.stats.voxelsTouched == objects[0].object->voxelCount());

    // Threads take runs of the order into their own buffers: the image does not depend on
    // how many.
    view.threads = 1;
    const ShearWarpFrame one = renderer.render(objects, view);
    view.threads = 3;
    const ShearWarpFrame three = renderer.render(objects, view);
    CHECK(one.image.pixels == three.image.pixels);
    CHECK(one.image.pixels == sorted.image.pixels);
    view.threads = 0;

    // Picking: the pixel's maximum, in front of nothing else.
    int x = 0, y = 0;
    for (int py = 0; py < 64; ++py)
        for (int px = 0; px < 64; ++px)
            if (sorted.image.at(px, py).a > sorted.image.at(x, y).a) {
                x = px;
                y = py;
            }
    const auto hit = ShearWarpRenderer::pick(sorted, x, y);
    REQUIRE(hit);
    CHECK(hit->object == 0);
    CHECK(glm::length(hit->localPosition) < 20.0);
}

TEST_CASE("the value-sorted MIP reads no value below the first one the table shows") {
    auto grid = makeMarschnerLobb(24);
    std::vector<ShearWarpObject> objects{objectOf(*grid, smoothColourRamp())};
    objects[0].compositing = ObjectCompositing::MIP;
    // Extracted under a table that shows every value; drawn under one hiding v < 0.5.
    objects[0].transferFunction.setChannel(TransferFunction1D::Alpha,
                                           {{0.0, 0.0}, {0.5, 0.0}, {0.51, 0.3}, {1.0, 0.6}});
    objects[0].tableKey = 2;
    ShearWarpRenderer renderer;
    const ShearWarpView view = orthoView(48, 1.8, 0.7, 0.4);
    const ShearWarpFrame sorted = renderer.render(objects, view);
    // The same object extracted under the hiding table holds only the voxels shown: leaving
    // the others out while drawing must give the same image.
    std::vector<ShearWarpObject> shownOnly{objectOf(*grid, objects[0].transferFunction)};
    shownOnly[0].compositing = ObjectCompositing::MIP;
    ShearWarpRenderer other;
    const ShearWarpFrame reduced = other.render(shownOnly, view);
    // The first 12-bit value whose alpha is above 0, and how many voxels reach it.
    int firstShown = 0;
    while (!(objects[0].transferFunction.evaluate(TransferFunction1D::Alpha,
                                                  double(firstShown) / 4095.0) > 0.0))
        ++firstShown;
    const VoxelObject::Arrays arrays = objects[0].object->arrays();
    const auto reaching =
        std::uint64_t(std::count_if(arrays.value12.begin(), arrays.value12.end(),
                                    [&](std::uint16_t v) { return int(v) >= firstShown; }));
    MESSAGE(reaching << " of " << arrays.value12.size() << " voxels at or above the first shown");
    CHECK(sorted.stats.valueSortedMip);
    CHECK(sorted.stats.voxelsTouched == reaching);
    CHECK(reaching < arrays.value12.size() * 3 / 4);
    CHECK(shownOnly[0].object->voxelCount() <= reaching);
    CHECK(reduced.image.pixels == sorted.image.pixels);
}

TEST_CASE("only pure MIP scenes without clipping take the value-sorted path") {
    auto grid = makeMarschnerLobb(24);
    const TransferFunction1D tf = smoothColourRamp();
    ShearWarpObject low = objectOf(*grid, tf, ObjectSource{ObjectSource::Threshold, 0, 0, 127});
    ShearWarpObject high = objectOf(*grid, tf, ObjectSource{ObjectSource::Threshold, 0, 128, 255});
    low.compositing = high.compositing = ObjectCompositing::MIP;
    ShearWarpRenderer renderer;
    ShearWarpView view = orthoView(48, 1.8, 0.7, 0.4);
    view.interObject = InterObjectCompositing::MIP;

    std::vector<ShearWarpObject> objects{low, high};
    const ShearWarpFrame two = renderer.render(objects, view);
    CHECK(two.stats.valueSortedMip);
    view.valueSortedMip = false;
    const ShearWarpFrame twoGeneral = renderer.render(objects, view);
    view.valueSortedMip = true;
    CHECK(rmse(two.image, twoGeneral.image) < 0.01);

    view.interObject = InterObjectCompositing::DVR; // two objects, DVR between them
    CHECK_FALSE(renderer.render(objects, view).stats.valueSortedMip);
    view.interObject = InterObjectCompositing::MIP;

    objects[1].compositing = ObjectCompositing::DVR; // a DVR object in the scene
    CHECK_FALSE(renderer.render(objects, view).stats.valueSortedMip);
    objects[1].compositing = ObjectCompositing::MIP;

    objects[0].clipPlanes = {glm::dvec4(1.0, 0.0, 0.0, 0.0)}; // half of it clipped
    objects[0].clipped.opacity = 1.0f;
    objects[0].clipKey = 1;
    CHECK_FALSE(renderer.render(objects, view).stats.valueSortedMip);
}
