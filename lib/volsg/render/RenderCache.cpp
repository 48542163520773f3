#include <volsg/render/RenderCache.h>

#include <functional>

namespace volsg {

std::size_t RenderCache::KeyHash::operator()(const Key& k) const noexcept {
    std::size_t h = std::hash<const void*>()(k.owner);
    h ^= k.type.hash_code() + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h ^= std::hash<std::uint64_t>()(k.key) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    return h;
}

RenderCache::Entry& RenderCache::findOrInsert(const Object* owner, std::type_index type,
                                              std::uint64_t key,
                                              std::unique_ptr<SlotBase> (*make)()) {
    auto [it, inserted] = entries_.try_emplace(Key{owner, type, key});
    Entry& e = it->second;
    if (inserted) {
        e.owner = ref_ptr<const Object>(owner);
        e.slot = make();
    }
    e.lastUsedFrame = frame_;
    return e;
}

void RenderCache::endFrame() {
    std::erase_if(entries_, [this](const auto& kv) {
        return kv.first.owner && kv.second.lastUsedFrame != frame_;
    });
}

} // namespace volsg
