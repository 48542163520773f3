// PNG (own encoder/decoder over zlib) and PFM files for Image.
#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/image/Image.h>
#include <volsg/io/AtomicFile.h>
#include <volsg/io/RegularFile.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string_view>

#include <zlib.h>

namespace volsg {

namespace {

// Readers refuse images above this many pixels (and either side above 1 << 16), so a corrupt
// header cannot make them allocate without bound.
constexpr std::uint64_t kMaxPixels = limits::maxImagePixels;
constexpr std::uint32_t kMaxSide = limits::maxImageSide;

[[noreturn]] void fail(const std::string& path, const std::string& message) {
    throw Error(message, path);
}

std::vector<unsigned char> readWholeFile(const std::string& path) {
    const std::uintmax_t size =
        regularFileSize(path, "cannot open for reading", limits::maxImageFileSize);
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot open for reading");
    std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
    if (in.gcount() != static_cast<std::streamsize>(size)) fail(path, "read error");
    return bytes;
}

/// Writes `bytes` through a temporary file and a rename, so a reader never sees half a file
/// and a failed save keeps the old one.
void writeWholeFile(const std::string& path, const std::vector<unsigned char>& bytes) {
    writeFileAtomically(
        path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

void checkImage(const std::string& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != std::size_t(image.width) * std::size_t(image.height))
        fail(path, "cannot write an empty or inconsistent image (" + std::to_string(image.width) +
                       "x" + std::to_string(image.height) + ", " +
                       std::to_string(image.pixels.size()) + " pixels)");
}

// ---------------------------------------------------------------------------------------- PNG

constexpr std::array<unsigned char, 8> kPngSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

void putU32(std::vector<unsigned char>& out, std::uint32_t v) {
    out.push_back(static_cast<unsigned char>(v >> 24));
    out.push_back(static_cast<unsigned char>(v >> 16));
    out.push_back(static_cast<unsigned char>(v >> 8));
    out.push_back(static_cast<unsigned char>(v));
}

std::uint32_t getU32(const unsigned char* p) {
    return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
           std::uint32_t(p[3]);
}

void putChunk(std::vector<unsigned char>& out, const char type[4], const unsigned char* data,
              std::size_t size) {
    putU32(out, static_cast<std::uint32_t>(size));
    const std::size_t typeAt = out.size();
    out.insert(out.end(), type, type + 4);
    if (size) out.insert(out.end(), data, data + size);
    // The CRC covers the type and the data.
    uLong crc = crc32(0L, Z_NULL, 0);
    crc = crc32(crc, out.data() + typeAt, static_cast<uInt>(4 + size));
    putU32(out, static_cast<std::uint32_t>(crc));
}

/// [0,1] to 0..255, rounded to nearest; NaN and below 0 give 0.
unsigned char toByte(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return static_cast<unsigned char>(std::floor(v * 255.0f + 0.5f));
}

int paeth(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    if (pa <= pb && pa <= pc) return a;
    return pb <= pc ? b : c;
}

/// Undoes the per-row filters in place; `rows` holds height rows of (1 + stride) bytes.
void unfilter(const std::string& path, std::vector<unsigned char>& rows, std::size_t stride,
              std::size_t height, std::size_t bpp) {
    for (std::size_t y = 0; y < height; ++y) {
        unsigned char* row = rows.data() + y * (stride + 1);
        const unsigned char filter = row[0];
        unsigned char* cur = row + 1;
        const unsigned char* prev = y > 0 ? rows.data() + (y - 1) * (stride + 1) + 1 : nullptr;
        switch (filter) {
        case 0:
            break;
        case 1:
            for (std::size_t i = bpp; i < stride; ++i)
                cur[i] = cur[i] + cur[i - bpp];
            break;
        case 2:
            if (prev)
                for (std::size_t i = 0; i < stride; ++i)
                    cur[i] = cur[i] + prev[i];
            break;
        case 3:
            for (std::size_t i = 0; i < stride; ++i) {
                const int left = i >= bpp ? cur[i - bpp] : 0;
                const int up = prev ? prev[i] : 0;
                cur[i] = static_cast<unsigned char>(cur[i] + ((left + up) >> 1));
            }
            break;
        case 4:
            for (std::size_t i = 0; i < stride; ++i) {
                const int left = i >= bpp ? cur[i - bpp] : 0;
                const int up = prev ? prev[i] : 0;
                const int upLeft = (prev && i >= bpp) ? prev[i - bpp] : 0;
                cur[i] = static_cast<unsigned char>(cur[i] + paeth(left, up, upLeft));
            }
            break;
        default:
            fail(path, "PNG row " + std::to_string(y) + " has unknown filter type " +
                           std::to_string(filter));
        }
    }
}

/// Inflates the concatenated IDAT data into exactly `expected` bytes.
std::vector<unsigned char> inflateExactly(const std::string& path,
                                          const std::vector<unsigned char>& compressed,
                                          std::size_t expected) {
    std::vector<unsigned char> out(expected);
    z_stream zs{};
    if (inflateInit(&zs) != Z_OK) fail(path, "zlib inflateInit failed");
    zs.next_in = const_cast<Bytef*>(compressed.data());
    zs.avail_in = static_cast<uInt>(compressed.size());
    zs.next_out = out.data();
    zs.avail_out = static_cast<uInt>(out.size());
    const int status = inflate(&zs, Z_FINISH);
    const std::size_t produced = expected - zs.avail_out;
    inflateEnd(&zs);
    if (status == Z_STREAM_END && produced == expected) return out;
    if (status == Z_STREAM_END || (status == Z_BUF_ERROR && zs.avail_out == 0))
        fail(path, "PNG image data has the wrong size for its header (" + std::to_string(produced) +
                       " of " + std::to_string(expected) + " bytes)");
    if (status == Z_BUF_ERROR)
        fail(path, "PNG image data is truncated (" + std::to_string(produced) + " of " +
                       std::to_string(expected) + " bytes)");
    fail(path, "PNG image data is corrupt (zlib: " + std::string(zs.msg ? zs.msg : "error") + ")");
}

// ---------------------------------------------------------------------------------------- PFM

/// The next whitespace-separated token of a PFM header, starting at `pos`.
std::string pfmToken(const std::string& path, const std::vector<unsigned char>& bytes,
                     std::size_t& pos) {
    while (pos < bytes.size() && std::isspace(bytes[pos]))
        ++pos;
    const std::size_t start = pos;
    while (pos < bytes.size() && !std::isspace(bytes[pos]) && pos - start < 32)
        ++pos;
    if (start == pos) fail(path, "PFM header is truncated");
    return std::string(bytes.begin() + std::ptrdiff_t(start), bytes.begin() + std::ptrdiff_t(pos));
}

std::uint32_t pfmDimension(const std::string& path, const std::string& token, const char* what) {
    char* end = nullptr;
    const unsigned long v = std::strtoul(token.c_str(), &end, 10);
    if (token.empty() || *end != '\0' || token[0] == '-' || v == 0 || v > kMaxSide)
        fail(path, std::string("PFM header has a bad ") + what + " '" + token + "'");
    return static_cast<std::uint32_t>(v);
}

float byteSwapped(float v) {
    return std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(v)));
}

} // namespace

