#include <volsg/core/Error.h>
#include <volsg/gl/Shader.h>
#include <volsg/nodes/LightModel.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/Shape.h>
#include <volsg/render/GpuMesh.h>
#include <volsg/render/RenderAction.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/render/ShapeShaders.h>

#include <algorithm>
#include <string>

#include <glm/gtc/type_ptr.hpp>

namespace volsg {

// A shape is drawn from its mesh, uploaded once per (node, mesh key) and kept in the
// Renderer's NodeCache while the node is drawn.
void Shape::render(RenderAction& action) {
    if (action.pass() == RenderPass::Volume) return;
    const State& state = action.state();
    GpuMesh& gpu = action.cache<GpuMesh>(*this, meshKey(state));
    if (!gpu.uploaded) action.shapeRenderer().upload(gpu, mesh(state));
    action.shapeRenderer().submit(action, gpu);
}

namespace {

// Inventor's SoMaterial defaults, used without a Material in scope or for an empty field.
constexpr glm::vec3 kDefaultAmbient{0.2f}, kDefaultDiffuse{0.8f}, kDefaultSpecular{0.0f},
    kDefaultEmissive{0.0f};
constexpr float kDefaultShininess = 0.2f, kDefaultTransparency = 0.0f;
/// Inventor's default SoEnvironment: white ambient light of intensity 0.2.
constexpr float kAmbientIntensity = 0.2f;

template <class F, class V> V firstOr(const F& field, V fallback) {
    return field.empty() ? fallback : field[0];
}

/// The matrix that maps normals: the cofactor matrix of the model's 3x3 part. It is the
/// inverse transpose times the determinant, so it keeps directions right (the shader
/// normalises, two-sided lighting ignores the sign) and stays defined for a flattening scale.
glm::mat3 normalMatrixOf(const glm::dmat4& model) {
    const glm::dvec3 a(model[0]), b(model[1]), c(model[2]);
    return glm::mat3(glm::dmat3(glm::cross(b, c), glm::cross(c, a), glm::cross(a, b)));
}

std::string shaderPrelude(int maxClipPlanes) {
    return "#version 330 core\n#define MAX_LIGHTS " + std::to_string(ShapeRenderer::kMaxLights) +
           "\n#define MAX_CLIP_PLANES " + std::to_string(maxClipPlanes) + "\n";
}

} // namespace

ShapeRenderer::ShapeRenderer() {
    GLint maxDistances = 8;
    glGetIntegerv(GL_MAX_CLIP_DISTANCES, &maxDistances);
    maxClipPlanes_ = std::clamp(int(maxDistances), 1, kMaxClipPlanes);
    const std::string prelude = shaderPrelude(maxClipPlanes_);
    const Shader vertex(GL_VERTEX_SHADER, prelude + shaders::shapeVertex, "shape");
    const Shader fragment(GL_FRAGMENT_SHADER, prelude + shaders::shapeFragment, "shape");
    program_ = Program({&vertex, &fragment}, "shape");
    ++programBuilds_;
    const Program& p = program_;
    loc_ = {p.uniformLocation("uModel"),          p.uniformLocation("uNormalMatrix"),
            p.uniformLocation("uViewProjection"), p.uniformLocation("uClipPlanes"),
            p.uniformLocation("uClipPlaneCount"), p.uniformLocation("uLit"),
            p.uniformLocation("uHasNormals"),     p.uniformLocation("uHasColors"),
            p.uniformLocation("uEmissive"),       p.uniformLocation("uAmbient"),
            p.uniformLocation("uDiffuse"),        p.uniformLocation("uSpecular"),
            p.uniformLocation("uShininess"),      p.uniformLocation("uAlpha"),
            p.uniformLocation("uViewer"),         p.uniformLocation("uLightCount"),
            p.uniformLocation("uLightVector"),    p.uniformLocation("uLightColor")};
}

void ShapeRenderer::upload(GpuMesh& gpu, const Mesh& mesh) {
    gpu.upload(mesh);
    ++meshUploads_;
}

void ShapeRenderer::beginFrame(const RenderView& view) {
    view_ = view;
    transparentQueue_.clear();
    drawsLastFrame_ = 0;
    // Per-frame uniforms are program state: set once, they survive other programs' use.
    program_.use();
    const glm::mat4 viewProjection(view.projection * view.view);
    glUniformMatrix4fv(loc_.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection));
    const glm::vec4 viewer(view.viewer);
    glUniform4fv(loc_.viewer, 1, glm::value_ptr(viewer));
}

