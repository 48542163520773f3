#include <volsg/volumeio/VolumeReader.h>

#include <filesystem>

#include <volsg/core/Error.h>
#include <volsg/volumeio/HeaderLineReader.h>
#include <volsg/volumeio/InputFile.h>
#include <volsg/volumeio/VoxelPayload.h>

namespace volsg {

ref_ptr<VolumeGrid> readRawVolume(const std::string& path, const RawVolumeLayout& layout,
                                  std::uint64_t byteLimit) {
    InputFile file(path);
    checkedGridBytes(path, 0, layout.dimensions, layout.type, layout.spacing, byteLimit);

    unsigned char magic[2] = {0, 0};
    const bool gzip = file.read(magic, 2) == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
    VoxelPayload payload;
    payload.bigEndian = layout.bigEndian;
    if (gzip) {
        payload.compression = "gzip";
        payload.decompressedSkip = layout.headerSkip;
    } else {
        payload.offset = layout.headerSkip;
    }
    return readVoxelGrid(path, 0, layout.dimensions, layout.type, layout.spacing, byteLimit, file,
                         payload);
}

ref_ptr<VolumeGrid> readVolume(const std::string& path, const RawVolumeLayout* rawLayout,
                               std::uint64_t byteLimit) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        return isZarrFolder(path) ? readOmeZarr(path, 0, byteLimit)
                                  : readDicomSeries(path, byteLimit);
    const std::string name =
        HeaderLineReader::lowercase(std::filesystem::path(path).filename().string());
    const auto endsWith = [&](std::string_view tail) {
        return name.size() >= tail.size() &&
               name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
    };
    if (endsWith(".zarr")) return readOmeZarr(path, 0, byteLimit); // says it is no folder
    if (endsWith(".nrrd") || endsWith(".nhdr")) return readNrrd(path, byteLimit);
    if (endsWith(".mhd") || endsWith(".mha")) return readMetaImage(path, byteLimit);
    if (endsWith(".nii") || endsWith(".nii.gz") || endsWith(".hdr") || endsWith(".hdr.gz"))
        return readNifti(path, byteLimit);
    if (endsWith(".dcm") || isDicomFile(path)) return readDicomSeries(path, byteLimit);
    if (!rawLayout)
        throw Error("raw volume needs dimensions and dataType (the file is not .nrrd, .nhdr, "
                    ".mhd, .mha, .nii, .nii.gz or DICOM)",
                    path);
    return readRawVolume(path, *rawLayout, byteLimit);
}

} // namespace volsg
