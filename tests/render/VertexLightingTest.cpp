// Where shapes sum their lights per vertex: the error model (VertexLighting.h) and, on a
// family of shapes, materials, lights and views, the promise it makes: where it chooses per
// vertex, the image differs from the per-fragment one by at most kVertexLightingTolerance
// (RMS per channel over the shape's pixels).

#include <doctest/doctest.h>

#include <volsg/context/OSMesaContext.h>
#include <volsg/geometry/Mesh.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/image/Image.h>
#include <volsg/io/SceneReader.h>
#include <volsg/render/Renderer.h>
#include <volsg/render/VertexLighting.h>

#include <cmath>
#include <limits>
#include <string>

using namespace volsg;

namespace {

/// Two triangles of a unit square in z = 0, with the given vertex normals.
Mesh square(glm::vec3 n0, glm::vec3 n1, glm::vec3 n2, glm::vec3 n3) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.normals = {n0, n1, n2, n3};
    m.indices = {0, 1, 2, 0, 2, 3};
    return m;
}

VertexLightingCase caseOf(const Mesh& mesh, std::span<const SceneLight> lights) {
    VertexLightingCase c;
    c.spread = measureShadingSpread(mesh);
    c.bounds = mesh.bounds();
    c.lights = lights;
    return c;
}

} // namespace

TEST_CASE("the shading spread of a mesh: its normals' angles, colours and edges") {
    const glm::vec3 z(0, 0, 1);
    const ShadingSpread flat = measureShadingSpread(square(z, z, z, z));
    CHECK(flat.normal == doctest::Approx(0.0));
    CHECK(flat.color == 0.0f);
    CHECK(flat.longestEdge == doctest::Approx(std::sqrt(2.0)));

    // Every triangle has two normals 0.2 rad apart (and none further): the quartic mean is 0.2.
    const glm::vec3 tilted(std::sin(0.2f), 0.0f, std::cos(0.2f));
    const ShadingSpread bent = measureShadingSpread(square(z, tilted, tilted, z));
    CHECK(bent.normal == doctest::Approx(0.2).epsilon(1e-4));

    Mesh colored = square(z, tilted, tilted, z);
    colored.colors = {{1, 0, 0, 1}, {0.5f, 0, 0, 1}, {0.5f, 0, 0, 1}, {1, 0, 0, 1}};
    const ShadingSpread c = measureShadingSpread(colored);
    CHECK(c.color == doctest::Approx(0.5).epsilon(1e-4));
    CHECK(c.colorTimesNormal == doctest::Approx(0.1).epsilon(1e-4));

    // No normals, or a zero one: the fragment derives its normal, per vertex cannot stand in.
    Mesh none = square(z, z, z, z);
    none.normals.clear();
    CHECK(std::isinf(measureShadingSpread(none).normal));
    CHECK(std::isinf(measureShadingSpread(square(z, z, glm::vec3(0.0f), z)).normal));
}

TEST_CASE("the predicted error of per-vertex lighting") {
    const glm::vec3 z(0, 0, 1);
    const Mesh flat = square(z, z, z, z);
    SceneLight directional; // towards +Z, white
    const SceneLight one[] = {directional};

    // A flat face under a directional light, seen orthographically, diffuse only: exact.
    CHECK(predictVertexLightingError(caseOf(flat, one)) == 0.0);

    // Bent normals: the diffuse cosine's curvature, (angle^2 / 11) times the diffuse colour.
    const glm::vec3 tilted(std::sin(0.3f), 0.0f, std::cos(0.3f));
    VertexLightingCase bent = caseOf(square(z, tilted, tilted, z), one);
    CHECK(predictVertexLightingError(bent) == doctest::Approx(0.8 * 0.09 / 11.0).epsilon(1e-3));
    // A sharp highlight raises it; a stretched model bends normals further apart.
    VertexLightingCase shiny = bent;
    shiny.specular = glm::vec3(1.0f);
    shiny.shininess = 100.0f;
    CHECK(predictVertexLightingError(shiny) > 50.0 * predictVertexLightingError(bent));
    VertexLightingCase stretched = bent;
    stretched.model = glm::scale(glm::dmat4(1.0), glm::dvec3(4.0, 1.0, 1.0));
    CHECK(predictVertexLightingError(stretched) ==
          doctest::Approx(16.0 * predictVertexLightingError(bent)).epsilon(1e-3));

    // What per-vertex lighting cannot stand in for: a spot light's cone edge, a point light
    // inside the bounds, a flattened model, no normals, NaN in the model.
    SceneLight spot;
    spot.vector = glm::vec4(0.5f, 0.5f, 3.0f, 1.0f);
    spot.spotCosCutOff = 0.9f;
    const SceneLight spots[] = {spot};
    CHECK(std::isinf(predictVertexLightingError(caseOf(flat, spots))));
    SceneLight point = spot;
    point.spotCosCutOff = -2.0f;
    point.vector = glm::vec4(0.5f, 0.5f, 0.0f, 1.0f);
    const SceneLight inside[] = {point};
    CHECK(std::isinf(predictVertexLightingError(caseOf(flat, inside))));
    VertexLightingCase eyeInside = caseOf(flat, one);
    eyeInside.specular = glm::vec3(0.5f); // (the diffuse term does not depend on the eye)
    eyeInside.viewer = glm::dvec4(0.5, 0.5, 0.0, 1.0);
    // The highlight may be missed whole: the specular colour.
    CHECK(predictVertexLightingError(eyeInside) == doctest::Approx(0.5));
    VertexLightingCase flattened = caseOf(flat, one);
    flattened.model = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, 1.0, 0.0));
    CHECK(std::isinf(predictVertexLightingError(flattened)));
    VertexLightingCase nan = caseOf(flat, one);
    nan.model[0][0] = std::numeric_limits<double>::quiet_NaN();
    CHECK(std::isinf(predictVertexLightingError(nan)));
    // A point light far away, with the eye: small and finite.
    point.vector = glm::vec4(0.5f, 0.5f, 50.0f, 1.0f);
    const SceneLight far[] = {point};
    VertexLightingCase distant = caseOf(flat, far);
    distant.viewer = glm::dvec4(0.5, 0.5, 40.0, 1.0);
    const double e = predictVertexLightingError(distant);
    CHECK(e > 0.0);
    CHECK(e < kVertexLightingTolerance);
}

