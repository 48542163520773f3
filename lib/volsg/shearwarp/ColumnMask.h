#pragma once
// Which columns of a line buffer the splat wrote, as bits: the row composite and the line's
// clear visit the runs of written columns only, so a row of scattered voxels costs its voxels,
// not its width.

#include <cstdint>

namespace volsg::columns {

/// Bit c of word c / 64 is set when a voxel splatted into columns c and c + 1 (its left
/// column). A mask is read at word -1 too (its coverage carries into word 0): it starts one
/// zero word after the start of its storage.
using Word = std::uint64_t;

inline void mark(Word* mask, int column) {
    mask[column >> 6] |= Word(1) << (column & 63);
}

/// The columns of word w covered by the voxels of `mask` (each covers its column and the next);
/// 0 for a null mask.
inline Word coverage(const Word* mask, int w) {
    if (!mask) return 0;
    return mask[w] | (mask[w] << 1) | (mask[w - 1] >> 63);
}

/// The maximal runs of columns in [lo, hi) covered by mask a or mask b (either may be null;
/// both null: [lo, hi) as one run), in ascending order:
/// `for (Runs runs(a, b, lo, hi); runs.next(begin, end);)`. Plain data and a loop, no callback,
/// so the kernels keep their own target attributes.
class Runs {
public:
    Runs(const Word* a, const Word* b, int lo, int hi)
        : a_(a), b_(b), hi_(hi), w_(lo >> 6), w1_(hi > lo ? (hi - 1) >> 6 : (lo >> 6) - 1),
          lo_(lo) {
        if (!a && !b) { // the whole range
            runStart_ = hi > lo ? lo : -1;
            w_ = w1_ + 1;
            return;
        }
        load();
    }

    [[gnu::always_inline]] bool next(int& begin, int& end) {
        for (;;) {
            if (w_ > w1_) {
                if (runStart_ < 0) return false;
                begin = runStart_;
                end = hi_;
                runStart_ = -1;
                return true;
            }
            if (runStart_ >= 0) { // in a run: it ends at the first clear bit
                const Word clear = pos_ < 64 ? ~m_ & (~Word(0) << pos_) : 0;
                if (clear) {
                    pos_ = __builtin_ctzll(clear);
                    begin = runStart_;
                    end = base_ + pos_;
                    runStart_ = -1;
                    return true;
                }
            } else {
                const Word set = pos_ < 64 ? m_ & (~Word(0) << pos_) : 0;
                if (set) {
                    pos_ = __builtin_ctzll(set);
                    runStart_ = base_ + pos_;
                    continue;
                }
            }
            ++w_;
            load();
        }
    }

private:
    [[gnu::always_inline]] void load() {
        if (w_ > w1_) return;
        m_ = coverage(a_, w_) | coverage(b_, w_);
        if (w_ == lo_ >> 6) m_ &= ~Word(0) << (lo_ & 63);
        if (w_ == w1_ && (hi_ & 63) != 0) m_ &= (Word(1) << (hi_ & 63)) - 1;
        base_ = w_ << 6;
        pos_ = 0;
    }

    const Word* a_;
    const Word* b_;
    int hi_, w_, w1_, lo_;
    Word m_ = 0;
    int base_ = 0, pos_ = 0, runStart_ = -1;
};

} // namespace volsg::columns
