// The band sweep and the jump set of the visible value (see visible_boundary.h).
//
// The bands. Inside row r, consecutive edges of a contour that keep running downwards form a
// chain (Edge::below): a y-monotone polyline across which v jumps by the same amount all along
// until another boundary crosses it. Row r is split only where a chain starts or ends inside
// (r, r+1) (a contour's turning points) and where two chains cross. A polygonal circle of
// 1000 vertices thus costs two chains per row, not a band per vertex: the sweep does
// O(chains log chains + vertices) work per band, and bands per row are 1 + turning points +
// crossings, which keeps the box reference at O(edges + pixels touched) for patterns made of
// many short edges (rings, zone plates). Crossings are found between neighbours in the
// mid-height order (sweep_band says why that suffices) at the exact height where their gap
// changes sign. Within a crossing-free band, the order at mid-height is the order everywhere,
// and a walk in that order (VisibilityWalker) gives each chain's jump.
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
#include "methods/scan/reference/visible_boundary.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace aabench {
namespace {

constexpr double kMinBandHeight = 1e-13;

// How far right of its left neighbour (at mid-height) a chain may lie left of it, at a vertex
// height, and still count as touching rather than crossing. Chains that coincide over part of
// a band and then part (pieces of a 3-D scene sharing an edge up to a T-junction, then
// leaving each other) have a gap of a few ulps of either sign along the shared part, so the
// mid-height order between them is a coin toss; a sign test at 0 then missed the crossing
// where the gap became truly negative whenever the shared part's rounding was negative too,
// and the band below the T-junction was walked in the wrong order (0.044 off in a pixel of
// `interpenetrate` in motion, found through its crawl). With this slack the part is split
// where the gap leaves [-slack, inf). A true overlap narrower than it treated as touching
// misassigns at most kTouchSlackPx x (band height <= 1) x |jump| per pixel: 1e-9 for values
// of order one, far below the 1e-6 every exact engine is held to (the fast engine's order
// certificate uses the same slack, fast_coverage.cpp).
constexpr double kTouchSlackPx = 1e-9;

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
    const auto& edges = table_.edges();
    const double top = r, bottom = r + 1.0;
    // Chains: start at an edge that enters the row from above or has no edge above it, and
    // follow `below` while the next edge starts inside the row. An edge with an edge above
    // it that starts inside the row is reached from that edge (which overlaps the row too).
    chains_.clear();
    chain_edges_.clear();
    breaks_.assign({top, bottom});
    for (const std::uint32_t idx : ids) {
        const Edge& head = edges[idx];
        if (head.y0 > top && head.above >= 0) continue;
        Chain chain{static_cast<std::uint32_t>(chain_edges_.size()), 0, std::max(head.y0, top),
                    0.0};
        std::uint32_t cur = idx;
        for (;;) {
            chain_edges_.push_back(cur);
            const int next = edges[cur].below;
            if (next < 0 || edges[next].y0 >= bottom) break;
            cur = static_cast<std::uint32_t>(next);
        }
        chain.count = static_cast<std::uint32_t>(chain_edges_.size()) - chain.first;
        chain.y_end = std::min(edges[cur].y1, bottom);
        if (!(chain.y_end > chain.y_start)) continue;
        if (chain.y_start > top) breaks_.push_back(chain.y_start);
        if (chain.y_end < bottom) breaks_.push_back(chain.y_end);
        chains_.push_back(chain);
    }
    std::sort(breaks_.begin(), breaks_.end());
    breaks_.erase(std::unique(breaks_.begin(), breaks_.end()), breaks_.end());
    const std::vector<double> breaks = breaks_;  // sweep_band reuses the members
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
        sweep_band(breaks[k], breaks[k + 1], 0, on_band);
    }
}

