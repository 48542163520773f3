#pragma once
// Meshes on the GPU shared by content: shapes whose meshes are equal (the 2,500 equal Cubes of
// a grid, or one USEd shape) draw the same GpuMesh, so the batched draws of ShapeRenderer
// group them into one instanced draw.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include <volsg/render/GpuMesh.h>

namespace volsg {

class ShapeRenderer;
struct ShapeDetail;

/// One per RenderCache (RenderCache::shared): the live GpuMeshes by the hash of their content.
/// A mesh stays while someone holds it (a shape's cache entry, a render cache's record).
class SharedMeshes {
public:
    /// The GpuMesh of `mesh`'s content: an existing one with equal content, or a new upload
    /// (counted by `shapes`).
    std::shared_ptr<GpuMesh> find(const Mesh& mesh, ShapeRenderer& shapes);
    /// Meshes alive and their GPU bytes (vertex and index buffers).
    std::size_t count() const;
    std::size_t bytes() const;

private:
    struct Entry {
        std::weak_ptr<GpuMesh> gpu;
        Mesh content; ///< compared on a hash match: equal hashes are not proof
    };
    std::unordered_multimap<std::uint64_t, Entry> entries_;
    std::size_t insertsSincePrune_ = 0;
};

/// What a shape node keeps per mesh key in the RenderCache: its shared mesh, and its coarser
/// ones for small projections (null for shapes without).
struct ShapeMesh {
    std::shared_ptr<GpuMesh> gpu;
    std::shared_ptr<const ShapeDetail> detail;
};

} // namespace volsg
