#include "methods/scan/kernel/edge_table.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "patterns/scene/bezier.h"

namespace aabench {

void EdgeTable::begin_reset(const Scene& scene) {
    has_rows_ = false;
    width_ = scene.width;
    height_ = scene.height;
    background_ = scene.background;
    shape_values_.clear();
    edges_.clear();
    require_window_frame(scene, "EdgeTable");
}

void EdgeTable::reset(const Scene& scene, RowBuckets rows, std::span<const double> curve_lines) {
    begin_reset(scene);
    for (int s = 0; s < static_cast<int>(scene.shapes.size()); ++s) {
        const Shape& shape = scene.shapes[s];
        shape_values_.push_back(shape.value);
        append_shape_edges(shape, s, curve_lines, on_lines_, edges_, contour_index_);
    }
    if (rows == RowBuckets::kNow) build_rows();
}

namespace {

// How far a grid's own steps may lie from steps[0] + l/n, in units of the line spacing 1/n:
// rounding puts ssaa's (l + 0.5)/k within 1e-15 of it; LineTouch::gap() tolerates up to its
// kMargin (1e-4), so anything past this tolerance is a grid of other spacing, refused.
constexpr double kStepTolerance = 1e-9;

// The edge from `top` to `bottom` (top.y < bottom.y) of a contour edge that runs down (winding
// +1) or up (-1).
Edge edge_between(const Point& top, const Point& bottom, bool down, int shape) {
    Edge e;
    e.x0 = top.x;
    e.y0 = top.y;
    e.x1 = bottom.x;
    e.y1 = bottom.y;
    e.dxdy = (e.x1 - e.x0) / (e.y1 - e.y0);
    e.winding = down ? 1 : -1;
    e.shape = shape;
    return e;
}

// Whether a line of `grid` lies in [y0, y1] (y0 <= y1, neither NaN). Line (j, l) is computed
// as the methods compute it, (j + offset) + steps[l] (`steps`: l/n or the grid's own), so "on
// a line" is decided bit for bit as they decide it.
class LineTouch {
public:
    LineTouch(const LineGrid& grid, const std::vector<double>& steps)
        : offset_(grid.offset),
          n_(grid.n),
          scale_(grid.n),
          steps_(steps.data()),
          j_lo_(grid.j_lo),
          j_hi_(grid.j_hi),
          bias_(1.0 - (grid.offset + steps[0] + j_lo_) * grid.n),
          first_(line(j_lo_, 0)),
          last_(line(j_hi_, grid.n - 1)) {}

    bool operator()(double y0, double y1) const {
        if (y1 < first_ || y0 > last_) return false;
        if (y0 <= first_) return true;  // and y1 >= first_
        // The lowest line at or past y0 (first_ < y0 <= last_, so it exists and is not the
        // first), from a guess corrected by comparing the lines' own values.
        double j = std::clamp(std::floor(y0 - offset_), j_lo_, j_hi_);
        int l = static_cast<int>(std::clamp((y0 - (j + offset_)) * scale_, 0.0, n_ - 1.0));
        for (;;) {  // back while the line before is still at or past y0
            const double pj = l > 0 ? j : j - 1.0;
            const int pl = l > 0 ? l - 1 : n_ - 1;
            if (pj < j_lo_ || !(line(pj, pl) >= y0)) break;
            j = pj;
            l = pl;
        }
        while (line(j, l) < y0) {  // up: stops at the last line at the latest (last_ >= y0)
            if (++l == n_) {
                l = 0;
                j += 1.0;
            }
        }
        return line(j, l) <= y1;
    }

