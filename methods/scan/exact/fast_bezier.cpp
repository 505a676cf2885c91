// The fast exact engine for scenes with Bezier segments (fast_bezier.h): what it computes, and
// why it is exact.
//
// Same value as the band sweep (methods/scan/reference/bezier_sweep.h and bezier_coverage.cpp,
// whose essays this builds on): for pixel (i, j) the integral over the pixel square of the
// visible value v, the value of the last shape whose nonzero winding number is nonzero there,
// else the background. Along a horizontal line v is the background plus the jumps of the
// boundaries left of the point, so a pixel gets the sum over the boundary pieces inside its
// row of jump times the part of the pixel right of the piece: for a monotone piece between
// heights y0 and y1 inside cell c, dy - integral of (x(t) - c) y'(t) dt, a polynomial of
// degree at most 5 in t, which 3-point Gauss-Legendre integrates exactly. The band sweep gets
// the jumps right by cutting the whole scene at every crossing of two pieces (found by
// subdividing their boxes) before it walks a band; that search over every pair of pieces whose
// boxes overlap is most of its time. This engine proves instead, row by row, that nothing
// crosses, and only where it cannot does it hand the row to the band sweep.
//
// - Chains. Every segment is cut where x' or y' vanishes into monotone pieces
//   (monotone_pieces' cuts), and consecutive pieces of a contour that keep running in one
//   vertical direction and meet end to start are one chain, top to bottom: a glyph's contour is
//   two to six chains, however many segments it has. A chain starts and ends only at a turning
//   point of its contour (or at the contour's first point, or beside a horizontal piece), and
//   those heights are the only places a row is cut into sub-bands. Inside a sub-band every
//   chain of the row spans it from top to bottom.
// - A certificate instead of a crossing search. In a sub-band [ya, yb] each chain's x-range is
//   the hull of its points at ya and yb and of its piece junctions between (each piece is
//   monotone in x). The chains are sorted by their ranges and each neighbour pair is checked:
//   if the left one's range ends where the right one's begins or before, the left chain lies
//   left of the right one at every height of the sub-band (touching allowed: two chains of a
//   turning point share their end). Where two ranges overlap, the sub-band is bisected in y
//   (for that pair alone) until every part shows the pair in order, or overlaps by less than
//   kMisorderAreaPx2 (two chains leaving one point: below); the pointwise order is transitive, so
//   proven neighbours order the whole sub-band, and one walk (per-shape winding numbers, the
//   topmost covering shape: visibility_rule.h's CoverWalk) gives every chain its jump, as the band
//   sweep's walk gives its pieces theirs. A pair the bisection cannot order (a crossing, a
//   tangency, a shared boundary) sends the row to the band sweep, bezier_rows_each, which cuts it
//   at the crossing: the row's value is the reference's own.
// - Exactness. Each piece's part in a cell goes through the band sweep's own cell cutting and
//   area integral (for_each_piece_cell, piece_area_integral: bezier_sweep.h), with the same
//   root finder (solve_monotone) at the row and sub-band borders, so a pixel differs from the
//   band sweep's only where the two cut a piece at different heights: rounding of doubles, far
//   below float32's (tests/fast_bezier_test.cpp holds it to the reference).
// - Bands. A chain's parameter at a height is solved in the bracket of its whole piece, so a
//   row's values depend on the row alone: any band split gives the same image.
// - No allocation once warm: the pieces, chains and rows live in a thread_local Scratch whose
//   vectors keep their capacity (rows that fall back allocate in the band sweep).
#include "methods/scan/exact/fast_bezier.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "methods/scan/kernel/cells.h"
#include "methods/scan/kernel/visibility_rule.h"
#include "methods/scan/reference/bezier_coverage.h"
#include "methods/scan/reference/bezier_sweep.h"
#include "methods/scan/reference/piece_coverage.h"
#include "patterns/scene/bezier.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

