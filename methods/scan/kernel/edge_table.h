// Shared scan-conversion machinery: the scene's edges bucketed by pixel row, the crossings of
// a horizontal line, and the visible value between crossings (nonzero winding per shape, the
// later shape on top). Every scanline method and the exact box reference build on this; no
// method includes another.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "methods/scan/kernel/visibility_rule.h"
#include "patterns/scene/scene.h"

namespace aabench {

// One non-horizontal contour edge, stored top to bottom (y0 < y1). `winding` is +1 when the
// contour runs downwards along it and -1 when upwards: crossing the edge from left to right
// adds `winding` to the shape's winding number (the sign convention is irrelevant for the
// nonzero rule as long as it is the same for every edge).
struct Edge {
    double x0, y0, x1, y1;
    double dxdy;  // (x1 - x0) / (y1 - y0)
    int winding;
    int shape;
    // The edge of the same contour that continues downwards from this edge's bottom vertex
    // (-1 when the contour turns back up there or runs horizontally), and its inverse. A chain
    // of `below` links is a y-monotone piece of a contour: sweeps treat it as one boundary.
    int below = -1;
    int above = -1;

    // x on the edge's line at height y, clamped to the edge's x-range so that a steep
    // extrapolation (dxdy up to 1e12 and more) can never leave the segment; exactly the
    // endpoint's x at y0 and y1, so consecutive edges of a chain meet exactly. Inline: the
    // sweeps call it once per edge per line.
    double x_at(double y) const {
        if (y <= y0) return x0;
        if (y >= y1) return x1;
        // From the nearer endpoint: from a far one, y - y0 rounds away all of y when the edge
        // is 1e300 px long (found by the render fuzzer: an edge from -1e300 came out as x = 0
        // all the way, and the box reference 3e-7 above the value range).
        const double x = y - y0 <= y1 - y ? x0 + (y - y0) * dxdy : x1 - (y1 - y) * dxdy;
        return std::clamp(x, std::min(x0, x1), std::max(x0, x1));
    }
};

// The one contour -> edge-record builder (EdgeTable, the fast exact engine and the scanline
// visibility all build their edges here). Appends the non-horizontal edges of `contour`, the
// boundary of shape `shape`, to `edges`, each stored top to bottom with its winding and its
// chain links (`below`, `above`) to the other edges of the contour appended by this call.
// Only edges reaching into the open y-range (y_lo, y_hi) are kept; the others are dropped and
// link to nothing. `index` is scratch (its memory is reused: no allocation once it has held as
// long a contour).
void append_contour_edges(const Contour& contour, int shape, std::vector<Edge>& edges,
                          std::vector<int>& index,
                          double y_lo = -std::numeric_limits<double>::infinity(),
                          double y_hi = std::numeric_limits<double>::infinity());

// The edges of every contour of `shape` (index `s` in its scene), by append_contour_edges: a
// shape with Bezier segments, when `curve_lines` is not empty, as the polygon through the points
// where its curves cross those lines (polygon_on_lines, patterns/scene/bezier.h), into the
// scratch `on_lines`; otherwise its polygon contours.
void append_shape_edges(const Shape& shape, int s, std::span<const double> curve_lines,
                        Contour& on_lines, std::vector<Edge>& edges, std::vector<int>& index);

// Crossing of a horizontal line with an edge.
struct Crossing {
    double x;
    int winding;
    int shape;
    std::uint32_t edge = 0;  // index in EdgeTable::edges() (kept by EdgeSweep, else unset)
};

// When the row buckets are built. Bucketing writes each edge into every row it spans: on a
// scene of long edges (grating: 2,000 edges spanning all 1,024 rows) that is millions of
// scattered writes, a fifth of a point-sampled render, for a sweep (edge_sweep.h) that only
// needs the buckets when it has to seek.
enum class RowBuckets { kNow, kOnDemand };

// The horizontal lines a multi-scanning method ever asks about: y = (j + offset) + l / n for
// integers j_lo <= j <= j_hi and 0 <= l < n, each computed in double exactly so (the methods'
// own formula: box-multiscan's j + l/n, offset 0; gauss-multiscan's (r + 0.5) + l/n). A table
// built for them (EdgeTable::reset below) keeps only the edges that touch one of them.
// `steps`, when not empty, replaces l / n: line l of row j is (j + offset) + steps[l] (ssaa's
// grid rows j + (l + 0.5)/k, offset 0). It holds n ascending values in [0, 1) evenly spaced
// 1/n apart up to rounding (EdgeTable::reset checks), and must outlive the reset.
struct LineGrid {
    double offset = 0.0;
    int n = 1;
    int j_lo = 0, j_hi = 0;
    std::span<const double> steps = {};
};

// The lines of `lines`, ascending, each computed as the methods compute it: (j + offset) + l/n,
// or (j + offset) + steps[l]. For the methods that hand them to another engine (the scanline
// visibility) as a curve's lines.
void grid_lines(const LineGrid& lines, std::vector<double>& out);

class EdgeTable {
public:
    EdgeTable() = default;
    explicit EdgeTable(const Scene& scene) { reset(scene); }
    // Rebuilds the table for `scene`, reusing the memory it holds: no allocation once it has
    // held a scene at least as large (methods keep one per thread to render allocation-free).
    // kOnDemand leaves the row buckets to build_rows().
    // A shape with Bezier segments is drawn as its flattening (Shape::contours), or, when
    // `curve_lines` (ascending) is given, as the polygon that meets each of those lines where
    // the curve does (polygon_on_lines, patterns/scene/bezier.h): for a caller that asks only
    // about those lines, every crossing is the curve's own, with no flattening.
    void reset(const Scene& scene, RowBuckets rows = RowBuckets::kNow,
               std::span<const double> curve_lines = {});
    // The same table for a caller that asks only about the lines of `lines` (every crossing,
    // crossings_at(), row() and chain walk on those lines gives what the full table gives):
    // an edge lying strictly between two neighbouring lines is never met, so it is left out,
    // and the chain links skip it (the kept edges of a chain meet the lines where the full
    // chain does, with the same x: the same records). Kept besides: every chain's first edge,
    // so that a chain enters the sweep at the same y0 (EdgeSweep::next_entry()) and walks the
    // same paths; a contour with a NaN end is kept whole. Why: a polygonised circle of
    // 1e-7 px sagitta has ~130 edges per pixel row it crosses, of which the n + 1 lines meet
    // 2-3; building and walking the rest was most of box-multiscan's render on `circles`.
    // A shape with Bezier segments is drawn as the polygon meeting every line of the grid
    // where its curves do (polygon_on_lines): the exact crossings, no flattening.
    void reset(const Scene& scene, RowBuckets rows, const LineGrid& lines);
    // Builds the row buckets if reset() left them; else nothing.
    void build_rows();
    bool has_rows() const { return has_rows_; }

