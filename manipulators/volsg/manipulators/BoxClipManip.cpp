#include <volsg/manipulators/BoxClipManip.h>

#include <algorithm>

#include <volsg/manipulators/DragMath.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Sphere.h>

namespace volsg {

namespace {
glm::dvec3 axisVector(int axis) {
    glm::dvec3 v(0.0);
    v[axis] = 1.0;
    return v;
}
} // namespace

void BoxClipManip::buildHandles(DraggerGeometry& parts) {
    for (int i = 0; i < 12; ++i)
        parts.addPart(Cube::create(), glm::vec3(0.85f));
    for (int i = 0; i < 6; ++i)
        parts.addPart(Cube::create(), glm::vec3(0.2f, 0.8f, 0.3f));
    for (int i = 0; i < 8; ++i)
        parts.addPart(Sphere::create(), glm::vec3(0.25f, 0.5f, 1.0f));
}

void BoxClipManip::placeHandles() {
    const glm::dvec3 lo(origin()), hi = lo + glm::dvec3(extent());
    const glm::dvec3 mid = 0.5 * (lo + hi), size = hi - lo;
    const double s = localHandleSize();
    const float edge = float(s * 0.006), knob = float(s * 0.02);
    // Edges: four along each axis, at the combinations of the other two axes' min and max.
    int id = firstEdge;
    for (int axis = 0; axis < 3; ++axis) {
        const int u = (axis + 1) % 3, v = (axis + 2) % 3;
        for (int corner = 0; corner < 4; ++corner) {
            glm::dvec3 p = mid;
            p[u] = (corner & 1) ? hi[u] : lo[u];
            p[v] = (corner & 2) ? hi[v] : lo[v];
            auto& cube = static_cast<Cube&>(handles().shape(id));
            glm::vec3 dims(edge);
            dims[axis] = float(size[axis]) + edge;
            if (cube.width() != dims.x) cube.width = dims.x;
            if (cube.height() != dims.y) cube.height = dims.y;
            if (cube.depth() != dims.z) cube.depth = dims.z;
            handles().place(id++, p);
        }
    }
    for (int face = 0; face < 6; ++face) {
        glm::dvec3 p = mid;
        p[face / 2] = (face & 1) ? hi[face / 2] : lo[face / 2];
        auto& cube = static_cast<Cube&>(handles().shape(firstFace + face));
        if (cube.width() != 2.0f * knob) {
            cube.width = 2.0f * knob;
            cube.height = 2.0f * knob;
            cube.depth = 2.0f * knob;
        }
        handles().place(firstFace + face, p);
    }
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                           (corner & 4) ? hi.z : lo.z);
        auto& sphere = static_cast<Sphere&>(handles().shape(firstCorner + corner));
        if (sphere.radius() != knob) sphere.radius = knob;
        handles().place(firstCorner + corner, p);
    }
}

void BoxClipManip::startDrag(int part, const Ray& localRay) {
    startMin_ = glm::dvec3(origin());
    startMax_ = startMin_ + glm::dvec3(extent());
    if (part >= firstFace && part < firstCorner) {
        const int face = part - firstFace;
        glm::dvec3 p = 0.5 * (startMin_ + startMax_);
        p[face / 2] = (face & 1) ? startMax_[face / 2] : startMin_[face / 2];
        const auto s = closestLineParameter(localRay, p, axisVector(face / 2));
        grabValid_ = s.has_value();
        startLine_ = s.value_or(0.0);
        startGrab_ = p;
    } else if (part >= firstCorner) {
        const int corner = part - firstCorner;
        startGrab_ = glm::dvec3((corner & 1) ? startMax_.x : startMin_.x,
                                (corner & 2) ? startMax_.y : startMin_.y,
                                (corner & 4) ? startMax_.z : startMin_.z);
        // The corner moves in the plane through it that faces the viewer.
        dragNormal_ = -glm::normalize(localRay.direction);
        const auto t = intersectRayPlane(localRay, dragNormal_, glm::dot(dragNormal_, startGrab_));
        grabValid_ = t.has_value();
        if (t) startGrab_ = localRay.at(*t);
    } else {
        grabValid_ = false; // edges only show the box
    }
}

void BoxClipManip::continueDrag(int part, const Ray& localRay) {
    if (!grabValid_ || part < firstFace) return;
    glm::dvec3 lo = startMin_, hi = startMax_;
    if (part < firstCorner) {
        const int face = part - firstFace, axis = face / 2;
        const auto s = closestLineParameter(localRay, startGrab_, axisVector(axis));
        if (!s) return;
        const double delta = *s - startLine_;
        if (face & 1)
            hi[axis] = std::max(startMax_[axis] + delta, lo[axis] + minimumExtent);
        else
            lo[axis] = std::min(startMin_[axis] + delta, hi[axis] - minimumExtent);
    } else {
        const int corner = part - firstCorner;
        const auto t = intersectRayPlane(localRay, dragNormal_, glm::dot(dragNormal_, startGrab_));
        if (!t) return;
        const glm::dvec3 delta = localRay.at(*t) - startGrab_;
        for (int axis = 0; axis < 3; ++axis) {
            if (corner & (1 << axis))
                hi[axis] = std::max(startMax_[axis] + delta[axis], lo[axis] + minimumExtent);
            else
                lo[axis] = std::min(startMin_[axis] + delta[axis], hi[axis] - minimumExtent);
        }
    }
    setBox(lo, hi);
}

void BoxClipManip::setBox(glm::dvec3 lo, glm::dvec3 hi) {
    const glm::vec3 o(lo), e(hi - lo);
    if (origin() != o) origin = o;
    if (extent() != e) extent = e;
}

} // namespace volsg
