// gauss-multiscan — multi-scanning with an axisymmetric filter of radius 1 px (Nishita &
// Nakamae 1984, §2.2.2, eq. 4–5, with the left-to-right bookkeeping of §3.3, eq. 5–6;
// method C of the paper's §4).
//
// Computes: for pixel (i, j) with centre (cx, cy) = (i + 0.5, j + 0.5),
//
//     C(i, j) = sum_{k=-(n-1)..n-1} integral over x of w_|k|(x - cx) v(x, cy + k/n) dx,
//
// where v is the visible value and w_l(s) = f(sqrt(s^2 + (l/n)^2)) / (n V) is the filter's
// cross-section on the sub-scanline at vertical distance l/n, times the line spacing 1/n,
// divided by the discrete volume V (methods/scan/multiscan/subscanline.h, CrossSectionTable), so
// that the weights of one pixel sum to exactly 1. The integral along x is exact (edge crossings are
// computed); only the y direction is discretised, by the 2n - 1 sub-scanlines that cross
// the pixel's support (those at distance 1 px touch it in one point and are skipped, as in
// the paper). F_l(x') = integral_0^x' w_l is tabulated at `lut` steps and interpolated
// linearly (the paper's 64-entry table), or evaluated in closed form with lut = 0.
//
// How (eq. 4–5, §3.3). The square R_ij between the centres P(i,j), P(i+1,j), P(i+1,j+1),
// P(i,j+1) is crossed by the sub-scanlines y = cy + l/n, l = 0..n-1. On one of them, a run
// [x'1, x'2] of R_ij (x' from R_ij's left side) with visible value I(S) adds I(S) times
//     W0 = F_l(x'2) - F_l(x'1)              to pixel (i,   j)
//     W1 = F_l(1-x'1) - F_l(1-x'2)          to pixel (i+1, j)
//     W2 = F_{n-l}(1-x'1) - F_{n-l}(1-x'2)  to pixel (i+1, j+1)
//     W3 = F_{n-l}(x'2) - F_{n-l}(x'1)      to pixel (i,   j+1).
// Each sub-scanline is walked once, left to right, region by region; the runs of a region
// are its §3.3 modes: mode 0, no visible crossing inside R_ij: one run [0, 1]; mode 1, from
// the left side to the first visible crossing x'_k: [0, x'_k]; mode 2, from one visible
// crossing to the next: [x'_{k-1}, x'_k]; mode 3, from the last one to the right side:
// [x'_k, 1]. A visible crossing is a point where the visible value changes (the tracer
// drops crossings hidden under a covering shape, the NEXT stack's job in §3.2). F at the
// previous crossing is carried along, so a visible crossing costs four look-ups and a mode-0
// region none (F_l(1) is a constant). Work per sub-scanline: O(regions not showing the
// background + visible changes), plus carrying its active edges over (edge_sweep.h); a run
// of mode-0 regions of one value is one addition per pixel in a tight loop.
// Derivations and measured errors: docs/methods-multiscan.md.
//
// 2-D scenes of constant values take eq. 4 change by change instead (methods/scan/
// region_rows.h): a change by dv at x adds dv times the part of each pixel's cross-section
// right of x, three cells of a difference row per pixel row it feeds, and a pixel row is the
// prefix sum of its two region rows' cells. A region row whose n lines provably have the same
// value changes at other x (SubscanlineTracer::add_region_row: box-multiscan's whole rows,
// with the lines y_top + l/n) is summed change by change over all its lines at once, the
// lines of a change within one region first (one table index per line); the others are traced
// line by line into the same rows. Work per region row: O(crossings) for the sweep, O(changes
// x n) table reads, and the prefix sum over the blocks of 8 pixels a change reached. The same
// sums as the scatter's up to rounding (within 4 float ulps, tests/region_rows_test.cpp).
//
// 3-D scenes (a ScreenScene; Method::own_visibility()): the sub-scanlines come from the
// paper's scanline hidden-surface removal with the NEXT stack (methods/scan/
// scanline_visibility.h, where the readings of §3.2 are recorded), as in box-multiscan. A run
// of affine value (value_plane) counts with its value at the run's midpoint (runs never cross
// a region border, so they are at most 1 px long). Two rows of accumulation, kept per thread.
//
// Readings of the paper that had to be decided:
// - Indexing. The paper numbers a region's sub-scanlines l = 1..n; the line l = n is the
//   line l = 0 of the region below. Both orders give every line once; here l = 0..n-1, and
//   the line through a row of centres (l = 0) feeds that row only (F_n = 0 for the row
//   below). So pixel (i, j) sums the lines cy + k/n, k = -(n-1)..n-1: the paper's "2n - 1
//   sub-scanlines determine each pixel".
// - Normalisation. The paper normalises "the filter's volume to 1"; we normalise by
//   the discrete sum over the sub-scanlines. Here V is the sum over the 2n - 1 lines of the
//   exact cross-section integral times the spacing 1/n; it tends to the continuous volume as
//   n grows, and a uniform scene gives exactly its value at every n.
// - The Gaussian is f(r) = exp(-r^2 / (2 sigma^2)) truncated at r = 1 (not shifted to reach
//   0 there); the cone is 1 - r. The row's filter (MethodTraits::filter) names the spec:
//   "gaussian:sigma=S,radius=1" or "cone:radius=1", each normalised to unit volume.
// - Image border. A pixel's support reaches 0.5 px beyond the image; the scene there is
//   integrated like anywhere else (shapes exist outside the image): regions R_{-1,j},
//   R_{W-1,j} and the region row above row 0 are walked, and contributions to pixels
//   outside the image are dropped.
// - A vertex or horizontal edge exactly on a sub-scanline: the line's visible value is taken
//   as the mean of its limits from above and below (both walked, weight 1/2 each). This keeps
//   the method symmetric under a vertical flip.
// - Line heights are computed as (r + 0.5) + double(l) / n for region row r.
// - Accumulation is of v - background, and the background is added once at the end: equal
//   to the paper's sum because the weights sum to 1, but regions showing the background
//   add nothing (a run of them is skipped in one step) and a uniform scene is reproduced
//   bit for bit.
//
// Parameters:
//   n       3         1..256   sub-scanline intervals between vertically adjacent centres.
//                              3 as in the paper's Fig. 5; it shows 6 and 12 for thin shapes.
//   filter  gaussian  gaussian|cone   the filter's profile (the paper uses the Gaussian and
//                              names the cone as the other usual choice).
//   sigma   0.5       0.05..10 Gaussian standard deviation in px (ignored by the cone). The
//                              paper gives none; 0.5 px puts the truncation at 1 px at
//                              exp(-2) = 0.14 of the peak. The range is the exact reference's
//                              (harness/reference/filter_reference.h), so every setting can be
//                              scored; at 10 px the filter is a flat disc to within 0.5%.
//   lut     64        0..4096  steps of the F_l table (64 in the paper); 0 evaluates F_l in
//                              closed form. Linear interpolation errs by at most
//                              ((1/lut)^2 / 8 max|f'| + (1/lut) / 4 f(1)) / (n V) per look-up
//                              (the second term from the Gaussian's rim; see the doc).
#include <algorithm>
#include <cmath>
#include <vector>

