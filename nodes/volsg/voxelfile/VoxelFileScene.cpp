#include <volsg/voxelfile/VoxelFileScene.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/io/RegularFile.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/volumescene/ShearWarpObjects.h>
#include <volsg/voxelfile/PackedVolume.h>

namespace volsg {

namespace {

/// Every ShearWarpVolume under `node`, depth first, each once (DEF/USE shares nodes).
void collectVolumes(Node& node, std::vector<ShearWarpVolume*>& out, std::set<Node*>& seen) {
    if (!seen.insert(&node).second) return;
    if (node.isA<ShearWarpVolume>()) out.push_back(static_cast<ShearWarpVolume*>(&node));
    if (auto* children = node.children())
        for (const auto& child : *children)
            if (child) collectVolumes(*child, out, seen);
}

/// Drops the VolumeData nodes of the stored scene.
void removeVolumeData(Node& node, std::set<Node*>& seen) {
    if (!seen.insert(&node).second) return;
    auto* children = node.children();
    if (!children) return;
    std::erase_if(*children, [](const ref_ptr<Node>& c) { return c && c->isA<VolumeData>(); });
    for (const auto& child : *children)
        if (child) removeVolumeData(*child, seen);
}

/// Makes the stored scene's self references ("#k") name the file: `reference + "#k"`.
void nameVoxelFile(Node& root, const std::string& reference) {
    std::vector<ShearWarpVolume*> volumes;
    std::set<Node*> seen;
    collectVolumes(root, volumes, seen);
    for (ShearWarpVolume* volume : volumes)
        if (volume->voxelFile().starts_with('#'))
            volume->voxelFile.setValue(reference + volume->voxelFile());
}

/// Walks the graph as a render does and extracts each ShearWarpVolume's objects the first
/// time it is reached.
class ObjectPacker : public Action {
public:
    std::map<const ShearWarpVolume*, std::vector<PackedObject>> objects;

protected:
    void dispatch(Node& node) override {
        if (node.isA<ShearWarpVolume>()) {
            auto& volume = static_cast<ShearWarpVolume&>(node);
            if (!objects.count(&volume)) objects[&volume] = pack(volume);
        }
        node.doAction(*this);
    }

private:
    std::vector<PackedObject> pack(ShearWarpVolume& volume) {
        if (!volume.voxelFile().empty())
            throw Error("volsg-pack: a ShearWarpVolume draws from voxelFile '" +
                        volume.voxelFile() + "' already: pack the scene with the volume");
        std::vector<VolumeObject*> sources;
        const std::vector<ShearWarpObject> gathered =
            gatherShearWarpObjects(volume, state(), &sources);
        std::vector<PackedObject> out;
        const VolumeData* data = state().nearestNode<VolumeData>();
        if (!data || !data->grid())
            throw Error("volsg-pack: a ShearWarpVolume has no VolumeData in scope");
        for (std::size_t i = 0; i < gathered.size(); ++i) {
            PackedObject o;
            o.objectIndex = std::uint32_t(i);
            const ExtractionSpec spec = sources[i]->extractionSpec(gathered[i].transferFunction);
            o.extraction.source = spec.source;
            o.extraction.selection = spec.selection;
            o.extraction.gradientThreshold = spec.gradientThreshold;
            o.extraction.dataRange = gathered[i].transferFunction.resolvedDataRange(*data->grid());
            o.voxels = gathered[i].object;
            out.push_back(std::move(o));
        }
        return out;
    }
};

} // namespace

VoxelFileContent packScene(Node& root) {
    ObjectPacker packer;
    packer.apply(root);
    std::vector<ShearWarpVolume*> volumes;
    std::set<Node*> seen;
    collectVolumes(root, volumes, seen);

    VoxelFileContent content;
    for (std::size_t v = 0; v < volumes.size(); ++v) {
        const auto it = packer.objects.find(volumes[v]);
        if (it == packer.objects.end())
            throw Error("volsg-pack: ShearWarpVolume " + std::to_string(v) +
                        " is not drawn (an inactive Switch child?): nothing to extract");
        for (PackedObject& o : it->second) {
            o.volumeIndex = std::uint32_t(v);
            content.objects.push_back(o);
        }
    }

    // The stored scene: a copy through the writer and reader, without volume files.
    ref_ptr<Node> copy = readSceneFromString(writeSceneToString(root));
    seen.clear();
    removeVolumeData(*copy, seen);
    std::vector<ShearWarpVolume*> copied;
    seen.clear();
    collectVolumes(*copy, copied, seen);
    if (copied.size() != volumes.size())
        throw Error("volsg-pack: the scene's copy differs from the scene");
    for (std::size_t v = 0; v < copied.size(); ++v)
        copied[v]->voxelFile.setValue("#" + std::to_string(v));
    content.sceneText = writeSceneToString(*copy);
    return content;
}

ref_ptr<Node> readVoxelFileScene(const std::string& path) {
    const std::shared_ptr<const VoxelFileContent> content = loadVoxelFileCached(path);
    ref_ptr<Node> root = readSceneFromString(content->sceneText, path);
    nameVoxelFile(*root, std::filesystem::path(path).filename().string());
    return root;
}

ref_ptr<Node> readSceneOrVoxelFile(const std::string& path) {
    // A regular file first: opening a FIFO to sniff its magic would block until a writer came.
    regularFileSize(path, "cannot read scene file", maxSceneFileSize);
    std::array<std::byte, 8> head{};
    std::ifstream file(path, std::ios::binary);
    file.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
    if (file.gcount() == std::streamsize(head.size()) && hasVoxelFileMagic(head))
        return readVoxelFileScene(path);
    return readScene(path);
}

std::string companionSceneText(const VoxelFileContent& content,
                               const std::string& voxelFileReference) {
    ref_ptr<Node> root = readSceneFromString(content.sceneText);
    nameVoxelFile(*root, voxelFileReference);
    return writeSceneToString(*root);
}

} // namespace volsg
