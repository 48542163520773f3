// Writes the seed corpus of fuzz-voxelfile (tests/fuzz/corpus/voxelfile/): small .vsgv files
// made by the real encoder, from no objects to two objects of a few voxels.
//   fuzz-make-voxelfile-seeds tests/fuzz/corpus/voxelfile
#include <volsg/core/Error.h>
#include <volsg/voxelfile/VoxelFile.h>

#include <cstdio>
#include <fstream>
#include <string>

using namespace volsg;

namespace {

ref_ptr<VoxelObject> smallObject(int count, int seed) {
    VoxelObject::Arrays a;
    a.dimensions = {4, 3, 2};
    a.spacing = {1.0, 1.5, 2.0};
    a.maxMagnitude = 0.75;
    for (int n = 0; n < count; ++n) {
        a.i.push_back(std::uint16_t(n % 4));
        a.j.push_back(std::uint16_t((n / 4) % 3));
        a.k.push_back(std::uint16_t((n / 12) % 2));
        a.value12.push_back(std::uint16_t((n * 311 + seed) % 4096));
        a.gradientCode.push_back(std::uint16_t((n * 97 + seed) % 4096));
        a.magnitude8.push_back(std::uint8_t(n * 13 + seed));
    }
    return VoxelObject::fromArrays(std::move(a));
}

void save(const std::string& dir, const char* name, const VoxelFileContent& content) {
    const std::string bytes = encodeVoxelFile(content);
    std::ofstream(dir + "/" + name, std::ios::binary) << bytes;
    std::printf("%s: %zu bytes\n", name, bytes.size());
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUTPUT_FOLDER\n", argv[0]);
        return 2;
    }
    const std::string dir = argv[1];
    const std::string scene = "#Inventor V2.1 ascii\nSeparator { ShearWarpVolume { "
                              "VolumeObject { } VolumeObject { } } }\n";
    VoxelFileContent empty;
    empty.sceneText = scene;
    save(dir, "no-objects.vsgv", empty);

    VoxelFileContent one = empty;
    PackedObject object;
    object.voxels = smallObject(24, 1);
    object.extraction.source.kind = ObjectSource::Threshold;
    object.extraction.source.low = 0.25;
    object.extraction.source.high = 0.75;
    object.extraction.selection = VoxelSelection::Surface;
    one.objects.push_back(object);
    save(dir, "one-object.vsgv", one);

    VoxelFileContent two = one;
    PackedObject tagged;
    tagged.objectIndex = 1;
    tagged.voxels = smallObject(5, 7);
    tagged.extraction.source.kind = ObjectSource::Tag;
    tagged.extraction.source.tag = 3;
    tagged.extraction.selection = VoxelSelection::Gradient;
    tagged.extraction.gradientThreshold = 0.1;
    tagged.extraction.dataRange = {-100.0, 900.0};
    two.objects.push_back(tagged);
    save(dir, "two-objects.vsgv", two);
    return 0;
}
