// The band sweep and the jump set of the visible value (see visible_boundary.h).
//
// The bands. Row r is split at every edge endpoint strictly inside (r, r+1) and at every
// crossing of two edges inside it. Crossings are found exactly where they occur: edges are
// sorted by x at the band's top; an insertion sort by x at the band's bottom swaps exactly
// the pairs that cross inside the band (an inversion), and each swap gives one crossing
// height. Within the final band, the order at mid-height is the order everywhere, and a
// walk in that order (VisibilityWalker) gives each edge's jump.
//
// Floating point. Crossing heights closer than kMinBandHeight to a band edge are not split
// off: the region misassigned by treating such a band as crossing-free is a triangle of
// height < kMinBandHeight, whose area is far below 1e-12 for edges of bounded slope.
// Coincident edges (two shapes sharing a border) need no split: the zero-width region
// between them contributes nothing, and their jumps add up to the true jump.
//
// The horizontal pieces of the jump set. Where one band ends and the next begins (at height
// Y), v just above Y is the step function of the upper band's segments at their bottom x,
// and v just below is that of the lower band's segments at their top x. Both are written as
// the walk's values (value_right), not as running sums of jumps, so that where they agree
// the difference is exactly zero and no spurious sliver of weight 1e-17 is reported. Where
// they differ, the interval is a horizontal piece with weight v_below - v_above. A segment
// continuing from one band into the next has the same x on both sides (the same Edge::x_at
// at the same height), so the pieces of the jump set close up exactly.
#include "harness/visible_boundary.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace aabench {
namespace {

constexpr double kMinBandHeight = 1e-13;

}  // namespace

BandSweep::BandSweep(const EdgeTable& table, int row_lo, int row_hi)
    : table_(table), walker_(table), row_lo_(row_lo) {
    const int height = table.height();
    margin_rows_.resize(static_cast<std::size_t>(std::max(0, row_hi - row_lo)));
    if (row_lo >= 0 && row_hi <= height) return;
    const auto& edges = table.edges();
    for (std::uint32_t idx = 0; idx < edges.size(); ++idx) {
        const Edge& e = edges[idx];
        // The rows whose open band (r, r+1) the edge overlaps, clamped in double first so
        // that far-away coordinates cannot overflow the int conversion.
        const double lo = std::max<double>(row_lo, std::floor(e.y0));
        const double hi = std::min<double>(row_hi - 1, std::ceil(e.y1) - 1.0);
        if (lo > hi) continue;
        const int first = static_cast<int>(lo), last = static_cast<int>(hi);
        for (int r = first; r <= std::min(last, -1); ++r) margin_rows_[r - row_lo].push_back(idx);
        for (int r = std::max(first, height); r <= last; ++r) {
            margin_rows_[r - row_lo].push_back(idx);
        }
    }
}

std::span<const std::uint32_t> BandSweep::row_edges(int r) const {
    if (r >= 0 && r < table_.height()) return table_.row(r);
    return margin_rows_[r - row_lo_];
}

void BandSweep::sweep_row(int r, const BandCallback& on_band) {
    const auto ids = row_edges(r);
    if (ids.empty()) return;
    const double top = r, bottom = r + 1.0;
    breaks_.assign({top, bottom});
    for (const std::uint32_t idx : ids) {
        const Edge& e = table_.edges()[idx];
        if (e.y0 > top && e.y0 < bottom) breaks_.push_back(e.y0);
        if (e.y1 > top && e.y1 < bottom) breaks_.push_back(e.y1);
    }
    std::sort(breaks_.begin(), breaks_.end());
    breaks_.erase(std::unique(breaks_.begin(), breaks_.end()), breaks_.end());
    for (std::size_t k = 0; k + 1 < breaks_.size(); ++k) {
        const double ya = breaks_[k], yb = breaks_[k + 1];
        band_.clear();
        for (const std::uint32_t idx : ids) {
            const Edge& e = table_.edges()[idx];
            if (e.y0 <= ya && e.y1 >= yb) band_.push_back({e.x_at(ya), e.x_at(yb), idx});
        }
        if (!band_.empty()) sweep_band(ya, yb, on_band);
    }
}

// All edges in band_ span [ya, yb]. Splits the band at crossings, then walks each part.
void BandSweep::sweep_band(double ya, double yb, const BandCallback& on_band) {
    std::sort(band_.begin(), band_.end(), [](const Pending& a, const Pending& b) {
        return a.x_top < b.x_top || (a.x_top == b.x_top && a.x_bottom < b.x_bottom);
    });
    // Insertion sort by x at the bottom: each swap is a pair that crosses in the band.
    crossings_.clear();
    order_ = band_;
    for (std::size_t k = 1; k < order_.size(); ++k) {
        for (std::size_t m = k; m > 0 && order_[m - 1].x_bottom > order_[m].x_bottom; --m) {
            const Pending& a = order_[m - 1];
            const Pending& b = order_[m];
            // a is left of b at the top and right of it at the bottom.
            const double gap_top = b.x_top - a.x_top;           // >= 0
            const double gap_bottom = a.x_bottom - b.x_bottom;  // > 0
            const double t = gap_top / (gap_top + gap_bottom);  // in [0, 1)
            const double yc = ya + t * (yb - ya);
            if (yc - ya > kMinBandHeight && yb - yc > kMinBandHeight) crossings_.push_back(yc);
            std::swap(order_[m - 1], order_[m]);
        }
    }
    if (crossings_.empty()) {
        walk_band(ya, yb, on_band);
        return;
    }
    std::sort(crossings_.begin(), crossings_.end());
    crossings_.erase(std::unique(crossings_.begin(), crossings_.end()), crossings_.end());
    crossings_.insert(crossings_.begin(), ya);
    crossings_.push_back(yb);
    const std::vector<double> cuts = std::move(crossings_);
    crossings_.clear();
    all_ = band_;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double sa = cuts[k], sb = cuts[k + 1];
        if (!(sb - sa > 0.0)) continue;
        band_.clear();
        for (const Pending& p : all_) {
            const Edge& e = table_.edges()[p.index];
            band_.push_back({e.x_at(sa), e.x_at(sb), p.index});
        }
        walk_band(sa, sb, on_band);
    }
}

