// The reference ray caster's MIP, MINIP, AVERAGE, tags, non-finite voxels and its error bound.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include <volsg/reference/ReferenceRayCaster.h>
#include <volsg/volume/TestVolumes.h>

using namespace volsg;

namespace {

RayCastCamera orthoCamera(int w, int h, double halfWidth, glm::dvec3 eye = {0, 0, 10},
                          glm::dvec3 up = {0, 1, 0}) {
    RayCastCamera c;
    c.width = w;
    c.height = h;
    c.view = glm::lookAt(eye, glm::dvec3(0.0), up);
    const double halfHeight = halfWidth * h / w;
    c.projection = glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, 0.1, 100.0);
    return c;
}

TransferFunction1D constantTf(glm::dvec3 color, double alpha) {
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Red, {{0.0, color.r}});
    tf.setChannel(TransferFunction1D::Green, {{0.0, color.g}});
    tf.setChannel(TransferFunction1D::Blue, {{0.0, color.b}});
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, alpha}});
    return tf;
}

double tauOf(double A, double L0) {
    return -std::log(1.0 - A) / L0;
}

/// Identity TF: C(v) = (v, v, v), A(v) = v, so a projection pixel is v^2 + (1 - v) * behind.
double identityPixel(double v, double behind) {
    return v * v + (1.0 - v) * behind;
}

/// Float ramp v = z + 0.5 along z over 17 voxels of 1/16 (exactly k/16 at voxel k).
RayCastVolume zRamp(VolumeRenderMode mode) {
    RayCastVolume v;
    v.data = makeRamp({4, 4, 17}, VoxelType::Float, 2, 0.0, 1.0, glm::dvec3(1.0 / 16.0));
    v.mode = mode;
    return v;
}

} // namespace

TEST_CASE("MIP finds a known maximum at its pixel and the trilinear falloff beside it") {
    // 9^3 zeros with 200 at the centre voxel; 18x18 pixels of 0.5 voxel over the box. Pixel (9, 8)
    // looks down the line x = y = 0.25 voxels from the centre: 200 (1 - 0.25)^2 at best.
    auto grid = VolumeGrid::create(glm::ivec3(9), VoxelType::UByte);
    grid->setValue(4, 4, 4, 200.0);
    RayCastVolume v;
    v.data = grid;
    v.mode = VolumeRenderMode::MIP;
    RayCastScene scene;
    scene.camera = orthoCamera(18, 18, 4.5);
    scene.volumes.push_back(v);
    scene.behind.background = glm::dvec3(0.5);
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double peak = 200.0 / 255.0 * 0.75 * 0.75;
    CHECK(std::abs(r.image.at(9, 8).r - identityPixel(peak, 0.5)) <= 1e-6);
    CHECK(std::abs(r.image.at(9, 8).a - peak) <= 1e-6);
    const double farther = 200.0 / 255.0 * 0.75 * 0.25; // pixel (10, 8): x = 0.75
    CHECK(std::abs(r.image.at(10, 8).r - identityPixel(farther, 0.5)) <= 1e-6);
    CHECK(r.image.at(0, 0).r == doctest::Approx(0.5).epsilon(1e-7)); // v = 0: the background
    CHECK(r.image.at(0, 0).a == 0.0f);

    scene.camera = orthoCamera(9, 9, 4.5); // pixel (4, 4) looks through the voxel centre
    const RayCastResult centred = ReferenceRayCaster().render(scene);
    CHECK(std::abs(centred.image.at(4, 4).r - identityPixel(200.0 / 255.0, 0.5)) <= 1e-6);
}

