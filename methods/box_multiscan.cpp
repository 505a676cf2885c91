// box-multiscan — multi-scanning with a box window (Nishita & Nakamae 1984, §2.2.1, eq. 1–3;
// method B of the paper's §4).
//
// Computes: for pixel (i, j), with n sub-scanlines dividing the pixel row into n bands, at
// y_l = j + l/n for l = 0..n (l = 0 and l = n are the row's borders),
//
//     C(i, j) = sum_{l=0..n} d_l * C'(i, l),   d_l = 1/(2n) for l = 0, n and 1/n otherwise,
//     C'(i, l) = integral over x in [i, i+1] of v(x, y_l),
//
// where v is the visible value (the last shape whose nonzero winding number is nonzero, else
// the background). C' is the paper's sum over faces of covered length times intensity
// (eq. 3), with the background counted as one more face. It is exact in x: crossings of the
// edges with the line are computed, never sampled; the sum over l is the trapezoidal rule in
// y (eq. 1). The error against the exact box (area) filter comes from the y direction only.
//
// A pixel row whose crossings run through it (no chain starts or ends inside it, no two cross)
// has the same value changes on all its n + 1 lines, only at other x: its lines are summed
// change by change (SubscanlineTracer::add_row), and a straight edge that stays in one pixel
// column over the row costs one x, whatever n is (the trapezoidal rule is exact for its
// linear x: it adds what its mean x gives). A row where chains start or end is summed chain
// by chain when the scene is one shape whose crossings provably alternate in winding (every
// built-in 2-D pattern). The other rows are traced line by line; there each boundary
// sub-scanline y = j is traced once and serves both rows it bounds (the paper: C'(i, n) is
// the next row's initial value). Work per pixel row: O(crossings) to carry the active edge
// list over (methods/scan/kernel/edge_sweep.h; plus the swaps of edges that crossed), O(visible
// changes) to accumulate (methods/scan/multiscan/subscanline.h, LineIntegralRow), times the lines
// for changes that cross a pixel border within the row, for chains that bend in it and on rows
// traced line by line; the prefix sum over the blocks of 8 pixels a change reached, one
// constant written over the others (O(width / 8) flags). No per-pixel work on a sub-scanline.
// A line whose crossings tie, or whose two limits differ, re-sorts the sweep's own edges
// (SubscanlineTracer::trace), never a row of the edge table.
// Derivations and measured convergence: docs/methods-multiscan.md.
//
// 3-D scenes (a ScreenScene: faces cut into face, pattern and shadow cells, each with its
// face's depth plane, hidden ones included; Method::own_visibility()): the paper's own
// hidden-surface removal runs on every sub-scanline (methods/scan/multiscan/scanline_visibility.h):
// crossings sorted left to right with the tie order shadow-right, pattern-right, face-right,
// face-left, pattern-left, shadow-left; the NEXT stack of the polygons hidden behind the
// current one; depth compared at the crossing. That file records how the paper's ambiguous
// points were read ("nearer" at a crossing; coincident crossings beyond the five roles) and
// why faces that interpenetrate come out differently from the exact answer (measured in
// tests/scanline_visibility_test.cpp and docs/methods-multiscan.md). A run of affine value
// (value_plane: depth images) is integrated exactly (its midpoint value times its length in
// each pixel). Memory: two rows of accumulation and the active edges, O(width + edges), kept
// per thread so a warm render allocates nothing.
//
// Colour scenes (docs/colour.md) are drawn per channel, the default: three renders of the
// geometry. The tracer drops crossings that change no value and its whole-row sums carry their
// dv through the proofs of subscanline_rows.cpp and alternating_row_p.h, so a colour version is
// a template of the tracer and its sinks over a three-component value, not done yet.
//
// Readings of the paper that had to be decided:
// - A vertex or a horizontal edge exactly on a sub-scanline (the paper does not say). There
//   v(x, y) jumps in y, and the trapezoidal rule of one pixel row needs the value from
//   inside that row: the row's top border uses the limit from below (y' -> j+), its bottom
//   border the limit from above (y' -> (j+1)-). So a pixel-aligned square gets its exact
//   area, and the result is symmetric under a vertical flip. Only when the two limits differ
//   (an edge starts or ends exactly on the line) is the border walked a second time, for
//   the other limit; otherwise its one profile serves both rows. An interior sub-scanline
//   (0 < l < n) with an endpoint on it uses the mean of the two limits (the trapezoidal
//   value at a jump).
// - The scene outside the image is not clipped: crossings left of x = 0 set the value at
//   x = 0, and shapes above or below the image never meet a sub-scanline.
// - Sub-scanline heights are computed as j + double(l) / n; the tests use the same formula,
//   so that "a vertex on the line" is decided identically.
//
// Parameters:
//   n   3   1..256   sub-scanline intervals per pixel row (n + 1 lines, the borders shared).
//                    3 is the paper's choice (§4: "n = 3 is usually enough"; 6 or more for
//                    thin shapes lying side by side). Error falls roughly as 1/n^2 on
//                    slanted edges and 1/n on horizontal ones: RMSE against the exact box
//                    filter on the built-in patterns at 64x64 is 2e-4..2.5e-2 at n = 3,
//                    4e-8..5e-5 at n = 256, already far below an 8-bit step (4e-3), so
//                    more lines would only cost time.
#include "methods/cost_model.h"
#include "methods/memory_model.h"
#include "methods/method.h"
#include "methods/scan/multiscan/scanline_visibility.h"
#include "patterns/scene/bezier.h"
#include "methods/scan/multiscan/subscanline.h"

