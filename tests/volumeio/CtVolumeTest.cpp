// The real CT volumes in examples/data: loaded through the raw gzip reader and checked against
// what their vtk.js index.json files say (dimensions, spacing, value range) and against the
// SHA-256 of the decompressed bytes as `gunzip | sha256sum` prints it.

#include <doctest/doctest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/volumeio/VolumeReader.h>

using namespace volsg;

namespace {

// FIPS 180-4 SHA-256, small and slow enough for a test (a few MB).
class Sha256 {
public:
    void update(const std::uint8_t* data, std::size_t size) {
        for (std::size_t i = 0; i < size; ++i) {
            block_[blockSize_++] = data[i];
            if (blockSize_ == 64) {
                compress();
                blockSize_ = 0;
            }
        }
        bitCount_ += std::uint64_t(size) * 8;
    }

    std::string hexDigest() {
        const std::uint64_t bits = bitCount_;
        const std::uint8_t one = 0x80, zero = 0;
        update(&one, 1);
        while (blockSize_ != 56)
            update(&zero, 1);
        for (int i = 7; i >= 0; --i) {
            const std::uint8_t b = std::uint8_t(bits >> (8 * i));
            update(&b, 1);
        }
        static const char* digits = "0123456789abcdef";
        std::string hex;
        for (const std::uint32_t word : state_)
            for (int shift = 28; shift >= 0; shift -= 4)
                hex += digits[(word >> shift) & 0xf];
        return hex;
    }

private:
    static std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

    void compress() {
        static constexpr std::array<std::uint32_t, 64> k = {
            0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4,
            0xab1c5ed5, 0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe,
            0x9bdc06a7, 0xc19bf174, 0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f,
            0x4a7484aa, 0x5cb0a9dc, 0x76f988da, 0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7,
            0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967, 0x27b70a85, 0x2e1b2138, 0x4d2c6dfc,
            0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85, 0xa2bfe8a1, 0xa81a664b,
            0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070, 0x19a4c116,
            0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
            0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7,
            0xc67178f2};
        std::array<std::uint32_t, 64> w{};
        for (int i = 0; i < 16; ++i)
            w[i] = std::uint32_t(block_[4 * i]) << 24 | std::uint32_t(block_[4 * i + 1]) << 16 |
                   std::uint32_t(block_[4 * i + 2]) << 8 | std::uint32_t(block_[4 * i + 3]);
        for (int i = 16; i < 64; ++i) {
            const std::uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
            const std::uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
            w[i] = w[i - 16] + s0 + w[i - 7] + s1;
        }
        std::array<std::uint32_t, 8> v = state_;
        for (int i = 0; i < 64; ++i) {
            const std::uint32_t s1 = rotr(v[4], 6) ^ rotr(v[4], 11) ^ rotr(v[4], 25);
            const std::uint32_t choice = (v[4] & v[5]) ^ (~v[4] & v[6]);
            const std::uint32_t t1 = v[7] + s1 + choice + k[i] + w[i];
            const std::uint32_t s0 = rotr(v[0], 2) ^ rotr(v[0], 13) ^ rotr(v[0], 22);
            const std::uint32_t majority = (v[0] & v[1]) ^ (v[0] & v[2]) ^ (v[1] & v[2]);
            const std::uint32_t t2 = s0 + majority;
            v = {t1 + t2, v[0], v[1], v[2], v[3] + t1, v[4], v[5], v[6]};
        }
        for (int i = 0; i < 8; ++i)
            state_[i] += v[i];
    }

    std::array<std::uint32_t, 8> state_ = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                           0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
    std::array<std::uint8_t, 64> block_{};
    std::size_t blockSize_ = 0;
    std::uint64_t bitCount_ = 0;
};

std::string sha256Hex(const std::string& text) {
    Sha256 h;
    h.update(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    return h.hexDigest();
}

// The SHA-256 of the voxels as the file stores them: little-endian bytes whatever the host.
std::string littleEndianSha256(const VolumeGrid& grid) {
    Sha256 h;
    const std::size_t size = voxelTypeSize(grid.type());
    const auto bytes = grid.bytes();
    const bool hostLittle = std::endian::native == std::endian::little;
    std::array<std::uint8_t, 4> element{};
    for (std::size_t i = 0; i < bytes.size(); i += size) {
        for (std::size_t b = 0; b < size; ++b)
            element[b] = std::uint8_t(bytes[i + (hostLittle ? b : size - 1 - b)]);
        h.update(element.data(), size);
    }
    return h.hexDigest();
}

std::string sharedData(const std::string& relative) {
    return std::string(VOLSG_DATA_DIR) + "/" + relative;
}

} // namespace

TEST_CASE("the test's SHA-256 matches the FIPS 180-4 examples") {
    CHECK(sha256Hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    CHECK(sha256Hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
          "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST_CASE("headsq CT loads as 64x64x93 SHORT with values 0 to 3926") {
    const std::string path = sharedData("vtkjs-headsq/headsq_64x64x93_int16le.raw.gz");
    if (!std::filesystem::exists(path)) {
        MESSAGE("skipped: " << path << " is absent");
        return;
    }
    const RawVolumeLayout layout{.dimensions = {64, 64, 93},
                                 .type = VoxelType::Short,
                                 .bigEndian = false,
                                 .headerSkip = 0,
                                 .spacing = {3.2, 3.2, 1.5}};
    const auto grid = readVolume(path, &layout);
    REQUIRE(grid);
    CHECK(grid->type() == VoxelType::Short);
    CHECK(grid->dimensions() == glm::ivec3(64, 64, 93));
    CHECK(grid->spacing() == glm::dvec3(3.2, 3.2, 1.5));
    CHECK(grid->byteSize() == 761856);
    const auto [lo, hi] = grid->minMax();
    CHECK(lo == 0.0);
    CHECK(hi == 3926.0);
    CHECK(littleEndianSha256(*grid).substr(0, 16) == "35b0a0101e612dc8");
}

TEST_CASE("LIDC2 CT loads as 256x256x133 UBYTE with the expected bytes") {
    const std::string path = sharedData("vtkjs-lidc2/lidc2_256x256x133_uint8.raw.gz");
    if (!std::filesystem::exists(path)) {
        MESSAGE("skipped: " << path << " is absent");
        return;
    }
    const RawVolumeLayout layout{.dimensions = {256, 256, 133},
                                 .type = VoxelType::UByte,
                                 .bigEndian = false,
                                 .headerSkip = 0,
                                 .spacing = {1.40625, 1.40625, 2.5}};
    const auto grid = readRawVolume(path, layout);
    REQUIRE(grid);
    CHECK(grid->type() == VoxelType::UByte);
    CHECK(grid->isLabelType()); // a UByte grid could serve as tags too
    CHECK(grid->dimensions() == glm::ivec3(256, 256, 133));
    CHECK(grid->spacing() == glm::dvec3(1.40625, 1.40625, 2.5));
    CHECK(grid->byteSize() == 8716288);
    const auto [lo, hi] = grid->minMax();
    CHECK(lo == 0.0);
    CHECK(hi == 255.0);
    CHECK(littleEndianSha256(*grid).substr(0, 16) == "d697a46dadafc1b2");

    // Too small a byte limit is refused before anything is read.
    CHECK_THROWS_WITH_AS(readRawVolume(path, layout, 8716287),
                         doctest::Contains("exceeds the allocation limit"), Error);
}
