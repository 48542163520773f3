// Writes the glTF mesh of examples/volume-with-mesh.iv (a torus knot) to the file named on the
// command line: `volsg-make-example-mesh examples/gltf/torus-knot.glb`. The committed file is
// this program's output (tests/gltf/GltfExampleTest.cpp checks it byte for byte).
#include <cstdio>
#include <fstream>
#include <iostream>

#include "ExampleMesh.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: volsg-make-example-mesh OUTPUT.glb\n";
        return 2;
    }
    const std::vector<std::uint8_t> bytes = volsg::example::torusKnotGlb();
    std::ofstream out(argv[1], std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out) {
        std::cerr << "volsg-make-example-mesh: cannot write " << argv[1] << "\n";
        return 1;
    }
    return 0;
}
