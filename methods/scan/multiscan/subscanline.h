// Shared machinery of the multi-scanning methods (Nishita & Nakamae 1984, §2.2; methods
// box-multiscan and gauss-multiscan; derivations in docs/methods-multiscan.md):
//
//   SubscanlineTracer   the visible value along one horizontal line, exactly: continuous in x,
//                       as a start value and the x positions where it changes.
//   LineIntegralRow     per-pixel integrals of such lines over [i, i+1], weighted and summed,
//                       in O(changes) per line and O(width) per pixel row.
//   CrossSectionTable   F_l(x') on the sub-scanlines of a radial filter of radius 1 px
//                       (methods/scan/kernel/filter.h), normalised, tabulated or exact.
//
// Horizontal edges and vertices that lie exactly on a line. Along a line through an edge
// endpoint, the visible value is discontinuous in y: the limit from below the line (y' -> y+)
// and from above it (y' -> y-) may differ (a horizontal edge on the line is the extreme
// case). The tracer returns both limits, and says whether they differ, so that each method
// chooses what its quadrature rule needs (the box rule takes the limit from inside the pixel
// row, interior lines take the mean). The limit from below counts an edge when
// y0 <= y < y1 (EdgeTable::crossings_at's rule), the limit from above when y0 < y <= y1.
#pragma once

#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "methods/scan/kernel/cells.h"
#include "methods/scan/kernel/edge_sweep.h"
#include "methods/scan/kernel/edge_table.h"
#include "methods/scan/kernel/filter.h"

namespace aabench {

// Right of x (up to the next change) the visible value is value + slope * (x' - x): constant
// (slope 0) for a shape with a constant value, affine along the line for a shape with a
// `value_plane` (depth images, smooth shading).
struct ValueChange {
    double x;
    double value;
    double slope = 0.0;
};

// The visible value along one horizontal line: `start` left of every change (always the
// background: no shape reaches x = -infinity), then the changes in ascending x. `affine` is
// true when some change has a nonzero slope; when false, every consumer takes the constant
// path it always took (bit for bit).
struct LineProfile {
    double start = 0.0;
    std::vector<ValueChange> changes;
    bool affine = false;
};

class LineIntegralRow;
class RegionRowSums;

class SubscanlineTracer {
public:
    // Lines may lie up to this far outside the image rows: a filter of radius 1 px centred on
    // the first or last pixel row reaches 0.5 px beyond the image, and the scene there is
    // still integrated (the image window does not clip the scene).
    static constexpr double kMarginPx = 1.0;

    SubscanlineTracer() = default;
    explicit SubscanlineTracer(EdgeTable& table) { reset(table); }
    // Traces `table` from now on, reusing the memory held (no allocation once warm). The
    // table may come without row buckets (RowBuckets::kOnDemand); they are built the first
    // time a line needs them.
    void reset(EdgeTable& table);

    // Traces the line at height y, -kMarginPx <= y <= height + kMarginPx. Always writes the
    // limit from below into `below`; writes `above` and returns true only when the two limits
    // differ, i.e. when an edge starts or ends exactly at y (else both are `below`).
    bool trace(double y, LineProfile& below, LineProfile& above);

    // Carries the sweep to the line y without walking it (no profile): what a caller that
    // accumulates the pixel row below with add_row() needs before its next row. A line outside
    // the image rows does nothing.
    void advance(double y);

