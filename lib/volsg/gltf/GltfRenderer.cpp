#include <volsg/gltf/GltfAsset.h>
#include <volsg/gltf/GltfGpuAsset.h>
#include <volsg/gltf/GltfRenderer.h>
#include <volsg/gltf/GltfShaders.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

namespace volsg {

namespace {

constexpr float kAmbientIntensity = 0.2f; // Inventor's default SoEnvironment

} // namespace

GltfRenderer::GltfRenderer() {
    maxClipPlanes_ = queryMaxClipPlanes(kMaxClipPlanes);
    program_ =
        shaders::surfaceProgram(shaders::gltfVertex, shaders::gltfFragment, maxClipPlanes_, "glTF");
    scopeLocations_ = SurfaceScope::Locations::of(program_);
    program_.use();
    program_.set("uBaseColorTexture", 0);
    program_.set("uMetallicRoughnessTexture", 1);
    program_.set("uNormalTexture", 2);
    program_.set("uOcclusionTexture", 3);
    program_.set("uEmissiveTexture", 4);
    program_.set("uAmbient", kAmbientIntensity);
}

GltfRenderer& GltfRenderer::of(FrameContext& frame) {
    return frame.cache.shared<GltfRenderer>();
}

void GltfRenderer::submit(const FrameContext& frame, const GltfAsset& asset,
                          const GltfGpuAsset& gpu, const GltfLook& look) {
    const RenderPass pass = frame.pass;
    if (pass == RenderPass::Volume) return;
    view_ = frame.view;

    NodeState node;
    node.extraEmissive = look.extraEmissive;
    node.alphaScale = 1.0f - std::clamp(look.transparency, 0.0f, 1.0f);
    if (look.boxClip) {
        const GltfBoxClip& b = *look.boxClip;
        node.boxClip = true;
        node.boxFromWorld = b.boxFromWorld;
        node.boxMin = b.min;
        node.boxMax = b.max;
        node.boxInside = std::max(b.insideOpacity, 0.0f);
        node.boxOutside = std::max(b.outsideOpacity, 0.0f);
        auto partial = [](float o) { return o > 0.0f && o < 1.0f; };
        if (partial(node.boxInside) || partial(node.boxOutside)) node.forceBlend = true;
    }
    if (node.alphaScale < 1.0f) node.forceBlend = true;

    // Which primitives belong to this pass; nothing else is gathered when none do.
    auto blended = [&](const GltfPrimitive& p) {
        return node.forceBlend || asset.materialOf(p).alphaMode == GltfAlphaMode::Blend;
    };
    bool any = false;
    for (const GltfInstance& instance : asset.instances)
        for (const GltfPrimitive& p : asset.meshes[std::size_t(instance.mesh)].primitives)
            if (!p.indices.empty() && blended(p) == (pass == RenderPass::Transparent)) any = true;
    if (!any) return;

    node.scope.setLights(look.lights, "a GltfModel", "it");
    node.scope.setClipPlanes(look.clipPlanes, maxClipPlanes_, "a GltfModel");

    ShapeRenderer& shapes = frame.shapes;
    const glm::dmat4& nodeModel = look.model;
    for (const GltfInstance& instance : asset.instances) {
        const glm::dmat4 model = nodeModel * instance.matrix;
        const double det = glm::determinant(glm::dmat3(model));
        if (!(std::abs(det) > 0.0) || !std::isfinite(det)) continue; // flattened: nothing shows
        const glm::mat3 normalMatrix(glm::transpose(glm::inverse(glm::dmat3(model))));
        const GltfMesh& mesh = asset.meshes[std::size_t(instance.mesh)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const GltfPrimitive& primitive = mesh.primitives[p];
            if (primitive.indices.empty()) continue;
            const bool blend = blended(primitive);
            if (blend != (pass == RenderPass::Transparent)) continue;
            if (!blend && !shapes.ownsNextOpaque()) continue; // another process's (sort-last)
            DrawItem item;
            item.gpu = &gpu.primitive(std::size_t(instance.mesh), p);
            item.material = &asset.materialOf(primitive);
            const GltfMaterial& m = *item.material;
            item.textures = {gpu.texture(m.baseColorTexture.texture, true),
                             gpu.texture(m.metallicRoughnessTexture.texture, false),
                             gpu.texture(m.normalTexture.texture, false),
                             gpu.texture(m.occlusionTexture.texture, false),
                             gpu.texture(m.emissiveTexture.texture, true)};
            item.model = glm::mat4(model);
            item.normalMatrix = normalMatrix;
            item.mirrored = det < 0.0;
            item.blend = blend;
            if (!blend) {
                draw(shapes, node, item);
            } else {
                const glm::dvec4 centre =
                    frame.view.view * model * glm::dvec4(primitive.bounds.center(), 1.0);
                shapes.queueTransparent(centre.z,
                                        [this, &shapes, node, item] { draw(shapes, node, item); });
            }
        }
    }
}

void GltfRenderer::draw(ShapeRenderer& shapes, const NodeState& node, const DrawItem& item) {
    const GltfGpuPrimitive& gpu = *item.gpu;
    const GltfMaterial& m = *item.material;
    const Program& p = program_;
    p.use();
    const glm::mat4 viewProjection(view_.projection * view_.view);
    p.set("uViewProjection", viewProjection);
    p.set("uViewer", glm::vec4(view_.viewer));
    p.set("uModel", item.model);
    p.set("uNormalMatrix", item.normalMatrix);

    node.scope.upload(scopeLocations_);
    shapes.setClipDistances(node.scope.clipPlaneCount);
    p.set("uExtraEmissive", node.extraEmissive);
    p.set("uAlphaScale", node.alphaScale);
    p.set("uBoxClip", node.boxClip ? 1 : 0);
    if (node.boxClip) {
        p.set("uBoxFromWorld", node.boxFromWorld);
        p.set("uBoxMin", node.boxMin);
        p.set("uBoxMax", node.boxMax);
        p.set("uBoxInsideOpacity", node.boxInside);
        p.set("uBoxOutsideOpacity", node.boxOutside);
    }

    p.set("uBaseColorFactor", m.baseColorFactor);
    p.set("uMetallicFactor", m.metallicFactor);
    p.set("uRoughnessFactor", m.roughnessFactor);
    p.set("uNormalScale", m.normalTexture.scale);
    p.set("uOcclusionStrength", m.occlusionTexture.scale);
    p.set("uEmissive", m.emissiveFactor);
    p.set("uAlphaMode", m.alphaMode == GltfAlphaMode::Opaque ? 0
                        : m.alphaMode == GltfAlphaMode::Mask ? 1
                                                             : 2);
    p.set("uAlphaCutoff", m.alphaCutoff);
    p.set("uUnlit", m.unlit || gpu.mode != GL_TRIANGLES ? 1 : 0);
    p.set("uHasNormals", gpu.hasNormals ? 1 : 0);
    p.set("uHasTangents", gpu.hasTangents ? 1 : 0);
    p.set("uHasColors", gpu.hasColors ? 1 : 0);

    static constexpr const char* use[5] = {"uUseBaseColorTexture", "uUseMetallicRoughnessTexture",
                                           "uUseNormalTexture", "uUseOcclusionTexture",
                                           "uUseEmissiveTexture"};
    static constexpr const char* setNames[5] = {"uSetBaseColor", "uSetMetallicRoughness",
                                                "uSetNormal", "uSetOcclusion", "uSetEmissive"};
    const int sets[5] = {m.baseColorTexture.texCoord, m.metallicRoughnessTexture.texCoord,
                         m.normalTexture.texCoord, m.occlusionTexture.texCoord,
                         m.emissiveTexture.texCoord};
    for (int i = 0; i < 5; ++i) {
        const Texture* t = item.textures[std::size_t(i)];
        p.set(use[i], t ? 1 : 0);
        p.set(setNames[i], sets[i]);
        if (t) t->bind(GLuint(i));
    }
    glActiveTexture(GL_TEXTURE0);

    // Constants of the attributes a primitive lacks are context state: set them per draw.
    glVertexAttrib4f(kGltfNormal, 0.0f, 0.0f, 1.0f, 0.0f);
    glVertexAttrib4f(kGltfTangent, 1.0f, 0.0f, 0.0f, 1.0f);
    glVertexAttrib4f(kGltfTexCoord0, 0.0f, 0.0f, 0.0f, 1.0f);
    glVertexAttrib4f(kGltfTexCoord1, 0.0f, 0.0f, 0.0f, 1.0f);
    glVertexAttrib4f(kGltfColor, 1.0f, 1.0f, 1.0f, 1.0f);

    const bool cull = !m.doubleSided && gpu.mode == GL_TRIANGLES;
    if (cull) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(item.mirrored ? GL_CW : GL_CCW);
    }
    gpu.vertexArray.bind();
    glDrawElements(gpu.mode, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
    VertexArray::unbind();
    if (!item.blend) shapes.countDraw(); // queued ones are counted by drawQueuedTransparent()
    if (cull) {                          // the passes run with culling off
        glDisable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
    }
}

} // namespace volsg