namespace aabench {
namespace {

class BoxMultiscanMethod : public Method {
public:
    explicit BoxMultiscanMethod(int sub_scanlines) : n_(sub_scanlines) {}

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        if (scene.width <= 0) return;
        // A ScreenScene (depth planes), or a scene with affine values (depth images): the
        // scanline visibility of methods/scan/multiscan/scanline_visibility.h. A 2-D scene of
        // constant values keeps the priority walk it always took, bit for bit.
        if (has_depth_planes(scene) || has_value_planes(scene)) {
            // One per thread: a Method may render from several TBB threads at once, and the
            // scratch keeps its memory, so rendering again allocates nothing.
            thread_local ScanlineVisibility visibility;
            thread_local std::vector<double> lines;  // a curve's exact crossings: these lines
            lines.clear();
            if (has_bezier(scene)) grid_lines(LineGrid{0.0, n_, row_lo, row_hi}, lines);
            visibility.reset(scene, lines);
            return accumulate(visibility, scene.width, row_lo, row_hi, out);
        }
        thread_local EdgeTable table;  // per thread, kept: a warm render allocates nothing
        thread_local SubscanlineTracer tracer;
        // Only the edges that touch a line j + l/n of the rows drawn (EdgeTable's LineGrid):
        // the others are never met. The tracer builds the row buckets if a line needs them.
        table.reset(scene, RowBuckets::kOnDemand, LineGrid{0.0, n_, row_lo, row_hi});
        tracer.reset(table);
        accumulate(tracer, scene.width, row_lo, row_hi, out);
    }

private:
    // Eq. 1–3 over the lines `tracer` gives (the priority order of a 2-D scene, or the
    // scanline hidden-surface removal of a ScreenScene): one row of accumulation.
    template <class Tracer>
    void accumulate(Tracer& tracer, int width, int row_lo, int row_hi, Image& out) const {
        thread_local LineIntegralRow current;
        thread_local LineProfile below, above;
        current.reset(width);
        const double border_weight = 0.5 / n_;
        const double inner_weight = 1.0 / n_;

        // The first row's top border: only its limit from below is inside the band.
        tracer.trace(row_lo, below, above);
        bool top_traced = true;  // `below` holds the row's top border (else: trace it again)
        for (int j = row_lo; j < row_hi; ++j) {
            // A row that SubscanlineTracer::add_row proves (crossings that run through it, or
            // one shape's alternating crossings): all n + 1 lines summed change by change or
            // chain by chain, the same sums up to rounding; else line by line.
            if (whole_row(tracer, j, current)) {
                top_traced = false;
            } else {
                if (!top_traced) tracer.trace(j, below, above);
                current.add(below, border_weight);
                for (int l = 1; l < n_; ++l) {
                    const double y = j + static_cast<double>(l) / n_;
                    if (tracer.trace(y, below, above)) {
                        current.add(below, 0.5 * inner_weight);
                        current.add(above, 0.5 * inner_weight);
                    } else {
                        current.add(below, inner_weight);
                    }
                }
                // The border y = j + 1: its limit from above closes row j; its limit from
                // below (the same profile when they agree) opens row j + 1.
                const bool split = tracer.trace(j + 1.0, below, above);
                current.add(split ? above : below, border_weight);
                top_traced = true;
            }
            current.resolve_and_clear(out.row(j));
        }
    }

