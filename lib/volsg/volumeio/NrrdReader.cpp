// NRRD (teem's "nearly raw raster data"): a text header of "field: value" lines, then the
// voxels, attached after a blank line or in a detached data file.

#include <cmath>
#include <memory>
#include <set>

#include <volsg/volumeio/HeaderLineReader.h>
#include <volsg/volumeio/InputFile.h>
#include <volsg/volumeio/VolumeReader.h>
#include <volsg/volumeio/VoxelPayload.h>

namespace volsg {

namespace {

struct NrrdHeader {
    int dimension = 0;
    bool hasType = false;
    VoxelType type = VoxelType::UByte;
    std::string encoding; // "raw" or "gzip"
    std::string endian;   // "", "little" or "big"
    glm::ivec3 sizes{0};
    int sizesLine = 0;
    bool hasSpacings = false;
    glm::dvec3 spacings{1.0};
    bool hasDirections = false;
    glm::dvec3 directionLengths{1.0};
    glm::dmat3 directions{1.0}; ///< unit columns, in the header's space
    bool hasOrigin = false;
    glm::dvec3 origin{0.0};
    glm::dvec3 spaceToLps{1.0}; ///< signs turning the header's space into LPS
    std::string dataFile;
    std::int64_t byteSkip = 0;
    std::int64_t lineSkip = 0;
};

// NRRD's type names, with internal runs of spaces collapsed ("unsigned  short" is legal).
VoxelType parseType(const std::string& text, const HeaderLineReader& lines) {
    const std::string lower = HeaderLineReader::lowercase(text);
    std::string t;
    for (std::string_view w : HeaderLineReader::splitWords(lower))
        t += (t.empty() ? "" : " ") + std::string(w);
    for (const char* name : {"uchar", "unsigned char", "uint8", "uint8_t"})
        if (t == name) return VoxelType::UByte;
    for (const char* name :
         {"ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t"})
        if (t == name) return VoxelType::UShort;
    for (const char* name :
         {"short", "short int", "signed short", "signed short int", "int16", "int16_t"})
        if (t == name) return VoxelType::Short;
    if (t == "float") return VoxelType::Float;
    lines.fail("unknown or unsupported type '" + text +
               "' (supported: uchar, ushort, short, float)");
}

// "(x,y,z)": one vector of 3 components (or of `components` when that is not 0).
std::vector<double> parseVector(std::string_view inside, const HeaderLineReader& lines,
                                const char* what) {
    std::vector<double> out;
    for (std::size_t start = 0;;) {
        const std::size_t comma = inside.find(',', start);
        out.push_back(lines.parseNumber(inside.substr(start, comma - start), what));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    return out;
}

// "(x,y,z) (x,y,z) (x,y,z)": the length of each vector is that axis' spacing, its direction
// the axis' direction (when the vectors have 3 components).
void parseDirections(std::string_view text, const HeaderLineReader& lines, NrrdHeader& h) {
    std::vector<std::vector<double>> vectors;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == ' ' || text[i] == '\t') {
            ++i;
            continue;
        }
        if (text.substr(i, 4) == "none")
            lines.fail("space direction " + std::to_string(vectors.size() + 1) +
                       " is 'none': every axis of a 3-dimensional volume needs a direction");
        if (text[i] != '(')
            lines.fail("malformed space directions: expected '(' at '" +
                       std::string(text.substr(i)) + "'");
        const std::size_t close = text.find(')', i);
        if (close == std::string_view::npos) lines.fail("malformed space directions: missing ')'");
        vectors.push_back(
            parseVector(text.substr(i + 1, close - i - 1), lines, "space direction component"));
        if (vectors.back().size() != vectors.front().size())
            lines.fail("space directions have different numbers of components");
        double sum = 0.0;
        for (double v : vectors.back())
            sum += v * v;
        const double length = std::sqrt(sum);
        if (!(length > 0.0) || !std::isfinite(length))
            lines.fail("space direction " + std::to_string(vectors.size()) +
                       " has zero length (spacing must be finite and > 0)");
        if (vectors.size() <= 3) {
            h.directionLengths[int(vectors.size()) - 1] = length;
            if (vectors.back().size() == 3)
                for (int r = 0; r < 3; ++r)
                    h.directions[int(vectors.size()) - 1][r] =
                        vectors.back()[std::size_t(r)] / length;
        }
        i = close + 1;
    }
    if (vectors.size() != 3)
        lines.fail("expected 3 space directions, got " + std::to_string(vectors.size()));
    h.hasDirections = true;
}

// The signs that turn a NRRD space into LPS (DICOM's patient space; VolumeGeometry.h).
// Non-anatomical spaces (scanner-xyz, 3D-right-handed, ...) are kept as they are.
glm::dvec3 signsToLps(const std::string& space) {
    const std::string s = HeaderLineReader::lowercase(space);
    if (s == "right-anterior-superior" || s == "ras") return {-1, -1, 1};
    if (s == "left-anterior-superior" || s == "las") return {1, -1, 1};
    return {1, 1, 1};
}

// Reads the header up to the blank line (or the end of a detached header).
NrrdHeader parseHeader(HeaderLineReader& lines, bool& sawBlankLine) {
    std::string line;
    if (!lines.next(line) || line.size() != 8 || line.compare(0, 7, "NRRD000") != 0 ||
        line[7] < '1' || line[7] > '9')
        lines.fail("not a NRRD file: the first line must be the magic 'NRRD0001'..'NRRD0005'");
    NrrdHeader h;
    std::set<std::string> seen;
    sawBlankLine = false;
    while (lines.next(line)) {
        if (line.empty()) {
            sawBlankLine = true;
            break;
        }
        if (line[0] == '#') continue;
        const std::size_t colon = line.find(':');
        if (colon == std::string::npos)
            lines.fail("malformed header line, expected 'field: value', got '" + line + "'");
        if (colon + 1 < line.size() && line[colon + 1] == '=') continue; // "key:=value" pair
        const std::string field = HeaderLineReader::lowercase(
            HeaderLineReader::trim(std::string_view(line).substr(0, colon)));
        const std::string value(HeaderLineReader::trim(std::string_view(line).substr(colon + 1)));
        if (!seen.insert(field).second) lines.fail("duplicate field '" + field + "'");

        if (field == "dimension") {
            const std::int64_t d = lines.parseInteger(value, "dimension");
            if (d != 3)
                lines.fail("only 3-dimensional volumes are supported, header says dimension " +
                           std::to_string(d));
            h.dimension = 3;
        } else if (field == "type") {
            h.type = parseType(value, lines);
            h.hasType = true;
        } else if (field == "encoding") {
            const std::string e = HeaderLineReader::lowercase(value);
            if (e == "raw")
                h.encoding = "raw";
            else if (e == "gzip" || e == "gz")
                h.encoding = "gzip";
            else
                lines.fail("unsupported encoding '" + value + "' (supported: raw, gzip)");
        } else if (field == "endian") {
            h.endian = HeaderLineReader::lowercase(value);
            if (h.endian != "little" && h.endian != "big")
                lines.fail("unknown endian '" + value + "' (expected little or big)");
        } else if (field == "sizes") {
            const auto words = HeaderLineReader::splitWords(value);
            if (words.size() != 3)
                lines.fail("expected 3 sizes, got " + std::to_string(words.size()));
            for (int a = 0; a < 3; ++a)
                h.sizes[a] = lines.parseDimension(words[a], "size");
            h.sizesLine = lines.lineNumber();
        } else if (field == "spacings") {
            const auto words = HeaderLineReader::splitWords(value);
            if (words.size() != 3)
                lines.fail("expected 3 spacings, got " + std::to_string(words.size()));
            for (int a = 0; a < 3; ++a)
                h.spacings[a] = lines.parseSpacing(words[a], "spacing");
            h.hasSpacings = true;
        } else if (field == "space directions") {
            parseDirections(value, lines, h);
        } else if (field == "space") {
            h.spaceToLps = signsToLps(value);
        } else if (field == "space origin") {
            const std::string_view v = value;
            if (v.size() < 2 || v.front() != '(' || v.back() != ')')
                lines.fail("malformed space origin: expected '(x,y,z)', got '" + value + "'");
            const auto o = parseVector(v.substr(1, v.size() - 2), lines, "space origin component");
            if (o.size() == 3) {
                h.origin = {o[0], o[1], o[2]};
                h.hasOrigin = true;
            }
        } else if (field == "data file" || field == "datafile") {
            if (value.empty()) lines.fail("empty data file name");
            // "LIST" or "name%03d.raw min max step": one file per slice (names may hold spaces).
            if (value == "LIST" || value.rfind("LIST ", 0) == 0 ||
                (value.find('%') != std::string::npos &&
                 HeaderLineReader::splitWords(value).size() >= 4))
                lines.fail("data split over several files is not supported: '" + value + "'");
            h.dataFile = value;
        } else if (field == "byte skip" || field == "byteskip") {
            h.byteSkip = lines.parseInteger(value, "byte skip");
            if (h.byteSkip < -1)
                lines.fail("byte skip must be >= -1, got " + std::to_string(h.byteSkip));
        } else if (field == "line skip" || field == "lineskip") {
            h.lineSkip = lines.parseInteger(value, "line skip");
            if (h.lineSkip < 0)
                lines.fail("line skip must be >= 0, got " + std::to_string(h.lineSkip));
        }
        // Other fields (kinds, centers, content, ...) say nothing the grid can hold.
    }
    return h;
}

} // namespace

