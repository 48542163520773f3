#include <volsg/slicing/TransferTable.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <volsg/core/Error.h>

namespace volsg {

double TransferTable::opticalDepthPerL0(double A) {
    return A > 0.0 ? -std::log1p(-std::min(A, kMaxOpacity)) : 0.0;
}

void TransferTable::build(const std::map<int, TransferFunction1D>& functions,
                          glm::dvec2 naturalRange) {
    rows_.clear();
    Row fallback;
    fallback.range = naturalRange;
    rows_.push_back(fallback); // the identity ramp unless tag -1 has a function
    for (const auto& [tag, function] : functions) {
        if (tag < -1 || tag > 65535)
            throw Error("transfer function tag must be -1 or 0..65535, got " + std::to_string(tag));
        Row row;
        row.tag = tag;
        row.function = function;
        row.range = function.dataRange() ? *function.dataRange() : naturalRange;
        if (tag == -1)
            rows_[0] = row;
        else
            rows_.push_back(row); // std::map iterates tags in ascending order
    }

    tagRows_.assign(std::size_t(kTagMapSide) * kTagMapSide, 0);
    for (std::size_t r = 1; r < rows_.size(); ++r)
        tagRows_[std::size_t(rows_[r].tag)] = std::uint16_t(r);

    texels_.assign(rows_.size() * std::size_t(kWidth) * 4, 0.0f);
    for (std::size_t r = 0; r < rows_.size(); ++r) {
        float* out = texels_.data() + r * std::size_t(kWidth) * 4;
        const TransferFunction1D& tf = rows_[r].function;
        for (int i = 0; i < kEntries; ++i) {
            const glm::dvec4 rgba = tf.evaluate(double(i) / double(kEntries - 1));
            for (int c = 0; c < 3; ++c)
                out[4 * i + c] = float(rgba[c]);
            out[4 * i + 3] = float(opticalDepthPerL0(rgba.a));
        }
        for (int c = 0; c < 4; ++c) // the filter's neighbour of the last sample
            out[4 * kEntries + c] = out[4 * (kEntries - 1) + c];
        out[4 * kRangeColumn + 0] = float(rows_[r].range.x);
        out[4 * kRangeColumn + 1] = float(rows_[r].range.y);
    }
}

bool TransferTable::rowMayEmit(const Row& row, double dataMin, double dataMax, double padV) const {
    // normalise() is monotonic, so the ends bound v over the interval (either order).
    const double v0 = TransferFunction1D::normalise(dataMin, row.range.x, row.range.y);
    const double v1 = TransferFunction1D::normalise(dataMax, row.range.x, row.range.y);
    return row.function.channel(TransferFunction1D::Alpha)
               .maxOver(std::min(v0, v1) - padV, std::max(v0, v1) + padV) > 0.0;
}

bool TransferTable::mayEmit(double dataMin, double dataMax, bool tagged, int tagMin, int tagMax,
                            double padV) const {
    if (rows_.empty()) return true;
    if (rowMayEmit(rows_[0], dataMin, dataMax, padV)) return true;
    if (!tagged) return false;
    for (std::size_t r = 1; r < rows_.size(); ++r)
        if (rows_[r].tag >= tagMin && rows_[r].tag <= tagMax &&
            rowMayEmit(rows_[r], dataMin, dataMax, padV))
            return true;
    return false;
}

} // namespace volsg
