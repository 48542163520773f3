#pragma once
// The compressors of Zarr v2 chunks (numcodecs ids "zlib", "gzip", "zstd", "blosc"), through
// Debian's zlib, libzstd and libblosc.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace volsg {

/// One chunk compressor as a .zarray's `compressor` names it; None is JSON null.
struct ZarrCodec {
    enum class Kind { None, Zlib, Gzip, Zstd, Blosc };
    Kind kind = Kind::None;
    int level = 0;                  ///< zlib/gzip 0..9, zstd level, blosc clevel 0..9
    std::string bloscInner = "lz4"; ///< blosc only: lz4, lz4hc, zstd, zlib, blosclz
    int bloscShuffle = 1;           ///< blosc only: 0 none, 1 byte, 2 bit (-1, auto, on writing: 1)

    /// The writer's defaults: zstd level 3, zlib and gzip level 5, blosc lz4 level 5 with byte
    /// shuffle (numcodecs' own defaults where it has them).
    static ZarrCodec named(const std::string& name); ///< none|zlib|gzip|zstd|blosc, else Error
    const char* id() const;                          ///< "zlib", ...; "null" for None
};

/// Decompresses one stored chunk into exactly `out`; an Error naming `chunkPath` when the
/// chunk is corrupt or cut off, or decompresses to any other size than out.size() (the codecs
/// write into `out` only and stop at its end: a decompression bomb costs nothing).
void decodeZarrChunk(const ZarrCodec& codec, std::span<const std::byte> stored,
                     std::span<std::byte> out, const std::string& chunkPath);

/// Compresses one chunk of `elementSize`-byte elements (blosc shuffles by it).
std::vector<std::byte> encodeZarrChunk(const ZarrCodec& codec, std::span<const std::byte> raw,
                                       std::size_t elementSize);

/// The most bytes a stored chunk of `rawBytes` can take with any codec: a larger file cannot
/// be a chunk and is refused before it is read.
std::size_t maxStoredChunkBytes(std::size_t rawBytes);

} // namespace volsg
