// The reference ray caster's DVR against closed forms of the emission-absorption integral.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include <volsg/core/Error.h>
#include <volsg/reference/ReferenceRayCaster.h>
#include <volsg/volume/TestVolumes.h>

using namespace volsg;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// An orthographic camera at `eye` looking at `target`, `halfWidth` world units each side.
RayCastCamera orthoCamera(int w, int h, double halfWidth, glm::dvec3 eye = {0, 0, 10},
                          glm::dvec3 target = {0, 0, 0}, glm::dvec3 up = {0, 1, 0}) {
    RayCastCamera c;
    c.width = w;
    c.height = h;
    c.view = glm::lookAt(eye, target, up);
    const double halfHeight = halfWidth * h / w;
    c.projection = glm::ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, 0.1, 100.0);
    return c;
}

RayCastCamera perspectiveCamera(int w, int h, double fovy, glm::dvec3 eye, glm::dvec3 target) {
    RayCastCamera c;
    c.width = w;
    c.height = h;
    c.view = glm::lookAt(eye, target, glm::dvec3(0, 1, 0));
    c.projection = glm::perspective(fovy, double(w) / h, 0.05, 100.0);
    return c;
}

/// World x (or y) of a pixel centre of an orthographic camera looking down -Z at the origin.
double pixelX(const RayCastCamera& c, double halfWidth, int x) {
    return -halfWidth + (x + 0.5) * 2.0 * halfWidth / c.width;
}
double pixelY(const RayCastCamera& c, double halfWidth, int y) {
    const double halfHeight = halfWidth * c.height / c.width;
    return halfHeight - (y + 0.5) * 2.0 * halfHeight / c.height;
}

/// Constant colour and opacity for every data value.
TransferFunction1D constantTf(glm::dvec3 color, double alpha) {
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Red, {{0.0, color.r}});
    tf.setChannel(TransferFunction1D::Green, {{0.0, color.g}});
    tf.setChannel(TransferFunction1D::Blue, {{0.0, color.b}});
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, alpha}});
    return tf;
}

/// A 16^3 constant volume filling [-0.5, 0.5]^3 (L0 = 1/16) with a constant TF.
RayCastVolume constantBox(glm::dvec3 color, double alpha, int n = 16) {
    RayCastVolume v;
    v.data = makeConstant(glm::ivec3(n), VoxelType::UByte, 100.0, glm::dvec3(1.0 / n));
    v.transferFunctions[-1] = constantTf(color, alpha);
    return v;
}

/// Extinction per unit length of opacity A over L0.
double tauOf(double A, double L0) {
    return -std::log(1.0 - A) / L0;
}

/// Parameter interval of a ray in the slab |n . p - c| <= half (n unit), intersected with `in`.
void clipToSlab(glm::dvec3 o, glm::dvec3 d, glm::dvec3 n, double centre, double half, double& t0,
                double& t1) {
    const double rate = glm::dot(n, d), at = glm::dot(n, o) - centre;
    if (rate == 0.0) {
        if (std::abs(at) > half) t1 = -kInf;
        return;
    }
    double a = (-half - at) / rate, b = (half - at) / rate;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
}

/// Chord of a ray through the cube of edge 1 centred at the origin with face normals (the
/// columns of) `axes`, counting only t >= tStart.
double cubeChord(glm::dvec3 o, glm::dvec3 d, const glm::dmat3& axes, double tStart = -kInf) {
    double t0 = tStart, t1 = kInf;
    for (int a = 0; a < 3; ++a)
        clipToSlab(o, d, axes[a], 0.0, 0.5, t0, t1);
    return std::max(0.0, t1 - t0);
}

glm::dvec3 rgb(const glm::vec4& p) {
    return glm::dvec3(p);
}

