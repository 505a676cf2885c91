// SubscanlineTracer::AlternatingRow (methods/scan/multiscan/subscanline.h): the state and the
// phases of add_alternating_row(), box-multiscan's and gauss-multiscan's whole rows where
// chains start or end inside the row (subscanline_rows.cpp; docs/methods-multiscan.md, "Whole
// rows, change by change"). Only subscanline_rows.cpp includes this.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "methods/scan/multiscan/subscanline.h"

namespace aabench {
namespace detail {

// How many crossings ahead add_alternating_row() asks for a chain's next edge record.
inline constexpr std::size_t kPrefetchAhead = 8;

// Asks for the cache lines of edge record `idx` (a record of 56 bytes may straddle two).
// Always inlined: GCC finds a call of it free of side effects (a prefetch changes no memory)
// and drops the call, with the prefetches, where it is not inlined.
[[gnu::always_inline]] inline void prefetch_edge(const std::vector<Edge>& edges,
                                                 std::uint32_t idx) {
    const char* record = reinterpret_cast<const char*>(edges.data() + idx);
    __builtin_prefetch(record);
    __builtin_prefetch(record + sizeof(Edge) - 1);
}

// Edge records ahead of their use in add_alternating_row()'s walk over the last line's
// crossings `top`, at crossing i: the chain's own edge record 2 kPrefetchAhead crossings
// ahead, and its next edge (read when the chain reaches it, a row or a few later)
// kPrefetchAhead ahead. A zone plate's 160,000 edge records (9 MB) are far from the cache
// otherwise.
[[gnu::always_inline]] inline void prefetch_chains(const std::vector<Edge>& edges,
                                                   std::span<const Crossing> top, std::size_t i) {
    const std::size_t m = top.size();
    if (i + 2 * kPrefetchAhead < m) prefetch_edge(edges, top[i + 2 * kPrefetchAhead].edge);
    if (i + kPrefetchAhead < m) {
        const std::uint32_t ahead = top[i + kPrefetchAhead].edge;
        const int below = edges[ahead].below;
        if (below >= 0) {
            prefetch_edge(edges, static_cast<std::uint32_t>(below));
            // The record after `below` in the chain's direction, assuming the chain's
            // records lie one stride apart (contour order; a table that dropped edges
            // between lines breaks this, and the prefetch is then only wasted).
            const std::uint32_t after = 2 * static_cast<std::uint32_t>(below) - ahead;
            if (after < edges.size()) prefetch_edge(edges, after);
        }
    }
}

}  // namespace detail

// add_alternating_row()'s row: the heights of its lines, the chains of the last line (`top`)
// and those entering in the row, and the phases that check and add them. Every crossing
// changes the value: by d = inside - outside where the winding number becomes s, by -d where
// it returns to 0. s is the first crossing's winding (the last line's first, else the first
// entering one's). Every member is inlined into add_alternating_row(): its state stays in
// registers and its loops are compiled as one function's.
class SubscanlineTracer::AlternatingRow {
public:
    [[gnu::always_inline]] AlternatingRow(SubscanlineTracer& tracer, double y_top, int n)
        : t_(tracer),
          edges_(tracer.table_->edges()),
          top_(tracer.sweep_.last_crossings()),
          m_(top_.size()),
          n_(n),
          lines_(n + 1),
          y_end_(y_top + 1.0),
          d_(tracer.table_->shape_value(0) - tracer.table_->background()) {
        for (int l = 0; l < n; ++l) {
            ys_[l] = y_top + static_cast<double>(l) / n;
            fraction_[l] = static_cast<double>(l) / n;
        }
        ys_[n] = y_end_;
    }

    // The chains entering inside the row, the tracks' storage and s; false when a chain
    // enters exactly on an interior line (there the line's two limits differ).
    [[gnu::always_inline]] bool prepare() {
        const std::span<const std::uint32_t> heads = t_.sweep_.entering_before(y_end_);
        t_.entering_.assign(heads.begin(), heads.end());
        t_.bottom_order_.clear();
        for (const std::uint32_t head : t_.entering_) {
            for (int l = 1; l < n_; ++l) {
                if (ys_[l] == edges_[head].y0) return false;
            }
        }
        const std::size_t tracks = m_ + t_.entering_.size();
        t_.track_x_.resize(tracks * lines_);
        t_.track_first_.resize(tracks);
        t_.track_end_.resize(tracks);
        t_.track_dv_.resize(tracks);
        t_.track_edge_.resize(tracks);
        entering_ = !t_.entering_.empty();  // before_ serves only to place entering chains
        if (entering_) t_.before_.resize((m_ + 1) * lines_);
        s_ = m_ > 0 ? top_[0].winding : 0;
        for (const std::uint32_t head : t_.entering_) {
            if (s_ == 0) s_ = edges_[head].winding;
        }
        return true;
    }