TEST_CASE("MIP, MINIP and AVERAGE of a clipped ramp take the kept chord only") {
    // Keep z in [-0.2, 0.3]: v = z + 0.5 runs from 0.3 to 0.8; its mean is 0.55.
    const double behind = 0.25;
    struct Expect {
        VolumeRenderMode mode;
        double v;
    };
    for (const Expect& e :
         {Expect{VolumeRenderMode::MIP, 0.8}, Expect{VolumeRenderMode::MINIP, 0.3},
          Expect{VolumeRenderMode::AVERAGE, 0.55}}) {
        RayCastVolume v = zRamp(e.mode);
        v.clipPlanes = {{0, 0, 1, -0.2}, {0, 0, -1, -0.3}};
        RayCastScene scene;
        scene.camera = orthoCamera(4, 4, 0.125);
        scene.volumes.push_back(v);
        scene.behind.background = glm::dvec3(behind);
        const RayCastResult r = ReferenceRayCaster().render(scene);
        for (const glm::vec4& p : r.image.pixels) {
            CHECK(std::abs(p.r - identityPixel(e.v, behind)) <= 1e-6);
            CHECK(std::abs(p.a - e.v) <= 1e-6);
        }
    }
}

TEST_CASE("MIP, MINIP and AVERAGE of a whole ramp") {
    // Unclipped: v is 1 over the first 1/32, linear over 1, 0 over the last 1/32: mean 1/2.
    struct Expect {
        VolumeRenderMode mode;
        double v;
    };
    for (const Expect& e :
         {Expect{VolumeRenderMode::MIP, 1.0}, Expect{VolumeRenderMode::MINIP, 0.0},
          Expect{VolumeRenderMode::AVERAGE, 0.5}}) {
        RayCastScene scene;
        scene.camera = orthoCamera(2, 2, 0.125);
        scene.volumes.push_back(zRamp(e.mode));
        const RayCastResult r = ReferenceRayCaster().render(scene);
        for (const glm::vec4& p : r.image.pixels)
            CHECK(std::abs(p.a - e.v) <= 1e-6);
    }
}

TEST_CASE("BoxClip with zero opacity removes its region from MIP") {
    RayCastVolume v = zRamp(VolumeRenderMode::MIP);
    RayCastBoxClip clip; // removes z > 0.1: the maximum left is v(0.1) = 0.6
    clip.origin = {-1.0, -1.0, 0.1};
    clip.extent = {2.0, 2.0, 1.0};
    clip.insideOpacity = 0.0;
    clip.outsideOpacity = 1.0;
    v.boxClip = clip;
    RayCastScene scene;
    scene.camera = orthoCamera(2, 2, 0.125);
    scene.volumes.push_back(v);
    const RayCastResult r = ReferenceRayCaster().render(scene);
    for (const glm::vec4& p : r.image.pixels)
        CHECK(std::abs(p.a - 0.6) <= 1e-6);
}

TEST_CASE("tags select their own transfer functions") {
    // Constant data; tag 1 for x < 0 (red, A = 0.05), tag 2 for x > 0 (green, A = 0.1), no
    // default (identity: the data value 0 gives A = 0 elsewhere).
    const glm::dvec3 red(1, 0, 0), green(0, 1, 0);
    const double L0 = 1.0 / 16.0, tau1 = tauOf(0.05, L0), tau2 = tauOf(0.1, L0);
    RayCastVolume v;
    v.data = makeConstant(glm::ivec3(16), VoxelType::UByte, 0.0, glm::dvec3(L0));
    auto tags = VolumeGrid::create(glm::ivec3(16), VoxelType::UShort, glm::dvec3(L0));
    for (int k = 0; k < 16; ++k)
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 16; ++i)
                tags->setValue(i, j, k, i < 8 ? 1.0 : 2.0);
    v.tags = tags;
    v.transferFunctions[1] = constantTf(red, 0.05);
    v.transferFunctions[2] = constantTf(green, 0.1);

    RayCastScene scene; // along -Z: each ray stays in one tag
    scene.camera = orthoCamera(16, 16, 0.8);
    scene.volumes.push_back(v);
    RayCastResult r = ReferenceRayCaster().render(scene);
    const double T1 = std::exp(-tau1), T2 = std::exp(-tau2);
    CHECK(std::abs(r.image.at(4, 8).r - (1.0 - T1)) <= 1e-5);
    CHECK(std::abs(r.image.at(4, 8).g) <= 1e-7);
    CHECK(std::abs(r.image.at(11, 8).g - (1.0 - T2)) <= 1e-5);
    CHECK(std::abs(r.image.at(11, 8).r) <= 1e-7);

    // Along -X: 0.5 of tag 2 first, then 0.5 of tag 1; the cut is exactly the cell face x = 0.
    scene.camera = orthoCamera(4, 4, 0.4, {10, 0, 0});
    r = ReferenceRayCaster().render(scene);
    const double h1 = std::exp(-0.5 * tau1), h2 = std::exp(-0.5 * tau2);
    const glm::dvec3 want = green * (1.0 - h2) + h2 * red * (1.0 - h1);
    for (const glm::vec4& p : r.image.pixels) {
        CHECK(std::abs(p.r - want.r) <= 1e-5);
        CHECK(std::abs(p.g - want.g) <= 1e-5);
        CHECK(std::abs(p.a - (1.0 - h1 * h2)) <= 1e-5);
    }
}

