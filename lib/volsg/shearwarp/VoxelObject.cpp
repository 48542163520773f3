#include <volsg/shearwarp/VoxelObject.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

#include <volsg/core/Error.h>
#include <volsg/shearwarp/GradientCode.h>
#include <volsg/shearwarp/PackedVoxel.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

namespace {

std::atomic<std::uint64_t> processBuilds{0}; // VoxelObject::processRenderListBuilds

/// Stable counting sort of `order` by key(v) in [0, buckets); returns where each bucket
/// starts in the sorted order (buckets + 1 entries, the last one order.size()).
template <class Key>
std::vector<std::uint32_t> countingSort(std::vector<std::uint32_t>& order, int buckets, Key key) {
    std::vector<std::uint32_t> start(std::size_t(buckets) + 1, 0);
    for (std::uint32_t v : order)
        ++start[std::size_t(key(v)) + 1];
    for (int i = 0; i < buckets; ++i)
        start[std::size_t(i) + 1] += start[std::size_t(i)];
    std::vector<std::uint32_t> at(start.begin(), start.end() - 1);
    std::vector<std::uint32_t> sorted(order.size());
    for (std::uint32_t v : order)
        sorted[at[std::size_t(key(v))]++] = v;
    order.swap(sorted);
    return start;
}

/// Normalised value v of every voxel, and whether alpha(v) > 0; integer types go through a
/// table over their raw values so the scan does no piecewise-linear search per voxel.
struct Classifier {
    const VolumeGrid& grid;
    const TransferFunction1D& tf;
    double lo, hi;
    std::vector<float> table;          // raw value -> v (integer types)
    std::vector<std::uint8_t> visible; // raw value -> alpha(v) > 0
    int tableBias = 0;

    Classifier(const VolumeGrid& g, const TransferFunction1D& t) : grid(g), tf(t) {
        const glm::dvec2 range = t.resolvedDataRange(g);
        lo = range.x;
        hi = range.y;
        int first = 0, last = -1;
        switch (g.type()) {
        case VoxelType::UByte:
            last = 255;
            break;
        case VoxelType::UShort:
            last = 65535;
            break;
        case VoxelType::Short:
            first = -32768;
            last = 32767;
            break;
        case VoxelType::Float:
            break;
        }
        if (last >= first) {
            tableBias = -first;
            table.resize(std::size_t(last - first + 1));
            visible.resize(table.size());
            for (int d = first; d <= last; ++d) {
                const double v = TransferFunction1D::normalise(double(d), lo, hi);
                table[std::size_t(d - first)] = float(v);
                visible[std::size_t(d - first)] = tf.evaluate(TransferFunction1D::Alpha, v) > 0.0;
            }
        }
    }
    float v(std::size_t index) const {
        const double d = grid.value(index);
        if (!table.empty()) return table[std::size_t(int(d) + tableBias)];
        return float(TransferFunction1D::normalise(d, lo, hi));
    }
    bool isVisible(std::size_t index) const {
        const double d = grid.value(index);
        if (!visible.empty()) return visible[std::size_t(int(d) + tableBias)] != 0;
        return tf.evaluate(TransferFunction1D::Alpha, TransferFunction1D::normalise(d, lo, hi)) >
               0.0;
    }
};

} // namespace

