// The pixels whose centre lies within a distance of a segment, visited without testing every
// pixel (the edge band of harness/measure/symptoms.h and the per-angle edge figures of
// harness/measure/edge_angles.h share it).
//
// Each segment visits only the rows its band reaches, and on each row only the pixel centres
// whose x can be within the distance: a point (x, yc) within d of the segment is within d of
// some segment point whose y lies in [yc - d, yc + d], so x lies in that slab's x-range of the
// segment widened by d. The candidates then get the exact point-segment distance test, so the
// band is exact and the work is O(length x band).
#pragma once

#include <algorithm>
#include <cmath>

#include "patterns/scene/scene.h"

namespace aabench::segment_band {

// floor/ceil results made indices in [lo, hi] before the cast: a scene coordinate may be any
// finite double, far outside int (and a NaN from an overflowing edge gives lo).
inline int clamped_index(double v, int lo, int hi) {
    if (!(v >= lo)) return lo;
    if (!(v <= hi)) return hi;
    return static_cast<int>(v);
}

// Squared distance from p to the segment [a, b] (a point when a == b).
inline double squared_distance_to_segment(Point p, Point a, Point b) {
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double px = p.x - a.x, py = p.y - a.y;
    const double length2 = ex * ex + ey * ey;
    double t = length2 > 0.0 ? (px * ex + py * ey) / length2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double dx = px - t * ex, dy = py - t * ey;
    return dx * dx + dy * dy;
}

// Calls visit(i, j) for every pixel of a width x height window whose centre (i + 0.5, j + 0.5)
// is within d (inclusive) of [a, b]; skip(i, j) true leaves a pixel out before its distance
// test (a pixel already marked needs none).
template <class Skip, class Visit>
void for_each_pixel_near(Point a, Point b, double d, int width, int height, Skip skip,
                         Visit visit) {
    const double d2 = d * d;
    const double y_lo = std::min(a.y, b.y) - d, y_hi = std::max(a.y, b.y) + d;
    // Rows whose centre j + 0.5 lies in [y_lo, y_hi].
    const int j_lo = clamped_index(std::ceil(y_lo - 0.5), 0, height);
    const int j_hi = clamped_index(std::floor(y_hi - 0.5), -1, height - 1);
    for (int j = j_lo; j <= j_hi; ++j) {
        const double yc = j + 0.5;
        // The segment's x-range within the slab [yc - d, yc + d] (see the top of the file).
        double x_lo, x_hi;
        if (a.y == b.y) {
            x_lo = std::min(a.x, b.x);
            x_hi = std::max(a.x, b.x);
        } else {
            const double t0 = (yc - d - a.y) / (b.y - a.y);
            const double t1 = (yc + d - a.y) / (b.y - a.y);
            const double ta = std::clamp(std::min(t0, t1), 0.0, 1.0);
            const double tb = std::clamp(std::max(t0, t1), 0.0, 1.0);
            const double xa = a.x + ta * (b.x - a.x), xb = a.x + tb * (b.x - a.x);
            x_lo = std::min(xa, xb);
            x_hi = std::max(xa, xb);
        }
        // One pixel of slack each side absorbs any rounding of the slab bounds; the exact test
        // below decides.
        const int i_lo = clamped_index(std::floor(x_lo - d - 0.5) - 1.0, 0, width);
        const int i_hi = clamped_index(std::ceil(x_hi + d - 0.5) + 1.0, -1, width - 1);
        for (int i = i_lo; i <= i_hi; ++i) {
            if (skip(i, j)) continue;
            if (squared_distance_to_segment({i + 0.5, yc}, a, b) <= d2) visit(i, j);
        }
    }
}

}  // namespace aabench::segment_band