/// The pixel of a homogeneous segment sequence: each (C, tau, length) in ray order.
struct Segment {
    glm::dvec3 color;
    double tau;
    double length;
};
glm::dvec4 composite(std::initializer_list<Segment> segments, glm::dvec3 behind) {
    glm::dvec3 light(0.0);
    double T = 1.0;
    for (const Segment& s : segments) {
        const double t = std::exp(-s.tau * s.length);
        light += T * s.color * (1.0 - t);
        T *= t;
    }
    return {light + T * behind, 1.0 - T};
}

void checkPixel(const glm::vec4& got, const glm::dvec4& want, double tolerance) {
    for (int c = 0; c < 4; ++c)
        CHECK(std::abs(double(got[c]) - want[c]) <= tolerance);
}

} // namespace

TEST_CASE("constant box transmittance is exp of minus tau times the chord") {
    const glm::dvec3 C(0.8, 0.4, 0.2), bg(0.1, 0.2, 0.3);
    RayCastScene scene;
    scene.camera = orthoCamera(32, 32, 0.8);
    scene.volumes.push_back(constantBox(C, 0.05));
    scene.behind.background = bg;
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double T = std::exp(-tauOf(0.05, 1.0 / 16.0) * 1.0);
    int inside = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const bool hit = std::abs(pixelX(scene.camera, 0.8, x)) < 0.5 &&
                             std::abs(pixelY(scene.camera, 0.8, y)) < 0.5;
            inside += hit;
            const glm::dvec4 want =
                hit ? glm::dvec4(C * (1.0 - T) + T * bg, 1.0 - T) : glm::dvec4(bg, 0.0);
            checkPixel(r.image.at(x, y), want, 1e-5);
        }
    CHECK(inside == 20 * 20);
    CHECK(r.errorBound <= 1e-4);
    CHECK(r.converged);
}

TEST_CASE("rotated constant box follows the geometric chord length") {
    const glm::dvec3 C(0.3, 0.9, 0.5);
    RayCastScene scene;
    scene.camera = orthoCamera(40, 40, 0.9);
    RayCastVolume v = constantBox(C, 0.05);
    const glm::dmat4 rotation = glm::rotate(glm::dmat4(1.0), 0.5, glm::dvec3(0, 1, 0)) *
                                glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(1, 0, 0));
    v.model = glm::translate(glm::dmat4(1.0), glm::dvec3(0.05, -0.02, 0.1)) * rotation;
    scene.volumes.push_back(v);
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double tau = tauOf(0.05, 1.0 / 16.0);
    const glm::dmat3 axes(rotation);
    int hits = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            // The ray in coordinates centred on the box (the translation moved it).
            const glm::dvec3 o(pixelX(scene.camera, 0.9, x) - 0.05,
                               pixelY(scene.camera, 0.9, y) + 0.02, 10.0 - 0.1);
            const double chord = cubeChord(o, {0, 0, -1}, axes);
            hits += chord > 0.0;
            const double T = std::exp(-tau * chord);
            checkPixel(r.image.at(x, y), glm::dvec4(C * (1.0 - T), 1.0 - T), 1e-5);
        }
    CHECK(hits > 400);
}

TEST_CASE("a pair of clip planes leaves a slab of known thickness") {
    const glm::dvec3 C(1.0, 0.5, 0.0), bg(0.2);
    RayCastScene scene;
    scene.camera = orthoCamera(24, 24, 0.6);
    RayCastVolume v = constantBox(C, 0.05);
    const glm::dvec3 n = glm::normalize(glm::dvec3(0.3, 0.0, 1.0));
    v.clipPlanes.push_back(glm::dvec4(n, -0.1));  // keep n.p >= -0.1
    v.clipPlanes.push_back(glm::dvec4(-n, -0.2)); // keep n.p <= 0.2
    scene.volumes.push_back(v);
    scene.behind.background = bg;
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double chord = 0.3 / n.z; // thickness 0.3 along n, crossed along -Z
    const double T = std::exp(-tauOf(0.05, 1.0 / 16.0) * chord);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            if (std::abs(pixelX(scene.camera, 0.6, x)) > 0.5 ||
                std::abs(pixelY(scene.camera, 0.6, y)) > 0.5)
                continue;
            checkPixel(r.image.at(x, y), glm::dvec4(C * (1.0 - T) + T * bg, 1.0 - T), 1e-5);
        }
}

