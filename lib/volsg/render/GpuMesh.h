#pragma once
// A Mesh on the GPU: vertex buffers, index buffer and the VAO that binds them.

#include <volsg/geometry/Mesh.h>
#include <volsg/gl/Buffer.h>
#include <volsg/gl/VertexArray.h>
#include <volsg/math/Box3.h>
#include <volsg/render/VertexLighting.h>

namespace volsg {

/// Attribute locations shared with the shape shaders.
enum MeshAttribute : GLuint {
    kPositionAttribute = 0,
    kNormalAttribute = 1,
    kColorAttribute = 2,
    kTexCoordAttribute = 3,
};

struct GpuMesh {
    VertexArray vertexArray;
    Buffer positions, normals, colors, texCoords, indices;
    GLsizei indexCount = 0;
    /// Mesh::outline, after the primitives in the index buffer (2 per edge; 0: none).
    GLsizei outlineCount = 0;
    GLenum mode = GL_TRIANGLES;
    bool hasNormals = false;           ///< one normal per position
    bool hasColors = false;            ///< one colour per position (replaces the diffuse colour)
    bool hasTranslucentColors = false; ///< some vertex colour has alpha < 1
    bool hasTexCoords = false;         ///< one texture coordinate per position
    Box3 bounds;                       ///< local coordinates
    ShadingSpread shading;             ///< what decides per-vertex lighting (VertexLighting.h)
    bool uploaded = false;

    /// Bytes of its buffers on the GPU.
    std::size_t bytes() const {
        return positions.size() + normals.size() + colors.size() + texCoords.size() +
               indices.size();
    }

    /// Sends `mesh` to the GPU (the GL context must be current). Throws Error for an index
    /// beyond the positions, which would make the draw read outside the buffers.
    void upload(const Mesh& mesh);
};

} // namespace volsg
