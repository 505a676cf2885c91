// Point sampling of a Scene along horizontal lines: the one sampling loop shared by `none`,
// `ssaa`, `nishita-d` and `fast-edge` (no method includes another; this is their common
// machinery, as edge_table.h is for the scanline methods).
//
// What a sample is: the topmost shape whose nonzero winding number is nonzero at the point
// (x, y), or the background. Shapes are ordered; a later shape covers an earlier one.
//
// Tie rule (the "top-left" fill convention of `none`, kept bit for bit): a point lying exactly
// on an edge takes the region to its right (larger x); on a horizontal edge, the region below
// (larger y). It follows from two half-open counts: an edge crosses the line y when
// y0 <= y < y1 (EdgeTable::crossings_at), and a crossing at x_c is applied before the sample at
// x when x_c <= x. So a pixel-aligned square [a, b] x [c, d] contains the sample points with
// a <= x < b and c <= y < d, and two shapes sharing an edge never both claim a point on it.
//
// Lines outside the image: the edge table buckets edges by image row only, so a line with
// y < 0 or y >= height (the Gaussian methods reach half a pixel or one pixel past the border)
// is served from a short list of the edges that reach into that margin band, with the same
// half-open rule (EdgeTable applies a closed rule on the line y == height itself; this
// sampler never uses it there, so the tie rule is the same on every line).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "methods/scan/edge_table.h"
#include "patterns/scene/scene.h"

namespace aabench {

class PointSampler {
public:
    // Lines may be sampled for -margin_px <= y < height + margin_px. margin_px >= 0.
    explicit PointSampler(const Scene& scene, double margin_px = 0.0);

    const EdgeTable& table() const { return table_; }

    // top[n] = index of the topmost shape covering (xs[n], y), or -1 for the background.
    // `xs` must be ascending (ties allowed); x may lie outside [0, width].
    void sample_top(double y, std::span<const double> xs, std::span<int> top);

    // values[n] = the visible value at (xs[n], y): value_of(top).
    void sample_values(double y, std::span<const double> xs, std::span<double> values);

    double value_of(int top) const {
        return top < 0 ? table_.background() : table_.shape_value(top);
    }

private:
    // Fills crossings_ with the crossings of the line y, sorted by x.
    void gather_crossings(double y);
    // Applies one crossing to the per-shape winding numbers and keeps top_ current.
    void cross(int shape, int winding);
    template <class Emit>
    void walk(double y, std::span<const double> xs, Emit emit);

    EdgeTable table_;
    std::vector<std::uint32_t> margin_edges_;  // edges reaching into [-margin, 0) or [h, h+margin)
    std::vector<Crossing> crossings_;
    std::vector<int> winding_;  // per shape, reset to zero after each line
    std::vector<int> nonzero_;  // shapes with nonzero winding (unsorted, few in practice)
    int top_ = -1;
};

}  // namespace aabench
