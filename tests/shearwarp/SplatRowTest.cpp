// The voxel-row splat: every kernel level (scalar; AVX2 where the CPU has it) against the
// definition written out plainly here, bit for bit, on random rows of every lookup kind, fresh
// and accumulating lines, face voxels, and early ray termination with random opaque-pixel links.
#include <doctest/doctest.h>

#include <volsg/shearwarp/PackedVoxel.h>
#include <volsg/shearwarp/SplatRow.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using namespace volsg;

namespace {

constexpr int kNone = std::numeric_limits<int>::max();

/// Opaque-pixel links of one intermediate row: open[c] == c while pixel c is open, else a later
/// column c' with every pixel in [c, c') stopped (c' <= width).
std::vector<std::int32_t> randomLinks(std::mt19937& rng, int width, float stoppedShare) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<bool> stopped(static_cast<std::size_t>(width));
    bool run = false;
    for (int c = 0; c < width; ++c) { // runs of stopped pixels, as rays saturate in patches
        if (unit(rng) < 0.15f) run = unit(rng) < stoppedShare;
        stopped[std::size_t(c)] = run;
    }
    std::vector<std::int32_t> open(static_cast<std::size_t>(width));
    for (int c = width - 1; c >= 0; --c) {
        if (!stopped[std::size_t(c)]) {
            open[std::size_t(c)] = c;
            continue;
        }
        int end = c + 1; // the first open pixel after c, or width
        while (end < width && stopped[std::size_t(end)])
            ++end;
        std::uniform_int_distribution<int> target(c + 1, end);
        open[std::size_t(c)] = target(rng);
    }
    return open;
}

bool isOpen(const std::vector<std::int32_t>* open, int c) {
    return open && (*open)[std::size_t(c)] == c;
}

/// The first open column >= c (width: none; no row: width + 1), by a plain scan.
int firstOpenByScan(const std::vector<std::int32_t>* open, int c, int width) {
    if (!open) return width + 1;
    while (c < width && !isOpen(open, c))
        ++c;
    return c;
}

/// Links still valid: an open pixel links to itself, a stopped one past stopped pixels only.
bool linksValid(const std::vector<std::int32_t>& open, int width) {
    for (int c = 0; c < width; ++c) {
        const int next = open[std::size_t(c)];
        if (next == c) continue;
        if (next <= c || next > width) return false;
        for (int d = c; d < next; ++d)
            if (open[std::size_t(d)] == d) return false;
    }
    return true;
}

bool sameOpenPixels(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
    for (std::size_t c = 0; c < a.size(); ++c)
        if ((a[c] == int(c)) != (b[c] == int(c))) return false;
    return true;
}

struct Tables {
    std::vector<glm::vec4> rgba; // 65536 premultiplied entries, a fifth transparent
    std::vector<std::uint8_t> lut2;
};

Tables randomTables(std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Tables t;
    t.rgba.resize(65536);
    for (glm::vec4& p : t.rgba) {
        const float alpha = unit(rng) < 0.2f ? 0.0f : unit(rng);
        p = glm::vec4(unit(rng) * alpha, unit(rng) * alpha, unit(rng) * alpha, alpha);
    }
    t.lut2.resize(4096);
    for (std::uint8_t& i : t.lut2)
        i = std::uint8_t(rng() & 0xFF);
    return t;
}

