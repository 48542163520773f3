#pragma once
// Shared by the slicing tests: an offscreen renderer, the reference image of the same volume
// description, image differences, a node that slices an arbitrary VolumeGrid, and the volumes,
// cameras, comparisons and checks the tests repeat.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <volsg/context/OSMesaContext.h>
#include <volsg/image/Image.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/reference/ReferenceRayCaster.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/Renderer.h>
#include <volsg/slicing/PagedBricks.h>
#include <volsg/slicing/VolumeSlicer.h>
#include <volsg/volume/TestVolumes.h>
#include <volsg/volume/TransferFunction1D.h>
#include <volsg/volume/VolumeGrid.h>
#include <volsg/volumescene/ReferenceScene.h>

namespace volsg::test {

/// One step of 8-bit colour: the unit of the tests' error bounds.
constexpr double k8Bit = 1.0 / 255.0;

/// What most GL tests start with: a current offscreen context and a Renderer
/// (TEST_CASE_FIXTURE(GlFixture, "...")).
struct GlFixture {
    OSMesaContext context;
    Renderer renderer;
};

/// Slices a volume given directly as the rendering model describes it (any grid, any
/// transfer functions), through the same VolumeSlicer the Volume node uses. Its model matrix
/// is the traversal's, and the ClipPlanes in scope are added to the description's.
class GridVolume : public Inherit<Node, GridVolume> {
public:
    static constexpr const char* typeName = "GridVolume";
    RayCastVolume description;
    SlicingSettings settings;
    std::uint64_t transferKey = 1; ///< bump when description.transferFunctions change
    SlicingStats stats;

    GridVolume() {
        static const bool added = (RenderAction::methods().add(&render), true);
        (void)added;
    }

    /// Its render method (RenderAction::methods()).
    static void render(RenderAction& action, GridVolume& node) {
        if (action.pass() != RenderPass::Volume) return;
        RayCastVolume v = node.description;
        v.model = action.state().modelMatrix() * node.description.model;
        v.transferKey = node.transferKey;
        std::vector<glm::dvec4> planes;
        action.clipPlanesInScope(planes);
        v.clipPlanes.insert(v.clipPlanes.end(), planes.begin(), planes.end());
        std::vector<SceneLight> lights;
        action.lightsInScope(lights);
        VolumeSlicer::draw(action.frame(), node, v, lights, node.settings, node.stats);
    }
};

/// A camera of type C at `eye` looking at the origin (+Y up), near and far around it.
template <class C>
ref_ptr<C> cameraAt(const glm::vec3& eye, float nearDistance, float farDistance) {
    auto camera = C::create();
    camera->position = eye;
    const glm::vec3 forward = glm::normalize(-eye);
    const glm::vec3 axis = glm::cross(glm::vec3(0, 0, -1), forward);
    const float s = glm::length(axis);
    const float angle = std::atan2(s, glm::dot(glm::vec3(0, 0, -1), forward));
    camera->orientation = Rotation{s > 1e-6f ? axis / s : glm::vec3(0, 1, 0), angle};
    camera->nearDistance = nearDistance;
    camera->farDistance = farDistance;
    return camera;
}

/// A perspective camera at `eye` looking at the origin (+Y up), near and far around it.
inline ref_ptr<PerspectiveCamera> perspectiveAt(const glm::vec3& eye, float heightAngle,
                                                float nearDistance, float farDistance) {
    auto camera = cameraAt<PerspectiveCamera>(eye, nearDistance, farDistance);
    camera->heightAngle = heightAngle;
    return camera;
}

inline ref_ptr<OrthographicCamera> orthographicAt(const glm::vec3& eye, float height,
                                                  float nearDistance, float farDistance) {
    auto camera = cameraAt<OrthographicCamera>(eye, nearDistance, farDistance);
    camera->height = height;
    return camera;
}

/// The reference ray caster's camera for a render of `camera` at w x h (GL clips rays to
/// the near and far planes, so the reference does too).
inline RayCastCamera rayCamera(const Camera& camera, int width, int height) {
    RayCastCamera c;
    c.view = camera.viewMatrix();
    c.projection = camera.projectionMatrix(double(width) / double(height));
    c.width = width;
    c.height = height;
    c.clipToNearFar = true;
    return c;
}

/// The reference image of volumes over a background (and optional opaque surfaces).
inline Image referenceImage(const RayCastCamera& camera, const std::vector<RayCastVolume>& volumes,
                            const glm::dvec3& background = glm::dvec3(0.0),
                            const RayCastBehind* behind = nullptr, double tolerance = 2e-4) {
    RayCastScene scene;
    scene.camera = camera;
    scene.volumes = volumes;
    if (behind)
        scene.behind = *behind;
    else
        scene.behind.background = background;
    RayCastOptions options;
    options.tolerance = tolerance;
    return ReferenceRayCaster(options).render(scene).image;
}

struct ImageDifference {
    double rmse = 0.0; ///< over the RGB channels of every pixel
    double max = 0.0;  ///< largest RGB channel difference
    int x = -1, y = -1;
};

inline ImageDifference difference(const Image& a, const Image& b) {
    REQUIRE(a.width == b.width);
    REQUIRE(a.height == b.height);
    ImageDifference d;
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double e = double(a.at(x, y)[c]) - double(b.at(x, y)[c]);
                sum += e * e;
                if (std::abs(e) > d.max || !std::isfinite(e)) {
                    d.max = std::isfinite(e) ? std::abs(e) : 1e30;
                    d.x = x;
                    d.y = y;
                }
            }
    d.rmse = std::sqrt(sum / (3.0 * a.width * a.height));
    return d;
}

