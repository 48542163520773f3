// NIfTI-1 and NIfTI-2 (.nii, .nii.gz, .hdr + .img): a fixed binary header (348 or 540 bytes),
// then the voxels. Parsed by hand rather than through Debian's niftilib: the header is a plain
// struct, and reading it here keeps the library's rules for untrusted input (sizes checked
// against the byte limit before allocating, bounded inflate, one-line errors naming the file)
// where niftilib allocates what the header says and prints its complaints to stderr.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include <zlib.h>

#include <volsg/core/Error.h>
#include <volsg/volumeio/HeaderLineReader.h>
#include <volsg/volumeio/InputFile.h>
#include <volsg/volumeio/VolumeReader.h>
#include <volsg/volumeio/VoxelPayload.h>

namespace volsg {

namespace {

constexpr std::size_t nifti1HeaderSize = 348, nifti2HeaderSize = 540;

// The first `want` bytes of the file, inflated when it is gzip: fewer when the file (or the
// stream) is shorter. Reads at most a bounded prefix of the compressed stream.
std::vector<unsigned char> headerBytes(InputFile& file, bool gzip, std::size_t want) {
    std::vector<unsigned char> out(want);
    file.seek(0);
    if (!gzip) {
        out.resize(file.read(out.data(), want));
        return out;
    }
    z_stream z{};
    if (inflateInit2(&z, 15 + 16) != Z_OK) file.fail("cannot initialise zlib");
    std::vector<unsigned char> input(16384);
    z.next_out = out.data();
    z.avail_out = uInt(want);
    int rc = Z_OK;
    while (z.avail_out > 0 && rc == Z_OK) {
        if (z.avail_in == 0) {
            const std::size_t got = file.read(input.data(), input.size());
            if (got == 0) break;
            z.next_in = input.data();
            z.avail_in = uInt(got);
        }
        rc = inflate(&z, Z_NO_FLUSH);
    }
    const std::size_t produced = want - z.avail_out;
    const std::string message = z.msg ? z.msg : "";
    inflateEnd(&z);
    if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR)
        file.fail("corrupt gzip stream in the NIfTI header (zlib: " + message + ")");
    out.resize(produced);
    return out;
}

// Little- or big-endian fields of the header, by byte offset.
struct HeaderView {
    const unsigned char* bytes;
    bool swap;
    template <class T> T get(std::size_t offset) const {
        unsigned char b[sizeof(T)];
        std::memcpy(b, bytes + offset, sizeof(T));
        if (swap) std::reverse(b, b + sizeof(T));
        T v;
        std::memcpy(&v, b, sizeof(T));
        return v;
    }
};

// What the reader takes from either header version.
struct NiftiHeader {
    int version = 1;
    bool swap = false;
    std::int64_t dim[8]{};
    int datatype = 0;
    double pixdim[8]{};
    std::int64_t voxOffset = 0;
    double sclSlope = 0, sclInter = 0;
    int qformCode = 0, sformCode = 0;
    double quatern[3]{}, qoffset[3]{};
    double srow[3][4]{};
    int xyztUnits = 0;
    bool singleFile = true; // "n+1"/"n+2"; "ni1"/"ni2" keep the voxels in a .img beside
};

NiftiHeader parseHeader(const std::vector<unsigned char>& bytes, const InputFile& file) {
    if (bytes.size() < 4) file.fail("not a NIfTI file: shorter than its 348-byte header");
    std::int32_t size;
    std::memcpy(&size, bytes.data(), 4);
    std::int32_t swapped;
    unsigned char reversed[4] = {bytes[3], bytes[2], bytes[1], bytes[0]};
    std::memcpy(&swapped, reversed, 4);
    NiftiHeader h;
    if (size == 348 || swapped == 348)
        h.version = 1;
    else if (size == 540 || swapped == 540)
        h.version = 2;
    else
        file.fail("not a NIfTI file: the header size field is neither 348 (NIfTI-1) nor 540 "
                  "(NIfTI-2)");
    h.swap = size != (h.version == 1 ? 348 : 540);
    const std::size_t need = h.version == 1 ? nifti1HeaderSize : nifti2HeaderSize;
    if (bytes.size() < need)
        file.fail("truncated NIfTI-" + std::to_string(h.version) + " header: " +
                  std::to_string(bytes.size()) + " of " + std::to_string(need) + " bytes");
    const HeaderView v{bytes.data(), h.swap};
    const char* magic = reinterpret_cast<const char*>(bytes.data() + (h.version == 1 ? 344 : 4));
    const char* single = h.version == 1 ? "n+1" : "n+2";
    const char* pair = h.version == 1 ? "ni1" : "ni2";
    if (std::memcmp(magic, single, 4) != 0 && std::memcmp(magic, pair, 4) != 0)
        file.fail(std::string("not a NIfTI file: the magic is not '") + single + "' or '" + pair +
                  "' (an ANALYZE 7.5 header is not supported)");
    h.singleFile = std::memcmp(magic, single, 4) == 0;
    if (h.version == 1) {
        for (int i = 0; i < 8; ++i) {
            h.dim[i] = v.get<std::int16_t>(40 + 2 * i);
            h.pixdim[i] = v.get<float>(76 + 4 * i);
        }
        h.datatype = v.get<std::int16_t>(70);
        const double offset = v.get<float>(108);
        if (!std::isfinite(offset) || offset < 0 || offset > 1e15 || offset != std::floor(offset))
            file.fail("NIfTI vox_offset must be a whole number of bytes >= 0");
        h.voxOffset = std::int64_t(offset);
        h.sclSlope = v.get<float>(112);
        h.sclInter = v.get<float>(116);
        h.xyztUnits = bytes[123];
        h.qformCode = v.get<std::int16_t>(252);
        h.sformCode = v.get<std::int16_t>(254);
        for (int i = 0; i < 3; ++i) {
            h.quatern[i] = v.get<float>(256 + 4 * i);
            h.qoffset[i] = v.get<float>(268 + 4 * i);
            for (int j = 0; j < 4; ++j)
                h.srow[i][j] = v.get<float>(280 + 16 * i + 4 * j);
        }
    } else {
        h.datatype = v.get<std::int16_t>(12);
        for (int i = 0; i < 8; ++i) {
            h.dim[i] = v.get<std::int64_t>(16 + 8 * i);
            h.pixdim[i] = v.get<double>(104 + 8 * i);
        }
        h.voxOffset = v.get<std::int64_t>(168);
        h.sclSlope = v.get<double>(176);
        h.sclInter = v.get<double>(184);
        h.qformCode = v.get<std::int32_t>(344);
        h.sformCode = v.get<std::int32_t>(348);
        for (int i = 0; i < 3; ++i) {
            h.quatern[i] = v.get<double>(352 + 8 * i);
            h.qoffset[i] = v.get<double>(376 + 8 * i);
            for (int j = 0; j < 4; ++j)
                h.srow[i][j] = v.get<double>(400 + 32 * i + 8 * j);
        }
        h.xyztUnits = v.get<std::int32_t>(500);
    }
    return h;
}

VoxelType voxelTypeOf(int datatype, const InputFile& file) {
    switch (datatype) {
    case 2:
        return VoxelType::UByte; // DT_UINT8
    case 4:
        return VoxelType::Short; // DT_INT16
    case 512:
        return VoxelType::UShort; // DT_UINT16
    case 16:
        return VoxelType::Float; // DT_FLOAT32
    default:
        file.fail("unsupported NIfTI datatype " + std::to_string(datatype) +
                  " (supported: 2 uint8, 4 int16, 512 uint16, 16 float32)");
    }
}

glm::ivec3 dimensionsOf(const NiftiHeader& h, const InputFile& file) {
    const std::int64_t rank = h.dim[0];
    if (rank < 3 || rank > 7)
        file.fail("NIfTI dim[0] is " + std::to_string(rank) + ": a volume has 3 dimensions");
    for (std::int64_t i = 4; i <= rank; ++i)
        if (h.dim[i] != 1)
            file.fail("NIfTI dimension " + std::to_string(i) + " is " + std::to_string(h.dim[i]) +
                      ": only single 3D volumes are supported (not time series or vectors)");
    glm::ivec3 d;
    for (int a = 0; a < 3; ++a) {
        if (h.dim[a + 1] < 1 || h.dim[a + 1] > limits::maxVolumeDimension)
            file.fail("NIfTI dim[" + std::to_string(a + 1) + "] is " +
                      std::to_string(h.dim[a + 1]) + ", expected 1.." +
                      std::to_string(limits::maxVolumeDimension));
        d[a] = int(h.dim[a + 1]);
    }
    return d;
}

// Millimetres per unit of xyzt_units' spatial code (unknown is taken as millimetres).
double millimetresPerUnit(int units) {
    switch (units & 7) {
    case 1:
        return 1000.0; // metre
    case 3:
        return 0.001; // micron
    default:
        return 1.0;
    }
}

// The geometry from sform (preferred: it is the scanner or template space the file declares)
// or qform; RAS is turned into LPS. Spacing comes from the same transform.
void placeGrid(const NiftiHeader& h, double unit, glm::dvec3& spacing, VolumeGeometry& g,
               const InputFile& file) {
    glm::dmat3 affine(1.0); // columns: world step per index step, RAS
    glm::dvec3 origin(0.0);
    if (h.sformCode > 0) {
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c)
                affine[c][r] = h.srow[r][c];
            origin[r] = h.srow[r][3];
        }
    } else if (h.qformCode > 0) {
        const double b = h.quatern[0], c = h.quatern[1], d = h.quatern[2];
        const double a = std::sqrt(std::max(0.0, 1.0 - (b * b + c * c + d * d)));
        const glm::dmat3 rotation(a * a + b * b - c * c - d * d, 2 * (b * c + a * d),
                                  2 * (b * d - a * c), // column 0
                                  2 * (b * c - a * d), a * a + c * c - b * b - d * d,
                                  2 * (c * d + a * b), // column 1
                                  2 * (b * d + a * c), 2 * (c * d - a * b),
                                  a * a + d * d - c * c - b * b); // column 2
        const double qfac = h.pixdim[0] < 0 ? -1.0 : 1.0;
        for (int c2 = 0; c2 < 3; ++c2)
            affine[c2] = rotation[c2] * std::abs(h.pixdim[c2 + 1]) * (c2 == 2 ? qfac : 1.0);
        origin = glm::dvec3(h.qoffset[0], h.qoffset[1], h.qoffset[2]);
    } else {
        for (int a = 0; a < 3; ++a)
            spacing[a] = std::abs(h.pixdim[a + 1]) * unit;
        return; // ANALYZE-style: spacing only, no placement
    }
    const glm::dmat3 rasToLps(-1, 0, 0, 0, -1, 0, 0, 0, 1);
    for (int a = 0; a < 3; ++a) {
        const double length = glm::length(affine[a]);
        if (!std::isfinite(length) || !(length > 0.0))
            file.fail(std::string(h.sformCode > 0 ? "sform" : "qform") + " axis " +
                      std::to_string(a) + " has zero or non-finite length");
        spacing[a] = length * unit;
        g.directions[a] = rasToLps * (affine[a] / length);
    }
    g.origin = rasToLps * origin * unit;
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(g.origin[a])) file.fail("NIfTI origin is not finite");
    g.known = true;
}

