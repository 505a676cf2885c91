#include "methods/scan/multiscan/subscanline.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "methods/scan/multiscan/jump_cells_p.h"
#include "patterns/scene/params.h"

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
    // At least width + 2 cells, in whole words of flags (kFlagWord blocks of
    // detail::kBlockCells cells), so that clear() and resolve() read the flags eight at a time.
    const std::size_t cells = static_cast<std::size_t>(width) + 2;
    const std::size_t word_cells = kFlagWord * detail::kBlockCells;
    const std::size_t words = (cells + word_cells - 1) / word_cells;
    diff_.assign(words * word_cells, 0.0);
    touched_.assign(words * kFlagWord, 0);
    diff_slope_.assign(width + 1, 0.0);
    base_ = 0.0;
    has_slope_ = false;
}

void LineIntegralRow::clear() {
    base_ = 0.0;
    if (has_slope_) {  // add_affine() marks nothing: every cell
        std::fill(diff_.begin(), diff_.end(), 0.0);
        std::fill(diff_slope_.begin(), diff_slope_.end(), 0.0);
        std::fill(touched_.begin(), touched_.end(), 0);
        has_slope_ = false;
        return;
    }
    // Only the touched blocks (and block 0, written unmarked), their flags eight at a time: a
    // row of few changes has few, and filling every cell of every row was a tenth of
    // box-multiscan's render on strips.
    double* cells = diff_.data();
    unsigned char* touched = touched_.data();
    for (std::size_t b = 0; b < touched_.size(); b += kFlagWord) {
        if (b != 0 && flag_word(touched + b) == 0) continue;
        for (std::size_t k = b; k < b + kFlagWord; ++k) {
            if (k != 0 && !touched[k]) continue;
            double* block = cells + k * detail::kBlockCells;
            for (std::size_t c = 0; c < detail::kBlockCells; ++c) block[c] = 0.0;  // vectorised
            touched[k] = 0;
        }
    }
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
    detail::JumpCells cells(diff_, touched_);
    for (const ValueChange& change : line.changes) {
        const double dv = weight * (change.value - before);
        before = change.value;
        cells.add(change.x, dv, width_);
    }
}

// The constant path of resolve() and resolve_and_clear(): block by block, a block nothing was
// added to (its cells all +0.0) written as one constant: the prefix sum is a chain of dependent
// additions, one per pixel, and on a row of few changes (strips, star) that chain was half of
// box-multiscan's render. Skipping a zero cell is the same sum bit for bit: sum + 0.0 == sum for
// every sum but -0.0, and sum starts at base_, a sum from +0.0, which round-to-nearest never
// takes to -0.0. With kClear each touched block is zeroed and unmarked as soon as it is read,
// and the blocks past the last pixel after the row (cells width and width + 1 receive sums
// too): a second pass of clear() over the flags and cells was a tenth of box-multiscan's render
// on star.
template <bool kClear>
void LineIntegralRow::resolve_constant(double sum, double* cells, unsigned char* touched,
                                       std::size_t blocks, std::size_t width, float* out) {
    constexpr std::size_t kBlock = detail::kBlockCells;
    std::size_t b = 0, i = 0;
    for (; i + kBlock <= width; ++b, i += kBlock) {
        // A word of flags at once: kFlagWord untouched blocks are one fill.
        if (b % kFlagWord == 0 && b != 0 && i + kFlagWord * kBlock <= width &&
            flag_word(touched + b) == 0) {
            const float value = static_cast<float>(sum);
            for (std::size_t k = 0; k < kFlagWord * kBlock; ++k) out[i + k] = value;
            b += kFlagWord - 1;
            i += (kFlagWord - 1) * kBlock;
            continue;
        }
        if (b != 0 && !touched[b]) {
            const float value = static_cast<float>(sum);
            for (std::size_t k = 0; k < kBlock; ++k) out[i + k] = value;  // vectorised
            continue;
        }
        double* block = cells + i;
        for (std::size_t k = 0; k < kBlock; ++k) {
            sum += block[k];
            out[i + k] = static_cast<float>(sum);
        }
        if constexpr (kClear) {
            for (std::size_t k = 0; k < kBlock; ++k) block[k] = 0.0;  // vectorised
            touched[b] = 0;
        }
    }
    for (std::size_t k = i; k < width; ++k) {
        sum += cells[k];
        out[k] = static_cast<float>(sum);
    }
    if constexpr (kClear) {
        for (; b < blocks; ++b) {
            if (b != 0 && !touched[b]) continue;
            double* block = cells + b * kBlock;
            for (std::size_t k = 0; k < kBlock; ++k) block[k] = 0.0;
            touched[b] = 0;
        }
    }
}

