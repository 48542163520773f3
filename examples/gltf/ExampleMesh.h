#pragma once
// The mesh of examples/volume-with-mesh.iv: a (2,3) torus knot tube as a .glb, built from
// closed-form geometry. Shared by the tool that writes examples/gltf/torus-knot.glb and the
// test that checks the committed file is what the tool writes.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

namespace volsg::example {

/// The bytes of the .glb: one mesh (one primitive: POSITION, NORMAL, u16 indices), one orange
/// dielectric metallic-roughness material, one node. Coordinates are rounded to multiples of 2^-16
/// so that the last bit of a sin or cos cannot change the file.
/// A .glb container (glTF 2.0 binary): the JSON chunk padded with spaces and the BIN chunk
/// padded with zeros to 4 bytes, as the format requires.
inline std::vector<std::uint8_t> packGlb(std::string json, std::vector<std::uint8_t> bin) {
    while (json.size() % 4)
        json += ' ';
    while (bin.size() % 4)
        bin.push_back(0);
    std::vector<std::uint8_t> out;
    auto u32 = [&](std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            out.push_back(std::uint8_t(v >> (8 * i)));
    };
    out.insert(out.end(), {'g', 'l', 'T', 'F'});
    u32(2);
    u32(std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    u32(std::uint32_t(json.size()));
    out.insert(out.end(), {'J', 'S', 'O', 'N'});
    out.insert(out.end(), json.begin(), json.end());
    u32(std::uint32_t(bin.size()));
    out.insert(out.end(), {'B', 'I', 'N', 0});
    out.insert(out.end(), bin.begin(), bin.end());
    return out;
}

inline std::vector<std::uint8_t> torusKnotGlb() {
    constexpr int kAround = 256, kSides = 16;
    constexpr double kScale = 0.11, kTube = 0.045;
    const double pi = std::numbers::pi;
    auto grid = [](double v) { return float(std::round(v * 65536.0) / 65536.0); };
    auto curve = [&](double t, double out[3]) {
        const double r = 2.0 + std::cos(3.0 * t);
        out[0] = kScale * r * std::cos(2.0 * t);
        out[1] = kScale * r * std::sin(2.0 * t);
        out[2] = kScale * std::sin(3.0 * t);
    };
    std::vector<float> positions, normals;
    float lo[3] = {1e30f, 1e30f, 1e30f}, hi[3] = {-1e30f, -1e30f, -1e30f};
    for (int i = 0; i < kAround; ++i) {
        const double t = 2.0 * pi * i / kAround, h = 1e-4;
        double c[3], a[3], b[3];
        curve(t, c);
        curve(t - h, a);
        curve(t + h, b);
        double d1[3], d2[3]; // first and second derivatives, by central differences
        for (int k = 0; k < 3; ++k) {
            d1[k] = (b[k] - a[k]) / (2 * h);
            d2[k] = (b[k] - 2 * c[k] + a[k]) / (h * h);
        }
        auto normalize = [](double v[3]) {
            const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            for (int k = 0; k < 3; ++k)
                v[k] /= l;
        };
        auto cross = [](const double x[3], const double y[3], double out[3]) {
            out[0] = x[1] * y[2] - x[2] * y[1];
            out[1] = x[2] * y[0] - x[0] * y[2];
            out[2] = x[0] * y[1] - x[1] * y[0];
        };
        double T[3] = {d1[0], d1[1], d1[2]}, B[3], N[3];
        normalize(T);
        cross(d1, d2, B);
        normalize(B);
        cross(B, T, N);
        for (int j = 0; j < kSides; ++j) {
            const double phi = 2.0 * pi * j / kSides;
            for (int k = 0; k < 3; ++k) {
                const double n = std::cos(phi) * N[k] + std::sin(phi) * B[k];
                const float p = grid(c[k] + kTube * n);
                positions.push_back(p);
                normals.push_back(grid(n));
                lo[k] = std::min(lo[k], p);
                hi[k] = std::max(hi[k], p);
            }
        }
    }
    std::vector<std::uint16_t> indices;
    for (int i = 0; i < kAround; ++i)
        for (int j = 0; j < kSides; ++j) {
            auto v = [&](int a, int s) {
                return std::uint16_t(((a % kAround) * kSides) + (s % kSides));
            };
            const std::uint16_t a = v(i, j), b = v(i + 1, j), c = v(i + 1, j + 1), d = v(i, j + 1);
            indices.insert(indices.end(), {a, b, c, a, c, d});
        }

    const std::size_t posBytes = positions.size() * 4, norBytes = normals.size() * 4,
                      idxBytes = indices.size() * 2;
    std::vector<std::uint8_t> bin(posBytes + norBytes + idxBytes);
    std::memcpy(bin.data(), positions.data(), posBytes);
    std::memcpy(bin.data() + posBytes, normals.data(), norBytes);
    std::memcpy(bin.data() + posBytes + norBytes, indices.data(), idxBytes);
    while (bin.size() % 4)
        bin.push_back(0);

    auto num = [](float v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.9g", double(v));
        return std::string(buf);
    };
    const std::size_t vertices = positions.size() / 3;
    std::string json =
        "{\"asset\":{\"version\":\"2.0\",\"generator\":\"volsg examples/gltf/MakeExampleMesh\"},"
        "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"name\":\"knot\",\"mesh\":0}],"
        "\"meshes\":[{\"name\":\"torus knot\",\"primitives\":[{\"attributes\":{\"POSITION\":0,"
        "\"NORMAL\":1},\"indices\":2,\"material\":0}]}],"
        "\"materials\":[{\"name\":\"orange plastic\",\"pbrMetallicRoughness\":{"
        "\"baseColorFactor\":[0.9,0.45,0.12,1.0],\"metallicFactor\":0.0,\"roughnessFactor\":0.4}}],"
        "\"buffers\":[{\"byteLength\":" +
        std::to_string(bin.size()) +
        "}],\"bufferViews\":["
        "{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" +
        std::to_string(posBytes) +
        ",\"target\":34962},{\"buffer\":0,\"byteOffset\":" + std::to_string(posBytes) +
        ",\"byteLength\":" + std::to_string(norBytes) +
        ",\"target\":34962},{\"buffer\":0,\"byteOffset\":" + std::to_string(posBytes + norBytes) +
        ",\"byteLength\":" + std::to_string(idxBytes) +
        ",\"target\":34963}],\"accessors\":["
        "{\"bufferView\":0,\"componentType\":5126,\"count\":" +
        std::to_string(vertices) + ",\"type\":\"VEC3\",\"min\":[" + num(lo[0]) + "," + num(lo[1]) +
        "," + num(lo[2]) + "],\"max\":[" + num(hi[0]) + "," + num(hi[1]) + "," + num(hi[2]) +
        "]},{\"bufferView\":1,\"componentType\":5126,\"count\":" + std::to_string(vertices) +
        ",\"type\":\"VEC3\"},{\"bufferView\":2,\"componentType\":5123,\"count\":" +
        std::to_string(indices.size()) + ",\"type\":\"SCALAR\"}]}";
    return packGlb(std::move(json), std::move(bin));
}

} // namespace volsg::example
