#include <volsg/nodes/GltfModel.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>

#include <volsg/core/Error.h>
#include <volsg/gltf/GltfAsset.h>
#include <volsg/gltf/GltfLoader.h>
#include <volsg/io/ReadContext.h>

namespace volsg {

GltfModel::~GltfModel() = default;

void GltfModel::readDone(const ReadContext& context) {
    directory_ = context.directory;
}

std::string GltfModel::path() const {
    return ReadContext{{}, directory_}.resolve(fileName());
}

const GltfAsset& GltfModel::asset() const {
    if (!asset_ || loadedVersion_ != version()) {
        asset_.reset(); // a failed reload leaves nothing stale behind
        if (fileName().empty()) throw Error("GltfModel has no fileName");
        asset_ = std::make_shared<const GltfAsset>(loadGltf(path()));
        loadedVersion_ = version();
        // Names this load for the GPU caches: a new asset may reuse the old one's address.
        static std::atomic<std::uint64_t> loads{0};
        loadSerial_ = ++loads;
    }
    return *asset_;
}

std::optional<GltfModel::PickDetail> GltfModel::pickDetail(std::size_t primitiveIndex) const {
    const GltfAsset& a = asset();
    std::size_t first = 0;
    for (const GltfInstance& instance : a.instances) {
        const GltfMesh& mesh = a.meshes[std::size_t(instance.mesh)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::size_t triangles = mesh.primitives[p].triangleCount();
            if (primitiveIndex < first + triangles)
                return PickDetail{instance.node, instance.mesh, int(p), primitiveIndex - first};
            first += triangles;
        }
    }
    return std::nullopt;
}

} // namespace volsg