    bool whole_row(SubscanlineTracer& tracer, int row, LineIntegralRow& sums) const {
        if (!tracer.add_row(row, n_, sums)) return false;
        tracer.advance(row + 1.0);  // the sweep only: the next row may not need the walk
        return true;
    }
    // The scanline visibility of 3-D scenes traces line by line.
    bool whole_row(ScanlineVisibility&, int, LineIntegralRow&) const { return false; }

    int n_;
};

}  // namespace

// What the harness knows of `box-multiscan` (methods/method_traits.h).
MethodTraits box_multiscan_traits() {
    MethodTraits t;
    t.curves = "exact crossings of each sub-scanline: the roots of y(t) = line, no flattening";
    t.own_visibility = true;
    t.coplanar_overlays = true;  // the scanline's tie order (scanline_visibility.h)
    t.affine_values = true;
    t.working_bytes = [](const ParamValues& p, const SceneSize& s) {
        using namespace memory_model;
        // Two rows of per-pixel sums (double, with one pixel of margin each side).
        double bytes =
            edge_table_bytes(s) + kSweepBytesPerEdge * s.vertices + 4.0 * 8.0 * (s.width + 2);
        const int n = p.get_int("n");
        if (n <= SubscanlineTracer::kMaxRowIntervals) {
            // The whole-row sums (subscanline_rows.cpp): per chain met, its x on the n + 1
            // lines (double) and its place among them per line (int), plus a few fields and
            // its entry in the list handed to the sweep, vectors grown by resize (x2); a row
            // meets at most every vertex.
            bytes += (2.0 * 12.0 * (n + 1) + kRowTrackBytes) * s.vertices;
        }
        return bytes;
    };
    t.time_ms = [](const ParamValues& p, const SceneSize& s) {
        using namespace cost_model;
        const double lines = kBoxMultiscanFixed + kBoxMultiscanPerLine * p.get_int("n");
        const double at_default = kBoxMultiscanFixed + kBoxMultiscanPerLine * 3;
        return linear_ms(kBoxMultiscan, s.pixels(), s.vertices) * lines / at_default;
    };
    // Line sampling in y: a horizontal (or nearly horizontal) edge on a sub-scanline takes the
    // mean of the line's two limits; moved off it by any amount, the line sees one limit: a
    // jump of up to (edge length in the pixel) x span / n. The same for the rounding of
    // 2^20 + y: a line j + l/n that is not a dyadic fraction cannot hold a vertex both before
    // and after the move.
    t.hard_cases.properties = {
        {Invariant::kContinuity, CaseSet::kCurveExtremumOnSubscanline,
         DocumentedBound::kLocalChanges,
         "a curve tangent to a sub-scanline, moved by d, changes that line's covered length by "
         "~2 sqrt(2 d / curvature): continuous, but not by less than d"},
        {Invariant::kContinuity, CaseSet::kHorizontalOnSubscanline, DocumentedBound::kLocalChanges,
         "line sampling in y: a horizontal edge moved across a sub-scanline jumps by up to 1/n"},
        {Invariant::kTranslation, CaseSet::kHorizontalOnSubscanline, DocumentedBound::kLocalChanges,
         "2^20 + y rounds y by up to 2^-33 px, off a sub-scanline it lay on: the same jump"},
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kTrapezoidArea,
         "trapezoidal rule in y: exact only where L(y) has no kink inside a sub-band"},
    };
    t.hard_cases.figures = [](const ParamValues& p) {
        return BoundFigures{.sub_scanlines = p.get_int("n")};
    };
    t.hard_cases.heavy = [](const ParamValues& p) { return p.get_int("n") >= 128; };
    t.hard_cases.line_settings = {"n=6", "n=12"};
    t.hard_cases.maximum_settings = {"n=256"};
    return t;
}

MethodInfo box_multiscan_method() {
    return {
        "box-multiscan",
        "n sub-scanlines per row, exact coverage along each, trapezoidal rule in y "
        "(Nishita & Nakamae 1984, eq. 1-3)",
        {{"n",
          ParamKind::kInt,
          3,
          1,
          256,
          {},
          "sub-scanline intervals per pixel row; 3 as in the paper, more for thin shapes"}},
        [](const ParamValues& p) { return std::make_unique<BoxMultiscanMethod>(p.get_int("n")); },
        "n",
        {1, 2, 3, 6, 12, 24}};
}

}  // namespace aabench
