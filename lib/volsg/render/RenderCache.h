#pragma once
// GPU-side data kept across frames (meshes, volume textures, programs), per owner and key.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <typeindex>
#include <unordered_map>

#include <volsg/core/Object.h>

namespace volsg {

/// One value of any type T per (owner, T, key), created on first use and kept while the owner
/// is drawn. The owner is whatever the value belongs to (a node, a grid): an entry not used
/// during a frame is dropped at the end of that frame, so an owner that left the scene, or a
/// key that changed (a mesh rebuilt for new field values), frees its GL objects one frame
/// later and nothing accumulates. Entries hold a reference to their owner, so its address
/// cannot be reused while its entry lives. shared<T>() is one value per type for the whole
/// cache (a renderer's program): kept for the cache's life. Lives in one Renderer, so one GL
/// context: values may own GL objects, and are destroyed with that context current.
class RenderCache {
public:
    RenderCache() = default;
    RenderCache(const RenderCache&) = delete;
    RenderCache& operator=(const RenderCache&) = delete;

    /// The value for (owner, T, key); a default-constructed T the first time. The reference
    /// stays valid until the end of the frame at least.
    template <class T> T& get(const Object& owner, std::uint64_t key = 0) {
        Entry& e = findOrInsert(&owner, std::type_index(typeid(T)), key, &make<T>);
        return static_cast<Slot<T>&>(*e.slot).value;
    }
    /// The one T of this cache (per GL context), made on first use and never dropped.
    template <class T> T& shared() {
        Entry& e = findOrInsert(nullptr, std::type_index(typeid(T)), 0, &make<T>);
        return static_cast<Slot<T>&>(*e.slot).value;
    }

    void beginFrame() { ++frame_; }
    /// Drops every owned entry not used since beginFrame().
    void endFrame();
    std::size_t size() const { return entries_.size(); }
    void clear() { entries_.clear(); }

private:
    struct SlotBase {
        virtual ~SlotBase() = default;
    };
    template <class T> struct Slot final : SlotBase { T value{}; };
    template <class T> static std::unique_ptr<SlotBase> make() {
        return std::unique_ptr<SlotBase>(new Slot<T>());
    }
    struct Key {
        const Object* owner; ///< null: a shared entry
        std::type_index type;
        std::uint64_t key;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const noexcept;
    };
    struct Entry {
        ref_ptr<const Object> owner;
        std::unique_ptr<SlotBase> slot;
        std::uint64_t lastUsedFrame = 0;
    };

    Entry& findOrInsert(const Object* owner, std::type_index type, std::uint64_t key,
                        std::unique_ptr<SlotBase> (*make)());

    std::unordered_map<Key, Entry, KeyHash> entries_;
    std::uint64_t frame_ = 0;
};

} // namespace volsg
