#include "SceneGenerators.h"

#include <cstdio>

namespace volsg::bench {

namespace {
const char* shapeOf(int i) {
    static const char* shapes[] = {"Cube { width 0.8 height 0.8 depth 0.8 }",
                                   "Sphere { radius 0.45 }", "Cone { bottomRadius 0.4 height 0.9 }",
                                   "Cylinder { radius 0.4 height 0.9 }"};
    return shapes[i % 4];
}

void appendItem(std::string& out, int i, float x, float y) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer,
                  "Separator {\n  Transform { translation %g %g 0 rotation 0 1 0 %g }\n"
                  "  Material { diffuseColor %g %g %g }\n  %s\n}\n",
                  double(x), double(y), 0.1 * (i % 31), 0.2 + 0.6 * ((i * 7) % 11) / 10.0,
                  0.2 + 0.6 * ((i * 5) % 13) / 12.0, 0.2 + 0.6 * ((i * 3) % 17) / 16.0, shapeOf(i));
    out += buffer;
}
} // namespace

std::string generateParseScene(int nodeCount) {
    std::string out = "#Inventor V2.1 ascii\n# volsg-bench parse suite\nSeparator {\n";
    const int items = nodeCount / 4; // each item is Separator, Transform, Material, shape
    for (int i = 0; i < items; ++i)
        appendItem(out, i, float(i % 100), float(i / 100));
    out += "}\n";
    return out;
}

std::string generateGridScene(int side) {
    std::string out = "#Inventor V2.1 ascii\n# volsg-bench traversal suite\nSeparator {\n";
    char buffer[256];
    const double half = 0.5 * side;
    std::snprintf(
        buffer, sizeof buffer,
        "OrthographicCamera { position %g %g %g height %g nearDistance 1 farDistance %g }\n"
        "DirectionalLight { direction -0.3 -0.4 -1 }\n",
        half - 0.5, half - 0.5, double(side), double(side), 2.0 * side);
    out += buffer;
    for (int i = 0; i < side * side; ++i)
        appendItem(out, i, float(i % side), float(i / side));
    out += "}\n";
    return out;
}

} // namespace volsg::bench
