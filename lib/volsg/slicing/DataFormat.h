#pragma once
// How a volume's data type goes into a GL texture, shared by the Volume slicer and the
// planar sections (lib/volsg/sections) so both reconstruct the same data values.

#include <cstddef>

#include <volsg/gl/GlLoader.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

/// data = scale * texel + offset.
struct DataFormat {
    GLenum internalFormat = GL_R16;
    GLenum type = GL_UNSIGNED_BYTE;
    std::size_t texelBytes = 2;
    float scale = 255.0f;
    float offset = 0.0f;
};

/// 8-bit data goes into R16 (the driver widens x to x * 257, exactly x / 255). Measured on
/// llvmpipe, sampling between two voxels 100 and 101 at 256 positions: R8 returned values off
/// by up to 0.498 data units (its filter rounds to 1/255 steps), R16 by 9e-6. R16 costs twice
/// the memory and is what we use. Short data is shifted by 32768 into R16, which
/// keeps all 65536 values (R16_SNORM merges -32768 with -32767, R16F keeps 11 bits).
inline DataFormat dataFormatOf(VoxelType type) {
    switch (type) {
    case VoxelType::UByte:
        return {GL_R16, GL_UNSIGNED_BYTE, 2, 255.0f, 0.0f};
    case VoxelType::UShort:
        return {GL_R16, GL_UNSIGNED_SHORT, 2, 65535.0f, 0.0f};
    case VoxelType::Short:
        return {GL_R16, GL_UNSIGNED_SHORT, 2, 65535.0f, -32768.0f};
    case VoxelType::Float:
        return {GL_R32F, GL_FLOAT, 4, 1.0f, 0.0f};
    }
    return {};
}

} // namespace volsg