    // Most edges of a fine polygonisation lie well inside one gap between lines, decided
    // here per vertex: in units of the line spacing, u = y n + bias puts line (j, l) within
    // ~1e-7 of the integer (j - j_lo) n + l + 1 while u < 2^28 (the computed u is monotone
    // in y; steps evenly spaced from steps[0] within kStepTolerance). A vertex kMargin inside the
    // gap (g, g + 1) gets g, any other -1: an edge whose two ends get the same g >= 0 meets no
    // line. (Truncation, not std::floor: u >= 0 here, and without SSE4.1 std::floor is a call.)
    std::int64_t gap(double y) const {
        const double u = y * scale_ + bias_;
        if (!(u >= 0.0 && u < kMaxFastU)) return -1;  // NaN too
        const auto g = static_cast<std::int64_t>(u);
        const double f = u - static_cast<double>(g);
        return f > kMargin && f < 1.0 - kMargin ? g : -1;
    }

private:
    static constexpr double kMargin = 1e-4;
    static constexpr double kMaxFastU = 268435456.0;  // 2^28

    double line(double j, int l) const { return (j + offset_) + steps_[l]; }

    double offset_;
    int n_;
    double scale_;
    const double* steps_;
    double j_lo_, j_hi_;
    double bias_;
    double first_, last_;
};

}  // namespace

void grid_lines(const LineGrid& lines, std::vector<double>& out) {
    out.clear();
    for (int j = lines.j_lo; j <= lines.j_hi; ++j) {
        for (int l = 0; l < lines.n; ++l) {
            const double step = lines.steps.empty() ? static_cast<double>(l) / lines.n : lines.steps[l];
            out.push_back((j + lines.offset) + step);
        }
    }
}

void EdgeTable::reset(const Scene& scene, RowBuckets rows, const LineGrid& lines) {
    begin_reset(scene);
    if (lines.n < 1 || lines.j_hi < lines.j_lo) {
        throw std::logic_error("EdgeTable: an empty line grid");
    }
    if (!lines.steps.empty() && lines.steps.size() != static_cast<std::size_t>(lines.n)) {
        throw std::logic_error("EdgeTable: a line grid with steps for other than n lines");
    }
    line_steps_.resize(static_cast<std::size_t>(lines.n));
    for (int l = 0; l < lines.n; ++l) {
        if (lines.steps.empty()) {
            line_steps_[l] = static_cast<double>(l) / lines.n;
            continue;
        }
        // LineTouch::gap() places the lines by their spacing from the first: a grid whose
        // steps are not 1/n apart would be told the wrong gaps, and edges it meets dropped.
        const double step = lines.steps[l];
        const double spacing_units = (step - lines.steps[0]) * lines.n - l;
        if (!(std::abs(spacing_units) <= kStepTolerance && step >= 0.0 && step < 1.0)) {
            throw std::logic_error("EdgeTable: a line grid whose steps are not 1/n apart");
        }
        line_steps_[l] = step;
    }
    curve_lines_.clear();
    // The grid's lines, computed as the methods compute them: a curve's polygon has its
    // vertices on them (polygon_on_lines), so each line meets it where it meets the curve.
    if (has_bezier(scene)) grid_lines(lines, curve_lines_);
    for (int s = 0; s < static_cast<int>(scene.shapes.size()); ++s) {
        const Shape& shape = scene.shapes[s];
        shape_values_.push_back(shape.value);
        if (has_bezier(shape)) {
            for (const SegmentContour& outline : shape.outline) {
                polygon_on_lines(outline, curve_lines_, on_lines_);
                append_edges_on_lines(on_lines_, s, lines);
            }
            continue;
        }
        for (const Contour& contour : shape.contours) append_edges_on_lines(contour, s, lines);
    }
    if (rows == RowBuckets::kNow) build_rows();
}

void EdgeTable::append_edges_on_lines(const Contour& contour, int shape, const LineGrid& lines) {
    const std::size_t n = contour.size();
    const std::size_t first_edge = edges_.size();
    const LineTouch touches(lines, line_steps_);
    // Direction of an edge from height a to height b, as append_contour_edges() decides it:
    // 0 horizontal (dropped there too), +1 down, -1 up (a NaN end reads as up).
    const auto direction = [](double a, double b) { return a == b ? 0 : (a < b ? 1 : -1); };
    if (n == 0) return;
    // Chain links as the edges are kept: each kept edge links to the last kept edge of its run
    // of one direction (a run down is a chain downwards in contour order, a run up one in
    // reverse order), over the dropped ones. The run that wraps around the contour's end
    // continues in the first edges: linked after the loop.
    int last_kept = -1;       // in the current run
    int first_run_kept = -1;  // the first kept edge before the first change of direction
    const auto link = [&](int dir, int earlier, int later) {  // in contour order
        if (dir > 0) {
            edges_[earlier].below = later;
            edges_[later].above = earlier;
        } else {
            edges_[later].below = earlier;
            edges_[earlier].above = later;
        }
    };
    std::size_t boundary = n;  // the first edge whose direction differs from the one before it
    bool nan = false;
    // Edge k runs from y_a to y_b, edge k + 1 on to y_c; each vertex's gap computed once.
    double y_a = contour[0].y, y_b = contour[n == 1 ? 0 : 1].y;
    std::int64_t gap_a = touches.gap(y_a), gap_b = touches.gap(y_b);
    int before = direction(contour[n - 1].y, y_a), dir = direction(y_a, y_b);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t k1 = k + 1 == n ? 0 : k + 1;
        const double y_c = contour[k1 + 1 == n ? 0 : k1 + 1].y;
        const int after = direction(y_b, y_c);
        if (dir != before) {
            if (boundary == n) boundary = k;
            last_kept = -1;
        }
        if (dir != 0) {
            const bool down = dir > 0;
            const double top_y = down ? y_a : y_b, bottom_y = down ? y_b : y_a;
            if (!(top_y < bottom_y)) {  // NaN
                nan = true;
                break;
            }
            // A chain's first edge: the one before it (down) or after it (up) in the contour
            // does not continue the chain upwards.
            const bool head = (down ? before : after) != dir;
            const bool between = gap_a == gap_b && gap_a >= 0;
            if (head || (!between && touches(top_y, bottom_y))) {
                const Point& top = down ? contour[k] : contour[k1];
                const Point& bottom = down ? contour[k1] : contour[k];
                const int cur = static_cast<int>(edges_.size());
                edges_.push_back(edge_between(top, bottom, down, shape));
                if (last_kept >= 0) link(dir, last_kept, cur);
                if (boundary == n && first_run_kept < 0) first_run_kept = cur;
                last_kept = cur;
            }
        }
        before = dir;
        dir = after;
        y_a = y_b;
        y_b = y_c;
        gap_a = gap_b;
        gap_b = touches.gap(y_c);
    }
    if (boundary == n || nan) {
        // Every edge runs one way (all horizontal), or an end is NaN (whose chains this does
        // not try to follow): the full contour, as reset(scene) builds it.
        edges_.resize(first_edge);
        append_contour_edges(contour, shape, edges_, contour_index_);
        return;
    }
    // boundary > 0: the last edge's run goes on into edge 0's (their directions agree).
    if (boundary > 0 && last_kept >= 0 && first_run_kept >= 0) {
        link(edges_[last_kept].winding, last_kept, first_run_kept);
    }
}

