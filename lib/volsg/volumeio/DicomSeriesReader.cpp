// DICOM series: one file per slice, read with GDCM (Debian libgdcm-dev). GDCM parses the data
// sets and decodes every transfer syntax it knows (raw, RLE, JPEG, JPEG-LS, JPEG 2000), which
// no hand-written reader could match; this file picks the series, orders and checks the
// slices, and places the volume (docs/SCENE-FORMAT.md section 3.8).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <vector>

#include <gdcmAttribute.h>
#include <gdcmImage.h>
#include <gdcmImageReader.h>
#include <gdcmReader.h>
#include <gdcmTrace.h>

#include <volsg/core/Error.h>
#include <volsg/volumeio/VolumeReader.h>
#include <volsg/volumeio/VoxelPayload.h>

namespace volsg {

namespace {

/// Most files a folder may hold for a series to be read from it.
constexpr std::size_t maxSeriesFiles = 20000;

const gdcm::Tag pixelDataTag(0x7fe0, 0x0010);

// What one slice's header says.
struct Slice {
    std::string path;
    std::string seriesUid;
    int rows = 0, columns = 0;
    int bitsAllocated = 0, bitsStored = 0, pixelRepresentation = 0, samples = 1, frames = 1;
    bool hasPosition = false, hasOrientation = false;
    glm::dvec3 position{0.0};
    glm::dvec3 rowDirection{1, 0, 0}, columnDirection{0, 1, 0};
    glm::dvec2 pixelSpacing{1.0}; // between rows (y), between columns (x)
    double sliceThickness = 0.0;
    double slope = 1.0, intercept = 0.0;
    double along = 0.0; // position along the series normal
};

// The text of an element, without DICOM's trailing padding; empty when absent.
std::string elementText(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
    if (!ds.FindDataElement(tag)) return {};
    const gdcm::ByteValue* bv = ds.GetDataElement(tag).GetByteValue();
    if (!bv || bv->GetLength() > 4096) return {};
    std::string s(bv->GetPointer(), bv->GetLength());
    while (!s.empty() && (s.back() == ' ' || s.back() == '\0'))
        s.pop_back();
    return s;
}

// A DS or IS value with `count` backslash-separated numbers; false when absent or malformed.
bool elementNumbers(const gdcm::DataSet& ds, const gdcm::Tag& tag, double* out, int count) {
    const std::string text = elementText(ds, tag);
    if (text.empty()) return false;
    std::size_t start = 0;
    for (int i = 0; i < count; ++i) {
        const std::size_t end = text.find('\\', start);
        const std::string word = text.substr(start, end == std::string::npos ? end : end - start);
        char* stop = nullptr;
        out[i] = std::strtod(word.c_str(), &stop);
        while (stop && *stop == ' ')
            ++stop;
        if (word.empty() || !stop || *stop != '\0' || !std::isfinite(out[i])) return false;
        if (end == std::string::npos && i + 1 < count) return false;
        start = end + 1;
    }
    return true;
}

template <std::uint16_t Group, std::uint16_t Element> int unsignedShort(const gdcm::DataSet& ds) {
    if (!ds.FindDataElement(gdcm::Tag(Group, Element))) return 0;
    gdcm::Attribute<Group, Element> a;
    a.SetFromDataSet(ds);
    return int(a.GetValue());
}

// The slice's header (everything before the pixel data), or false when the file is not DICOM.
bool readSliceHeaderUnguarded(const std::string& path, Slice& s) {
    gdcm::Reader reader;
    reader.SetFileName(path.c_str());
    std::set<gdcm::Tag> skip{pixelDataTag};
    if (!reader.ReadUpToTag(pixelDataTag, skip)) return false;
    const gdcm::DataSet& ds = reader.GetFile().GetDataSet();
    s.path = path;
    s.seriesUid = elementText(ds, gdcm::Tag(0x0020, 0x000e));
    s.rows = unsignedShort<0x0028, 0x0010>(ds);
    s.columns = unsignedShort<0x0028, 0x0011>(ds);
    s.samples = std::max(1, unsignedShort<0x0028, 0x0002>(ds));
    s.bitsAllocated = unsignedShort<0x0028, 0x0100>(ds);
    s.bitsStored = unsignedShort<0x0028, 0x0101>(ds);
    s.pixelRepresentation = unsignedShort<0x0028, 0x0103>(ds);
    double v[6];
    if (elementNumbers(ds, gdcm::Tag(0x0028, 0x0008), v, 1)) s.frames = int(v[0]);
    if ((s.hasPosition = elementNumbers(ds, gdcm::Tag(0x0020, 0x0032), v, 3)))
        s.position = {v[0], v[1], v[2]};
    if ((s.hasOrientation = elementNumbers(ds, gdcm::Tag(0x0020, 0x0037), v, 6))) {
        s.rowDirection = {v[0], v[1], v[2]};
        s.columnDirection = {v[3], v[4], v[5]};
    }
    if (elementNumbers(ds, gdcm::Tag(0x0028, 0x0030), v, 2)) s.pixelSpacing = {v[0], v[1]};
    if (elementNumbers(ds, gdcm::Tag(0x0018, 0x0050), v, 1)) s.sliceThickness = v[0];
    if (elementNumbers(ds, gdcm::Tag(0x0028, 0x1053), v, 1)) s.slope = v[0];
    if (elementNumbers(ds, gdcm::Tag(0x0028, 0x1052), v, 1)) s.intercept = v[0];
    return true;
}

// readSliceHeaderUnguarded, with whatever GDCM throws on malformed input (bad_alloc for an
// absurd element length, its own exceptions) taken as "not a DICOM file GDCM can read".
bool readSliceHeader(const std::string& path, Slice& s) {
    try {
        return readSliceHeaderUnguarded(path, s);
    } catch (const std::exception&) {
        return false;
    }
}

// The files that may hold the series: the folder's regular files, in name order.
std::vector<std::string> folderFiles(const std::filesystem::path& folder) {
    std::vector<std::string> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        if (!entry.is_regular_file(ec)) continue;
        if (files.size() == maxSeriesFiles)
            throw Error("more than " + std::to_string(maxSeriesFiles) +
                            " files in the folder: not read as one DICOM series",
                        folder.string());
        files.push_back(entry.path().string());
    }
    if (ec) throw Error("cannot list the DICOM folder: " + ec.message(), folder.string());
    std::sort(files.begin(), files.end());
    return files;
}

// The slices of the series `path` names: the named file's series, or the folder's largest.
std::vector<Slice> collectSeries(const std::string& path) {
    std::error_code ec;
    const bool folder = std::filesystem::is_directory(path, ec);
    std::string wantedUid;
    if (!folder) {
        Slice named;
        if (!std::filesystem::is_regular_file(path, ec))
            throw Error("cannot open DICOM file: No such file or directory", path);
        if (!readSliceHeader(path, named))
            throw Error("not a DICOM file (GDCM cannot parse it)", path);
        wantedUid = named.seriesUid;
    }
    const std::filesystem::path where =
        folder ? std::filesystem::path(path) : std::filesystem::path(path).parent_path();
    std::map<std::string, std::vector<Slice>> bySeries;
    for (const std::string& file : folderFiles(where.empty() ? "." : where)) {
        Slice s;
        if (!readSliceHeader(file, s)) continue; // not DICOM: a README, a DICOMDIR's sibling
        if (!folder && s.seriesUid != wantedUid) continue;
        bySeries[s.seriesUid].push_back(std::move(s));
    }
    if (bySeries.empty()) throw Error("no DICOM files in the folder", path);
    auto largest = std::max_element(bySeries.begin(), bySeries.end(), [](auto& a, auto& b) {
        return a.second.size() < b.second.size();
    });
    return std::move(largest->second);
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    return glm::length(a - b) <= tolerance;
}

// Checks that the slices make one regular volume and orders them along their normal; returns
// the slice spacing.
double orderSlices(std::vector<Slice>& slices) {
    const Slice& first = slices.front();
    const auto fail = [&](const Slice& s, const std::string& what) -> void {
        throw Error(what + " (series of " + std::to_string(slices.size()) + " slices)", s.path);
    };
    for (const Slice& s : slices) {
        if (s.frames != 1) fail(s, "multi-frame DICOM files are not supported");
        if (s.samples != 1)
            fail(s, "colour DICOM images (SamplesPerPixel " + std::to_string(s.samples) +
                        ") are not supported");
        if (s.rows < 1 || s.columns < 1) fail(s, "slice has no Rows or Columns");
        if (s.rows != first.rows || s.columns != first.columns)
            fail(s, "slice size differs from the series' first slice");
        if (s.bitsAllocated != first.bitsAllocated ||
            s.pixelRepresentation != first.pixelRepresentation)
            fail(s, "pixel format differs from the series' first slice");
        if (!near(s.rowDirection, first.rowDirection, 1e-4) ||
            !near(s.columnDirection, first.columnDirection, 1e-4))
            fail(s, "Image Orientation (Patient) differs from the series' first slice");
        if (std::abs(s.pixelSpacing.x - first.pixelSpacing.x) > 1e-4 ||
            std::abs(s.pixelSpacing.y - first.pixelSpacing.y) > 1e-4)
            fail(s, "Pixel Spacing differs from the series' first slice");
        if (slices.size() > 1 && !s.hasPosition)
            fail(s, "slice has no Image Position (Patient): the series cannot be ordered");
    }
    const glm::dvec3 normal = glm::cross(first.rowDirection, first.columnDirection);
    if (!(glm::length(normal) > 0.5)) fail(first, "Image Orientation (Patient) is degenerate");
    for (Slice& s : slices)
        s.along = glm::dot(s.position, normal);
    std::sort(slices.begin(), slices.end(),
              [](const Slice& a, const Slice& b) { return a.along < b.along; });
    if (slices.size() == 1) return first.sliceThickness > 0.0 ? first.sliceThickness : 1.0;
    std::vector<double> gaps;
    for (std::size_t i = 1; i < slices.size(); ++i) {
        gaps.push_back(slices[i].along - slices[i - 1].along);
        if (!(gaps.back() > 0.0))
            fail(slices[i], "two slices at the same position (" + std::to_string(slices[i].along) +
                                " mm along the normal): a series with repeats cannot be read");
    }
    // Against the median gap, so that a missing slice is named where it is missing.
    std::vector<double> sorted = gaps;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(sorted.size() / 2),
                     sorted.end());
    const double spacing = sorted[sorted.size() / 2];
    for (std::size_t i = 0; i < gaps.size(); ++i)
        if (std::abs(gaps[i] - spacing) > 0.01 * spacing + 1e-3)
            fail(slices[i + 1], "slices are not evenly spaced: a gap of " +
                                    std::to_string(gaps[i]) + " mm before this slice, where the " +
                                    "others are " + std::to_string(spacing) + " mm");
    return spacing;
}

