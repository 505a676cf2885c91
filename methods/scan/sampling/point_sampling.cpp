#include "methods/scan/sampling/point_sampling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace aabench {

void PointSampler::reset(const Scene& scene, const LineGrid& lines) {
    table_.reset(scene, RowBuckets::kOnDemand, lines);
    reset_for_table(scene, 0.0);
}

void PointSampler::reset(const Scene& scene, double margin_px,
                         std::span<const double> curve_lines) {
    // Row buckets only if the sweep has to seek (lines sampled out of order).
    table_.reset(scene, RowBuckets::kOnDemand, curve_lines);
    reset_for_table(scene, margin_px);
}

void PointSampler::reset_for_table(const Scene& scene, double margin_px) {
    sweep_.reset(table_);
    cover_.reset(table_.shape_count());
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

template <class Emit>
void PointSampler::walk(double y, std::span<const double> xs, Emit emit) {
    const std::span<const Crossing> crossings = gather_crossings(y);
    std::size_t next = 0;
    const std::size_t count = crossings.size();
    for (std::size_t n = 0; n < xs.size(); ++n) {
        const double x = xs[n];
        // `<=`: a sample on an edge takes the region to its right (the tie rule above).
        while (next < count && crossings[next].x <= x) {
            cover_.cross(crossings[next].shape, crossings[next].winding);
            ++next;
        }
        emit(n, cover_.seen(inv_depth_, x, y));
    }
    // Crossings right of the last sample were never applied: clear what was.
    cover_.clear();
}

void PointSampler::sample_centres(double y, std::span<float> out) {
    centre_runs(y, out.size(), [&](std::size_t first, std::size_t end, int top) {
        const float value =
            static_cast<float>(top < 0 ? table_.background() : table_.shape_value(top));
        std::fill(out.begin() + first, out.begin() + end, value);
    });
}

void PointSampler::sample_value_runs(double y, std::span<const double> xs,
                                     std::span<double> values, std::vector<std::uint32_t>& starts) {
    starts.clear();
    if (xs.empty()) return;
    thread_local ValueRuns runs;  // kept: a warm call allocates nothing
    sample_runs(y, xs, runs);
    runs.write(values.first(xs.size()));
    for (const std::uint32_t change : runs.changes()) starts.push_back(change);
}

void PointSampler::sample_runs(double y, std::span<const double> xs, ValueRuns& runs) {
    // The runs are the changes of sample_changes (one walk of the crossings, written once),
    // after sample 0's run, whose value that walk returns at its end.
    runs.clear();
    runs.starts.push_back(0);
    runs.values.push_back(0.0);
    const double first = sample_changes(y, xs, [&](std::size_t n, double, double after) {
        runs.starts.push_back(static_cast<std::uint32_t>(n));
        runs.values.push_back(after);
    });
    runs.values.front() = first;
}

void PointSampler::sample_top_runs(double y, std::span<const double> xs, TopRuns& runs) {
    // sample_runs() with the shape for the value.
    runs.clear();
    runs.starts.push_back(0);
    runs.values.push_back(-1);
    const int first = sample_changes_of(
        y, xs,
        [&](std::size_t n, int, int after) {
            runs.starts.push_back(static_cast<std::uint32_t>(n));
            runs.values.push_back(after);
        },
        [](int top) { return top; });
    runs.values.front() = first;
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
