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
// methods/scan/kernel/visibility_rule.h (kDepthTieRelative; then the shape nearer just right of the
// sample, then the later shape, as in 2-D). So `none`, `ssaa`, `nishita-d` and `fast-edge`'s fill
// are z-buffer methods on 3-D scenes, with the scene's own shapes (hidden ones included), and
// exactly the 2-D methods otherwise (the depth path is taken only when the scene has depth planes).
//
// Affine values (a shape's `value_plane`: depth images, smooth shading): a sample takes the
// plane's value at the sample point.
//
// Crossings: lines inside the image come from an EdgeSweep (methods/scan/kernel/edge_sweep.h),
// carried over from line to line, so lines in ascending y cost the edges they meet, not a sort. The
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
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <vector>

#include "methods/scan/kernel/edge_sweep.h"
#include "methods/scan/kernel/edge_table.h"
#include "methods/scan/kernel/visibility_rule.h"
#include "patterns/scene/bezier.h"
#include "patterns/scene/scene.h"

namespace aabench {

// A sample row as runs of one value: run r covers samples [starts[r], starts[r + 1]) (the last
// to the row's end) and has value values[r]; starts[0] == 0 and neighbouring runs differ in
// value. at() reads the value of sample n through a cursor that moves run by run, so reading a
// pixel's window left to right, pixel after pixel, costs the runs passed, not a search.
template <class T>
struct RunsOf {
    std::vector<std::uint32_t> starts;
    std::vector<T> values;

    T at(std::size_t n) {
        while (cursor_ + 1 < starts.size() && starts[cursor_ + 1] <= n) ++cursor_;
        while (starts[cursor_] > n) --cursor_;
        return values[cursor_];
    }
    void clear() {
        starts.clear();
        values.clear();
        cursor_ = 0;
    }
    // Every sample's value into out (out.size() samples: the row's length).
    void write(std::span<T> out) const {
        for (std::size_t r = 0; r < starts.size(); ++r) {
            const std::size_t end = r + 1 < starts.size() ? starts[r + 1] : out.size();
            std::fill(out.begin() + starts[r], out.begin() + end, values[r]);
        }
    }
    // The starts of all runs but the first: the samples whose value differs from the one left.
    std::span<const std::uint32_t> changes() const {
        return std::span<const std::uint32_t>(starts).subspan(starts.empty() ? 0 : 1);
    }

private:
    std::size_t cursor_ = 0;
};
// Runs of sample values (doubles), and runs of the shape each sample sees (-1: the background),
// which neighbouring runs differ in: a colour scene's runs, whose values are its shapes'
// colours (sample_top_runs).
using ValueRuns = RunsOf<double>;
using TopRuns = RunsOf<int>;

class PointSampler {
public:
    // Lines may be sampled for -margin_px <= y < height + margin_px. margin_px >= 0.
    PointSampler() = default;
    explicit PointSampler(const Scene& scene, double margin_px = 0.0) { reset(scene, margin_px); }
    // Samples `scene` from now on, reusing the memory held: no allocation once it has held a
    // scene at least as large (methods keep one per thread). `curve_lines`: the lines the
    // caller will sample (ascending), on which shapes with Bezier segments then cross exactly
    // where their curves do (EdgeTable::reset); without them, such shapes are their flattening.
    void reset(const Scene& scene, double margin_px = 0.0,
               std::span<const double> curve_lines = {});
    // The same for a caller that samples only the lines of `lines` (EdgeTable's LineGrid: the
    // edges lying between two of them are left out of the table), without a margin; curves
    // cross each line of the grid exactly where they do.
    void reset(const Scene& scene, const LineGrid& lines);

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
    // Only when flat(): the runs sample_centres writes, as run(first, end, top) for pixels
    // [first, end) of a row `width` pixels wide whose centres see shape `top` (-1: the
    // background), left to right, every pixel in one run and no run empty. sample_centres is
    // this with each run filled with float(its value); a colour scene's caller fills every plane
    // from one walk, each with the shape's channel value (the same float, so each plane is the
    // channel's sample_centres bit for bit: which shape a centre sees depends on the geometry
    // alone).
    template <class Run>
    void centre_runs(double y, std::size_t width, Run run);

