#include <volsg/image/TextureFile.h>

#include <cstring>
#include <memory>

#include <simage.h>

#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/io/RegularFile.h>

namespace volsg {

ImageValue readTextureFile(const std::string& path) {
    regularFileSize(path, "cannot read texture file", limits::maxImageFileSize);
    int width = 0, height = 0, components = 0;
    std::unique_ptr<unsigned char, void (*)(unsigned char*)> data(
        simage_read_image(path.c_str(), &width, &height, &components), &simage_free_image);
    if (!data) {
        const char* why = simage_get_last_error();
        throw Error(std::string("cannot read texture file: ") +
                        (why && *why ? why : "unknown image format"),
                    path);
    }
    if (width <= 0 || height <= 0 || components < 1 || components > 4 ||
        std::uint32_t(width) > limits::maxImageSide ||
        std::uint32_t(height) > limits::maxImageSide ||
        std::uint64_t(width) * std::uint64_t(height) > limits::maxImagePixels)
        throw Error("texture file of " + std::to_string(width) + " x " + std::to_string(height) +
                        " x " + std::to_string(components) + " is outside the image limits",
                    path);
    ImageValue image;
    image.width = width;
    image.height = height;
    image.components = components;
    image.pixels.resize(std::size_t(width) * std::size_t(height) * std::size_t(components));
    std::memcpy(image.pixels.data(), data.get(), image.pixels.size());
    return image;
}

} // namespace volsg
