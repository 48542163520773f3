#include <volsg/render/StereoRenderer.h>

#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

/// A perspective camera whose frustum is shifted sideways in clip space: the off-axis frustum
/// of one eye (Camera only describes symmetric ones).
class OffAxisCamera : public Inherit<PerspectiveCamera, OffAxisCamera> {
public:
    static constexpr const char* typeName = "OffAxisCamera";
    double clipShift = 0.0; ///< x_ndc gains P00 * clipShift (a shear in eye space)

    glm::dmat4 projectionMatrix(double viewportAspect) const override {
        glm::dmat4 shift(1.0);
        shift[2][0] = -clipShift; // eye space z = -w_clip for a perspective projection
        return PerspectiveCamera::projectionMatrix(viewportAspect) * shift;
    }

protected:
    ~OffAxisCamera() override = default;
};

void copyCameraFields(const Camera& from, Camera& to) {
    to.viewportMapping = from.viewportMapping();
    to.position = from.position();
    to.orientation = from.orientation();
    to.aspectRatio = from.aspectRatio();
    to.nearDistance = from.nearDistance();
    to.farDistance = from.farDistance();
    to.focalDistance = from.focalDistance();
}

Rotation rotationOf(const glm::dquat& q) {
    const glm::dquat n = glm::normalize(q.w < 0.0 ? -q : q);
    const double angle = 2.0 * std::acos(std::min(n.w, 1.0));
    const double s = std::sqrt(std::max(1.0 - n.w * n.w, 0.0));
    if (s < 1e-12) return Rotation{};
    return Rotation{glm::vec3(float(n.x / s), float(n.y / s), float(n.z / s)), float(angle)};
}

} // namespace

StereoMode parseStereoMode(const std::string& text) {
    if (text == "off") return StereoMode::Off;
    if (text == "anaglyph") return StereoMode::Anaglyph;
    if (text == "side-by-side") return StereoMode::SideBySide;
    throw Error("unknown stereo mode '" + text + "' (off, anaglyph, side-by-side)");
}

const char* stereoModeName(StereoMode mode) {
    switch (mode) {
    case StereoMode::Anaglyph:
        return "anaglyph";
    case StereoMode::SideBySide:
        return "side-by-side";
    case StereoMode::Off:
        break;
    }
    return "off";
}

ref_ptr<Camera> stereoEyeCamera(const Camera& center, double separationFraction, Eye eye) {
    const double focal = double(center.focalDistance());
    const double side = eye == Eye::Left ? -1.0 : 1.0;
    const double half = 0.5 * separationFraction * focal; // half the eye separation
    const glm::dquat turn = center.orientation().quat();
    const glm::dvec3 right = turn * glm::dvec3(1.0, 0.0, 0.0);
    if (const auto* ortho = dynamic_cast<const OrthographicCamera*>(&center)) {
        auto camera = OrthographicCamera::create();
        copyCameraFields(center, *camera);
        camera->height = ortho->height();
        // Turn about the focal point so that the eye moves by `half` to its side.
        const glm::dvec3 forward = turn * glm::dvec3(0.0, 0.0, -1.0);
        const glm::dvec3 focus = glm::dvec3(center.position()) + forward * focal;
        const glm::dvec3 up = turn * glm::dvec3(0.0, 1.0, 0.0);
        const glm::dquat yaw = glm::angleAxis(side * std::atan2(half, focal), up);
        camera->position = glm::vec3(focus + yaw * (glm::dvec3(center.position()) - focus));
        camera->orientation = rotationOf(yaw * turn);
        return camera;
    }
    const auto* perspective = dynamic_cast<const PerspectiveCamera*>(&center);
    if (!perspective) throw Error("stereo needs a perspective or an orthographic camera");
    auto camera = OffAxisCamera::create();
    copyCameraFields(center, *camera);
    camera->heightAngle = perspective->heightAngle();
    camera->position = glm::vec3(glm::dvec3(center.position()) + right * (side * half));
    // The eye's window at the focal distance is the centre camera's: x_ndc gains P00 * side *
    // half / focal, so that a point there projects where the centre camera sees it.
    camera->clipShift = side * half / focal;
    return camera;
}

ref_ptr<Camera> worldSpaceCamera(const SceneCamera& scene) {
    ref_ptr<Camera> camera = ref_ptr<Node>(scene.camera->type().create()).cast<Camera>();
    copyCameraFields(*scene.camera, *camera);
    if (auto* p = dynamic_cast<PerspectiveCamera*>(camera.get()))
        p->heightAngle = static_cast<const PerspectiveCamera&>(*scene.camera).heightAngle();
    if (auto* o = dynamic_cast<OrthographicCamera*>(camera.get()))
        o->height = static_cast<const OrthographicCamera&>(*scene.camera).height();
    const glm::dmat3 m(scene.model);
    camera->position =
        glm::vec3(scene.model * glm::dvec4(glm::dvec3(scene.camera->position()), 1.0));
    const glm::dquat turn = glm::quat_cast(
        glm::dmat3(glm::normalize(m[0]), glm::normalize(m[1]), glm::normalize(m[2])));
    camera->orientation = rotationOf(turn * scene.camera->orientation().quat());
    return camera;
}

Image renderStereo(Renderer& renderer, Node& root, const RenderOptions& options,
                   const StereoOptions& stereo) {
    if (stereo.mode == StereoMode::Off) return renderer.render(root, options);
    RenderOptions o = options;
    if (!o.camera)
        o.camera = worldSpaceCamera(findOrMakeCamera(root, double(o.width) / double(o.height)));
    const ref_ptr<Camera> center = o.camera;
    auto eyeImage = [&](Eye eye, int width) {
        RenderOptions e = o;
        e.width = width;
        e.camera = stereoEyeCamera(*center, stereo.separationFraction, eye);
        return renderer.render(root, e);
    };
    if (stereo.mode == StereoMode::Anaglyph) {
        Image image = eyeImage(Eye::Left, o.width);
        const Image right = eyeImage(Eye::Right, o.width);
        for (std::size_t i = 0; i < image.pixels.size(); ++i) {
            image.pixels[i].g = right.pixels[i].g;
            image.pixels[i].b = right.pixels[i].b;
        }
        return image;
    }
    if (o.width < 2) throw Error("a side-by-side stereo image needs a width of 2 or more");
    const int leftWidth = o.width / 2;
    const Image left = eyeImage(Eye::Left, leftWidth);
    const Image right = eyeImage(Eye::Right, o.width - leftWidth);
    Image image(o.width, o.height);
    for (int y = 0; y < o.height; ++y) {
        for (int x = 0; x < leftWidth; ++x)
            image.at(x, y) = left.at(x, y);
        for (int x = 0; x < right.width; ++x)
            image.at(leftWidth + x, y) = right.at(x, y);
    }
    return image;
}

} // namespace volsg
