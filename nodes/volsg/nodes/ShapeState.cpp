#include <volsg/nodes/ShapeState.h>

#include <algorithm>

#include <volsg/geometry/MeshKey.h>
#include <volsg/nodes/BaseColor.h>
#include <volsg/nodes/Bindings.h>
#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Coordinate4.h>
#include <volsg/nodes/DrawStyle.h>
#include <volsg/nodes/Environment.h>
#include <volsg/nodes/LightModel.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Normal.h>
#include <volsg/nodes/ShapeHints.h>
#include <volsg/nodes/Texture2.h>
#include <volsg/nodes/Texture2Transform.h>
#include <volsg/nodes/TextureCoordinate2.h>
#include <volsg/nodes/TextureCoordinateDefault.h>
#include <volsg/nodes/TextureCoordinateEnvironment.h>
#include <volsg/nodes/TextureCoordinatePlane.h>
#include <volsg/nodes/VertexProperty.h>
#include <volsg/state/State.h>

namespace volsg {

namespace {

template <class T> void take(const Node*& slot, const Node& node) {
    if (!slot && node.isA<T>()) slot = &node;
}
template <class T> void take(const T*& slot, const Node& node) {
    if (!slot && node.isA<T>()) slot = static_cast<const T*>(&node);
}

/// What a VertexProperty supplies, as Coin's SoVertexProperty::doAction sets elements only
/// for its non-empty fields.
void takeVertexProperty(ShapeState& s, const VertexProperty& vp) {
    if (!s.coordinates && !vp.vertex.empty()) s.coordinates = &vp;
    if (!s.normals && !vp.normal.empty()) {
        s.normals = &vp;
        if (!s.normalBinding) s.normalBinding = &vp;
    }
    if (!s.textureCoords && !vp.texCoord.empty()) s.textureCoords = &vp;
    if (!vp.orderedRGBA.empty()) {
        if (!s.diffuse) s.diffuse = &vp;
        if (!s.transparency) s.transparency = &vp;
        if (!s.materialBinding) s.materialBinding = &vp;
    }
}

void take(ShapeState& s, const Node& node) {
    if (node.isA<VertexProperty>()) {
        takeVertexProperty(s, static_cast<const VertexProperty&>(node));
        return;
    }
    take<Coordinate3>(s.coordinates, node);
    take<Coordinate4>(s.coordinates, node);
    take<Normal>(s.normals, node);
    take<NormalBinding>(s.normalBinding, node);
    take<TextureCoordinate2>(s.textureCoords, node);
    take<TextureCoordinatePlane>(s.textureCoords, node);
    take<TextureCoordinateEnvironment>(s.textureCoords, node);
    take<TextureCoordinateDefault>(s.textureCoords, node);
    take(s.textureCoordBinding, node);
    take<MaterialBinding>(s.materialBinding, node);
    if (node.isA<Material>()) {
        take<Material>(s.diffuse, node);
        take<Material>(s.transparency, node);
        take(s.material, node);
    }
    take<BaseColor>(s.diffuse, node);
    take(s.hints, node);
    take(s.drawStyle, node);
    take(s.complexity, node);
    take(s.lightModel, node);
    take(s.environment, node);
}

std::uint64_t mixNode(std::uint64_t key, const Node* node) {
    key = combineMeshKey(key, reinterpret_cast<std::uintptr_t>(node));
    return combineMeshKey(key, node ? node->version() : 0);
}

} // namespace

ShapeState gatherShapeState(const State& state, const VertexProperty* own) {
    ShapeState s;
    if (own) takeVertexProperty(s, *own);
    const Texture2* texture = nullptr;
    bool textureSeen = false;
    const auto& entries = state.entries();
    for (auto it = entries.rbegin(); it != entries.rend(); ++it) {
        const Node& node = *it->node;
        take(s, node);
        if (!textureSeen && node.isA<Texture2>()) {
            textureSeen = true;
            texture = static_cast<const Texture2*>(&node);
        }
    }
    // Texture transforms compose from the outermost in (each one after those before it).
    for (const StateEntry& e : entries)
        if (e.node->isA<Texture2Transform>()) {
            s.textureMatrix =
                s.textureMatrix * static_cast<const Texture2Transform&>(*e.node).matrix();
            s.textureTransformKey = mixNode(s.textureTransformKey, e.node);
        }
    if (texture && !texture->texels().empty()) s.texture = texture;
    return s;
}

std::uint64_t ShapeState::meshKey() const {
    std::uint64_t key = 0x9e3779b97f4a7c15ULL;
    for (const Node* n :
         {coordinates, normals, normalBinding, textureCoords,
          static_cast<const Node*>(textureCoordBinding), diffuse, transparency, materialBinding,
          static_cast<const Node*>(hints), static_cast<const Node*>(complexity)})
        key = mixNode(key, n);
    return combineMeshKey(key, texture ? 1 : 0);
}

float ShapeState::complexityValue() const {
    return complexity ? std::clamp(complexity->value(), 0.0f, 1.0f) : 0.5f;
}

std::size_t materialCount(const ShapeState& s) {
    std::size_t n = 1;
    if (s.diffuse) {
        if (s.diffuse->isA<Material>())
            n = std::max(n, static_cast<const Material*>(s.diffuse)->diffuseColor.size());
        else if (s.diffuse->isA<BaseColor>())
            n = std::max(n, static_cast<const BaseColor*>(s.diffuse)->rgb.size());
        else if (s.diffuse->isA<VertexProperty>())
            n = std::max(n, static_cast<const VertexProperty*>(s.diffuse)->orderedRGBA.size());
    }
    if (s.transparency && s.transparency->isA<Material>())
        n = std::max(n, static_cast<const Material*>(s.transparency)->transparency.size());
    return n;
}

glm::vec4 materialColor(const ShapeState& s, std::size_t i) {
    auto at = [i](const auto& field, auto fallback) {
        return field.empty() ? fallback : field[std::min(i, field.size() - 1)];
    };
    glm::vec4 out(0.8f, 0.8f, 0.8f, 1.0f);
    if (s.diffuse) {
        if (s.diffuse->isA<Material>())
            out = glm::vec4(
                at(static_cast<const Material*>(s.diffuse)->diffuseColor, glm::vec3(0.8f)), 1.0f);
        else if (s.diffuse->isA<BaseColor>())
            out =
                glm::vec4(at(static_cast<const BaseColor*>(s.diffuse)->rgb, glm::vec3(0.8f)), 1.0f);
        else if (s.diffuse->isA<VertexProperty>())
            out = unpackRGBA(
                at(static_cast<const VertexProperty*>(s.diffuse)->orderedRGBA, 0xCCCCCCFFu));
    }
    if (s.transparency && s.transparency->isA<Material>())
        out.a = 1.0f - at(static_cast<const Material*>(s.transparency)->transparency, 0.0f);
    else if (s.transparency && s.transparency->isA<VertexProperty>())
        out.a = unpackRGBA(at(static_cast<const VertexProperty*>(s.transparency)->orderedRGBA,
                              0xCCCCCCFFu))
                    .a;
    // Coin keeps diffuse colour and transparency packed in 8-bit RGBA (SoLazyElement), so a
    // file's diffuseColor 1.7 draws as 1 (legoDog.iv has them).
    return glm::clamp(out, glm::vec4(0.0f), glm::vec4(1.0f));
}

VertexAttributes vertexAttributes(const ShapeState& s, VertexArrays& storage) {
    VertexAttributes a;
    if (s.coordinates) {
        if (s.coordinates->isA<Coordinate3>()) {
            a.points = static_cast<const Coordinate3*>(s.coordinates)->point.getValues();
        } else if (s.coordinates->isA<Coordinate4>()) {
            const auto& point = static_cast<const Coordinate4*>(s.coordinates)->point.getValues();
            storage.points.resize(point.size());
            for (std::size_t i = 0; i < point.size(); ++i)
                storage.points[i] =
                    point[i].w != 0.0f ? glm::vec3(point[i]) / point[i].w : glm::vec3(point[i]);
            a.points = storage.points;
        } else if (s.coordinates->isA<VertexProperty>()) {
            a.points = static_cast<const VertexProperty*>(s.coordinates)->vertex.getValues();
        }
    }
    if (s.normals) {
        if (s.normals->isA<Normal>())
            a.normals = static_cast<const Normal*>(s.normals)->vector.getValues();
        else if (s.normals->isA<VertexProperty>())
            a.normals = static_cast<const VertexProperty*>(s.normals)->normal.getValues();
    }
    if (s.normalBinding) {
        if (s.normalBinding->isA<NormalBinding>())
            a.normalBinding =
                toBinding(static_cast<const NormalBinding*>(s.normalBinding)->value());
        else if (s.normalBinding->isA<VertexProperty>())
            a.normalBinding =
                toBinding(static_cast<const VertexProperty*>(s.normalBinding)->normalBinding());
    }
    if (s.materialBinding) {
        if (s.materialBinding->isA<MaterialBinding>())
            a.materialBinding =
                toBinding(static_cast<const MaterialBinding*>(s.materialBinding)->value());
        else if (s.materialBinding->isA<VertexProperty>())
            a.materialBinding =
                toBinding(static_cast<const VertexProperty*>(s.materialBinding)->materialBinding());
    }
    if (a.materialBinding != Binding::Overall) {
        const std::size_t n = materialCount(s);
        storage.colors.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            storage.colors[i] = materialColor(s, i);
        a.colors = storage.colors;
    }
    if (s.textured()) {
        if (s.textureCoords && s.textureCoords->isA<TextureCoordinate2>())
            a.textureCoords =
                static_cast<const TextureCoordinate2*>(s.textureCoords)->point.getValues();
        else if (s.textureCoords && s.textureCoords->isA<VertexProperty>())
            a.textureCoords =
                static_cast<const VertexProperty*>(s.textureCoords)->texCoord.getValues();
        else if (s.textureCoords && s.textureCoords->isA<TextureCoordinatePlane>()) {
            const auto& plane = static_cast<const TextureCoordinatePlane&>(*s.textureCoords);
            a.planeTextureCoords = true;
            a.planeS = plane.directionS();
            a.planeT = plane.directionT();
        } else
            a.defaultTextureCoords = true;
        if (s.textureCoordBinding)
            a.textureCoordBinding = toBinding(s.textureCoordBinding->value());
    }
    if (s.hints) {
        a.creaseAngle = s.hints->creaseAngle();
        a.clockwise = s.hints->vertexOrdering() == ShapeHints::CLOCKWISE;
        a.convexFaces = s.hints->faceType() == ShapeHints::CONVEX;
    }
    return a;
}

} // namespace volsg
