#pragma once
// What the shapes read from the state: the nearest node in scope for each thing a shape needs
// (Inventor's elements), gathered in one pass, and the vertex data they give.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/geometry/VertexShapes.h>

namespace volsg {

class Complexity;
class DrawStyle;
class Environment;
class LightModel;
class Material;
class Node;
class ShapeHints;
class State;
class Texture2;
class TextureCoordinateBinding;
class VertexProperty;

/// The nearest node in scope for each element a shape reads. A shape's own vertexProperty
/// (its field) comes before the state for what it has.
struct ShapeState {
    const Node* coordinates = nullptr;   ///< Coordinate3, Coordinate4 or VertexProperty
    const Node* normals = nullptr;       ///< Normal or VertexProperty
    const Node* normalBinding = nullptr; ///< NormalBinding or VertexProperty
    /// TextureCoordinate2, VertexProperty, or a TextureCoordinatePlane, -Environment or
    /// -Default function.
    const Node* textureCoords = nullptr;
    const TextureCoordinateBinding* textureCoordBinding = nullptr;
    const Node* diffuse = nullptr;         ///< Material, BaseColor or VertexProperty
    const Node* transparency = nullptr;    ///< Material or VertexProperty
    const Node* materialBinding = nullptr; ///< MaterialBinding or VertexProperty
    const Material* material = nullptr;    ///< ambient, specular, emissive, shininess
    const ShapeHints* hints = nullptr;
    const DrawStyle* drawStyle = nullptr;
    const Complexity* complexity = nullptr;
    const LightModel* lightModel = nullptr;
    const Environment* environment = nullptr;
    const Texture2* texture = nullptr; ///< null, or one with texels
    glm::mat4 textureMatrix{1.0f};     ///< the Texture2Transforms in scope, composed
    std::uint64_t textureTransformKey = 0;

    /// Changes whenever anything the mesh of a shape depends on changes (the nodes above and
    /// their versions, whether a texture is in scope).
    std::uint64_t meshKey() const;
    /// Complexity value in [0, 1] (0.5 without a Complexity node).
    float complexityValue() const;
    /// A texture in scope that has texels (Texture2 with an empty image turns texturing off).
    bool textured() const { return texture != nullptr; }
};

/// Reads the state from the innermost entry out. `own` is the shape's vertexProperty field
/// value (or null).
ShapeState gatherShapeState(const State& state, const VertexProperty* own);

/// The arrays the state gives a vertex shape, with their bindings; `storage` keeps what had to
/// be computed (Coordinate4 divided by w, colours packed from the materials).
struct VertexArrays {
    std::vector<glm::vec3> points;
    std::vector<glm::vec4> colors;
};
VertexAttributes vertexAttributes(const ShapeState& shape, VertexArrays& storage);

/// The diffuse colour and alpha of material `i` (the last one for an index beyond them), from
/// the nearest diffuse and transparency nodes (Inventor's defaults without them).
glm::vec4 materialColor(const ShapeState& shape, std::size_t i);
/// How many materials the diffuse and transparency nodes hold (the larger count; at least 1).
std::size_t materialCount(const ShapeState& shape);

} // namespace volsg