TEST_CASE("voxels of a tag without a transfer function use the default") {
    auto l = makeLabelledVolume(16);
    RayCastVolume v;
    v.data = makeConstant(glm::ivec3(16), VoxelType::UByte, 0.0);
    v.tags = l.tags;
    v.transferFunctions[-1] = constantTf(glm::dvec3(0, 0, 1), 0.02);
    v.transferFunctions[1] = constantTf(glm::dvec3(1, 0, 0), 0.0); // tag 1 is invisible
    RayCastScene scene;
    scene.camera = orthoCamera(16, 16, 8.0);
    scene.volumes.push_back(v);
    const RayCastResult r = ReferenceRayCaster().render(scene);
    // The corner column (tags 3 and 0 only) has 16 voxels of the default: blue.
    CHECK(std::abs(r.image.at(0, 0).b - (1.0 - std::pow(0.98, 16.0))) <= 1e-5);
    CHECK(r.image.at(0, 0).r == 0.0f);
    // The centre column crosses the invisible tag-1 ball: less than 16 voxels absorb.
    CHECK(r.image.at(8, 8).a < r.image.at(0, 0).a - 1e-3);
    CHECK(r.image.at(8, 8).r == 0.0f);
}

TEST_CASE("NaN and infinite voxels map to the ends of the finite range") {
    // Float 8^3 of 0.5 with a finite minimum 0.2 and maximum 0.9; NaN at (1,1,3), +Inf at
    // (5,5,4), -Inf at (3,6,7). Pixel (px, py) looks down voxel column (px, 7 - py).
    auto g = makeConstant(glm::ivec3(8), VoxelType::Float, 0.5);
    g->setValue(6, 1, 0, 0.2);
    g->setValue(1, 6, 0, 0.9);
    g->setValue(1, 1, 3, std::numeric_limits<double>::quiet_NaN());
    g->setValue(5, 5, 4, std::numeric_limits<double>::infinity());
    g->setValue(3, 6, 7, -std::numeric_limits<double>::infinity());
    RayCastScene scene;
    scene.camera = orthoCamera(8, 8, 4.0);
    RayCastVolume v;
    v.data = g;
    v.mode = VolumeRenderMode::MIP;
    scene.volumes.push_back(v);
    RayCastResult r = ReferenceRayCaster().render(scene);
    CHECK(r.image.at(5, 2).a == doctest::Approx(1.0).epsilon(1e-7));       // +Inf -> 0.9 -> v = 1
    CHECK(r.image.at(0, 0).a == doctest::Approx(3.0 / 7.0).epsilon(1e-6)); // plain 0.5

    scene.volumes[0].mode = VolumeRenderMode::MINIP;
    r = ReferenceRayCaster().render(scene);
    CHECK(std::abs(r.image.at(1, 6).a) <= 1e-7); // NaN -> 0.2 -> v = 0
    CHECK(std::abs(r.image.at(3, 1).a) <= 1e-7); // -Inf -> 0.2 -> v = 0
    CHECK(r.image.at(0, 0).a == doctest::Approx(3.0 / 7.0).epsilon(1e-6));

    scene.volumes[0].mode = VolumeRenderMode::DVR;
    scene.camera = orthoCamera(16, 16, 4.0, {6, 7, 10}); // oblique: interpolates next to them
    r = ReferenceRayCaster().render(scene);
    for (const glm::vec4& p : r.image.pixels)
        for (int c = 0; c < 4; ++c)
            CHECK(std::isfinite(p[c]));
}

