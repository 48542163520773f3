#include <volsg/voxelfile/PositionCoding.h>

#include <volsg/core/Error.h>

namespace volsg {

namespace {

void putVarint(std::string& out, std::uint64_t v) {
    while (v >= 0x80) {
        out.push_back(char(std::uint8_t(v) | 0x80));
        v >>= 7;
    }
    out.push_back(char(v));
}

/// A bounds-checked varint cursor over the position code.
struct VarintReader {
    const std::uint8_t* data;
    std::size_t size, at = 0;
    const std::string& where;

    std::uint64_t next() {
        std::uint64_t v = 0;
        for (int shift = 0; shift < 35; shift += 7) { // positions need at most 17 bits
            if (at >= size) throw Error(where + ": position code ends inside a number");
            const std::uint8_t byte = data[at++];
            v |= std::uint64_t(byte & 0x7F) << shift;
            if (!(byte & 0x80)) return v;
        }
        throw Error(where + ": position code holds an over-long number");
    }
};

} // namespace

std::string encodePositions(const glm::ivec3& n, const std::vector<std::uint16_t>& i,
                            const std::vector<std::uint16_t>& j,
                            const std::vector<std::uint16_t>& k) {
    std::string out;
    std::size_t v = 0;
    const std::size_t count = i.size();
    std::vector<std::pair<int, int>> runs; // (start, length) of the current scanline
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y) {
            runs.clear();
            while (v < count && k[v] == z && j[v] == y) {
                if (i[v] >= n.x || (!runs.empty() && i[v] < runs.back().first + runs.back().second))
                    throw Error("voxel positions are not in increasing (k, j, i) order");
                if (!runs.empty() && i[v] == runs.back().first + runs.back().second)
                    ++runs.back().second;
                else
                    runs.emplace_back(int(i[v]), 1);
                ++v;
            }
            putVarint(out, runs.size());
            int end = 0;
            for (const auto& [start, length] : runs) {
                putVarint(out, std::uint64_t(start - end));
                putVarint(out, std::uint64_t(length - 1));
                end = start + length;
            }
        }
    if (v != count) throw Error("voxel positions are not in (k, j, i) order within the volume");
    return out;
}

void decodePositions(const std::uint8_t* code, std::size_t size, const glm::ivec3& n,
                     std::size_t count, std::vector<std::uint16_t>& i,
                     std::vector<std::uint16_t>& j, std::vector<std::uint16_t>& k,
                     const std::string& where) {
    // Each scanline takes at least one byte: refuse before looping over absurd dimensions.
    if (std::uint64_t(n.y) * std::uint64_t(n.z) > size)
        throw Error(where + ": position code shorter than the volume's " +
                    std::to_string(std::uint64_t(n.y) * std::uint64_t(n.z)) + " scanlines");
    i.resize(count);
    j.resize(count);
    k.resize(count);
    VarintReader in{code, size, 0, where};
    std::size_t v = 0;
    for (int z = 0; z < n.z; ++z)
        for (int y = 0; y < n.y; ++y) {
            const std::uint64_t runs = in.next();
            std::uint64_t x = 0;
            for (std::uint64_t r = 0; r < runs; ++r) {
                x += in.next();
                const std::uint64_t length = in.next() + 1;
                if (x + length > std::uint64_t(n.x))
                    throw Error(where + ": a run passes the end of scanline (j " +
                                std::to_string(y) + ", k " + std::to_string(z) + ")");
                if (length > count - v)
                    throw Error(where + ": position code holds more than the declared " +
                                std::to_string(count) + " voxels");
                for (std::uint64_t e = x + length; x < e; ++x, ++v) {
                    i[v] = std::uint16_t(x);
                    j[v] = std::uint16_t(y);
                    k[v] = std::uint16_t(z);
                }
            }
        }
    if (v != count)
        throw Error(where + ": position code holds " + std::to_string(v) +
                    " voxels, the header declares " + std::to_string(count));
    if (in.at != size) throw Error(where + ": bytes left over after the position code");
}

} // namespace volsg