void LineIntegralRow::resolve(float* out) const {
    const auto width = static_cast<std::size_t>(width_);
    if (!has_slope_) {
        // Read only (kClear false): the casts write nothing.
        return resolve_constant<false>(base_, const_cast<double*>(diff_.data()),
                                       const_cast<unsigned char*>(touched_.data()), touched_.size(),
                                       width, out);
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
    resolve_constant<true>(base, diff_.data(), touched_.data(), touched_.size(),
                           static_cast<std::size_t>(width_), out);
}

double RadialProfile::value(double r) const {
    if (!(r < 1.0)) return 0.0;
    if (kind == RadialProfileKind::kCone) return 1.0 - r;
    return std::exp(-r * r / (2.0 * sigma_px * sigma_px));
}

double RadialProfile::cross_section_integral(double y, double x) const {
    const double y2 = y * y;
    if (!(y2 < 1.0)) return 0.0;
    const double m = std::min(x, std::sqrt(1.0 - y2));  // the support ends at the circle
    if (!(m > 0.0)) return 0.0;
    if (kind == RadialProfileKind::kGaussian) {
        // exp(-(s^2 + y^2) / 2 sigma^2) = exp(-y^2 / 2 sigma^2) * exp(-s^2 / 2 sigma^2), and
        // the integral of the latter over [0, m] is sigma sqrt(pi/2) erf(m / (sigma sqrt 2)).
        const double s = sigma_px;
        return std::exp(-y2 / (2.0 * s * s)) * s * std::sqrt(std::numbers::pi / 2.0) *
               std::erf(m / (s * std::numbers::sqrt2));
    }
    // Integral of sqrt(s^2 + y^2) over [0, m] = (m sqrt(m^2 + y^2) + y^2 asinh(m / |y|)) / 2;
    // on the centre line y = 0 it is m^2 / 2 (the y^2 asinh term tends to 0).
    const double ay = std::abs(y);
    const double root = std::sqrt(m * m + y2);
    const double log_term = ay > 0.0 ? y2 * std::asinh(m / ay) : 0.0;
    return m - 0.5 * (m * root + log_term);
}

std::string RadialProfile::reference_spec() const {
    if (kind == RadialProfileKind::kCone) return "cone:radius=1";
    return fmt::format("gaussian:sigma={},radius=1", format_real(sigma_px));
}

CrossSectionTable::CrossSectionTable(const RadialProfile& filter, int sub_scanlines, int lut_steps)
    : filter_(filter), n_(sub_scanlines), lut_steps_(lut_steps) {
    // Discrete volume: lines at k/n for k = -(n-1)..(n-1) (k = +-n contribute 0), spacing 1/n,
    // each line's cross-section integrated exactly over [-1, 1].
    double volume = 0.0;
    for (int k = -(n_ - 1); k <= n_ - 1; ++k) {
        const double y = static_cast<double>(std::abs(k)) / n_;
        volume += 2.0 * filter_.cross_section_integral(y, 1.0) / n_;
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
    return scale_ * filter_.cross_section_integral(static_cast<double>(l) / n_, clamp_unit(x));
}

}  // namespace aabench