    // Only when flat(): sample_values(y, xs, values) bit for bit, written as runs between
    // crossings (a fill per run, no step per sample), and `starts` (cleared first) the index n
    // of every sample n > 0 whose value differs from sample n - 1's, ascending. Callers that
    // combine samples per pixel compute only the pixels a start touches and copy the rest from
    // their left neighbour (the same values in the same order give the same sum). xs ascending
    // and about evenly spaced (a crossing's first sample is found by interpolation, then
    // stepped to: any ascending xs is right, uneven ones only slower).
    void sample_value_runs(double y, std::span<const double> xs, std::span<double> values,
                           std::vector<std::uint32_t>& starts);
    // The same row as runs only, nothing written per sample (xs non-empty): for the methods
    // that read the values of the few pixels an edge passes through and copy the others.
    void sample_runs(double y, std::span<const double> xs, ValueRuns& runs);
    // The same row as its changes only (xs non-empty), nothing stored: returns the value of
    // sample 0 after calling on_change(n, before, after) for every sample n > 0 whose value
    // `after` differs from sample n - 1's `before`, n ascending (the run starts of
    // sample_runs, bit for bit). For the methods that count per pixel from the changes.
    template <class OnChange>
    double sample_changes(double y, std::span<const double> xs, OnChange on_change) {
        return sample_changes_of(y, xs, on_change, [this](int top) {
            return top < 0 ? table_.background() : table_.shape_value(top);
        });
    }
    // sample_changes() of what value_of(top) says each sample is (top: the shape it sees, -1
    // the background): a change is where that differs from the sample before.
    template <class OnChange, class ValueOf>
    auto sample_changes_of(double y, std::span<const double> xs, OnChange on_change,
                           ValueOf value_of) -> decltype(value_of(0));
    // Only when flat(): sample_runs() of the shapes the samples see (run values: the shape,
    // -1 the background), whatever their values: neighbouring runs see different shapes. A
    // colour scene's caller maps each to its colour; where two shapes' values agree in one
    // channel, that channel's grey runs merge the two, and the samples are the same values.
    void sample_top_runs(double y, std::span<const double> xs, TopRuns& runs);
    // Only when flat(): the sample rows ys (ascending, inside the image rows) in one pass
    // over the active edges, when every row meets the same chains in the same order: no
    // chain starts or ends between the first row and the last, and on every row the chains'
    // x are in the first row's order. Then returns true,
    // sets `start` to the value left of every crossing, and calls on_change(n, before, after)
    // for every crossing that changes the value, n[b] its first sample on row b (x <= xs[n[b]],
    // 0 included; xs.size() for a crossing right of the last sample). Else returns false,
    // having called nothing. Not sample_changes()'s calls: changes between the same two
    // samples are not merged, and those at or left of sample 0 come with n = 0; a caller whose
    // sum is linear in the steps, in integers (ssaa's dyadic sums), gets the same sums bit for
    // bit, since the values a row's samples take are the same (same crossings, same x, same
    // rule). One call per crossing, not per row: a caller can add a crossing's rows at once.
    // What it saves: the sweep carried over k lines and the walk of each (the crossings'
    // visibility walked once, their x and first samples per row).
    template <class OnChange>
    bool sample_rows_changes(std::span<const double> ys, std::span<const double> xs,
                             double& start, OnChange on_change);

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
    // reset()'s part after the edge table: the sweep, the visibility state and the planes.
    void reset_for_table(const Scene& scene, double margin_px);
    // The first n >= filled with x <= xs[n], for x <= xs.back() (xs ascend; per_px: samples per px
    // over xs, 0 when all are at one x). The first n with x <= xs[n] is guessed by interpolation,
    // then stepped to, then raised to `filled`. Not searched from `filled`: that chained each
    // crossing's search to the last one's, a wait of a few dependent loads per crossing that was
    // most of the time on a grating.
    static std::size_t first_sample_from(double x, std::span<const double> xs, double per_px,
                                         std::size_t filled) {
        std::size_t n = 0;
        if (x > xs.front()) {
            // Rounded up: on evenly spaced samples the answer, with no step.
            const double guess = (x - xs.front()) * per_px;
            n = std::min(static_cast<std::size_t>(guess) + 1, xs.size() - 1);
        }
        while (n > 0 && x <= xs[n - 1]) --n;
        while (xs[n] < x) ++n;  // stops: x <= xs.back()
        return std::max(n, filled);
    }
    // The crossings of the line y, sorted by x (ties in any order).
    std::span<const Crossing> gather_crossings(double y);
    template <class Emit>
    void walk(double y, std::span<const double> xs, Emit emit);