// Where two chains' x-ranges overlap, the sub-band is cut in y until each part shows them
// apart; a part whose overlap (its height times the width the two ranges share) is at most
// kMisorderAreaPx2 is taken in the sort's order. Were the order wrong there, the region between
// the two chains at the heights where they are swapped lies inside the shared width, so a
// pixel moves by at most that area times the jump: 1e-9 for values of order one, the slack the
// polygon engine allows its order test (fast_engine_p.h, kOrderSlackPx), 1000 times below the
// 1e-6 budget. The parts that need it are where two chains leave one point (a turning point
// of a contour, a spike of two chains running the same way): their ranges share the point in
// every part that holds it, and the shared width shrinks with the part's height.
constexpr double kMisorderAreaPx2 = 1e-9;
// Two chains that share their point at a part's top (or bottom) are cut a sixteenth of the
// part from it, not halfway: the overlap lives near the point, and the far part is then
// usually apart at once, so about four cuts reach kMisorderAreaPx2 (halving took about 15).
constexpr double kNearPointCut = 1.0 / 16.0;
// The cutting's budget per neighbour pair (parts looked at): a pair that runs closer than that
// over a stretch (tangent or shared boundaries, or a crossing) would otherwise be cut down
// everywhere; past the budget the row goes to the band sweep.
constexpr int kRefineBudget = 64;

constexpr double kNoFlatLo = std::numeric_limits<double>::infinity();
constexpr double kNoFlatHi = -std::numeric_limits<double>::infinity();

// A chain: pieces [first, end) of Scratch::pieces, top to bottom.
struct Chain {
    std::uint32_t first = 0, end = 0;
    int shape = 0;
    int winding = 0;  // +1 where the contour runs down, -1 where it runs up
    double y_top = 0.0, y_bottom = 0.0;
    // The x-hull of the horizontal pieces of the contour that meet the chain at its top and at
    // its bottom (empty: +inf, -inf). No row is cut at them, but they are boundaries inside the
    // row where they lie, so they count in the chain's reach there (Engine::draw_row).
    double top_flat_lo = kNoFlatLo, top_flat_hi = kNoFlatHi;
    double bottom_flat_lo = kNoFlatLo, bottom_flat_hi = kNoFlatHi;
};

// A horizontal piece: dropped from the pieces (no horizontal line crosses it), kept as the
// reach it gives the chains beside it.
struct Flat {
    std::size_t next_piece;  // the index the contour's next piece got
    double y, lo, hi;
};

// A chain at one height: the piece holding it, the parameter and x there.
struct Place {
    std::uint32_t piece = 0;
    double t = 0.0;
    double x = 0.0;
};

// A chain in the sub-band being walked.
struct Member {
    std::uint32_t chain = 0;
    Place top, bottom;
    double x_min = 0.0, x_max = 0.0;
    bool ends_inside = false;  // the chain starts or ends inside the row
    // x_min, x_max widened by the horizontal pieces at the chain's ends inside the row: what
    // the row's clusters are made of.
    double reach_lo = 0.0, reach_hi = 0.0;
};

struct Scratch {
    std::vector<Segment> storage;  // polygon contours as straight segments
    std::vector<BezierPiece> pieces;
    std::vector<Chain> chains;
    std::vector<std::uint32_t> by_top;  // chains by their top
    std::vector<std::uint32_t> active;  // chains reaching the current row
    std::vector<std::uint32_t> hint;    // per chain: the piece its next search starts from
    std::vector<double> cuts;
    std::vector<Member> row_members;  // every chain of the row, over its part of the row
    std::vector<Member> members;      // the chains of one sub-band
    std::vector<double> cache_y;      // per chain: the height its last row ended at
    std::vector<Place> cache;         // and its place there
    std::vector<int> fallback;
    std::vector<double> ts;
    std::vector<Flat> flats;  // one contour's horizontal pieces
    CellRow<double, 16> cells;
    CoverWalk walk;
};
thread_local Scratch t_scratch;

// The root of coordinate `axis` (0 x, 1 y) = value on a monotone piece of a segment, t in
// [lo, hi]: solve_monotone's answer (patterns/scene/bezier.h) to within kNewtonStepStop, at a
// fraction of its cost. A line's root in closed form; a curve's by Newton's method on the
// coordinate's power-basis polynomial about the segment's start, started from the secant and
// kept inside the bracket, which every step narrows (a step that would leave it, or that
// follows a step which failed to halve it, is a bisection), until a Newton step moves t by at
// most kNewtonStepStop, the bracket is two doubles wide, or f is 0. solve_monotone narrows the
// bracket to two doubles every time, 30-60 steps a root; this takes 3-5. A function of
// (piece, axis, value, lo, hi) alone, so rows and bands agree.
//
// The error left in t is about the last step where Newton converges linearly (at a piece's
// end, where the coordinate's slope vanishes) and its square elsewhere: at most 1e-12, which
// moves a point of a segment by |B'| 1e-12 px, 1e-9 px for a segment 1000 px long, and a
// pixel's area by as much: 1000 times below the 1e-6 budget.
constexpr double kNewtonStepStop = 1e-12;

