// The two-level row composite: every level against the definition written out plainly here, bit
// for bit, on random rows holding runs of DVR, MIP and Surface objects, with both inter-object
// modes, opaque geometry, and the flush that merges the runs.
#include <doctest/doctest.h>

#include <volsg/shearwarp/TwoLevelComposite.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

using namespace volsg;

namespace {

/// One row's two-level buffers: what the kernel changes.
struct RowState {
    std::vector<glm::vec4> global, local;
    std::vector<float> localValue, localDepth, hitDepth, pickSlice;
    std::vector<std::int16_t> localObject, pickObject;

    TwoLevelRow row(const TwoLevelObject* objects, const float* limit, InterObjectCompositing inter,
                    std::int16_t object) {
        return TwoLevelRow{global.data(),
                           local.data(),
                           localValue.data(),
                           localDepth.data(),
                           localObject.data(),
                           hitDepth.data(),
                           pickObject.data(),
                           pickSlice.data(),
                           limit,
                           objects,
                           inter,
                           object,
                           17.0f,
                           0.25f,
                           0.6f,
                           0.375,
                           -0.01,
                           0.125};
    }
    bool operator==(const RowState& o) const {
        auto same = [](const auto& a, const auto& b) {
            return a.size() == b.size() &&
                   std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
        };
        return same(global, o.global) && same(local, o.local) && same(localValue, o.localValue) &&
               same(localDepth, o.localDepth) && same(hitDepth, o.hitDepth) &&
               same(pickSlice, o.pickSlice) && localObject == o.localObject &&
               pickObject == o.pickObject;
    }
};

glm::vec4 randomPremultiplied(std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const float pick = unit(rng);
    const float alpha = pick < 0.2f ? 0.0f : pick < 0.4f ? 0.03f * unit(rng) : unit(rng);
    return glm::vec4(unit(rng) * alpha, unit(rng) * alpha, unit(rng) * alpha, alpha);
}

RowState randomRow(std::mt19937& rng, int width, int objects) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    RowState s;
    for (int c = 0; c < width; ++c) {
        s.global.push_back(randomPremultiplied(rng));
        const int object = int(rng() % std::uint32_t(objects + 1)) - 1; // -1: no run
        s.localObject.push_back(std::int16_t(object));
        s.local.push_back(object < 0 ? glm::vec4(0.0f) : randomPremultiplied(rng));
        s.localValue.push_back(object < 0 || unit(rng) < 0.3f ? -1.0f : unit(rng));
        s.localDepth.push_back(object < 0 || unit(rng) < 0.3f ? 1.0f : unit(rng));
        s.hitDepth.push_back(unit(rng) < 0.5f ? 1.0f : unit(rng));
        s.pickObject.push_back(unit(rng) < 0.5f ? std::int16_t(-1) : std::int16_t(rng() % 3));
        s.pickSlice.push_back(unit(rng) < 0.5f ? 0.0f : 40.0f);
    }
    return s;
}

/// The MIP table at v in [0, 1], linear between its 4096 entries.
glm::vec4 tableAt(const glm::vec4* table, float value) {
    const float x = std::clamp(value, 0.0f, 1.0f) * 4095.0f;
    const int i = std::min(int(x), 4094);
    const float f = x - float(i);
    return table[i] * (1.0f - f) + table[i + 1] * f;
}

/// The definition of the flush (TwoLevelComposite.h), pixel c.
void flushByDefinition(RowState& s, const TwoLevelRow& r, std::size_t c) {
    const int oi = s.localObject[c];
    if (oi < 0) return;
    const TwoLevelObject& o = r.objects[oi];
    glm::vec4 layer = s.local[c];
    if (o.compositing == ObjectCompositing::MIP)
        layer = s.localValue[c] >= 0.0f ? tableAt(o.mipTable, s.localValue[c]) : glm::vec4(0.0f);
    if (o.compositing == ObjectCompositing::Surface && layer.a >= 0.5f) {
        layer = glm::vec4(glm::vec3(layer) / layer.a, 1.0f);
        if (s.localDepth[c] < 1.0f) s.hitDepth[c] = s.localDepth[c];
    }
    s.global[c] = r.inter == InterObjectCompositing::DVR ? layer + (1.0f - layer.a) * s.global[c]
                                                         : glm::max(s.global[c], layer);
    s.localObject[c] = -1;
    s.local[c] = glm::vec4(0.0f);
    s.localValue[c] = -1.0f;
    s.localDepth[c] = 1.0f;
}

