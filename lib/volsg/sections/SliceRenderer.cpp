#include <volsg/sections/SliceRenderer.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include <volsg/core/Error.h>
#include <volsg/core/KeyMixing.h>
#include <volsg/gl/Buffer.h>
#include <volsg/gl/Program.h>
#include <volsg/gl/Shader.h>
#include <volsg/gl/Texture.h>
#include <volsg/gl/VertexArray.h>
#include <volsg/render/FrameContext.h>
#include <volsg/render/ShapeRenderer.h>
#include <volsg/sections/SectionShaders.h>
#include <volsg/slicing/DataFormat.h>
#include <volsg/slicing/SliceShaders.h>
#include <volsg/slicing/TransferTable.h>

namespace volsg {

namespace {

/// A slice polygon has at most 12 edge crossings (a plane through box corners repeats them),
/// so at most 10 triangles.
constexpr std::size_t kMaxPolygonVertices = 30;

/// The program and a small vertex buffer for the polygon, per context.
struct SectionProgram {
    Program program;
    Buffer vertices;
    VertexArray vertexArray;
};

/// The whole volume as one 3D texture (and its tags), per VolumeData node and grid.
struct SectionDataTexture {
    Texture data, tags;
    DataFormat format;
    bool uploaded = false;
};

/// Transfer table and tag map, per VolumeData node, grid and transfer functions.
struct SectionTables {
    TransferTable table;
    Texture tableTexture, tagRowTexture;
    bool built = false;
};

void prepareProgram(SectionProgram& p) {
    if (p.program) return;
    const std::string prelude =
        "#version 330 core\n#define ENTRIES " + std::to_string(TransferTable::kEntries) +
        "\n#define MAX_CLIP_PLANES " + std::to_string(SliceRenderer::kMaxClipPlanes) + "\n";
    const Shader vertex(GL_VERTEX_SHADER, prelude + shaders::sectionVertex, "section");
    const Shader fragment(GL_FRAGMENT_SHADER,
                          prelude + shaders::sliceCommon + shaders::sectionFragment, "section");
    p.program = Program({&vertex, &fragment}, "section");
    p.program.use();
    p.program.set("uData", 0);
    p.program.set("uTable", 1);
    p.program.set("uTags", 2);
    p.program.set("uTagRows", 3);
    p.vertices = Buffer(GL_ARRAY_BUFFER);
    p.vertices.setData(nullptr, kMaxPolygonVertices * sizeof(glm::vec3), GL_DYNAMIC_DRAW);
    p.vertexArray = VertexArray::create();
    p.vertexArray.setAttribute(0, p.vertices, 3);
    VertexArray::unbind();
}

/// Float data goes up with its non-finite voxels replaced as the reference replaces them.
std::vector<float> finiteFloats(const VolumeGrid& grid) {
    const auto [lowest, highest] = grid.minMax();
    const auto src = grid.data<float>();
    std::vector<float> out(src.size());
    for (std::size_t i = 0; i < src.size(); ++i) {
        const float x = src[i];
        out[i] = std::isnan(x) || x == -std::numeric_limits<float>::infinity() ? float(lowest)
                 : x == std::numeric_limits<float>::infinity()                 ? float(highest)
                                                                               : x;
    }
    return out;
}

void prepareData(SectionDataTexture& t, const VolumeInScope& volume) {
    if (t.uploaded) return;
    const VolumeGrid& grid = *volume.data;
    const glm::ivec3 n = grid.dimensions();
    t.format = dataFormatOf(grid.type());
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &maxSize);
    if (n.x > maxSize || n.y > maxSize || n.z > maxSize)
        throw Error("a slice's volume of " + std::to_string(n.x) + "x" + std::to_string(n.y) + "x" +
                    std::to_string(n.z) + " voxels exceeds GL_MAX_3D_TEXTURE_SIZE " +
                    std::to_string(maxSize));
    std::vector<std::uint16_t> shifted;
    std::vector<float> floats;
    const void* pixels = grid.bytes().data();
    if (grid.type() == VoxelType::Short) {
        const auto src = grid.data<std::int16_t>();
        shifted.resize(src.size());
        for (std::size_t i = 0; i < src.size(); ++i)
            shifted[i] = std::uint16_t(int(src[i]) + 32768);
        pixels = shifted.data();
    } else if (grid.type() == VoxelType::Float) {
        floats = finiteFloats(grid);
        pixels = floats.data();
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    t.data = Texture(GL_TEXTURE_3D); // linear, clamp to edge
    t.data.image3D(t.format.internalFormat, n.x, n.y, n.z, GL_RED, t.format.type, pixels);
    if (volume.tags) {
        const bool wide = volume.tags->type() == VoxelType::UShort;
        t.tags = Texture(GL_TEXTURE_3D);
        t.tags.setFilter(GL_NEAREST, GL_NEAREST); // integer textures are never filtered
        t.tags.image3D(wide ? GL_R16UI : GL_R8UI, n.x, n.y, n.z, GL_RED_INTEGER,
                       wide ? GL_UNSIGNED_SHORT : GL_UNSIGNED_BYTE, volume.tags->bytes().data());
    }
    t.uploaded = true;
}

void prepareTables(SectionTables& t, const VolumeInScope& volume) {
    if (t.built) return;
    const auto [lo, hi] = volume.data->naturalRange();
    t.table.build(volume.transferFunctions, {lo, hi});
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    if (t.table.rows() > maxSize)
        throw Error(std::to_string(t.table.rows() - 1) +
                    " tagged transfer functions apply to one slice; at most " +
                    std::to_string(maxSize - 1) + " fit its transfer table");
    t.tableTexture = Texture(GL_TEXTURE_2D); // linear, clamped
    t.tableTexture.image2D(GL_RGBA32F, TransferTable::kWidth, t.table.rows(), GL_RGBA, GL_FLOAT,
                           t.table.texels().data());
    if (t.table.rows() > 1) {
        t.tagRowTexture = Texture(GL_TEXTURE_2D);
        t.tagRowTexture.setFilter(GL_NEAREST, GL_NEAREST);
        t.tagRowTexture.image2D(GL_R16UI, TransferTable::kTagMapSide, TransferTable::kTagMapSide,
                                GL_RED_INTEGER, GL_UNSIGNED_SHORT, t.table.tagRows().data());
    }
    t.built = true;
}

/// Everything one slice draw needs, captured during traversal (transparent slices are drawn
/// after it, sorted with the transparent shapes). The cache entries live until the frame ends.
struct SliceDraw {
    SectionProgram* shared = nullptr; ///< its vertex buffer is rewritten per draw
    const SectionDataTexture* data = nullptr;
    const SectionTables* tables = nullptr;
    std::vector<glm::vec3> triangles;
    std::vector<glm::vec4> localPlanes;
    glm::mat4 modelViewProjection{1.0f};
    glm::vec3 halfExtent{0.0f}, invSpacing{1.0f}, voxelCount{1.0f};
    SliceStyle style;
    bool tagged = false;
};

void issue(const SliceDraw& d) {
    const Program& program = d.shared->program;
    program.use();
    program.set("uModelViewProjection", d.modelViewProjection);
    program.set("uHalfExtent", d.halfExtent);
    program.set("uInvSpacing", d.invSpacing);
    program.set("uVoxelCount", d.voxelCount);
    program.set("uDataScale", d.data->format.scale);
    program.set("uDataOffset", d.data->format.offset);
    program.set("uLinear", d.style.linear ? 1 : 0);
    program.set("uAlphaUse", int(d.style.alphaUse));
    program.set("uTagged", d.tagged ? 1 : 0);
    program.set("uClipPlaneCount", int(d.localPlanes.size()));
    if (!d.localPlanes.empty())
        program.set("uClipPlanes", d.localPlanes.data(), int(d.localPlanes.size()));
    d.data->data.bind(0);
    d.tables->tableTexture.bind(1);
    if (d.tagged) {
        d.data->tags.bind(2);
        d.tables->tagRowTexture.bind(3);
    }
    glActiveTexture(GL_TEXTURE0);
    d.shared->vertices.setSubData(0, d.triangles.data(), d.triangles.size() * sizeof(glm::vec3));
    d.shared->vertexArray.bind();
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(d.triangles.size()));
    VertexArray::unbind();
    glUseProgram(0);
}

} // namespace