double solve_piece(const BezierPiece& piece, int axis, double value, double lo, double hi) {
    if (piece.arc) return piece_solve(piece, axis, value, lo, hi);
    const Segment& seg = *piece.segment;
    auto c = [&](int k) { return axis == 0 ? seg.p[k].x : seg.p[k].y; };
    double a0 = c(0) - value, a1 = 0.0, a2 = 0.0, a3 = 0.0;
    if (seg.degree == 1) {
        a1 = c(1) - c(0);
    } else if (seg.degree == 2) {
        a1 = 2.0 * (c(1) - c(0));
        a2 = c(0) - 2.0 * c(1) + c(2);
    } else {
        a1 = 3.0 * (c(1) - c(0));
        a2 = 3.0 * (c(0) - 2.0 * c(1) + c(2));
        a3 = c(3) - 3.0 * c(2) + 3.0 * c(1) - c(0);
    }
    auto f = [&](double t) { return a0 + t * (a1 + t * (a2 + t * a3)); };
    auto df = [&](double t) { return a1 + t * (2.0 * a2 + t * 3.0 * a3); };
    double flo = f(lo), fhi = f(hi);
    if (flo == 0.0) return lo;
    if (fhi == 0.0) return hi;
    if ((flo > 0.0) == (fhi > 0.0)) return std::abs(flo) <= std::abs(fhi) ? lo : hi;
    double t = lo + (hi - lo) * (flo / (flo - fhi));
    if (seg.degree == 1) return std::clamp(t, lo, hi);
    const bool rising = fhi > 0.0;  // f < 0 at lo, > 0 at hi (or the reverse)
    double step_before = hi - lo, step = step_before;
    for (int k = 0; k < 100; ++k) {
        if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
        const double ft = f(t);
        if (ft == 0.0) return t;
        if ((ft > 0.0) == rising) {
            hi = t;
        } else {
            lo = t;
        }
        const double d = df(t);
        // Newton's step where it lands inside the bracket and shrinks faster than the step
        // before last (Numerical Recipes' rtsafe rule), else a bisection.
        const double newton = d != 0.0 ? t - ft / d : lo - 1.0;
        step_before = step;
        if (newton > lo && newton < hi && std::abs(2.0 * ft) <= std::abs(step_before * d)) {
            step = t - newton;
            t = newton;
            if (std::abs(step) <= kNewtonStepStop) return t;
        } else {
            step = 0.5 * (hi - lo);
            t = lo + step;
            if (!(t > lo && t < hi)) return t;
        }
    }
    return t;
}

Point top_point(const BezierPiece& p) { return p.down ? p.a : p.b; }
Point bottom_point(const BezierPiece& p) { return p.down ? p.b : p.a; }

