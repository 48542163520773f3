#include <volsg/gltf/GltfGpuAsset.h>

namespace volsg {

namespace {

template <class T>
void attribute(VertexArray& vao, Buffer& buffer, GLuint location, const std::vector<T>& values,
               GLint components) {
    if (values.empty()) {
        vao.bind();
        glDisableVertexAttribArray(location); // its constant is set before each draw
        return;
    }
    buffer = Buffer(GL_ARRAY_BUFFER);
    buffer.setData(values);
    vao.setAttribute(location, buffer, components);
}

bool isMipmapFilter(int filter) {
    return filter == GL_NEAREST_MIPMAP_NEAREST || filter == GL_LINEAR_MIPMAP_NEAREST ||
           filter == GL_NEAREST_MIPMAP_LINEAR || filter == GL_LINEAR_MIPMAP_LINEAR;
}

Texture makeTexture(const GltfAsset& asset, int index, bool srgb) {
    const GltfTexture& t = asset.textures[std::size_t(index)];
    const GltfImage& image = asset.images[std::size_t(t.image)];
    const GltfSampler sampler =
        t.sampler >= 0 ? asset.samplers[std::size_t(t.sampler)] : GltfSampler{};
    Texture texture(GL_TEXTURE_2D);
    // glTF's first row is v = 0, which is also the first row GL stores: no flip.
    texture.image2D(srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, image.width, image.height, GL_RGBA,
                    GL_UNSIGNED_BYTE, image.rgba.data());
    texture.bind(0);
    if (isMipmapFilter(sampler.minFilter)) glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, sampler.minFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, sampler.magFilter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, sampler.wrapS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, sampler.wrapT);
    return texture;
}

} // namespace

void GltfGpuAsset::upload(const GltfAsset& asset) {
    primitives_.clear();
    primitives_.resize(asset.meshes.size());
    std::vector<char> instanced(asset.meshes.size(), 0);
    for (const GltfInstance& i : asset.instances)
        instanced[std::size_t(i.mesh)] = 1;
    for (std::size_t m = 0; m < asset.meshes.size(); ++m) {
        primitives_[m].resize(asset.meshes[m].primitives.size());
        if (!instanced[m]) continue; // not in the scene: nothing to draw
        for (std::size_t p = 0; p < asset.meshes[m].primitives.size(); ++p) {
            const GltfPrimitive& src = asset.meshes[m].primitives[p];
            GltfGpuPrimitive& dst = primitives_[m][p];
            if (src.indices.empty()) continue;
            dst.vertexArray = VertexArray::create();
            dst.positions = Buffer(GL_ARRAY_BUFFER);
            dst.positions.setData(src.positions);
            dst.vertexArray.setAttribute(kGltfPosition, dst.positions, 3);
            const bool triangles = src.kind == GltfPrimitive::Kind::Triangles;
            dst.hasNormals = triangles && !src.normals.empty();
            dst.hasTangents = triangles && !src.tangents.empty();
            dst.hasColors = !src.colors.empty();
            attribute(dst.vertexArray, dst.normals, kGltfNormal,
                      dst.hasNormals ? src.normals : std::vector<glm::vec3>{}, 3);
            attribute(dst.vertexArray, dst.tangents, kGltfTangent,
                      dst.hasTangents ? src.tangents : std::vector<glm::vec4>{}, 4);
            attribute(dst.vertexArray, dst.texCoords0, kGltfTexCoord0, src.texCoords0, 2);
            attribute(dst.vertexArray, dst.texCoords1, kGltfTexCoord1, src.texCoords1, 2);
            attribute(dst.vertexArray, dst.colors, kGltfColor, src.colors, 4);
            dst.indices = Buffer(GL_ELEMENT_ARRAY_BUFFER);
            dst.vertexArray.setIndexBuffer(dst.indices);
            dst.indices.setData(src.indices);
            dst.indexCount = GLsizei(src.indices.size());
            dst.mode = src.kind == GltfPrimitive::Kind::Points  ? GL_POINTS
                       : src.kind == GltfPrimitive::Kind::Lines ? GL_LINES
                                                                : GL_TRIANGLES;
        }
    }
    VertexArray::unbind();
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    linear_.clear();
    srgb_.clear();
    linear_.resize(asset.textures.size());
    srgb_.resize(asset.textures.size());
    auto need = [&](const GltfTextureRef& ref, bool srgb) {
        if (!ref.present()) return;
        std::vector<Texture>& set = srgb ? srgb_ : linear_;
        if (!set[std::size_t(ref.texture)])
            set[std::size_t(ref.texture)] = makeTexture(asset, ref.texture, srgb);
    };
    for (const GltfMaterial& m : asset.materials) {
        need(m.baseColorTexture, true);
        need(m.emissiveTexture, true);
        need(m.metallicRoughnessTexture, false);
        need(m.normalTexture, false);
        need(m.occlusionTexture, false);
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    uploaded_ = true;
}

const Texture* GltfGpuAsset::texture(int index, bool srgb) const {
    if (index < 0) return nullptr;
    const Texture& t = (srgb ? srgb_ : linear_)[std::size_t(index)];
    return t ? &t : nullptr;
}

} // namespace volsg
