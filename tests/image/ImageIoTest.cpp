// PNG and PFM files: exact round trips, quantisation, and clear errors on bad files.
#include <doctest/doctest.h>

#include <volsg/core/Error.h>
#include <volsg/image/Image.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <zlib.h>

using namespace volsg;

namespace {

std::string outputPath(const std::string& name) {
    const std::filesystem::path dir =
        std::filesystem::path(VOLSG_BINARY_DIR) / "test-output" / "image";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

std::vector<unsigned char> readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::vector<unsigned char>& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

/// Every 8-bit level appears in some channel: value (x + 7y + c*61) mod 256.
Image byteLevelsImage(int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            glm::vec4 v;
            for (int c = 0; c < 3; ++c)
                v[c] = float((x + 7 * y + c * 61) % 256) / 255.0f;
            v.a = 1.0f;
            image.at(x, y) = v;
        }
    return image;
}

// A PNG chunk, for building files the writer never makes (filters, grey, RGBA).
void putU32(std::vector<unsigned char>& out, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8)
        out.push_back(static_cast<unsigned char>(v >> s));
}
void putChunk(std::vector<unsigned char>& out, const char* type,
              const std::vector<unsigned char>& data) {
    putU32(out, std::uint32_t(data.size()));
    std::vector<unsigned char> typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    out.insert(out.end(), typed.begin(), typed.end());
    putU32(out, std::uint32_t(crc32(crc32(0, Z_NULL, 0), typed.data(), uInt(typed.size()))));
}
std::vector<unsigned char> pngFile(int w, int h, int colorType, std::vector<unsigned char> raw) {
    std::vector<unsigned char> file{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    std::vector<unsigned char> header;
    putU32(header, std::uint32_t(w));
    putU32(header, std::uint32_t(h));
    header.insert(header.end(), {8, static_cast<unsigned char>(colorType), 0, 0, 0});
    putChunk(file, "IHDR", header);
    uLongf size = compressBound(uLong(raw.size()));
    std::vector<unsigned char> z(size);
    compress2(z.data(), &size, raw.data(), uLong(raw.size()), 9);
    z.resize(size);
    putChunk(file, "IDAT", z);
    putChunk(file, "IEND", {});
    return file;
}

} // namespace

TEST_CASE("PNG write then read gives back every 8-bit value exactly") {
    const Image image = byteLevelsImage(37, 23);
    const std::string path = outputPath("levels.png");
    writePng(path, image);
    CHECK_FALSE(std::filesystem::exists(path + ".tmp"));
    const Image back = readPng(path);
    REQUIRE(back.width == 37);
    REQUIRE(back.height == 23);
    for (int y = 0; y < 23; ++y)
        for (int x = 0; x < 37; ++x)
            for (int c = 0; c < 3; ++c)
                REQUIRE(back.at(x, y)[c] == image.at(x, y)[c]); // both are k/255 in float
    CHECK(back.at(5, 5).a == 1.0f);
}

TEST_CASE("PNG quantisation clamps to 0..1 and rounds to nearest") {
    Image image(6, 1);
    image.at(0, 0) = {0.25f, 0.5f, 0.75f, 1.0f}; // 63.75, 127.5, 191.25
    image.at(1, 0) = {-0.5f, 1.5f, 0.6f / 255.0f, 1.0f};
    image.at(2, 0) = {0.99f / 255.0f, 1.49f / 255.0f, 1.51f / 255.0f, 1.0f};
    image.at(3, 0) = {NAN, INFINITY, -INFINITY, 1.0f};
    const std::string path = outputPath("quantise.png");
    writePng(path, image);
    const Image back = readPng(path);
    auto level = [&](int x, int c) { return int(std::lround(back.at(x, 0)[c] * 255.0f)); };
    CHECK(level(0, 0) == 64);
    CHECK(level(0, 1) == 128);
    CHECK(level(0, 2) == 191);
    CHECK(level(1, 0) == 0);
    CHECK(level(1, 1) == 255);
    CHECK(level(1, 2) == 1);
    CHECK(level(2, 0) == 1);
    CHECK(level(2, 1) == 1);
    CHECK(level(2, 2) == 2);
    CHECK(level(3, 0) == 0);
    CHECK(level(3, 1) == 255);
    CHECK(level(3, 2) == 0);
}

