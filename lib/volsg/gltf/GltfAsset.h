#pragma once
// A glTF 2.0 file as plain data, validated: what the loader makes and what drawing, bounding
// boxes and picking use. Nothing here points into the file's buffers any more.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/math/Box3.h>

namespace volsg {

enum class GltfAlphaMode { Opaque, Mask, Blend };

/// A material's use of a texture (glTF textureInfo): which texture, which TEXCOORD_n set, and
/// the normal texture's `scale` or the occlusion texture's `strength`.
struct GltfTextureRef {
    int texture = -1; ///< index into GltfAsset::textures; -1: none
    int texCoord = 0; ///< 0 or 1
    float scale = 1.0f;
    bool present() const { return texture >= 0; }
};

/// glTF's metallic-roughness material, with the core extras and KHR_materials_unlit.
struct GltfMaterial {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    GltfTextureRef baseColorTexture; ///< sRGB
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    GltfTextureRef metallicRoughnessTexture; ///< roughness in G, metallic in B (linear)
    GltfTextureRef normalTexture;            ///< tangent space, scale = normal scale
    GltfTextureRef occlusionTexture;         ///< R channel, scale = strength
    GltfTextureRef emissiveTexture;          ///< sRGB
    glm::vec3 emissiveFactor{0.0f};
    GltfAlphaMode alphaMode = GltfAlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    bool unlit = false; ///< KHR_materials_unlit: base colour only
};

/// A decoded image, always 8-bit RGBA, rows top first as in the file.
struct GltfImage {
    std::string name;
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

/// Filters and wraps, as the GL enum values glTF uses (GL_LINEAR = 9729, GL_REPEAT = 10497...).
/// A filter the file leaves out is LINEAR (magnification) or LINEAR_MIPMAP_LINEAR.
struct GltfSampler {
    int magFilter = 9729; // GL_LINEAR
    int minFilter = 9987; // GL_LINEAR_MIPMAP_LINEAR
    int wrapS = 10497;    // GL_REPEAT
    int wrapT = 10497;
};

struct GltfTexture {
    int image = 0;
    int sampler = -1; ///< -1: GltfSampler's defaults
};

/// One draw of a mesh: points, lines or triangles (strips, fans and loops are converted to
/// lists), every attribute as float (normalized integers already divided out), sparse
/// accessors applied. Optional attributes are empty or have one entry per position.
struct GltfPrimitive {
    enum class Kind { Points, Lines, Triangles };
    Kind kind = Kind::Triangles;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;  ///< empty: flat normals (glTF's rule), made when drawn
    std::vector<glm::vec4> tangents; ///< xyz and the bitangent sign in w
    std::vector<glm::vec2> texCoords0, texCoords1;
    std::vector<glm::vec4> colors; ///< COLOR_0, RGB given alpha 1
    /// 1 per point, 2 per line, 3 per triangle; every index < positions.size().
    std::vector<std::uint32_t> indices;
    int material = -1; ///< -1: glTF's default material
    Box3 bounds;       ///< of the positions, mesh coordinates

    std::size_t triangleCount() const { return kind == Kind::Triangles ? indices.size() / 3 : 0; }
};

struct GltfMesh {
    std::string name;
    std::vector<GltfPrimitive> primitives;
};

/// A mesh placed by a node of the scene: `matrix` maps the mesh's coordinates to the model's
/// (the product of the node's and its ancestors' transforms).
struct GltfInstance {
    int node = 0;
    int mesh = 0;
    glm::dmat4 matrix{1.0};
};

struct GltfAsset {
    std::string fileName;
    std::vector<GltfMesh> meshes;
    std::vector<GltfMaterial> materials;
    std::vector<GltfTexture> textures;
    std::vector<GltfImage> images;
    std::vector<GltfSampler> samplers;
    /// The default scene's (scene, else scene 0, else every root node) mesh nodes, depth first.
    std::vector<GltfInstance> instances;
    /// Of every instanced vertex in model coordinates (exact, not a box of boxes).
    Box3 bounds;

    /// The material of a primitive (glTF's default material for -1).
    const GltfMaterial& materialOf(const GltfPrimitive& primitive) const {
        static const GltfMaterial defaultMaterial;
        return primitive.material >= 0 ? materials[std::size_t(primitive.material)]
                                       : defaultMaterial;
    }
};

} // namespace volsg
