#pragma once
// Where Inventor's lighting may be summed per vertex (as its OpenGL did) instead of per
// fragment: software rasterisers spend most of a polygon frame in the fragment shader, and
// per-vertex lighting differs from per-fragment lighting by an amount that the mesh's shape,
// the material, the lights and the view predict.
//
// Linear interpolation across a primitive of a function with second derivative M, over an
// angle range t, misses it by M t^2 / 8 at most and by about M t^2 / 11 in the root mean
// square. The lit colour is a function of the normal's angle (the diffuse cosine: M = 1; the
// specular power n: M = max(n, 1)), of the light's direction (point lights) and of the view's
// (perspective, through the half vector). Vertex colours multiply the diffuse term: the
// product of two linear functions a and b misses by about |Δa| |Δb| / 5.5 in the RMS.

#include <span>

#include <glm/glm.hpp>

#include <volsg/math/Box3.h>
#include <volsg/render/FrameContext.h>

namespace volsg {

struct Mesh;

/// The per-vertex path is taken where the predicted RMS difference of the lit colour from the
/// per-fragment path is at most this, per channel (colours 0..1).
inline constexpr double kVertexLightingTolerance = 2.0 / 255.0;

/// What of a mesh decides how far per-vertex lighting strays: measured once, when it is
/// uploaded. Weighted by the primitives' sizes (area, length), as pixels are.
struct ShadingSpread {
    /// The quartic mean over primitives of the largest angle between two of their vertex
    /// normals (radians): its square is the RMS of the squared angles. Infinite where the
    /// mesh has no normals or a zero one (the fragment derives a normal there).
    float normal = 0.0f;
    /// The RMS over primitives of the largest step of a vertex colour channel times the
    /// normals' angle (0 without vertex colours), and of the colour step alone.
    float colorTimesNormal = 0.0f, color = 0.0f;
    float longestEdge = 0.0f; ///< local units
};

/// Measures `mesh` (triangles, lines or points).
ShadingSpread measureShadingSpread(const Mesh& mesh);

/// What decides one shape's choice, besides its mesh.
struct VertexLightingCase {
    ShadingSpread spread;
    Box3 bounds; ///< local
    glm::dmat4 model{1.0};
    glm::vec3 diffuse{0.8f}, specular{0.0f};
    float shininess = 0.0f; ///< the exponent (Inventor's 0..1 times 128)
    bool vertexColors = false;
    std::span<const SceneLight> lights;
    glm::vec3 attenuation{0.0f, 0.0f, 1.0f}; ///< squared, linear, constant
    glm::dvec4 viewer{0.0, 0.0, 1.0, 0.0};   ///< RenderView::viewer
};

/// The predicted RMS difference, per channel, between the shape lit per vertex and per
/// fragment; infinite where per-vertex lighting cannot stand in (spot lights, the eye or a
/// point light inside the shape's bounds, a degenerate model, no normals).
double predictVertexLightingError(const VertexLightingCase& c);

} // namespace volsg
