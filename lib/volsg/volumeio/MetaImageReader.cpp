// MetaImage (ITK's MetaIO): "Key = Value" header lines ending with ElementDataFile, then the
// voxels in the same file (LOCAL, .mha) or in a separate one (.mhd).

#include <memory>
#include <set>

#include <volsg/volumeio/HeaderLineReader.h>
#include <volsg/volumeio/InputFile.h>
#include <volsg/volumeio/VolumeReader.h>
#include <volsg/volumeio/VoxelPayload.h>

namespace volsg {

namespace {

struct MetaImageHeader {
    int dimensionCount = 0;
    glm::ivec3 sizes{0};
    int sizesLine = 0;
    bool hasType = false;
    VoxelType type = VoxelType::UByte;
    bool hasSpacing = false;
    glm::dvec3 spacing{1.0};
    bool hasElementSize = false;
    glm::dvec3 elementSize{1.0};
    bool bigEndian = false;
    bool compressed = false;
    std::uint64_t compressedSize = 0; // 0: not given
    std::int64_t headerSize = 0;
    std::string dataFile;
    bool hasPlacement = false;  ///< Offset or TransformMatrix given
    glm::dvec3 offset{0.0};     ///< Offset (Position, Origin): voxel 0's centre, LPS
    glm::dmat3 directions{1.0}; ///< TransformMatrix (Rotation, Orientation), column per axis
};

// "n n n": three finite numbers.
glm::dvec3 parseTriple(const std::string& value, const char* what, const HeaderLineReader& lines) {
    const auto words = HeaderLineReader::splitWords(value);
    if (words.size() != 3)
        lines.fail(std::string("expected 3 values in ") + what + ", got " +
                   std::to_string(words.size()));
    return {lines.parseNumber(words[0], what), lines.parseNumber(words[1], what),
            lines.parseNumber(words[2], what)};
}

// MetaIO writes the matrix row by row, each row the direction of one index axis (ITK's
// direction matrix transposed); ITK's MetaImages are in LPS.
glm::dmat3 parseDirections(const std::string& value, const HeaderLineReader& lines) {
    const auto words = HeaderLineReader::splitWords(value);
    if (words.size() != 9)
        lines.fail("expected 9 values in TransformMatrix, got " + std::to_string(words.size()));
    glm::dmat3 m;
    for (int axis = 0; axis < 3; ++axis) {
        for (int r = 0; r < 3; ++r)
            m[axis][r] = lines.parseNumber(words[std::size_t(3 * axis + r)], "TransformMatrix");
        const double length = glm::length(m[axis]);
        if (!(length > 0.0)) lines.fail("TransformMatrix has a zero axis");
        m[axis] /= length;
    }
    return m;
}

VoxelType parseElementType(const std::string& text, const HeaderLineReader& lines) {
    if (text == "MET_UCHAR") return VoxelType::UByte;
    if (text == "MET_USHORT") return VoxelType::UShort;
    if (text == "MET_SHORT") return VoxelType::Short;
    if (text == "MET_FLOAT") return VoxelType::Float;
    lines.fail("unknown or unsupported ElementType '" + text +
               "' (supported: MET_UCHAR, MET_USHORT, MET_SHORT, MET_FLOAT)");
}

glm::dvec3 parseSpacingTriple(const std::string& value, const char* what,
                              const HeaderLineReader& lines) {
    const auto words = HeaderLineReader::splitWords(value);
    if (words.size() != 3)
        lines.fail(std::string("expected 3 values in ") + what + ", got " +
                   std::to_string(words.size()));
    glm::dvec3 s;
    for (int a = 0; a < 3; ++a)
        s[a] = lines.parseSpacing(words[a], what);
    return s;
}

// Reads "Key = Value" lines up to and including ElementDataFile, which MetaIO writes last.
MetaImageHeader parseHeader(HeaderLineReader& lines) {
    MetaImageHeader h;
    std::set<std::string> seen;
    std::string line;
    bool sawDataFile = false;
    while (lines.next(line)) {
        if (HeaderLineReader::trim(line).empty()) continue;
        const std::size_t equals = line.find('=');
        if (equals == std::string::npos)
            lines.fail("malformed header line, expected 'Key = Value', got '" +
                       std::string(line.substr(0, 80)) + "'");
        const std::string key = HeaderLineReader::lowercase(
            HeaderLineReader::trim(std::string_view(line).substr(0, equals)));
        const std::string value(HeaderLineReader::trim(std::string_view(line).substr(equals + 1)));
        if (!seen.insert(key).second) lines.fail("duplicate key '" + key + "'");

        if (key == "objecttype") {
            if (HeaderLineReader::lowercase(value) != "image")
                lines.fail("unsupported ObjectType '" + value + "' (expected Image)");
        } else if (key == "ndims") {
            const std::int64_t n = lines.parseInteger(value, "NDims");
            if (n != 3)
                lines.fail("only 3-dimensional volumes are supported, header says NDims " +
                           std::to_string(n));
            h.dimensionCount = 3;
        } else if (key == "dimsize") {
            const auto words = HeaderLineReader::splitWords(value);
            if (words.size() != 3)
                lines.fail("expected 3 values in DimSize, got " + std::to_string(words.size()));
            for (int a = 0; a < 3; ++a)
                h.sizes[a] = lines.parseDimension(words[a], "DimSize");
            h.sizesLine = lines.lineNumber();
        } else if (key == "elementtype") {
            h.type = parseElementType(value, lines);
            h.hasType = true;
        } else if (key == "elementspacing") {
            h.spacing = parseSpacingTriple(value, "ElementSpacing", lines);
            h.hasSpacing = true;
        } else if (key == "elementsize") {
            h.elementSize = parseSpacingTriple(value, "ElementSize", lines);
            h.hasElementSize = true;
        } else if (key == "binarydatabyteordermsb" || key == "elementbyteordermsb") {
            h.bigEndian = lines.parseBool(value, line.substr(0, equals));
        } else if (key == "binarydata") {
            if (!lines.parseBool(value, "BinaryData"))
                lines.fail("ASCII MetaImage data (BinaryData = False) is not supported");
        } else if (key == "compresseddata") {
            h.compressed = lines.parseBool(value, "CompressedData");
        } else if (key == "compresseddatasize") {
            const std::int64_t n = lines.parseInteger(value, "CompressedDataSize");
            if (n < 1) lines.fail("CompressedDataSize must be >= 1, got " + std::to_string(n));
            h.compressedSize = std::uint64_t(n);
        } else if (key == "headersize") {
            h.headerSize = lines.parseInteger(value, "HeaderSize");
            if (h.headerSize < -1)
                lines.fail("HeaderSize must be >= -1, got " + std::to_string(h.headerSize));
        } else if (key == "elementnumberofchannels") {
            if (lines.parseInteger(value, "ElementNumberOfChannels") != 1)
                lines.fail("only single-channel volumes are supported, ElementNumberOfChannels "
                           "is " +
                           value);
        } else if (key == "offset" || key == "position" || key == "origin") {
            h.offset = parseTriple(value, "Offset", lines);
            h.hasPlacement = true;
        } else if (key == "transformmatrix" || key == "rotation" || key == "orientation") {
            h.directions = parseDirections(value, lines);
            h.hasPlacement = true;
        } else if (key == "elementdatafile") {
            if (value.empty()) lines.fail("empty ElementDataFile");
            // "LIST" or "name%03d.raw min max step": one file per slice (names may hold spaces).
            if (value == "LIST" || value.rfind("LIST ", 0) == 0 ||
                (value.find('%') != std::string::npos &&
                 HeaderLineReader::splitWords(value).size() >= 4))
                lines.fail("data split over several files is not supported: '" + value + "'");
            h.dataFile = value;
            sawDataFile = true;
            break;
        }
        // Other keys (CenterOfRotation, AnatomicalOrientation, ElementMin/Max, ...) say
        // nothing the grid holds.
    }
    if (!sawDataFile) lines.fail("MetaImage header has no ElementDataFile line");
    return h;
}

} // namespace

ref_ptr<VolumeGrid> readMetaImage(const std::string& path, std::uint64_t byteLimit) {
    auto header = std::make_unique<InputFile>(path);
    HeaderLineReader lines(*header);
    const MetaImageHeader h = parseHeader(lines);
    if (h.sizes.x == 0) header->fail("MetaImage header has no DimSize (no dimensions)");
    if (!h.hasType) header->fail("MetaImage header has no ElementType");
    const glm::dvec3 spacing = h.hasSpacing ? h.spacing : h.elementSize;
    checkedGridBytes(path, h.sizesLine, h.sizes, h.type, spacing, byteLimit);

    const bool local = HeaderLineReader::lowercase(h.dataFile) == "local";
    std::unique_ptr<InputFile> detached;
    if (!local) detached = InputFile::openDataFile(path, h.dataFile);
    InputFile& data = detached ? *detached : *header;

    VoxelPayload payload;
    payload.offset = data.position(); // just past ElementDataFile for LOCAL, else 0
    payload.bigEndian = h.bigEndian;
    if (h.compressed) {
        payload.compression = "zlib";
        payload.compressedSize = h.compressedSize;
        if (h.headerSize == -1) {
            if (h.compressedSize == 0)
                header->fail("HeaderSize = -1 with CompressedData needs CompressedDataSize");
            if (h.compressedSize > data.size())
                data.fail("CompressedDataSize " + std::to_string(h.compressedSize) +
                          " exceeds the file size " + std::to_string(data.size()));
            payload.offset = data.size() - h.compressedSize;
        } else {
            payload.offset += std::uint64_t(h.headerSize);
        }
    } else if (h.headerSize == -1) {
        payload.atEnd = true;
    } else {
        payload.offset += std::uint64_t(h.headerSize);
    }
    ref_ptr<VolumeGrid> grid =
        readVoxelGrid(path, h.sizesLine, h.sizes, h.type, spacing, byteLimit, data, payload);
    if (h.hasPlacement) {
        VolumeGeometry geometry;
        geometry.known = true;
        geometry.directions = h.directions;
        geometry.origin = h.offset;
        grid->setGeometry(geometry);
    }
    return grid;
}

} // namespace volsg