#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/multiscan/region_rows.h"
#include "methods/scan/multiscan/scanline_visibility.h"
#include "patterns/scene/bezier.h"
#include "methods/scan/multiscan/subscanline.h"

namespace aabench {
namespace {

class GaussMultiscanMethod : public Method {
public:
    GaussMultiscanMethod(int sub_scanlines, const Filter& filter, int lut_steps)
        : n_(sub_scanlines),
          filter_(filter),
          table_(filter, sub_scanlines, lut_steps),
          region_weights_(table_) {}

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        if (scene.width <= 0) return;
        // A ScreenScene (depth planes), or a scene with affine values (depth images): the
        // scanline visibility of methods/scan/multiscan/scanline_visibility.h. A 2-D scene of
        // constant values keeps the priority walk it always took, bit for bit.
        if (has_depth_planes(scene) || has_value_planes(scene)) {
            // Per thread (compare --jobs renders one Method from several threads); its memory
            // is kept, so rendering again allocates nothing.
            thread_local ScanlineVisibility visibility;
            thread_local std::vector<double> lines;  // a curve's exact crossings: these lines
            lines.clear();
            if (has_bezier(scene)) grid_lines(LineGrid{0.5, n_, row_lo - 1, row_hi}, lines);
            visibility.reset(scene, lines);
            return accumulate(visibility, scene, row_lo, row_hi, out);
        }
        thread_local EdgeTable table;  // per thread, kept: a warm render allocates nothing
        thread_local SubscanlineTracer tracer;
        // Only the edges that touch a line (r + 0.5) + l/n of the region rows r = row_lo - 1 ..
        // row_hi - 1, or the next one's first (EdgeTable's LineGrid): the others are never met.
        // The tracer builds the row buckets if a line needs them.
        table.reset(scene, RowBuckets::kOnDemand, LineGrid{0.5, n_, row_lo - 1, row_hi});
        tracer.reset(table);
        accumulate_2d(tracer, scene, row_lo, row_hi, out);
    }

private:
    // accumulate() for a 2-D scene of constant values, as difference rows (methods/scan/
    // region_rows.h): a region row whose lines SubscanlineTracer::add_region_row proves (the
    // conditions of box-multiscan's whole rows) is summed change by change, the others line by
    // line, each line's changes into the same rows; a pixel row costs its changes and a
    // prefix sum over the blocks of 8 pixels they reached. The same sums as accumulate()'s
    // region-by-region scatter up to rounding (tests/region_rows_test.cpp).
    void accumulate_2d(SubscanlineTracer& tracer, const Scene& scene, int row_lo, int row_hi,
                       Image& out) const {
        const int height = scene.height;
        thread_local LineProfile below, above;
        // The terms of region row r - 1 (from_above) and of region row r (here), both rows each.
        thread_local RegionCells rows[2];
        for (RegionCells& row : rows) row.reset(scene.width);
        RegionCells* from_above = &rows[0];
        RegionCells* here = &rows[1];
        const double background = scene.background;
        for (int r = row_lo - 1; r < row_hi; ++r) {
            const double y_top = r + 0.5;
            RegionRowSums sums(region_weights_, background, *here);
            bool whole = false;
            if (y_top >= 0.0 && y_top < height) {
                tracer.advance(y_top);  // the sweep to line 0 (where it stands after line n - 1)
                whole = tracer.add_region_row(y_top, n_, sums);
            }
            if (!whole) {
                // Region row row_lo - 1 feeds only row row_lo (of the band): its line l = 0 lies
                // on the centres of row row_lo - 1, which it feeds alone.
                for (int l = (r < row_lo ? 1 : 0); l < n_; ++l) {
                    const double y = y_top + static_cast<double>(l) / n_;
                    if (tracer.trace(y, below, above)) {
                        sums.add_line(below, l, 0.5);
                        sums.add_line(above, l, 0.5);
                    } else {
                        sums.add_line(below, l, 1.0);
                    }
                }
            }
            if (r >= row_lo) {
                RegionRowSums::resolve_and_clear(*from_above, *here, background, out.row(r));
            } else {
                from_above->clear();
            }
            std::swap(from_above, here);  // here is empty again
        }
    }