// The monotone pieces of one contour (its segments in order) and their chains.
void add_contour(Scratch& s, const Segment* segments, std::size_t count, int shape) {
    const std::size_t first = s.pieces.size();
    const std::size_t first_chain = s.chains.size();
    s.flats.clear();
    for (std::size_t k = 0; k < count; ++k) {
        const Segment& seg = segments[k];
        s.ts.assign({0.0, 1.0});
        bezier_extrema(seg, 0, s.ts);
        bezier_extrema(seg, 1, s.ts);
        std::sort(s.ts.begin(), s.ts.end());
        s.ts.erase(std::unique(s.ts.begin(), s.ts.end()), s.ts.end());
        Point a = seg.p[0];
        for (std::size_t m = 0; m + 1 < s.ts.size(); ++m) {
            const Point b = bezier_at(seg, s.ts[m + 1]);
            if (a.y != b.y) {
                s.pieces.push_back({&seg, s.ts[m], s.ts[m + 1], a, b, shape, b.y > a.y});
            } else if (a.x != b.x) {
                s.flats.push_back({s.pieces.size(), a.y, std::min(a.x, b.x), std::max(a.x, b.x)});
            }
            a = b;
        }
    }
    // Runs of pieces of one direction that meet end to start, each reversed to top-to-bottom
    // order when it runs up.
    for (std::size_t k = first; k < s.pieces.size();) {
        std::size_t e = k + 1;
        while (e < s.pieces.size() && s.pieces[e].down == s.pieces[k].down &&
               s.pieces[e].a == s.pieces[e - 1].b) {
            ++e;
        }
        const bool down = s.pieces[k].down;
        if (!down)
            std::reverse(s.pieces.begin() + static_cast<std::ptrdiff_t>(k),
                         s.pieces.begin() + static_cast<std::ptrdiff_t>(e));
        Chain c;
        c.first = static_cast<std::uint32_t>(k);
        c.end = static_cast<std::uint32_t>(e);
        c.shape = shape;
        c.winding = down ? 1 : -1;
        c.y_top = s.pieces[k].y_top();
        c.y_bottom = s.pieces[e - 1].y_bottom();
        s.chains.push_back(c);
        k = e;
    }
    // Each horizontal piece joins the chains before and after it in the contour (it is where
    // one ends and the next begins): their reach at its height.
    const std::size_t last = s.pieces.size();
    if (last == first) return;
    auto chain_of = [&](std::size_t piece) -> Chain& {
        const auto begin = s.chains.begin() + static_cast<std::ptrdiff_t>(first_chain);
        const auto it = std::upper_bound(begin, s.chains.end(), piece,
                                         [](std::size_t p, const Chain& c) { return p < c.first; });
        return *(it - 1);
    };
    for (const Flat& f : s.flats) {
        const std::size_t after = f.next_piece < last ? f.next_piece : first;
        const std::size_t before = f.next_piece > first ? f.next_piece - 1 : last - 1;
        for (const std::size_t piece : {before, after}) {
            Chain& c = chain_of(piece);
            if (c.y_top == f.y) {
                c.top_flat_lo = std::min(c.top_flat_lo, f.lo);
                c.top_flat_hi = std::max(c.top_flat_hi, f.hi);
            }
            if (c.y_bottom == f.y) {
                c.bottom_flat_lo = std::min(c.bottom_flat_lo, f.lo);
                c.bottom_flat_hi = std::max(c.bottom_flat_hi, f.hi);
            }
        }
    }
}

void extract(Scratch& s, const Scene& scene) {
    s.storage.clear();
    s.pieces.clear();
    s.chains.clear();
    std::size_t straight = 0;
    for (const Shape& shape : scene.shapes) {
        if (has_bezier(shape)) continue;
        for (const Contour& c : shape.contours) straight += c.size();
    }
    s.storage.reserve(straight);  // no reallocation below: the pieces point into it
    for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
        const Shape& shape = scene.shapes[k];
        const int index = static_cast<int>(k);
        if (has_bezier(shape)) {
            for (const SegmentContour& c : shape.outline) add_contour(s, c.data(), c.size(), index);
            continue;
        }
        for (const Contour& c : shape.contours) {
            const std::size_t start = s.storage.size();
            for (std::size_t v = 0; v < c.size(); ++v) {
                Segment seg;
                seg.p[0] = c[v];
                seg.p[1] = c[v + 1 == c.size() ? 0 : v + 1];
                s.storage.push_back(seg);
            }
            add_contour(s, s.storage.data() + start, c.size(), index);
        }
    }
    s.by_top.resize(s.chains.size());
    for (std::size_t k = 0; k < s.chains.size(); ++k) s.by_top[k] = static_cast<std::uint32_t>(k);
    std::sort(s.by_top.begin(), s.by_top.end(), [&](std::uint32_t a, std::uint32_t b) {
        return s.chains[a].y_top < s.chains[b].y_top;
    });
    s.hint.resize(s.chains.size());
    s.cache_y.assign(s.chains.size(), std::numeric_limits<double>::quiet_NaN());
    s.cache.resize(s.chains.size());
}

// Chain c at height y (c.y_top <= y <= c.y_bottom), its pieces searched from `from` down; at
// the junction of two pieces, the lower one when `below` (the piece that goes on below y).
// The parameter is solved in the bracket of the whole piece, so it is a function of y alone.
Place place_at(const Scratch& s, const Chain& c, std::uint32_t from, double y, bool below) {
    std::uint32_t k = std::max(from, c.first);
    while (k + 1 < c.end &&
           (s.pieces[k].y_bottom() < y || (below && s.pieces[k].y_bottom() == y))) {
        ++k;
    }
    const BezierPiece& p = s.pieces[k];
    if (y <= p.y_top()) return {k, p.t_top(), top_point(p).x};
    if (y >= p.y_bottom()) return {k, p.t_bottom(), bottom_point(p).x};
    const double t = solve_piece(p, 1, y, p.t0, p.t1);
    return {k, t, piece_at(p, t).x};
}

