#include <volsg/volumeio/VoxelPayload.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <zlib.h>

#include <volsg/core/Error.h>
#include <volsg/volumeio/InputFile.h>

namespace volsg {

namespace {

// Where uncompressed data starts, or an Error when the file cannot hold exactly `expected` bytes.
std::uint64_t uncompressedOffset(const InputFile& file, const VoxelPayload& payload,
                                 std::uint64_t expected) {
    const std::uint64_t offset = payload.offset;
    if (payload.atEnd) {
        const std::uint64_t available = file.size() < offset ? 0 : file.size() - offset;
        if (available < expected)
            file.fail("expected " + std::to_string(expected) +
                      " bytes of data at the end of the file, file has " +
                      std::to_string(available));
        return file.size() - expected;
    }
    if (offset > file.size())
        file.fail("data offset " + std::to_string(offset) +
                  " is past the end of the file, file has " + std::to_string(file.size()) +
                  " bytes");
    const std::uint64_t available = file.size() - offset;
    if (available != expected)
        file.fail("expected " + std::to_string(expected) + " bytes of data, file has " +
                  std::to_string(available) +
                  (offset > 0 ? " after offset " + std::to_string(offset) : std::string()));
    return offset;
}

// The compressed stream's length, or an Error when it cannot possibly inflate to `expected`
// bytes: deflate expands at most 1032:1, so a short file is refused before allocating.
std::uint64_t compressedLength(const InputFile& file, const VoxelPayload& payload,
                               std::uint64_t expected) {
    if (payload.offset > file.size())
        file.fail("compressed data offset " + std::to_string(payload.offset) +
                  " is past the end of the file (" + std::to_string(file.size()) + " bytes)");
    const std::uint64_t left = file.size() - payload.offset;
    if (payload.compressedSize > left)
        file.fail("compressed data size " + std::to_string(payload.compressedSize) +
                  " exceeds the " + std::to_string(left) + " bytes left in the file");
    const std::uint64_t length = payload.compressedSize ? payload.compressedSize : left;
    constexpr std::uint64_t maxRatio = 1032, slack = 1024;
    if (length < (expected + slack) / maxRatio)
        file.fail("truncated " + payload.compression + " stream: " + std::to_string(length) +
                  " compressed bytes cannot hold the expected " + std::to_string(expected) +
                  " decompressed bytes");
    return length;
}

// Inflates from the file's current position into `out`, after dropping `skip` bytes.
class StreamInflater {
public:
    StreamInflater(InputFile& file, std::uint64_t inputSize, std::string name)
        : file_(file), inputLeft_(inputSize), name_(std::move(name)),
          input_(std::size_t(256) << 10) {
        // 15 + 32: a zlib or a gzip header, whichever the stream has.
        if (inflateInit2(&stream_, 15 + 32) != Z_OK) file_.fail("cannot initialise zlib");
    }
    ~StreamInflater() { inflateEnd(&stream_); }
    StreamInflater(const StreamInflater&) = delete;
    StreamInflater& operator=(const StreamInflater&) = delete;

    void run(std::uint64_t skip, std::span<std::byte> out) {
        const std::uint64_t expected = skip + out.size();
        std::vector<unsigned char> scratch(std::size_t(64) << 10);
        std::uint64_t produced = 0;
        for (;;) {
            if (stream_.avail_in < 2) refill();
            // Output goes to the scratch buffer while skipping, then straight into the grid, then
            // one probe byte: producing it proves the stream is longer than it should be.
            unsigned char* target;
            std::size_t room;
            if (produced < skip) {
                target = scratch.data();
                room = std::size_t(std::min<std::uint64_t>(scratch.size(), skip - produced));
            } else if (produced < expected) {
                target = reinterpret_cast<unsigned char*>(out.data()) + (produced - skip);
                room = std::size_t(std::min<std::uint64_t>(UINT_MAX, expected - produced));
            } else {
                target = scratch.data();
                room = 1;
            }
            stream_.next_out = target;
            stream_.avail_out = uInt(room);
            const int rc = inflate(&stream_, Z_NO_FLUSH);
            produced += room - stream_.avail_out;
            if (produced > expected)
                file_.fail("decompressed " + name_ + " data is larger than the expected " +
                           std::to_string(expected) + " bytes");
            if (rc == Z_STREAM_END) {
                if (!nextGzipMember()) break;
                continue;
            }
            if (rc == Z_NEED_DICT || rc == Z_DATA_ERROR || rc == Z_STREAM_ERROR ||
                rc == Z_MEM_ERROR)
                file_.fail("corrupt " + name_ + " stream (zlib: " +
                           (stream_.msg ? stream_.msg : "error " + std::to_string(rc)) + ")");
            // Out of input with room left for output: the stream was cut off.
            if (stream_.avail_in == 0 && inputLeft_ == 0 &&
                (stream_.avail_out > 0 || rc == Z_BUF_ERROR))
                file_.fail("truncated " + name_ + " stream: " +
                           (produced == expected
                                ? std::string("it ends before its end marker and checksum")
                                : "it ends after " + std::to_string(produced) +
                                      " of the expected " + std::to_string(expected) +
                                      " decompressed bytes"));
        }
        if (produced != expected)
            file_.fail("decompressed " + name_ + " data has " + std::to_string(produced) +
                       " bytes, expected " + std::to_string(expected));
    }

private:
    // Tops up the input buffer, keeping unread bytes (so two bytes can be looked at together).
    void refill() {
        if (inputLeft_ == 0) return;
        if (stream_.avail_in > 0 && stream_.next_in != input_.data())
            std::memmove(input_.data(), stream_.next_in, stream_.avail_in);
        const std::size_t want =
            std::size_t(std::min<std::uint64_t>(input_.size() - stream_.avail_in, inputLeft_));
        const std::size_t got = file_.read(input_.data() + stream_.avail_in, want);
        if (got == 0)
            inputLeft_ = 0; // the file is shorter than promised: a truncated stream
        else
            inputLeft_ -= got;
        stream_.next_in = input_.data();
        stream_.avail_in += uInt(got);
    }