    // Eq. 4–6 over the lines `tracer` gives (the priority order of a 2-D scene, or the
    // scanline hidden-surface removal of a ScreenScene): two rows of accumulation.
    template <class Tracer>
    void accumulate(Tracer& tracer, const Scene& scene, int row_lo, int row_hi, Image& out) const {
        const int width = scene.width;
        // Pixel rows r (upper) and r + 1 (lower) of region row r; column i at index i + 1,
        // for i = -1..width (the outer columns are dropped).
        thread_local std::vector<double> upper, lower;
        thread_local LineProfile below, above;
        upper.assign(width + 2, 0.0);
        lower.assign(width + 2, 0.0);
        const double background = scene.background;
        for (int r = row_lo - 1; r < row_hi; ++r) {
            // Region row row_lo - 1 feeds only row row_lo (of the band): its line l = 0 lies
            // on the centres of row row_lo - 1, which it feeds alone.
            for (int l = (r < row_lo ? 1 : 0); l < n_; ++l) {
                const double y = (r + 0.5) + static_cast<double>(l) / n_;
                if (tracer.trace(y, below, above)) {
                    scatter(below, l, 0.5, background, upper.data(), lower.data(), width);
                    scatter(above, l, 0.5, background, upper.data(), lower.data(), width);
                } else {
                    scatter(below, l, 1.0, background, upper.data(), lower.data(), width);
                }
            }
            if (r >= row_lo) {
                float* row = out.row(r);
                for (int i = 0; i < width; ++i) {
                    row[i] = static_cast<float>(background + upper[i + 1]);
                }
            }
            std::swap(upper, lower);
            std::fill(lower.begin(), lower.end(), 0.0);
        }
    }

