#include <volsg/render/GpuMesh.h>
#include <volsg/render/ShapeDetail.h>

#include <algorithm>
#include <cmath>

namespace volsg {

const GpuMesh& ShapeDetail::choose(const RenderView& view, const glm::dmat4& model,
                                   const GpuMesh& full) const {
    if (levels.empty()) return full;
    const glm::dmat4 toEye = view.view * model;
    // The largest stretch of the model-view: a length in the shape's units is at most this
    // long in the eye's.
    const double scale =
        std::sqrt(std::max({glm::dot(glm::dvec3(toEye[0]), glm::dvec3(toEye[0])),
                            glm::dot(glm::dvec3(toEye[1]), glm::dvec3(toEye[1])),
                            glm::dot(glm::dvec3(toEye[2]), glm::dvec3(toEye[2]))}));
    const glm::dvec4 eye = toEye * glm::dvec4(centre, 1.0);
    // Clip w at the sphere's point nearest the eye (the eye looks down -z): the depth that
    // magnifies most under a perspective, 1 under an orthographic projection.
    const glm::dmat4& p = view.projection;
    const double nearestZ = eye.z + scale * radius;
    const double w = p[2][3] * nearestZ + p[3][3];
    const double pixelsPerUnit =
        0.5 * std::max(std::abs(p[0][0]) * view.width, std::abs(p[1][1]) * view.height) / w;
    const double pixelsPerShapeUnit = scale * pixelsPerUnit;
    if (!(w > 0.0) || !std::isfinite(pixelsPerShapeUnit)) return full;
    for (auto it = levels.rbegin(); it != levels.rend(); ++it)
        if (it->deviation * pixelsPerShapeUnit <= kShapeDetailPixels) return *it->mesh;
    return full;
}

const GpuMesh& ShapeDetail::chooseFor(FrameContext& frame, const glm::dmat4& model,
                                      const GpuMesh& full) const {
    if (!frame.debug.shapeDetail) return full;
    const GpuMesh& chosen = choose(frame.view, model, full);
    frame.coarserShapes += &chosen != &full;
    return chosen;
}

} // namespace volsg
