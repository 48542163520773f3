#include <volsg/manipulators/ExaminerNavigation.h>

#include <algorithm>
#include <cmath>

#include <volsg/manipulators/DragMath.h>

namespace volsg {

namespace {
// The half height of the view at the focal distance (ADJUST_CAMERA: widened when the viewport
// is taller than wide, as Camera::projectionMatrix does).
double halfHeightAtFocus(const Camera& c, double aspect) {
    double h;
    if (const auto* o = dynamic_cast<const OrthographicCamera*>(&c))
        h = 0.5 * double(o->height());
    else
        h = double(c.focalDistance()) *
            std::tan(0.5 * double(static_cast<const PerspectiveCamera&>(c).heightAngle()));
    return aspect < 1.0 ? h / aspect : h;
}
} // namespace

CameraPose interpolatePose(const CameraPose& from, const CameraPose& to, double s) {
    s = std::clamp(s, 0.0, 1.0);
    CameraPose p;
    p.position = glm::mix(from.position, to.position, s);
    glm::dquat b = glm::normalize(to.orientation);
    const glm::dquat a = glm::normalize(from.orientation);
    if (glm::dot(a, b) < 0.0) b = -b; // the shorter way round
    p.orientation = glm::normalize(glm::slerp(a, b, s));
    p.focalDistance = from.focalDistance + (to.focalDistance - from.focalDistance) * s;
    return p;
}

double seekEasing(double s) {
    s = std::clamp(s, 0.0, 1.0);
    return s * s * (3.0 - 2.0 * s);
}

ExaminerNavigation::ExaminerNavigation(ref_ptr<Camera> camera, int width, int height)
    : camera_(std::move(camera)) {
    setViewport(width, height);
    saveHome();
}

void ExaminerNavigation::setViewport(int width, int height) {
    width_ = std::max(width, 1);
    height_ = std::max(height, 1);
}

glm::dvec3 ExaminerNavigation::viewDirection() const {
    return glm::normalize(glm::dvec3(camera_->orientation().matrix() * glm::dvec4(0, 0, -1, 0)));
}

glm::dvec3 ExaminerNavigation::upDirection() const {
    return glm::normalize(glm::dvec3(camera_->orientation().matrix() * glm::dvec4(0, 1, 0, 0)));
}

glm::dvec3 ExaminerNavigation::focalPoint() const {
    return glm::dvec3(camera_->position()) + viewDirection() * double(camera_->focalDistance());
}

glm::dvec3 ExaminerNavigation::trackballVector(const glm::dvec2& pixel) const {
    // Bell's trackball: a sphere of radius 0.8 (of the smaller half-size) in the middle, a
    // hyperbolic sheet outside, so drags beyond the sphere still turn smoothly.
    const double m = 0.5 * double(std::min(width_, height_));
    const glm::dvec2 p((pixel.x - 0.5 * width_) / m, (0.5 * height_ - pixel.y) / m);
    constexpr double r = 0.8;
    const double d2 = glm::dot(p, p);
    const double z = d2 <= 0.5 * r * r ? std::sqrt(r * r - d2) : 0.5 * r * r / std::sqrt(d2);
    return {p.x, p.y, z};
}

void ExaminerNavigation::rotate(const glm::dvec2& from, const glm::dvec2& to) {
    stopSeek();
    const glm::dquat turn = rotationBetween(trackballVector(from), trackballVector(to));
    const glm::dvec3 focus = focalPoint();
    // The scene turns by `turn` in eye space, so the camera turns the other way about the focus.
    const glm::dquat orientation = camera_->orientation().quat() * glm::inverse(turn);
    camera_->orientation = rotationFromQuat(orientation);
    const glm::dvec3 back = glm::normalize(camera_->orientation().quat()) * glm::dvec3(0, 0, 1);
    camera_->position = glm::vec3(focus + back * double(camera_->focalDistance()));
}

double ExaminerNavigation::worldUnitsPerPixel() const {
    return 2.0 * halfHeightAtFocus(*camera_, aspect()) / double(height_);
}

void ExaminerNavigation::pan(const glm::dvec2& from, const glm::dvec2& to) {
    stopSeek();
    const glm::dvec2 delta = (to - from) * worldUnitsPerPixel();
    const glm::dvec3 right = glm::normalize(glm::cross(viewDirection(), upDirection()));
    // Dragging right moves the scene right: the camera goes left (y is down in pixels).
    camera_->position =
        glm::vec3(glm::dvec3(camera_->position()) - right * delta.x + upDirection() * delta.y);
}

void ExaminerNavigation::dolly(double factor) {
    if (!(factor > 0.0)) return;
    stopSeek();
    if (auto* o = dynamic_cast<OrthographicCamera*>(camera_.get())) {
        o->height = float(double(o->height()) * factor);
        return;
    }
    const glm::dvec3 focus = focalPoint();
    const double distance = std::max(double(camera_->focalDistance()) * factor, 1e-6);
    camera_->focalDistance = float(distance);
    camera_->position = glm::vec3(focus - viewDirection() * distance);
}

void ExaminerNavigation::zoom(double factor) {
    if (!(factor > 0.0)) return;
    if (auto* o = dynamic_cast<OrthographicCamera*>(camera_.get())) {
        o->height = float(double(o->height()) * factor);
    } else {
        auto& p = static_cast<PerspectiveCamera&>(*camera_);
        p.heightAngle = float(std::clamp(double(p.heightAngle()) * factor, 0.01, 3.0));
    }
}

void ExaminerNavigation::viewAll(const Box3& box) {
    stopSeek();
    camera_->viewAll(box, aspect());
}

std::optional<CameraPose> ExaminerNavigation::seekTarget(const glm::dvec3& point,
                                                         double fraction) const {
    CameraPose to = pose();
    const glm::dvec3 forward = viewDirection();
    // Distance along the view to the point after moving `fraction` of the way there.
    const double along = glm::dot(point - to.position, forward);
    if (!(along > 0.0)) return std::nullopt;
    to.focalDistance = along * (1.0 - std::clamp(fraction, 0.0, 0.99));
    to.position = point - forward * to.focalDistance;
    return to;
}

CameraPose ExaminerNavigation::pose() const {
    return {glm::dvec3(camera_->position()), glm::normalize(camera_->orientation().quat()),
            double(camera_->focalDistance())};
}

void ExaminerNavigation::applyPose(const CameraPose& pose) {
    camera_->position = glm::vec3(pose.position);
    camera_->orientation = rotationFromQuat(pose.orientation);
    camera_->focalDistance = float(pose.focalDistance);
}

void ExaminerNavigation::seek(const glm::dvec3& point, double fraction) {
    stopSeek();
    const auto to = seekTarget(point, fraction);
    if (!to) return;
    camera_->position = glm::vec3(to->position);
    camera_->focalDistance = float(to->focalDistance);
}

bool ExaminerNavigation::startSeek(const glm::dvec3& point, double fraction, double duration) {
    const auto to = seekTarget(point, fraction);
    if (!to) return false;
    if (!(duration > 0.0)) {
        seek(point, fraction);
        return true;
    }
    seek_ = Seek{pose(), *to, camera_->orientation(), duration, 0.0};
    return true;
}

CameraPose ExaminerNavigation::seekPose(double t) const {
    if (!seek_) return pose();
    return interpolatePose(seek_->from, seek_->to, seekEasing(t / seek_->duration));
}

bool ExaminerNavigation::stepSeek(double seconds) {
    if (!seek_) return false;
    seek_->elapsed += std::max(seconds, 0.0);
    // (With a little slack, so that frames summing to the duration end it in rounding.)
    if (seek_->elapsed >= seek_->duration * (1.0 - 1e-9)) {
        // Exactly the fields seek() sets: the orientation field is left as it was.
        camera_->position = glm::vec3(seek_->to.position);
        camera_->focalDistance = float(seek_->to.focalDistance);
        camera_->orientation = seek_->endOrientation;
        seek_.reset();
        return false;
    }
    applyPose(seekPose(seek_->elapsed));
    return true;
}

bool ExaminerNavigation::isOrthographic() const {
    return dynamic_cast<const OrthographicCamera*>(camera_.get()) != nullptr;
}

void ExaminerNavigation::toggleProjection() {
    const double halfHeight = halfHeightAtFocus(*camera_, 1.0); // before ADJUST_CAMERA widening
    const double focal = std::max(double(camera_->focalDistance()), 1e-6);
    ref_ptr<Camera> next;
    if (isOrthographic()) {
        auto p = PerspectiveCamera::create();
        p->heightAngle = float(2.0 * std::atan(halfHeight / focal));
        next = p;
    } else {
        auto o = OrthographicCamera::create();
        o->height = float(2.0 * halfHeight);
        next = o;
    }
    next->position = camera_->position();
    next->orientation = camera_->orientation();
    next->focalDistance = camera_->focalDistance();
    next->nearDistance = camera_->nearDistance();
    next->farDistance = camera_->farDistance();
    next->aspectRatio = camera_->aspectRatio();
    camera_ = next;
}

void ExaminerNavigation::saveHome() {
    home_.orthographic = isOrthographic();
    home_.position = camera_->position();
    home_.orientation = camera_->orientation();
    home_.focalDistance = camera_->focalDistance();
    home_.nearDistance = camera_->nearDistance();
    home_.farDistance = camera_->farDistance();
    if (auto* o = dynamic_cast<OrthographicCamera*>(camera_.get())) home_.height = o->height();
    if (auto* p = dynamic_cast<PerspectiveCamera*>(camera_.get()))
        home_.heightAngle = p->heightAngle();
}

void ExaminerNavigation::goHome() {
    stopSeek();
    if (home_.orthographic != isOrthographic()) toggleProjection();
    camera_->position = home_.position;
    camera_->orientation = home_.orientation;
    camera_->focalDistance = home_.focalDistance;
    camera_->nearDistance = home_.nearDistance;
    camera_->farDistance = home_.farDistance;
    if (auto* o = dynamic_cast<OrthographicCamera*>(camera_.get())) o->height = home_.height;
    if (auto* p = dynamic_cast<PerspectiveCamera*>(camera_.get()))
        p->heightAngle = home_.heightAngle;
}

void ExaminerNavigation::adjustClipping(const Box3& box) {
    if (box.isEmpty()) return;
    const glm::dvec3 forward = viewDirection();
    const double radius = std::max(0.5 * glm::length(box.size()), 1e-6);
    double along = glm::dot(box.center() - glm::dvec3(camera_->position()), forward);
    if (isOrthographic() && along - radius < radius * 1e-3) {
        // Stepping back along the view changes nothing in an orthographic image.
        const double step = radius - along + radius * 0.01;
        camera_->position = glm::vec3(glm::dvec3(camera_->position()) - forward * step);
        camera_->focalDistance = float(double(camera_->focalDistance()) + step);
        along += step;
    }
    const double farD = std::max(along + radius, 1e-3);
    const double nearD = std::max(along - radius, farD * 1e-3);
    // 1% slack so that the box's own faces are not clipped by rounding.
    const float n = float(nearD * 0.99), f = float(farD * 1.01);
    if (camera_->nearDistance() != n) camera_->nearDistance = n;
    if (camera_->farDistance() != f) camera_->farDistance = f;
}

Ray ExaminerNavigation::pixelRay(const glm::dvec2& pixel) const {
    const glm::dmat4 view = camera_->viewMatrix();
    const glm::dmat4 projection = camera_->projectionMatrix(aspect());
    const glm::dmat4 inverse = glm::inverse(projection * view);
    const glm::dvec2 ndc(2.0 * pixel.x / double(width_) - 1.0,
                         1.0 - 2.0 * pixel.y / double(height_));
    glm::dvec4 nearPoint = inverse * glm::dvec4(ndc, -1.0, 1.0);
    glm::dvec4 farPoint = inverse * glm::dvec4(ndc, 1.0, 1.0);
    nearPoint /= nearPoint.w;
    farPoint /= farPoint.w;
    return {glm::dvec3(nearPoint), glm::normalize(glm::dvec3(farPoint - nearPoint))};
}

} // namespace volsg
