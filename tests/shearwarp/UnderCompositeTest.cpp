// The pure DVR row composite: every kernel (scalar, AVX2 where the CPU has it) against the
// definition written out plainly here, bit for bit, on rows with opaque pixels, empty samples,
// picks due and taken, odd lengths and ranges, and opaque geometry.
#include <doctest/doctest.h>

#include <volsg/shearwarp/UnderComposite.h>

#include <cstring>
#include <random>
#include <vector>

using namespace volsg;

namespace {

/// One row's state: what a kernel changes.
struct RowState {
    std::vector<glm::vec4> pixels;
    std::vector<std::int16_t> pickObject;
    std::vector<float> pickSlice;
    std::vector<std::int32_t> open;
    int opaqueCount = 0;

    UnderRow row(const float* limit) {
        return UnderRow{pixels.data(), pickObject.data(), pickSlice.data(), open.data(),
                        limit,         &opaqueCount,      std::int16_t(7),  12.0f,
                        0.5f};
    }
    bool operator==(const RowState& o) const {
        return pixels.size() == o.pixels.size() &&
               std::memcmp(pixels.data(), o.pixels.data(), pixels.size() * sizeof(glm::vec4)) ==
                   0 &&
               pickObject == o.pickObject &&
               std::memcmp(pickSlice.data(), o.pickSlice.data(), pickSlice.size() * 4) == 0 &&
               open == o.open && opaqueCount == o.opaqueCount;
    }
};

/// The definition (UnderComposite.h), one pixel at a time with glm.
void compositeByDefinition(RowState& s, const glm::vec4* a, float wa, const glm::vec4* b, float wb,
                           int lo, int hi, const float* limit) {
    for (int c = lo; c < hi; ++c) {
        glm::vec4 sample(0.0f);
        if (a && b)
            sample = wa * a[c] + wb * b[c];
        else if (a)
            sample = wa * a[c];
        else
            sample = wb * b[c];
        const float alpha = s.pixels[std::size_t(c)].w;
        if (alpha >= UnderComposite::kOpaque) {
            if (s.open[std::size_t(c)] == c) {
                s.open[std::size_t(c)] = c + 1;
                ++s.opaqueCount;
            }
            continue;
        }
        if (sample.w <= 0.0f) continue;
        if (limit && !(0.5f > limit[c])) continue;
        s.pixels[std::size_t(c)] = s.pixels[std::size_t(c)] + (1.0f - alpha) * sample;
        if (sample.w >= UnderComposite::kPickAlpha && s.pickObject[std::size_t(c)] < 0) {
            s.pickObject[std::size_t(c)] = 7;
            s.pickSlice[std::size_t(c)] = 12.0f;
        }
    }
}

/// A premultiplied line: colour * alpha with alpha 0 (and so colour 0) for about one voxel in
/// five, small alphas, near-1 alphas.
std::vector<glm::vec4> randomLine(std::mt19937& rng, int width) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<glm::vec4> line(std::size_t(width) + 1);
    for (glm::vec4& p : line) {
        const float pick = unit(rng);
        const float alpha = pick < 0.2f ? 0.0f : pick < 0.5f ? 0.03f * unit(rng) : unit(rng);
        p = glm::vec4(unit(rng) * alpha, unit(rng) * alpha, unit(rng) * alpha, alpha);
    }
    return line;
}

RowState randomRow(std::mt19937& rng, int width) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    RowState s;
    for (int c = 0; c < width; ++c) {
        const float pick = unit(rng);
        // Open, partly covered, just below and at or above the opaque threshold.
        const float alpha = pick < 0.3f   ? 0.0f
                            : pick < 0.6f ? unit(rng)
                            : pick < 0.8f ? 0.9989f
                                          : 0.999f + 0.001f * unit(rng);
        s.pixels.emplace_back(unit(rng) * alpha, unit(rng) * alpha, unit(rng) * alpha, alpha);
        s.pickObject.push_back(unit(rng) < 0.5f ? std::int16_t(-1) : std::int16_t(3));
        s.pickSlice.push_back(unit(rng) < 0.5f ? 0.0f : 40.0f);
        // Opaque pixels met before are linked already, the others not yet.
        s.open.push_back(alpha >= UnderComposite::kOpaque && unit(rng) < 0.5f ? c + 1 : c);
    }
    s.opaqueCount = 5;
    return s;
}

} // namespace

