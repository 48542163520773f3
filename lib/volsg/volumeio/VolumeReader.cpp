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
    const std::string extension =
        HeaderLineReader::lowercase(std::filesystem::path(path).extension().string());
    if (extension == ".nrrd" || extension == ".nhdr") return readNrrd(path, byteLimit);
    if (extension == ".mhd" || extension == ".mha") return readMetaImage(path, byteLimit);
    if (!rawLayout)
        throw Error("raw volume needs dimensions and dataType (the file is not .nrrd, .nhdr, "
                    ".mhd or .mha)",
                    path);
    return readRawVolume(path, *rawLayout, byteLimit);
}

} // namespace volsg