/// The definition (SplatRow.h), one voxel at a time with glm: hidden voxels left out (before
/// their colour is looked up), the colour from the lookup, transparent voxels left out, (1 - fu) C
/// and fu C (face weights on the outer columns) added to the line, the left column marked.
void splatByDefinition(const SplatRow& r, std::vector<glm::vec4>& line, int& lo, int& hi,
                       std::vector<bool>& marked, int& voxels, SplatSkip& skip,
                       const std::vector<std::int32_t>* openA,
                       const std::vector<std::int32_t>* openB) {
    for (std::uint32_t i = r.begin; i < r.end; ++i) {
        const std::uint32_t v = r.packed[i];
        const unsigned a = PackedVoxel::a(v);
        const int col = int(a) + r.colBase;
        if (r.skipHidden) {
            if (col < skip.hiddenBefore) {
                ++skip.hidden;
                continue;
            }
            if (col > skip.visibleThrough) {
                const bool anyOpen = isOpen(openA, col) || isOpen(openA, col + 1) ||
                                     isOpen(openB, col) || isOpen(openB, col + 1);
                if (!anyOpen) {
                    ++skip.hidden;
                    skip.hiddenBefore = std::min(firstOpenByScan(openA, col, r.width),
                                                 firstOpenByScan(openB, col, r.width)) -
                                        1;
                    continue;
                }
                skip.visibleThrough = col;
            }
        }
        glm::vec4 colour(0.0f);
        switch (r.lookup) {
        case SplatLookup::MipValue:
            colour = glm::vec4(float(r.values[i]) * (1.0f / 4095.0f), 0.0f, 0.0f, 1.0f);
            break;
        case SplatLookup::Direct:
            colour = r.rgba[PackedVoxel::attributes16(v) & r.mask];
            break;
        case SplatLookup::TwoStage:
            colour = r.rgba[PackedVoxel::second4(v) * 256 + r.lut2[PackedVoxel::main12(v)]];
            break;
        }
        if ((!r.fresh || r.skipHidden) && colour.a <= 0.0f) continue;
        const float w0 = a == r.edgeA0 ? (r.fu <= 0.5f ? 1.0f : 0.0f) : 1.0f - r.fu;
        const float w1 = a == r.edgeA1 ? (r.fu >= 0.5f ? 1.0f : 0.0f) : r.fu;
        line[std::size_t(col)] = line[std::size_t(col)] + w0 * colour;
        line[std::size_t(col) + 1] = line[std::size_t(col) + 1] + w1 * colour;
        lo = std::min(lo, col);
        hi = std::max(hi, col + 2);
        marked[std::size_t(col)] = true;
        ++voxels;
    }
}

/// The columns whose bits are set in a mask of `words` words.
std::vector<bool> markedColumns(const std::vector<std::uint64_t>& mask, int width) {
    std::vector<bool> marked(std::size_t(width) + 1, false);
    for (int c = 0; c <= width; ++c)
        marked[std::size_t(c)] = (mask[std::size_t(c >> 6) + 1] >> (c & 63)) & 1u;
    return marked;
}

bool sameBits(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec4)) == 0;
}

} // namespace