// The grid type that holds stored * slope + intercept exactly: the stored type when the
// rescale is the identity, SHORT for integer shifts that fit (CT in Hounsfield units), else
// FLOAT.
VoxelType gridTypeFor(const std::vector<Slice>& slices) {
    const Slice& first = slices.front();
    bool identity = true, integerShift = true;
    double lowest = 0.0, highest = 0.0;
    const int bits = first.bitsStored > 0 ? std::min(first.bitsStored, first.bitsAllocated)
                                          : first.bitsAllocated;
    const double storedLo = first.pixelRepresentation ? -std::ldexp(1.0, bits - 1) : 0.0;
    const double storedHi =
        first.pixelRepresentation ? std::ldexp(1.0, bits - 1) - 1.0 : std::ldexp(1.0, bits) - 1.0;
    for (const Slice& s : slices) {
        if (s.slope != 1.0 || s.intercept != 0.0) identity = false;
        if (s.slope != 1.0 || s.intercept != std::floor(s.intercept)) integerShift = false;
        lowest = std::min(lowest, storedLo + s.intercept);
        highest = std::max(highest, storedHi + s.intercept);
    }
    if (identity) {
        if (first.bitsAllocated == 8 && !first.pixelRepresentation) return VoxelType::UByte;
        if (first.bitsAllocated == 16)
            return first.pixelRepresentation ? VoxelType::Short : VoxelType::UShort;
    }
    if (integerShift && first.bitsAllocated <= 16 && lowest >= -32768.0 && highest <= 32767.0)
        return VoxelType::Short;
    return VoxelType::Float;
}