/// The share of pixels whose RGB channels all differ by at most `tolerance`.
inline double fractionWithin(const Image& a, const Image& b, double tolerance) {
    std::size_t close = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const glm::vec3 d = glm::abs(glm::vec3(a.pixels[i]) - glm::vec3(b.pixels[i]));
        if (d.x <= tolerance && d.y <= tolerance && d.z <= tolerance) ++close;
    }
    return double(close) / double(a.pixels.size());
}

inline bool allFinite(const Image& image) {
    return std::all_of(image.pixels.begin(), image.pixels.end(), [](const glm::vec4& p) {
        return std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) && std::isfinite(p.a);
    });
}

/// Writes the image for a look when VOLSG_TEST_IMAGES names a folder.
inline void keepImage(const Image& image, const std::string& name) {
    if (const char* folder = std::getenv("VOLSG_TEST_IMAGES"))
        writePng(std::string(folder) + "/" + name + ".png", image);
}

/// A transfer function with the given alpha curve and colour ramps.
inline TransferFunction1D
transferFunction(std::vector<PiecewiseLinear::Point> alpha,
                 std::vector<PiecewiseLinear::Point> red = {{0, 0}, {1, 1}},
                 std::vector<PiecewiseLinear::Point> green = {{0, 0}, {1, 1}},
                 std::vector<PiecewiseLinear::Point> blue = {{0, 0}, {1, 1}}) {
    TransferFunction1D tf;
    tf.setChannel(TransferFunction1D::Alpha, std::move(alpha));
    tf.setChannel(TransferFunction1D::Red, std::move(red));
    tf.setChannel(TransferFunction1D::Green, std::move(green));
    tf.setChannel(TransferFunction1D::Blue, std::move(blue));
    return tf;
}

/// The same function as TransferFunction node fields.
inline void setNodeFields(TransferFunction& node, const TransferFunction1D& tf) {
    auto points = [&](TransferFunction1D::Channel c) {
        std::vector<glm::vec2> out;
        for (const auto& p : tf.channel(c).points())
            out.emplace_back(float(p.x), float(p.y));
        return out;
    };
    node.red = points(TransferFunction1D::Red);
    node.green = points(TransferFunction1D::Green);
    node.blue = points(TransferFunction1D::Blue);
    node.alpha = points(TransferFunction1D::Alpha);
    if (tf.dataRange()) node.dataRange = glm::vec2(*tf.dataRange());
}

} // namespace volsg::test