    // Every line of box-multiscan's pixel row `row_index` at once: the top border y = row
    // (limit from below) and the bottom border y = row + 1 (limit from above) with weight
    // 1/(2n), the interior lines y_l = row + l/n with weight 1/n, added to `row`, when that can
    // be proven to be the sum of tracing them one by one (up to the rounding of the sums).
    // The sweep must stand on y = row (traced or advanced there last). Three cases:
    // - no chain starts inside the row nor ends above its bottom border, and the crossings,
    //   in the list's order, have non-decreasing x on every line: every line has the same
    //   crossings in the same order, hence the same value changes, only at other x, and the
    //   lines' integrals are summed change by change. A change whose x stays in one pixel c on
    //   every line adds dv * (c + 1 - xbar) and dv * (xbar - c), with xbar the weighted mean
    //   of its x over the lines (the weights sum to 1); on an edge that spans the row
    //   straight, xbar is the x at the row's middle, since the trapezoidal rule is exact for a
    //   linear function: a straight edge inside one pixel column costs one x per row whatever
    //   n is. A change that crosses a pixel border within the row, or whose chain bends in it
    //   (add_bent_row), is summed over its lines;
    // - chains start or end inside the row, or bend: one shape whose crossings alternate in
    //   winding (add_alternating_row) adds chain by chain;
    // - anything else declines.
    // Straight edges' interior x are interpolated between the borders' (x_at's rounding
    // differs, by ulps of the vertices' coordinates: within a few float ulps of the
    // line-by-line sums while vertices lie within ~1e9 px; at 1e11 px both carry ~1e-5 px).
    // `row` must be empty (cleared). Returns false, leaving it empty, when the proof fails:
    // the caller traces the lines itself.
    bool add_row(int row_index, int n, LineIntegralRow& row);
    // The same machinery for gauss-multiscan's region row between the centre rows y_top and
    // y_top + 1 (y_top = r + 0.5): its lines y_top + l/n, l = 0..n-1, each with the weight 1
    // of a line whose two limits agree, scattered by eq. 4 into `sums` (region_rows.h). The
    // line y_top + 1 is the next region row's first: it is followed (and handed to the sweep
    // when it can take it) but adds nothing. Declines, adding nothing, when add_row() would,
    // and when an edge starts or ends exactly on y_top (there trace() takes the mean of the
    // line's two limits). The sweep must stand on y_top (traced or advanced there last).
    bool add_region_row(double y_top, int n, RegionRowSums& sums);
    // Past this many intervals per row (n, i.e. n + 1 lines) add_row() declines: it holds
    // x for every changing crossing on every line (a grating's 2,000 changes per line at 17
    // lines: 270 KB; kept per thread).
    static constexpr int kMaxRowIntervals = 16;  // LineIntegralRow::kMaxLines - 1

private:
    // Edges that include every edge a limit of the line y meets, in ascending index.
    std::span<const std::uint32_t> candidates(double y, bool from_below);
    // The crossings of the line for one limit, sorted by x, in crossings_at's order among
    // equal x (std::sort of the candidates in table order): what every line cost before the
    // sweep, and still the answer when the sweep cannot give it bit for bit.
    std::span<const Crossing> sorted_crossings(double y, bool from_below);
    // sorted_crossings() from the sweep's last line y (EdgeSweep::ended_known()).
    std::span<const Crossing> sorted_from_sweep(double y, bool from_below);
    // Whether an edge of `list` starts or ends exactly at y.
    bool endpoint_in(std::span<const std::uint32_t> list, double y) const;
    // The profile of `crossings` (sorted by x); true when two of them share an x, whose
    // order then reaches the profile (see trace()).
    bool walk(std::span<const Crossing> crossings, LineProfile& out);

    EdgeTable* table_ = nullptr;
    EdgeSweep sweep_;  // the limit from below on lines inside the image (edge_sweep.h)
    VisibilityWalker walker_;
    std::vector<std::uint32_t> top_margin_;     // edges reaching into [-kMarginPx, 0]
    std::vector<std::uint32_t> bottom_margin_;  // edges reaching into [height, height + margin]
    std::vector<Crossing> crossings_;
    std::vector<std::uint32_t> hit_edges_;  // scratch of sorted_from_sweep()
    // add_row() and add_region_row(): the lines y_top + l/n, l = 0..n, into `sink` (a
    // LineIntegralRow or a RegionRowSums; subscanline_rows.cpp says what it is asked).
    template <class Sink>
    bool add_lines(double y_top, int n, Sink& sink);
    // Of a row that bends (add_lines()), its changes summed over their lines; false when it
    // declines (a chain ends in the row, or two cross).
    template <class Sink>
    bool add_bent_row(double y_top, int n, double start, std::span<const Crossing> crossings,
                      Sink& sink);

