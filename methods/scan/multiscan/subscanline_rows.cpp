// SubscanlineTracer::add_row and LineIntegralRow's whole-row sums
// (methods/scan/multiscan/subscanline.h): box-multiscan's pixel rows summed change by change
// instead of line by line, and the proofs that this is the same sum (docs/methods-multiscan.md,
// "Whole rows, change by change").
#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include "methods/scan/multiscan/alternating_row_p.h"
#include "methods/scan/multiscan/jump_cells_p.h"
#include "methods/scan/multiscan/region_rows.h"
#include "methods/scan/multiscan/subscanline.h"

namespace aabench {

using detail::cell_of;
using detail::JumpCells;

static_assert(SubscanlineTracer::kMaxRowIntervals + 1 == LineIntegralRow::kMaxLines);

namespace {

// The trapezoidal weight of line l of n + 1.
double row_weight(int l, int n) { return l == 0 || l == n ? 0.5 / n : 1.0 / n; }

// One change's lines first..end - 1 (x on line l: xs[l], weights weight[l]), which lie within
// [lo, hi], into the cells. Only lo picks cells, and each line's share is continuous in its x
// across pixel borders, so an interpolated x an ulp outside [lo, hi] (lo, hi the borders' x)
// changes the sums by that ulp only. When they lie in two pixels c and c + 1 (or one), line l adds
// w_l max(right - x_l, 0) to cell c and w_l max(x_l - right, 0) to cell c + 2, right = c + 1,
// and the rest of w_l to cell c + 1 (what JumpCells::add gives it for either pixel), summed
// over the lines without branching: which side a line lies on, and whether a change stays
// in one pixel, are as good as random on a ring. Across more pixels, line by line.
// kLines > 0: the caller's first and end are 0 and kLines, known here (loops unrolled).
template <int kLines = 0>
void add_track_cells(JumpCells& cells, const double* xs, int first, int end, const double* weight,
                     double lo, double hi, double dv, int width) {
    if constexpr (kLines > 0) {
        first = 0;
        end = kLines;
    }
    if (lo > 0.0 && hi < width) {
        const std::size_t c = cell_of(lo);
        const double right = c + 1.0;  // the border between pixels c and c + 1
        if (hi < right + 1.0) {
            double weights = 0.0, left_part = 0.0, right_part = 0.0;
            for (int l = first; l < end; ++l) {
                const double d = xs[l] - right;
                weights += weight[l];
                left_part += weight[l] * std::max(-d, 0.0);
                right_part += weight[l] * std::max(d, 0.0);
            }
            const double here = dv * left_part, after = dv * right_part;
            cells.add_cells(c, here, (dv * weights - here) - after, after);
            return;
        }
    }
    for (int l = first; l < end; ++l) cells.add(xs[l], dv * weight[l], width);
}

// add_track_cells() of a change present on all `lines` lines; the line counts of n = 1..3
// (3 is box-multiscan's default) unrolled.
void add_full_track(JumpCells& cells, const double* xs, int lines, const double* weight, double lo,
                    double hi, double dv, int width) {
    switch (lines) {
        case 2:
            return add_track_cells<2>(cells, xs, 0, 2, weight, lo, hi, dv, width);
        case 3:
            return add_track_cells<3>(cells, xs, 0, 3, weight, lo, hi, dv, width);
        case 4:
            return add_track_cells<4>(cells, xs, 0, 4, weight, lo, hi, dv, width);
        default:
            return add_track_cells(cells, xs, 0, lines, weight, lo, hi, dv, width);
    }
}

}  // namespace

// add_alternating_row()'s additions to a LineIntegralRow: every line starts outside (the
// weights sum to 1), and each chain's lines go to the cells as add_track_cells() sums them.
class LineIntegralRow::Tracks {
public:
    Tracks(LineIntegralRow& row, int n, double outside)
        : row_(row), cells_(row.diff_), lines_(n + 1) {
        row.base_ += outside;
        for (int l = 0; l <= n; ++l) weight_[l] = row_weight(l, n);
    }
    void add(const double* xs, int first, int end, double lo, double hi, double dv) {
        if (first == 0 && end == lines_) {  // present on every line: the common case
            add_full_track(cells_, xs, lines_, weight_, lo, hi, dv, row_.width_);
        } else {
            add_track_cells(cells_, xs, first, end, weight_, lo, hi, dv, row_.width_);
        }
    }
    // Forgets everything added (the row the caller left empty is empty again).
    void discard() {
        cells_.discard();
        row_.clear();
    }

private:
    LineIntegralRow& row_;
    JumpCells cells_;
    int lines_;
    double weight_[kMaxLines];
};

void SubscanlineTracer::advance(double y) {
    if (y >= 0.0 && y < table_->height()) sweep_.crossings(y);
}

bool SubscanlineTracer::add_row(int row_index, int n, LineIntegralRow& row) {
    return add_lines(row_index, n, row);
}

bool SubscanlineTracer::add_region_row(double y_top, int n, RegionRowSums& sums) {
    // Line 0 with an endpoint on it takes the mean of its two limits in trace(); the sweep's
    // list is the limit from below. (endpoint_on_line() is exact but after a seek to y = 0,
    // and y_top is never 0.)
    if (sweep_.last_line() != y_top || sweep_.endpoint_on_line()) return false;
    return add_lines(y_top, n, sums);
}

// The sink is asked for (LineIntegralRow and RegionRowSums answer):
//   add_row_spans(start, x, dv, count, n)  changes that run straight from x[2k] on line 0 to
//                                          x[2k + 1] on line n, every line starting at start;
//   add_row_lines(start, x, dv, count, n)  changes with their x on every line, x[k (n + 1) + l];
//   Sink::Tracks(sink, n, outside)         one alternating shape's chains, each added as soon
//                                          as it passed its checks (add(xs, first, end, lo,
//                                          hi, dv): x on lines first..end - 1, within [lo, hi]),
//                                          discard() forgetting all of them.
template <class Sink>
bool SubscanlineTracer::add_lines(double y_top, int n, Sink& row) {
    if (n < 1 || n > kMaxRowIntervals) return false;
    const double y = y_top, y_end = y_top + 1.0;
    if (!(y >= 0.0 && y < table_->height()) || sweep_.last_line() != y) return false;
    // A chain entering at y_end itself is not in the bottom border's limit from above.
    if (sweep_.next_entry() < y_end) return add_alternating_row(y_top, n, row);
    const std::span<const Crossing> crossings = sweep_.last_crossings();
    const auto& edges = table_->edges();
    const bool one_shape = table_->shape_count() == 1;
    const double outside = table_->background();
    const double inside = one_shape ? table_->shape_value(0) : outside;
    // Crossing i takes the visible value from `value` to `next`: recorded as a change when they
    // differ (change_at_, change_dv_ = new value - old value).
    const auto note_change = [&](std::size_t i, double& value, double next) {
        if (next == value) return false;
        change_at_.push_back(static_cast<std::uint32_t>(i));
        change_dv_.push_back(next - value);
        value = next;
        return true;
    };
    // The walk, once, in the list's order (what walk() computes on each line): which crossings
    // change the visible value, and by how much; returns the value left of them. Several
    // shapes walk before the straight pass below (or keep the last row's walk); one shape
    // walks here only for add_bent_row() (the straight pass counts its winding itself).
    // walked_ and walk_keys_ serve several shapes only (reset() clears walked_).
    const auto walk_changes = [&] {
        if (one_shape) {
            change_at_.clear();
            change_dv_.clear();
            double value = outside;
            OneShapeWalk<> one(inside, outside);
            for (std::size_t i = 0; i < crossings.size(); ++i) {
                note_change(i, value, one.cross(crossings[i].winding));
            }
            return outside;
        }
        // The walk sees only the crossings' shapes and windings, in order: a row whose list
        // carries the same as the last row walked here (the same chains, none entered, ended
        // or swapped: most rows of strips and star) has the same changes, kept from it.
        const auto key = [](const Crossing& c) {
            return static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.shape)) << 32 |
                   static_cast<std::uint32_t>(c.winding);
        };
        bool same = walked_ && walk_keys_.size() == crossings.size();
        for (std::size_t i = 0; same && i < crossings.size(); ++i) {
            same = walk_keys_[i] == key(crossings[i]);
        }
        if (!same) {
            change_at_.clear();
            change_dv_.clear();
            walk_keys_.resize(crossings.size());
            walker_.reset();
            walk_start_ = walker_.value();
            double value = walk_start_;
            for (std::size_t i = 0; i < crossings.size(); ++i) {
                walk_keys_[i] = key(crossings[i]);
                note_change(i, value, walker_.cross(crossings[i].shape, crossings[i].winding));
            }
            walked_ = true;
        }
        return walk_start_;
    };
    // Straight rows: every crossing's edge spans the row (y1 >= y_end; y0 <= y, as the sweep
    // met it on y), so its x runs straight from the top border to the bottom one, and two
    // neighbours in order at both borders are in order on every line between. Checked for
    // every crossing before anything is added. One shape walks in the same pass (a winding
    // counter), so that a row it leaves at a bent chain for add_alternating_row() has walked
    // only the crossings before it; several shapes walk first (or keep the last row's walk).
    double start = outside;
    std::size_t count = 0;
    if (one_shape) {
        change_at_.clear();
        change_dv_.clear();
        change_x_.clear();
    } else {
        start = walk_changes();
        count = change_at_.size();
        change_x_.resize(2 * count);
    }
    bottom_x_.resize(crossings.size());
    bool strict = true;  // no edge ends on the bottom border: the sweep can take the x over
    // The pass, compiled for each case (the walk in it or not); an answer when the row is not
    // straight (add_lines()'s), none when it is.
    const auto pass = [&]<bool kOneShape>() -> std::optional<bool> {
        double last_top = -std::numeric_limits<double>::infinity(), last_bottom = last_top;
        std::size_t k = 0;
        double value = outside;
        OneShapeWalk<> one(inside, outside);  // kOneShape: the walk in this pass
        bool straight_through = true;  // `strict`, kept here while the pass runs
        for (std::size_t i = 0; i < crossings.size(); ++i) {
            const Edge& e = edges[crossings[i].edge];
            if (!(y_end <= e.y1)) {
                // A chain bends or ends in the row: one alternating shape sums its chains one
                // by one (no walk: every crossing is a change); otherwise the row's changes
                // (walked here, or the last row's walk where its keys match) are summed line
                // by line.
                if (kOneShape && add_alternating_row(y_top, n, row)) return true;
                return add_bent_row(y_top, n, walk_changes(), crossings, row);
            }
            const double top = crossings[i].x, bottom = e.x_at(y_end);
            if (top < last_top || bottom < last_bottom) return false;  // edges cross in the row
            bottom_x_[i] = bottom;
            straight_through = straight_through && y_end < e.y1;
            last_top = top;
            last_bottom = bottom;
            if constexpr (kOneShape) {
                if (note_change(i, value, one.cross(crossings[i].winding))) {
                    change_x_.push_back(top);
                    change_x_.push_back(bottom);
                }
            } else if (k < count && change_at_[k] == i) {
                change_x_[2 * k] = top;
                change_x_[2 * k + 1] = bottom;
                ++k;
            }
        }
        strict = straight_through;
        return std::nullopt;
    };
    const std::optional<bool> answer =
        one_shape ? pass.template operator()<true>() : pass.template operator()<false>();
    if (answer) return *answer;  // not a straight row
    count = change_at_.size();
    row.add_row_spans(start, change_x_.data(), change_dv_.data(), count, n);
    // The sweep's next line is the bottom border, whose x are at hand (it does the work itself
    // when refused).
    if (strict) sweep_.move_straight(y_end, bottom_x_.data());
    return true;
}

