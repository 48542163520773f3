#include <volsg/actions/PickAction.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <volsg/geometry/RayIntersect.h>
#include <volsg/geometry/RayQuadric.h>
#include <volsg/gltf/GltfAsset.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Cylinder.h>
#include <volsg/nodes/File.h>
#include <volsg/nodes/GltfModel.h>
#include <volsg/nodes/LOD.h>
#include <volsg/nodes/LevelOfDetail.h>
#include <volsg/nodes/ObliqueSlice.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/nodes/PickStyle.h>
#include <volsg/nodes/Shape.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Text2.h>
#include <volsg/nodes/TextFont.h>
#include <volsg/render/InventorRendering.h>
#include <volsg/render/Renderer.h>
#include <volsg/sections/SliceSampler.h>
#include <volsg/text/ScreenTextRenderer.h>
#include <volsg/volumescene/VolumeInScope.h>

namespace volsg {

namespace {

/// PickStyle BOUNDING_BOX: the ray against a local box, hit where it enters the box (where it
/// leaves it when it starts inside), with the normal of that face.
void pickLocalBox(PickAction& action, const Box3& box) {
    if (box.isEmpty()) return;
    const glm::dmat4& model = action.state().modelMatrix();
    const double det = glm::determinant(model);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return; // flattened: nothing to hit
    const Ray local = action.worldRay().transformed(glm::inverse(model));
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    int axis0 = -1, axis1 = -1;
    for (int a = 0; a < 3; ++a) {
        if (local.direction[a] == 0.0) {
            if (local.origin[a] < box.min[a] || local.origin[a] > box.max[a]) return;
            continue;
        }
        double near = (box.min[a] - local.origin[a]) / local.direction[a];
        double far = (box.max[a] - local.origin[a]) / local.direction[a];
        if (near > far) std::swap(near, far);
        if (near > t0) {
            t0 = near;
            axis0 = a;
        }
        if (far < t1) {
            t1 = far;
            axis1 = a;
        }
        if (t0 > t1) return;
    }
    const bool entering = axis0 >= 0; // else the ray starts inside the box
    const double t = entering ? t0 : t1;
    const int axis = entering ? axis0 : axis1;
    if (axis < 0 || !std::isfinite(t)) return;
    glm::dvec3 normal(0.0);
    normal[axis] = (local.direction[axis] > 0.0) == entering ? -1.0 : 1.0;
    action.addLocalHit(local.at(t), normal, 0);
}

void pickShape(PickAction& action, Shape& shape) {
    const PickStyle::Style style = PickStyle::inScope(action.state());
    if (style == PickStyle::UNPICKABLE) return;
    const Mesh& m = shape.mesh(action.state());
    if (style == PickStyle::BOUNDING_BOX) return pickLocalBox(action, m.bounds());
    if (m.primitive != Mesh::Primitive::Triangles || m.indices.size() < 3) return;
    const glm::dmat4& model = action.state().modelMatrix();
    const double det = glm::determinant(model);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return; // flattened: nothing to hit
    // Ray::transformed keeps t, so t stays the world distance along the (unit) world ray.
    const Ray local = action.worldRay().transformed(glm::inverse(model));
    const bool smooth = m.normals.size() == m.positions.size();
    const std::size_t triangles = m.indices.size() / 3;
    for (std::size_t i = 0; i < triangles; ++i) {
        const std::uint32_t ia = m.indices[3 * i], ib = m.indices[3 * i + 1],
                            ic = m.indices[3 * i + 2];
        if (ia >= m.positions.size() || ib >= m.positions.size() || ic >= m.positions.size())
            continue;
        const glm::dvec3 a(m.positions[ia]), b(m.positions[ib]), c(m.positions[ic]);
        const auto hit = intersectTriangle(local, a, b, c);
        if (!hit) continue;
        glm::dvec3 normal(0.0);
        if (smooth)
            normal = (1.0 - hit->u - hit->v) * glm::dvec3(m.normals[ia]) +
                     hit->u * glm::dvec3(m.normals[ib]) + hit->v * glm::dvec3(m.normals[ic]);
        if (!(glm::length(normal) > 0.0)) normal = glm::cross(b - a, c - a);
        const glm::dvec3 point = (1.0 - hit->u - hit->v) * a + hit->u * b + hit->v * c;
        action.addLocalHit(point, glm::normalize(normal), i);
    }
}

/// Sphere, Cone and Cylinder are picked on their exact surfaces, as Coin picks them (not on the
/// tessellation drawn, which changes with Complexity); the primitive index is the part (Cone:
/// 0 sides, 1 bottom; Cylinder: 0 sides, 1 top, 2 bottom).
template <class Round, class Intersect>
void pickRound(PickAction& action, Round& shape, Intersect intersect) {
    const PickStyle::Style style = PickStyle::inScope(action.state());
    if (style == PickStyle::UNPICKABLE) return;
    if (style == PickStyle::BOUNDING_BOX) return pickLocalBox(action, shape.objectBox());
    const glm::dmat4& model = action.state().modelMatrix();
    const double det = glm::determinant(model);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return; // flattened: nothing to hit
    const Ray local = action.worldRay().transformed(glm::inverse(model));
    const auto add = [&](const std::vector<QuadricHit>& hits, std::size_t part) {
        for (const QuadricHit& hit : hits)
            action.addLocalHit(hit.point, hit.normal, part);
    };
    intersect(local, add);
}

void pickSphere(PickAction& action, Sphere& sphere) {
    pickRound(action, sphere, [&](const Ray& ray, const auto& add) {
        add(intersectSphere(ray, std::abs(double(sphere.radius()))), 0);
    });
}

void pickCone(PickAction& action, Cone& cone) {
    pickRound(action, cone, [&](const Ray& ray, const auto& add) {
        const double r = std::abs(double(cone.bottomRadius())), h = std::abs(double(cone.height()));
        if (cone.parts() & Cone::SIDES) add(intersectConeSide(ray, r, h), 0);
        if (cone.parts() & Cone::BOTTOM) add(intersectDisc(ray, r, -0.5 * h, -1.0), 1);
    });
}

void pickCylinder(PickAction& action, Cylinder& cylinder) {
    pickRound(action, cylinder, [&](const Ray& ray, const auto& add) {
        const double r = std::abs(double(cylinder.radius())),
                     h = std::abs(double(cylinder.height()));
        const int parts = cylinder.parts();
        if (parts & Cylinder::SIDES) add(intersectCylinderSide(ray, r, h), 0);
        if (h > 0.0 && (parts & Cylinder::TOP)) add(intersectDisc(ray, r, 0.5 * h, 1.0), 1);
        if (h > 0.0 && (parts & Cylinder::BOTTOM)) add(intersectDisc(ray, r, -0.5 * h, -1.0), 2);
    });
}

/// Text2 is hit where the ray, at the depth of the text's origin, falls in the screen rectangle
/// of its glyphs (Coin's SoText2::rayPick: the quad around the string in the plane through the
/// origin facing the camera). Only pixel picks know the view; the normal faces the camera.
void pickText2(PickAction& action, Text2& text) {
    const auto& view = action.pixelView();
    if (!view) return;
    std::shared_ptr<FontFace> face;
    const ScreenText layout = screenTextInScope(text, action.state(), face);
    if (layout.glyphs.empty() || layout.boxMin == layout.boxMax) return;
    const glm::dmat4& model = action.state().modelMatrix();
    const double det = glm::determinant(model);
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return;
    const glm::dvec3 anchor(model * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dmat4 viewProjection = view->projection * view->view;
    const ScreenTextPlacement place =
        placeScreenText(viewProjection, view->width, view->height, anchor, layout.anchorShift);
    if (!place.visible) return;
    // Where the ray meets the plane through the origin parallel to the screen.
    const Ray& ray = action.worldRay();
    const glm::dvec3 eyeOrigin(view->view * glm::dvec4(ray.origin, 1.0));
    const glm::dvec3 eyeDirection(view->view * glm::dvec4(ray.direction, 0.0));
    const double eyeDepth = (view->view * glm::dvec4(anchor, 1.0)).z;
    if (eyeDirection.z == 0.0) return;
    const double t = (eyeDepth - eyeOrigin.z) / eyeDirection.z;
    if (!(t >= 0.0)) return;
    const glm::dvec3 hit = ray.origin + t * ray.direction;
    const glm::dvec4 clip = viewProjection * glm::dvec4(hit, 1.0);
    if (!(clip.w > 0.0)) return;
    const glm::dvec2 window((clip.x / clip.w + 1.0) * 0.5 * view->width,
                            (clip.y / clip.w + 1.0) * 0.5 * view->height);
    const glm::dvec2 lo = glm::dvec2(place.origin + layout.boxMin);
    const glm::dvec2 hi = glm::dvec2(place.origin + layout.boxMax);
    if (window.x < lo.x || window.x > hi.x || window.y < lo.y || window.y > hi.y) return;
    const glm::dvec3 towardsCamera =
        glm::dvec3(glm::inverse(view->view) * glm::dvec4(0.0, 0.0, 1.0, 0.0));
    const glm::dvec3 localPoint(glm::inverse(model) * glm::dvec4(hit, 1.0));
    // addLocalHit maps normals by the inverse transpose; this is the world normal mapped back.
    const glm::dvec3 localNormal = glm::transpose(glm::dmat3(model)) * towardsCamera;
    action.addLocalHit(localPoint, localNormal, 0);
}

/// Hits the slice where the ray crosses its polygon inside the volume box and the slice is
/// drawn there (not discarded by its alpha use), reporting the voxel and data value
/// (PickedVoxel) with the plane's normal.
void pickSlice(PickAction& action, const VolumeInScope& volume, const SlicePlane& plane,
               const SliceStyle& style) {
    const Ray localRay = action.worldRay().transformed(glm::inverse(volume.model));
    const auto t = plane.intersect(localRay, volume.halfExtent());
    if (!t) return;
    const glm::dvec3 local = localRay.at(*t);
    const SliceSample s = SliceSampler(volume, style).sample(local);
    if (s.discarded()) return;
    action.addLocalHit(local, plane.normal, 0, PickedVoxel{s.voxel, s.voxelValue, s.value, s.tag});
}

void pickOrthoSlice(PickAction& action, OrthoSlice& slice) {
    if (PickStyle::inScope(action.state()) == PickStyle::UNPICKABLE) return slice.doAction(action);
    if (const auto volume = gatherVolumeInScope(action.state()))
        pickSlice(action, *volume, slice.localPlane(*volume->data), slice.style());
    slice.doAction(action);
}

void pickObliqueSlice(PickAction& action, ObliqueSlice& slice) {
    if (PickStyle::inScope(action.state()) == PickStyle::UNPICKABLE) return;
    const auto plane = slice.localPlane();
    if (!plane) return;
    if (const auto volume = gatherVolumeInScope(action.state()))
        pickSlice(action, *volume, *plane, slice.style());
}

/// Whether the ray (t >= 0) meets the box at all: the slab test, to skip whole primitives.
bool rayMeetsBox(const Ray& ray, const Box3& box) {
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (ray.direction[a] == 0.0) {
            if (ray.origin[a] < box.min[a] || ray.origin[a] > box.max[a]) return false;
            continue;
        }
        double near = (box.min[a] - ray.origin[a]) / ray.direction[a];
        double far = (box.max[a] - ray.origin[a]) / ray.direction[a];
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1) return false;
    }
    return true;
}

void pickGltfModel(PickAction& action, GltfModel& model) {
    const PickStyle::Style style = PickStyle::inScope(action.state());
    if (style == PickStyle::UNPICKABLE) return;
    const GltfAsset& a = model.asset();
    if (style == PickStyle::BOUNDING_BOX) return pickLocalBox(action, a.bounds);
    const glm::dmat4& nodeModel = action.state().modelMatrix();
    const StateEntry* boxEntry = action.state().nearest<BoxClip>();
    std::size_t first = 0; // flat index of the instance's primitive's first triangle
    for (const GltfInstance& instance : a.instances) {
        const GltfMesh& mesh = a.meshes[std::size_t(instance.mesh)];
        const glm::dmat4 model = nodeModel * instance.matrix;
        const double det = glm::determinant(glm::dmat3(model));
        const bool invertible = std::abs(det) > 0.0 && std::isfinite(det);
        const Ray local = invertible ? action.worldRay().transformed(glm::inverse(model)) : Ray{};
        const glm::dmat3 normalToNode = glm::transpose(glm::inverse(glm::dmat3(instance.matrix)));
        for (const GltfPrimitive& p : mesh.primitives) {
            const std::size_t triangles = p.triangleCount();
            if (!invertible || triangles == 0 || !rayMeetsBox(local, p.bounds)) {
                first += triangles;
                continue;
            }
            const bool smooth = p.normals.size() == p.positions.size();
            for (std::size_t i = 0; i < triangles; ++i) {
                const std::uint32_t ia = p.indices[3 * i], ib = p.indices[3 * i + 1],
                                    ic = p.indices[3 * i + 2];
                const glm::dvec3 A(p.positions[ia]), B(p.positions[ib]), C(p.positions[ic]);
                const auto hit = intersectTriangle(local, A, B, C);
                if (!hit) continue;
                const double w = 1.0 - hit->u - hit->v;
                const glm::dvec3 point = w * A + hit->u * B + hit->v * C;
                if (boxEntry) { // BoxClip opacity 0 removes geometry for picking too
                    const auto& box = static_cast<const BoxClip&>(*boxEntry->node);
                    const glm::dvec3 world(model * glm::dvec4(point, 1.0));
                    const glm::dvec3 q(glm::inverse(boxEntry->model) * glm::dvec4(world, 1.0));
                    const glm::dvec3 lo(glm::min(box.origin(), box.origin() + box.extent()));
                    const glm::dvec3 hi(glm::max(box.origin(), box.origin() + box.extent()));
                    const bool inside = glm::all(glm::greaterThanEqual(q, lo)) &&
                                        glm::all(glm::lessThanEqual(q, hi));
                    if ((inside ? box.insideOpacity() : box.outsideOpacity()) <= 0.0f) continue;
                }
                glm::dvec3 normal(0.0);
                if (smooth)
                    normal = w * glm::dvec3(p.normals[ia]) + hit->u * glm::dvec3(p.normals[ib]) +
                             hit->v * glm::dvec3(p.normals[ic]);
                if (!(glm::length(normal) > 0.0)) normal = glm::cross(B - A, C - A);
                action.addLocalHit(glm::dvec3(instance.matrix * glm::dvec4(point, 1.0)),
                                   normalToNode * normal, first + i);
            }
            first += triangles;
        }
    }
}

void traverseChild(PickAction& action, Group& group, int index) {
    if (index < 0 || std::size_t(index) >= group.getNumChildren()) return;
    if (Node* child = group.getChild(std::size_t(index))) action.traverse(*child);
}

/// LOD: the child for the distance from the pick's camera (or the ray's origin).
void pickLOD(PickAction& action, LOD& node) {
    const StateView* view = action.state().view();
    const glm::dvec3 eye = view ? view->eye : action.worldRay().origin;
    traverseChild(action, node, node.childFor(eye, action.state().modelMatrix()));
}

/// LevelOfDetail: the child drawn under the pick's camera; a ray given directly has no screen
/// to measure on, and picks the first (most detailed) child.
void pickLevelOfDetail(PickAction& action, LevelOfDetail& node) {
    const StateView* view = action.state().view();
    if (!view || !view->projected) return traverseChild(action, node, 0);
    traverseChild(action, node,
                  levelOfDetailChild(action.state(), node, view->view, view->projection,
                                     view->width, view->height));
}

void pickFile(PickAction& action, File& node) {
    node.update();
    if (node.readError()) throw *node.readError();
    node.doAction(action);
}

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
    pixelView_.reset();
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
        const glm::dmat4 view = camera->viewMatrix(cameraModel);
        const glm::dmat4 projection = camera->projectionMatrix(aspect);
        const PixelRay pr = rayThroughPixel(view, projection, px_, py_, width_, height_);
        if (!pr.valid) return;
        pixelView_ = PixelView{view, projection, width_, height_};
        worldRay_ = pr.ray;
        near_ = pr.nearDistance;
        far_ = pr.farDistance;
        rayValid_ = true;
        // LOD and LevelOfDetail choose their child by this camera.
        StateView stateView;
        stateView.view = view;
        stateView.projection = projection;
        stateView.eye = glm::dvec3(glm::inverse(view)[3]);
        stateView.projected = true;
        stateView.width = width_;
        stateView.height = height_;
        state().setView(stateView);
    }
    if (!rayValid_) return;
    if (!hasPixel_) {
        StateView view;
        view.eye = worldRay_.origin;
        state().setView(view);
    }
    Action::beginTraversal(root);
}

ActionMethods& PickAction::methods() {
    static ActionMethods* table = [] {
        auto* t = new ActionMethods(); // never destroyed: methods may run during exit
        t->add(&pickShape);
        t->add(&pickSphere);
        t->add(&pickCone);
        t->add(&pickCylinder);
        t->add(&pickOrthoSlice);
        t->add(&pickObliqueSlice);
        t->add(&pickGltfModel);
        t->add(&pickLOD);
        t->add(&pickLevelOfDetail);
        t->add(&pickFile);
        t->add(&pickText2);
        return t;
    }();
    return *table;
}

void PickAction::dispatch(Node& node) {
    methods().apply(*this, node);
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