TEST_CASE("linear ramp with linear opacity matches the closed-form optical depth") {
    // Float ramp 0..1 along z over 17 voxels of L0 = 1/16: the field is v = 1 on z in
    // [0.5, 17/32], v = z + 0.5 on [-0.5, 0.5] and 0 below. A(v) = alpha v, so
    // tau = -ln(1 - alpha v) / L0, and with w = 1 - alpha v an antiderivative of -ln(1 - alpha v)
    // is G(v) = (w ln w - w) / alpha. Optical depth:
    //   D = [ (1/32) (-ln(1 - alpha)) + G(1) - G(0) ] / L0.
    // A constant colour emits C (1 - T) whatever the shape of tau.
    const double alpha = 0.1, L0 = 1.0 / 16.0;
    const glm::dvec3 C(0.25, 0.5, 1.0), bg(0.5, 0.0, 0.25);
    RayCastVolume v;
    v.data = makeRamp({4, 4, 17}, VoxelType::Float, 2, 0.0, 1.0, glm::dvec3(L0));
    TransferFunction1D tf = constantTf(C, 0.0);
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, 0.0}, {1.0, alpha}});
    tf.setDataRange(0.0, 1.0);
    v.transferFunctions[-1] = tf;
    RayCastScene scene;
    scene.camera = orthoCamera(8, 8, 0.125);
    scene.volumes.push_back(v);
    scene.behind.background = bg;
    const RayCastResult r = ReferenceRayCaster().render(scene);

    auto G = [&](double x) {
        const double u = 1.0 - alpha * x;
        return (u * std::log(u) - u) / alpha;
    };
    const double D = (-std::log(1.0 - alpha) / 32.0 + (G(1.0) - G(0.0))) / L0;
    const double T = std::exp(-D);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            checkPixel(r.image.at(x, y), glm::dvec4(C * (1.0 - T) + T * bg, 1.0 - T), 1e-4);
    CHECK(r.errorBound <= 1e-4);
}

TEST_CASE("ramp with linear colour under constant opacity matches the closed form") {
    // tau constant; C(v) = (v, 1 - v, 0.5) and v falls linearly from 1 to 0 over length 1 between
    // two constant ends of 1/32. For C(s) = c0 + c1 s: integral_0^L C tau e^(-tau s) ds =
    // c0 (1 - e^(-tau L)) + c1 ((1 - e^(-tau L)) / tau - L e^(-tau L)).
    const double A = 0.05, L0 = 1.0 / 16.0, tau = tauOf(A, L0);
    RayCastVolume v;
    v.data = makeRamp({2, 2, 17}, VoxelType::Float, 2, 0.0, 1.0, glm::dvec3(L0));
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Red, {{0.0, 0.0}, {1.0, 1.0}});
    tf.setChannel(TransferFunction1D::Green, {{0.0, 1.0}, {1.0, 0.0}});
    tf.setChannel(TransferFunction1D::Blue, {{0.0, 0.5}});
    tf.setChannel(TransferFunction1D::Alpha, {{0.0, A}});
    v.transferFunctions[-1] = tf;
    RayCastScene scene;
    scene.camera = orthoCamera(4, 4, 0.0625);
    scene.volumes.push_back(v);
    const RayCastResult r = ReferenceRayCaster().render(scene);

    const glm::dvec3 c1(1.0, 0.0, 0.5), c0(0.0, 1.0, 0.5); // C(v = 1), C(v = 0)
    const double end = 1.0 / 32.0, eEnd = std::exp(-tau * end), eMid = std::exp(-tau);
    glm::dvec3 light = c1 * (1.0 - eEnd);
    light += eEnd * (c1 * (1.0 - eMid) + (c0 - c1) * ((1.0 - eMid) / tau - eMid));
    light += eEnd * eMid * c0 * (1.0 - eEnd);
    const double T = eEnd * eMid * eEnd;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            checkPixel(r.image.at(x, y), glm::dvec4(light, 1.0 - T), 1e-4);
}