template <class Sink>
bool SubscanlineTracer::add_bent_row(double y_top, int n, double start,
                                     std::span<const Crossing> crossings, Sink& row) {
    // Each crossing follows its chain down through the row (the sweep's follow()): on an
    // interior line the edge with y0 <= y_l < y1 (a vertex on the line continues the chain at
    // the same x), on the bottom border the one with y0 < y_end <= y1. A chain that ends
    // inside the row declines (there the line's two limits differ: trace() takes their mean).
    const auto& edges = table_->edges();
    const std::size_t count = change_at_.size();
    const std::size_t lines = static_cast<std::size_t>(n) + 1;
    change_x_.resize(count * lines);
    double last[kMaxRowIntervals + 1];
    std::fill(last, last + lines, -std::numeric_limits<double>::infinity());
    std::size_t k = 0;
    for (std::size_t i = 0; i < crossings.size(); ++i) {
        const bool changes = k < count && change_at_[k] == i;
        double* xs = changes ? change_x_.data() + k * lines : nullptr;
        std::uint32_t idx = crossings[i].edge;
        for (int l = 0; l <= n; ++l) {
            double x;
            if (l == 0) {
                x = crossings[i].x;
            } else {
                const double yl = l < n ? y_top + static_cast<double>(l) / n : y_top + 1.0;
                // Interior lines: the edge must reach below y_l; the bottom border: down to it.
                while (l < n ? !(yl < edges[idx].y1) : !(yl <= edges[idx].y1)) {
                    // A chain ends inside the row (add_alternating_row() declined it).
                    if (edges[idx].below < 0) return false;
                    idx = static_cast<std::uint32_t>(edges[idx].below);
                }
                x = edges[idx].x_at(yl);
            }
            if (x < last[l]) return false;  // chains cross in the row
            last[l] = x;
            if (xs) xs[l] = x;
        }
        k += changes;
    }
    row.add_row_lines(start, change_x_.data(), change_dv_.data(), count, n);
    return true;
}