void SliceRenderer::draw(FrameContext& frame, const VolumeInScope& volume, const SlicePlane& plane,
                         const SliceStyle& style) {
    const bool transparent = style.alphaUse == SliceAlphaUse::AsIs;
    if (frame.pass != (transparent ? RenderPass::Transparent : RenderPass::Opaque)) return;
    const glm::dvec3 half = volume.halfExtent();
    std::vector<glm::vec3> triangles = plane.polygon(half);
    if (triangles.empty() || triangles.size() > kMaxPolygonVertices) return;

    const std::vector<glm::dvec4>& worldPlanes = volume.clipPlanes;
    if (worldPlanes.size() > std::size_t(kMaxClipPlanes))
        throw Error(std::to_string(worldPlanes.size()) +
                    " ClipPlanes are in scope of a slice; it clips with at most " +
                    std::to_string(kMaxClipPlanes));
    // World plane (a, d) at x = M p keeps a . M p >= d: the local normal is M^T a.
    std::vector<glm::vec4> localPlanes;
    const glm::dmat4 modelTranspose = glm::transpose(volume.model);
    for (const glm::dvec4& w : worldPlanes)
        localPlanes.emplace_back(
            glm::vec3(glm::dvec3(modelTranspose * glm::dvec4(w.x, w.y, w.z, 0.0))), float(w.w));

    const std::uint64_t gridKey =
        mixKey(std::uint64_t(reinterpret_cast<std::uintptr_t>(volume.data.get())),
               std::uint64_t(reinterpret_cast<std::uintptr_t>(volume.tags.get())));
    SectionProgram& shared = frame.cache.shared<SectionProgram>();
    prepareProgram(shared);
    // Without a data owner the data itself keys its copy.
    const Object& owner = volume.dataOwner ? *volume.dataOwner : *volume.data;
    SectionDataTexture& data = frame.cache.get<SectionDataTexture>(owner, gridKey);
    prepareData(data, volume);
    SectionTables& tables =
        frame.cache.get<SectionTables>(owner, mixKey(gridKey, volume.transferKey));
    prepareTables(tables, volume);

    SliceDraw d;
    d.shared = &shared;
    d.data = &data;
    d.tables = &tables;
    d.triangles = std::move(triangles);
    d.localPlanes = std::move(localPlanes);
    d.modelViewProjection = glm::mat4(frame.view.projection * frame.view.view * volume.model);
    d.halfExtent = glm::vec3(half);
    d.invSpacing = glm::vec3(1.0 / volume.data->spacing());
    d.voxelCount = glm::vec3(volume.data->dimensions());
    d.style = style;
    d.tagged = volume.tags && tables.table.rows() > 1;
    if (!transparent) {
        frame.shapes.setClipDistances(0); // this shader clips by discarding
        issue(d);
        // Volumes copy the opaque depth only when something opaque was drawn.
        frame.shapes.countDraw();
        return;
    }
    // Sorted with the transparent shapes by the view depth of the polygon's centre.
    glm::dvec3 centre(0.0);
    for (const glm::vec3& p : d.triangles)
        centre += glm::dvec3(p);
    centre /= double(d.triangles.size());
    const double eyeDepth = (frame.view.view * volume.model * glm::dvec4(centre, 1.0)).z;
    ShapeRenderer& shapes = frame.shapes;
    shapes.queueTransparent(eyeDepth, [d, &shapes] {
        shapes.setClipDistances(0);
        issue(d);
    });
}

} // namespace volsg