TEST_CASE("every row splat kernel gives the definition's line bit for bit") {
    std::vector<SimdLevel> levels{SimdLevel::Scalar};
    if (simdLevelAvailable(SimdLevel::Avx2))
        levels.push_back(SimdLevel::Avx2);
    else
        MESSAGE("this CPU has no AVX2: the scalar kernel only");
    std::mt19937 rng(20261126);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const Tables tables = randomTables(rng);
    int rows = 0;
    for (int width : {4, 5, 9, 40, 131, 300})
        for (int lookup = 0; lookup < 3; ++lookup)
            for (int fresh = 0; fresh < 2; ++fresh)
                for (int skipHidden = 0; skipHidden < 2; ++skipHidden)
                    for (int trial = 0; trial < 10; ++trial) {
                        // The row: voxels of b = 7 at increasing a, dense or sparse, between
                        // voxels of other rows that must not be read.
                        const int colBase = int(rng() % 3);
                        const int lastA = std::min(255, width - 3 - colBase);
                        const float density = trial % 3 == 0 ? 0.95f : unit(rng);
                        std::vector<std::uint32_t> packed;
                        for (int i = int(rng() % 4); i > 0; --i)
                            packed.push_back(PackedVoxel::pack(rng() & 0xFF, 6, rng(), rng()));
                        const auto begin = std::uint32_t(packed.size());
                        for (int a = 0; a <= lastA; ++a)
                            if (unit(rng) < density)
                                packed.push_back(
                                    PackedVoxel::pack(unsigned(a), 7, rng() & 0xFFF, rng() & 0xF));
                        const auto end = std::uint32_t(packed.size());
                        for (int i = int(rng() % 4); i > 0; --i)
                            packed.push_back(PackedVoxel::pack(rng() & 0xFF, 8, rng(), rng()));
                        std::vector<std::uint16_t> values(packed.size());
                        for (std::uint16_t& v : values)
                            v = std::uint16_t(rng() & 0xFFF);

                        SplatRow row{};
                        row.packed = packed.data();
                        row.values = values.data();
                        row.rgba = tables.rgba.data();
                        row.lut2 = tables.lut2.data();
                        row.mask = trial % 2 ? 0xFFFu : 0xFFFFu;
                        row.begin = begin;
                        row.end = end;
                        row.lookup = SplatLookup(lookup);
                        row.fresh = fresh != 0;
                        row.colBase = colBase;
                        const float fus[] = {0.0f, 0.5f, 1.0f, unit(rng), unit(rng)};
                        row.fu = fus[trial % 5];
                        row.edgeA0 = trial % 4 < 2 ? 0u : 256u;
                        row.edgeA1 = trial % 3 == 0 ? unsigned(lastA) : 256u;
                        row.skipHidden = skipHidden != 0;
                        row.width = width;

                        // Links: rows with no, some or mostly stopped pixels, or outside.
                        const float stoppedShare = float(trial % 4) / 3.0f;
                        std::vector<std::int32_t> linksA = randomLinks(rng, width, stoppedShare);
                        std::vector<std::int32_t> linksB = randomLinks(rng, width, stoppedShare);
                        const bool hasA = trial % 5 != 4, hasB = trial % 7 != 6;

                        std::vector<glm::vec4> startLine(std::size_t(width) + 1, glm::vec4(0.0f));
                        int startLo = kNone, startHi = 0;
                        if (!fresh) { // part 0's shares already there
                            for (glm::vec4& p : startLine)
                                if (unit(rng) < 0.5f)
                                    p = glm::vec4(unit(rng), unit(rng), 0.0f, unit(rng));
                            startLo = int(rng() % std::uint32_t(width));
                            startHi = startLo + 1;
                        }
                        SplatSkip startSkip;
                        if (!fresh && trial % 2) { // what the row's first part left
                            startSkip.hiddenBefore = int(rng() % std::uint32_t(width));
                            startSkip.visibleThrough = int(rng() % std::uint32_t(width));
                            startSkip.hidden = 3;
                        }

                        // Marks part 0 left (fresh: none); one word before and after.
                        std::vector<std::uint64_t> startMask(std::size_t(width) / 64 + 3, 0);
                        if (!fresh)
                            for (int c = 0; c < width; ++c)
                                if (unit(rng) < 0.3f)
                                    startMask[std::size_t(c >> 6) + 1] |= 1ull << (c & 63);
                        std::vector<glm::vec4> expected = startLine;
                        int expectedLo = startLo, expectedHi = startHi;
                        std::vector<bool> expectedMarks = markedColumns(startMask, width);
                        const int startVoxels = fresh ? 0 : int(rng() % 50);
                        int expectedVoxels = startVoxels;
                        SplatSkip expectedSkip = startSkip;
                        splatByDefinition(row, expected, expectedLo, expectedHi, expectedMarks,
                                          expectedVoxels, expectedSkip,
                                          row.skipHidden && hasA ? &linksA : nullptr,
                                          row.skipHidden && hasB ? &linksB : nullptr);
                        for (SimdLevel level : levels) {
                            std::vector<glm::vec4> got = startLine;
                            std::vector<std::uint64_t> mask = startMask;
                            SplatLine line{got.data(), startLo, startHi, mask.data() + 1,
                                           startVoxels};
                            SplatSkip skip = startSkip;
                            std::vector<std::int32_t> openA = linksA, openB = linksB;
                            row.openA = row.skipHidden && hasA ? openA.data() : nullptr;
                            row.openB = row.skipHidden && hasB ? openB.data() : nullptr;
                            RowSplat::splat(level, row, line, skip);
                            INFO("level ", int(level), ", width ", width, ", lookup ", lookup,
                                 ", fresh ", fresh, ", skipHidden ", skipHidden, ", trial ", trial,
                                 ", voxels ", end - begin);
                            CHECK(sameBits(got, expected));
                            CHECK(line.lo == expectedLo);
                            CHECK(line.hi == expectedHi);
                            CHECK(markedColumns(mask, width) == expectedMarks);
                            CHECK(line.voxels == expectedVoxels);
                            CHECK(mask.front() == 0u); // the word before is only read
                            CHECK(skip.hidden == expectedSkip.hidden);
                            CHECK(skip.hiddenBefore == expectedSkip.hiddenBefore);
                            CHECK(skip.visibleThrough == expectedSkip.visibleThrough);
                            // The links may be shortened, never changed in meaning.
                            CHECK(sameOpenPixels(openA, linksA));
                            CHECK(sameOpenPixels(openB, linksB));
                            CHECK(linksValid(openA, width));
                            CHECK(linksValid(openB, width));
                        }
                        ++rows;
                    }
    MESSAGE(rows, " rows, ", levels.size(), " levels");
}