// No crossings inside [ya, yb]: walk the edges in their order at mid-height.
void BandSweep::walk_band(double ya, double yb, const BandCallback& on_band) {
    const double ym = 0.5 * (ya + yb);
    for (Pending& p : band_) p.x_top = table_.edges()[p.index].x_at(ym);  // reuse the slot
    std::sort(band_.begin(), band_.end(),
              [](const Pending& a, const Pending& b) { return a.x_top < b.x_top; });
    walker_.reset();
    double before = table_.background();
    segments_.clear();
    for (const Pending& p : band_) {
        const Edge& e = table_.edges()[p.index];
        const double after = walker_.cross(e.shape, e.winding);
        segments_.push_back({e.x_at(ya), e.x_at(yb), after - before, after, p.index});
        before = after;
    }
    on_band(Band{ya, yb, segments_});
}

namespace {

// A step of v along a band border: from x on (until the next step) v is `value`.
struct Step {
    double x;
    double value;
};

class JumpSetBuilder {
public:
    JumpSetBuilder(double background, double x_lo, double x_hi,
                   const std::function<void(const JumpSegment&)>& on_segment)
        : background_(background), x_lo_(x_lo), x_hi_(x_hi), on_segment_(on_segment) {}

    void band(const Band& band) {
        top_.clear();
        for (const BandSegment& s : band.segments) {
            if (s.jump == 0.0) continue;
            // Downward piece: its right-hand side (cross > 0) is the left, so the weight is
            // v left minus v right.
            on_segment_({{s.x_top, band.y_top}, {s.x_bottom, band.y_bottom}, -s.jump});
            top_.push_back({s.x_top, s.value_right});
        }
        if (has_previous_ && previous_y_ == band.y_top) {
            border(bottom_, top_, band.y_top);
        } else {
            finish();
            border({}, top_, band.y_top);
        }
        bottom_.clear();
        for (const BandSegment& s : band.segments) {
            if (s.jump != 0.0) bottom_.push_back({s.x_bottom, s.value_right});
        }
        has_previous_ = true;
        previous_y_ = band.y_bottom;
    }

    // Closes the last band: below it (until the next band) v is the background.
    void finish() {
        if (has_previous_) border(bottom_, {}, previous_y_);
        has_previous_ = false;
    }

private:
    // Emits the horizontal pieces at height y where v just below (`below`) differs from v
    // just above (`above`). Both are in walk order, the true order inside the band. At the
    // border that order may disagree with the rounded x: two edges that cross exactly on the
    // border (every crossing is a border) have equal true x but x_at values an ulp apart in
    // either order, and crossings within kMinBandHeight of a border are not split off. Such
    // an inversion means "coincident here", so x is made monotone along the walk (a running
    // maximum) instead of sorting, which would pair the values with the wrong intervals.
    void border(std::vector<Step> above, std::vector<Step> below, double y) {
        for (std::vector<Step>* steps : {&above, &below}) {
            for (std::size_t k = 1; k < steps->size(); ++k) {
                (*steps)[k].x = std::max((*steps)[k].x, (*steps)[k - 1].x);
            }
        }
        double v_above = background_, v_below = background_;
        std::size_t i = 0, k = 0;
        double x = -HUGE_VAL;
        while (i < above.size() || k < below.size()) {
            const double next = std::min(i < above.size() ? above[i].x : HUGE_VAL,
                                         k < below.size() ? below[k].x : HUGE_VAL);
            emit(x, next, y, v_below - v_above);
            x = next;
            while (i < above.size() && above[i].x == x) v_above = above[i++].value;
            while (k < below.size() && below[k].x == x) v_below = below[k++].value;
        }
        emit(x, HUGE_VAL, y, v_below - v_above);  // zero for closed contours
    }

    void emit(double x0, double x1, double y, double weight) {
        if (weight == 0.0) return;
        x0 = std::max(x0, x_lo_);
        x1 = std::min(x1, x_hi_);
        if (x0 < x1) on_segment_({{x0, y}, {x1, y}, weight});
    }

    double background_, x_lo_, x_hi_;
    const std::function<void(const JumpSegment&)>& on_segment_;
    std::vector<Step> top_, bottom_;
    bool has_previous_ = false;
    double previous_y_ = 0.0;
};

}  // namespace

void for_each_jump_segment(const Scene& scene, int row_lo, int row_hi, double x_lo, double x_hi,
                           const std::function<void(const JumpSegment&)>& on_segment) {
    const EdgeTable table(scene);
    BandSweep sweep(table, row_lo, row_hi);
    JumpSetBuilder builder(scene.background, x_lo, x_hi, on_segment);
    const BandCallback on_band = [&](const Band& band) { builder.band(band); };
    for (int r = row_lo; r < row_hi; ++r) sweep.sweep_row(r, on_band);
    builder.finish();
}

std::vector<JumpSegment> visible_jump_set(const Scene& scene, int row_lo, int row_hi, double x_lo,
                                          double x_hi) {
    std::vector<JumpSegment> out;
    for_each_jump_segment(scene, row_lo, row_hi, x_lo, x_hi,
                          [&](const JumpSegment& s) { out.push_back(s); });
    return out;
}

}  // namespace aabench