namespace volsg::test {

/// A grid of `dims` voxels whose value at local point p is f(p / halfExtent) in [0, 1] (so f
/// sees [-1, 1]^3), scaled to the type as TestVolumes does (UByte 255, UShort 65535, Short
/// 32767, Float 1).
template <class F>
ref_ptr<VolumeGrid> makeGrid(glm::ivec3 dims, VoxelType type, glm::dvec3 spacing, F&& f) {
    auto grid = VolumeGrid::create(dims, type, spacing);
    const glm::dvec3 half = 0.5 * grid->extent();
    const double scale = type == VoxelType::UByte    ? 255.0
                         : type == VoxelType::UShort ? 65535.0
                         : type == VoxelType::Short  ? 32767.0
                                                     : 1.0;
    for (int k = 0; k < dims.z; ++k)
        for (int j = 0; j < dims.y; ++j)
            for (int i = 0; i < dims.x; ++i)
                grid->setValue(i, j, k, scale * f(grid->voxelCenter(i, j, k) / half));
    return grid;
}

/// Slicing and reference images of one volume description.
struct Comparison {
    Image gl, reference;
    ImageDifference difference;
    SlicingStats stats;
};

inline Comparison compareGrid(Renderer& renderer, const RayCastVolume& volume,
                              const SlicingSettings& settings, Camera& camera, int size,
                              const glm::vec3& background = glm::vec3(0.0f),
                              bool interactive = false, const RenderDebug& debug = {}) {
    auto root = Separator::create();
    auto node = GridVolume::create();
    node->description = volume;
    node->settings = settings;
    root->addChild(node);
    RenderOptions options;
    options.width = options.height = size;
    options.camera = ref_ptr<Camera>(&camera);
    options.background = background;
    options.interactive = interactive;
    options.debug = debug;
    Comparison c;
    c.gl = renderer.render(*root, options);
    c.stats = node->stats;
    c.reference = referenceImage(rayCamera(camera, size, size), {volume}, glm::dvec3(background));
    c.difference = difference(c.gl, c.reference);
    return c;
}

/// A camera at `distance` times the largest extent along `direction` that frames the volume.
inline ref_ptr<PerspectiveCamera> framing(const VolumeGrid& grid, glm::vec3 direction,
                                          float distance = 2.5f) {
    const auto e = grid.extent();
    const float extent = float(std::max({e.x, e.y, e.z}));
    return perspectiveAt(glm::normalize(direction) * distance * extent,
                         2.0f * std::atan(0.45f / distance), 0.5f * distance * extent,
                         2.0f * distance * extent);
}

/// A volume of `data` under one transfer function (the default one, key -1).
inline RayCastVolume volumeOf(ref_ptr<const VolumeGrid> data, const TransferFunction1D& function,
                              VolumeRenderMode mode = VolumeRenderMode::DVR) {
    RayCastVolume v;
    v.data = std::move(data);
    v.transferFunctions[-1] = function;
    v.mode = mode;
    return v;
}

/// makeLabelledVolume(n) with its tags, under `functions` by tag (-1: the default).
inline RayCastVolume labelledVolume(int n, std::map<int, TransferFunction1D> functions,
                                    VolumeRenderMode mode = VolumeRenderMode::DVR) {
    const LabelledVolume labelled = makeLabelledVolume(n);
    RayCastVolume v;
    v.data = labelled.data;
    v.tags = labelled.tags;
    v.transferFunctions = std::move(functions);
    v.mode = mode;
    return v;
}

/// An alpha curve 0 but for a spike of `alpha` at `peak`, rising from `from` and gone at `to`.
inline std::vector<PiecewiseLinear::Point> spike(double from, double peak, double to,
                                                 double alpha = 0.9) {
    return {{0, 0}, {from, 0}, {peak, alpha}, {to, 0}, {1, 0}};
}

/// `settings` with pre-integration.
inline SlicingSettings preIntegrated(SlicingSettings settings) {
    settings.preIntegrated = true;
    return settings;
}

/// A smooth blob with a ripple: values in [0, 1], non-zero up to the box faces.
inline double blob(const glm::dvec3& p) {
    const double r = glm::length(p);
    return std::clamp(0.55 - 0.45 * r + 0.15 * std::sin(4.0 * p.x) * std::cos(3.0 * p.y), 0.0, 1.0);
}

/// Marschner-Lobb 17^3 (16-bit) under a smooth transfer function of rising opacity.
inline RayCastVolume marschnerLobbVolume() {
    return volumeOf(
        makeMarschnerLobb(17, VoxelType::UShort),
        transferFunction({{0.3, 0}, {0.7, 0.8}}, {{0, 0.1}, {1, 1}}, {{0, 0.8}, {1, 0.3}}));
}

/// The same volume and camera sliced with two settings, first `a`, then `b`.
inline std::pair<Comparison, Comparison>
compareSettings(Renderer& renderer, const RayCastVolume& volume, const SlicingSettings& a,
                const SlicingSettings& b, Camera& camera, int size) {
    Comparison first = compareGrid(renderer, volume, a, camera, size);
    return {std::move(first), compareGrid(renderer, volume, b, camera, size)};
}

/// Writes both images of a comparison for a look (VOLSG_TEST_IMAGES): NAME and NAME-ref.
inline void keepImages(const Comparison& c, const std::string& name) {
    keepImage(c.gl, name);
    keepImage(c.reference, name + "-ref");
}

/// Logs `what` and the difference to the reference, and checks that its RMSE is below
/// `rmse` / 255 and its largest channel difference below `max` / 255.
inline void checkDifference(const ImageDifference& d, double rmse, double max,
                            const std::string& what = {}) {
    MESSAGE(what << "rmse " << d.rmse * 255 << "/255, max " << d.max * 255 << "/255");
    CHECK(d.rmse < rmse * k8Bit);
    CHECK(d.max < max * k8Bit);
}

/// Checks that the slicing drew triangles and, as checkDifference, how close it came to the
/// reference; the message names `what` and the plane count.
inline void checkSliced(const Comparison& c, double rmse, double max,
                        const std::string& what = {}) {
    CHECK(c.stats.sliceTriangles > 0);
    checkDifference(c.difference, rmse, max, what + std::to_string(c.stats.planes) + " planes: ");
}

/// "x,y,z", as a stream writes the numbers.
inline std::string text(const glm::vec3& v) {
    std::ostringstream out;
    out << v.x << "," << v.y << "," << v.z;
    return out.str();
}

/// A scene drawn by GL and by the reference (renderReference at tolerance 2e-4: GL's opaque
/// geometry, the volumes ray cast) with the same options; the images are kept as NAME-gl and
/// NAME-ref.
inline ImageDifference compareScene(Renderer& renderer, Node& root, const RenderOptions& options,
                                    const std::string& name, Image* glImage = nullptr) {
    const Image gl = renderer.render(root, options);
    RayCastOptions rays;
    rays.tolerance = 2e-4;
    const Image ref = renderReference(root, options, nullptr, rays);
    keepImage(gl, name + "-gl");
    keepImage(ref, name + "-ref");
    if (glImage) *glImage = gl;
    return difference(gl, ref);
}

} // namespace volsg::test