    // The crossings of the last line: on every line, those present must be in order and
    // alternate in winding, s, -s, s, ... (the winding number is 0 or s between them). Each
    // chain is added to `sums` as soon as it has passed its checks; false: a check failed.
    template <class Tracks>
    [[gnu::always_inline]] bool add_last_line(Tracks& sums) {
        const std::size_t m = m_;
        const int lines = lines_;
        double last[kMaxRowIntervals + 1];
        int present[kMaxRowIntervals + 1];
        // While every chain so far is present on every line, the checks need no per-line
        // state: the previous chain's x (and its range: chains whose ranges over the row do not
        // overlap are in order on every line), and i chains before this one on every line.
        bool uniform = true;
        const double* previous = nullptr;
        double previous_hi = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < m; ++i) {
            const int w = top_[i].winding;
            if (w != 1 && w != -1) return false;
            double* xs = t_.track_x_.data() + i * lines;
            detail::prefetch_chains(edges_, top_, i);
            double lo, hi;
            if (!last_line_track(i, xs, lo, hi)) return false;
            const double dv = d_ * w * s_;
            if (uniform && t_.track_end_[i] == lines) {
                if (w != (i % 2 == 0 ? s_ : -s_)) return false;
                if (previous && !(lo >= previous_hi)) {
                    bool in_order = true;
                    for (int l = 0; l < lines; ++l) in_order &= !(xs[l] < previous[l]);
                    if (!in_order) return false;  // chains cross in the row
                }
                if (entering_) {
                    for (int l = 0; l < lines; ++l) before(l, i) = static_cast<int>(i);
                }
                previous = xs;
                previous_hi = hi;
                add_track(sums, i, lo, hi, dv);
                continue;
            }
            if (uniform) {  // the first chain that ends in the row: per-line state from here
                uniform = false;
                for (int l = 0; l < lines; ++l) {
                    last[l] = previous ? previous[l] : -std::numeric_limits<double>::infinity();
                    present[l] = static_cast<int>(i);
                }
            }
            for (int l = 0; l < lines; ++l) {
                if (entering_) before(l, i) = present[l];
                if (l >= t_.track_end_[i]) {
                    xs[l] = last[l];  // absent: the x of the last present one left of it
                    continue;
                }
                if (xs[l] < last[l]) return false;  // chains cross in the row
                if (w != (present[l] % 2 == 0 ? s_ : -s_)) return false;
                last[l] = xs[l];
                ++present[l];
            }
            add_track(sums, i, lo, hi, dv);
        }
        if (entering_) {
            if (uniform) std::fill(present, present + lines, static_cast<int>(m));
            for (int l = 0; l < lines; ++l) before(l, m) = present[l];
        }
        return true;
    }

    // The entering chains, line by line: each lies strictly inside one gap of the last
    // line's chains (found by x), and the entering chains of one gap, left to right,
    // alternate from the winding the gap calls for (a shape's top outside the shape, a
    // hole's top inside it) and are even in number, so that the whole line alternates. Then
    // each is added to `sums`; false: a check failed (nothing of them added).
    template <class Tracks>
    [[gnu::always_inline]] bool add_entering(Tracks& sums) {
        if (!entering_) return true;
        if (!follow_entering()) return false;
        for (int l = 1; l < lines_; ++l) {
            if (!place_entering(l)) return false;
        }
        for (std::size_t e = 0; e < t_.entering_.size(); ++e) {
            const std::size_t k = m_ + e;
            if (t_.track_first_[k] >= t_.track_end_[k]) continue;  // entered and ended between
            const double* xs = t_.track_x_.data() + k * lines_;
            const auto [lo, hi] =
                std::minmax_element(xs + t_.track_first_[k], xs + t_.track_end_[k]);
            add_track(sums, k, *lo, *hi, d_ * t_.track_dv_[k] * s_);
        }
        return true;
    }

    // No chain present on the bottom border has an edge ending there: the sweep can take it.
    bool strict() const { return strict_; }

private:
    // Per line l, the crossings present before the last line's chain i (i = m: all of them).
    int& before(int l, std::size_t i) { return t_.before_[l * (m_ + 1) + i]; }

    template <class Tracks>
    [[gnu::always_inline]] void add_track(Tracks& sums, std::size_t k, double lo, double hi,
                                          double dv) {
        sums.add(t_.track_x_.data() + k * lines_, t_.track_first_[k], t_.track_end_[k], lo, hi, dv);
    }

    // Follows track k's chain from edge `idx` over lines first..n: x on each line it meets,
    // its end (the first line past the chain). false: it ends on an interior line.
    [[gnu::always_inline]] bool follow(std::size_t k, std::uint32_t idx, int first) {
        double* xs = t_.track_x_.data() + k * lines_;
        t_.track_first_[k] = first;
        t_.track_end_[k] = lines_;
        for (int l = first; l < lines_; ++l) {
            const double yl = ys_[l];
            while (l < n_ ? !(yl < edges_[idx].y1) : !(yl <= edges_[idx].y1)) {
                if (edges_[idx].below < 0) {
                    if (l < n_ && edges_[idx].y1 == yl) return false;
                    t_.track_end_[k] = l;
                    return true;
                }
                idx = static_cast<std::uint32_t>(edges_[idx].below);
            }
            xs[l] = edges_[idx].x_at(yl);
        }
        t_.track_edge_[k] = idx;
        strict_ = strict_ && y_end_ < edges_[idx].y1;
        return true;
    }