    // Of a row where chains start or end inside it: one shape whose crossings alternate in
    // winding on every line (the winding number only 0 or s = +-1 between them: disjoint
    // contours, holes inside them, as every built-in 2-D pattern), checked line by line in
    // the list's order, with the chains entering in the row placed in their gaps by x (those of
    // one gap alternating from the winding the gap calls for, even in number). Then every
    // crossing is a change of +-(inside - outside), whatever the others do, and each chain
    // adds its own lines. false: not proven.
    template <class Sink>
    bool add_alternating_row(double y_top, int n, Sink& sink);
    class AlternatingRow;  // its row's state and phases (alternating_row_p.h)
    // After add_alternating_row(): hands the bottom border's crossings to the sweep when it
    // can take them (EdgeSweep::adopt), so that the next line is not followed twice.
    void hand_over_bottom(double y_top, int n, std::span<const Crossing> top);

    // add_row(): the crossings that change the visible value, and by how much (left to
    // right), and their x: top and bottom per change, or every line's on a bent row.
    std::vector<std::uint32_t> change_at_;  // positions in the list
    std::vector<double> change_dv_;
    // Of several shapes, the walk that gave change_at_ and change_dv_: each crossing's
    // (shape, winding), and the value left of them; walked_ false: none kept.
    std::vector<std::uint64_t> walk_keys_;
    double walk_start_ = 0.0;
    bool walked_ = false;
    std::vector<double> change_x_;
    // add_alternating_row(): per chain met (the last line's, then the entering ones), x on
    // every line, the lines it is present on, its change; per line, the crossings present
    // before each of the last line's; the entering heads; per line, (gap, entering index).
    std::vector<double> track_x_;
    std::vector<int> track_first_, track_end_;
    std::vector<double> track_dv_;
    std::vector<int> before_;
    std::vector<std::uint32_t> entering_;
    std::vector<std::uint64_t> gaps_;
    std::vector<std::uint32_t> track_edge_;    // the edge a chain meets on the bottom border
    std::vector<std::uint64_t> bottom_order_;  // gaps_ of the bottom border, in order
    std::vector<Crossing> next_list_;          // the bottom border's crossings, for the sweep
    std::vector<double> bottom_x_;             // a straight row's x on its bottom border
};

// Sum over lines of weight * integral over [i, i+1] of the line's visible value, for the
// pixels i of one row. A change of the value by dv at x adds dv * (i + 1 - x) to the pixel
// containing x and dv to every pixel right of it: one entry in a difference array, turned
// into pixel values by a prefix sum.
// The cells of a LineIntegralRow, 8 to a flag (a cache line of doubles).
using LineCells = CellRow<double, 8>;

class LineIntegralRow {
public:
    explicit LineIntegralRow(int width = 0);
    // Sets the width and zeroes the row, reusing the memory it holds (no allocation once it has
    // held a row this wide).
    void reset(int width);
    void clear();
    void add(const LineProfile& line, double weight);
    // A whole pixel row of lines y_l = row + l/n, l = 0..n, with the trapezoidal weights
    // (1/(2n) at l = 0 and n, 1/n between), whose value starts at `start` on every line and
    // jumps by dv[k] (unweighted) at the k-th change, k < count. The x of change k on line l:
    //   add_row_spans: on the straight line from x[2k] (l = 0) to x[2k + 1] (l = n);
    //   add_row_lines: x[k * (n + 1) + l].
    // The sum of add() over the n + 1 lines, up to the rounding (SubscanlineTracer::add_row).
    void add_row_spans(double start, const double* x, const double* dv, std::size_t count, int n);
    void add_row_lines(double start, const double* x, const double* dv, std::size_t count, int n);
    // The most lines per row add_row_lines() takes (SubscanlineTracer::kMaxRowIntervals + 1).
    static constexpr int kMaxLines = 17;
    // Writes the accumulated value of every pixel, rounded once to float32.
    void resolve(float* out) const;
    // resolve(), then clear(), in one pass: each touched block is zeroed as the prefix sum
    // reads it (the same values bit for bit; box-multiscan's rows).
    void resolve_and_clear(float* out);