TEST_CASE("plane opacity 0.5 halves tau and a depth ramp integrates to half") {
    const glm::dvec3 C(0.6, 0.6, 0.1);
    const double tau = tauOf(0.2, 1.0 / 16.0);
    for (const auto& curve : {std::vector<PiecewiseLinear::Point>{{0.0, 0.5}, {1.0, 0.5}},
                              std::vector<PiecewiseLinear::Point>{{0.0, 0.0}, {1.0, 1.0}}}) {
        RayCastScene scene;
        scene.camera = orthoCamera(8, 8, 0.4);
        RayCastVolume v = constantBox(C, 0.2);
        v.planeOpacity = curve;
        scene.volumes.push_back(v);
        const RayCastResult r = ReferenceRayCaster().render(scene);
        // Constant m = 0.5: depth 0.5 tau. m = t rising 0..1 across the chord: mean 0.5 too.
        const double T = std::exp(-0.5 * tau);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                checkPixel(r.image.at(x, y), glm::dvec4(C * (1.0 - T), 1.0 - T), 1e-5);
    }
}

TEST_CASE("plane opacity counts depth from the nearest to the farthest box corner") {
    // The unit box rotated 45 degrees about Y: corner depths span sqrt(2). m = 1 for t < 0.5, then
    // 0: only the front half of the depth range absorbs. The central ray meets the box at depth
    // 0 (t = 0) and leaves at sqrt(2) (t = 1): chord sqrt(2), absorbing part sqrt(2)/2.
    RayCastScene scene;
    scene.camera = orthoCamera(1, 1, 0.01);
    RayCastVolume v = constantBox(glm::dvec3(1.0), 0.05);
    v.model = glm::rotate(glm::dmat4(1.0), glm::radians(45.0), glm::dvec3(0, 1, 0));
    v.planeOpacity = {{0.0, 1.0}, {0.5, 1.0}, {0.5, 0.0}};
    scene.volumes.push_back(v);
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double T = std::exp(-tauOf(0.05, 1.0 / 16.0) * std::sqrt(2.0) / 2.0);
    CHECK(std::abs(r.image.at(0, 0).a - (1.0 - T)) <= 1e-5);
}

TEST_CASE("BoxClip inside and outside opacity split the chord") {
    const glm::dvec3 C(0.9, 0.1, 0.1), blue(0.0, 0.0, 1.0), bg(0.05);
    const double tau = tauOf(0.08, 1.0 / 16.0);
    RayCastScene scene;
    scene.camera = orthoCamera(32, 32, 0.8);
    RayCastVolume v = constantBox(C, 0.08);
    RayCastBoxClip clip;
    clip.origin = glm::dvec3(-0.25);
    clip.extent = glm::dvec3(0.5);
    clip.insideOpacity = 1.0;
    clip.outsideOpacity = 0.4;
    clip.insideColor = blue;
    clip.insideColorWeight = 0.5;
    v.boxClip = clip;
    scene.volumes.push_back(v);
    scene.behind.background = bg;
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const glm::dvec3 Cin = 0.5 * C + 0.5 * blue;
    const glm::dvec4 through =
        composite({{C, 0.4 * tau, 0.25}, {Cin, tau, 0.5}, {C, 0.4 * tau, 0.25}}, bg);
    const glm::dvec4 around = composite({{C, 0.4 * tau, 1.0}}, bg);
    int in = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const double px = std::abs(pixelX(scene.camera, 0.8, x));
            const double py = std::abs(pixelY(scene.camera, 0.8, y));
            if (px > 0.5 || py > 0.5) continue;
            const bool inBox = px < 0.25 && py < 0.25;
            in += inBox;
            checkPixel(r.image.at(x, y), inBox ? through : around, 1e-5);
        }
    CHECK(in == 10 * 10);
}

