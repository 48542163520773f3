#pragma once
// Reads the image files textures name (SGI .rgb, PNG, JPEG, GIF, TIFF, ... as Coin reads them:
// through Debian's libsimage, the image loader Coin itself uses).

#include <string>

#include <volsg/fields/Values.h>

namespace volsg {

/// The file's texels, rows bottom up (as Inventor's SoSFImage holds them). Throws Error naming
/// the file when it is not a regular file, is larger than the image limits or cannot be read.
ImageValue readTextureFile(const std::string& path);

} // namespace volsg
