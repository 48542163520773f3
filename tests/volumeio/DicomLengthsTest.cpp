// The DICOM length walk (lib/volsg/volumeio/DicomLengths.h): every declared length is checked
// against the bytes left before GDCM allocates for it. On a real slice (written by pydicom from
// the head CT, examples/data/derived/headsq_dicom) and on hand-made data sets of each form.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <volsg/core/Error.h>
#include <volsg/volumeio/DicomLengths.h>
#include <volsg/volumeio/VolumeReader.h>

#include <unistd.h>

using namespace volsg;

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), {});
}

void put16(Bytes& b, unsigned v) {
    b.push_back(std::uint8_t(v));
    b.push_back(std::uint8_t(v >> 8));
}

void put32(Bytes& b, std::uint32_t v) {
    put16(b, v & 0xffff);
    put16(b, v >> 16);
}

/// An implicit VR little endian element header.
void implicitElement(Bytes& b, unsigned group, unsigned element, std::uint32_t length) {
    put16(b, group);
    put16(b, element);
    put32(b, length);
}

/// An explicit VR little endian element header.
void explicitElement(Bytes& b, unsigned group, unsigned element, const char* vr,
                     std::uint32_t length) {
    put16(b, group);
    put16(b, element);
    b.push_back(std::uint8_t(vr[0]));
    b.push_back(std::uint8_t(vr[1]));
    const std::string v = vr;
    if (v == "OB" || v == "OW" || v == "SQ" || v == "UN" || v == "UT") {
        put16(b, 0);
        put32(b, length);
    } else {
        put16(b, length);
    }
}

const std::string slice = std::string(VOLSG_DATA_DIR) + "/derived/headsq_dicom/slice-001.dcm";

/// Where the pixel data element (7fe0,0010) starts in explicit VR little endian bytes.
std::size_t pixelDataAt(const Bytes& b) {
    for (std::size_t i = 132; i + 8 <= b.size(); ++i)
        if (b[i] == 0xe0 && b[i + 1] == 0x7f && b[i + 2] == 0x10 && b[i + 3] == 0x00 &&
            b[i + 4] == 'O' && b[i + 5] == 'W')
            return i;
    return 0;
}

/// What readVolume says of `bytes` written as the file `name` in a fresh folder ("" if it reads).
std::string readError(const Bytes& bytes, const std::string& name) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("volsg-dicom-lengths-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const std::string path = (dir / name).string();
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    std::string message;
    try {
        (void)readVolume(path);
    } catch (const Error& e) {
        message = e.what();
    }
    std::filesystem::remove_all(dir);
    return message;
}

} // namespace

TEST_CASE("a real slice passes, and its pixel data declared 4 GB long is refused with its offset") {
    Bytes b = readFile(slice);
    REQUIRE(b.size() > 1000);
    CHECK(dicomLengthProblem(b).empty());
    const std::size_t at = pixelDataAt(b);
    REQUIRE(at > 0);
    b[at + 8] = 0x00;
    b[at + 9] = 0x00;
    b[at + 10] = 0x00;
    b[at + 11] = 0xf0;
    const std::string problem = dicomLengthProblem(b);
    CHECK(problem == "byte " + std::to_string(at) +
                         ": element (7fe0,0010) declares 4026531840 bytes, " +
                         std::to_string(b.size() - at - 12) + " are left in the file");

    // Through the reader: one line naming the file and the element, no allocation of 4 GB.
    const std::string message = readError(b, "bad.dcm");
    CHECK(message.find("bad.dcm: not a DICOM file: byte ") != std::string::npos);
    CHECK(message.find("(7fe0,0010) declares 4026531840 bytes") != std::string::npos);
}

TEST_CASE("a slice cut anywhere inside an element is refused, cut between elements it passes") {
    const Bytes whole = readFile(slice);
    const std::size_t pixels = pixelDataAt(whole);
    REQUIRE(pixels > 0);
    int refused = 0;
    for (std::size_t cut = 140; cut < pixels + 12; ++cut) {
        const Bytes part(whole.begin(), whole.begin() + std::ptrdiff_t(cut));
        if (!dicomLengthProblem(part).empty()) ++refused;
    }
    // The pixel data's value is cut at every one of these positions past its header.
    CHECK(refused > int(pixels - 140) / 2);
    // Cut just after an element's header, before its value: refused.
    CHECK_FALSE(
        dicomLengthProblem(Bytes(whole.begin(), whole.begin() + std::ptrdiff_t(pixels + 12)))
            .empty());
}