ref_ptr<VoxelObject> VoxelObject::extract(const VolumeGrid& data, const VolumeGrid* tags,
                                          const ExtractionSpec& spec) {
    const glm::ivec3 n = data.dimensions();
    if (n.x > 65535 || n.y > 65535 || n.z > 65535)
        throw Error("shear-warp: volume dimensions above 65535 are not supported");
    if (spec.source.kind == ObjectSource::Tag) {
        if (!tags) throw Error("VolumeObject source TAG needs a label volume (tagFileName)");
        if (tags->dimensions() != n)
            throw Error("VolumeObject: label volume dimensions differ from the data's");
    }
    ref_ptr<VoxelObject> object(new VoxelObject());
    object->dimensions_ = n;
    object->spacing_ = data.spacing();
    const Classifier classify(data, spec.transferFunction);

    // 1. The region, as a byte mask (Surface needs the neighbours' membership).
    std::vector<std::uint8_t> region(data.voxelCount());
    for (std::size_t i = 0; i < region.size(); ++i) {
        switch (spec.source.kind) {
        case ObjectSource::Whole:
            region[i] = classify.isVisible(i);
            break;
        case ObjectSource::Tag:
            region[i] = int(tags->value(i)) == spec.source.tag;
            break;
        case ObjectSource::Threshold: {
            const double d = data.value(i);
            region[i] = d >= spec.source.low && d <= spec.source.high;
            break;
        }
        }
    }

    auto inRegion = [&](int i, int j, int k) {
        return data.contains(i, j, k) && region[data.index(i, j, k)] != 0;
    };
    const double l0 = data.smallestSpacing();
    const glm::dvec3 h = data.spacing();
    auto gradientAt = [&](int i, int j, int k) {
        glm::dvec3 g;
        const int p[3] = {i, j, k};
        for (int axis = 0; axis < 3; ++axis) {
            int lo[3] = {p[0], p[1], p[2]}, hi[3] = {p[0], p[1], p[2]};
            lo[axis] = std::max(0, p[axis] - 1);
            hi[axis] = std::min(n[axis] - 1, p[axis] + 1);
            const double span = double(hi[axis] - lo[axis]) * h[axis];
            g[axis] = span > 0.0 ? (double(classify.v(data.index(hi[0], hi[1], hi[2]))) -
                                    double(classify.v(data.index(lo[0], lo[1], lo[2])))) /
                                       span
                                 : 0.0;
        }
        return g;
    };

    // 2. Selection and attributes, in (k, j, i) order.
    std::vector<float> magnitudes;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const std::size_t index = data.index(i, j, k);
                if (!region[index]) continue;
                bool keep = true;
                switch (spec.selection) {
                case VoxelSelection::Visible:
                    keep = spec.source.kind == ObjectSource::Whole || classify.isVisible(index);
                    break;
                case VoxelSelection::Surface:
                    keep = !inRegion(i - 1, j, k) || !inRegion(i + 1, j, k) ||
                           !inRegion(i, j - 1, k) || !inRegion(i, j + 1, k) ||
                           !inRegion(i, j, k - 1) || !inRegion(i, j, k + 1);
                    break;
                case VoxelSelection::Gradient:
                    keep = glm::length(gradientAt(i, j, k)) * l0 >= spec.gradientThreshold;
                    break;
                }
                if (!keep) continue;
                const glm::dvec3 g = gradientAt(i, j, k);
                object->i_.push_back(std::uint16_t(i));
                object->j_.push_back(std::uint16_t(j));
                object->k_.push_back(std::uint16_t(k));
                object->value12_.push_back(
                    std::uint16_t(std::lround(double(classify.v(index)) * 4095.0)));
                object->gradientCode_.push_back(GradientCode::encode(glm::vec3(-g)));
                magnitudes.push_back(float(glm::length(g) * l0));
            }

    // 3. Magnitudes to 8 bits, logarithmically over [max / 256, max].
    for (float m : magnitudes)
        object->maxMagnitude_ = std::max(object->maxMagnitude_, double(m));
    object->magnitude8_.resize(magnitudes.size());
    for (std::size_t i = 0; i < magnitudes.size(); ++i)
        object->magnitude8_[i] = object->magnitudeCode(magnitudes[i]);
    return object;
}

std::uint8_t VoxelObject::magnitudeCode(double m) const {
    if (!(maxMagnitude_ > 0.0) || !(m > 0.0)) return 0;
    // code c stands for max * 256^((c - 255) / 255): 0 is anything up to max / 256.
    const double c = 255.0 + 255.0 * std::log(m / maxMagnitude_) / std::log(256.0);
    return std::uint8_t(std::clamp(std::lround(c), 0L, 255L));
}

double VoxelObject::magnitudeOf(std::uint8_t code) const {
    if (code == 0) return 0.0;
    return maxMagnitude_ * std::pow(256.0, (double(code) - 255.0) / 255.0);
}

bool VoxelObject::hasRenderList(int axis) const {
    std::lock_guard lock(buildMutex_);
    return lists_[std::size_t(axis)] != nullptr;
}

RenderList& VoxelObject::renderList(int axis) {
    if (axis < 0 || axis > 2) throw Error("RenderList axis must be 0, 1 or 2");
    std::lock_guard lock(buildMutex_);
    auto& list = lists_[std::size_t(axis)];
    if (!list) {
        auto built = std::make_unique<RenderList>();
        build(*built, axis);
        list = std::move(built);
        ++builds_;
        processBuilds.fetch_add(1, std::memory_order_relaxed);
    }
    return *list;
}