// The hull of a chain's x between two of its places: their x and its piece junctions between.
void x_range(const Scratch& s, const Place& top, const Place& bottom, double& lo, double& hi) {
    lo = std::min(top.x, bottom.x);
    hi = std::max(top.x, bottom.x);
    for (std::uint32_t k = top.piece; k < bottom.piece; ++k) {
        const double x = bottom_point(s.pieces[k]).x;
        lo = std::min(lo, x);
        hi = std::max(hi, x);
    }
}

// Whether chain l lies left of chain r (touching allowed) at every height of [y0, y1], given
// their places there, to within kMisorderAreaPx2: their ranges, cut in y where they overlap,
// within `budget` parts.
bool ordered(const Scratch& s, const Chain& l, const Chain& r, double y0, double y1,
             const Place& l0, const Place& l1, const Place& r0, const Place& r1, int& budget) {
    double llo, lhi, rlo, rhi;
    x_range(s, l0, l1, llo, lhi);
    x_range(s, r0, r1, rlo, rhi);
    if (lhi <= rlo) return true;
    if (rhi < llo || --budget < 0) return false;  // apart the other way round, or out of budget
    if ((y1 - y0) * (lhi - rlo) <= kMisorderAreaPx2) return true;
    double ym = 0.5 * (y0 + y1);
    if (l0.x == r0.x) {
        ym = y0 + kNearPointCut * (y1 - y0);
    } else if (l1.x == r1.x) {
        ym = y1 - kNearPointCut * (y1 - y0);
    }
    if (!(ym > y0 && ym < y1)) return false;
    const Place lm = place_at(s, l, l0.piece, ym, true);
    const Place rm = place_at(s, r, r0.piece, ym, true);
    return ordered(s, l, r, y0, ym, l0, lm, r0, rm, budget) &&
           ordered(s, l, r, ym, y1, lm, l1, rm, r1, budget);
}

class Engine {
public:
    Engine(const Scene& scene, Image& out, int row_lo, int row_hi, FastBezierStats& stats)
        : scene_(scene), out_(out), lo_(row_lo), hi_(row_hi), stats_(stats), s_(t_scratch) {}

    void run() {
        extract(s_, scene_);
        s_.cells.reset(scene_.width);
        s_.walk.reset(static_cast<int>(scene_.shapes.size()));
        s_.active.clear();
        s_.fallback.clear();
        std::size_t next = 0;
        for (int j = lo_; j < hi_; ++j) {
            const double y0 = j, y1 = j + 1.0;
            std::erase_if(s_.active, [&](std::uint32_t c) { return s_.chains[c].y_bottom <= y0; });
            for (; next < s_.by_top.size() && s_.chains[s_.by_top[next]].y_top < y1; ++next) {
                const std::uint32_t c = s_.by_top[next];
                if (s_.chains[c].y_bottom <= y0) continue;
                s_.active.push_back(c);
                s_.hint[c] = s_.chains[c].first;
            }
            ++stats_.rows;
            float* row = out_.row(j);
            if (s_.active.empty()) {
                ++stats_.empty_rows;
                std::fill(row, row + scene_.width, static_cast<float>(scene_.background));
                continue;
            }
            if (!draw_row(y0, y1)) {
                s_.cells.clear();
                s_.fallback.push_back(j);
                ++stats_.fallback_rows;
                continue;
            }
            s_.cells.resolve_and_clear(scene_.background, row, [](std::size_t, double sum) {
                return static_cast<float>(sum);
            });
        }
        if (!s_.fallback.empty()) bezier_rows_each(scene_, s_.fallback, out_);
    }

private:
    // Chain c at height y through its cache: the place its last row ended at, when y is that
    // height (the lower piece at a junction when `below`), else place_at. The same place
    // either way: a place is a function of the chain and the height.
    Place cached_place(std::uint32_t c, double y, bool below) {
        const Chain& chain = s_.chains[c];
        if (s_.cache_y[c] == y) {
            Place p = s_.cache[c];
            if (below && p.piece + 1 < chain.end && s_.pieces[p.piece].y_bottom() == y) {
                ++p.piece;
                p.t = s_.pieces[p.piece].t_top();
            }
            return p;
        }
        return place_at(s_, chain, s_.hint[c], y, below);
    }