template <class Sink>
bool SubscanlineTracer::add_alternating_row(double y_top, int n, Sink& row) {
    if (table_->shape_count() != 1) return false;
    AlternatingRow alternating(*this, y_top, n);
    if (!alternating.prepare()) return false;
    // Each chain is added as soon as it has passed its checks, into the row the caller left
    // empty; a later failure empties it.
    typename Sink::Tracks sums(row, n, table_->background());  // every line starts outside
    if (!alternating.add_last_line(sums) || !alternating.add_entering(sums)) {
        sums.discard();
        return false;
    }
    if (alternating.strict()) hand_over_bottom(y_top, n, sweep_.last_crossings());
    return true;
}

void SubscanlineTracer::hand_over_bottom(double y_top, int n, std::span<const Crossing> top) {
    // The bottom border's crossings are the chains present on it, in order, with the entering
    // ones in their gaps: the sweep's next line (the caller checked that no edge of them ends
    // on it; EdgeSweep::adopt refuses when a chain starts on it).
    const auto& edges = table_->edges();
    const std::size_t m = top.size();
    const int lines = n + 1;
    next_list_.resize(m + entering_.size());  // an upper bound, trimmed below
    std::size_t size = 0;
    // bottom_order_: the entering chains present on the bottom border, by gap, then x.
    std::size_t q = 0;
    const auto push_entering_at = [&](std::size_t gap) {
        for (; q < bottom_order_.size() && (bottom_order_[q] >> 32) == gap; ++q) {
            const std::size_t k = m + (bottom_order_[q] & 0xffffffffu);
            const Edge& e = edges[track_edge_[k]];  // a chain's edges share its winding
            next_list_[size++] = {track_x_[k * lines + n], e.winding, e.shape, track_edge_[k]};
        }
    };
    for (std::size_t i = 0; i < m; ++i) {
        push_entering_at(i);
        if (track_end_[i] == lines) {
            next_list_[size++] = {track_x_[i * lines + n], top[i].winding, top[i].shape,
                                  track_edge_[i]};
        }
    }
    push_entering_at(m);
    next_list_.resize(size);
    sweep_.adopt(y_top + 1.0, next_list_, entering_.size());
}