// The chains spanning [ya, yb] as polylines (their vertices inside the band plus the two
// ends), sorted by x at mid-height.
void BandSweep::collect_active(double ya, double yb) {
    const auto& edges = table_.edges();
    const double ym = 0.5 * (ya + yb);
    active_.clear();
    points_.clear();
    for (std::uint32_t c = 0; c < chains_.size(); ++c) {
        const Chain& chain = chains_[c];
        if (!(chain.y_start <= ya && chain.y_end >= yb)) continue;
        Active a{c, static_cast<std::uint32_t>(points_.size()), 0, 0.0};
        bool started = false;
        for (std::uint32_t k = 0; k < chain.count; ++k) {
            const Edge& e = edges[chain_edges_[chain.first + k]];
            if (e.y1 <= ya) continue;
            if (e.y0 >= yb) break;
            if (!started) {
                points_.push_back({ya, e.x_at(ya)});
                started = true;
            }
            if (ym >= e.y0 && ym <= e.y1) a.x_mid = e.x_at(ym);
            if (e.y1 < yb) {
                points_.push_back({e.y1, e.x1});
            } else {
                points_.push_back({yb, e.x_at(yb)});
                break;
            }
        }
        a.count = static_cast<std::uint32_t>(points_.size()) - a.first;
        active_.push_back(a);
    }
    // Chains come in edge order, which for most patterns is nearly x order already (bars,
    // strips, wedges are generated left to right): an insertion sort is linear then.
    const auto by_x = [](const Active& a, const Active& b) { return a.x_mid < b.x_mid; };
    std::size_t descents = 0;
    for (std::size_t k = 1; k < active_.size(); ++k) descents += by_x(active_[k], active_[k - 1]);
    if (descents * 16 > active_.size()) {
        std::sort(active_.begin(), active_.end(), by_x);
    } else {
        for (std::size_t k = 1; k < active_.size(); ++k) {
            for (std::size_t m = k; m > 0 && by_x(active_[m], active_[m - 1]); --m) {
                std::swap(active_[m], active_[m - 1]);
            }
        }
    }
}

// Appends to crossings_ every height strictly inside (ya, yb) where `right` (right of `left`
// at mid-height) passes to the left of `left`. Both polylines are piecewise linear in y with
// breakpoints at their vertices, so their gap is too: its sign is known from its values at
// the union of the breakpoints, and a sign change is located by linear interpolation.
void BandSweep::gap_crossings(const Active& left, const Active& right, double ya, double yb) {
    const YX* pl = points_.data() + left.first;
    const YX* pr = points_.data() + right.first;
    std::uint32_t i = 0, k = 0;
    // x of a polyline at y, advancing its cursor (y only grows).
    auto x_of = [](const YX* p, std::uint32_t n, std::uint32_t& cur, double y) {
        while (cur + 1 < n && p[cur + 1].y < y) ++cur;
        if (cur + 1 >= n) return p[n - 1].x;
        const YX a = p[cur], b = p[cur + 1];
        if (y <= a.y) return a.x;
        if (y >= b.y) return b.x;
        return a.x + (b.x - a.x) * ((y - a.y) / (b.y - a.y));
    };
    std::uint32_t ci = 0, ck = 0;
    double prev_y = ya;
    double prev_gap = x_of(pr, right.count, ck, ya) - x_of(pl, left.count, ci, ya);
    while (i < left.count || k < right.count) {
        double y;
        if (k >= right.count || (i < left.count && pl[i].y <= pr[k].y)) {
            y = pl[i++].y;
        } else {
            y = pr[k++].y;
        }
        if (!(y > prev_y)) continue;
        const double gap = x_of(pr, right.count, ck, y) - x_of(pl, left.count, ci, y);
        const bool was_apart = prev_gap >= -kTouchSlackPx, is_apart = gap >= -kTouchSlackPx;
        if (was_apart != is_apart) {
            // Linear interpolation of where the gap crosses 0, kept inside [prev_y, y] (with a
            // gap that was a rounding-sized negative, the zero lies just above prev_y).
            const double t = std::clamp(prev_gap / (prev_gap - gap), 0.0, 1.0);
            const double yc = prev_y + (y - prev_y) * t;
            if (yc - ya > kMinBandHeight && yb - yc > kMinBandHeight) crossings_.push_back(yc);
        }
        prev_y = y;
        prev_gap = gap;
    }
}

// Splits [ya, yb] at the crossings of its chains, then walks each crossing-free part.
// Neighbours in the mid-height order suffice: if chains A < B < C (at mid-height) cross
// anywhere, then where A meets C, B is on the wrong side of A or of C, so one neighbouring
// pair's gap changed sign before that. A part is split at most kMaxSplitDepth times deep:
// a crossing found again within kMinBandHeight of a part's border is rounding, not geometry.
void BandSweep::sweep_band(double ya, double yb, int depth, const BandCallback& on_band) {
    constexpr int kMaxSplitDepth = 8;
    collect_active(ya, yb);
    if (active_.empty()) return;
    crossings_.clear();
    for (std::size_t k = 0; k + 1 < active_.size(); ++k) {
        gap_crossings(active_[k], active_[k + 1], ya, yb);
    }
    if (crossings_.empty() || depth >= kMaxSplitDepth) {
        walk_band(ya, yb, on_band);
        return;
    }
    std::vector<double> cuts = crossings_;
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    cuts.insert(cuts.begin(), ya);
    cuts.push_back(yb);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        if (cuts[k + 1] > cuts[k]) sweep_band(cuts[k], cuts[k + 1], depth + 1, on_band);
    }
}