    // Row [y0, y1] into the cells; false (the cells to be cleared) where an order is not
    // proven. The row's chains are sorted by their x-ranges over the row and grouped into
    // clusters of overlapping or touching ranges: between two clusters lies a strip of
    // positive width that no boundary enters over the row's height, so what is seen there is
    // one state for the whole row, and each cluster is walked from it alone, cut into
    // sub-bands only at its own chains' ends. (Touching ranges join: two chains leaving one
    // point inside the row touch there, and the state beside the point changes at its height.)
    bool draw_row(double y0, double y1) {
        s_.row_members.clear();
        for (const std::uint32_t c : s_.active) {
            const Chain& chain = s_.chains[c];
            const double ya = std::max(y0, chain.y_top), yb = std::min(y1, chain.y_bottom);
            Member m;
            m.chain = c;
            m.top = cached_place(c, ya, true);
            m.bottom = place_at(s_, chain, m.top.piece, yb, false);
            s_.cache_y[c] = yb;
            s_.cache[c] = m.bottom;
            x_range(s_, m.top, m.bottom, m.x_min, m.x_max);
            m.ends_inside = chain.y_top > y0 || chain.y_bottom < y1;
            if (chain.y_top > y0) {  // a horizontal piece at its top lies inside the row
                m.reach_lo = std::min(m.x_min, chain.top_flat_lo);
                m.reach_hi = std::max(m.x_max, chain.top_flat_hi);
            } else {
                m.reach_lo = m.x_min;
                m.reach_hi = m.x_max;
            }
            if (chain.y_bottom < y1) {
                m.reach_lo = std::min(m.reach_lo, chain.bottom_flat_lo);
                m.reach_hi = std::max(m.reach_hi, chain.bottom_flat_hi);
            }
            s_.row_members.push_back(m);
        }
        // By reach: a cluster is a run of members whose reaches overlap or touch. Inside one
        // the sort by range comes back (walk_band and draw_cut_cluster sort their members).
        std::sort(s_.row_members.begin(), s_.row_members.end(),
                  [](const Member& a, const Member& b) { return a.reach_lo < b.reach_lo; });
        CellRow<double, 16>::HeldPair held(s_.cells);
        const std::size_t n = s_.row_members.size();
        for (std::size_t a = 0; a < n;) {
            std::size_t b = a + 1;
            double reach = s_.row_members[a].reach_hi;
            bool cut = s_.row_members[a].ends_inside;
            while (b < n && s_.row_members[b].reach_lo <= reach) {
                reach = std::max(reach, s_.row_members[b].reach_hi);
                cut = cut || s_.row_members[b].ends_inside;
                ++b;
            }
            const std::span<Member> cluster(s_.row_members.data() + a, b - a);
            if (!cut) sort_members(cluster);
            if (!(cut ? draw_cut_cluster(cluster, y0, y1, held)
                      : walk_band(cluster, y0, y1, held))) {
                held.discard();
                s_.walk.clear();
                return false;
            }
            a = b;
        }
        s_.walk.clear();
        return true;
    }

    static void sort_members(std::span<Member> members) {
        std::sort(members.begin(), members.end(), [](const Member& a, const Member& b) {
            return a.x_min < b.x_min || (a.x_min == b.x_min && a.x_max < b.x_max);
        });
    }

    // A cluster with chains that start or end inside the row: sub-band by sub-band between
    // those ends, each walked from the state left of the cluster (the walk is unwound after
    // every sub-band but the last, whose end state is the one right of the cluster).
    bool draw_cut_cluster(std::span<const Member> cluster, double y0, double y1,
                          CellRow<double, 16>::HeldPair& held) {
        s_.cuts.clear();
        for (const Member& m : cluster) {
            const Chain& chain = s_.chains[m.chain];
            if (chain.y_top > y0 && chain.y_top < y1) s_.cuts.push_back(chain.y_top);
            if (chain.y_bottom > y0 && chain.y_bottom < y1) s_.cuts.push_back(chain.y_bottom);
        }
        std::sort(s_.cuts.begin(), s_.cuts.end());
        s_.cuts.erase(std::unique(s_.cuts.begin(), s_.cuts.end()), s_.cuts.end());
        double ya = y0;
        for (std::size_t k = 0; k <= s_.cuts.size(); ++k) {
            const double yb = k < s_.cuts.size() ? s_.cuts[k] : y1;
            s_.members.clear();
            for (const Member& row : cluster) {
                const Chain& chain = s_.chains[row.chain];
                if (chain.y_top > ya || chain.y_bottom < yb) continue;  // not in this sub-band
                Member m;
                m.chain = row.chain;
                m.top = ya == std::max(y0, chain.y_top)
                            ? row.top
                            : place_at(s_, chain, row.top.piece, ya, true);
                m.bottom = yb == std::min(y1, chain.y_bottom)
                               ? row.bottom
                               : place_at(s_, chain, m.top.piece, yb, false);
                x_range(s_, m.top, m.bottom, m.x_min, m.x_max);
                s_.members.push_back(m);
            }
            sort_members(s_.members);
            if (!walk_band(s_.members, ya, yb, held)) return false;
            if (k < s_.cuts.size()) {
                for (auto it = s_.members.rbegin(); it != s_.members.rend(); ++it) {
                    const Chain& chain = s_.chains[it->chain];
                    s_.walk.cross(chain.shape, -chain.winding);
                }
            }
            ya = yb;
        }
        return true;
    }

