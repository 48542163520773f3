#include <volsg/nodes/GltfModel.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/core/Error.h>
#include <volsg/geometry/RayIntersect.h>
#include <volsg/gltf/GltfAsset.h>
#include <volsg/gltf/GltfGpuAsset.h>
#include <volsg/gltf/GltfLoader.h>
#include <volsg/gltf/GltfRenderer.h>
#include <volsg/io/ReadContext.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/render/RenderAction.h>

namespace volsg {

namespace {

/// Whether the ray (t >= 0) meets the box at all: the slab test, to skip whole primitives.
bool rayMeetsBox(const Ray& ray, const Box3& box) {
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        if (ray.direction[a] == 0.0) {
            if (ray.origin[a] < box.min[a] || ray.origin[a] > box.max[a]) return false;
            continue;
        }
        double near = (box.min[a] - ray.origin[a]) / ray.direction[a];
        double far = (box.max[a] - ray.origin[a]) / ray.direction[a];
        if (near > far) std::swap(near, far);
        t0 = std::max(t0, near);
        t1 = std::min(t1, far);
        if (t0 > t1) return false;
    }
    return true;
}

} // namespace

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

void GltfModel::render(RenderAction& action) {
    if (action.pass() == RenderPass::Volume) return;
    const GltfAsset& a = asset();
    // Keyed by the load, so a reload starts a fresh GPU copy and the old one is dropped.
    GltfGpuAsset& gpu = action.cache<GltfGpuAsset>(*this, loadSerial_);
    if (!gpu.uploaded()) gpu.upload(a);
    GltfRenderer::of(action).submit(action, a, gpu);
}

void GltfModel::getBoundingBox(BoundingBoxAction& action) {
    action.extendByLocal(asset().bounds);
}

void GltfModel::pick(PickAction& action) {
    const GltfAsset& a = asset();
    const glm::dmat4& nodeModel = action.state().modelMatrix();
    const StateEntry* boxEntry = action.state().nearest<BoxClip>();
    std::size_t first = 0; // flat index of the instance's primitive's first triangle
    for (const GltfInstance& instance : a.instances) {
        const GltfMesh& mesh = a.meshes[std::size_t(instance.mesh)];
        const glm::dmat4 model = nodeModel * instance.matrix;
        const double det = glm::determinant(glm::dmat3(model));
        const bool invertible = std::abs(det) > 0.0 && std::isfinite(det);
        const Ray local = invertible ? action.worldRay().transformed(glm::inverse(model)) : Ray{};
        const glm::dmat3 normalToNode = glm::transpose(glm::inverse(glm::dmat3(instance.matrix)));
        for (const GltfPrimitive& p : mesh.primitives) {
            const std::size_t triangles = p.triangleCount();
            if (!invertible || triangles == 0 || !rayMeetsBox(local, p.bounds)) {
                first += triangles;
                continue;
            }
            const bool smooth = p.normals.size() == p.positions.size();
            for (std::size_t i = 0; i < triangles; ++i) {
                const std::uint32_t ia = p.indices[3 * i], ib = p.indices[3 * i + 1],
                                    ic = p.indices[3 * i + 2];
                const glm::dvec3 A(p.positions[ia]), B(p.positions[ib]), C(p.positions[ic]);
                const auto hit = intersectTriangle(local, A, B, C);
                if (!hit) continue;
                const double w = 1.0 - hit->u - hit->v;
                const glm::dvec3 point = w * A + hit->u * B + hit->v * C;
                if (boxEntry) { // BoxClip opacity 0 removes geometry for picking too
                    const auto& box = static_cast<const BoxClip&>(*boxEntry->node);
                    const glm::dvec3 world(model * glm::dvec4(point, 1.0));
                    const glm::dvec3 q(glm::inverse(boxEntry->model) * glm::dvec4(world, 1.0));
                    const glm::dvec3 lo(glm::min(box.origin(), box.origin() + box.extent()));
                    const glm::dvec3 hi(glm::max(box.origin(), box.origin() + box.extent()));
                    const bool inside = glm::all(glm::greaterThanEqual(q, lo)) &&
                                        glm::all(glm::lessThanEqual(q, hi));
                    if ((inside ? box.insideOpacity() : box.outsideOpacity()) <= 0.0f) continue;
                }
                glm::dvec3 normal(0.0);
                if (smooth)
                    normal = w * glm::dvec3(p.normals[ia]) + hit->u * glm::dvec3(p.normals[ib]) +
                             hit->v * glm::dvec3(p.normals[ic]);
                if (!(glm::length(normal) > 0.0)) normal = glm::cross(B - A, C - A);
                action.addLocalHit(glm::dvec3(instance.matrix * glm::dvec4(point, 1.0)),
                                   normalToNode * normal, first + i);
            }
            first += triangles;
        }
    }
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