void writePng(const std::string& path, const Image& image) {
    checkImage(path, image);
    const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
    const std::size_t stride = w * 3;
    // Filter type 0 (none) on every row: simple, and exact by construction.
    std::vector<unsigned char> raw(h * (stride + 1));
    for (std::size_t y = 0; y < h; ++y) {
        unsigned char* row = raw.data() + y * (stride + 1);
        row[0] = 0;
        const glm::vec4* px = image.pixels.data() + y * w;
        for (std::size_t x = 0; x < w; ++x) {
            row[1 + 3 * x] = toByte(px[x].r);
            row[2 + 3 * x] = toByte(px[x].g);
            row[3 + 3 * x] = toByte(px[x].b);
        }
    }
    uLongf compressedSize = compressBound(static_cast<uLong>(raw.size()));
    std::vector<unsigned char> compressed(compressedSize);
    if (compress2(compressed.data(), &compressedSize, raw.data(), static_cast<uLong>(raw.size()),
                  6) != Z_OK)
        fail(path, "zlib compress2 failed");

    std::vector<unsigned char> file(kPngSignature.begin(), kPngSignature.end());
    std::vector<unsigned char> header;
    putU32(header, static_cast<std::uint32_t>(w));
    putU32(header, static_cast<std::uint32_t>(h));
    header.insert(header.end(), {8, 2, 0, 0, 0}); // 8 bit, RGB, deflate, adaptive, no interlace
    putChunk(file, "IHDR", header.data(), header.size());
    putChunk(file, "IDAT", compressed.data(), compressedSize);
    putChunk(file, "IEND", nullptr, 0);
    writeWholeFile(path, file);
}