    // SubscanlineTracer::add_alternating_row()'s additions, chain by chain (subscanline_rows.cpp).
    class Tracks;

private:
    // SubscanlineTracer::add_alternating_row() adds each chain as soon as it has passed its
    // checks, and clears the row when a later one fails.
    friend class SubscanlineTracer;

    // An affine line: a change (da, db) of v = a + b x' at x adds the exact integral of
    // da + db x' over [x, c + 1] to the pixel c holding x, and da + db (i + 0.5) (the exact
    // integral over [i, i + 1]) to every pixel i right of it: two difference arrays.
    void add_affine(const LineProfile& line, double weight);

    int width_;
    double base_ = 0.0;  // weight * start, summed: the value left of every change
    // diff_[i] changes pixel i and all right of it (diff_[width + 1]: only
    // JumpCells::add_cells() writes there, and only zeros; it keeps that write in bounds).
    // Its flagged blocks are those a JumpCells wrote to since the last clear() (block 0 is
    // always summed: diff_[0] is also written directly); resolve() and clear() skip the others.
    LineCells diff_;
    std::vector<double> diff_slope_;  // the same for the slope b (affine lines only)
    bool has_slope_ = false;          // an affine line was added since the last clear()
};

// F_l(x') of eq. 4 for the sub-scanline at vertical distance l/n from a pixel centre
// (l = 0..n): the integral of the filter's cross-section from the centre's x to x'
// (0 <= x' <= 1), times the line spacing 1/n, divided by the filter's discrete volume
// sum_{k=-n..n} (1/n) * integral_{-1}^{1} f(sqrt(s^2 + (k/n)^2)) ds, so that the weights of
// all sub-scanlines through one pixel's support sum to 1. F_n = 0: the line at distance
// 1 px touches the support only at one point.
class CrossSectionTable {
public:
    // lut_steps = 0: every value in closed form. lut_steps > 0: F_l tabulated at x' = m /
    // lut_steps and interpolated linearly (the paper's table, 64 steps).
    // `filter`: a radial filter of radius 1 px (std::invalid_argument otherwise), weighed by
    // its profile (Filter::profile_line_integral).
    CrossSectionTable(const Filter& filter, int sub_scanlines, int lut_steps);

    double at(int l, double x) const {
        if (lut_steps_ == 0) return exact(l, x);
        const double t = clamp_unit(x) * lut_steps_;
        // t == lut_steps_ must use the last interval, not run past the table.
        const int m = t < lut_steps_ ? static_cast<int>(t) : lut_steps_ - 1;
        const double* row = values_.data() + static_cast<std::size_t>(l) * (lut_steps_ + 1);
        return row[m] + (t - m) * (row[m + 1] - row[m]);
    }
    // F_l(1), exact in both modes (a table node).
    double total(int l) const { return totals_[l]; }
    double exact(int l, double x) const;
    int sub_scanlines() const { return n_; }
    int lut_steps() const { return lut_steps_; }
    // F_l at the table's node m / lut_steps (lut_steps > 0), the value at() interpolates from.
    double node(int l, int m) const {
        return values_[static_cast<std::size_t>(l) * (lut_steps_ + 1) + m];
    }

private:
    static double clamp_unit(double x) { return x < 0.0 ? 0.0 : (x > 1.0 ? 1.0 : x); }

    Filter filter_;
    int n_;
    int lut_steps_;
    double scale_;                // 1 / (n * discrete volume)
    std::vector<double> totals_;  // F_l(1), l = 0..n
    std::vector<double> values_;  // (n + 1) rows of lut_steps + 1 nodes
};

}  // namespace aabench
