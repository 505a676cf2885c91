// Per-pixel sums of point samples taken from the runs of their sample rows (ValueRuns,
// methods/scan/sampling/point_sampling.h), with a cost per value change and per pixel, not per
// sample: the accumulation of `ssaa` (box filter on the grid) and `nishita-d` on flat scenes.
//
// How: a pixel row's sum is a function of the pixel that steps only where some sample row
// changes value near the pixel. Each change adds its step to a difference array over the
// pixels (RowDifferences), one prefix sum along the row then gives every pixel's sum, and the
// pixels no change touched copy their left neighbour (a fill, not a sum). This is how a
// supersampler fills sample spans between crossings: counts per pixel, not a query per sample.
//
// Exactly, in integers. The sums the methods always computed are double additions in a fixed
// order (sample by sample, row by row); a prefix sum in double along a row would drift from
// them. So the values are taken as integers in units of 2^exponent (DyadicValues): when every
// value of the scene is an integer multiple N 2^e of one power of two with |N| small (0 and 1
// in all the built-in patterns), every partial sum of the box filter is exact in double, in
// any order, and the integer sum here is the same number bit for bit. Scenes with other values
// keep the per-sample sums (the callers check DyadicValues::exact first).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "methods/scan/kernel/cells.h"
#include "methods/scan/kernel/edge_table.h"

namespace aabench {

// Whether the background and shape values of a table are integers in one power-of-two unit:
// v = units(v) * 2^exponent exactly, |units(v)| <= max_units <= kMaxUnits.
struct DyadicValues {
    // Sums of up to 64^2 samples (ssaa's k <= 64) of 2^20 units stay below 2^53: exact in double,
    // and the nishita-d weights keep 34 fractional bits or more (run_sums.cpp).
    static constexpr std::int64_t kMaxUnits = std::int64_t{1} << 20;

    bool exact = false;  // false: some value is not such a multiple (or is not finite)
    int exponent = 0;
    std::int64_t max_units = 0;  // the largest |units(v)|
    bool nonnegative = true;     // every value >= 0

    static DyadicValues of(const EdgeTable& table);
    double unit_inverse = 1.0;  // 2^-exponent
    // Exact: v times a power of two stays normal (the exponent is kept far from double's ends).
    std::int64_t units(double v) const { return static_cast<std::int64_t>(v * unit_inverse); }
};

// The float32 nearest to a double sum that is known only to lie within `slack` of `approx`:
// rounding is monotonic, so when both ends of [approx - slack, approx + slack] round to one
// float, so does the sum; otherwise (the sum is that close to a midpoint of two floats, or to
// 0) nothing is decided and the caller computes the sum itself.
inline bool decided_float(double approx, double slack, float& out) {
    const float lo = static_cast<float>(approx - slack), hi = static_cast<float>(approx + slack);
    out = lo;
    // -0 and +0 compare equal but are different images: the sign decides too.
    return lo == hi && std::signbit(lo) == std::signbit(hi);
}

// floor(s / k) for the sample indices of a row, by a multiply (a change costs a division
// otherwise, and there are hundreds a row): exact for s < 2^32 / k (see the constructor).
class DivideBy {
public:
    DivideBy(std::uint32_t k, std::uint64_t largest_s)
        : k_(k),
          // s * m / 2^32 = s / k + s e / 2^32 with 0 < e <= 1: the floor is right while
          // s e / 2^32 < 1 / k, which s < 2^32 / k ensures; larger rows divide.
          magic_((std::uint64_t{1} << 32) / k + 1),
          use_magic_(largest_s * k < (std::uint64_t{1} << 32)) {}
    std::uint32_t operator()(std::uint32_t s) const {
        return use_magic_ ? static_cast<std::uint32_t>((s * magic_) >> 32) : s / k_;
    }

private:
    std::uint32_t k_;
    std::uint64_t magic_;
    bool use_magic_;
};

// The difference array of one pixel row in integer units (kernel/cells.h): writer().add(i, d)
// makes pixel i and every pixel right of it d larger and flags pixel i (blocks of one cell);
// resolve_and_clear(first, row, resolve) sets row[i] = resolve(i, first + the steps at 0..i)
// at pixel 0 and at every flagged pixel, left to right, and each unflagged pixel copies its
// left neighbour (the same sum), so a row costs its changes and its flagged pixels, not its
// width. Index width takes the steps that fall right of the row.
using RowDifferences = CellRow<std::int64_t, 1>;

}  // namespace aabench