Image readPng(const std::string& path) {
    const std::vector<unsigned char> bytes = readWholeFile(path);
    if (bytes.size() < kPngSignature.size() ||
        !std::equal(kPngSignature.begin(), kPngSignature.end(), bytes.begin()))
        fail(path, "not a PNG file (bad signature)");

    std::size_t pos = kPngSignature.size();
    std::uint32_t width = 0, height = 0;
    int colorType = -1;
    bool sawHeader = false, sawEnd = false;
    std::vector<unsigned char> idat;
    while (!sawEnd) {
        if (bytes.size() - pos < 12)
            fail(path,
                 "PNG file is truncated (no IEND chunk after byte " + std::to_string(pos) + ")");
        const std::uint32_t length = getU32(&bytes[pos]);
        const unsigned char* type = &bytes[pos + 4];
        if (length > bytes.size() - pos - 12)
            fail(path, "PNG file is truncated (a chunk of " + std::to_string(length) +
                           " bytes runs past the end of the file)");
        const unsigned char* data = type + 4;
        const std::uint32_t storedCrc = getU32(data + length);
        const uLong crc = crc32(crc32(0L, Z_NULL, 0), type, static_cast<uInt>(4 + length));
        const std::string typeName(reinterpret_cast<const char*>(type), 4);
        if (static_cast<std::uint32_t>(crc) != storedCrc)
            fail(path, "PNG chunk " + typeName + " has a bad CRC");
        if (typeName == "IHDR") {
            if (length != 13) fail(path, "PNG IHDR chunk has the wrong length");
            width = getU32(data);
            height = getU32(data + 4);
            const int bitDepth = data[8];
            colorType = data[9];
            if (width == 0 || height == 0 || width > kMaxSide || height > kMaxSide ||
                std::uint64_t(width) * height > kMaxPixels)
                fail(path, "PNG size " + std::to_string(width) + "x" + std::to_string(height) +
                               " is not supported");
            if (bitDepth != 8)
                fail(path, "PNG bit depth " + std::to_string(bitDepth) +
                               " is not supported (only 8-bit)");
            if (colorType != 0 && colorType != 2 && colorType != 4 && colorType != 6)
                fail(path, "PNG colour type " + std::to_string(colorType) +
                               " is not supported (grey, grey+alpha, RGB or RGBA only)");
            if (data[10] != 0 || data[11] != 0)
                fail(path, "PNG uses an unknown compression or filter method");
            if (data[12] != 0) fail(path, "interlaced PNG is not supported");
            sawHeader = true;
        } else if (typeName == "IDAT") {
            if (!sawHeader) fail(path, "PNG IDAT chunk before IHDR");
            idat.insert(idat.end(), data, data + length);
        } else if (typeName == "IEND") {
            sawEnd = true;
        } else if ((type[0] & 0x20) == 0 && typeName != "PLTE") {
            // A suggested palette (PLTE) may accompany RGB data and is ignored; any other
            // critical chunk changes how the data reads.
            fail(path, "PNG has an unknown critical chunk " + typeName);
        }
        pos += 12 + std::size_t(length);
    }
    if (!sawHeader) fail(path, "PNG has no IHDR chunk");
    if (idat.empty()) fail(path, "PNG has no image data");

    const std::size_t channels = colorType == 0 ? 1 : colorType == 4 ? 2 : colorType == 2 ? 3 : 4;
    const std::size_t stride = std::size_t(width) * channels;
    std::vector<unsigned char> rows =
        inflateExactly(path, idat, std::size_t(height) * (stride + 1));
    unfilter(path, rows, stride, height, channels);

    Image image(static_cast<int>(width), static_cast<int>(height));
    for (std::size_t y = 0; y < height; ++y) {
        const unsigned char* row = rows.data() + y * (stride + 1) + 1;
        glm::vec4* px = image.pixels.data() + y * width;
        for (std::size_t x = 0; x < width; ++x) {
            const unsigned char* s = row + x * channels;
            glm::vec4 v;
            switch (channels) {
            case 1:
                v = glm::vec4(glm::vec3(s[0]), 255.0f);
                break;
            case 2:
                v = glm::vec4(glm::vec3(s[0]), s[1]);
                break;
            case 3:
                v = glm::vec4(s[0], s[1], s[2], 255.0f);
                break;
            default:
                v = glm::vec4(s[0], s[1], s[2], s[3]);
                break;
            }
            px[x] = v / 255.0f;
        }
    }
    return image;
}

