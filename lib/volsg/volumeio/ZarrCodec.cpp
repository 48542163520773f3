#include <volsg/volumeio/ZarrCodec.h>

#include <climits>
#include <cstring>

#include <blosc.h>
#include <zlib.h>
#include <zstd.h>
#include <zstd_errors.h>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

[[noreturn]] void failChunk(const std::string& chunkPath, const std::string& message) {
    throw Error(message, chunkPath);
}

std::string sizeMismatch(const char* codec, std::size_t got, std::size_t expected) {
    return std::string(codec) + " chunk decompresses to " + std::to_string(got) +
           " bytes, expected " + std::to_string(expected) + " (the .zarray's chunks x dtype size)";
}

// zlib and gzip streams: inflate into `out`, then one probe byte proves nothing follows.
void inflateChunk(const ZarrCodec& codec, std::span<const std::byte> stored,
                  std::span<std::byte> out, const std::string& chunkPath) {
    if (stored.size() > UINT_MAX || out.size() >= UINT_MAX)
        failChunk(chunkPath, std::string(codec.id()) + " chunk too large for zlib");
    z_stream stream{};
    // 15: a zlib header; 15 + 16: a gzip header (numcodecs' GZip).
    if (inflateInit2(&stream, codec.kind == ZarrCodec::Kind::Gzip ? 15 + 16 : 15) != Z_OK)
        failChunk(chunkPath, "cannot initialise zlib");
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(stored.data()));
    stream.avail_in = uInt(stored.size());
    stream.next_out = reinterpret_cast<Bytef*>(out.data());
    stream.avail_out = uInt(out.size());
    int rc = inflate(&stream, Z_FINISH);
    std::size_t produced = out.size() - stream.avail_out;
    unsigned char probe = 0;
    if (rc == Z_BUF_ERROR && stream.avail_out == 0) {
        // `out` is full but the stream goes on: it is larger than the chunk.
        stream.next_out = &probe;
        stream.avail_out = 1;
        rc = inflate(&stream, Z_FINISH);
        produced += 1 - stream.avail_out;
    }
    const std::string message = stream.msg ? stream.msg : "error " + std::to_string(rc);
    inflateEnd(&stream);
    if (produced > out.size())
        failChunk(chunkPath, std::string(codec.id()) + " chunk decompresses to more than the " +
                                 std::to_string(out.size()) + " bytes a chunk has");
    if (rc == Z_STREAM_END) {
        if (produced != out.size())
            failChunk(chunkPath, sizeMismatch(codec.id(), produced, out.size()));
        return;
    }
    if (rc == Z_BUF_ERROR)
        failChunk(chunkPath, "truncated " + std::string(codec.id()) + " chunk: it ends after " +
                                 std::to_string(produced) + " of " + std::to_string(out.size()) +
                                 " bytes");
    failChunk(chunkPath, "corrupt " + std::string(codec.id()) + " chunk (zlib: " + message + ")");
}

void zstdChunk(std::span<const std::byte> stored, std::span<std::byte> out,
               const std::string& chunkPath) {
    const unsigned long long declared = ZSTD_getFrameContentSize(stored.data(), stored.size());
    if (declared == ZSTD_CONTENTSIZE_ERROR)
        failChunk(chunkPath, "corrupt zstd chunk (not a zstd frame)");
    if (declared != ZSTD_CONTENTSIZE_UNKNOWN && declared != out.size())
        failChunk(chunkPath, sizeMismatch("zstd", std::size_t(declared), out.size()));
    const std::size_t got = ZSTD_decompress(out.data(), out.size(), stored.data(), stored.size());
    if (ZSTD_isError(got)) {
        const ZSTD_ErrorCode code = ZSTD_getErrorCode(got);
        if (code == ZSTD_error_srcSize_wrong)
            failChunk(chunkPath,
                      "truncated zstd chunk (" + std::to_string(stored.size()) + " bytes stored)");
        if (code == ZSTD_error_dstSize_tooSmall)
            failChunk(chunkPath, "zstd chunk decompresses to more than the " +
                                     std::to_string(out.size()) + " bytes a chunk has");
        failChunk(chunkPath,
                  std::string("corrupt zstd chunk (zstd: ") + ZSTD_getErrorName(got) + ")");
    }
    if (got != out.size()) failChunk(chunkPath, sizeMismatch("zstd", got, out.size()));
}

void bloscChunk(std::span<const std::byte> stored, std::span<std::byte> out,
                const std::string& chunkPath) {
    if (stored.size() < BLOSC_MIN_HEADER_LENGTH)
        failChunk(chunkPath, "truncated blosc chunk: " + std::to_string(stored.size()) +
                                 " bytes, less than its 16-byte header");
    std::size_t declared = 0, storedSize = 0, block = 0;
    blosc_cbuffer_sizes(stored.data(), &declared, &storedSize, &block);
    if (storedSize != stored.size())
        failChunk(chunkPath, "blosc chunk header says " + std::to_string(storedSize) +
                                 " stored bytes, the file has " + std::to_string(stored.size()) +
                                 (storedSize > stored.size() ? " (truncated)" : ""));
    if (blosc_cbuffer_validate(stored.data(), stored.size(), &declared) != 0)
        failChunk(chunkPath, "corrupt blosc chunk header");
    if (declared != out.size()) failChunk(chunkPath, sizeMismatch("blosc", declared, out.size()));
    const int got = blosc_decompress_ctx(stored.data(), out.data(), out.size(), 1);
    if (got < 0)
        failChunk(chunkPath, "corrupt blosc chunk (blosc error " + std::to_string(got) + ")");
    if (std::size_t(got) != out.size())
        failChunk(chunkPath, sizeMismatch("blosc", std::size_t(got), out.size()));
}

} // namespace