// Decodes one slice's pixels (any transfer syntax GDCM knows) into `out`, rescaled.
void readSlicePixels(const Slice& s, ref_ptr<VolumeGrid>& grid, int k, std::vector<char>& buffer) {
    gdcm::ImageReader reader;
    reader.SetFileName(s.path.c_str());
    bool read = false;
    try {
        read = reader.Read();
    } catch (const std::exception& e) {
        throw Error(std::string("GDCM cannot read the slice's pixel data: ") + e.what(), s.path);
    }
    if (!read) throw Error("GDCM cannot read the slice's pixel data", s.path);
    const gdcm::Image& image = reader.GetImage();
    const std::size_t pixels = std::size_t(s.rows) * std::size_t(s.columns);
    const std::size_t bytesPer = std::size_t(s.bitsAllocated) / 8;
    if (image.GetBufferLength() != pixels * bytesPer)
        throw Error("pixel data holds " + std::to_string(image.GetBufferLength()) +
                        " bytes, expected " + std::to_string(pixels * bytesPer) + " (" +
                        std::to_string(s.columns) + " x " + std::to_string(s.rows) + " x " +
                        std::to_string(bytesPer) + ")",
                    s.path);
    buffer.resize(pixels * bytesPer);
    bool decoded = false;
    try {
        decoded = image.GetBuffer(buffer.data());
    } catch (const std::exception& e) {
        throw Error(std::string("GDCM cannot decode the slice's pixel data: ") + e.what(), s.path);
    }
    if (!decoded) throw Error("GDCM cannot decode the slice's pixel data", s.path);
    const std::size_t base = grid->index(0, 0, k);
    for (std::size_t i = 0; i < pixels; ++i) {
        double stored;
        if (bytesPer == 1) {
            stored = s.pixelRepresentation ? double(std::int8_t(buffer[i]))
                                           : double(std::uint8_t(buffer[i]));
        } else {
            std::uint16_t raw;
            std::memcpy(&raw, buffer.data() + 2 * i, 2);
            stored = s.pixelRepresentation ? double(std::int16_t(raw)) : double(raw);
        }
        grid->setValue(base + i, stored * s.slope + s.intercept);
    }
}

} // namespace