void writePfm(const std::string& path, const Image& image) {
    checkImage(path, image);
    const std::size_t w = std::size_t(image.width), h = std::size_t(image.height);
    // Negative scale = little-endian samples.
    const std::string header = "PF\n" + std::to_string(w) + " " + std::to_string(h) + "\n-1.0\n";
    std::vector<unsigned char> file(header.begin(), header.end());
    const std::size_t dataAt = file.size();
    file.resize(dataAt + w * h * 3 * sizeof(float));
    unsigned char* out = file.data() + dataAt;
    for (std::size_t row = 0; row < h; ++row) {
        const std::size_t y = h - 1 - row; // PFM stores the bottom row first
        for (std::size_t x = 0; x < w; ++x) {
            const glm::vec4& p = image.pixels[y * w + x];
            float rgb[3] = {p.r, p.g, p.b};
            if constexpr (std::endian::native == std::endian::big)
                for (float& c : rgb)
                    c = byteSwapped(c);
            std::memcpy(out, rgb, sizeof rgb);
            out += sizeof rgb;
        }
    }
    writeWholeFile(path, file);
}

Image readPfm(const std::string& path) {
    const std::vector<unsigned char> bytes = readWholeFile(path);
    std::size_t pos = 0;
    const std::string magic = pfmToken(path, bytes, pos);
    if (magic != "PF" && magic != "Pf") fail(path, "not a PFM file (expected PF or Pf)");
    const std::size_t channels = magic == "PF" ? 3 : 1;
    const std::uint32_t width = pfmDimension(path, pfmToken(path, bytes, pos), "width");
    const std::uint32_t height = pfmDimension(path, pfmToken(path, bytes, pos), "height");
    if (std::uint64_t(width) * height > kMaxPixels) fail(path, "PFM image is too large");
    const std::string scaleText = pfmToken(path, bytes, pos);
    char* end = nullptr;
    const double scale = std::strtod(scaleText.c_str(), &end);
    if (*end != '\0' || !std::isfinite(scale) || scale == 0.0)
        fail(path, "PFM header has a bad scale '" + scaleText + "'");
    // Exactly one whitespace character separates the header from the samples.
    if (pos >= bytes.size() || !std::isspace(bytes[pos])) fail(path, "PFM header is truncated");
    ++pos;
    const bool fileLittle = scale < 0.0;
    const bool swap = fileLittle != (std::endian::native == std::endian::little);

    const std::size_t count = std::size_t(width) * height * channels;
    if (bytes.size() - pos < count * sizeof(float))
        fail(path, "PFM file is truncated (" + std::to_string(bytes.size() - pos) + " of " +
                       std::to_string(count * sizeof(float)) + " data bytes)");
    Image image(static_cast<int>(width), static_cast<int>(height));
    const unsigned char* in = bytes.data() + pos;
    for (std::size_t row = 0; row < height; ++row) {
        const std::size_t y = height - 1 - row;
        for (std::size_t x = 0; x < width; ++x) {
            float c[3];
            std::memcpy(c, in, channels * sizeof(float));
            in += channels * sizeof(float);
            if (swap)
                for (std::size_t i = 0; i < channels; ++i)
                    c[i] = byteSwapped(c[i]);
            image.pixels[y * width + x] = channels == 3 ? glm::vec4(c[0], c[1], c[2], 1.0f)
                                                        : glm::vec4(c[0], c[0], c[0], 1.0f);
        }
    }
    return image;
}

void writeImage(const std::string& path, const Image& image) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") return writePng(path, image);
    if (ext == ".pfm") return writePfm(path, image);
    fail(path, ext.empty() ? std::string("image file name has no extension (expected .png or .pfm)")
                           : "unknown image file extension '" + ext + "' (expected .png or .pfm)");
}

} // namespace volsg