ZarrCodec ZarrCodec::named(const std::string& name) {
    ZarrCodec codec;
    if (name == "none" || name == "null") return codec;
    if (name == "zlib" || name == "gzip") {
        codec.kind = name == "zlib" ? Kind::Zlib : Kind::Gzip;
        codec.level = 5;
    } else if (name == "zstd") {
        codec.kind = Kind::Zstd;
        codec.level = 3;
    } else if (name == "blosc") {
        codec.kind = Kind::Blosc;
        codec.level = 5;
    } else {
        throw Error("unknown compressor '" + name + "' (none, zlib, gzip, zstd or blosc)");
    }
    return codec;
}

const char* ZarrCodec::id() const {
    switch (kind) {
    case Kind::None:
        return "null";
    case Kind::Zlib:
        return "zlib";
    case Kind::Gzip:
        return "gzip";
    case Kind::Zstd:
        return "zstd";
    case Kind::Blosc:
        return "blosc";
    }
    return "null";
}

std::size_t maxStoredChunkBytes(std::size_t rawBytes) {
    // Every codec's worst case is the raw bytes plus a little framing (deflate: 5 bytes per
    // 16 KiB block; zstd and blosc less).
    return rawBytes + rawBytes / 64 + 4096;
}

void decodeZarrChunk(const ZarrCodec& codec, std::span<const std::byte> stored,
                     std::span<std::byte> out, const std::string& chunkPath) {
    switch (codec.kind) {
    case ZarrCodec::Kind::None:
        if (stored.size() != out.size())
            failChunk(chunkPath, "uncompressed chunk has " + std::to_string(stored.size()) +
                                     " bytes, expected " + std::to_string(out.size()) +
                                     " (the .zarray's chunks x dtype size)");
        std::memcpy(out.data(), stored.data(), out.size());
        return;
    case ZarrCodec::Kind::Zlib:
    case ZarrCodec::Kind::Gzip:
        inflateChunk(codec, stored, out, chunkPath);
        return;
    case ZarrCodec::Kind::Zstd:
        zstdChunk(stored, out, chunkPath);
        return;
    case ZarrCodec::Kind::Blosc:
        bloscChunk(stored, out, chunkPath);
        return;
    }
}

std::vector<std::byte> encodeZarrChunk(const ZarrCodec& codec, std::span<const std::byte> raw,
                                       std::size_t elementSize) {
    std::vector<std::byte> out;
    switch (codec.kind) {
    case ZarrCodec::Kind::None:
        out.assign(raw.begin(), raw.end());
        return out;
    case ZarrCodec::Kind::Zlib:
    case ZarrCodec::Kind::Gzip: {
        z_stream stream{};
        if (deflateInit2(&stream, codec.level, Z_DEFLATED,
                         codec.kind == ZarrCodec::Kind::Gzip ? 15 + 16 : 15, 8,
                         Z_DEFAULT_STRATEGY) != Z_OK)
            throw Error("cannot initialise zlib");
        out.resize(deflateBound(&stream, uLong(raw.size())) + 32);
        stream.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(raw.data()));
        stream.avail_in = uInt(raw.size());
        stream.next_out = reinterpret_cast<Bytef*>(out.data());
        stream.avail_out = uInt(out.size());
        const int rc = deflate(&stream, Z_FINISH);
        out.resize(out.size() - stream.avail_out);
        deflateEnd(&stream);
        if (rc != Z_STREAM_END) throw Error("zlib compression failed");
        return out;
    }
    case ZarrCodec::Kind::Zstd: {
        out.resize(ZSTD_compressBound(raw.size()));
        const std::size_t n =
            ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), codec.level);
        if (ZSTD_isError(n)) throw Error(std::string("zstd: ") + ZSTD_getErrorName(n));
        out.resize(n);
        return out;
    }
    case ZarrCodec::Kind::Blosc: {
        out.resize(raw.size() + BLOSC_MAX_OVERHEAD);
        const int n = blosc_compress_ctx(
            codec.level, codec.bloscShuffle < 0 ? 1 : codec.bloscShuffle, elementSize, raw.size(),
            raw.data(), out.data(), out.size(), codec.bloscInner.c_str(), 0, 1);
        if (n <= 0) throw Error("blosc compression failed (" + std::to_string(n) + ")");
        out.resize(std::size_t(n));
        return out;
    }
    }
    return out;
}

} // namespace volsg
