// The Gaussian supersamplers' accumulation rows (methods/ssaa/ssaa_grid.cpp,
// methods/ssaa/ssaa_pattern.cpp): a pixel row receives the weighted samples of the sample rows
// within a pixel of it, and is written out as soon as the last of them has been added.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "methods/scan/kernel/image.h"

namespace aabench {

// The Gaussian variants' accumulation: sample row p feeds pixel rows p - 1 .. p + 1 only, so
// three rows of doubles suffice (not the whole image). Each pixel receives the same terms in the
// same order as with a full-image accumulator, so the result is the same bit for bit. Row j is
// complete, rounded to float32 and written out, before sample row j + 2 starts.
class AccumulatorRing {
public:
    void reset(int width) {
        width_ = width;
        rows_.assign(3 * static_cast<std::size_t>(width), 0.0);
    }
    double* row(int j) { return rows_.data() + static_cast<std::size_t>(j % 3) * width_; }
    // Before sample row p (p >= row_lo - 1) of a band whose first pixel row is row_lo:
    // writes out pixel row p - 2 and clears its slot for p + 1.
    void begin_sample_row(int p, int row_lo, Image& out) {
        if (p - 2 >= row_lo) flush(p - 2, out);
        if (p + 1 >= row_lo) std::fill(row(p + 1), row(p + 1) + width_, 0.0);
    }
    // After the last sample row (row_hi, which wrote out row row_hi - 2 and reused its slot):
    // the band's last pixel row.
    void finish(int row_hi, Image& out) {
        if (row_hi >= 1) flush(row_hi - 1, out);
    }

private:
    void flush(int j, Image& out) {
        const double* acc = row(j);
        float* dst = out.row(j);
        for (int i = 0; i < width_; ++i) dst[i] = static_cast<float>(acc[i]);
    }
    int width_ = 0;
    std::vector<double> rows_;
};

}  // namespace aabench