    // After a member's end: true when another gzip member follows (then inflate is reset for
    // it). Other trailing bytes are ignored, as gzip does.
    bool nextGzipMember() {
        refill();
        if (stream_.avail_in < 2 || stream_.next_in[0] != 0x1f || stream_.next_in[1] != 0x8b)
            return false;
        if (inflateReset(&stream_) != Z_OK) file_.fail("cannot reset zlib");
        return true;
    }

    InputFile& file_;
    std::uint64_t inputLeft_;
    std::string name_;
    std::vector<unsigned char> input_;
    z_stream stream_{};
};

} // namespace

std::uint64_t checkedGridBytes(const std::string& headerPath, int headerLine, glm::ivec3 dimensions,
                               VoxelType type, glm::dvec3 spacing, std::uint64_t byteLimit) {
    std::uint64_t bytes = 0;
    try {
        bytes = VolumeGrid::checkedByteSize(dimensions, type, byteLimit);
    } catch (const Error& e) {
        throw Error(e.message(), headerPath, headerLine);
    }
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(spacing[a]) || !(spacing[a] > 0.0))
            throw Error("volume spacing must be finite and > 0, got " + std::to_string(spacing.x) +
                            " " + std::to_string(spacing.y) + " " + std::to_string(spacing.z),
                        headerPath, headerLine);
    return bytes;
}

ref_ptr<VolumeGrid> readVoxelGrid(const std::string& headerPath, int headerLine,
                                  glm::ivec3 dimensions, VoxelType type, glm::dvec3 spacing,
                                  std::uint64_t byteLimit, InputFile& data,
                                  const VoxelPayload& payload) {
    const std::uint64_t bytes =
        checkedGridBytes(headerPath, headerLine, dimensions, type, spacing, byteLimit);
    const bool compressed = !payload.compression.empty();
    if (compressed && payload.decompressedSkip > std::numeric_limits<std::uint64_t>::max() / 2)
        data.fail("byte skip of " + std::to_string(payload.decompressedSkip) +
                  " decompressed bytes is absurd");
    const std::uint64_t offset =
        compressed ? payload.offset : uncompressedOffset(data, payload, bytes);
    const std::uint64_t length =
        compressed ? compressedLength(data, payload, payload.decompressedSkip + bytes) : bytes;

    ref_ptr<VolumeGrid> grid;
    try {
        grid = VolumeGrid::create(dimensions, type, spacing, byteLimit);
    } catch (const Error& e) {
        throw Error(e.message(), headerPath, headerLine);
    }
    const std::span<std::byte> out = grid->bytes();
    data.seek(offset);
    if (compressed) {
        StreamInflater inflater(data, length, payload.compression);
        inflater.run(payload.decompressedSkip, out);
    } else if (data.read(out.data(), out.size()) != out.size()) {
        data.fail("file ended while reading " + std::to_string(bytes) + " bytes of data");
    }
    const std::size_t size = voxelTypeSize(type);
    if (size > 1 && payload.bigEndian != (std::endian::native == std::endian::big))
        swapElementBytes(out.data(), out.size(), size);
    return grid;
}

void swapElementBytes(std::byte* bytes, std::size_t byteCount, std::size_t elementSize) {
    // Plain loops over whole elements: the compiler turns these into vector shuffles.
    if (elementSize == 2) {
        for (std::size_t i = 0; i + 1 < byteCount; i += 2)
            std::swap(bytes[i], bytes[i + 1]);
    } else if (elementSize == 4) {
        for (std::size_t i = 0; i + 3 < byteCount; i += 4) {
            std::swap(bytes[i], bytes[i + 3]);
            std::swap(bytes[i + 1], bytes[i + 2]);
        }
    } else {
        for (std::size_t i = 0; i + elementSize <= byteCount; i += elementSize)
            std::reverse(bytes + i, bytes + i + elementSize);
    }
}

} // namespace volsg