TEST_CASE("BoxClip with its own model matrix is placed in world coordinates") {
    RayCastScene scene;
    scene.camera = orthoCamera(32, 32, 0.8);
    RayCastVolume v = constantBox(glm::dvec3(1.0), 0.05);
    v.model = glm::translate(glm::dmat4(1.0), glm::dvec3(-0.3, 0.0, 0.0)); // volume x in [-.8,.2]
    RayCastBoxClip clip;
    clip.origin = glm::dvec3(-0.5);
    clip.extent = glm::dvec3(1.0);
    clip.model = glm::dmat4(1.0); // world [-0.5, 0.5]^3, not the volume's local box
    clip.insideOpacity = 1.0;
    clip.outsideOpacity = 0.0;
    v.boxClip = clip;
    scene.volumes.push_back(v);
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double T = std::exp(-tauOf(0.05, 1.0 / 16.0));
    for (int x = 0; x < 32; ++x) {
        const double wx = pixelX(scene.camera, 0.8, x);
        const bool visible = wx > -0.5 && wx < 0.2;
        CHECK(std::abs(r.image.at(x, 16).a - (visible ? 1.0 - T : 0.0)) <= 1e-5);
    }
}

TEST_CASE("perspective rays through a constant box follow their chords") {
    const glm::dvec3 C(0.2, 0.7, 0.9);
    const double fovy = glm::radians(40.0), tau = tauOf(0.05, 1.0 / 16.0);
    RayCastScene scene;
    scene.camera = perspectiveCamera(24, 16, fovy, {0, 0, 3}, {0, 0, 0});
    scene.volumes.push_back(constantBox(C, 0.05));
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double tanHalf = std::tan(0.5 * fovy), aspect = 24.0 / 16.0;
    int hits = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 24; ++x) {
            // The ray direction from the field of view, not from unprojecting.
            const double nx = (x + 0.5) / 24 * 2 - 1, ny = 1 - (y + 0.5) / 16 * 2;
            const glm::dvec3 d =
                glm::normalize(glm::dvec3(nx * tanHalf * aspect, ny * tanHalf, -1));
            const double chord = cubeChord({0, 0, 3}, d, glm::dmat3(1.0));
            hits += chord > 0.0;
            const double T = std::exp(-tau * chord);
            checkPixel(r.image.at(x, y), glm::dvec4(C * (1.0 - T), 1.0 - T), 1e-5);
        }
    CHECK(hits > 50);
}

TEST_CASE("a camera inside the volume sees only what lies in front of it") {
    const double fovy = glm::radians(60.0), tau = tauOf(0.05, 1.0 / 16.0);
    RayCastScene scene;
    scene.camera = perspectiveCamera(16, 16, fovy, {0, 0, 0.2}, {0, 0, -1});
    scene.volumes.push_back(constantBox(glm::dvec3(1.0), 0.05));
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double tanHalf = std::tan(0.5 * fovy);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const double nx = (x + 0.5) / 16 * 2 - 1, ny = 1 - (y + 0.5) / 16 * 2;
            const glm::dvec3 d = glm::normalize(glm::dvec3(nx * tanHalf, ny * tanHalf, -1));
            const double chord = cubeChord({0, 0, 0.2}, d, glm::dmat3(1.0), 0.0);
            CHECK(chord >= 0.7 - 1e-12); // at least the 0.7 straight ahead
            CHECK(std::abs(r.image.at(x, y).a - (1.0 - std::exp(-tau * chord))) <= 1e-5);
        }
}

