#include <volsg/core/Error.h>
#include <volsg/render/GpuMesh.h>

#include <algorithm>
#include <string>

namespace volsg {

void GpuMesh::upload(const Mesh& mesh) {
    const std::size_t vertexCount = mesh.positions.size();
    for (const auto* list : {&mesh.indices, &mesh.outline})
        for (std::uint32_t i : *list)
            if (i >= vertexCount)
                throw Error("mesh index " + std::to_string(i) + " is beyond its " +
                            std::to_string(vertexCount) + " positions");

    const bool triangles = mesh.primitive == Mesh::Primitive::Triangles;
    mode = triangles                                  ? GL_TRIANGLES
           : mesh.primitive == Mesh::Primitive::Lines ? GL_LINES
                                                      : GL_POINTS;
    const std::size_t perPrimitive = mesh.verticesPerPrimitive();
    // A trailing partial primitive would be ignored by GL anyway; leave it out explicitly.
    indexCount = GLsizei(mesh.indices.size() - mesh.indices.size() % perPrimitive);
    outlineCount = triangles ? GLsizei(mesh.outline.size() - mesh.outline.size() % 2) : 0;
    hasNormals = !mesh.normals.empty() && mesh.normals.size() == vertexCount;
    hasTexCoords = !mesh.texCoords.empty() && mesh.texCoords.size() == vertexCount;
    hasColors = !mesh.colors.empty() && mesh.colors.size() == vertexCount;
    hasTranslucentColors = hasColors && std::any_of(mesh.colors.begin(), mesh.colors.end(),
                                                    [](const glm::vec4& c) { return c.a < 1.0f; });
    bounds = mesh.bounds();
    shading = measureShadingSpread(mesh);

    if (!vertexArray) {
        vertexArray = VertexArray::create();
        positions = Buffer(GL_ARRAY_BUFFER);
        normals = Buffer(GL_ARRAY_BUFFER);
        colors = Buffer(GL_ARRAY_BUFFER);
        texCoords = Buffer(GL_ARRAY_BUFFER);
        indices = Buffer(GL_ELEMENT_ARRAY_BUFFER);
    }
    vertexArray.bind();
    positions.setData(mesh.positions);
    vertexArray.setAttribute(kPositionAttribute, positions, 3);
    if (hasNormals) {
        normals.setData(mesh.normals);
        vertexArray.setAttribute(kNormalAttribute, normals, 3);
    } else {
        vertexArray.disableAttribute(kNormalAttribute, glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
    }
    if (hasColors) {
        colors.setData(mesh.colors);
        vertexArray.setAttribute(kColorAttribute, colors, 4);
    } else {
        vertexArray.disableAttribute(kColorAttribute, glm::vec4(1.0f));
    }
    if (hasTexCoords) {
        texCoords.setData(mesh.texCoords);
        vertexArray.setAttribute(kTexCoordAttribute, texCoords, 2);
    } else {
        vertexArray.disableAttribute(kTexCoordAttribute, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    }
    // The element buffer binding is VAO state: bind it while the VAO is bound.
    vertexArray.setIndexBuffer(indices);
    if (outlineCount > 0) {
        std::vector<std::uint32_t> all(mesh.indices.begin(), mesh.indices.begin() + indexCount);
        all.insert(all.end(), mesh.outline.begin(), mesh.outline.begin() + outlineCount);
        indices.setData(all);
    } else {
        indices.setData(mesh.indices);
    }
    VertexArray::unbind();
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    uploaded = true;
}

} // namespace volsg
