#pragma once
// A private folder for one fuzzing process: readers that take a path read the input from a
// real file here, beside small companion files a detached header or a glTF URI may name.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

#include <volsg/core/Error.h>

namespace volsg::fuzz {

class FuzzScratch {
public:
    /// Companion files: `data.raw` (4096 bytes 0..255 repeated) and `data.raw.gz` (gzip of
    /// 64 zero bytes) for detached volume headers, `buffer.bin` (256 bytes) for glTF buffers.
    FuzzScratch() {
        std::string pattern = "/tmp/volsg-fuzz-XXXXXX";
        if (!::mkdtemp(pattern.data())) std::abort();
        folder_ = pattern;
        std::string ramp(4096, '\0');
        for (std::size_t i = 0; i < ramp.size(); ++i)
            ramp[i] = char(i & 0xff);
        write("data.raw", ramp);
        static constexpr unsigned char gzipZeros[] = {
            0x1f, 0x8b, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0x03, 0x63, 0x60,
            0xa0, 0x0c, 0x00, 0x00, 0x36, 0x63, 0x8d, 0x75, 0x40, 0x00, 0x00, 0x00};
        write("data.raw.gz",
              std::string_view(reinterpret_cast<const char*>(gzipZeros), sizeof gzipZeros));
        write("buffer.bin", ramp.substr(0, 256));
    }
    ~FuzzScratch() {
        for (const char* name :
             {"data.raw", "data.raw.gz", "buffer.bin", "input.nrrd", "input.nhdr", "input.mha",
              "input.mhd", "input.raw", "input.gltf", "input.glb", "input.nii", "input.hdr",
              "input.dcm", "tiny.nrrd", "tiny.gltf", "tiny.png", "tiny.iv", "loop.iv", "scene.iv"})
            ::unlink((folder_ + "/" + name).c_str());
        ::rmdir(folder_.c_str());
    }
    FuzzScratch(const FuzzScratch&) = delete;
    FuzzScratch& operator=(const FuzzScratch&) = delete;

    /// Writes `bytes` to `name` in the folder (replacing it) and returns the file's path.
    std::string write(const std::string& name, std::string_view bytes) const {
        const std::string path = folder_ + "/" + name;
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        if (!out) std::abort();
        return path;
    }

    /// The one scratch folder of this process (removed at exit).
    static const FuzzScratch& instance() {
        static const FuzzScratch scratch;
        return scratch;
    }

private:
    std::string folder_;
};

/// The fuzz input as text.
inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

/// Voxel storage the volume targets allow: large enough for every code path, small enough
/// that libFuzzer's memory limit only catches real leaks or unchecked allocations.
inline constexpr std::uint64_t fuzzVolumeByteLimit = std::uint64_t(64) << 20;

/// The volume-header targets: the first byte picks the attached (even) or detached (odd) file
/// name, the rest is written there and read by `read(path, byteLimit)`; a volsg::Error is the
/// documented outcome, and whatever loads has its values scanned.
template <class Read>
void readVolumeHeader(const std::uint8_t* data, std::size_t size, const char* attachedName,
                      const char* detachedName, Read read) {
    if (size < 1) return;
    const std::string path = FuzzScratch::instance().write(
        (data[0] & 1) ? detachedName : attachedName, asText(data + 1, size - 1));
    try {
        (void)read(path, fuzzVolumeByteLimit)->minMax();
    } catch (const Error&) {
    }
}

} // namespace volsg::fuzz