// No crossings inside [ya, yb] (active_ holds its chains in order): walk them left to right.
void BandSweep::walk_band(double ya, double yb, const BandCallback& on_band) {
    const auto& edges = table_.edges();
    walker_.reset();
    double before = table_.background();
    segments_.clear();
    for (const Active& a : active_) {
        const Chain& chain = chains_[a.chain];
        std::uint32_t first = chain_edges_[chain.first];
        for (std::uint32_t k = 0; k < chain.count; ++k) {
            first = chain_edges_[chain.first + k];
            if (edges[first].y1 > ya) break;
        }
        const Edge& e = edges[first];
        const double after = walker_.cross(e.shape, e.winding);
        segments_.push_back({points_[a.first].x, points_[a.first + a.count - 1].x,
                             after - before, after, first});
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
    JumpSetBuilder(const EdgeTable& table, double x_lo, double x_hi,
                   const std::function<void(const JumpSegment&)>& on_segment)
        : table_(table), background_(table.background()), x_lo_(x_lo), x_hi_(x_hi),
          on_segment_(on_segment) {}

    // The band's pieces, and the horizontal pieces at its top border.
    //
    // The walk order is the true order of the segments inside the band. At its borders the
    // rounded x may disagree: two edges that cross exactly on a border (every crossing is one)
    // have equal true x but x_at values apart in either order, and a crossing within
    // kMinBandHeight of a border is not split off at all. For edges of ordinary slope the
    // disagreement is an ulp; along nearly horizontal edges (dx/dy of 1e10 and more, up to
    // 1e300) an unresolved crossing inverts the order at the border by 1e-5 px and up to whole
    // pixels, and the part of a piece on the wrong side of the crossing carries the wrong
    // weight there. Such an inversion means "coincident here", so each border's x are made
    // monotone along the walk (a running maximum) and the pieces themselves start and end at
    // those x: the pieces and the horizontal steps between them then describe one closed jump
    // set (weights in = weights out at every point), which a radial filter needs, since it
    // weighs every loose end in full. Found by the hard-case suite (2e-5 at a pixel near
    // crossing edges of slope 1e-11) and the render fuzzer (0.56 near an edge of slope 1e-300).
    void band(const Band& band) {
        std::vector<Step> top, bottom;
        double x_top = -HUGE_VAL, x_bottom = -HUGE_VAL;
        for (const BandSegment& s : band.segments) {
            if (s.jump == 0.0) continue;
            x_top = std::max(x_top, s.x_top);
            x_bottom = std::max(x_bottom, s.x_bottom);
            // Downward pieces: their right-hand side (cross > 0) is the left, so the weight
            // is v left minus v right.
            for_each_piece(table_, band, s, [&](double xa, double ya, double xb, double yb) {
                if (ya == band.y_top) xa = x_top;
                if (yb == band.y_bottom) xb = x_bottom;
                on_segment_({{xa, ya}, {xb, yb}, -s.jump});
            });
            top.push_back({x_top, s.value_right});
            bottom.push_back({x_bottom, s.value_right});
        }
        if (has_previous_ && previous_y_ == band.y_top) {
            border(bottom_, top, band.y_top);
        } else {
            finish();
            border({}, top, band.y_top);
        }
        bottom_ = std::move(bottom);
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
    // just above (`above`). Both are in walk order with x monotone (see band()). Each is
    // written as the walk's values (value_right), not as running sums of jumps, so that where
    // they agree the difference is exactly zero and no spurious sliver of weight 1e-17 is
    // reported.
    void border(const std::vector<Step>& above, const std::vector<Step>& below, double y) {
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

    const EdgeTable& table_;
    double background_, x_lo_, x_hi_;
    const std::function<void(const JumpSegment&)>& on_segment_;
    std::vector<Step> bottom_;  // the previous band's bottom border
    bool has_previous_ = false;
    double previous_y_ = 0.0;
};

}  // namespace

void for_each_jump_segment(const Scene& scene, int row_lo, int row_hi, double x_lo, double x_hi,
                           const std::function<void(const JumpSegment&)>& on_segment) {
    const EdgeTable table(scene);
    BandSweep sweep(table, row_lo, row_hi);
    JumpSetBuilder builder(table, x_lo, x_hi, on_segment);
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