TEST_CASE("a volume entirely behind the camera contributes nothing") {
    const glm::dvec3 bg(0.3, 0.2, 0.1);
    RayCastScene scene;
    scene.camera = perspectiveCamera(16, 16, glm::radians(60.0), {0, 0, -2}, {0, 0, -10});
    scene.volumes.push_back(constantBox(glm::dvec3(1.0), 0.5));
    scene.behind.background = bg;
    RayCastScene ortho = scene;
    ortho.camera = orthoCamera(16, 16, 1.0, {0, 0, -2}, {0, 0, -10});
    for (const RayCastScene* s : {&scene, &ortho}) {
        const RayCastResult r = ReferenceRayCaster().render(*s);
        for (const glm::vec4& p : r.image.pixels) {
            CHECK(p.a == 0.0f);
            CHECK(rgb(p) == glm::dvec3(glm::vec3(bg)));
        }
    }
}

TEST_CASE("anisotropic spacing uses the smallest spacing as L0 and local chords") {
    // 8^3 voxels of (1, 1.5, 2.5): box 8 x 12 x 20, L0 = 1, so T = (1 - A)^chord.
    const double A = 0.02;
    RayCastVolume v;
    v.data = makeConstant(glm::ivec3(8), VoxelType::UByte, 50.0, {1.0, 1.5, 2.5});
    v.transferFunctions[-1] = constantTf(glm::dvec3(1.0), A);
    struct View {
        glm::dvec3 eye, up;
        double chord;
    };
    for (const View& view : {View{{0, 0, 50}, {0, 1, 0}, 20.0}, View{{50, 0, 0}, {0, 1, 0}, 8.0},
                             View{{0, 50, 0}, {0, 0, 1}, 12.0}}) {
        RayCastScene scene;
        scene.camera = orthoCamera(4, 4, 1.0, view.eye, {0, 0, 0}, view.up);
        scene.volumes.push_back(v);
        const RayCastResult r = ReferenceRayCaster().render(scene);
        for (const glm::vec4& p : r.image.pixels)
            CHECK(std::abs(p.a - (1.0 - std::pow(1.0 - A, view.chord))) <= 1e-5);
    }
}

TEST_CASE("scaling the model does not change the optical depth in local units") {
    const double A = 0.02;
    RayCastVolume v;
    v.data = makeConstant(glm::ivec3(8), VoxelType::UByte, 50.0, {1.0, 1.5, 2.5});
    v.transferFunctions[-1] = constantTf(glm::dvec3(1.0), A);
    v.model = glm::scale(glm::dmat4(1.0), glm::dvec3(0.1, 0.1, 0.05)); // world box 0.8 x 1.2 x 1
    RayCastScene scene;
    scene.camera = orthoCamera(4, 4, 0.2);
    scene.volumes.push_back(v);
    const RayCastResult r = ReferenceRayCaster().render(scene);
    for (const glm::vec4& p : r.image.pixels)
        CHECK(std::abs(p.a - (1.0 - std::pow(1.0 - A, 20.0))) <= 1e-5);
}

TEST_CASE("opacity near one is clamped to 1 - 1e-6 and stays finite") {
    // One voxel thick along the ray (chord = L0): T = 1 - min(A, 1 - 1e-6) = 1e-6 exactly.
    RayCastVolume thin;
    thin.data = makeConstant({8, 8, 1}, VoxelType::UByte, 7.0);
    thin.transferFunctions[-1] = constantTf(glm::dvec3(0.0), 1.0 - 1e-9);
    RayCastScene scene;
    scene.camera = orthoCamera(4, 4, 2.0);
    scene.volumes.push_back(thin);
    scene.behind.background = glm::dvec3(1.0);
    RayCastResult r = ReferenceRayCaster().render(scene);
    for (const glm::vec4& p : r.image.pixels)
        CHECK(std::abs(double(p.r) - 1e-6) <= 1e-12);

    // Sixteen voxels: the ray is opaque; the pixel is the colour, with no NaN or Inf.
    scene.volumes[0] = constantBox(glm::dvec3(0.25, 0.5, 0.75), 1.0 - 1e-9);
    scene.camera = orthoCamera(4, 4, 0.4);
    r = ReferenceRayCaster().render(scene);
    for (const glm::vec4& p : r.image.pixels) {
        CHECK(std::isfinite(p.r));
        checkPixel(p, glm::dvec4(0.25, 0.5, 0.75, 1.0), 1e-6);
    }
    scene.volumes[0] = constantBox(glm::dvec3(1.0), 1.0); // A = 1 exactly
    r = ReferenceRayCaster().render(scene);
    for (const glm::vec4& p : r.image.pixels)
        checkPixel(p, glm::dvec4(1.0), 1e-6);
}