TEST_CASE("PFM write then read is bit exact and keeps row 0 at the top") {
    Image image(5, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x)
            image.at(x, y) = {0.1f * float(x) + 1e-7f, -3.25e-9f * float(y),
                              1e30f / float(1 + x * y), 1.0f};
    image.at(4, 3) = {123456.789f, -0.0f, 1.17549435e-38f, 1.0f};
    const std::string path = outputPath("exact.pfm");
    writePfm(path, image);
    const Image back = readPfm(path);
    REQUIRE(back.width == 5);
    REQUIRE(back.height == 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x)
            for (int c = 0; c < 3; ++c)
                REQUIRE(std::bit_cast<std::uint32_t>(back.at(x, y)[c]) ==
                        std::bit_cast<std::uint32_t>(image.at(x, y)[c]));
    // The file itself stores the bottom row first, little-endian, after "PF\n5 4\n-1.0\n".
    const std::vector<unsigned char> bytes = readBytes(path);
    const std::string header = "PF\n5 4\n-1.0\n";
    REQUIRE(bytes.size() == header.size() + 5 * 4 * 3 * 4);
    CHECK(std::string(bytes.begin(), bytes.begin() + std::ptrdiff_t(header.size())) == header);
    float first = 0.0f;
    std::memcpy(&first, bytes.data() + header.size(), 4);
    CHECK(first == image.at(0, 3).r);
}