    // One sub-scanline at offset l below the centre row of `upper`, walked left to right over
    // the regions R_{-1..width-1}, scattering eq. 4 to the four corners of each region.
    // An affine run (a shape with a value_plane) counts with its value at the run's midpoint:
    // exact for the box part of the run's length, and the error of the filter's first moment
    // over a run of at most 1 px otherwise (docs/methods-multiscan.md).
    void scatter(const LineProfile& line, int l, double weight, double background, double* upper,
                 double* lower, int width) const {
        const int m = n_ - l;
        const bool feeds_lower = l > 0;  // F_n = 0
        const double total_l = table_.total(l), total_m = table_.total(m);
        const std::vector<ValueChange>& changes = line.changes;
        const std::size_t count = changes.size();
        std::size_t k = 0;
        double value = line.start, slope = 0.0, anchor = 0.0;
        // Changes left of the first region only set the value entering it.
        while (k < count && changes[k].x < -0.5) {
            value = changes[k].value;
            slope = changes[k].slope;
            anchor = changes[k].x;
            ++k;
        }
        // I(S) of the run [xa, xb], less the background, times weight. With slope 0 this is
        // weight * (value - background) bit for bit (value + 0 * d == value).
        auto run_value = [&](double xa, double xb) {
            return weight * (value + slope * (0.5 * (xa + xb) - anchor) - background);
        };
        // Region i - 1's share of pixel i is held in a register and added together with
        // region i's own share, so each pixel is loaded and stored once per line: adding W0
        // and W1 in place would chain every region to the previous one through memory.
        double carry_upper = 0.0, carry_lower = 0.0;  // W1, W2 of the region to the left
        for (int i = -1; i < width; ++i) {
            const double left = i + 0.5, right = left + 1.0;
            // Sums over this region's runs of I(S) * W_l,0..3 (eq. 4).
            double w0, w1, w2, w3;
            if (k == count || !(changes[k].x < right)) {
                // Mode 0: no visible crossing, one run with x'1 = 0, x'2 = 1.
                const double a = run_value(left, right);
                if (a == 0.0 && slope == 0.0) {
                    // Showing the background, this region and every one up to the next
                    // visible crossing add nothing: settle the carries and skip to it, so a
                    // line costs O(regions not showing the background + visible crossings).
                    upper[i + 1] += carry_upper;
                    if (feeds_lower) lower[i + 1] += carry_lower;
                    carry_upper = carry_lower = 0.0;
                    if (k == count) break;
                    // The region holding the next crossing, > i since changes[k].x >= right.
                    // x - 0.5 is exact for |x| >= 0.5 (both multiples of x's ulp); nearer 0 a
                    // rounding can only move a crossing on a region border to the region on
                    // its right, where x' = -tiny clamps to 0: the same run.
                    const double next = std::floor(changes[k].x - 0.5);
                    if (next >= width) break;
                    i = static_cast<int>(next) - 1;  // the loop's ++i lands on it
                    continue;
                }
                w0 = w1 = a * total_l;
                w2 = w3 = a * total_m;
                if (slope == 0.0) {
                    // A constant value up to the region holding the next visible crossing:
                    // every region between adds the same W0 + W1 of its two pixels' shares
                    // (carry + w0, both a * F_l(1)), so they are added in a loop of one
                    // addition per pixel, the same sums bit for bit, where the region by
                    // region walk cost most of a line on a shape that covers much of it.
                    const int end = next_crossing_region(changes, k, count, i, width);
                    upper[i + 1] += carry_upper + w0;
                    const double u = w1 + w0;
                    for (int p = i + 1; p < end; ++p) upper[p + 1] += u;
                    carry_upper = w1;
                    if (feeds_lower) {
                        lower[i + 1] += carry_lower + w3;
                        const double v = w2 + w3;
                        for (int p = i + 1; p < end; ++p) lower[p + 1] += v;
                        carry_lower = w2;
                    }
                    i = end - 1;  // the loop's ++i lands on the region holding it
                    continue;
                }
            } else {
                // F at x'1 (initially the left side, x'1 = 0): F_l(x'1), F_l(1 - x'1),
                // F_m(1 - x'1), F_m(x'1).
                double g0 = 0.0, g1 = total_l, g2 = total_m, g3 = 0.0;
                double run_start = left;
                w0 = w1 = w2 = w3 = 0.0;
                do {
                    // Mode 1 (first visible crossing) or mode 2: the run [x'1, x'k] ends here.
                    const double a = run_value(run_start, changes[k].x);
                    const double x = changes[k].x - left;
                    const double h0 = table_.at(l, x), h1 = table_.at(l, 1.0 - x);
                    w0 += a * (h0 - g0);
                    w1 += a * (g1 - h1);
                    g0 = h0;
                    g1 = h1;
                    if (feeds_lower) {
                        const double h2 = table_.at(m, 1.0 - x), h3 = table_.at(m, x);
                        w2 += a * (g2 - h2);
                        w3 += a * (h3 - g3);
                        g2 = h2;
                        g3 = h3;
                    }
                    value = changes[k].value;
                    slope = changes[k].slope;
                    anchor = run_start = changes[k].x;
                    ++k;
                } while (k < count && changes[k].x < right);
                // Mode 3: from the last visible crossing to the right side, x'2 = 1.
                const double a = run_value(run_start, right);
                w0 += a * (total_l - g0);
                w1 += a * g1;
                w2 += a * g2;
                w3 += a * (total_m - g3);
            }
            // upper[i + 1] is pixel (i, r): W0 of this region, W1 of the one to its left.
            upper[i + 1] += carry_upper + w0;
            carry_upper = w1;
            if (feeds_lower) {
                lower[i + 1] += carry_lower + w3;
                carry_lower = w2;
            }
        }
        // Pixel (width, .) lies outside the image: its carries are dropped.
    }