void append_shape_edges(const Shape& shape, int s, std::span<const double> curve_lines,
                        Contour& on_lines, std::vector<Edge>& edges, std::vector<int>& index) {
    if (has_bezier(shape) && !curve_lines.empty()) {
        for (const SegmentContour& outline : shape.outline) {
            polygon_on_lines(outline, curve_lines, on_lines);
            append_contour_edges(on_lines, s, edges, index);
        }
        return;
    }
    for (const Contour& contour : shape.contours) append_contour_edges(contour, s, edges, index);
}

void append_contour_edges(const Contour& contour, int shape, std::vector<Edge>& edges,
                          std::vector<int>& index, double y_lo, double y_hi) {
    const std::size_t n = contour.size();
    // Index in `edges` of contour edge k (from point k to k + 1), -1 if dropped.
    index.assign(n, -1);
    // k + 1 wrapped by a compare, not `% n`: an integer division per vertex was a tenth of
    // the fast engine's setup on rings.
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t k1 = k + 1 == n ? 0 : k + 1;
        const Point a = contour[k];
        const Point b = contour[k1];
        // Horizontal edges change no winding number on any horizontal walk, and contribute no
        // area: they are dropped.
        if (a.y == b.y) continue;
        const bool down = a.y < b.y;
        const Point& top = down ? a : b;
        const Point& bottom = down ? b : a;
        if (bottom.y <= y_lo || top.y >= y_hi) continue;  // outside the y-range asked for
        index[k] = static_cast<int>(edges.size());
        edges.push_back(edge_between(top, bottom, down, shape));
    }
    // Chain links: edge k running down continues into edge k + 1 if that one runs down too
    // (they share point k + 1); edge k running up continues downwards into edge k - 1 if that
    // one runs up too (they share point k).
    for (std::size_t k = 0; k < n; ++k) {
        const int cur = index[k], next = index[k + 1 == n ? 0 : k + 1];
        if (cur < 0 || next < 0 || cur == next) continue;
        const bool cur_down = edges[cur].winding > 0, next_down = edges[next].winding > 0;
        if (cur_down && next_down) {
            edges[cur].below = next;
            edges[next].above = cur;
        } else if (!cur_down && !next_down) {
            edges[next].below = cur;
            edges[cur].above = next;
        }
    }
}