// stored * slope + inter, when the header asks for it: the grid becomes Float.
ref_ptr<VolumeGrid> applyScaling(ref_ptr<VolumeGrid> stored, const NiftiHeader& h,
                                 std::uint64_t byteLimit, const InputFile& file) {
    const double slope = h.sclSlope, inter = h.sclInter;
    if (slope == 0.0 || !std::isfinite(slope) || (slope == 1.0 && inter == 0.0)) return stored;
    if (!std::isfinite(inter)) file.fail("NIfTI scl_inter is not finite");
    ref_ptr<VolumeGrid> out;
    try {
        out = VolumeGrid::create(stored->dimensions(), VoxelType::Float, stored->spacing(),
                                 byteLimit);
    } catch (const Error& e) {
        file.fail(e.message() + " (scaled by scl_slope to float)");
    }
    std::span<float> dst = out->data<float>();
    for (std::size_t i = 0; i < dst.size(); ++i)
        dst[i] = float(stored->value(i) * slope + inter);
    out->setGeometry(stored->geometry());
    return out;
}

// The .img of a .hdr/.img pair ("ni1"): same stem, .img or .img.gz; its name, beside the header.
std::string pairedImageName(const std::string& path, const InputFile& file) {
    std::filesystem::path p(path);
    const bool gz = HeaderLineReader::lowercase(p.extension().string()) == ".gz";
    if (gz) p.replace_extension(); // name.hdr.gz -> name.hdr
    for (const char* candidate : {".img", ".img.gz"}) {
        std::filesystem::path img = p;
        img.replace_extension(candidate);
        if (std::filesystem::exists(img)) return img.filename().string();
    }
    file.fail("NIfTI header says its voxels are in a separate .img file, and none is beside it");
}

} // namespace

