#include "methods/scan/sampling/run_sums.h"

#include <algorithm>
#include <climits>
#include <cmath>

namespace aabench {

DyadicValues DyadicValues::of(const EdgeTable& table) {
    // The exponent of each value's lowest set bit: v = M 2^(e - 53) with M an integer of 53
    // bits (frexp), so v = (M >> t) 2^(e - 53 + t) for t = M's trailing zeros.
    DyadicValues d;
    int lowest = INT_MAX;
    double largest = 0.0;
    auto visit = [&](double v) {
        if (!std::isfinite(v)) return false;
        d.nonnegative = d.nonnegative && v >= 0.0;
        if (v == 0.0) return true;
        int e = 0;
        const double m = std::frexp(std::abs(v), &e);
        const auto mantissa = static_cast<std::uint64_t>(std::ldexp(m, 53));
        lowest = std::min(lowest, e - 53 + __builtin_ctzll(mantissa));
        largest = std::max(largest, std::abs(v));
        return true;
    };
    if (!visit(table.background())) return d;
    for (int s = 0; s < table.shape_count(); ++s) {
        if (!visit(table.shape_value(s))) return d;
    }
    if (lowest == INT_MAX) lowest = 0;  // every value 0
    // Far from the ends of double's range, so that scaling by 2^exponent (and by the weights'
    // 2^-60 of nishita-d) stays exact and normal.
    constexpr int kExponentLimit = 900;
    if (lowest < -kExponentLimit || lowest > kExponentLimit) return d;
    const double max_units = std::ldexp(largest, -lowest);  // exact: an integer
    if (max_units > static_cast<double>(kMaxUnits)) return d;
    d.exact = true;
    d.exponent = lowest;
    d.unit_inverse = std::ldexp(1.0, -lowest);
    d.max_units = static_cast<std::int64_t>(max_units);
    return d;
}

}  // namespace aabench
