#pragma once
// GltfModel: a glTF 2.0 file (.gltf or .glb) in the scene, drawn with PBR materials among
// Inventor shapes and volumes (lib/volsg/gltf/).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

struct GltfAsset;

/// `GltfModel { fileName "part.glb" }`: the file's default scene, its node transforms under
/// the model matrix in scope. Takes part in every action: render (opaque and MASK primitives
/// in the Opaque pass, BLEND ones back to front in the Transparent pass: see GltfRenderer),
/// bounding box (exact, of every instanced vertex), pick (triangles; pickDetail() names the
/// glTF node, mesh, primitive and triangle), search, and write (the node and its file name,
/// not the mesh data). ClipPlanes and BoxClip in scope clip it as they clip shapes.
class GltfModel : public Inherit<Node, GltfModel> {
public:
    static constexpr const char* typeName = "GltfModel";
    SFString fileName{this, "fileName", ""};

    /// The loaded file: read on first use and again after a field changes; relative names
    /// resolve against the folder of the scene file (readDone). Throws Error naming the file
    /// and the glTF element at fault (GltfLoader.h). Not thread-safe.
    const GltfAsset& asset() const;
    /// fileName resolved against the scene file's folder.
    std::string path() const;

    /// What a pick's PickedPoint::primitiveIndex on this model names.
    struct PickDetail {
        int node = 0;             ///< glTF node index
        int mesh = 0;             ///< glTF mesh index
        int primitive = 0;        ///< index in the mesh's primitives
        std::size_t triangle = 0; ///< triangle of that primitive (strips and fans unrolled)
    };
    /// Decodes a PickedPoint::primitiveIndex reported by this model; empty if out of range.
    std::optional<PickDetail> pickDetail(std::size_t primitiveIndex) const;

    /// Which load asset() is (a process-wide count): keys the GPU copy, since a new asset may
    /// reuse the old one's address.
    std::uint64_t loadSerial() const { return loadSerial_; }

    void readDone(const ReadContext& context) override;

protected:
    ~GltfModel() override;

private:
    std::string directory_; ///< of the scene file that named fileName
    mutable std::shared_ptr<const GltfAsset> asset_;
    mutable std::uint64_t loadedVersion_ = 0;
    mutable std::uint64_t loadSerial_ = 0; ///< which load asset_ is (process-wide count)
};

} // namespace volsg