ref_ptr<VolumeGrid> readNifti(const std::string& path, std::uint64_t byteLimit) {
    InputFile file(path);
    unsigned char magic[2] = {0, 0};
    const bool gzip = file.read(magic, 2) == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
    const NiftiHeader h = parseHeader(headerBytes(file, gzip, nifti2HeaderSize), file);
    const VoxelType type = voxelTypeOf(h.datatype, file);
    const glm::ivec3 dims = dimensionsOf(h, file);
    glm::dvec3 spacing(1.0);
    VolumeGeometry geometry;
    placeGrid(h, millimetresPerUnit(h.xyztUnits), spacing, geometry, file);
    const std::size_t headerSize = h.version == 1 ? nifti1HeaderSize : nifti2HeaderSize;
    if (h.singleFile && h.voxOffset < std::int64_t(headerSize))
        file.fail("NIfTI vox_offset " + std::to_string(h.voxOffset) +
                  " lies inside the header (at least " + std::to_string(headerSize) + ")");
    if (h.voxOffset < 0) file.fail("NIfTI vox_offset is negative");

    std::unique_ptr<InputFile> detached;
    if (!h.singleFile) detached = InputFile::openDataFile(path, pairedImageName(path, file));
    InputFile& data = detached ? *detached : file;
    data.seek(0);
    unsigned char dataMagic[2] = {0, 0};
    const bool dataGzip =
        detached ? data.read(dataMagic, 2) == 2 && dataMagic[0] == 0x1f && dataMagic[1] == 0x8b
                 : gzip;
    VoxelPayload payload;
    payload.bigEndian = (std::endian::native == std::endian::big) != h.swap;
    if (dataGzip) {
        payload.compression = "gzip";
        payload.decompressedSkip = std::uint64_t(h.voxOffset);
    } else {
        payload.offset = std::uint64_t(h.voxOffset); // the voxels run to the file's end
    }
    ref_ptr<VolumeGrid> grid =
        readVoxelGrid(path, 0, dims, type, spacing, byteLimit, data, payload);
    grid->setGeometry(geometry);
    return applyScaling(grid, h, byteLimit, file);
}

} // namespace volsg
