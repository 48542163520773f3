#pragma once
// Shared by the slicing tests: an offscreen renderer, the reference image of the same volume
// description, image differences, and a node that slices an arbitrary VolumeGrid.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <volsg/context/OSMesaContext.h>
#include <volsg/image/Image.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/reference/ReferenceRayCaster.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/Renderer.h>
#include <volsg/slicing/VolumeSlicer.h>
#include <volsg/volume/TransferFunction1D.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg::test {

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

/// A perspective camera at `eye` looking at the origin (+Y up), near and far around it.
inline ref_ptr<PerspectiveCamera> perspectiveAt(const glm::vec3& eye, float heightAngle,
                                                float nearDistance, float farDistance) {
    auto camera = PerspectiveCamera::create();
    camera->position = eye;
    const glm::vec3 forward = glm::normalize(-eye);
    const glm::vec3 axis = glm::cross(glm::vec3(0, 0, -1), forward);
    const float s = glm::length(axis);
    const float angle = std::atan2(s, glm::dot(glm::vec3(0, 0, -1), forward));
    camera->orientation = Rotation{s > 1e-6f ? axis / s : glm::vec3(0, 1, 0), angle};
    camera->heightAngle = heightAngle;
    camera->nearDistance = nearDistance;
    camera->farDistance = farDistance;
    return camera;
}

inline ref_ptr<OrthographicCamera> orthographicAt(const glm::vec3& eye, float height,
                                                  float nearDistance, float farDistance) {
    auto camera = OrthographicCamera::create();
    camera->position = eye;
    const glm::vec3 forward = glm::normalize(-eye);
    const glm::vec3 axis = glm::cross(glm::vec3(0, 0, -1), forward);
    const float s = glm::length(axis);
    const float angle = std::atan2(s, glm::dot(glm::vec3(0, 0, -1), forward));
    camera->orientation = Rotation{s > 1e-6f ? axis / s : glm::vec3(0, 1, 0), angle};
    camera->height = height;
    camera->nearDistance = nearDistance;
    camera->farDistance = farDistance;
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

} // namespace volsg::test
