#include <volsg/render/ShapeRenderer.h>
#include <volsg/render/SharedMeshes.h>

#include <cstring>
#include <iterator>

namespace volsg {

namespace {

template <class T> std::uint64_t mix(std::uint64_t h, const std::vector<T>& values) {
    // FNV-1a over 8-byte words (and the tail), seeded with the size: fast enough to run once
    // per new mesh.
    const auto* p = reinterpret_cast<const unsigned char*>(values.data());
    const std::size_t bytes = values.size() * sizeof(T);
    h = (h ^ bytes) * 0x100000001b3ULL;
    std::size_t i = 0;
    for (; i + 8 <= bytes; i += 8) {
        std::uint64_t w;
        std::memcpy(&w, p + i, 8);
        h = (h ^ w) * 0x100000001b3ULL;
        h ^= h >> 29;
    }
    for (; i < bytes; ++i)
        h = (h ^ p[i]) * 0x100000001b3ULL;
    return h;
}

template <class T> bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

std::uint64_t contentHash(const Mesh& m) {
    std::uint64_t h = 0xcbf29ce484222325ULL ^ std::uint64_t(m.primitive);
    h = mix(h, m.positions);
    h = mix(h, m.normals);
    h = mix(h, m.colors);
    h = mix(h, m.texCoords);
    return mix(h, m.indices);
}

bool sameContent(const Mesh& a, const Mesh& b) {
    return a.primitive == b.primitive && sameBytes(a.positions, b.positions) &&
           sameBytes(a.normals, b.normals) && sameBytes(a.colors, b.colors) &&
           sameBytes(a.texCoords, b.texCoords) && sameBytes(a.indices, b.indices);
}

} // namespace

std::shared_ptr<GpuMesh> SharedMeshes::find(const Mesh& mesh, ShapeRenderer& shapes) {
    const std::uint64_t h = contentHash(mesh);
    auto [first, last] = entries_.equal_range(h);
    for (auto it = first; it != last; ++it) {
        if (!sameContent(it->second.content, mesh)) continue;
        if (std::shared_ptr<GpuMesh> live = it->second.gpu.lock()) return live;
        entries_.erase(it);
        break;
    }
    auto gpu = std::make_shared<GpuMesh>();
    shapes.upload(*gpu, mesh);
    entries_.emplace(h, Entry{gpu, mesh});
    // Drop the entries of meshes nobody holds any more, now and then (amortised).
    if (++insertsSincePrune_ > entries_.size() / 2 + 64) {
        insertsSincePrune_ = 0;
        std::erase_if(entries_, [](const auto& kv) { return kv.second.gpu.expired(); });
    }
    return gpu;
}

std::size_t SharedMeshes::count() const {
    std::size_t n = 0;
    for (const auto& kv : entries_)
        n += !kv.second.gpu.expired();
    return n;
}

std::size_t SharedMeshes::bytes() const {
    std::size_t n = 0;
    for (const auto& kv : entries_)
        if (const auto live = kv.second.gpu.lock()) n += live->bytes();
    return n;
}

} // namespace volsg