    const std::vector<Edge>& edges() const { return edges_; }
    int width() const { return width_; }
    int height() const { return height_; }
    int shape_count() const { return static_cast<int>(shape_values_.size()); }
    double shape_value(int shape) const { return shape_values_[shape]; }
    double background() const { return background_; }

    // Indices of the edges whose y-range overlaps the open row band (r, r+1), r in [0, height),
    // in ascending index. Needs has_rows().
    std::span<const std::uint32_t> row(int r) const;

    // Crossings of the line at height y (0 <= y <= height), sorted by x. An edge counts when
    // y0 <= y < y1 (half-open, so a vertex on the line is counted once, by the edge leaving
    // it downwards); the line y == height uses the last row's edges with y1 == height too.
    // Needs has_rows().
    void crossings_at(double y, std::vector<Crossing>& out) const;

private:
    int width_ = 0, height_ = 0;
    bool has_rows_ = false;
    double background_ = 0.0;
    std::vector<double> shape_values_;
    std::vector<Edge> edges_;
    // CSR: row r's edges are row_edges_[start[r]..start[r+1]).
    std::vector<std::uint32_t> row_start_;
    std::vector<std::uint32_t> row_edges_;
    // append_contour_edges() for reset(scene, rows, lines): the contour's edges that touch a
    // line of `lines`, and its chains' first edges.
    void append_edges_on_lines(const Contour& contour, int shape, const LineGrid& lines);
    // What both reset()s do first: the scene's size and background, the table emptied, and a
    // scene outside its window frame refused (require_window_frame, patterns/scene/scene.h).
    void begin_reset(const Scene& scene);

    std::vector<int> contour_index_;   // scratch of reset(): edge index of each contour edge
    std::vector<double> curve_lines_;  // scratch of reset(lines) on curves: the grid's lines
    Contour on_lines_;                 // scratch of reset() on curves: polygon_on_lines()
    std::vector<double> line_steps_;   // scratch of reset(lines): line l's step, l < n
    std::vector<std::uint32_t> fill_;  // scratch of reset(): next free slot per row
};

// The visible value at a point of a horizontal walk of a 2-D scene: the value of the shape the
// visibility rule (visibility_rule.h) puts on top there, or the background. Feed it crossings
// left to right.
class VisibilityWalker {
public:
    VisibilityWalker() = default;
    explicit VisibilityWalker(const EdgeTable& table) { bind(table); }
    // Walks `table` from now on (reusing the memory held), starting from reset().
    void bind(const EdgeTable& table);
    void reset();
    // Applies one crossing; returns the visible value after it.
    double cross(int shape, int winding);
    double value() const { return value_; }

private:
    const EdgeTable* table_ = nullptr;
    CoverWalk cover_;
    double value_ = 0.0;
};

}  // namespace aabench