TEST_CASE("tiny opacity gives the exact small absorption") {
    RayCastScene scene;
    scene.camera = orthoCamera(4, 4, 0.4);
    scene.volumes.push_back(constantBox(glm::dvec3(1.0), 1e-6));
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double absorbed = -std::expm1(16.0 * std::log1p(-1e-6)); // (1 - A)^(chord / L0)
    for (const glm::vec4& p : r.image.pixels) {
        CHECK(std::abs(double(p.r) / absorbed - 1.0) <= 1e-6);
        CHECK(std::abs(double(p.a) / absorbed - 1.0) <= 1e-5);
    }
}

TEST_CASE("1x1xN and Nx1x1 volumes render their closed forms") {
    // 1 x 1 x 16 column of 0.1 voxels: chord 1.6 = 16 L0 along Z.
    RayCastScene scene;
    RayCastVolume column;
    column.data = makeConstant({1, 1, 16}, VoxelType::UByte, 3.0, glm::dvec3(0.1));
    column.transferFunctions[-1] = constantTf(glm::dvec3(1.0), 0.05);
    scene.camera = orthoCamera(2, 2, 0.1);
    scene.volumes.push_back(column);
    RayCastResult r = ReferenceRayCaster().render(scene);
    for (const glm::vec4& p : r.image.pixels)
        CHECK(std::abs(p.a - (1.0 - std::pow(0.95, 16.0))) <= 1e-5);

    // 16 x 1 x 1 ramp (value 17 i, identity TF): rays along Z cross one voxel (chord = L0), so
    // 1 - T = A(v) = v, with v linear in x between the outermost centres and clamped beyond.
    RayCastVolume row;
    row.data = makeRamp({16, 1, 1}, VoxelType::UByte, 0, 0.0, 255.0, glm::dvec3(0.1));
    scene.camera = orthoCamera(32, 2, 0.8);
    scene.volumes[0] = row;
    r = ReferenceRayCaster().render(scene);
    for (int x = 0; x < 32; ++x) {
        const double u = std::clamp((pixelX(scene.camera, 0.8, x) + 0.8) / 0.1 - 0.5, 0.0, 15.0);
        const double v = u / 15.0;
        CHECK(std::abs(r.image.at(x, 0).a - v) <= 1e-5);
        CHECK(std::abs(r.image.at(x, 1).r - v * v) <= 1e-5); // C A + (1 - A) * 0
    }
}

TEST_CASE("opaque geometry inside the volume ends the ray at its distance") {
    const glm::dvec3 C(0.5, 0.25, 1.0), surface(0.2, 0.3, 0.4);
    RayCastScene scene;
    scene.camera = orthoCamera(8, 8, 0.4);
    scene.volumes.push_back(constantBox(C, 0.1));
    scene.behind.backgroundPixels.assign(64, surface);
    scene.behind.opaqueDistance.assign(64, 10.0); // the eye plane is z = 10: surface at z = 0
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double T = std::exp(-tauOf(0.1, 1.0 / 16.0) * 0.5);
    for (const glm::vec4& p : r.image.pixels)
        checkPixel(p, glm::dvec4(C * (1.0 - T) + T * surface, 1.0 - T), 1e-5);
}