void LineIntegralRow::add_row_spans(double start, const double* x, const double* dv,
                                    std::size_t count, int n) {
    base_ += start;  // the weights sum to 1
    const double width = width_;
    double weight[kMaxLines];
    for (int l = 0; l <= n; ++l) weight[l] = row_weight(l, n);
    JumpCells cells(diff_);
    for (std::size_t k = 0; k < count; ++k) {
        const double top = x[2 * k], bottom = x[2 * k + 1];
        const double lo = std::min(top, bottom), hi = std::max(top, bottom);
        if (hi <= 0.0) {  // left of the image on every line
            diff_[0] += dv[k];
        } else if (lo >= width) {  // right of it: no pixel lies right of it
        } else if (lo > 0.0 && hi < width && hi < static_cast<double>(cell_of(lo)) + 1.0) {
            // One pixel c on every line: the weighted mean x is the middle's (see add_row).
            const std::size_t c = cell_of(lo);
            const double right = (c + 1.0) - 0.5 * (top + bottom);
            cells.add_cell(c, dv[k] * right, dv[k] * (1.0 - right));
        } else {
            // Across pixels: x on each line on the straight line between the borders, summed
            // as add_track_cells() sums a change (two pixels at once, more line by line).
            double xs[kMaxLines];
            for (int l = 0; l <= n; ++l) {
                xs[l] = l == 0 ? top : (l == n ? bottom : top + (bottom - top) * l / n);
            }
            add_full_track(cells, xs, n + 1, weight, lo, hi, dv[k], width_);
        }
    }
}

void LineIntegralRow::add_row_lines(double start, const double* x, const double* dv,
                                    std::size_t count, int n) {
    base_ += start;  // the weights sum to 1
    const int lines = n + 1;
    double weight[kMaxLines];
    for (int l = 0; l < lines; ++l) weight[l] = row_weight(l, n);
    JumpCells cells(diff_);
    for (std::size_t k = 0; k < count; ++k) {
        const double* xs = x + k * static_cast<std::size_t>(lines);
        const auto [lo, hi] = std::minmax_element(xs, xs + lines);
        add_full_track(cells, xs, lines, weight, *lo, *hi, dv[k], width_);
    }
}

}  // namespace aabench