TEST_CASE("big-endian and grey PFM files are read") {
    // "Pf" grey, 2x1, scale +1 (big-endian): values 0.5 and -2.
    std::vector<unsigned char> bytes;
    const std::string header = "Pf\n2 1\n1.0\n";
    bytes.assign(header.begin(), header.end());
    for (float v : {0.5f, -2.0f}) {
        const std::uint32_t u = std::bit_cast<std::uint32_t>(v);
        for (int s = 24; s >= 0; s -= 8)
            bytes.push_back(static_cast<unsigned char>(u >> s));
    }
    const std::string path = outputPath("grey-be.pfm");
    writeBytes(path, bytes);
    const Image image = readPfm(path);
    REQUIRE(image.width == 2);
    CHECK(image.at(0, 0) == glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
    CHECK(image.at(1, 0) == glm::vec4(-2.0f, -2.0f, -2.0f, 1.0f));
}

TEST_CASE("readPng undoes all five row filters for grey, RGB and RGBA") {
    // 3x5 RGB image, one row per filter type 0..4, with known pixel values.
    const int w = 3, h = 5, bpp = 3;
    std::vector<std::vector<int>> pixels(h, std::vector<int>(w * bpp));
    for (int y = 0; y < h; ++y)
        for (int i = 0; i < w * bpp; ++i)
            pixels[y][i] = (y * 53 + i * 29 + 7) % 256;
    auto paeth = [](int a, int b, int c) {
        const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
        return (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
    };
    std::vector<unsigned char> raw;
    for (int y = 0; y < h; ++y) {
        raw.push_back(static_cast<unsigned char>(y));
        for (int i = 0; i < w * bpp; ++i) {
            const int x = pixels[y][i];
            const int a = i >= bpp ? pixels[y][i - bpp] : 0;
            const int b = y > 0 ? pixels[y - 1][i] : 0;
            const int c = (y > 0 && i >= bpp) ? pixels[y - 1][i - bpp] : 0;
            const int predicted = y == 0   ? 0
                                  : y == 1 ? a
                                  : y == 2 ? b
                                  : y == 3 ? (a + b) / 2
                                           : paeth(a, b, c);
            raw.push_back(static_cast<unsigned char>((x - predicted) & 0xFF));
        }
    }
    const std::string path = outputPath("filters.png");
    writeBytes(path, pngFile(w, h, 2, raw));
    const Image image = readPng(path);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                REQUIRE(image.at(x, y)[c] == float(pixels[y][x * bpp + c]) / 255.0f);

    const std::string greyPath = outputPath("grey.png");
    writeBytes(greyPath, pngFile(2, 1, 0, {0, 10, 200}));
    const Image grey = readPng(greyPath);
    CHECK(grey.at(1, 0) == glm::vec4(200.0f / 255.0f, 200.0f / 255.0f, 200.0f / 255.0f, 1.0f));

    const std::string rgbaPath = outputPath("rgba.png");
    writeBytes(rgbaPath, pngFile(1, 1, 6, {0, 1, 2, 3, 128}));
    const Image rgba = readPng(rgbaPath);
    CHECK(rgba.at(0, 0) == glm::vec4(1.0f, 2.0f, 3.0f, 128.0f) / 255.0f);
}

TEST_CASE("readPng on a truncated file throws an Error naming the file") {
    const std::string full = outputPath("whole.png");
    writePng(full, byteLevelsImage(64, 64));
    const std::vector<unsigned char> bytes = readBytes(full);
    for (std::size_t keep : {std::size_t(4), std::size_t(20), bytes.size() / 2, bytes.size() - 5}) {
        const std::string cut = outputPath("truncated.png");
        writeBytes(cut,
                   std::vector<unsigned char>(bytes.begin(), bytes.begin() + std::ptrdiff_t(keep)));
        try {
            readPng(cut);
            FAIL("no error for a PNG cut to " << keep << " bytes");
        } catch (const Error& e) {
            CHECK(e.file() == cut);
            CHECK(std::string(e.what()).find("truncated.png") != std::string::npos);
        }
    }
}

TEST_CASE("readPng refuses corrupt and unsupported files with clear messages") {
    const std::string path = outputPath("bad.png");
    writePng(path, byteLevelsImage(4, 4));
    std::vector<unsigned char> bytes = readBytes(path);
    bytes[43] ^= 0xFF; // inside the IDAT data: the CRC no longer matches
    writeBytes(path, bytes);
    CHECK_THROWS_WITH_AS(readPng(path), doctest::Contains("bad CRC"), Error);

    writeBytes(path, {'n', 'o', 't', ' ', 'a', ' ', 'p', 'n', 'g'});
    CHECK_THROWS_WITH_AS(readPng(path), doctest::Contains("not a PNG"), Error);

    writeBytes(path, pngFile(1, 1, 3, {0, 0})); // palette
    CHECK_THROWS_WITH_AS(readPng(path), doctest::Contains("colour type 3"), Error);

    CHECK_THROWS_AS(readPng(outputPath("does-not-exist.png")), Error);
}

TEST_CASE("writeImage picks the format by extension and names an unknown one") {
    const Image image = byteLevelsImage(3, 2);
    writeImage(outputPath("by-ext.PNG"), image);
    CHECK(readPng(outputPath("by-ext.PNG")).at(2, 1) == image.at(2, 1));
    writeImage(outputPath("by-ext.pfm"), image);
    CHECK(readPfm(outputPath("by-ext.pfm")).at(2, 1) == image.at(2, 1));
    CHECK_THROWS_WITH_AS(writeImage(outputPath("picture.jpg"), image), doctest::Contains("'.jpg'"),
                         Error);
}

TEST_CASE("readPfm on a truncated file throws an Error") {
    const std::string path = outputPath("cut.pfm");
    writePfm(path, Image(4, 4, glm::vec4(1.0f)));
    std::vector<unsigned char> bytes = readBytes(path);
    bytes.resize(bytes.size() - 1);
    writeBytes(path, bytes);
    CHECK_THROWS_WITH_AS(readPfm(path), doctest::Contains("truncated"), Error);
}
