// ShapeRenderer's batching of opaque shapes: grouped by everything but the model matrix and the
// material, drawn as one instanced draw per group (ShapeRenderer.h, setBatching).
#include <volsg/render/GpuMesh.h>
#include <volsg/render/ShapeRenderer.h>

#include <algorithm>
#include <cstddef>
#include <cstring>

#include <glm/gtc/type_ptr.hpp>

namespace volsg {

namespace {

bool sameLight(const SceneLight& a, const SceneLight& b) {
    return a.vector == b.vector && a.color == b.color && a.spotDirection == b.spotDirection &&
           a.spotCosCutOff == b.spotCosCutOff && a.spotExponent == b.spotExponent;
}

/// FNV-1a over the key's bytes (the key is zeroed before it is filled, padding included).
std::uint64_t hashBytes(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (std::size_t i = 0; i < bytes; ++i)
        h = (h ^ p[i]) * 0x100000001b3ULL;
    return h;
}

} // namespace

int ShapeRenderer::internScope(const ShapeLook& look, bool lit) {
    const std::span<const SceneLight> lights = lit ? look.lights : std::span<const SceneLight>();
    // Shapes in a row mostly see the same lights and planes: look back a few scopes only.
    const int n = int(scopes_.size());
    for (int i = n - 1; i >= std::max(0, n - 4); --i) {
        const Scope& s = scopes_[std::size_t(i)];
        if (s.lights.size() != lights.size() || s.clipPlanes.size() != look.clipPlanes.size())
            continue;
        if (!std::equal(lights.begin(), lights.end(), s.lights.begin(), sameLight)) continue;
        if (!std::equal(look.clipPlanes.begin(), look.clipPlanes.end(), s.clipPlanes.begin()))
            continue;
        return i;
    }
    scopes_.push_back(
        {{lights.begin(), lights.end()}, {look.clipPlanes.begin(), look.clipPlanes.end()}});
    return n;
}

void ShapeRenderer::batch(const GpuMesh& gpu, const ShapeLook& look) {
    const bool lit = (gpu.mode == GL_TRIANGLES || gpu.hasNormals) && !look.baseColorOnly;
    BatchKey key;
    std::memset(&key, 0, sizeof key);
    key.mesh = &gpu;
    const ShapeTexturing& t = look.texturing;
    key.texture = t.texture && t.texture->uploaded ? t.texture : nullptr;
    key.scope = internScope(look, lit);
    key.textureModel = key.texture ? int(t.model) : -1;
    key.style = int(look.style);
    key.lineWidth = look.lineWidth;
    key.pointSize = look.pointSize;
    key.lit = lit;
    key.vertexLighting = lit && lightsPerVertex(gpu, look);
    key.specularOn = look.material.specular != glm::vec3(0.0f);
    if (lit) ++litLastFrame_;
    if (key.vertexLighting) ++vertexLitLastFrame_;
    key.cull = cullsBackFaces(gpu, look);
    const bool mirrored = glm::determinant(glm::dmat3(look.model)) < 0.0;
    key.frontClockwise = look.clockwise != mirrored;
    key.twoSided = look.twoSidedLighting;
    if (key.texture) {
        key.sphereMap = t.sphereMap;
        key.blendColor = t.blendColor;
        key.textureMatrix = t.matrix;
    }
    key.attenuation = look.environment.attenuation;
    key.fogColor = look.environment.fogColor;
    key.fogType = look.environment.fogType;
    key.fogVisibility = look.environment.fogVisibility;

    // Find the batch: the last one used first (shapes in a row often share it), then the rest.
    std::size_t index = batches_.size();
    const auto same = [&key](const Batch& b) { return std::memcmp(&b.key, &key, sizeof key) == 0; };
    if (!batches_.empty() && same(batches_.back())) {
        index = batches_.size() - 1;
    } else {
        const std::uint64_t h = hashBytes(&key, sizeof key);
        const auto found = batchIndex_.find(h);
        if (found != batchIndex_.end() && same(batches_[found->second])) index = found->second;
        if (index == batches_.size()) {
            Batch& b = batches_.emplace_back();
            b.key = key;
            fill(gpu, look, b.item); // the shared uniforms of the group
            if (found == batchIndex_.end()) batchIndex_.emplace(h, index);
        }
    }
    Batch& b = batches_[index];
    b.members.push_back(batched_.size());

    Batched& out = batched_.emplace_back();
    const SurfaceMaterial& m = look.material;
    out.instance.model = glm::mat4(look.model);
    float shininess = m.shininess * 128.0f;
    glm::vec3 emissive = m.emissive;
    // Unlit (BASE_COLOR, or lines and points without normals: fill()): diffuse alone.
    if (look.baseColorOnly || !(gpu.mode == GL_TRIANGLES || gpu.hasNormals))
        emissive = glm::vec3(0.0f);
    out.instance.emissiveShininess = glm::vec4(emissive, shininess);
    out.instance.ambient = glm::vec4(m.ambient * look.environment.ambient, 0.0f);
    out.instance.diffuseAlpha = glm::vec4(m.diffuse, 1.0f - m.transparency);
    out.instance.specular = glm::vec4(m.specular, 0.0f);
    const glm::dvec3 centre = gpu.bounds.isEmpty() ? glm::dvec3(0.0) : gpu.bounds.center();
    out.depth = float((view_.view * (look.model * glm::dvec4(centre, 1.0))).z);
}

void ShapeRenderer::flushOpaque() {
    if (batched_.empty()) return;
    // One upload: the batches one after the other, each front to back (larger eye z first).
    instances_.clear();
    instances_.reserve(batched_.size());
    std::vector<std::pair<std::size_t, std::size_t>> ranges; // first instance, count
    ranges.reserve(batches_.size());
    for (Batch& b : batches_) {
        std::stable_sort(b.members.begin(), b.members.end(), [this](std::size_t x, std::size_t y) {
            return batched_[x].depth > batched_[y].depth;
        });
        ranges.emplace_back(instances_.size(), b.members.size());
        for (std::size_t i : b.members)
            instances_.push_back(batched_[i].instance);
    }
    instanceBuffer_.setData(instances_, GL_STREAM_DRAW);

    constexpr GLsizei stride = sizeof(Instance);
    for (std::size_t g = 0; g < batches_.size(); ++g) {
        const DrawItem& item = batches_[g].item;
        const GpuMesh& gpu = *item.mesh;
        applyState(useVariant(item, true), item, false);
        gpu.vertexArray.bind();
        glBindBuffer(GL_ARRAY_BUFFER, instanceBuffer_.id());
        const std::size_t base = ranges[g].first * sizeof(Instance);
        for (GLuint column = 0; column < 4; ++column) {
            glEnableVertexAttribArray(4 + column);
            glVertexAttribPointer(4 + column, 4, GL_FLOAT, GL_FALSE, stride,
                                  reinterpret_cast<const void*>(base + column * sizeof(glm::vec4)));
            glVertexAttribDivisor(4 + column, 1);
        }
        for (GLuint k = 0; k < 4; ++k) {
            const std::size_t offset =
                offsetof(Instance, emissiveShininess) + k * sizeof(glm::vec4);
            glEnableVertexAttribArray(8 + k);
            glVertexAttribPointer(8 + k, 4, GL_FLOAT, GL_FALSE, stride,
                                  reinterpret_cast<const void*>(base + offset));
            glVertexAttribDivisor(8 + k, 1);
        }
        drawElements(item, GLsizei(ranges[g].second));
        restoreState(item);
        ++drawsLastFrame_;
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    batchesLastFrame_ += batches_.size();
    batchedShapesLastFrame_ += batched_.size();
    batches_.clear();
    batchIndex_.clear();
    batched_.clear();
}

} // namespace volsg
