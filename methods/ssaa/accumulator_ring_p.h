// The Gaussian supersamplers' accumulation rows (methods/ssaa/ssaa_grid.cpp,
// methods/ssaa/ssaa_pattern.cpp): a pixel row receives the weighted samples of the sample rows
// within a pixel of it, and is written out as soon as the last of them has been added.
#pragma once

#include <array>
#include <cstddef>

#include "methods/scan/kernel/cells.h"
#include "methods/scan/kernel/image.h"

namespace aabench {

// The Gaussian variants' accumulation: sample row p feeds pixel rows p - 1 .. p + 1 only, so
// three rows of doubles suffice (not the whole image). Each pixel receives the same terms in the
// same order as with a full-image accumulator, so the result is the same bit for bit. Row j is
// complete, rounded to float32 and written out, before sample row j + 2 starts. The rows are
// kernel cell rows (methods/scan/kernel/cells.h) that hold pixel values, not changes
// (Prefix::kNone): every pixel of a row receives samples, so every block is flagged.
class SampleRowRing {
public:
    void reset(int width) {
        for (Row& r : rows_) r.reset(width);
    }
    double* row(int j) { return slot(j).cells(); }
    // Before sample row p (p >= row_lo - 1) of a band whose first pixel row is row_lo:
    // writes out pixel row p - 2 and clears its slot for p + 1.
    void begin_sample_row(int p, int row_lo, Image& out) {
        if (p - 2 >= row_lo) flush(p - 2, out);
        if (p + 1 >= row_lo) {
            slot(p + 1).clear();
            slot(p + 1).flag_all();
        }
    }
    // After the last sample row (row_hi, which wrote out row row_hi - 2 and reused its slot):
    // the band's last pixel row.
    void finish(int row_hi, Image& out) {
        if (row_hi >= 1) flush(row_hi - 1, out);
    }

private:
    using Row = CellRow<double, 8>;
    Row& slot(int j) { return rows_[static_cast<std::size_t>(j % 3)]; }
    void flush(int j, Image& out) {
        slot(j).resolve_and_clear<Prefix::kNone>(
            0.0, out.row(j), [](std::size_t, double value) { return static_cast<float>(value); });
    }
    std::array<Row, 3> rows_;
};

}  // namespace aabench