TEST_CASE("window depth converts to the distance along the pixel ray") {
    for (const RayCastCamera& camera :
         {orthoCamera(8, 8, 1.0), perspectiveCamera(8, 8, 0.8, {0, 0, 10}, {0, 0, 0})}) {
        // The world point where pixel (2, 5)'s ray meets z = 0, projected to window depth.
        const Ray ray = ReferenceRayCaster::pixelRay(camera, 2, 5);
        const double t = -ray.origin.z / ray.direction.z;
        const glm::dvec4 clip = camera.projection * camera.view * glm::dvec4(ray.at(t), 1.0);
        const double windowDepth = 0.5 * clip.z / clip.w + 0.5;
        CHECK(ReferenceRayCaster::rayDistanceFromWindowDepth(camera, 2, 5, windowDepth) ==
              doctest::Approx(t).epsilon(1e-9));
        CHECK(ReferenceRayCaster::rayDistanceFromWindowDepth(camera, 2, 5, 1.0) == kInf);
    }
}

TEST_CASE("overlapping volumes are composited per sample") {
    // Red box z in [-0.5, 0.5], green box shifted to z in [0, 1]: along -Z the ray sees green
    // alone (0.5), both mixed (0.5: tau adds, colour weighted by tau), then red alone (0.5).
    const glm::dvec3 red(1, 0, 0), green(0, 1, 0), bg(0.0);
    const double tauRed = tauOf(0.05, 1.0 / 16.0), tauGreen = tauOf(0.1, 1.0 / 16.0);
    RayCastScene scene;
    scene.camera = orthoCamera(4, 4, 0.4);
    scene.volumes.push_back(constantBox(red, 0.05));
    RayCastVolume g = constantBox(green, 0.1);
    g.model = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 0.5));
    scene.volumes.push_back(g);
    const RayCastResult r = ReferenceRayCaster().render(scene);
    const double both = tauRed + tauGreen;
    const glm::dvec3 mixed = (tauRed * red + tauGreen * green) / both;
    const glm::dvec4 want =
        composite({{green, tauGreen, 0.5}, {mixed, both, 0.5}, {red, tauRed, 0.5}}, bg);
    for (const glm::vec4& p : r.image.pixels)
        checkPixel(p, want, 1e-5);
}

TEST_CASE("invalid input is reported as an Error") {
    RayCastScene scene;
    scene.camera = orthoCamera(4, 4, 1.0);
    scene.volumes.push_back(RayCastVolume{});
    CHECK_THROWS_AS(ReferenceRayCaster().render(scene), Error); // no data

    scene.volumes[0] = constantBox(glm::dvec3(1.0), 0.1);
    scene.volumes[0].tags = makeConstant(glm::ivec3(8), VoxelType::UByte, 1.0);
    CHECK_THROWS_AS(ReferenceRayCaster().render(scene), Error); // tag dimensions differ
    scene.volumes[0].tags = makeConstant(glm::ivec3(16), VoxelType::Float, 1.0);
    CHECK_THROWS_AS(ReferenceRayCaster().render(scene), Error); // tags must be labels

    scene.volumes[0] = constantBox(glm::dvec3(1.0), 0.1);
    scene.volumes[0].model = glm::dmat4(0.0);
    CHECK_THROWS_AS(ReferenceRayCaster().render(scene), Error); // singular model

    scene.volumes[0] = constantBox(glm::dvec3(1.0), 0.1);
    scene.behind.backgroundPixels.assign(3, glm::dvec3(0.0));
    CHECK_THROWS_AS(ReferenceRayCaster().render(scene), Error); // wrong per-pixel size
    scene.behind.backgroundPixels.clear();
    scene.camera.width = 0;
    CHECK_THROWS_AS(ReferenceRayCaster().render(scene), Error);

    RayCastOptions bad;
    bad.tolerance = 0.0;
    CHECK_THROWS_AS(ReferenceRayCaster{bad}, Error);
}