void EdgeTable::build_rows() {
    if (has_rows_) return;
    has_rows_ = true;
    // Bucket the edges by the rows whose open band (r, r+1) they overlap: a counting pass,
    // then a fill pass (compressed sparse rows).
    auto row_range = [&](const Edge& e, int& first, int& last) {
        first = static_cast<int>(std::max(0.0, std::floor(e.y0)));
        last = static_cast<int>(std::min<double>(height_, std::ceil(e.y1))) - 1;
    };
    row_start_.assign(static_cast<std::size_t>(height_) + 1, 0);
    for (const Edge& e : edges_) {
        if (e.y1 <= 0.0 || e.y0 >= height_) continue;
        int first, last;
        row_range(e, first, last);
        for (int r = first; r <= last; ++r) ++row_start_[r + 1];
    }
    for (int r = 0; r < height_; ++r) row_start_[r + 1] += row_start_[r];
    row_edges_.resize(row_start_[height_]);
    std::vector<std::uint32_t>& fill = fill_;
    fill.assign(row_start_.begin(), row_start_.end() - 1);
    for (std::uint32_t idx = 0; idx < edges_.size(); ++idx) {
        const Edge& e = edges_[idx];
        if (e.y1 <= 0.0 || e.y0 >= height_) continue;
        int first, last;
        row_range(e, first, last);
        for (int r = first; r <= last; ++r) row_edges_[fill[r]++] = idx;
    }
}

std::span<const std::uint32_t> EdgeTable::row(int r) const {
    if (!has_rows_) throw std::logic_error("EdgeTable::row: row buckets not built (build_rows)");
    return {row_edges_.data() + row_start_[r], row_edges_.data() + row_start_[r + 1]};
}

void EdgeTable::crossings_at(double y, std::vector<Crossing>& out) const {
    out.clear();
    if (!(y >= 0.0 && y <= height_) || height_ == 0) return;
    const bool bottom_line = y == height_;
    const int r = std::min(static_cast<int>(std::floor(y)), height_ - 1);
    for (const std::uint32_t idx : row(r)) {
        const Edge& e = edges_[idx];
        const bool hit = bottom_line ? (e.y0 < y && e.y1 >= y) : (e.y0 <= y && y < e.y1);
        if (hit) out.push_back({e.x_at(y), e.winding, e.shape});
    }
    std::sort(out.begin(), out.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
}

void VisibilityWalker::bind(const EdgeTable& table) {
    table_ = &table;
    cover_.reset(table.shape_count());
    value_ = table.background();
}

void VisibilityWalker::reset() {
    cover_.clear();
    value_ = table_->background();
}

double VisibilityWalker::cross(int shape, int winding) {
    cover_.cross(shape, winding);
    const int top = cover_.top();
    value_ = top < 0 ? table_->background() : table_->shape_value(top);
    return value_;
}

}  // namespace aabench