bool isDicomFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::array<char, 132> head{};
    in.read(head.data(), std::streamsize(head.size()));
    return in.gcount() == std::streamsize(head.size()) &&
           std::memcmp(head.data() + 128, "DICM", 4) == 0;
}

ref_ptr<VolumeGrid> readDicomSeries(const std::string& path, std::uint64_t byteLimit) {
    // GDCM reports problems on stderr; the errors here say them once, naming the file.
    gdcm::Trace::DebugOff();
    gdcm::Trace::WarningOff();
    gdcm::Trace::ErrorOff();
    std::vector<Slice> slices = collectSeries(path);
    const double sliceSpacing = orderSlices(slices);
    const Slice& first = slices.front();
    if (first.bitsAllocated != 8 && first.bitsAllocated != 16)
        throw Error("DICOM BitsAllocated " + std::to_string(first.bitsAllocated) +
                        " is not supported (8 or 16)",
                    first.path);
    const glm::ivec3 dims(first.columns, first.rows, int(slices.size()));
    const glm::dvec3 spacing(first.pixelSpacing.y, first.pixelSpacing.x, sliceSpacing);
    const VoxelType type = gridTypeFor(slices);
    checkedGridBytes(first.path, 0, dims, type, spacing, byteLimit);
    ref_ptr<VolumeGrid> grid = VolumeGrid::create(dims, type, spacing, byteLimit);
    std::vector<char> buffer;
    for (std::size_t k = 0; k < slices.size(); ++k)
        readSlicePixels(slices[k], grid, int(k), buffer);

    VolumeGeometry geometry;
    geometry.known = first.hasPosition && first.hasOrientation;
    geometry.directions =
        glm::dmat3(glm::normalize(first.rowDirection), glm::normalize(first.columnDirection),
                   glm::normalize(glm::cross(first.rowDirection, first.columnDirection)));
    geometry.origin = first.position;
    grid->setGeometry(geometry);
    return grid;
}

} // namespace volsg
