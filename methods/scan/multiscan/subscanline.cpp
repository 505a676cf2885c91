#include "methods/scan/multiscan/subscanline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "methods/scan/multiscan/jump_cells_p.h"

namespace aabench {

void SubscanlineTracer::reset(EdgeTable& table) {
    table_ = &table;
    walked_ = false;  // another table's walk
    sweep_.reset(table);
    walker_.bind(table);
    top_margin_.clear();
    bottom_margin_.clear();
    const double height = table.height();
    const auto& edges = table.edges();
    for (std::uint32_t idx = 0; idx < edges.size(); ++idx) {
        const Edge& e = edges[idx];
        // Closed overlaps: a superset of what either limit needs at any y in the margin, the
        // image's top and bottom lines included.
        if (e.y0 <= 0.0 && e.y1 >= -kMarginPx) top_margin_.push_back(idx);
        if (e.y1 >= height && e.y0 <= height + kMarginPx) bottom_margin_.push_back(idx);
    }
}

std::span<const std::uint32_t> SubscanlineTracer::candidates(double y, bool from_below) {
    // On and beyond the image's top and bottom lines, the margin lists. Inside, the limit from
    // below needs the edges overlapping (y, y + eps): EdgeTable row floor(y); the limit from
    // above those overlapping (y - eps, y): row ceil(y) - 1. On an integer y these are
    // different rows. Any list in ascending index that holds the edges met gives the same
    // crossings in the same order, so which superset serves does not show in the image.
    if (y <= 0.0) return top_margin_;
    if (y >= table_->height()) return bottom_margin_;
    table_->build_rows();
    const double r = from_below ? std::floor(y) : std::ceil(y) - 1.0;
    return table_->row(static_cast<int>(r));
}

std::span<const Crossing> SubscanlineTracer::sorted_crossings(double y, bool from_below) {
    crossings_.clear();
    const auto& edges = table_->edges();
    for (const std::uint32_t idx : candidates(y, from_below)) {
        const Edge& e = edges[idx];
        const bool hit = from_below ? (e.y0 <= y && y < e.y1) : (e.y0 < y && y <= e.y1);
        if (hit) crossings_.push_back({e.x_at(y), e.winding, e.shape});
    }
    std::sort(crossings_.begin(), crossings_.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    return crossings_;
}

std::span<const Crossing> SubscanlineTracer::sorted_from_sweep(double y, bool from_below) {
    // The edges a limit meets, gathered from the sweep's line instead of the table's row: the
    // limit from below is the sweep's list itself; the limit from above (y0 < y <= y1) keeps
    // its edges that started above y, takes for one that starts on y the edge of its chain
    // ending there (if any), and adds the chains that ended on y. Put in ascending index, the
    // same hits in the same order as sorted_crossings()'s candidates give, so std::sort makes
    // the same order of them, ties included. What it saves: the row buckets (on circles, 1.7
    // million edges bucketed per render) and a pass over every edge of the row per line.
    const auto& edges = table_->edges();
    hit_edges_.clear();
    for (const Crossing& c : sweep_.last_crossings()) {
        if (from_below || edges[c.edge].y0 < y) {
            hit_edges_.push_back(c.edge);
        } else if (edges[c.edge].above >= 0) {
            hit_edges_.push_back(static_cast<std::uint32_t>(edges[c.edge].above));
        }
    }
    if (!from_below) {
        const std::span<const std::uint32_t> ended = sweep_.ended_on_line();
        hit_edges_.insert(hit_edges_.end(), ended.begin(), ended.end());
    }
    std::sort(hit_edges_.begin(), hit_edges_.end());
    crossings_.clear();
    for (const std::uint32_t idx : hit_edges_) {
        const Edge& e = edges[idx];
        crossings_.push_back({e.x_at(y), e.winding, e.shape});
    }
    std::sort(crossings_.begin(), crossings_.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    return crossings_;
}

bool SubscanlineTracer::endpoint_in(std::span<const std::uint32_t> list, double y) const {
    const auto& edges = table_->edges();
    for (const std::uint32_t idx : list) {
        if (edges[idx].y0 == y || edges[idx].y1 == y) return true;
    }
    return false;
}

bool SubscanlineTracer::walk(std::span<const Crossing> crossings, LineProfile& out) {
    out.changes.clear();
    // Two crossings at the same x (sorted input: neighbours) are reported, not resolved.
    bool tied = false;
    double last_x = std::numeric_limits<double>::quiet_NaN();
    if (table_->shape_count() == 1) {
        // One shape (every built-in 2-D pattern): what the walker would say, without its
        // bookkeeping per crossing (visibility_rule.h).
        const double outside = table_->background();
        OneShapeWalk<> one(table_->shape_value(0), outside);
        out.start = outside;
        double value = outside;
        for (const Crossing& c : crossings) {
            tied = tied || c.x == last_x;
            last_x = c.x;
            const double next = one.cross(c.winding);
            if (next != value) {
                out.changes.push_back({c.x, next});
                value = next;
            }
        }
        return tied;
    }
    walker_.reset();
    out.start = walker_.value();
    double value = out.start;
    for (const Crossing& c : crossings) {
        tied = tied || c.x == last_x;
        last_x = c.x;
        const double next = walker_.cross(c.shape, c.winding);
        // Crossings that change no visible value (inside a covering shape, or a shape
        // entering under one) are dropped: each consumer then does work per visible change,
        // the paper's "visible crossings" (§3.3).
        if (next != value) {
            out.changes.push_back({c.x, next});
            value = next;
        }
    }
    return tied;
}

bool SubscanlineTracer::trace(double y, LineProfile& below, LineProfile& above) {
    bool split;
    if (y >= 0.0 && y < table_->height()) {
        // Inside the image the limit from below comes from the sweep. Crossings of equal x
        // change the visible value in an order that reaches the sums (a change A -> B -> C at
        // one x adds two terms where A -> C adds one), and crossings_at's order among them is
        // std::sort's: on such a line (rare: shapes sharing an edge, a vertex on the line) the
        // old sort is redone, so every image stays what it was.
        // The sweep's own list gives the edges to sort (sorted_from_sweep).
        if (walk(sweep_.crossings(y), below)) walk(sorted_from_sweep(y, true), below);
        // An edge with an endpoint on y either starts there (the sweep met it) or ends there;
        // on y == 0 one that ends there may lie wholly above the image: the top margin list.
        split = sweep_.endpoint_on_line() || (y == 0.0 && endpoint_in(top_margin_, y));
        // The limit from above from the sweep too, when it knows the chains that ended on y.
        if (split && sweep_.ended_known() && y > 0.0) {
            walk(sorted_from_sweep(y, false), above);
            return true;
        }
    } else {
        // Beyond the image's lines both limits' candidates are the same margin list, which
        // holds every edge with an endpoint on y.
        walk(sorted_crossings(y, true), below);
        split = endpoint_in(candidates(y, true), y);
    }
    if (split) walk(sorted_crossings(y, false), above);
    return split;
}

LineIntegralRow::LineIntegralRow(int width) { reset(width); }

void LineIntegralRow::reset(int width) {
    width_ = width;
    diff_.reset(width);
    diff_slope_.assign(width + 1, 0.0);
    base_ = 0.0;
    has_slope_ = false;
}

void LineIntegralRow::clear() {
    base_ = 0.0;
    if (has_slope_) {  // add_affine() flags nothing: every cell
        diff_.clear_all();
        std::fill(diff_slope_.begin(), diff_slope_.end(), 0.0);
        has_slope_ = false;
        return;
    }
    // Only the flagged blocks (and block 0, written unflagged): a row of few changes has few,
    // and filling every cell of every row was a tenth of box-multiscan's render on strips.
    diff_.clear();
}

void LineIntegralRow::add_affine(const LineProfile& line, double weight) {
    has_slope_ = true;
    base_ += weight * line.start;
    // v = a + b x' right of each change; a and b before the first change: the background.
    double a_before = line.start, b_before = 0.0;
    for (const ValueChange& change : line.changes) {
        const double b = change.slope;
        const double a = change.value - b * change.x;
        const double da = weight * (a - a_before), db = weight * (b - b_before);
        a_before = a;
        b_before = b;
        const double x = change.x;
        if (x <= 0.0) {
            diff_[0] += da;
            diff_slope_[0] += db;
        } else if (x < width_) {
            const auto c = static_cast<std::size_t>(x);
            // integral over [x, c + 1] of da + db t = (c + 1 - x) (da + db (c + 1 + x) / 2)
            const double partial = ((c + 1.0) - x) * (da + db * 0.5 * ((c + 1.0) + x));
            diff_[c] += partial;
            diff_[c + 1] += da - partial;
            diff_slope_[c + 1] += db;
        }
    }
}

void LineIntegralRow::add(const LineProfile& line, double weight) {
    if (line.affine) return add_affine(line, weight);
    base_ += weight * line.start;
    double before = line.start;
    detail::JumpCells cells(diff_);
    for (const ValueChange& change : line.changes) {
        const double dv = weight * (change.value - before);
        before = change.value;
        cells.add(change.x, dv, width_);
    }
}

// Without affine lines, the kernel row's prefix sum over the flagged blocks (cells.h): a block
// nothing was added to is written as one constant, the same sum bit for bit. On a row of few
// changes (strips, star) the chain of dependent additions, one per pixel, was half of
// box-multiscan's render.
void LineIntegralRow::resolve(float* out) const {
    if (!has_slope_) {
        return diff_.resolve(base_, out,
                             [](std::size_t, double sum) { return static_cast<float>(sum); });
    }
    double sum = base_;
    double slope = 0.0;
    for (int i = 0; i < width_; ++i) {
        sum += diff_[i];
        slope += diff_slope_[i];
        out[i] = static_cast<float>(sum + slope * (i + 0.5));
    }
}

void LineIntegralRow::resolve_and_clear(float* out) {
    if (has_slope_) {
        resolve(out);
        clear();
        return;
    }
    const double base = base_;
    base_ = 0.0;
    diff_.resolve_and_clear(base, out,
                            [](std::size_t, double sum) { return static_cast<float>(sum); });
}

CrossSectionTable::CrossSectionTable(const Filter& filter, int sub_scanlines, int lut_steps)
    : filter_(filter), n_(sub_scanlines), lut_steps_(lut_steps) {
    // The lines l/n, l = 0..n, reach exactly the support of radius 1 (F_n = 0).
    if (filter_.is_box() || filter_.radius_px() != 1.0) {
        throw std::invalid_argument("CrossSectionTable: needs a radial filter of radius 1 px");
    }
    // Discrete volume: lines at k/n for k = -(n-1)..(n-1) (k = +-n contribute 0), spacing 1/n,
    // each line's cross-section integrated exactly over [-1, 1].
    double volume = 0.0;
    for (int k = -(n_ - 1); k <= n_ - 1; ++k) {
        const double y = static_cast<double>(std::abs(k)) / n_;
        volume += 2.0 * filter_.profile_line_integral(y, 1.0) / n_;
    }
    scale_ = 1.0 / (n_ * volume);
    totals_.resize(n_ + 1);
    for (int l = 0; l <= n_; ++l) totals_[l] = exact(l, 1.0);
    if (lut_steps_ > 0) {
        values_.resize(static_cast<std::size_t>(n_ + 1) * (lut_steps_ + 1));
        for (int l = 0; l <= n_; ++l) {
            double* row = values_.data() + static_cast<std::size_t>(l) * (lut_steps_ + 1);
            for (int m = 0; m <= lut_steps_; ++m) {
                row[m] = exact(l, static_cast<double>(m) / lut_steps_);
            }
            row[lut_steps_] = totals_[l];  // the same double as total(l), bit for bit
        }
    }
}

double CrossSectionTable::exact(int l, double x) const {
    if (l >= n_) return 0.0;  // the line at distance 1 px: a single point of the support
    return scale_ * filter_.profile_line_integral(static_cast<double>(l) / n_, clamp_unit(x));
}

}  // namespace aabench
