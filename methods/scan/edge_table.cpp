#include "methods/scan/edge_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aabench {

void EdgeTable::reset(const Scene& scene, RowBuckets rows) {
    has_rows_ = false;
    width_ = scene.width;
    height_ = scene.height;
    background_ = scene.background;
    shape_values_.clear();
    edges_.clear();
    // Edges are in window coordinates: a caller that forgot in_window_frame()
    // (patterns/scene/scene.h) would render the wrong part of the plane, silently. Say so instead.
    if (has_origin(scene)) {
        throw std::logic_error("EdgeTable: scene has a window origin; pass in_window_frame(scene)");
    }
    for (int s = 0; s < static_cast<int>(scene.shapes.size()); ++s) {
        const Shape& shape = scene.shapes[s];
        shape_values_.push_back(shape.value);
        for (const Contour& contour : shape.contours) {
            append_contour_edges(contour, s, edges_, contour_index_);
        }
    }
    if (rows == RowBuckets::kNow) build_rows();
}

void append_contour_edges(const Contour& contour, int shape, std::vector<Edge>& edges,
                          std::vector<int>& index, Point origin, double y_lo, double y_hi) {
    const std::size_t n = contour.size();
    // Index in `edges` of contour edge k (from point k to k + 1), -1 if dropped.
    index.assign(n, -1);
    // k + 1 wrapped by a compare, not `% n`: an integer division per vertex was a tenth of
    // the fast engine's setup on rings.
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t k1 = k + 1 == n ? 0 : k + 1;
        const Point a{contour[k].x - origin.x, contour[k].y - origin.y};
        const Point b{contour[k1].x - origin.x, contour[k1].y - origin.y};
        // Horizontal edges change no winding number on any horizontal walk, and contribute no
        // area: they are dropped.
        if (a.y == b.y) continue;
        const bool down = a.y < b.y;
        const Point& top = down ? a : b;
        const Point& bottom = down ? b : a;
        if (bottom.y <= y_lo || top.y >= y_hi) continue;  // outside the y-range asked for
        index[k] = static_cast<int>(edges.size());
        Edge e;
        e.x0 = top.x;
        e.y0 = top.y;
        e.x1 = bottom.x;
        e.y1 = bottom.y;
        e.dxdy = (e.x1 - e.x0) / (e.y1 - e.y0);
        e.winding = down ? 1 : -1;
        e.shape = shape;
        edges.push_back(e);
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
