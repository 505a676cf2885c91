// SMAA's area texture (methods/smaa/smaa_area_p.h).
#include "methods/smaa/smaa_area_p.h"

#include <algorithm>
#include <cmath>

namespace aabench {
namespace {

// Positive and negative parts of the integral of the straight line through (xa, ya), (xb, yb)
// (xa < xb) over [u0, u1] clipped to [xa, xb]: the areas between it and y = 0 above and below.
struct Parts {
    double positive = 0.0;
    double negative = 0.0;
};

Parts line_parts(double xa, double ya, double xb, double yb, double u0, double u1) {
    const double lo = std::max(u0, xa), hi = std::min(u1, xb);
    Parts parts;
    if (hi <= lo) return parts;
    const double slope = (yb - ya) / (xb - xa);
    const double y_lo = ya + slope * (lo - xa), y_hi = ya + slope * (hi - xa);
    if ((y_lo >= 0.0) == (y_hi >= 0.0) || y_lo == 0.0 || y_hi == 0.0) {
        // No sign change inside: a trapezoid.
        const double area = 0.5 * (y_lo + y_hi) * (hi - lo);
        (area >= 0.0 ? parts.positive : parts.negative) += std::abs(area);
        return parts;
    }
    // The line crosses y = 0 at `root` inside (lo, hi): two triangles.
    const double root = lo - y_lo / slope;
    const double first = 0.5 * y_lo * (root - lo), second = 0.5 * y_hi * (hi - root);
    (first > 0.0 ? parts.positive : parts.negative) += std::abs(first);
    (second > 0.0 ? parts.positive : parts.negative) += std::abs(second);
    return parts;
}

Parts add(Parts a, Parts b) { return {a.positive + b.positive, a.negative + b.negative}; }

// Height of a single crossing edge's midpoint: +1/2 on the own side, -1/2 on the other.
double height(SmaaCrossing c) { return c == SmaaCrossing::kOwn ? 0.5 : -0.5; }

bool single(SmaaCrossing c) { return c == SmaaCrossing::kOwn || c == SmaaCrossing::kOther; }

// The shape's parts over [u0, u1] for single crossings or none at each end (at least one single).
Parts shape_parts(SmaaCrossing first, SmaaCrossing second, double d, double u0, double u1) {
    const double middle = 0.5 * d;
    if (single(first) && single(second) && first != second) {
        return line_parts(0.0, height(first), d, height(second), u0, u1);  // Z
    }
    Parts parts;  // U, or an L (one end only): a line from each single end to the middle
    if (single(first)) parts = add(parts, line_parts(0.0, height(first), middle, 0.0, u0, u1));
    if (single(second)) parts = add(parts, line_parts(middle, 0.0, d, height(second), u0, u1));
    return parts;
}

Parts pattern_parts(SmaaCrossing first, SmaaCrossing second, double d, double u0, double u1) {
    // An end with crossing edges on both sides: the mean of its two readings.
    if (first == SmaaCrossing::kBoth) {
        const Parts a = pattern_parts(SmaaCrossing::kOwn, second, d, u0, u1);
        const Parts b = pattern_parts(SmaaCrossing::kOther, second, d, u0, u1);
        return {0.5 * (a.positive + b.positive), 0.5 * (a.negative + b.negative)};
    }
    if (second == SmaaCrossing::kBoth) {
        const Parts a = pattern_parts(first, SmaaCrossing::kOwn, d, u0, u1);
        const Parts b = pattern_parts(first, SmaaCrossing::kOther, d, u0, u1);
        return {0.5 * (a.positive + b.positive), 0.5 * (a.negative + b.negative)};
    }
    if (first == SmaaCrossing::kNone && second == SmaaCrossing::kNone) return {};
    return shape_parts(first, second, d, u0, u1);
}

}  // namespace

SmaaArea smaa_orthogonal_area(SmaaCrossing first, SmaaCrossing second, int d_first, int d_second) {
    const double d = d_first + d_second + 1.0;
    const Parts parts = pattern_parts(first, second, d, d_first, d_first + 1.0);
    return {static_cast<float>(parts.positive), static_cast<float>(parts.negative)};
}

SmaaAreaTable::SmaaAreaTable(int max_distance) : max_distance_(std::max(max_distance, 0)) {
    const int side = max_distance_ + 1;
    areas_.resize(static_cast<std::size_t>(kSmaaCrossingCount) * kSmaaCrossingCount * side * side);
    for (int a = 0; a < kSmaaCrossingCount; ++a) {
        for (int b = 0; b < kSmaaCrossingCount; ++b) {
            for (int d1 = 0; d1 < side; ++d1) {
                for (int d2 = 0; d2 < side; ++d2) {
                    const std::size_t pattern =
                        static_cast<std::size_t>(a) * kSmaaCrossingCount + b;
                    areas_[(pattern * side + d1) * side + d2] = smaa_orthogonal_area(
                        static_cast<SmaaCrossing>(a), static_cast<SmaaCrossing>(b), d1, d2);
                }
            }
        }
    }
}

}  // namespace aabench
