#include "methods/scan/point_sampling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aabench {

void PointSampler::reset(const Scene& scene, double margin_px) {
    // Row buckets only if the sweep has to seek (lines sampled out of order).
    table_.reset(scene, RowBuckets::kOnDemand);
    sweep_.reset(table_);
    winding_.assign(table_.shape_count(), 0);
    nonzero_.clear();
    top_ = -1;
    margin_edges_.clear();
    inv_depth_.clear();
    planes_.clear();
    has_value_plane_.clear();
    bool depth = false, affine = false;
    for (const Shape& shape : scene.shapes) {
        depth = depth || shape.inv_depth.has_value();
        affine = affine || shape.value_plane.has_value();
    }
    if (depth) {
        for (const Shape& shape : scene.shapes) {
            if (!shape.inv_depth) {
                throw std::invalid_argument(
                    "PointSampler: a scene with depth planes needs one on every shape");
            }
            inv_depth_.push_back(*shape.inv_depth);
        }
    }
    if (affine) {
        for (const Shape& shape : scene.shapes) {
            planes_.push_back(shape.value_plane.value_or(AffinePlane{shape.value, 0.0, 0.0}));
            has_value_plane_.push_back(shape.value_plane.has_value());
        }
    }
    one_shape_ = table_.shape_count() == 1 && inv_depth_.empty();
    if (margin_px > 0.0) {
        const double h = table_.height();
        const auto& edges = table_.edges();
        for (std::uint32_t idx = 0; idx < edges.size(); ++idx) {
            const Edge& e = edges[idx];
            // The half-open y-range [y0, y1) meets [-margin, 0) or [h, h + margin).
            const bool above = e.y0 < 0.0 && e.y1 > -margin_px;
            const bool below = e.y1 > h && e.y0 < h + margin_px;
            if (above || below) margin_edges_.push_back(idx);
        }
    }
}

std::span<const Crossing> PointSampler::gather_crossings(double y) {
    if (y >= 0.0 && y < table_.height()) return sweep_.crossings(y);
    // Margin band: the same half-open rule as EdgeTable::crossings_at on interior lines.
    crossings_.clear();
    const auto& edges = table_.edges();
    for (const std::uint32_t idx : margin_edges_) {
        const Edge& e = edges[idx];
        if (e.y0 <= y && y < e.y1) crossings_.push_back({e.x_at(y), e.winding, e.shape});
    }
    std::sort(crossings_.begin(), crossings_.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    return crossings_;
}

void PointSampler::clear_walk() {
    if (one_shape_) winding_[0] = 0;
    for (const int s : nonzero_) winding_[s] = 0;
    nonzero_.clear();
    top_ = -1;
}

void PointSampler::cross(int shape, int winding) {
    if (one_shape_) {
        // One shape without depth: the nonzero rule is one counter (nonzero_ unused).
        winding_[0] += winding;
        top_ = winding_[0] != 0 ? 0 : -1;
        return;
    }
    const int before = winding_[shape];
    const int after = before + winding;
    winding_[shape] = after;
    if (before == 0 && after != 0) {
        nonzero_.push_back(shape);
        top_ = std::max(top_, shape);
    } else if (before != 0 && after == 0) {
        nonzero_.erase(std::find(nonzero_.begin(), nonzero_.end(), shape));
        // Only losing the topmost shape needs a rescan; few shapes overlap at one point, so a
        // linear scan beats a balanced tree.
        if (shape == top_) {
            top_ = nonzero_.empty() ? -1 : *std::max_element(nonzero_.begin(), nonzero_.end());
        }
    }
}

int PointSampler::nearest_at(double x, double y) const {
    if (nonzero_.size() <= 1) return nonzero_.empty() ? -1 : nonzero_[0];
    int best = nonzero_[0];
    double best_w = inv_depth_[best].at(x, y);
    for (std::size_t k = 1; k < nonzero_.size(); ++k) {
        const int s = nonzero_[k];
        const double w = inv_depth_[s].at(x, y);
        // Equal depth: the later shape, as in 2-D.
        if (w > best_w || (w == best_w && s > best)) {
            best = s;
            best_w = w;
        }
    }
    return best;
}

template <class Emit>
void PointSampler::walk(double y, std::span<const double> xs, Emit emit) {
    const std::span<const Crossing> crossings = gather_crossings(y);
    std::size_t next = 0;
    const std::size_t count = crossings.size();
    for (std::size_t n = 0; n < xs.size(); ++n) {
        const double x = xs[n];
        // `<=`: a sample on an edge takes the region to its right (the tie rule above).
        while (next < count && crossings[next].x <= x) {
            cross(crossings[next].shape, crossings[next].winding);
            ++next;
        }
        emit(n, inv_depth_.empty() ? top_ : nearest_at(x, y));
    }
    // Crossings right of the last sample were never applied: clear what was.
    clear_walk();
}

void PointSampler::sample_centres(double y, std::span<float> out) {
    const std::span<const Crossing> crossings = gather_crossings(y);
    const std::size_t width = out.size();
    const double last_centre = static_cast<double>(width) - 0.5;
    auto value = [&] {
        return static_cast<float>(top_ < 0 ? table_.background() : table_.shape_value(top_));
    };
    float current = value();
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
            std::fill(out.begin() + filled, out.begin() + first, current);
            filled = first;
        }
        cross(c.shape, c.winding);
        current = value();
    }
    std::fill(out.begin() + filled, out.end(), current);
    clear_walk();
}

void PointSampler::sample_top(double y, std::span<const double> xs, std::span<int> top) {
    walk(y, xs, [&](std::size_t n, int t) { top[n] = t; });
}

void PointSampler::sample_values(double y, std::span<const double> xs,
                                 std::span<double> values) {
    if (planes_.empty()) {
        walk(y, xs, [&](std::size_t n, int t) {
            values[n] = t < 0 ? table_.background() : table_.shape_value(t);
        });
        return;
    }
    walk(y, xs, [&](std::size_t n, int t) { values[n] = value_at(t, xs[n], y); });
}

}  // namespace aabench
