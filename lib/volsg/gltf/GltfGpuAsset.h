#pragma once
// A GltfAsset on the GPU: one VAO per primitive, one GL texture per (texture, colour space).

#include <cstddef>
#include <vector>

#include <volsg/gl/Buffer.h>
#include <volsg/gl/Texture.h>
#include <volsg/gl/VertexArray.h>
#include <volsg/gltf/GltfAsset.h>

namespace volsg {

/// Attribute locations shared with the glTF shaders.
enum GltfAttribute : GLuint {
    kGltfPosition = 0,
    kGltfNormal = 1,
    kGltfTangent = 2,
    kGltfTexCoord0 = 3,
    kGltfTexCoord1 = 4,
    kGltfColor = 5
};

struct GltfGpuPrimitive {
    VertexArray vertexArray;
    Buffer positions, normals, tangents, texCoords0, texCoords1, colors, indices;
    GLsizei indexCount = 0;
    GLenum mode = GL_TRIANGLES;
    bool hasNormals = false, hasTangents = false, hasColors = false;
};

/// Kept per node in the Renderer's NodeCache (so per GL context); built once by upload().
class GltfGpuAsset {
public:
    /// Sends every instanced primitive and every texture a material uses (context current).
    void upload(const GltfAsset& asset);
    bool uploaded() const { return uploaded_; }

    const GltfGpuPrimitive& primitive(std::size_t mesh, std::size_t primitive) const {
        return primitives_[mesh][primitive];
    }
    /// The GL texture of glTF texture `index` decoded as sRGB (base colour, emissive) or not;
    /// null for -1.
    const Texture* texture(int index, bool srgb) const;

private:
    std::vector<std::vector<GltfGpuPrimitive>> primitives_;
    std::vector<Texture> linear_, srgb_; ///< per glTF texture; empty Texture where unused
    bool uploaded_ = false;
};

} // namespace volsg
