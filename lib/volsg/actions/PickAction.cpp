#include <volsg/actions/PickAction.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/render/Renderer.h>

#include <cmath>

namespace volsg {

void Node::pick(PickAction& action) {
    doAction(action);
}

namespace {

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::dvec3 project(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 h = m * glm::dvec4(p, 1.0);
    return glm::dvec3(h) / h.w;
}

/// The ray of a pixel, from view and projection matrices. The pixel centre is unprojected at
/// the near (NDC z = -1) and far (z = +1) planes; where that line crosses the eye plane
/// (eye z = 0) is the camera: the eye point for a perspective projection, a point of the
/// camera's plane for an orthographic one. Works for any invertible projection.
struct PixelRay {
    Ray ray;
    double nearDistance = 0.0, farDistance = 0.0;
    bool valid = false;
};
PixelRay rayThroughPixel(const glm::dmat4& view, const glm::dmat4& projection, double x, double y,
                         int width, int height) {
    PixelRay out;
    const double ndcX = 2.0 * (x + 0.5) / width - 1.0;
    const double ndcY = 1.0 - 2.0 * (y + 0.5) / height;
    const glm::dmat4 eyeFromClip = glm::inverse(projection);
    const glm::dvec3 eyeNear = project(eyeFromClip, {ndcX, ndcY, -1.0});
    const glm::dvec3 eyeFar = project(eyeFromClip, {ndcX, ndcY, 1.0});
    const double dz = eyeFar.z - eyeNear.z;
    if (!isFinite(eyeNear) || !isFinite(eyeFar) || dz == 0.0) return out;
    const glm::dvec3 eyeOrigin = eyeNear + (-eyeNear.z / dz) * (eyeFar - eyeNear);

    const glm::dmat4 worldFromEye = glm::inverse(view);
    const glm::dvec3 origin = project(worldFromEye, eyeOrigin);
    const glm::dvec3 nearPoint = project(worldFromEye, eyeNear);
    const glm::dvec3 farPoint = project(worldFromEye, eyeFar);
    const glm::dvec3 along = farPoint - nearPoint;
    const double length = glm::length(along);
    if (!isFinite(origin) || !(length > 0.0) || !std::isfinite(length)) return out;
    out.ray = {origin, along / length};
    out.nearDistance = glm::dot(nearPoint - origin, out.ray.direction);
    out.farDistance = glm::dot(farPoint - origin, out.ray.direction);
    out.valid = true;
    return out;
}

} // namespace

void PickAction::setPixel(double x, double y, int width, int height) {
    hasPixel_ = true;
    px_ = x;
    py_ = y;
    width_ = width;
    height_ = height;
}

void PickAction::setCamera(ref_ptr<Camera> camera, const glm::dmat4& cameraModel) {
    camera_ = std::move(camera);
    cameraModel_ = cameraModel;
}

void PickAction::setRay(const Ray& worldRay, double nearDistance, double farDistance) {
    hasPixel_ = false;
    const double length = glm::length(worldRay.direction);
    rayValid_ = length > 0.0 && std::isfinite(length) && isFinite(worldRay.origin);
    worldRay_ = {worldRay.origin, rayValid_ ? worldRay.direction / length : worldRay.direction};
    near_ = nearDistance;
    far_ = farDistance;
}

void PickAction::beginTraversal(Node& root) {
    picked_.reset();
    if (hasPixel_) {
        rayValid_ = false;
        if (width_ <= 0 || height_ <= 0) return;
        const double aspect = double(width_) / double(height_);
        ref_ptr<Camera> camera = camera_;
        glm::dmat4 cameraModel = cameraModel_;
        if (!camera) {
            SceneCamera scene = findOrMakeCamera(root, aspect);
            camera = scene.camera;
            cameraModel = scene.model;
        }
        if (!camera) return;
        const PixelRay pr =
            rayThroughPixel(camera->viewMatrix(cameraModel), camera->projectionMatrix(aspect), px_,
                            py_, width_, height_);
        if (!pr.valid) return;
        worldRay_ = pr.ray;
        near_ = pr.nearDistance;
        far_ = pr.farDistance;
        rayValid_ = true;
    }
    if (!rayValid_) return;
    Action::beginTraversal(root);
}

void PickAction::dispatch(Node& node) {
    node.pick(*this);
}

void PickAction::addLocalHit(const glm::dvec3& localPoint, const glm::dvec3& localNormal,
                             std::size_t primitiveIndex, std::optional<PickedVoxel> voxel) {
    const glm::dmat4& model = state().modelMatrix();
    const glm::dvec3 point(model * glm::dvec4(localPoint, 1.0));
    const double distance = glm::dot(point - worldRay_.origin, worldRay_.direction);
    if (!(distance >= near_ && distance <= far_)) return;
    if (picked_ && !(distance < picked_->distance)) return; // ties: the first one stays

    for (const StateEntry* entry : state().all<ClipPlane>()) {
        const auto& clip = static_cast<const ClipPlane&>(*entry->node);
        const glm::dvec4 plane = ClipPlane::worldPlane(clip.plane(), entry->model);
        if (glm::dot(glm::dvec3(plane), point) < plane.w) return;
    }

    // Normals are covectors: they transform by the inverse transpose.
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(model)));
    glm::dvec3 normal = normalMatrix * localNormal;
    const double length = glm::length(normal);
    normal = length > 0.0 ? normal / length : glm::dvec3(0.0);

    picked_ = PickedPoint{point, normal, distance, path(), primitiveIndex, voxel};
}

} // namespace volsg
