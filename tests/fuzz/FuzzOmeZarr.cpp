// libFuzzer target: OME-Zarr images (readOmeZarr). The input is three parts split at its first
// two NUL bytes: the image's .zattrs, its array "0"'s .zarray, and one chunk, stored under
// both key spellings ("0/0/0" and "0.0.0") in a private image folder. Seeds (corpus/omezarr/):
// an 8x8x8 UBYTE pyramid written by volsg-pyramid with each compressor.
#include <filesystem>
#include <fstream>

#include <volsg/volumeio/VolumeReader.h>

#include "FuzzScratch.h"

namespace {

// The image folder of this process, removed at exit.
class ImageFolder {
public:
    ImageFolder() {
        std::string pattern = "/tmp/volsg-fuzz-zarr-XXXXXX";
        if (!::mkdtemp(pattern.data())) std::abort();
        root_ = pattern;
        std::filesystem::create_directories(image() + "/0/0/0");
    }
    ~ImageFolder() {
        std::error_code ec;
        std::filesystem::remove_all(root_, ec);
    }
    std::string image() const { return root_ + "/image.zarr"; }
    void put(const std::string& name, std::string_view bytes) const {
        std::ofstream out(image() + "/" + name, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), std::streamsize(bytes.size()));
    }

private:
    std::string root_;
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const ImageFolder folder;
    const std::string_view input = volsg::fuzz::asText(data, size);
    const std::size_t first = input.find('\0');
    const std::size_t second = first == input.npos ? input.npos : input.find('\0', first + 1);
    if (second == input.npos) return 0;
    folder.put(".zattrs", input.substr(0, first));
    folder.put("0/.zarray", input.substr(first + 1, second - first - 1));
    folder.put("0/0/0/0", input.substr(second + 1));
    folder.put("0/0.0.0", input.substr(second + 1));
    try {
        (void)volsg::readOmeZarr(folder.image(), 0, volsg::fuzz::fuzzVolumeByteLimit)->minMax();
    } catch (const volsg::Error&) {
    }
    return 0;
}