/// The definition of the composite (TwoLevelComposite.h), one pixel at a time with glm.
void compositeByDefinition(RowState& s, const TwoLevelRow& r, const glm::vec4* a, float wa,
                           const glm::vec4* b, float wb, int lo, int hi) {
    for (int c = lo; c < hi; ++c) {
        const std::size_t p = std::size_t(c);
        const glm::vec4 sample = a && b ? wa * a[c] + wb * b[c] : a ? wa * a[c] : wb * b[c];
        if (sample.a <= 0.0f) continue;
        if (r.limit && !(r.zSlice > r.limit[c])) continue;
        if (s.localObject[p] != r.object) {
            flushByDefinition(s, r, p);
            s.localObject[p] = r.object;
        }
        const TwoLevelObject& o = r.objects[r.object];
        bool picked = false;
        if (o.compositing == ObjectCompositing::MIP) {
            if (sample.r > s.localValue[p]) {
                s.localValue[p] = sample.r;
                picked = tableAt(o.mipTable, sample.r).a >= TwoLevelComposite::kPickAlpha;
            }
        } else {
            s.local[p] = sample + (1.0f - sample.a) * s.local[p];
            picked = sample.a >= TwoLevelComposite::kPickAlpha;
            if (o.compositing == ObjectCompositing::Surface &&
                sample.a >= TwoLevelComposite::kSurfaceDepthAlpha)
                s.localDepth[p] = r.sliceDepth + float(r.depthScale * (r.zu * c + r.zvRow));
        }
        if (picked) {
            s.pickObject[p] = r.object;
            s.pickSlice[p] = r.slice;
        }
    }
}

} // namespace

TEST_CASE("every two-level composite level gives the definition's buffers bit for bit") {
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    // Objects 0 DVR, 1 MIP, 2 Surface, 3 MIP (a table with a transparent low end).
    std::vector<glm::vec4> tableA(4096), tableB(4096);
    for (glm::vec4& t : tableA)
        t = randomPremultiplied(rng);
    for (int i = 0; i < 4096; ++i)
        tableB[std::size_t(i)] = i < 1500 ? glm::vec4(0.0f) : randomPremultiplied(rng);
    const TwoLevelObject objects[] = {{ObjectCompositing::DVR, nullptr},
                                      {ObjectCompositing::MIP, tableA.data()},
                                      {ObjectCompositing::Surface, nullptr},
                                      {ObjectCompositing::MIP, tableB.data()}};
    int rows = 0;
    for (int width : {1, 2, 7, 64, 201})
        for (int object = 0; object < 4; ++object)
            for (int inter = 0; inter < 2; ++inter)
                for (int lines = 1; lines <= 3; ++lines)
                    for (int withLimit = 0; withLimit < 2; ++withLimit)
                        for (int trial = 0; trial < 6; ++trial) {
                            std::vector<glm::vec4> a(std::size_t(width) + 1), b(a.size());
                            for (std::size_t c = 0; c < a.size(); ++c) {
                                a[c] = randomPremultiplied(rng);
                                b[c] = randomPremultiplied(rng);
                                if (object % 2 == 1 && unit(rng) < 0.7f) // MIP: value, 0, 0, 1
                                    a[c] = glm::vec4(unit(rng), 0.0f, 0.0f, 1.0f),
                                    b[c] = glm::vec4(unit(rng), 0.0f, 0.0f, 1.0f);
                            }
                            std::uniform_int_distribution<int> column(0, width);
                            int lo = column(rng), hi = column(rng);
                            if (lo > hi) std::swap(lo, hi);
                            if (trial == 0) lo = 0, hi = width;
                            const float wa = trial == 1 ? 1.0f : unit(rng), wb = 1.0f - wa;
                            std::vector<float> limit(static_cast<std::size_t>(width));
                            for (float& l : limit)
                                l = unit(rng) - 0.5f; // a sample counts where 0.25 > limit
                            const glm::vec4* pa = lines & 1 ? a.data() : nullptr;
                            const glm::vec4* pb = lines & 2 ? b.data() : nullptr;
                            const float* lim = withLimit ? limit.data() : nullptr;
                            const auto mode = InterObjectCompositing(inter);

                            const RowState start = randomRow(rng, width, 4);
                            RowState expected = start;
                            RowState forDefinition = start;
                            compositeByDefinition(
                                expected,
                                forDefinition.row(objects, lim, mode, std::int16_t(object)), pa, wa,
                                pb, wb, lo, hi);
                            for (SimdLevel level : {SimdLevel::Scalar, SimdLevel::Avx2}) {
                                RowState got = start;
                                TwoLevelComposite::composite(
                                    level, got.row(objects, lim, mode, std::int16_t(object)), pa,
                                    wa, pb, wb, lo, hi);
                                INFO("level ", int(level), ", width ", width, ", object ", object,
                                     ", inter ", inter, ", lines ", lines, ", limit ", withLimit,
                                     ", columns [", lo, ", ", hi, ")");
                                CHECK(got == expected);
                            }
                            // The flush of the whole row after it.
                            RowState flushed = expected;
                            const TwoLevelRow r =
                                flushed.row(objects, nullptr, mode, std::int16_t(object));
                            TwoLevelComposite::flush(r, 0, width);
                            for (std::size_t c = 0; c < std::size_t(width); ++c)
                                flushByDefinition(expected, r, c);
                            CHECK(flushed == expected);
                            ++rows;
                        }
    MESSAGE(rows, " rows");
}

