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
// Depth (a ScreenScene: every shape carries an inv_depth plane). Then a sample is the shape
// nearest at the point among those whose winding number is nonzero there: the largest
// 1/z_v evaluated at the sample itself, a depth per sample, which is what a z-buffer with
// one depth per sample resolves to; ties in depth are decided by the one rule of
// methods/scan/visibility_rule.h (kDepthTieRelative; then the shape nearer just right of the
// sample, then the later shape, as in 2-D). So `none`, `ssaa`, `nishita-d` and `fast-edge`'s fill
// are z-buffer methods on 3-D scenes, with the scene's own shapes (hidden ones included), and
// exactly the 2-D methods otherwise (the depth path is taken only when the scene has depth planes).
//
// Affine values (a shape's `value_plane`: depth images, smooth shading): a sample takes the
// plane's value at the sample point.
//
// Crossings: lines inside the image come from an EdgeSweep (methods/scan/edge_sweep.h), carried
// over from line to line, so lines in ascending y cost the edges they meet, not a sort. The
// order among crossings of equal x does not matter here: all of them are applied before the
// first sample at or right of their x, and the state they leave (winding numbers, the topmost
// or nearest shape, ties in depth to the later shape) does not depend on the order.
//
// Lines outside the image: the edge table buckets edges by image row only, so a line with
// y < 0 or y >= height (the Gaussian methods reach half a pixel or one pixel past the border)
// is served from a short list of the edges that reach into that margin band, with the same
// half-open rule (EdgeTable applies a closed rule on the line y == height itself; this
// sampler never uses it there, so the tie rule is the same on every line).
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "methods/scan/edge_sweep.h"
#include "methods/scan/edge_table.h"
#include "methods/scan/visibility_rule.h"
#include "patterns/scene/scene.h"

namespace aabench {

class PointSampler {
public:
    // Lines may be sampled for -margin_px <= y < height + margin_px. margin_px >= 0.
    PointSampler() = default;
    explicit PointSampler(const Scene& scene, double margin_px = 0.0) { reset(scene, margin_px); }
    // Samples `scene` from now on, reusing the memory held: no allocation once it has held a
    // scene at least as large (methods keep one per thread).
    void reset(const Scene& scene, double margin_px = 0.0);

    const EdgeTable& table() const { return table_; }

    // top[n] = index of the topmost shape covering (xs[n], y), or -1 for the background.
    // `xs` must be ascending (ties allowed); x may lie outside [0, width].
    void sample_top(double y, std::span<const double> xs, std::span<int> top);

    // values[n] = the visible value at (xs[n], y): value_at(top, xs[n], y).
    void sample_values(double y, std::span<const double> xs, std::span<double> values);

    // True when every value is a shape's constant or the background: no depth planes, no
    // value planes. Then a line's value is constant between crossings.
    bool flat() const { return inv_depth_.empty() && planes_.empty(); }
    // Only when flat(): out[i] = float(the visible value at (i + 0.5, y)), i in [0, out.size()),
    // the pixel centres; sample_values at those points rounded to float, bit for bit, but
    // written as runs between crossings (a fill per run instead of a walk step per pixel).
    void sample_centres(double y, std::span<float> out);

    // Only when flat(): sample_values(y, xs, values) bit for bit, written as runs between
    // crossings (a fill per run, no step per sample), and `starts` (cleared first) the index n
    // of every sample n > 0 whose value differs from sample n - 1's, ascending. Callers that
    // combine samples per pixel compute only the pixels a start touches and copy the rest from
    // their left neighbour (the same values in the same order give the same sum). xs ascending
    // and about evenly spaced (a crossing's first sample is found by interpolation, then
    // stepped to: any ascending xs is right, uneven ones only slower).
    void sample_value_runs(double y, std::span<const double> xs, std::span<double> values,
                           std::vector<std::uint32_t>& starts);

    // The value of shape `top` (-1: the background) at (x, y): its value, or its value_plane.
    double value_at(int top, double x, double y) const {
        if (top < 0) return table_.background();
        return planes_.empty() || !has_value_plane_[top] ? table_.shape_value(top)
                                                         : planes_[top].at(x, y);
    }
    // True when the shapes carry depth planes (the z-buffer path above).
    bool has_depth() const { return !inv_depth_.empty(); }
    // Shape `shape`'s depth plane (1/z_v); only with has_depth().
    const AffinePlane& inv_depth(int shape) const { return inv_depth_[shape]; }

private:
    // The crossings of the line y, sorted by x (ties in any order).
    std::span<const Crossing> gather_crossings(double y);
    template <class Emit>
    void walk(double y, std::span<const double> xs, Emit emit);

    EdgeTable table_;
    EdgeSweep sweep_;
    std::vector<std::uint32_t> margin_edges_;  // edges reaching into [-margin, 0) or [h, h+margin)
    std::vector<Crossing> crossings_;          // margin lines' crossings
    CoverWalk cover_;  // the visibility rule along a line, cleared after each line
    std::vector<AffinePlane> inv_depth_;  // per shape, empty for a 2-D scene
    std::vector<AffinePlane> planes_;     // per shape value planes, empty when no shape has one
    std::vector<char> has_value_plane_;
};

// For the methods that combine the samples of a window per pixel (after sample_value_runs):
// marks (sets to 1) the pixels whose value must be computed rather than copied from their left
// neighbour. Pixel i reads samples [stride i + lo, stride i + lo + size) of each sample row
// (size >= stride); with pixel i - 1 that spans [stride (i - 1) + lo, stride i + lo + size).
// A start s of a row (its value changes between samples s - 1 and s) inside that span, both
// sides of it read, makes pixel i differ from pixel i - 1; where no row has one, the two read
// the same values in every position, and compute the same sum. Pixel 0 is not marked here.
inline void mark_pixels_at_starts(std::span<const std::uint32_t> starts, int stride, int lo,
                                  int size, std::span<char> marked) {
    const long long last = static_cast<long long>(marked.size()) - 1;
    // floor(a / b) for b > 0 and any a.
    auto floor_div = [](long long a, long long b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
    for (const std::uint32_t start : starts) {
        const long long s = start;
        // stride (i - 1) + lo <= s - 1  and  s <= stride i + lo + size - 1.
        const long long i_lo = std::max(0LL, -floor_div(-(s + 1 - lo - size), stride));
        const long long i_hi = std::min(last, floor_div(s - 1 - lo, stride) + 1);
        for (long long i = i_lo; i <= i_hi; ++i) marked[i] = 1;
    }
}

}  // namespace aabench
