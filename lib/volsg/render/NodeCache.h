#pragma once
// GPU-side data that nodes keep across frames (meshes, volume textures), per node and key.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <typeindex>
#include <unordered_map>

#include <volsg/core/Node.h>

namespace volsg {

/// One value of any type T per (node, T, key), created on first use and kept while the node
/// is drawn. An entry not used during a frame is dropped at the end of that frame: a node
/// that left the scene, or a key that changed (a mesh rebuilt for new field values), frees
/// its GL objects one frame later, so nothing accumulates across frames. Entries hold a
/// reference to their node, so a node's address cannot be reused by another node while its
/// entry lives. Lives in one Renderer, so one GL context: values may own GL objects, and are
/// destroyed with that context current.
class NodeCache {
public:
    NodeCache() = default;
    NodeCache(const NodeCache&) = delete;
    NodeCache& operator=(const NodeCache&) = delete;

    /// The value for (node, T, key); a default-constructed T the first time. The reference
    /// stays valid until the end of the frame at least.
    template <class T> T& get(const Node& node, std::uint64_t key = 0) {
        Entry& e = findOrInsert(node, std::type_index(typeid(T)), key,
                                [] { return std::unique_ptr<SlotBase>(new Slot<T>()); });
        return static_cast<Slot<T>&>(*e.slot).value;
    }

    void beginFrame() { ++frame_; }
    /// Drops every entry not used since beginFrame().
    void endFrame();
    std::size_t size() const { return entries_.size(); }
    void clear() { entries_.clear(); }

private:
    struct SlotBase {
        virtual ~SlotBase() = default;
    };
    template <class T> struct Slot final : SlotBase { T value{}; };
    struct Key {
        const Node* node;
        std::type_index type;
        std::uint64_t key;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        std::size_t operator()(const Key& k) const noexcept;
    };
    struct Entry {
        ref_ptr<const Node> node;
        std::unique_ptr<SlotBase> slot;
        std::uint64_t lastUsedFrame = 0;
    };

    Entry& findOrInsert(const Node& node, std::type_index type, std::uint64_t key,
                        std::unique_ptr<SlotBase> (*make)());

    std::unordered_map<Key, Entry, KeyHash> entries_;
    std::uint64_t frame_ = 0;
};

} // namespace volsg
