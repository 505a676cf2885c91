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
    // Edges are in window coordinates: a caller that forgot in_window_frame() (patterns/scene/scene.h)
    // would render the wrong part of the plane, silently. Say so instead.
    if (has_origin(scene)) {
        throw std::logic_error("EdgeTable: scene has a window origin; pass in_window_frame(scene)");
    }
    for (int s = 0; s < static_cast<int>(scene.shapes.size()); ++s) {
        const Shape& shape = scene.shapes[s];
        shape_values_.push_back(shape.value);
        for (const Contour& contour : shape.contours) {
            const std::size_t n = contour.size();
            // Index in edges_ of contour edge k (from point k to k + 1), -1 if horizontal.
            std::vector<int>& index = contour_index_;
            index.assign(n, -1);
            for (std::size_t k = 0; k < n; ++k) {
                const Point a = contour[k];
                const Point b = contour[(k + 1) % n];
                // Horizontal edges change no winding number on any horizontal walk, and
                // contribute no area: they are dropped.
                if (a.y == b.y) continue;
                index[k] = static_cast<int>(edges_.size());
                Edge e;
                e.winding = a.y < b.y ? 1 : -1;
                const Point top = a.y < b.y ? a : b;
                const Point bottom = a.y < b.y ? b : a;
                e.x0 = top.x;
                e.y0 = top.y;
                e.x1 = bottom.x;
                e.y1 = bottom.y;
                e.dxdy = (e.x1 - e.x0) / (e.y1 - e.y0);
                e.shape = s;
                edges_.push_back(e);
            }
            // Chain links: edge k running down continues into edge k + 1 if that one runs down
            // too (they share point k + 1); edge k running up continues downwards into edge
            // k - 1 if that one runs up too (they share point k).
            for (std::size_t k = 0; k < n; ++k) {
                const int cur = index[k], next = index[(k + 1) % n];
                if (cur < 0 || next < 0 || cur == next) continue;
                const bool cur_down = edges_[cur].winding > 0, next_down = edges_[next].winding > 0;
                if (cur_down && next_down) {
                    edges_[cur].below = next;
                    edges_[next].above = cur;
                } else if (!cur_down && !next_down) {
                    edges_[next].below = cur;
                    edges_[cur].above = next;
                }
            }
        }
    }
    if (rows == RowBuckets::kNow) build_rows();
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
    winding_.assign(table.shape_count(), 0);
    nonzero_stack_.clear();
    value_ = table.background();
}

void VisibilityWalker::reset() {
    for (int s : nonzero_stack_) winding_[s] = 0;
    nonzero_stack_.clear();
    value_ = table_->background();
}

double VisibilityWalker::cross(int shape, int winding) {
    const int before = winding_[shape];
    const int after = before + winding;
    winding_[shape] = after;
    if (before == 0 && after != 0) {
        nonzero_stack_.push_back(shape);
        update_top();
    } else if (before != 0 && after == 0) {
        nonzero_stack_.erase(std::find(nonzero_stack_.begin(), nonzero_stack_.end(), shape));
        update_top();
    }
    return value_;
}

void VisibilityWalker::update_top() {
    // Few shapes overlap at any one point in practice, so a linear scan for the topmost
    // (largest index) beats a balanced tree.
    if (nonzero_stack_.empty()) {
        value_ = table_->background();
        return;
    }
    value_ = table_->shape_value(*std::max_element(nonzero_stack_.begin(), nonzero_stack_.end()));
}

}  // namespace aabench