TEST_CASE("a Surface run is drawn opaque at its flush, a MIP run at its maximum") {
    std::vector<glm::vec4> table(4096, glm::vec4(0.0f));
    for (int i = 2048; i < 4096; ++i)
        table[std::size_t(i)] = glm::vec4(0.5f, 0.25f, 0.0f, 0.5f);
    const TwoLevelObject objects[] = {{ObjectCompositing::Surface, nullptr},
                                      {ObjectCompositing::MIP, table.data()}};
    RowState s;
    s.global.assign(2, glm::vec4(0.0f));
    s.local.assign(2, glm::vec4(0.0f));
    s.localValue.assign(2, -1.0f);
    s.localDepth.assign(2, 1.0f);
    s.hitDepth.assign(2, 1.0f);
    s.pickSlice.assign(2, 0.0f);
    s.localObject.assign(2, -1);
    s.pickObject.assign(2, -1);
    // Pixel 0: a Surface sample of alpha 0.6 (dense: its depth is kept), then a MIP sample
    // flushes it; pixel 1: MIP samples 0.3 then 0.7.
    const std::vector<glm::vec4> surface{glm::vec4(0.3f, 0.0f, 0.0f, 0.6f), glm::vec4(0.0f)};
    const std::vector<glm::vec4> low{glm::vec4(0.0f), glm::vec4(0.3f, 0.0f, 0.0f, 1.0f)};
    const std::vector<glm::vec4> high{glm::vec4(0.7f, 0.0f, 0.0f, 1.0f),
                                      glm::vec4(0.7f, 0.0f, 0.0f, 1.0f)};
    const auto dvr = InterObjectCompositing::DVR;
    TwoLevelComposite::composite(SimdLevel::Scalar, s.row(objects, nullptr, dvr, 0), surface.data(),
                                 1.0f, nullptr, 0.0f, 0, 2);
    CHECK(s.localObject[0] == 0);
    const float depth = s.localDepth[0];
    CHECK(depth == 0.6f + float(0.375 * (-0.01 * 0 + 0.125))); // sliceDepth 0.6
    TwoLevelComposite::composite(SimdLevel::Scalar, s.row(objects, nullptr, dvr, 1), low.data(),
                                 1.0f, nullptr, 0.0f, 0, 2);
    TwoLevelComposite::composite(SimdLevel::Scalar, s.row(objects, nullptr, dvr, 1), high.data(),
                                 1.0f, nullptr, 0.0f, 0, 2);
    CHECK(s.global[0] == glm::vec4(0.5f, 0.0f, 0.0f, 1.0f)); // colour / alpha, opaque
    CHECK(s.hitDepth[0] == depth);
    CHECK(s.localValue[1] == 0.7f);
    CHECK(s.pickObject[1] == 1); // 0.7 is shown (table alpha 0.5), 0.3 was not
    TwoLevelComposite::flush(s.row(objects, nullptr, dvr, 1), 0, 2);
    CHECK(s.global[1] == glm::vec4(0.5f, 0.25f, 0.0f, 0.5f));
    CHECK(s.global[0].a == 1.0f); // pixel 0's MIP run (0.7) went over the opaque Surface
    CHECK(s.localObject == std::vector<std::int16_t>{-1, -1});
}