TEST_CASE("the row splat splits a voxel between two columns and hides covered voxels") {
    // Voxels a = 0, 1, 3 of colour (0.5, 0, 0, 0.5); fu = 0.25; a = 0 on the volume's low face.
    const std::vector<glm::vec4> rgba(4096, glm::vec4(0.5f, 0.0f, 0.0f, 0.5f));
    const std::vector<std::uint32_t> packed{PackedVoxel::pack(0, 0, 1, 0),
                                            PackedVoxel::pack(1, 0, 1, 0),
                                            PackedVoxel::pack(3, 0, 1, 0)};
    SplatRow row{};
    row.packed = packed.data();
    row.rgba = rgba.data();
    row.mask = 0xFFF;
    row.begin = 0;
    row.end = 3;
    row.lookup = SplatLookup::Direct;
    row.fresh = true;
    row.colBase = 2;
    row.fu = 0.25f;
    row.edgeA0 = 0;
    row.edgeA1 = 256;
    row.width = 8;
    for (SimdLevel level : {SimdLevel::Scalar, SimdLevel::Avx2}) {
        if (!simdLevelAvailable(level)) continue;
        std::vector<glm::vec4> pixels(9, glm::vec4(0.0f));
        std::vector<std::uint64_t> mask(3, 0);
        SplatLine line{pixels.data(), kNone, 0, mask.data() + 1};
        SplatSkip skip;
        row.skipHidden = false;
        RowSplat::splat(level, row, line, skip);
        // Column 2: the face voxel's full share (fu <= 0.5); 3: 0.25 of a = 0 and 0.75 of a = 1.
        CHECK(pixels[2] == glm::vec4(0.5f, 0.0f, 0.0f, 0.5f));
        CHECK(pixels[3] == glm::vec4(0.25f, 0.0f, 0.0f, 0.25f) * 0.5f +
                               glm::vec4(0.75f, 0.0f, 0.0f, 0.75f) * 0.5f);
        CHECK(pixels[4].w == 0.125f);
        CHECK(pixels[5].w == 0.375f);
        CHECK(pixels[6].w == 0.125f);
        CHECK(line.lo == 2);
        CHECK(line.hi == 7);
        CHECK(mask[1] == 0b101100u); // the voxels' left columns 2, 3 and 5
        // Columns 2-4 stopped in both rows: a = 0 and 1 are hidden, a = 3 (columns 5, 6) not.
        std::vector<std::int32_t> openA{0, 1, 5, 5, 5, 5, 6, 7}, openB = openA;
        std::fill(pixels.begin(), pixels.end(), glm::vec4(0.0f));
        mask.assign(3, 0);
        line = SplatLine{pixels.data(), kNone, 0, mask.data() + 1};
        row.skipHidden = true;
        row.openA = openA.data();
        row.openB = openB.data();
        RowSplat::splat(level, row, line, skip);
        CHECK(skip.hidden == 2);
        CHECK(skip.hiddenBefore == 4);
        CHECK(line.lo == 5);
        CHECK(line.hi == 7);
        CHECK(mask[1] == 0b100000u); // column 5 alone
        CHECK(pixels[5].w == 0.375f);
    }
}
