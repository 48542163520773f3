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
#include <optional>
#include <set>
#include <span>
#include <vector>

#include <gdcmAttribute.h>
#include <gdcmImage.h>
#include <gdcmImageReader.h>
#include <gdcmReader.h>
#include <gdcmTrace.h>

#include <volsg/core/Error.h>
#include <volsg/volumeio/DicomLengths.h>
#include <volsg/volumeio/IsolatedCall.h>
#include <volsg/volumeio/VolumeReader.h>
#include <volsg/volumeio/VoxelPayload.h>

namespace volsg {

namespace {

/// Most files a folder may hold for a series to be read from it.
constexpr std::size_t maxSeriesFiles = 20000;
/// Largest file read as one slice (a 16384^2 slice of 32-bit values is 1 GiB).
constexpr std::uintmax_t maxSliceFileBytes = std::uintmax_t(1) << 30;

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

// Why the file cannot be a DICOM slice whose every declared length fits in it, or "": GDCM
// sizes buffers from declared lengths, so they are checked first (DicomLengths.h).
std::string lengthProblem(const std::string& path, DicomPixelData* pixels = nullptr) {
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return "cannot read it: " + ec.message();
    if (size > maxSliceFileBytes)
        return "larger than " + std::to_string(maxSliceFileBytes) +
               " bytes, more than one single-frame slice takes";
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    std::ifstream in(path, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        return "cannot read it";
    return dicomLengthProblem(bytes, pixels);
}

// readSliceHeaderUnguarded after the length check, with whatever GDCM throws on malformed input
// taken as "not a DICOM file GDCM can read"; `why` (when given) says what was wrong.
bool readSliceHeader(const std::string& path, Slice& s, std::string* why = nullptr) {
    std::string problem = lengthProblem(path);
    if (problem.empty()) {
        try {
            if (readSliceHeaderUnguarded(path, s)) return true;
            problem = "GDCM cannot parse it";
        } catch (const std::exception&) {
            problem = "GDCM cannot parse it";
        }
    }
    if (why) *why = std::move(problem);
    return false;
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

// A slice header as the isolated child hands it over (plain bytes in shared memory).
struct SliceRecord {
    bool ok = false;
    char seriesUid[80] = {};
    char why[240] = {};
    int rows, columns, bitsAllocated, bitsStored, pixelRepresentation, samples, frames;
    bool hasPosition, hasOrientation;
    double position[3], rowDirection[3], columnDirection[3], pixelSpacing[2];
    double sliceThickness, slope, intercept;
};

void copyText(char* to, std::size_t size, const std::string& text) {
    const std::size_t n = std::min(text.size(), size - 1);
    std::memcpy(to, text.data(), n);
    to[n] = '\0';
}

SliceRecord toRecord(const Slice& s) {
    SliceRecord r;
    r.ok = true;
    copyText(r.seriesUid, sizeof r.seriesUid, s.seriesUid);
    r.rows = s.rows;
    r.columns = s.columns;
    r.bitsAllocated = s.bitsAllocated;
    r.bitsStored = s.bitsStored;
    r.pixelRepresentation = s.pixelRepresentation;
    r.samples = s.samples;
    r.frames = s.frames;
    r.hasPosition = s.hasPosition;
    r.hasOrientation = s.hasOrientation;
    for (int i = 0; i < 3; ++i) {
        r.position[i] = s.position[i];
        r.rowDirection[i] = s.rowDirection[i];
        r.columnDirection[i] = s.columnDirection[i];
    }
    r.pixelSpacing[0] = s.pixelSpacing[0];
    r.pixelSpacing[1] = s.pixelSpacing[1];
    r.sliceThickness = s.sliceThickness;
    r.slope = s.slope;
    r.intercept = s.intercept;
    return r;
}

Slice fromRecord(const SliceRecord& r, const std::string& path) {
    Slice s;
    s.path = path;
    s.seriesUid = r.seriesUid;
    s.rows = r.rows;
    s.columns = r.columns;
    s.bitsAllocated = r.bitsAllocated;
    s.bitsStored = r.bitsStored;
    s.pixelRepresentation = r.pixelRepresentation;
    s.samples = r.samples;
    s.frames = r.frames;
    s.hasPosition = r.hasPosition;
    s.hasOrientation = r.hasOrientation;
    s.position = {r.position[0], r.position[1], r.position[2]};
    s.rowDirection = {r.rowDirection[0], r.rowDirection[1], r.rowDirection[2]};
    s.columnDirection = {r.columnDirection[0], r.columnDirection[1], r.columnDirection[2]};
    s.pixelSpacing = {r.pixelSpacing[0], r.pixelSpacing[1]};
    s.sliceThickness = r.sliceThickness;
    s.slope = r.slope;
    s.intercept = r.intercept;
    return s;
}

// The headers of `files`, read by GDCM in a child process (IsolatedCall.h): a slot per file,
// empty where the file is not a DICOM slice GDCM reads, with the reason in `why`. A file on
// which GDCM aborts is found by reading the files one child each.
std::vector<std::optional<Slice>> readSliceHeaders(const std::vector<std::string>& files,
                                                   std::vector<std::string>& why) {
    std::vector<SliceRecord> records(files.size());
    const auto readAll = [&](std::size_t begin, std::size_t end) {
        return runIsolated((end - begin) * sizeof(SliceRecord),
                           [&](std::span<std::byte> shared, std::string&) {
                               for (std::size_t i = begin; i < end; ++i) {
                                   Slice s;
                                   std::string reason;
                                   SliceRecord r;
                                   if (readSliceHeader(files[i], s, &reason))
                                       r = toRecord(s);
                                   else
                                       copyText(r.why, sizeof r.why, reason);
                                   std::memcpy(shared.data() + (i - begin) * sizeof r, &r,
                                               sizeof r);
                               }
                               return true;
                           },
                           [&](std::span<const std::byte> shared) {
                               std::memcpy(static_cast<void*>(records.data() + begin),
                                           shared.data(), (end - begin) * sizeof(SliceRecord));
                           });
    };
    if (!readAll(0, files.size()).ok)
        for (std::size_t i = 0; i < files.size(); ++i) {
            const IsolatedOutcome one = readAll(i, i + 1);
            if (!one.ok)
                copyText(records[i].why, sizeof records[i].why,
                         "GDCM stopped on it: " + one.message);
        }
    std::vector<std::optional<Slice>> out(files.size());
    why.assign(files.size(), std::string());
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (records[i].ok)
            out[i] = fromRecord(records[i], files[i]);
        else
            why[i] = records[i].why;
    }
    return out;
}

// The slices of the series `path` names: the named file's series, or the folder's largest.
std::vector<Slice> collectSeries(const std::string& path) {
    std::error_code ec;
    const bool folder = std::filesystem::is_directory(path, ec);
    std::string wantedUid;
    if (!folder) {
        if (!std::filesystem::is_regular_file(path, ec))
            throw Error("cannot open DICOM file: No such file or directory", path);
        std::vector<std::string> why;
        const auto named = readSliceHeaders({path}, why);
        if (!named[0]) throw Error("not a DICOM file: " + why[0], path);
        wantedUid = named[0]->seriesUid;
    }
    const std::filesystem::path where =
        folder ? std::filesystem::path(path) : std::filesystem::path(path).parent_path();
    const std::vector<std::string> files = folderFiles(where.empty() ? "." : where);
    std::vector<std::string> why;
    std::vector<std::optional<Slice>> headers = readSliceHeaders(files, why);
    std::map<std::string, std::vector<Slice>> bySeries;
    for (std::optional<Slice>& s : headers) {
        if (!s) continue; // not DICOM: a README, a DICOMDIR's sibling
        if (!folder && s->seriesUid != wantedUid) continue;
        bySeries[s->seriesUid].push_back(std::move(*s));
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

// Decodes one slice's stored pixels (any transfer syntax GDCM knows) into `out`, which holds
// rows x columns x bitsAllocated / 8 bytes. Runs in the isolated child.
void decodeSlicePixels(const Slice& s, std::span<std::byte> out) {
    // GDCM's raw codec copies as many bytes as the image should have, whatever the pixel data
    // holds (a heap over-read): native pixel data is measured first.
    DicomPixelData pixels;
    if (const std::string problem = lengthProblem(s.path, &pixels); !problem.empty())
        throw Error("not a DICOM file: " + problem, s.path);
    if (!pixels.found) throw Error("the slice has no pixel data", s.path);
    if (!pixels.encapsulated && pixels.length < out.size())
        throw Error("pixel data holds " + std::to_string(pixels.length) + " bytes, expected " +
                        std::to_string(out.size()) + " (" + std::to_string(s.columns) + " x " +
                        std::to_string(s.rows) + " x " + std::to_string(s.bitsAllocated / 8) + ")",
                    s.path);
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
    if (image.GetBufferLength() != out.size())
        throw Error("pixel data holds " + std::to_string(image.GetBufferLength()) +
                        " bytes, expected " + std::to_string(out.size()) + " (" +
                        std::to_string(s.columns) + " x " + std::to_string(s.rows) + " x " +
                        std::to_string(s.bitsAllocated / 8) + ")",
                    s.path);
    bool decoded = false;
    try {
        decoded = image.GetBuffer(reinterpret_cast<char*>(out.data()));
    } catch (const std::exception& e) {
        throw Error(std::string("GDCM cannot decode the slice's pixel data: ") + e.what(), s.path);
    }
    if (!decoded) throw Error("GDCM cannot decode the slice's pixel data", s.path);
}

// Slice k's stored values, rescaled, into the grid.
void storeSlice(const Slice& s, std::span<const std::byte> stored, VolumeGrid& grid, int k) {
    const std::size_t pixels = std::size_t(s.rows) * std::size_t(s.columns);
    const std::size_t bytesPer = std::size_t(s.bitsAllocated) / 8;
    const std::size_t base = grid.index(0, 0, k);
    for (std::size_t i = 0; i < pixels; ++i) {
        double value;
        if (bytesPer == 1) {
            const auto b = std::uint8_t(stored[i]);
            value = s.pixelRepresentation ? double(std::int8_t(b)) : double(b);
        } else {
            std::uint16_t raw;
            std::memcpy(&raw, stored.data() + 2 * i, 2);
            value = s.pixelRepresentation ? double(std::int16_t(raw)) : double(raw);
        }
        grid.setValue(base + i, value * s.slope + s.intercept);
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
    // The stored pixels of every slice, decoded by GDCM in the isolated child; the sizes were
    // checked against the byte limit above (checkedGridBytes: the grid is at least as large).
    const std::size_t sliceBytes =
        std::size_t(first.rows) * std::size_t(first.columns) * std::size_t(first.bitsAllocated / 8);
    const IsolatedOutcome decoded = runIsolated(
        sliceBytes * slices.size(),
        [&](std::span<std::byte> shared, std::string& message) {
            try {
                for (std::size_t k = 0; k < slices.size(); ++k)
                    decodeSlicePixels(slices[k], shared.subspan(k * sliceBytes, sliceBytes));
            } catch (const Error& e) {
                message = e.what();
                return false;
            }
            return true;
        },
        [&](std::span<const std::byte> shared) {
            for (std::size_t k = 0; k < slices.size(); ++k)
                storeSlice(slices[k], shared.subspan(k * sliceBytes, sliceBytes), *grid, int(k));
        });
    if (!decoded.ok) {
        // The child's own message names the slice; a child that died says only its signal.
        if (decoded.message.rfind("stopped by signal", 0) != 0) throw Error(decoded.message);
        throw Error("GDCM stopped while decoding the series' pixel data: " + decoded.message,
                    first.path);
    }

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
