#include "VolPackCases.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <utility>

#include "VolPackRenderer.h"
#include <volsg/actions/SearchAction.h>
#include <volsg/core/Error.h>
#include <volsg/io/SceneReader.h>
#include <volsg/nodes/VolumeData.h>

namespace volsg::volpackbench {

namespace {

std::string number(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.9g", v);
    return buffer;
}

/// An orthographic camera 0.3 rad above the equator that sees a cube of side `extent` centred
/// on the origin whole from every orbit angle (its bounding sphere fits the view height).
std::string cameraFor(double extent) {
    const double radius = 0.5 * std::sqrt(3.0) * extent;
    const double distance = 2.0 * radius, elevation = 0.3;
    return "  OrthographicCamera { position 0 " + number(distance * std::sin(elevation)) + " " +
           number(distance * std::cos(elevation)) + " orientation 1 0 0 " + number(-elevation) +
           " height " + number(2.0 * radius * 1.02) + " nearDistance " +
           number(distance - 1.05 * radius) + " farDistance " + number(distance + 1.05 * radius) +
           " focalDistance " + number(distance) + " }\n";
}

/// A transfer function over data bytes 0..255: colour and alpha control points (byte, value).
struct Ramp {
    std::vector<std::pair<double, glm::dvec3>> colour;
    std::vector<glm::dvec2> alpha;
};

std::string points(const std::vector<glm::dvec2>& p) {
    std::string s = "[ ";
    for (std::size_t i = 0; i < p.size(); ++i)
        s += (i ? ", " : "") + number(p[i].x) + " " + number(p[i].y);
    return s + " ]";
}

/// The TransferFunction node of a ramp (control points at byte / 255, dataRange 0 255).
std::string transferFunction(const Ramp& ramp, const std::string& indent) {
    std::vector<glm::dvec2> channel[3];
    for (const auto& [byte, colour] : ramp.colour)
        for (int c = 0; c < 3; ++c)
            channel[c].emplace_back(byte / 255.0, colour[c]);
    std::vector<glm::dvec2> alpha;
    for (const glm::dvec2& p : ramp.alpha)
        alpha.emplace_back(p.x / 255.0, p.y);
    return indent + "TransferFunction { dataRange 0 255\n" + indent + "  red " +
           points(channel[0]) + " green " + points(channel[1]) + " blue " + points(channel[2]) +
           "\n" + indent + "  alpha " + points(alpha) + " }\n";
}

/// Shaded, the ShearWarpVolume reads the colour channels as a ramp over the Phong intensity
/// (RTVR's LUT3): black to VolPack's material colour, with the ramp's opacity.
std::string shadedTransferFunction(const Ramp& ramp) {
    const glm::dvec3 material = volpack::Shading{}.materialColor;
    Ramp shaded = ramp;
    shaded.colour = {{0.0, glm::dvec3(0.0)}, {255.0, material}};
    return transferFunction(shaded, "    ");
}

/// The grey ramp of the generated volumes: colour 0 -> 1 and alpha 0 -> `alpha` from byte `lo`
/// to byte `hi` (the issue's `--tf 40 255 0.6`).
Ramp greyRamp(double lo, double hi, double alpha) {
    return {{{0.0, glm::dvec3(0.0)}, {lo, glm::dvec3(0.0)}, {hi, glm::dvec3(1.0)}},
            {{0.0, 0.0}, {lo, 0.0}, {hi, alpha}}};
}

std::string volumeScene(const std::string& title, double extent, const std::string& volumeData,
                        const Ramp& ramp) {
    return "#Inventor V2.1 ascii\n# volsg-volpack-bench case " + title + "\nSeparator {\n" +
           cameraFor(extent) + "  " + volumeData + "\n" + transferFunction(ramp, "  ") +
           "  Volume { }\n}\n";
}

std::string rawVolumeData(const std::filesystem::path& file, const glm::ivec3& n,
                          const glm::dvec3& spacing) {
    return "VolumeData { fileName \"" + std::filesystem::absolute(file).string() +
           "\" dimensions " + std::to_string(n.x) + " " + std::to_string(n.y) + " " +
           std::to_string(n.z) + " dataType UBYTE spacing " + number(spacing.x) + " " +
           number(spacing.y) + " " + number(spacing.z) + " }";
}

double extentOf(const glm::ivec3& n, const glm::dvec3& spacing) {
    const glm::dvec3 e = glm::dvec3(n) * spacing;
    return std::max({e.x, e.y, e.z});
}

// --- Generated volumes -------------------------------------------------------------------------

/// A deterministic hash of a voxel index to [0, 1) (splitmix64).
double hashUnit(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    x ^= x >> 31;
    return double(x >> 11) * (1.0 / 9007199254740992.0);
}

/// Writes an n^3 byte volume whose voxel (i, j, k) is value(x, y, z), x = i / n etc.
void writeVolume(const std::filesystem::path& file, int n,
                 const std::function<double(double, double, double, std::size_t)>& value) {
    std::vector<std::uint8_t> bytes(std::size_t(n) * std::size_t(n) * std::size_t(n));
    std::size_t index = 0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i, ++index) {
                const double v = value((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n, index);
                bytes[index] = std::uint8_t(std::clamp(std::lround(v), 0l, 255l));
            }
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out) throw Error("cannot write " + file.string());
}

double gaussian(const glm::dvec3& p, const glm::dvec3& centre, double sigma) {
    const glm::dvec3 d = p - centre;
    return std::exp(-glm::dot(d, d) / (2.0 * sigma * sigma));
}

/// A sphere shell (radius 0.4, about 6 voxels thick at 256) with the octant x, z > 0.5 cut away,
/// and six dense gaussian blobs inside it.
double shellValue(double x, double y, double z, std::size_t) {
    const glm::dvec3 p(x, y, z), c(0.5);
    double v = 0.0;
    if (!(x > 0.5 && z > 0.5)) {
        const double r = glm::length(p - c);
        const double t = (r - 0.4) / 0.012;
        v = 255.0 * std::exp(-t * t);
    }
    static const glm::dvec3 blobs[] = {{0.40, 0.45, 0.42}, {0.60, 0.40, 0.55}, {0.50, 0.62, 0.48},
                                       {0.35, 0.35, 0.62}, {0.62, 0.60, 0.35}, {0.45, 0.55, 0.65}};
    for (const glm::dvec3& b : blobs)
        v = std::max(v, 255.0 * gaussian(p, b, 0.045));
    return v;
}

/// Five dense gaussian blobs (sigma 0.08): with the grey ramp their interiors are opaque.
double blobsValue(double x, double y, double z, std::size_t) {
    static const glm::dvec3 blobs[] = {{0.30, 0.30, 0.50},
                                       {0.70, 0.32, 0.40},
                                       {0.50, 0.70, 0.50},
                                       {0.30, 0.62, 0.30},
                                       {0.66, 0.64, 0.70}};
    double v = 0.0;
    for (const glm::dvec3& b : blobs)
        v = std::max(v, 255.0 * gaussian(glm::dvec3(x, y, z), b, 0.08));
    return v;
}

/// Head CT (int16, 0..3926) as bytes: round(255 v / max).
void writeHeadBytes(const std::filesystem::path& data, const std::filesystem::path& file) {
    const std::filesystem::path source = data / "vtkjs-headsq" / "headsq_64x64x93_int16le.raw.gz";
    ref_ptr<Node> root = readSceneFromString("#Inventor V2.1 ascii\nVolumeData { fileName \"" +
                                                 std::filesystem::absolute(source).string() +
                                                 "\" dimensions 64 64 93 dataType SHORT }\n",
                                             "head-ct");
    const std::vector<Node*> found = findAll(*root, VolumeData::classType());
    if (found.empty()) throw Error("no VolumeData", source.string());
    ref_ptr<const VolumeGrid> grid = static_cast<VolumeData&>(*found.front()).grid();
    double top = 1.0;
    for (std::size_t i = 0; i < grid->voxelCount(); ++i)
        top = std::max(top, grid->value(i));
    std::vector<std::uint8_t> bytes(grid->voxelCount());
    for (std::size_t i = 0; i < bytes.size(); ++i)
        bytes[i] = std::uint8_t(std::clamp(std::lround(255.0 * grid->value(i) / top), 0l, 255l));
    std::ofstream out(file, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out) throw Error("cannot write " + file.string());
}

// --- The CT transfer functions -----------------------------------------------------------------

const glm::dvec3 kSkin(1.0, 0.78, 0.62), kBone(1.0, 0.97, 0.9);

/// Chest CT (LIDC2, bytes: air and lung 0-7, fat and soft tissue 8-60, vessels 90-149, bone
/// 150-255). Skin: all tissue, a dense body; bone: sparse opaque surfaces.
Ramp chestSkin() {
    return {{{0.0, kSkin * 0.6}, {255.0, kSkin}},
            {{0.0, 0.0}, {10.0, 0.0}, {40.0, 0.25}, {255.0, 0.25}}};
}
Ramp chestBone() {
    return {{{0.0, kBone * 0.7}, {255.0, kBone}},
            {{0.0, 0.0}, {150.0, 0.0}, {200.0, 0.8}, {255.0, 0.8}}};
}
/// Head CT (headsq scaled to bytes: air 0-15, soft tissue and brain 56-79, bone 90-170).
Ramp headSkin() {
    return {{{0.0, kSkin * 0.6}, {255.0, kSkin}},
            {{0.0, 0.0}, {30.0, 0.0}, {60.0, 0.3}, {255.0, 0.3}}};
}
Ramp headBone() {
    return {{{0.0, kBone * 0.7}, {255.0, kBone}},
            {{0.0, 0.0}, {95.0, 0.0}, {140.0, 0.8}, {255.0, 0.8}}};
}

Case fromRamp(const std::string& name, const std::string& description, double extent,
              const std::string& volumeData, const Ramp& ramp, bool shaded) {
    Case c;
    c.name = name;
    c.description = description + (shaded ? ", shaded" : "");
    c.sceneText = volumeScene(name, extent, volumeData, ramp);
    c.shaded = shaded;
    if (shaded) c.shearWarpTransferFunction = shadedTransferFunction(ramp);
    return c;
}

bool endsWith(const std::string& s, const std::string& tail) {
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

} // namespace

std::vector<std::string> caseNames(const CaseInputs& inputs) {
    std::vector<std::string> names = {"sphere",
                                      "shell",
                                      "blobs",
                                      "random1",
                                      "random10",
                                      "ml",
                                      "ml-shaded",
                                      "chest-skin",
                                      "chest-skin-shaded",
                                      "chest-bone",
                                      "chest-bone-shaded",
                                      "head-skin",
                                      "head-skin-shaded",
                                      "head-bone",
                                      "head-bone-shaded"};
    if (inputs.raw) {
        names.push_back("raw");
        names.push_back("raw-shaded");
    }
    return names;
}

Case makeCase(const std::string& name, const CaseInputs& in) {
    const int n = in.side;
    const std::string side = std::to_string(n);
    const glm::ivec3 cube(n);
    const Ramp grey = greyRamp(40.0, 255.0, 0.6);
    const bool shaded = endsWith(name, "-shaded");
    const std::string base = shaded ? name.substr(0, name.size() - 7) : name;
    std::filesystem::create_directories(in.out);
    if (base == "sphere" && !shaded) {
        // Soft sphere: v = 1 - r / (0.45 n). Visible where v >= 0.4, a ball of radius 0.27 n:
        // 4/3 pi (0.27 * 256)^3 = 1.40M voxels at n = 256 (8.4% of the volume). (The scene of
        // the earlier measurements, unchanged.)
        Case c;
        c.name = name;
        c.description = "soft sphere " + side + "^3, grey DVR";
        c.sceneText = "#Inventor V2.1 ascii\n# volsg-volpack-bench case sphere: a " + side +
                      "^3 8-bit soft sphere, ~8% of its voxels visible, grey DVR\nSeparator {\n" +
                      cameraFor(double(n)) + "  VolumeData { generator SOFT_SPHERE dimensions " +
                      side + " " + side + " " + side +
                      " }\n"
                      "  TransferFunction { red [ 0 0, 0.4 0.2, 1 1 ] green [ 0 0, 0.4 0.2, 1 1 ] "
                      "blue [ 0 0, 0.4 0.2, 1 1 ] alpha [ 0 0, 0.399 0, 0.4 0.004, 1 0.05 ] }\n"
                      "  Volume { }\n}\n";
        return c;
    }
    if (base == "ml") {
        // The volume suite's smooth transfer function (its opacity given for 64^3, converted to
        // this side so the optical depth is the same). (The earlier measurements' scene.)
        const double alpha = 1.0 - std::pow(1.0 - 0.06, 64.0 / double(n));
        Case c;
        c.name = name;
        c.description =
            "Marschner-Lobb " + side + "^3, smooth colour TF" + (shaded ? ", shaded" : "");
        c.sceneText = "#Inventor V2.1 ascii\n# volsg-volpack-bench case ml: Marschner-Lobb " +
                      side + "^3, smooth transfer function (the volume suite's)\nSeparator {\n" +
                      cameraFor(double(n) * 2.0 / double(n - 1)) +
                      "  VolumeData { generator MARSCHNER_LOBB dimensions " + side + " " + side +
                      " " + side +
                      " }\n"
                      "  TransferFunction {\n"
                      "    red [ 0 0.1, 0.5 0.9, 1 1 ]  green [ 0 0.3, 0.5 0.6, 1 0.9 ]  "
                      "blue [ 0 1, 0.5 0.4, 1 0.1 ]\n"
                      "    alpha [ 0 0, 1 " +
                      number(alpha) + " ]\n  }\n  Volume { }\n}\n";
        c.shaded = shaded;
        if (shaded) {
            const glm::dvec3 material = volpack::Shading{}.materialColor;
            c.shearWarpTransferFunction =
                "    TransferFunction { red [ 0 0, 1 " + number(material.r) + " ] green [ 0 0, 1 " +
                number(material.g) + " ] blue [ 0 0, 1 " + number(material.b) +
                " ] alpha [ 0 0, 1 " + number(alpha) + " ] }\n";
        }
        return c;
    }
    using Generator = double (*)(double, double, double, std::size_t);
    const std::pair<const char*, Generator> generated[] = {
        {"shell", shellValue}, {"blobs", blobsValue}, {"random1", nullptr}, {"random10", nullptr}};
    for (const auto& [gName, generator] : generated) {
        if (base != gName || shaded) continue;
        const std::filesystem::path file = in.out / (base + "-" + side + ".raw");
        const double fraction = base == "random1" ? 0.01 : 0.10;
        if (generator)
            writeVolume(file, n, generator);
        else // sparse random voxels of random visible value 41..255, the rest 0
            writeVolume(file, n, [fraction](double, double, double, std::size_t i) {
                return hashUnit(2 * i) < fraction ? 41.0 + 214.0 * hashUnit(2 * i + 1) : 0.0;
            });
        const std::string what = base == "shell"     ? "cut-open sphere shell + 6 dense blobs "
                                 : base == "blobs"   ? "5 dense blobs with opaque interiors "
                                 : base == "random1" ? "1% random voxels "
                                                     : "10% random voxels ";
        return fromRamp(name, what + side + "^3, grey ramp 40..255 -> 0.6", double(n),
                        rawVolumeData(file, cube, glm::dvec3(1.0)), grey, false);
    }
    if (base == "chest-skin" || base == "chest-bone") {
        const glm::ivec3 dims(256, 256, 133);
        const glm::dvec3 spacing(1.40625, 1.40625, 2.5);
        const std::filesystem::path file =
            in.data / "vtkjs-lidc2" / "lidc2_256x256x133_uint8.raw.gz";
        const bool skin = base == "chest-skin";
        return fromRamp(name, std::string("chest CT 256x256x133, ") + (skin ? "skin" : "bone"),
                        extentOf(dims, spacing), rawVolumeData(file, dims, spacing),
                        skin ? chestSkin() : chestBone(), shaded);
    }
    if (base == "head-skin" || base == "head-bone") {
        const glm::ivec3 dims(64, 64, 93);
        const glm::dvec3 spacing(3.2, 3.2, 1.5);
        const std::filesystem::path file = in.out / "head-ct-64x64x93-bytes.raw";
        writeHeadBytes(in.data, file);
        const bool skin = base == "head-skin";
        return fromRamp(name, std::string("head CT 64x64x93 (8-bit), ") + (skin ? "skin" : "bone"),
                        extentOf(dims, spacing), rawVolumeData(file, dims, spacing),
                        skin ? headSkin() : headBone(), shaded);
    }
    if (base == "raw" && in.raw) {
        const RawInput& r = *in.raw;
        return fromRamp(name,
                        r.file.filename().string() + ", grey ramp " + number(r.tfLow) + ".." +
                            number(r.tfHigh) + " -> " + number(r.tfAlpha),
                        extentOf(r.dimensions, r.spacing),
                        rawVolumeData(r.file, r.dimensions, r.spacing),
                        greyRamp(r.tfLow, r.tfHigh, r.tfAlpha), shaded);
    }
    std::string known;
    for (const std::string& k : caseNames(in))
        known += (known.empty() ? "" : ", ") + k;
    throw Error("unknown case '" + name + "' (" + known + ", all)");
}

} // namespace volsg::volpackbench
