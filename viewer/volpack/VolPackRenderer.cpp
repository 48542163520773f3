#include "VolPackRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <volpack.h>

#include <volsg/core/Error.h>

namespace volsg::volpack {

namespace {

/// VolPack's matrices are row-major double[4][4] acting on column vectors (m[row][col], the
/// translation in m[i][3]); glm's are column-major.
void toVolPack(const glm::dmat4& m, vpMatrix4 out) {
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            out[row][col] = m[col][row];
}

bool isGrey(const Classification& c) {
    for (const glm::dvec3& rgb : c.color)
        if (rgb.r != rgb.g || rgb.g != rgb.b) return false;
    return true;
}

/// The 8-bit level VolPack should store for opacity A: the nearest one.
int opacityLevel(double a) {
    return int(std::lround(std::clamp(a, 0.0, 1.0) * 255.0));
}

} // namespace

void Renderer::check(int result, const char* what) const {
    if (result != VP_OK)
        throw Error(std::string("VolPack ") + what + ": " + vpGetErrorString(vpGetError(vpc_)));
}

Renderer::Renderer(const VolumeGrid& grid, const Classification& classification,
                   const Shading& shading)
    : dimensions_(grid.dimensions()), spacing_(grid.spacing()), shaded_(shading.enabled) {
    if (grid.type() != VoxelType::UByte)
        throw Error("the VolPack baseline takes UBYTE volumes only (VolPack's scalars are 8-bit)");
    if (glm::any(glm::greaterThan(dimensions_, glm::ivec3(VP_MAX_VOLUME_DIM))))
        throw Error("VolPack takes at most 1024 voxels per side");
    vpc_ = vpCreateContext();
    if (!vpc_) throw Error("vpCreateContext failed");
    try {
        check(vpSetVolumeSize(vpc_, dimensions_.x, dimensions_.y, dimensions_.z), "volume size");
        classifierTable_.assign(256, 0.0f);
        for (int d = 0; d < 256; ++d) {
            const int level = opacityLevel(classification.opacity[std::size_t(d)]);
            // VolPack truncates opacity * 255; a quarter level above `level` stores `level`.
            classifierTable_[std::size_t(d)] = level == 0 ? 0.0f : float((level + 0.25) / 255.0);
        }
        auto data = grid.data<std::uint8_t>();
        for (std::uint8_t d : data)
            if (classifierTable_[d] > 0.0f) ++classifiedVoxels_;

        // The raw voxels: VolPack's lookup shader wants a 2-byte shading field, so each voxel
        // holds its shading index (the data byte, or the encoded normal) and the data byte.
        const glm::dvec3 material = shading.materialColor;
        channels_ = shaded_ ? ((material.r == material.g && material.g == material.b) ? 1 : 3)
                            : (isGrey(classification) ? 1 : 3);
        rawVoxels_.resize(data.size());
        for (std::size_t v = 0; v < data.size(); ++v)
            rawVoxels_[v] = {std::uint16_t(data[v]), data[v], 0};
        const int voxelBytes = int(sizeof(RawVoxel));
        RawVoxel* layout = nullptr;
        check(vpSetVoxelSize(vpc_, voxelBytes, 2, 1, 1), "voxel size");
        check(vpSetVoxelField(vpc_, 0, sizeof(std::uint16_t), int(vpFieldOffset(layout, shade)),
                              shaded_ ? VP_NORM_MAX : 255),
              "shading field");
        check(vpSetVoxelField(vpc_, 1, 1, int(vpFieldOffset(layout, density)), 255),
              "density field");
        check(vpSetRawVoxels(vpc_, rawVoxels_.data(), int(rawVoxels_.size()) * voxelBytes,
                             voxelBytes, dimensions_.x * voxelBytes,
                             dimensions_.x * dimensions_.y * voxelBytes),
              "raw voxels");
        check(vpSetClassifierTable(vpc_, 0, 1, classifierTable_.data(),
                                   int(classifierTable_.size() * sizeof(float))),
              "classifier table");
        if (!shaded_) {
            // Unshaded: the "shading" table is the transfer function's colour per data byte, in
            // VolPack's 0..255 units; VolPack multiplies it by the voxel's opacity.
            shadeTable_.assign(std::size_t(256 * channels_), 0.0f);
            for (int d = 0; d < 256; ++d)
                for (int c = 0; c < channels_; ++c)
                    shadeTable_[std::size_t(d * channels_ + c)] = float(
                        255.0 * std::clamp(classification.color[std::size_t(d)][c], 0.0, 1.0));
        } else {
            // VolPack's central-difference normals, encoded in 13 bits, into the shading field.
            std::vector<unsigned char> scalars(data.begin(), data.end());
            check(vpVolumeNormals(vpc_, scalars.data(), int(scalars.size()), 1, VP_SKIP_FIELD, 0),
                  "normals");
            shadeTable_.assign(std::size_t(VP_NORM_MAX + 1) * std::size_t(channels_), 0.0f);
            // Coefficients in 0..1: vpSetMaterial scales them to VolPack's 0..255 itself.
            const glm::dvec3 c = material;
            check(vpSetMaterial(vpc_, VP_MATERIAL0, VP_AMBIENT, VP_BOTH_SIDES,
                                shading.ambient * c.r, shading.ambient * c.g,
                                shading.ambient * c.b),
                  "ambient");
            check(vpSetMaterial(vpc_, VP_MATERIAL0, VP_DIFFUSE, VP_BOTH_SIDES,
                                shading.diffuse * c.r, shading.diffuse * c.g,
                                shading.diffuse * c.b),
                  "diffuse");
            check(vpSetMaterial(vpc_, VP_MATERIAL0, VP_SPECULAR, VP_BOTH_SIDES, shading.specular,
                                shading.specular, shading.specular),
                  "specular");
            check(vpSetMaterial(vpc_, VP_MATERIAL0, VP_SHINYNESS, VP_BOTH_SIDES, shading.shininess,
                                0.0, 0.0),
                  "shininess");
            const glm::dvec3 l = glm::normalize(shading.lightDirection);
            check(vpSetLight(vpc_, VP_LIGHT0, VP_DIRECTION, l.x, l.y, l.z), "light direction");
            check(vpSetLight(vpc_, VP_LIGHT0, VP_COLOR, 1.0, 1.0, 1.0), "light colour");
            check(vpEnable(vpc_, VP_LIGHT0, 1), "light");
        }
        check(vpSetLookupShader(vpc_, channels_, 1, 0, shadeTable_.data(),
                                int(shadeTable_.size() * sizeof(float)), 0, nullptr, 0),
              "lookup shader");
        check(vpSetd(vpc_, VP_MIN_VOXEL_OPACITY, 0.5 / 255.0), "minimum opacity");
        check(vpClassifyVolume(vpc_), "classification");
        check(vpSetd(vpc_, VP_MAX_RAY_OPACITY, 1.0), "maximum ray opacity");
    } catch (...) {
        vpDestroyContext(vpc_);
        throw;
    }
}

Renderer::~Renderer() {
    if (vpc_) vpDestroyContext(vpc_);
}

void Renderer::setMaxRayOpacity(double threshold) {
    check(vpSetd(vpc_, VP_MAX_RAY_OPACITY, threshold), "maximum ray opacity");
}

Image Renderer::render(const Camera& camera, int width, int height) {
    Image image;
    render(camera, width, height, image);
    return image;
}

void Renderer::render(const Camera& camera, int width, int height, Image& image) {
    if (width < 1 || height < 1) throw Error("VolPack image size must be at least 1x1");
    const double aspect = double(width) / double(height);
    const glm::dmat4 projection = camera.projectionMatrix(aspect);
    if (projection[0][3] != 0.0 || projection[1][3] != 0.0 || projection[2][3] != 0.0)
        throw Error("the VolPack baseline renders parallel projections only (an "
                    "OrthographicCamera); VolPack 1.0b3 does not factor perspective views");

    // VolPack object coordinates -> volsg local coordinates (see the class comment).
    const double maxdim = double(std::max({dimensions_.x, dimensions_.y, dimensions_.z}));
    glm::dmat4 objectToLocal(1.0);
    for (int a = 0; a < 3; ++a) {
        objectToLocal[a][a] = maxdim * spacing_[a];
        objectToLocal[3][a] = 0.5 * spacing_[a];
    }
    const glm::dmat4 model = camera.viewMatrix() * objectToLocal;
    glm::dmat4 project = projection;
    if (pixelShift_) {
        // VolPack's pixel (x, y) sits at window coordinate (x, y); GL's at (x + 0.5, y + 0.5).
        glm::dmat4 shift(1.0);
        shift[3][0] = -1.0 / width;
        shift[3][1] = -1.0 / height;
        project = shift * project;
    }
    vpMatrix4 m;
    check(vpCurrentMatrix(vpc_, VP_MODEL), "current matrix");
    toVolPack(model, m);
    check(vpSetMatrix(vpc_, m), "model matrix");
    check(vpCurrentMatrix(vpc_, VP_VIEW), "current matrix");
    toVolPack(glm::dmat4(1.0), m);
    check(vpSetMatrix(vpc_, m), "view matrix");
    check(vpCurrentMatrix(vpc_, VP_PROJECT), "current matrix");
    toVolPack(project, m);
    check(vpSetMatrix(vpc_, m), "projection matrix");

    if (width != imageWidth_ || height != imageHeight_) {
        pixels_.assign(std::size_t(width) * std::size_t(height) * std::size_t(channels_), 0);
        check(vpSetImage(vpc_, pixels_.data(), width, height, width * channels_,
                         channels_ == 1 ? VP_LUMINANCE : VP_RGB),
              "image");
        imageWidth_ = width;
        imageHeight_ = height;
    }
    if (shaded_) check(vpShadeTable(vpc_), "shade table");
    check(vpRenderClassifiedVolume(vpc_), "render");

    // VolPack's row 0 is window y = 0, the bottom; the Image's row 0 is the top.
    if (image.width != width || image.height != height)
        image = Image(width, height, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    for (int y = 0; y < height; ++y) {
        const unsigned char* row = pixels_.data() + std::size_t(height - 1 - y) *
                                                        std::size_t(width) * std::size_t(channels_);
        for (int x = 0; x < width; ++x) {
            glm::vec4& p = image.at(x, y);
            p.a = 1.0f;
            if (channels_ == 1)
                p.r = p.g = p.b = float(row[x]) / 255.0f;
            else
                for (int c = 0; c < 3; ++c)
                    p[c] = float(row[3 * x + c]) / 255.0f;
        }
    }
}

} // namespace volsg::volpack