TEST_CASE("implicit VR sequences of undefined length are walked into") {
    Bytes b;
    implicitElement(b, 0x0008, 0x0060, 2); // Modality "CT"
    b.push_back('C');
    b.push_back('T');
    implicitElement(b, 0x0008, 0x1140, 0xffffffffu); // a sequence of undefined length
    implicitElement(b, 0xfffe, 0xe000, 0xffffffffu); // an item of undefined length
    implicitElement(b, 0x0008, 0x1150, 4);
    put32(b, 0);
    implicitElement(b, 0xfffe, 0xe00d, 0);
    implicitElement(b, 0xfffe, 0xe0dd, 0);
    CHECK(dicomLengthProblem(b).empty());

    Bytes bad = b;
    // The element inside the item declares more than the file holds.
    bad[30] = 0xff;
    bad[31] = 0xff;
    bad[32] = 0xff;
    bad[33] = 0x7f;
    CHECK(dicomLengthProblem(bad) ==
          "byte 26: element (0008,1150) declares 2147483647 bytes, 20 are left in the file");
}

TEST_CASE("encapsulated pixel data: fragments are skipped whole, and checked") {
    Bytes b(128, 0);
    for (char c : std::string("DICM"))
        b.push_back(std::uint8_t(c));
    const std::string jpeg = "1.2.840.10008.1.2.4.50";
    explicitElement(b, 0x0002, 0x0010, "UI", std::uint32_t(jpeg.size()));
    b.insert(b.end(), jpeg.begin(), jpeg.end());
    explicitElement(b, 0x7fe0, 0x0010, "OB", 0xffffffffu);
    implicitElement(b, 0xfffe, 0xe000, 0); // the basic offset table, empty
    implicitElement(b, 0xfffe, 0xe000, 6); // a fragment: bytes that look like a huge element
    for (std::uint8_t x : {0x08, 0x00, 0xff, 0xff, 0xff, 0xff})
        b.push_back(x);
    implicitElement(b, 0xfffe, 0xe0dd, 0);
    CHECK(dicomLengthProblem(b).empty());

    Bytes bad = b;
    bad[bad.size() - 8 - 6 - 4] = 0xff; // the fragment's length: 255 bytes
    CHECK(dicomLengthProblem(bad).find("element (fffe,e000) declares 255 bytes") !=
          std::string::npos);
}

TEST_CASE("an explicit VR element without a value representation is refused") {
    Bytes b(128, 0);
    for (char c : std::string("DICM"))
        b.push_back(std::uint8_t(c));
    explicitElement(b, 0x0002, 0x0010, "UI", 20);
    b.resize(b.size() + 20, '1');
    put16(b, 0x0008);
    put16(b, 0x0060);
    b.push_back(0x01);
    b.push_back(0x02);
    put16(b, 2);
    put16(b, 0);
    CHECK(dicomLengthProblem(b) == "byte 160: element (0008,0060) has no value representation "
                                   "(two capital letters expected)");
}

// Found by fuzz-dicom: GDCM's raw codec copied the image's size from pixel data that held less
// (a heap over-read); native pixel data is measured before GDCM decodes it.
TEST_CASE("native pixel data shorter than the image is refused before GDCM decodes it") {
    Bytes b = readFile(slice);
    const std::size_t at = pixelDataAt(b);
    REQUIRE(at > 0);
    std::uint32_t length = 0;
    std::memcpy(&length, &b[at + 8], 4);
    REQUIRE(at + 12 + length == b.size());
    const std::uint32_t shorter = length - 100;
    std::memcpy(&b[at + 8], &shorter, 4);
    b.resize(b.size() - 100);
    CHECK(dicomLengthProblem(b).empty());

    const std::string message = readError(b, "short.dcm");
    CAPTURE(message);
    CHECK(message.find("short.dcm: pixel data holds " + std::to_string(shorter) +
                       " bytes, expected " + std::to_string(length)) != std::string::npos);
}