void ShapeRenderer::beginPass() {
    enabledClipPlanes_ = maxClipPlanes_; // unknown after other nodes' passes: switch all off
    setClipDistances(0);
}

void ShapeRenderer::endFrame() {
    setClipDistances(0);
    glUseProgram(0);
    VertexArray::unbind();
    transparentQueue_.clear();
}

void ShapeRenderer::submit(RenderAction& action, const GpuMesh& gpu) {
    if (gpu.indexCount == 0) return;
    const Material* material = action.state().nearestNode<Material>();
    const float transparency =
        material ? firstOr(material->transparency, kDefaultTransparency) : kDefaultTransparency;
    const bool transparent = transparency > 0.0f || gpu.hasTranslucentColors;
    if (action.pass() == RenderPass::Opaque && !transparent) {
        DrawItem item;
        fill(action, gpu, item);
        draw(item);
    } else if (action.pass() == RenderPass::Transparent && transparent) {
        fill(action, gpu, transparentQueue_.emplace_back());
    }
}

void ShapeRenderer::queueTransparent(double eyeDepth, std::function<void()> draw) {
    DrawItem& item = transparentQueue_.emplace_back();
    item.eyeDepth = eyeDepth;
    item.external = std::move(draw);
}

void ShapeRenderer::fill(RenderAction& action, const GpuMesh& gpu, DrawItem& item) {
    const State& state = action.state();
    item.mesh = &gpu;
    const glm::dmat4& model = state.modelMatrix();
    item.model = glm::mat4(model);
    item.normalMatrix = normalMatrixOf(model);
    const glm::dvec4 centre = action.viewMatrix() * model * glm::dvec4(gpu.bounds.center(), 1.0);
    item.eyeDepth = gpu.bounds.isEmpty() ? 0.0 : centre.z;

    if (const Material* m = state.nearestNode<Material>()) {
        item.emissive = firstOr(m->emissiveColor, kDefaultEmissive);
        item.ambient = firstOr(m->ambientColor, kDefaultAmbient) * kAmbientIntensity;
        item.diffuse = firstOr(m->diffuseColor, kDefaultDiffuse);
        item.specular = firstOr(m->specularColor, kDefaultSpecular);
        item.shininess = firstOr(m->shininess, kDefaultShininess) * 128.0f;
        item.alpha = 1.0f - firstOr(m->transparency, kDefaultTransparency);
    } else {
        item.emissive = kDefaultEmissive;
        item.ambient = kDefaultAmbient * kAmbientIntensity;
        item.diffuse = kDefaultDiffuse;
        item.specular = kDefaultSpecular;
        item.shininess = kDefaultShininess * 128.0f;
        item.alpha = 1.0f - kDefaultTransparency;
    }
    item.lit = gpu.mode == GL_TRIANGLES;
    // Inventor's LightModel BASE_COLOR: unlit, the diffuse (or vertex) colour alone.
    if (const LightModel* lightModel = state.nearestNode<LightModel>();
        lightModel && lightModel->model() == LightModel::BASE_COLOR) {
        item.lit = false;
        item.emissive = glm::vec3(0.0f);
    }

    if (item.lit) {
        action.lightsInScope(lightScratch_);
        if (lightScratch_.size() > std::size_t(kMaxLights))
            throw Error(std::to_string(lightScratch_.size()) +
                        " lights are in scope of a shape; at most " + std::to_string(kMaxLights) +
                        " light a shape");
        item.lightCount = int(lightScratch_.size());
        for (std::size_t i = 0; i < lightScratch_.size(); ++i) {
            item.lightVectors[i] = lightScratch_[i].vector;
            item.lightColors[i] = lightScratch_[i].color;
        }
    } else {
        item.lightCount = 0;
    }

    action.clipPlanesInScope(planeScratch_);
    if (planeScratch_.size() > std::size_t(maxClipPlanes_))
        throw Error(std::to_string(planeScratch_.size()) +
                    " ClipPlanes are in scope of a shape, but this OpenGL clips with at most " +
                    std::to_string(maxClipPlanes_) + " (GL_MAX_CLIP_DISTANCES)");
    item.clipPlaneCount = int(planeScratch_.size());
    for (std::size_t i = 0; i < planeScratch_.size(); ++i)
        item.clipPlanes[i] = glm::vec4(planeScratch_[i]);
}