TEST_CASE("every row composite kernel gives the definition's pixels bit for bit") {
    std::vector<SimdLevel> levels{SimdLevel::Scalar};
    if (simdLevelAvailable(SimdLevel::Avx2))
        levels.push_back(SimdLevel::Avx2);
    else
        MESSAGE("this CPU has no AVX2: the scalar kernel only");
    std::mt19937 rng(20261125);
    int rows = 0;
    for (int width : {1, 2, 3, 4, 5, 8, 17, 64, 301})
        for (int lines = 1; lines <= 3; ++lines) // a only, b only, both
            for (int withLimit = 0; withLimit < 2; ++withLimit)
                for (int trial = 0; trial < 12; ++trial) {
                    const std::vector<glm::vec4> a = randomLine(rng, width);
                    const std::vector<glm::vec4> b = randomLine(rng, width);
                    std::uniform_int_distribution<int> column(0, width);
                    int lo = column(rng), hi = column(rng);
                    if (lo > hi) std::swap(lo, hi);
                    if (trial == 0) lo = 0, hi = width;
                    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
                    const float wa = trial == 1 ? 1.0f : unit(rng), wb = 1.0f - wa;
                    std::vector<float> limit(static_cast<std::size_t>(width));
                    for (float& l : limit)
                        l = unit(rng) - 0.25f; // a sample counts where 0.5 > limit
                    const float* lim = withLimit ? limit.data() : nullptr;
                    const glm::vec4* pa = lines & 1 ? a.data() : nullptr;
                    const glm::vec4* pb = lines & 2 ? b.data() : nullptr;

                    const RowState start = randomRow(rng, width);
                    RowState expected = start;
                    compositeByDefinition(expected, pa, wa, pb, wb, lo, hi, lim);
                    for (SimdLevel level : levels) {
                        RowState got = start;
                        UnderComposite::composite(level, got.row(lim), pa, wa, pb, wb, lo, hi);
                        INFO("level ", int(level), ", width ", width, ", columns [", lo, ", ", hi,
                             "), lines ", lines, ", limit ", withLimit);
                        CHECK(got == expected);
                    }
                    ++rows;
                }
    MESSAGE(rows, " rows, ", levels.size(), " levels");
}

TEST_CASE("the row composite stops at the opaque threshold and records the first heavy sample") {
    // Three pixels: open, just below kOpaque, at it. Two samples of alpha 0.5 arrive.
    for (SimdLevel level : {SimdLevel::Scalar, SimdLevel::Avx2}) {
        if (!simdLevelAvailable(level)) continue;
        RowState s;
        s.pixels = {glm::vec4(0.0f), glm::vec4(0.0f, 0.0f, 0.0f, 0.9985f),
                    glm::vec4(0.0f, 0.0f, 0.0f, 0.999f), glm::vec4(0.0f)};
        s.pickObject.assign(4, -1);
        s.pickSlice.assign(4, 0.0f);
        s.open = {0, 1, 2, 3};
        const std::vector<glm::vec4> line(4, glm::vec4(0.5f, 0.25f, 0.0f, 0.5f));
        UnderComposite::composite(level, s.row(nullptr), line.data(), 1.0f, nullptr, 0.0f, 0, 3);
        CHECK(s.pixels[0] == glm::vec4(0.5f, 0.25f, 0.0f, 0.5f));
        CHECK(s.pixels[1].w == doctest::Approx(0.9985f + 0.0015f * 0.5f).epsilon(1e-6));
        CHECK(s.pixels[2].w == 0.999f); // terminated: takes nothing
        CHECK(s.open == std::vector<std::int32_t>{0, 1, 3, 3});
        CHECK(s.opaqueCount == 1);
        CHECK(s.pickObject == std::vector<std::int16_t>{7, 7, -1, -1});
        CHECK(s.pixels[3] == glm::vec4(0.0f)); // outside [lo, hi)
        // A second slice: pixel 0 keeps its first pick; pixel 1 became opaque with the first
        // and is linked now, unchanged.
        s.pickSlice[0] = 3.0f;
        const glm::vec4 stopped = s.pixels[1];
        CHECK(stopped.w >= UnderComposite::kOpaque);
        UnderComposite::composite(level, s.row(nullptr), line.data(), 1.0f, nullptr, 0.0f, 0, 3);
        CHECK(s.pickSlice[0] == 3.0f);
        CHECK(s.pixels[0].w == 0.75f);
        CHECK(s.pixels[1] == stopped);
        CHECK(s.open == std::vector<std::int32_t>{0, 2, 3, 3});
        CHECK(s.opaqueCount == 2);
    }
}