namespace {

struct Difference {
    double rms = 0.0;
    int pixels = 0;
};

/// RMS per channel over the pixels where either image is not the background.
Difference difference(const Image& a, const Image& b, glm::vec3 background) {
    Difference d;
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const glm::vec3 p(a.at(x, y)), q(b.at(x, y));
            if (p == background && q == background) continue;
            for (int c = 0; c < 3; ++c)
                sum += double(p[c] - q[c]) * double(p[c] - q[c]);
            ++d.pixels;
        }
    d.rms = d.pixels > 0 ? std::sqrt(sum / (3.0 * d.pixels)) : 0.0;
    return d;
}

} // namespace

TEST_CASE("where shapes are lit per vertex, they match per-fragment lighting within the "
          "stated tolerance") {
    OSMesaContext context;
    enableGlErrorChecking();
    Renderer renderer;
    const glm::vec3 background(0.0f);
    const char* shapes[] = {
        "Complexity { value 0.3 } Sphere { }", "Sphere { }",
        "Complexity { value 1 } Sphere { }",   "Cone { }",
        "Complexity { value 1 } Cylinder { }", "Transform { scaleFactor 2.5 0.6 1 } Sphere { }"};
    const char* materials[] = {
        "Material { diffuseColor 0.8 0.6 0.4 }",
        "Material { diffuseColor 0.7 0.2 0.2 specularColor 0.5 0.5 0.5 shininess 0.2 }",
        "Material { diffuseColor 0.2 0.3 0.8 specularColor 0.9 0.9 0.9 shininess 0.8 }"};
    const char* lights[] = {"", "DirectionalLight { direction -1 -1 -1 }",
                            "PointLight { location 2 2 3 }", "PointLight { location 30 20 40 }"};
    const char* cameras[] = {"PerspectiveCamera { position 0 0 5 }",
                             "OrthographicCamera { position 0 0 5 height 3 }",
                             "PerspectiveCamera { position 0 0 2.2 }"};
    int perVertex = 0, perFragment = 0, avoided = 0;
    double worstChosen = 0.0;
    for (const char* camera : cameras)
        for (const char* light : lights)
            for (const char* material : materials)
                for (const char* shape : shapes) {
                    const std::string text = std::string("#Inventor V2.1 ascii\nSeparator { ") +
                                             camera + " " + light + " " + material + " " + shape +
                                             " }\n";
                    CAPTURE(text);
                    ref_ptr<Node> root = readSceneFromString(text);
                    RenderOptions options;
                    options.width = options.height = 96;
                    options.background = background;
                    options.debug.shapeLighting = RenderDebug::Lighting::PerFragment;
                    const Image exact = renderer.render(*root, options);
                    options.debug.shapeLighting = RenderDebug::Lighting::Automatic;
                    const Image chosen = renderer.render(*root, options);
                    const RenderStats stats = renderer.stats();
                    REQUIRE(stats.litShapes == 1);
                    if (stats.vertexLitShapes == 1) {
                        ++perVertex;
                        const Difference d = difference(chosen, exact, background);
                        CAPTURE(d.pixels);
                        CHECK(d.pixels > 200);
                        CHECK(d.rms <= kVertexLightingTolerance);
                        worstChosen = std::max(worstChosen, d.rms);
                    } else {
                        ++perFragment;
                        CHECK(difference(chosen, exact, background).rms == 0.0);
                        options.debug.shapeLighting = RenderDebug::Lighting::PerVertex;
                        const Image forced = renderer.render(*root, options);
                        avoided +=
                            difference(forced, exact, background).rms > kVertexLightingTolerance;
                    }
                }
    MESSAGE("per vertex ", perVertex, ", per fragment ", perFragment, " (", avoided,
            " of them would have missed the tolerance per vertex); worst chosen RMS ",
            worstChosen * 255.0, "/255");
    // The model is not vacuous either way: it takes the per-vertex path for many of these
    // cases, and keeps per fragment where per vertex would have shown.
    CHECK(perVertex >= 24);
    CHECK(perFragment >= 100);
    CHECK(avoided >= 100);
}
