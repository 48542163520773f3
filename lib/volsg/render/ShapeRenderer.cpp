#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/fields/Values.h>
#include <volsg/render/GpuMesh.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/render/ShapeShaders.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

namespace volsg {

namespace {

/// The matrix that maps normals: the cofactor matrix of the model's 3x3 part. It is the
/// inverse transpose times the determinant, so it keeps directions right (the shader
/// normalises, two-sided lighting ignores the sign) and stays defined for a flattening scale.
glm::mat3 normalMatrixOf(const glm::dmat4& model) {
    const glm::dvec3 a(model[0]), b(model[1]), c(model[2]);
    return glm::mat3(glm::dmat3(glm::cross(b, c), glm::cross(c, a), glm::cross(a, b)));
}

} // namespace

ShapeRenderer::Locations ShapeRenderer::locate(const Program& p) const {
    auto at = [&p](const char* name) { return p.uniformLocation(name); };
    return {at("uModel"),        at("uNormalMatrix"),  at("uViewProjection"),
            at("uView"),         at("uTextureMatrix"), at("uEmissive"),
            at("uAmbient"),      at("uDiffuse"),       at("uSpecular"),
            at("uShininess"),    at("uAlpha"),         at("uViewer"),
            at("uSpot"),         at("uSpotExponent"),  at("uAttenuation"),
            at("uTextureModel"), at("uBlendColor"),    at("uFogType"),
            at("uFogColor"),     at("uFogVisibility"), SurfaceScope::Locations::of(p)};
}

ShapeRenderer::ShapeRenderer() {
    maxClipPlanes_ = queryMaxClipPlanes(kMaxClipPlanes);
    instanceBuffer_ = Buffer(GL_ARRAY_BUFFER);
}

const ShapeRenderer::Locations& ShapeRenderer::useVariant(const DrawItem& item, bool instanced) {
    const GpuMesh& gpu = *item.mesh;
    const int lights = item.scope.lightCount;
    bool positional = false;
    for (int i = 0; i < lights; ++i)
        positional = positional || item.scope.lightVectors[std::size_t(i)].w != 0.0f;
    // The constants the program is specialised by (ShapeShaders.h), each defined true or
    // false; the first three are tested with #ifdef as well, and defined only when true.
    const std::pair<const char*, bool> constants[] = {
        {"INSTANCED", instanced},
        {"VERTEX_LIGHTING", item.vertexLighting},
        // No clip plane in scope: the vertex stage writes no clip distance (none is enabled).
        {"NO_CLIP_PLANES", item.scope.clipPlaneCount == 0},
        {"LIT", item.lit},
        {"HAS_NORMALS", gpu.hasNormals},
        {"NONZERO_NORMALS", gpu.hasNormals && std::isfinite(gpu.shading.normal)},
        {"HAS_COLORS", gpu.hasColors},
        {"TWO_SIDED", item.twoSided},
        {"CULL_BY_NORMAL", item.cull && drawsOutline(item)},
        {"TEXTURED", item.textureModel >= 0},
        {"SPHERE_MAP", item.textureModel >= 0 && item.sphereMap},
        {"FOG", item.environment.fogType != 0},
        {"SPECULAR", item.specularOn},
        {"ORTHOGRAPHIC", view_.viewer.w == 0.0},
        {"POSITIONAL_LIGHTS", positional}};
    constexpr std::size_t kPresenceTested = 3;
    unsigned key = unsigned(lights); // 0 to kMaxLights: four bits
    for (std::size_t i = 0; i < std::size(constants); ++i)
        key |= unsigned(constants[i].second) << (4 + i);
    auto [found, added] = variants_.try_emplace(key);
    Variant& v = found->second;
    if (added) {
        std::string defines = "#define LIGHT_COUNT " + std::to_string(lights) + "\n";
        for (std::size_t i = 0; i < std::size(constants); ++i) {
            const auto& [name, on] = constants[i];
            if (i < kPresenceTested && !on) continue;
            defines += std::string("#define ") + name + (on ? " true\n" : " false\n");
        }
        // The vertex stage sums lights only per vertex (its light uniforms exist only then).
        const std::string vertex = std::string(shaders::shapeVertex) +
                                   (item.vertexLighting ? shaders::shapeLighting : "") +
                                   shaders::shapeVertexMain;
        const std::string fragment = std::string(shaders::shapeFragment) + shaders::shapeLighting +
                                     shaders::shapeFragmentMain;
        try {
            v.program = shaders::surfaceProgram(vertex.c_str(), fragment.c_str(), maxClipPlanes_,
                                                "shape", defines);
        } catch (...) {
            variants_.erase(found);
            throw;
        }
        v.at = locate(v.program);
        v.program.use();
        glUniform1i(v.program.uniformLocation("uTexture"), 0);
        ++programBuilds_;
    }
    v.program.use();
    if (v.frame != frameSerial_) {
        // Per-frame uniforms are program state: set once per frame and program.
        glUniformMatrix4fv(v.at.viewProjection, 1, GL_FALSE, glm::value_ptr(viewProjection_));
        glUniform4fv(v.at.viewer, 1, glm::value_ptr(viewer_));
        glUniformMatrix4fv(v.at.view, 1, GL_FALSE, glm::value_ptr(eye_));
        v.frame = frameSerial_;
    }
    return v.at;
}

void ShapeRenderer::upload(GpuMesh& gpu, const Mesh& mesh) {
    gpu.upload(mesh);
    ++meshUploads_;
}

void ShapeRenderer::beginFrame(const RenderView& view) {
    view_ = view;
    transparentQueue_.clear();
    drawsLastFrame_ = 0;
    vertexLitLastFrame_ = litLastFrame_ = submittedMeshBytes_ = 0;
    submittedIndices_ = 0;
    opaqueOrdinal_ = 0;
    sharedOutLastFrame_ = 0;
    batchesLastFrame_ = batchedShapesLastFrame_ = 0;
    scopes_.clear();
    batches_.clear();
    batchIndex_.clear();
    batched_.clear();
    ++frameSerial_; // the variants take the view uniforms when first used in the frame
    viewProjection_ = glm::mat4(view.projection * view.view);
    viewer_ = glm::vec4(view.viewer);
    eye_ = glm::mat4(view.view);
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
    batches_.clear();
    batchIndex_.clear();
    batched_.clear();
}

void ShapeRenderer::submit(const FrameContext& frame, const GpuMesh& gpu, const ShapeLook& look) {
    if (gpu.indexCount == 0 || look.style == ShapeLook::Style::Invisible) return;
    // Every instance and pass counts (a shape drawn directly or replayed from a render cache).
    submittedIndices_ += std::uint64_t(gpu.indexCount);
    if (submittedIndices_ > limits::maxFrameShapeIndices)
        throw Error("more than " + std::to_string(limits::maxFrameShapeIndices) +
                    " shape vertices in one frame (every USE of a shape draws it again)");
    if (frame.pass == RenderPass::Opaque) submittedMeshBytes_ += gpu.bytes(); // once a frame
    const bool transparent = look.material.transparency > 0.0f || gpu.hasTranslucentColors;
    if (frame.pass == RenderPass::Opaque && !transparent && !ownsNextOpaque()) return;
    if (frame.pass == RenderPass::Opaque && !transparent && batching_) {
        batch(gpu, look);
    } else if (frame.pass == RenderPass::Opaque && !transparent) {
        DrawItem item;
        fill(gpu, look, item);
        countLighting(item);
        draw(item);
    } else if (frame.pass == RenderPass::Transparent && transparent) {
        DrawItem& item = transparentQueue_.emplace_back();
        fill(gpu, look, item);
        countLighting(item);
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
    item.ambient = m.ambient * look.environment.ambient;
    item.diffuse = m.diffuse;
    item.specular = m.specular;
    item.specularOn = m.specular != glm::vec3(0.0f);
    item.shininess = m.shininess * 128.0f;
    item.alpha = 1.0f - m.transparency;
    // Lines and points are lit only with normals of their own; without, Coin draws them in
    // its BASE_COLOR light model (SoIndexedLineSet, SoPointSet): the diffuse colour alone.
    item.lit = gpu.mode == GL_TRIANGLES || gpu.hasNormals;
    if (look.baseColorOnly || !item.lit) {
        item.lit = false;
        item.emissive = glm::vec3(0.0f);
    }
    item.style = look.style;
    item.lineWidth = look.lineWidth > 0.0f ? look.lineWidth : 1.0f;
    item.pointSize = look.pointSize > 0.0f ? look.pointSize : 1.0f;
    item.cull = cullsBackFaces(gpu, look);
    // A mirroring model matrix turns the winding around.
    const bool mirrored = glm::determinant(glm::dmat3(look.model)) < 0.0;
    item.frontClockwise = look.clockwise != mirrored;
    item.twoSided = look.twoSidedLighting;
    const ShapeTexturing& t = look.texturing;
    item.texture = t.texture && t.texture->uploaded ? t.texture : nullptr;
    item.textureModel = item.texture ? int(t.model) : -1;
    item.blendColor = t.blendColor;
    item.textureMatrix = t.matrix;
    item.sphereMap = t.sphereMap;
    item.environment = look.environment;

    item.scope.lightCount = 0;
    item.vertexLighting = item.lit && lightsPerVertex(gpu, look);
    if (item.lit) {
        item.scope.setLights(look.lights, "a shape", "a shape");
        for (std::size_t i = 0; i < look.lights.size(); ++i) {
            const SceneLight& l = look.lights[i];
            item.spots[i] = glm::vec4(l.spotDirection, l.spotCosCutOff);
            item.spotExponents[i] = l.spotExponent;
        }
    }
    item.scope.setClipPlanes(look.clipPlanes, maxClipPlanes_, "a shape");
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
    applyState(useVariant(item, false), item, true);
    gpu.vertexArray.bind();
    drawElements(item, 1);
    restoreState(item);
    ++drawsLastFrame_;
}

void ShapeRenderer::applyState(const Locations& at, const DrawItem& item, bool withMaterial) {
    const GpuMesh& gpu = *item.mesh;
    if (withMaterial) {
        glUniformMatrix4fv(at.model, 1, GL_FALSE, glm::value_ptr(item.model));
        glUniformMatrix3fv(at.normalMatrix, 1, GL_FALSE, glm::value_ptr(item.normalMatrix));
        glUniform3fv(at.emissive, 1, glm::value_ptr(item.emissive));
        glUniform3fv(at.ambient, 1, glm::value_ptr(item.ambient));
        glUniform3fv(at.diffuse, 1, glm::value_ptr(item.diffuse));
        glUniform3fv(at.specular, 1, glm::value_ptr(item.specular));
        glUniform1f(at.shininess, item.shininess);
        glUniform1f(at.alpha, item.alpha);
    }
    item.scope.upload(at.scope);
    const int lights = item.scope.lightCount;
    if (lights > 0) {
        glUniform4fv(at.spot, lights, glm::value_ptr(item.spots[0]));
        glUniform1fv(at.spotExponent, lights, item.spotExponents.data());
    }
    const ShapeEnvironment& env = item.environment;
    glUniform3fv(at.attenuation, 1, glm::value_ptr(env.attenuation));
    if (env.fogType != 0) glUniform1i(at.fogType, env.fogType);
    glUniform3fv(at.fogColor, 1, glm::value_ptr(env.fogColor));
    // Fog without a visibility reaches the far plane; its distance is not known here, so the
    // renderer uses the eye distance to the far plane of the projection.
    float visibility = env.fogVisibility;
    if (!(visibility > 0.0f)) {
        const glm::dmat4& p = view_.projection;
        const bool orthographic = p[3][3] == 1.0;
        visibility =
            orthographic ? float((p[3][2] - 1.0) / p[2][2]) : float(p[3][2] / (p[2][2] + 1.0));
    }
    glUniform1f(at.fogVisibility, visibility);
    glUniform1i(at.textureModel, item.textureModel);
    if (item.textureModel >= 0) {
        item.texture->texture.bind(0);
        glUniform3fv(at.blendColor, 1, glm::value_ptr(item.blendColor));
        glUniformMatrix4fv(at.textureMatrix, 1, GL_FALSE, glm::value_ptr(item.textureMatrix));
    }
    setClipDistances(item.scope.clipPlaneCount);

    // Draw style and culling are restored after the draw (restoreState): the passes run with
    // filled polygons, one-pixel lines and no culling.
    const bool lines = item.style == ShapeLook::Style::Lines;
    const bool points = item.style == ShapeLook::Style::Points || gpu.mode == GL_POINTS;
    if (gpu.mode == GL_TRIANGLES && item.style != ShapeLook::Style::Filled && !drawsOutline(item))
        glPolygonMode(GL_FRONT_AND_BACK, lines ? GL_LINE : GL_POINT);
    // Coin draws with GL_LEQUAL (SoDepthBufferElement): of two faces sharing an edge drawn as
    // lines, the later one shows.
    glDepthFunc(GL_LEQUAL);
    if (item.lineWidth != 1.0f) glLineWidth(item.lineWidth);
    if (points && item.pointSize != 1.0f) glPointSize(item.pointSize);
    // Back faces are culled in every polygon mode, as GL culls for Coin; the edges of an
    // outline are lines, which GL does not cull: the shader drops a back face's by its normal.
    const bool byNormal = item.cull && drawsOutline(item); // the program's CULL_BY_NORMAL
    if (item.cull && !byNormal) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
        glFrontFace(item.frontClockwise ? GL_CW : GL_CCW);
    }
}

bool ShapeRenderer::lightsPerVertex(const GpuMesh& gpu, const ShapeLook& look) const {
    if (lighting_ != RenderDebug::Lighting::Automatic)
        return lighting_ == RenderDebug::Lighting::PerVertex && gpu.hasNormals;
    VertexLightingCase c;
    c.spread = gpu.shading;
    c.bounds = gpu.bounds;
    c.model = look.model;
    c.diffuse = look.material.diffuse;
    c.specular = look.material.specular;
    c.shininess = look.material.shininess * 128.0f;
    c.vertexColors = gpu.hasColors;
    c.lights = look.lights;
    c.attenuation = look.environment.attenuation;
    c.viewer = view_.viewer;
    return predictVertexLightingError(c) <= kVertexLightingTolerance;
}

bool ShapeRenderer::cullsBackFaces(const GpuMesh& gpu, const ShapeLook& look) {
    // Polygons in any draw style (Coin culls in line and point mode too); an outline only with
    // normals to tell a back face's edges by.
    if (!look.cullBackFaces || gpu.mode != GL_TRIANGLES) return false;
    const bool outline = look.style == ShapeLook::Style::Lines && gpu.outlineCount > 0;
    return !outline || gpu.hasNormals;
}

bool ShapeRenderer::drawsOutline(const DrawItem& item) {
    return item.style == ShapeLook::Style::Lines && item.mesh->mode == GL_TRIANGLES &&
           item.mesh->outlineCount > 0;
}

void ShapeRenderer::drawElements(const DrawItem& item, GLsizei instances) {
    const GpuMesh& gpu = *item.mesh;
    // The LINES style of polygons with an outline: its edges, after the triangles.
    const bool outline = drawsOutline(item);
    const GLenum mode = outline ? GL_LINES : gpu.mode;
    const GLsizei count = outline ? gpu.outlineCount : gpu.indexCount;
    const void* first =
        outline ? reinterpret_cast<const void*>(std::size_t(gpu.indexCount) * sizeof(std::uint32_t))
                : nullptr;
    if (instances == 1)
        glDrawElements(mode, count, GL_UNSIGNED_INT, first);
    else
        glDrawElementsInstanced(mode, count, GL_UNSIGNED_INT, first, instances);
}

void ShapeRenderer::restoreState(const DrawItem& item) {
    const GpuMesh& gpu = *item.mesh;
    const bool points = item.style == ShapeLook::Style::Points || gpu.mode == GL_POINTS;
    if (item.cull && !drawsOutline(item)) {
        glDisable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
    }
    if (gpu.mode == GL_TRIANGLES && item.style != ShapeLook::Style::Filled && !drawsOutline(item))
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDepthFunc(GL_LESS); // the passes' default
    if (item.lineWidth != 1.0f) glLineWidth(1.0f);
    if (points && item.pointSize != 1.0f) glPointSize(1.0f);
}

void ShapeTexture::upload(const ImageValue& image, bool repeatS, bool repeatT) {
    if (!texture) texture = Texture(GL_TEXTURE_2D);
    static constexpr GLenum formats[4] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
    static constexpr GLenum internal[4] = {GL_R8, GL_RG8, GL_RGB8, GL_RGBA8};
    const int c = std::clamp(image.components, 1, 4);
    texture.image2D(internal[c - 1], image.width, image.height, formats[c - 1], GL_UNSIGNED_BYTE,
                    image.pixels.data());
    // Grey (and grey + alpha) images act as luminance textures, as in Inventor.
    const GLint swizzle[4][4] = {{GL_RED, GL_RED, GL_RED, GL_ONE},
                                 {GL_RED, GL_RED, GL_RED, GL_GREEN},
                                 {GL_RED, GL_GREEN, GL_BLUE, GL_ONE},
                                 {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA}};
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle[c - 1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, repeatS ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, repeatT ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    glGenerateMipmap(GL_TEXTURE_2D);
    texture.setFilter(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    uploaded = true;
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