TEST_CASE("the composite of written columns visits the runs the marks cover, bit for bit") {
    std::vector<SimdLevel> levels{SimdLevel::Scalar};
    if (simdLevelAvailable(SimdLevel::Avx2)) levels.push_back(SimdLevel::Avx2);
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int rows = 0;
    for (int width : {1, 3, 63, 64, 65, 130, 301})
        for (int lines = 1; lines <= 3; ++lines)
            for (int trial = 0; trial < 16; ++trial) {
                // Lines as a splat leaves them: marked left columns, each covering itself and
                // the next column; zero outside what the marks cover.
                std::vector<glm::vec4> line[2];
                std::vector<std::uint64_t> mask[2];
                std::vector<bool> covered(std::size_t(width) + 1, false);
                const float density = trial % 4 == 0 ? 0.9f : trial % 4 == 1 ? 0.02f : unit(rng);
                for (int l = 0; l < 2; ++l) {
                    const std::vector<glm::vec4> random = randomLine(rng, width);
                    line[l].assign(std::size_t(width) + 1, glm::vec4(0.0f));
                    mask[l].assign(std::size_t(width) / 64 + 3, 0);
                    if (!(lines & (1 << l))) continue;
                    for (int c = 0; c + 1 <= width; ++c)
                        if (unit(rng) < density) {
                            mask[l][std::size_t(c >> 6) + 1] |= 1ull << (c & 63);
                            for (int d : {c, c + 1}) {
                                line[l][std::size_t(d)] = random[std::size_t(d)];
                                covered[std::size_t(d)] = true;
                            }
                        }
                }
                std::uniform_int_distribution<int> column(0, width);
                int lo = column(rng), hi = column(rng);
                if (lo > hi) std::swap(lo, hi);
                if (trial % 3 == 0) lo = 0, hi = width;
                const float wa = unit(rng), wb = 1.0f - wa;
                const glm::vec4* pa = lines & 1 ? line[0].data() : nullptr;
                const glm::vec4* pb = lines & 2 ? line[1].data() : nullptr;

                // The definition on the covered columns of [lo, hi) only.
                const RowState start = randomRow(rng, width);
                RowState expected = start;
                for (int c = lo; c < hi; ++c)
                    if (covered[std::size_t(c)])
                        compositeByDefinition(expected, pa, wa, pb, wb, c, c + 1, nullptr);
                for (SimdLevel level : levels) {
                    RowState got = start;
                    UnderComposite::compositeWritten(level, got.row(nullptr), pa, wa,
                                                     mask[0].data() + 1, pb, wb, mask[1].data() + 1,
                                                     lo, hi);
                    INFO("level ", int(level), ", width ", width, ", columns [", lo, ", ", hi,
                         "), lines ", lines, ", trial ", trial);
                    CHECK(got == expected);
                    // The full composite gives the same pixels and picks (only links differ).
                    RowState full = start;
                    UnderComposite::composite(level, full.row(nullptr), pa, wa, pb, wb, lo, hi);
                    CHECK(std::memcmp(full.pixels.data(), got.pixels.data(),
                                      full.pixels.size() * sizeof(glm::vec4)) == 0);
                    CHECK(full.pickObject == got.pickObject);
                }
                ++rows;
            }
    MESSAGE(rows, " rows");
}
