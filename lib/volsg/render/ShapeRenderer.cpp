#include <volsg/core/Error.h>
#include <volsg/gl/Shader.h>
#include <volsg/render/GpuMesh.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/render/ShapeShaders.h>

#include <algorithm>
#include <string>

#include <glm/gtc/type_ptr.hpp>

namespace volsg {

namespace {

/// Inventor's default SoEnvironment: white ambient light of intensity 0.2.
constexpr float kAmbientIntensity = 0.2f;

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

void ShapeRenderer::submit(const FrameContext& frame, const GpuMesh& gpu, const ShapeLook& look) {
    if (gpu.indexCount == 0) return;
    const bool transparent = look.material.transparency > 0.0f || gpu.hasTranslucentColors;
    if (frame.pass == RenderPass::Opaque && !transparent) {
        DrawItem item;
        fill(gpu, look, item);
        draw(item);
    } else if (frame.pass == RenderPass::Transparent && transparent) {
        DrawItem& item = transparentQueue_.emplace_back();
        fill(gpu, look, item);
        const glm::dvec4 centre = view_.view * look.model * glm::dvec4(gpu.bounds.center(), 1.0);
        item.eyeDepth = gpu.bounds.isEmpty() ? 0.0 : centre.z;
    }
}

void ShapeRenderer::queueTransparent(double eyeDepth, std::function<void()> draw) {
    DrawItem& item = transparentQueue_.emplace_back();
    item.eyeDepth = eyeDepth;
    item.external = std::move(draw);
}

void ShapeRenderer::fill(const GpuMesh& gpu, const ShapeLook& look, DrawItem& item) {
    item.mesh = &gpu;
    item.model = glm::mat4(look.model);
    item.normalMatrix = normalMatrixOf(look.model);
    const SurfaceMaterial& m = look.material;
    item.emissive = m.emissive;
    item.ambient = m.ambient * kAmbientIntensity;
    item.diffuse = m.diffuse;
    item.specular = m.specular;
    item.shininess = m.shininess * 128.0f;
    item.alpha = 1.0f - m.transparency;
    item.lit = gpu.mode == GL_TRIANGLES;
    if (look.baseColorOnly) {
        item.lit = false;
        item.emissive = glm::vec3(0.0f);
    }

    if (item.lit) {
        if (look.lights.size() > std::size_t(kMaxLights))
            throw Error(std::to_string(look.lights.size()) +
                        " lights are in scope of a shape; at most " + std::to_string(kMaxLights) +
                        " light a shape");
        item.lightCount = int(look.lights.size());
        for (std::size_t i = 0; i < look.lights.size(); ++i) {
            item.lightVectors[i] = look.lights[i].vector;
            item.lightColors[i] = look.lights[i].color;
        }
    } else {
        item.lightCount = 0;
    }

    if (look.clipPlanes.size() > std::size_t(maxClipPlanes_))
        throw Error(std::to_string(look.clipPlanes.size()) +
                    " ClipPlanes are in scope of a shape, but this OpenGL clips with at most " +
                    std::to_string(maxClipPlanes_) + " (GL_MAX_CLIP_DISTANCES)");
    item.clipPlaneCount = int(look.clipPlanes.size());
    for (std::size_t i = 0; i < look.clipPlanes.size(); ++i)
        item.clipPlanes[i] = glm::vec4(look.clipPlanes[i]);
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