    // The first region right of region i (i < it <= width) that holds changes[k] (region r
    // holds x when x < r + 1.5, the mode test of scatter()), or width when none does (k ==
    // count, or the change lies right of the last region). Regions i..it - 1 hold none.
    static int next_crossing_region(const std::vector<ValueChange>& changes, std::size_t k,
                                    std::size_t count, int i, int width) {
        if (k == count) return width;
        const double x = changes[k].x;
        // floor(x - 0.5) is the region, up to the rounding of x - 0.5 near 0: settled by
        // the mode test itself.
        const double guess = std::floor(x - 0.5);
        int r = !(guess < width) ? width  // NaN too: no x < r + 1.5, as in the mode test
                                 : std::max(i + 1, static_cast<int>(std::max(guess, 0.0)));
        while (r > i + 1 && x < (r - 1) + 1.5) --r;
        while (r < width && !(x < r + 1.5)) ++r;
        return r;
    }

    int n_;
    Filter filter_;
    CrossSectionTable table_;
    RegionWeights region_weights_;  // refers to table_
};

// The filter of the parameters, radius 1: the method weighs by its profile and the harness
// scores against its exact reference (see "Readings" above).
Filter gauss_multiscan_filter(const ParamValues& p) {
    return p.get_choice("filter") == "cone" ? Filter::cone(1.0)
                                            : Filter::gaussian(p.get_real("sigma"), 1.0);
}

}  // namespace