ref_ptr<VolumeGrid> readNrrd(const std::string& path, std::uint64_t byteLimit) {
    auto header = std::make_unique<InputFile>(path);
    HeaderLineReader lines(*header);
    bool sawBlankLine = false;
    const NrrdHeader h = parseHeader(lines, sawBlankLine);
    const auto missing = [&](const char* what) {
        header->fail(std::string("NRRD header has no '") + what + "' field");
    };
    if (h.dimension == 0) missing("dimension");
    if (h.sizes.x == 0) missing("sizes");
    if (!h.hasType) missing("type");
    if (h.encoding.empty()) missing("encoding");
    if (voxelTypeSize(h.type) > 1 && h.endian.empty())
        header->fail("NRRD header has no 'endian' field, needed for " +
                     std::string(voxelTypeName(h.type)) + " voxels");
    const glm::dvec3 spacing = h.hasSpacings ? h.spacings : h.directionLengths;
    checkedGridBytes(path, h.sizesLine, h.sizes, h.type, spacing, byteLimit);

    std::unique_ptr<InputFile> detached;
    if (!h.dataFile.empty())
        detached = InputFile::openDataFile(path, h.dataFile);
    else if (!sawBlankLine)
        header->fail("NRRD header has no 'data file' field and no blank line before attached data");
    InputFile& data = detached ? *detached : *header;
    data.skipLines(std::uint64_t(h.lineSkip));

    VoxelPayload payload;
    payload.offset = data.position();
    payload.bigEndian = h.endian == "big";
    if (h.encoding == "gzip") {
        if (h.byteSkip < 0) header->fail("byte skip -1 is only allowed with raw encoding");
        payload.compression = "gzip";
        payload.decompressedSkip = std::uint64_t(h.byteSkip);
    } else if (h.byteSkip < 0) {
        payload.atEnd = true;
    } else {
        payload.offset += std::uint64_t(h.byteSkip);
    }
    ref_ptr<VolumeGrid> grid =
        readVoxelGrid(path, h.sizesLine, h.sizes, h.type, spacing, byteLimit, data, payload);
    if (h.hasDirections) {
        VolumeGeometry geometry;
        geometry.known = true;
        const glm::dmat3 toLps(glm::dvec3(h.spaceToLps.x, 0, 0), glm::dvec3(0, h.spaceToLps.y, 0),
                               glm::dvec3(0, 0, h.spaceToLps.z));
        geometry.directions = toLps * h.directions;
        geometry.origin = toLps * h.origin;
        grid->setGeometry(geometry);
    }
    return grid;
}

} // namespace volsg