    // Members spanning [ya, yb], sorted by their ranges: the order proven between neighbours,
    // then the walk from the current state, each chain's jump into the cells.
    bool walk_band(std::span<const Member> members, double ya, double yb,
                   CellRow<double, 16>::HeldPair& held) {
        ++stats_.sub_bands;
        for (std::size_t k = 0; k + 1 < members.size(); ++k) {
            const Member& l = members[k];
            const Member& r = members[k + 1];
            if (l.x_max <= r.x_min) continue;
            ++stats_.refined_pairs;
            int budget = kRefineBudget;
            if (!ordered(s_, s_.chains[l.chain], s_.chains[r.chain], ya, yb, l.top, l.bottom, r.top,
                         r.bottom, budget)) {
                return false;
            }
        }
        // The walk: each chain's jump is the value right of it minus the value left of it.
        auto seen = [&] {
            const int top = s_.walk.top();
            return top < 0 ? scene_.background : scene_.shapes[top].value;
        };
        double before = seen();
        for (const Member& m : members) {
            const Chain& chain = s_.chains[m.chain];
            s_.walk.cross(chain.shape, chain.winding);
            const double after = seen();
            const double jump = after - before;
            before = after;
            s_.hint[m.chain] = std::max(s_.hint[m.chain], m.bottom.piece);
            if (jump != 0.0) accumulate(m, ya, yb, jump, held);
        }
        return true;
    }

    // The chain's part [ya, yb] times `jump` into the cells, piece by piece, cell by cell.
    void accumulate(const Member& m, double ya, double yb, double jump,
                    CellRow<double, 16>::HeldPair& held) {
        const int width = scene_.width;
        for (std::uint32_t k = m.top.piece; k <= m.bottom.piece; ++k) {
            const BezierPiece& p = s_.pieces[k];
            const bool first = k == m.top.piece, last = k == m.bottom.piece;
            const double ta = first ? m.top.t : p.t_top(), tb = last ? m.bottom.t : p.t_bottom();
            const double y_from = first ? ya : p.y_top(), y_to = last ? yb : p.y_bottom();
            if (!(y_from < y_to)) continue;
            for_each_piece_cell(
                p, ta, tb, y_from, y_to, width,
                [&](double cell, double t0, double t1, double c0, double c1) {
                    const double dy = c1 - c0;
                    if (cell < 0.0) {
                        s_.cells[0] += jump * dy;
                        return;
                    }
                    const double area = piece_area_integral(p, t0, t1, cell);
                    held.add_cell(static_cast<std::size_t>(cell), jump * (dy - area), jump * area);
                },
                solve_piece);
        }
    }

    const Scene& scene_;
    Image& out_;
    int lo_, hi_;
    FastBezierStats& stats_;
    Scratch& s_;
};

}  // namespace

bool fast_bezier_draws(const Scene& scene) {
    return has_bezier(scene) && !has_curves(scene) && !has_depth_planes(scene) &&
           !has_affine_values(scene);
}

void fast_bezier_rows(const Scene& scene, Image& out, int row_lo, int row_hi,
                      FastBezierStats* stats) {
    require_window_frame(scene, "fast Bezier rows");
    FastBezierStats local;
    row_lo = std::max(row_lo, 0);
    row_hi = std::min(row_hi, scene.height);
    if (row_lo >= row_hi) return;
    Engine(scene, out, row_lo, row_hi, stats ? *stats : local).run();
}

}  // namespace aabench