    EdgeTable table_;
    EdgeSweep sweep_;
    // sample_rows_changes(): per crossing of the first row, its first sample on every row; per
    // row, the last x met.
    std::vector<std::uint32_t> row_samples_;
    std::vector<double> row_last_x_;
    std::vector<std::uint32_t> margin_edges_;  // edges reaching into [-margin, 0) or [h, h+margin)
    std::vector<Crossing> crossings_;          // margin lines' crossings
    CoverWalk cover_;  // the visibility rule along a line, cleared after each line
    std::vector<AffinePlane> inv_depth_;  // per shape, empty for a 2-D scene
    std::vector<AffinePlane> planes_;     // per shape value planes, empty when no shape has one
    std::vector<char> has_value_plane_;
};

template <class Run>
void PointSampler::centre_runs(double y, std::size_t width, Run run) {
    const std::span<const Crossing> crossings = gather_crossings(y);
    const double last_centre = static_cast<double>(width) - 0.5;
    std::size_t filled = 0;
    for (const Crossing& c : crossings) {
        // The first centre i + 0.5 with c.x <= i + 0.5 (walk's `<=`: the tie rule). For
        // 0.5 < x <= width - 0.5, x - 0.5 is exact (x and 0.5 share the ulp grid below 2^52),
        // so its ceiling is that i; outside, the crossing is applied before every centre or
        // after the last one. `!(x <= last_centre)` also sends a NaN there, as walk never
        // applies one (nor, being stuck at it, any crossing after it).
        std::size_t first;
        if (c.x <= 0.5) {
            first = 0;
        } else if (!(c.x <= last_centre)) {
            break;
        } else {
            first = static_cast<std::size_t>(std::ceil(c.x - 0.5));
        }
        if (first > filled) {
            run(filled, first, cover_.top());
            filled = first;
        }
        cover_.cross(c.shape, c.winding);
    }
    if (filled < width) run(filled, width, cover_.top());
    cover_.clear();
}

template <class OnChange, class ValueOf>
auto PointSampler::sample_changes_of(double y, std::span<const double> xs, OnChange on_change,
                                     ValueOf value_of) -> decltype(value_of(0)) {
    const std::span<const Crossing> crossings = gather_crossings(y);
    const std::size_t count = xs.size();
    const double first_x = xs.front(), last_x = xs.back();
    // Samples per px for the interpolation guess; 0 when every sample is at one x.
    const double per_px = count > 1 && last_x > first_x ? (count - 1) / (last_x - first_x) : 0.0;
    auto value = [&] { return value_of(cover_.top()); };
    using Value = decltype(value_of(0));
    Value current = value();  // left of the next crossing
    Value first = current;    // sample 0's value, once a crossing lies right of it
    Value last = current;     // the value of samples [.., filled)
    std::size_t filled = 0;    // samples [0, filled) have their value
    for (const Crossing& c : crossings) {
        // walk's rule: the crossing is applied before the first sample with c.x <= x. One right
        // of the last sample is never applied; `!(c.x <= last_x)` sends a NaN there too, as
        // walk, stuck at a NaN, applies neither it nor any crossing after it.
        if (!(c.x <= last_x)) break;
        const std::size_t n = first_sample_from(c.x, xs, per_px, filled);
        if (n > filled) {
            // Samples [filled, n) take `current`.
            if (filled == 0) {
                first = current;
            } else if (current != last) {
                on_change(filled, last, current);
            }
            last = current;
            filled = n;
        }
        cover_.cross(c.shape, c.winding);
        current = value();
    }
    if (filled == 0) {
        first = current;
    } else if (current != last) {
        on_change(filled, last, current);
    }
    cover_.clear();
    return first;
}

template <class OnChange>
bool PointSampler::sample_rows_changes(std::span<const double> ys, std::span<const double> xs,
                                       double& start, OnChange on_change) {
    const std::size_t rows = ys.size();
    if (!flat() || rows == 0 || xs.empty()) return false;
    const double y_last = ys.back();
    if (!(ys.front() >= 0.0 && y_last < table_.height())) return false;
    const std::span<const Crossing> crossings = sweep_.crossings(ys.front());
    // A chain entering at or above the last row would meet some rows but not the first.
    if (!(sweep_.next_entry() > y_last)) return false;
    const std::size_t count = xs.size();
    const double first_x = xs.front(), last_x = xs.back();
    const double per_px = count > 1 && last_x > first_x ? (count - 1) / (last_x - first_x) : 0.0;
    const auto& edges = table_.edges();
    row_samples_.resize(crossings.size() * rows);
    row_last_x_.assign(rows, -std::numeric_limits<double>::infinity());
    // Every crossing's x on every row, as the sweep would find it there (the chain's edge with
    // y0 <= y < y1, Edge::x_at), checked before anything is called.
    for (std::size_t i = 0; i < crossings.size(); ++i) {
        std::uint32_t idx = crossings[i].edge;
        std::uint32_t* first_samples = row_samples_.data() + i * rows;
        for (std::size_t b = 0; b < rows; ++b) {
            double x = crossings[i].x;
            if (b != 0) {
                const double y = ys[b];
                while (!(y < edges[idx].y1)) {
                    if (edges[idx].below < 0) return false;  // the chain ends above the row
                    idx = static_cast<std::uint32_t>(edges[idx].below);
                }
                x = edges[idx].x_at(y);
            }
            // Out of order (chains cross between the rows), or NaN (sample_changes stops there).
            if (!(x >= row_last_x_[b])) return false;
            row_last_x_[b] = x;
            first_samples[b] = x <= last_x
                                   ? static_cast<std::uint32_t>(first_sample_from(x, xs, per_px, 0))
                                   : static_cast<std::uint32_t>(count);
        }
    }
    auto value = [&] {
        const int top = cover_.top();
        return top < 0 ? table_.background() : table_.shape_value(top);
    };
    start = value();
    double current = start;
    for (std::size_t i = 0; i < crossings.size(); ++i) {
        cover_.cross(crossings[i].shape, crossings[i].winding);
        const double next = value();
        if (next == current) continue;
        on_change(row_samples_.data() + i * rows, current, next);
        current = next;
    }
    cover_.clear();
    return true;
}

// The lines a method samples, for PointSampler::reset's curve_lines: y = j + offsets[s] for
// every j in [j_lo, j_hi] and every offset (any order, each in [0, 1)), ascending, computed as
// the methods compute them. Left empty when the scene has no Bezier segments (nothing to do).
inline void sample_lines(const Scene& scene, int j_lo, int j_hi, std::span<const double> offsets,
                         std::vector<double>& out) {
    out.clear();
    if (!has_bezier(scene)) return;
    for (int j = j_lo; j <= j_hi; ++j) {
        for (const double offset : offsets) out.push_back(j + offset);
    }
    std::sort(out.begin(), out.end());
}

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

// Whether a pixel row whose `rows` sample rows hold `changes` value changes in all is better
// summed pixel by pixel from values written out than by marks and run cursors: where an edge
// passes every pixel or two (gratings, zone plates, rings) nearly every pixel is marked, and
// marking and the cursor cost more than they save. A change marks about two pixels, and a
// marked pixel read through cursors costs about twice one summed from an array: past a change
// every 4 pixels per row, writing the values out is the cheaper.
inline bool dense_changes(std::size_t changes, std::size_t rows, std::size_t width) {
    return changes * 4 > width * rows;
}

// The stretches of a pixel row that the marks of mark_pixels_at_starts (marked[0] set) make:
// fill(i, end, value_of(i)) for each marked pixel i and the unmarked ones right of it, up to
// the next mark (found with memchr: no step per copied pixel).
template <class ValueOf, class Fill>
void for_marked_runs(std::span<const char> marked, ValueOf value_of, Fill fill) {
    const std::size_t width = marked.size();
    std::size_t i = 0;
    while (i < width) {
        const auto value = value_of(i);
        const void* next = i + 1 < width ? std::memchr(&marked[i + 1], 1, width - i - 1) : nullptr;
        const std::size_t end =
            next ? static_cast<std::size_t>(static_cast<const char*>(next) - marked.data()) : width;
        fill(i, end, value);
        i = end;
    }
}

// Writes a pixel row from the marks of mark_pixels_at_starts (marked[0] set): row[i] =
// value_of(i) at every marked pixel, and each unmarked pixel the value of the marked one to
// its left (a fill per stretch, found with memchr: no step per copied pixel).
template <class ValueOf>
void write_marked_row(std::span<const char> marked, float* row, ValueOf value_of) {
    for_marked_runs(marked, value_of, [row](std::size_t first, std::size_t end, float value) {
        std::fill(row + first, row + end, value);
    });
}

}  // namespace aabench
