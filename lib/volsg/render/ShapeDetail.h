#pragma once
// Level of detail for curved shapes a few pixels wide: a Sphere, Cone or Cylinder that covers
// a handful of pixels is drawn from a coarser tessellation whose surface lies within a quarter
// of a pixel of the true one. The image stays that of the shape; the triangles, which bound
// llvmpipe's frame in scenes of many small shapes, drop (a 5-pixel sphere: 80 instead of 420).

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/render/FrameContext.h>

namespace volsg {

struct GpuMesh;

/// The most a coarser mesh's surface may lie from the true one, projected, in pixels.
constexpr double kShapeDetailPixels = 0.25;

/// A shape's coarser meshes (Shape::buildCoarserMeshes on the GPU), kept beside its full mesh.
struct ShapeDetail {
    struct Level {
        std::shared_ptr<GpuMesh> mesh;
        double deviation = 0.0; ///< from the true surface, in the shape's units
    };
    std::vector<Level> levels; ///< finest first
    /// A sphere around the shape, in its units: where it is nearest the eye bounds the scale.
    glm::dvec3 centre{0.0};
    double radius = 0.0;

    /// The coarsest level whose deviation projects below kShapeDetailPixels in `view` for a
    /// shape drawn with `model`; `full` where none does (or the eye is inside the shape's
    /// sphere, or a matrix is not finite).
    const GpuMesh& choose(const RenderView& view, const glm::dmat4& model,
                          const GpuMesh& full) const;
    /// choose() when `frame.debug.shapeDetail` (else `full`), counted in frame.coarserShapes.
    const GpuMesh& chooseFor(FrameContext& frame, const glm::dmat4& model,
                             const GpuMesh& full) const;
};

} // namespace volsg