TEST_CASE("a MIP volume is a layer composited in depth order with a DVR volume") {
    // DVR box (red, A = 0.05) at z in [-0.5, 0.5]; a MIP ramp shifted to z in [1.5, 2.5] lies in
    // front: pixel = MIP layer over the DVR result.
    RayCastScene scene;
    scene.camera = orthoCamera(2, 2, 0.1);
    RayCastVolume box;
    box.data = makeConstant(glm::ivec3(16), VoxelType::UByte, 0.0, glm::dvec3(1.0 / 16.0));
    box.transferFunctions[-1] = constantTf(glm::dvec3(1, 0, 0), 0.05);
    RayCastVolume mip = zRamp(VolumeRenderMode::MIP);
    mip.clipPlanes = {{0, 0, -1, -2.3}}; // keep z <= 2.3: v max = 2.3 - 2 + 0.5 = 0.8
    mip.model = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 2.0));
    scene.volumes = {box, mip};
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double T = std::exp(-tauOf(0.05, 1.0 / 16.0));
    const double A = 0.8;
    for (const glm::vec4& p : r.image.pixels) {
        CHECK(std::abs(p.r - (0.8 * A + (1.0 - A) * (1.0 - T))) <= 1e-5);
        CHECK(std::abs(p.g - 0.8 * A) <= 1e-5);
        CHECK(std::abs(p.a - (1.0 - (1.0 - A) * T)) <= 1e-5);
    }
}

TEST_CASE("the step-halving check reaches a bound of 1e-4 that a much finer step confirms") {
    // Marschner-Lobb with a transfer function that has interior control points, seen obliquely.
    RayCastVolume v;
    v.data = makeMarschnerLobb(41, VoxelType::UByte);
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Red, {{0.0, 0.0}, {0.6, 1.0}});
    tf.setChannel(TransferFunction1D::Green, {{0.3, 0.2}, {1.0, 0.9}});
    tf.setChannel(TransferFunction1D::Blue, {{0.0, 1.0}, {1.0, 0.0}});
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}, {0.35, 0.0}, {0.6, 0.03}, {1.0, 0.1}});
    v.transferFunctions[-1] = tf;
    v.model = glm::rotate(glm::dmat4(1.0), 0.4, glm::normalize(glm::dvec3(1, 2, 0)));
    RayCastScene scene;
    scene.camera = orthoCamera(24, 24, 1.6, {2, 3, 8});
    scene.volumes.push_back(v);
    scene.behind.background = glm::dvec3(0.1, 0.2, 0.3);
    const RayCastResult r = ReferenceRayCaster().render(scene);
    CHECK(r.converged);
    CHECK(r.errorBound <= 1e-4);
    CHECK(r.errorBound > 1e-6); // the check really compared something
    CHECK(r.maxHalvingsUsed >= 2);

    RayCastOptions fine;
    fine.adaptive = false;
    fine.step = v.data->smallestSpacing() / 128.0;
    const RayCastResult reference = ReferenceRayCaster(fine).render(scene);
    CHECK(std::isinf(reference.errorBound));
    double worst = 0.0, strongest = 0.0;
    for (std::size_t i = 0; i < r.image.pixels.size(); ++i) {
        const glm::vec4 d = glm::abs(r.image.pixels[i] - reference.image.pixels[i]);
        worst = std::max({worst, double(d.r), double(d.g), double(d.b), double(d.a)});
        strongest = std::max(strongest, double(reference.image.pixels[i].a));
    }
    CHECK(strongest > 0.2);       // the volume is visible
    CHECK(worst <= r.errorBound); // the reported bound holds
}