const ValueSortedVoxels* VoxelObject::valueSorted() {
    if (!ValueSortedVoxels::fits(dimensions_)) return nullptr;
    std::lock_guard lock(buildMutex_);
    if (!valueSorted_) {
        // Sorted by value, stably: within a value in extraction order, which is (k, j, i).
        auto sorted = std::make_unique<ValueSortedVoxels>();
        std::vector<std::uint32_t> order(i_.size());
        for (std::size_t v = 0; v < order.size(); ++v)
            order[v] = std::uint32_t(v);
        const std::vector<std::uint32_t> start = countingSort(
            order, 4096, [&](std::uint32_t v) { return std::min<unsigned>(value12_[v], 4095u); });
        std::copy(start.begin(), start.end(), sorted->start.begin());
        sorted->position.resize(order.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            sorted->position[i] = ValueSortedVoxels::pack(i_[order[i]], j_[order[i]], k_[order[i]]);
        valueSorted_ = std::move(sorted);
    }
    return valueSorted_.get();
}

void VoxelObject::adoptRenderList(std::unique_ptr<RenderList> list) {
    if (!list) throw Error("no RenderList to adopt");
    list->checkConsistent(i_.size(), dimensions_);
    std::lock_guard lock(buildMutex_);
    auto& slot = lists_[std::size_t(list->axis)];
    if (!slot) slot = std::move(list);
}

std::uint64_t VoxelObject::processRenderListBuilds() {
    return processBuilds.load(std::memory_order_relaxed);
}

unsigned VoxelObject::renderListBuilds() const {
    std::lock_guard lock(buildMutex_);
    return builds_;
}

VoxelObject::Arrays VoxelObject::arrays() const {
    return {dimensions_, spacing_, maxMagnitude_, i_, j_, k_, value12_, gradientCode_, magnitude8_};
}

ref_ptr<VoxelObject> VoxelObject::fromArrays(Arrays a) {
    const std::size_t n = a.i.size();
    if (a.j.size() != n || a.k.size() != n || a.value12.size() != n || a.gradientCode.size() != n ||
        a.magnitude8.size() != n)
        throw Error("voxel object arrays differ in length");
    for (int axis = 0; axis < 3; ++axis)
        if (a.dimensions[axis] < 1 || a.dimensions[axis] > 65536)
            throw Error("voxel object dimensions must be 1..65536 each");
    for (std::size_t v = 0; v < n; ++v)
        if (a.i[v] >= a.dimensions.x || a.j[v] >= a.dimensions.y || a.k[v] >= a.dimensions.z)
            throw Error("voxel object position outside its dimensions");
    ref_ptr<VoxelObject> object(new VoxelObject);
    object->dimensions_ = a.dimensions;
    object->spacing_ = a.spacing;
    object->maxMagnitude_ = a.maxMagnitude;
    object->i_ = std::move(a.i);
    object->j_ = std::move(a.j);
    object->k_ = std::move(a.k);
    object->value12_ = std::move(a.value12);
    object->gradientCode_ = std::move(a.gradientCode);
    object->magnitude8_ = std::move(a.magnitude8);
    return object;
}

std::size_t VoxelObject::memoryBytes() const {
    std::lock_guard lock(buildMutex_);
    std::size_t bytes = i_.size() * (3 * sizeof(std::uint16_t) + 2 * sizeof(std::uint16_t) + 1);
    for (const auto& list : lists_)
        if (list) bytes += list->memoryBytes();
    if (valueSorted_)
        bytes +=
            valueSorted_->position.size() * sizeof(std::uint32_t) + sizeof(valueSorted_->start);
    return bytes;
}

void VoxelObject::build(RenderList& list, int c) const {
    const int a = (c + 1) % 3, b = (c + 2) % 3;
    const std::vector<std::uint16_t>* coords[3] = {&i_, &j_, &k_};
    const auto& ca = *coords[a];
    const auto& cb = *coords[b];
    const auto& cc = *coords[c];
    const std::size_t count = i_.size();

    // Stable counting sorts by a, then b, then (slice, piece a, piece b): order (c, piece, b, a).
    std::vector<std::uint32_t> order(count);
    for (std::size_t i = 0; i < count; ++i)
        order[i] = std::uint32_t(i);
    const int na = dimensions_[a], nb = dimensions_[b], nc = dimensions_[c];
    const int piecesA = (na + 255) / 256, piecesB = (nb + 255) / 256;
    countingSort(order, na, [&](std::uint32_t v) { return ca[v]; });
    countingSort(order, nb, [&](std::uint32_t v) { return cb[v]; });
    auto groupOf = [&](std::uint32_t v) {
        return (int(cc[v]) * piecesA + (ca[v] >> 8)) * piecesB + (cb[v] >> 8);
    };
    countingSort(order, nc * piecesA * piecesB, groupOf);

    list.axis = c;
    list.packed.resize(count);
    list.value12.resize(count);
    list.gradientCode.resize(count);
    list.magnitude8.resize(count);
    list.entries.clear();
    int group = -1;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t v = order[i];
        const int g = groupOf(v);
        if (g != group) {
            if (!list.entries.empty()) {
                auto& e = list.entries.back();
                e.firstClipped = e.last = e.lastClipped = e.lastInSlice = std::uint32_t(i);
            }
            RenderListEntry e;
            e.first = std::uint32_t(i);
            e.offset = glm::u16vec3(ca[v] & ~0xFF, cb[v] & ~0xFF, cc[v] & ~0xFF);
            e.z = std::uint8_t(cc[v] & 0xFF);
            list.entries.push_back(e);
            group = g;
        }
        list.value12[i] = value12_[v];
        list.gradientCode[i] = gradientCode_[v];
        list.magnitude8[i] = magnitude8_[v];
        list.packed[i] = PackedVoxel::pack(ca[v] & 0xFF, cb[v] & 0xFF, 0, 0);
    }
    if (!list.entries.empty()) {
        auto& e = list.entries.back();
        e.firstClipped = e.last = e.lastClipped = e.lastInSlice = std::uint32_t(count);
    }
    list.derivePacked(0, std::uint32_t(count), PackedLayout::ValueMagnitude);
}

} // namespace volsg