// What the harness knows of `gauss-multiscan` (methods/method_traits.h).
MethodTraits gauss_multiscan_traits() {
    MethodTraits t;
    t.curves = "exact crossings of each sub-scanline: the roots of y(t) = line, no flattening";
    t.own_visibility = true;
    t.coplanar_overlays = true;  // the scanline's tie order (scanline_visibility.h)
    t.affine_values = true;
    // Radius 1, unit volume: the exact reference of the profile (see "Readings" above).
    t.filter = gauss_multiscan_filter;
    t.working_bytes = [](const ParamValues& p, const SceneSize& s) {
        using namespace memory_model;
        // Two region rows of difference cells (two doubles per pixel, a pixel of margin each
        // side), or the 3-D path's two rows of per-pixel sums: the same bytes.
        double bytes =
            edge_table_bytes(s) + kSweepBytesPerEdge * s.vertices + 4.0 * 8.0 * (s.width + 2);
        const int n = p.get_int("n");
        if (n <= SubscanlineTracer::kMaxRowIntervals) {
            // The whole region rows, as box-multiscan's whole rows (box_multiscan.cpp), and
            // their node table: per line, lut + 1 nodes of eight doubles.
            bytes += (2.0 * 12.0 * (n + 1) + kRowTrackBytes) * s.vertices;
            bytes += 64.0 * n * (p.get_int("lut") + 1);
        }
        return bytes;
    };
    t.time_ms = [](const ParamValues& p, const SceneSize& s) {
        using namespace cost_model;
        const double lines = kGaussMultiscanFixed + kGaussMultiscanPerLine * p.get_int("n");
        const double at_default = kGaussMultiscanFixed + kGaussMultiscanPerLine * 3;
        return linear_ms(kGaussMultiscan, s.pixels(), s.vertices) * lines / at_default;
    };
    // Line sampling in y, as box-multiscan's (box_multiscan.cpp).
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kCurveExtremumOnSubscanline,
         DocumentedBound::kLocalChanges,
         "a curve tangent to a sub-scanline, moved by d, changes that line's covered length by "
         "~2 sqrt(2 d / curvature): continuous, but not by less than d"},
        {Invariant::kContinuity, CaseSet::kHorizontalOnSubscanline, DocumentedBound::kLocalChanges,
         "line sampling in y: a horizontal edge moved across a sub-scanline jumps"},
        {Invariant::kTranslation, CaseSet::kHorizontalOnSubscanline, DocumentedBound::kLocalChanges,
         "2^20 + y rounds y by up to 2^-33 px, off a sub-scanline it lay on: the same jump"},
    };
    t.hard_cases.heavy = [](const ParamValues& p) { return p.get_int("n") >= 128; };
    t.hard_cases.line_settings = {"n=6", "n=12"};
    t.hard_cases.maximum_settings = {"n=256"};
    return t;
}

MethodInfo gauss_multiscan_method() {
    return {"gauss-multiscan",
            "n sub-scanlines between centre rows, radial filter of radius 1 px scattered to "
            "the four pixels of each region (Nishita & Nakamae 1984, eq. 4-6)",
            {{"n",
              ParamKind::kInt,
              3,
              1,
              256,
              {},
              "sub-scanline intervals between centre rows; 3 as in the paper"},
             {"filter",
              ParamKind::kChoice,
              0,
              0,
              0,
              {"gaussian", "cone"},
              "radial profile, radius 1 px; the paper uses the Gaussian"},
             {"sigma",
              ParamKind::kReal,
              0.5,
              0.05,
              10.0,
              {},
              "Gaussian standard deviation in px (cone ignores it); truncated at 1 px"},
             {"lut",
              ParamKind::kInt,
              64,
              0,
              4096,
              {},
              "steps of the F_l table, 64 as in the paper; 0 = closed form"}},
            [](const ParamValues& p) {
                return std::make_unique<GaussMultiscanMethod>(
                    p.get_int("n"), gauss_multiscan_filter(p), p.get_int("lut"));
            },
            "n",
            {1, 2, 3, 6, 12, 24}};
}

}  // namespace aabench