TEST_CASE("a jump in the transfer function is integrated exactly") {
    // Ramp v = z + 0.5 along the ray; alpha jumps from 0 to 0.1 at v = 0.53 (duplicate control
    // points), in the middle of a cell. Only z >= 0.03 absorbs: 0.47 of the linear part plus the
    // constant 1/32 at the top.
    RayCastVolume v = zRamp(VolumeRenderMode::DVR);
    TransferFunction1D tf = constantTf(glm::dvec3(1.0), 0.0);
    tf.setChannel(TransferFunction1D::Alpha, {{0.53, 0.0}, {0.53, 0.1}});
    v.transferFunctions[-1] = tf;
    RayCastScene scene;
    scene.camera = orthoCamera(4, 4, 0.125);
    scene.volumes.push_back(v);
    RayCastResult r = ReferenceRayCaster().render(scene);
    const double T = std::exp(-tauOf(0.1, 1.0 / 16.0) * (0.47 + 1.0 / 32.0));
    for (const glm::vec4& p : r.image.pixels)
        CHECK(std::abs(p.a - (1.0 - T)) <= 1e-5);
    CHECK(r.errorBound <= 1e-4);

    // An empty data range is a step at lo: dataRange 0.53 0.53 gives v = 1 where d >= 0.53.
    TransferFunction1D stepRange = constantTf(glm::dvec3(1.0), 0.0);
    stepRange.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}, {1.0, 0.1}});
    stepRange.setDataRange(0.53, 0.53);
    scene.volumes[0].transferFunctions[-1] = stepRange;
    r = ReferenceRayCaster().render(scene);
    for (const glm::vec4& p : r.image.pixels)
        CHECK(std::abs(p.a - (1.0 - T)) <= 1e-5);
}

TEST_CASE("the image does not depend on the thread count") {
    RayCastVolume v;
    v.data = makeSoftSphere(24, VoxelType::UByte);
    RayCastScene scene;
    scene.camera = orthoCamera(20, 20, 14.0, {3, 4, 30});
    scene.volumes.push_back(v);
    RayCastOptions one, two;
    one.threads = 1;
    two.threads = 2;
    const RayCastResult a = ReferenceRayCaster(one).render(scene);
    const RayCastResult b = ReferenceRayCaster(two).render(scene);
    CHECK(std::memcmp(a.image.pixels.data(), b.image.pixels.data(),
                      a.image.pixels.size() * sizeof(glm::vec4)) == 0);
    CHECK(a.errorBound == b.errorBound);
}

TEST_CASE("empty-space skipping agrees with marching through every brick") {
    // Opacity only above v = 0.5: most bricks of the soft sphere are skipped with 4-voxel bricks
    // and none with one brick over the whole volume.
    RayCastVolume v;
    v.data = makeSoftSphere(32, VoxelType::UByte);
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Alpha, {{0.5, 0.0}, {1.0, 0.2}});
    v.transferFunctions[-1] = tf;
    RayCastScene scene;
    scene.camera = orthoCamera(24, 24, 18.0, {5, -3, 40});
    scene.volumes.push_back(v);
    RayCastOptions small, whole;
    small.brickSize = 4;
    whole.brickSize = 32;
    const RayCastResult a = ReferenceRayCaster(small).render(scene);
    const RayCastResult b = ReferenceRayCaster(whole).render(scene);
    double worst = 0.0, strongest = 0.0;
    for (std::size_t i = 0; i < a.image.pixels.size(); ++i) {
        const glm::vec4 d = glm::abs(a.image.pixels[i] - b.image.pixels[i]);
        worst = std::max({worst, double(d.r), double(d.g), double(d.b), double(d.a)});
        strongest = std::max(strongest, double(a.image.pixels[i].a));
    }
    CHECK(strongest > 0.1);
    CHECK(worst <= 1e-4);
}