void ShapeRenderer::setClipDistances(int count) {
    for (int i = count; i < enabledClipPlanes_; ++i)
        glDisable(GLenum(GL_CLIP_DISTANCE0 + i));
    for (int i = enabledClipPlanes_; i < count; ++i)
        glEnable(GLenum(GL_CLIP_DISTANCE0 + i));
    enabledClipPlanes_ = count;
}

void ShapeRenderer::draw(const DrawItem& item) {
    if (item.external) {
        item.external();
        ++drawsLastFrame_;
        return;
    }
    const GpuMesh& gpu = *item.mesh;
    program_.use();
    glUniformMatrix4fv(loc_.model, 1, GL_FALSE, glm::value_ptr(item.model));
    glUniformMatrix3fv(loc_.normalMatrix, 1, GL_FALSE, glm::value_ptr(item.normalMatrix));
    glUniform1i(loc_.lit, item.lit ? 1 : 0);
    glUniform1i(loc_.hasNormals, gpu.hasNormals ? 1 : 0);
    glUniform1i(loc_.hasColors, gpu.hasColors ? 1 : 0);
    glUniform3fv(loc_.emissive, 1, glm::value_ptr(item.emissive));
    glUniform3fv(loc_.ambient, 1, glm::value_ptr(item.ambient));
    glUniform3fv(loc_.diffuse, 1, glm::value_ptr(item.diffuse));
    glUniform3fv(loc_.specular, 1, glm::value_ptr(item.specular));
    glUniform1f(loc_.shininess, item.shininess);
    glUniform1f(loc_.alpha, item.alpha);
    glUniform1i(loc_.lightCount, item.lightCount);
    if (item.lightCount > 0) {
        glUniform4fv(loc_.lightVector, item.lightCount, glm::value_ptr(item.lightVectors[0]));
        glUniform3fv(loc_.lightColor, item.lightCount, glm::value_ptr(item.lightColors[0]));
    }
    glUniform1i(loc_.clipPlaneCount, item.clipPlaneCount);
    if (item.clipPlaneCount > 0)
        glUniform4fv(loc_.clipPlanes, item.clipPlaneCount, glm::value_ptr(item.clipPlanes[0]));
    setClipDistances(item.clipPlaneCount);
    gpu.vertexArray.bind();
    glDrawElements(gpu.mode, gpu.indexCount, GL_UNSIGNED_INT, nullptr);
    ++drawsLastFrame_;
}

void ShapeRenderer::drawQueuedTransparent() {
    // Back to front; equal depths keep scene order.
    std::stable_sort(transparentQueue_.begin(), transparentQueue_.end(),
                     [](const DrawItem& a, const DrawItem& b) { return a.eyeDepth < b.eyeDepth; });
    for (const DrawItem& item : transparentQueue_)
        draw(item);
    transparentQueue_.clear();
}

} // namespace volsg