    // The last line's chain i on every line it meets (xs) and its range [lo, hi] over them;
    // false: it ends on an interior line.
    [[gnu::always_inline]] bool last_line_track(std::size_t i, double* xs, double& lo, double& hi) {
        const Edge& e = edges_[top_[i].edge];
        const double x0 = top_[i].x;
        xs[0] = x0;
        if (y_end_ <= e.y1) {
            // Straight through the row: x between the borders' (a straight edge's x is
            // linear in y; the interpolation differs from x_at by rounding only).
            const double x1 = e.x_at(y_end_);
            for (int l = 1; l < n_; ++l) xs[l] = x0 + (x1 - x0) * fraction_[l];
            xs[n_] = x1;
            t_.track_first_[i] = 0;
            t_.track_end_[i] = lines_;
            t_.track_edge_[i] = top_[i].edge;
            strict_ = strict_ && y_end_ < e.y1;
            lo = std::min(x0, x1);
            hi = std::max(x0, x1);
            return true;
        }
        if (!follow(i, top_[i].edge, 1)) return false;
        t_.track_first_[i] = 0;  // follow() starts on line 1
        const auto [min, max] = std::minmax_element(xs, xs + t_.track_end_[i]);
        lo = *min;
        hi = *max;
        return true;
    }

    // Each entering chain followed from the line below its head, with its winding in
    // track_dv_; false: one ends on an interior line, or its winding is not +-1.
    bool follow_entering() {
        for (std::size_t e = 0; e < t_.entering_.size(); ++e) {
            const std::size_t k = m_ + e;
            const double y0 = edges_[t_.entering_[e]].y0;
            int first = 1;
            while (!(ys_[first] > y0)) ++first;
            if (!follow(k, t_.entering_[e], first)) return false;
            const int w = edges_[t_.entering_[e]].winding;
            if (w != 1 && w != -1) return false;
            t_.track_dv_[k] = w;
        }
        return true;
    }

    // Line l's entering chains placed in the gaps of the last line's chains and checked
    // (add_entering()); on the bottom border, their order kept for hand_over_bottom().
    bool place_entering(int l) {
        const std::size_t m = m_;
        const int lines = lines_;
        const double* row_x = t_.track_x_.data();  // the last line's chains: stride `lines`
        const std::vector<double>& track_x = t_.track_x_;
        std::vector<std::uint64_t>& gaps = t_.gaps_;
        gaps.clear();  // (gap, entering index), sorted below by gap, then x
        for (std::size_t e = 0; e < t_.entering_.size(); ++e) {
            const std::size_t k = m + e;
            if (l < t_.track_first_[k] || l >= t_.track_end_[k]) continue;
            const double x = track_x[k * lines + l];
            // The first of the last line's chains whose x is >= x (absent ones carry the x of
            // the present one left of them), and it must lie strictly right of x.
            std::size_t lo = 0, hi = m;
            while (lo < hi) {
                const std::size_t mid = (lo + hi) / 2;
                if (row_x[mid * lines + l] < x)
                    lo = mid + 1;
                else
                    hi = mid;
            }
            if (lo < m && !(row_x[lo * lines + l] > x)) return false;
            gaps.push_back(static_cast<std::uint64_t>(lo) << 32 | e);
        }
        std::sort(gaps.begin(), gaps.end(), [&](std::uint64_t a, std::uint64_t b) {
            if ((a >> 32) != (b >> 32)) return (a >> 32) < (b >> 32);
            return track_x[(m + (a & 0xffffffffu)) * lines + l] <
                   track_x[(m + (b & 0xffffffffu)) * lines + l];
        });
        for (std::size_t g = 0; g < gaps.size();) {
            const std::size_t lo = gaps[g] >> 32;
            int parity = before(l, lo) % 2;  // 1: inside the shape
            std::size_t h = g;
            for (; h < gaps.size() && (gaps[h] >> 32) == lo; ++h) {
                const int w = static_cast<int>(t_.track_dv_[m + (gaps[h] & 0xffffffffu)]);
                if (w != (parity == 0 ? s_ : -s_)) return false;
                parity ^= 1;
            }
            if (parity != before(l, lo) % 2) return false;  // odd in the gap
            if (l == n_) {
                t_.bottom_order_.insert(t_.bottom_order_.end(), gaps.begin() + g, gaps.begin() + h);
            }
            g = h;
        }
        return true;
    }

    SubscanlineTracer& t_;
    const std::vector<Edge>& edges_;
    const std::span<const Crossing> top_;
    const std::size_t m_;
    const int n_, lines_;
    const double y_end_, d_;
    double ys_[kMaxRowIntervals + 1], fraction_[kMaxRowIntervals + 1];
    bool entering_ = false;
    bool strict_ = true;
    int s_ = 0;
};

}  // namespace aabench
