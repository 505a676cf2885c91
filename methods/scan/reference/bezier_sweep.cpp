// Monotone pieces, their crossings and the bands between them (bezier_sweep.h).
#include "methods/scan/reference/bezier_sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>

#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// --- Quarter arcs ---

constexpr double kHalfPi = 0.5 * std::numbers::pi;

// The offset (u, v) of the first quadrant turned by quadrant * 90 degrees.
Point turn(int quadrant, double u, double v) {
    switch (quadrant) {
        case 0: return {u, v};
        case 1: return {-v, u};
        case 2: return {-u, -v};
        default: return {v, -u};
    }
}

double arc_tau(const QuarterArc& arc, double t) { return arc.reversed ? 1.0 - t : t; }

// d - sin(d) for d in [0, pi / 2]: below 1/4 by its Taylor series (six terms: the next is
// below 1e-16 of the sum), where the difference would cancel; above by the difference (its
// relative error ~6 eps / d^2 < 1e-14 there).
double angle_minus_sine(double d) {
    if (d >= 0.25) return d - std::sin(d);
    const double d2 = d * d;
    double series = 1.0;
    for (double k : {156.0, 110.0, 72.0, 42.0, 20.0}) series = 1.0 - d2 / k * series;
    return d * d2 / 6.0 * series;
}

}  // namespace

Point arc_at(const QuarterArc& arc, double t) {
    const double tau = arc_tau(arc, t);
    double u = arc.r, v = 0.0;
    if (tau >= 1.0) {
        u = 0.0;
        v = arc.r;
    } else if (tau > 0.0) {
        u = arc.r * std::cos(tau * kHalfPi);
        v = arc.r * std::sin(tau * kHalfPi);
    }
    const Point d = turn(arc.quadrant, u, v);
    return {arc.center.x + d.x, arc.center.y + d.y};
}

Point arc_derivative(const QuarterArc& arc, double t) {
    const double phi = arc_tau(arc, t) * kHalfPi;
    const double k = (arc.reversed ? -kHalfPi : kHalfPi) * arc.r;
    return turn(arc.quadrant, -k * std::sin(phi), k * std::cos(phi));
}

double arc_area_integral(const QuarterArc& arc, double ta, double tb, double c) {
    const Point pa = arc_at(arc, ta), pb = arc_at(arc, tb);
    const double chord = (0.5 * (pa.x + pb.x) - c) * (pb.y - pa.y);
    // The arc runs counterclockwise in (x, y) as theta grows, so the loop arc-then-chord-back
    // encloses the circular segment with the sign of theta's change.
    const double turned = (arc_tau(arc, tb) - arc_tau(arc, ta)) * kHalfPi;
    const double segment = 0.5 * arc.r * arc.r * angle_minus_sine(std::abs(turned));
    return turned >= 0.0 ? chord + segment : chord - segment;
}

double arc_solve(const QuarterArc& arc, int axis, double value, double lo, double hi) {
    // In the first quadrant's frame the coordinate is u (cos) or v (sin), with a sign.
    const int q = arc.quadrant;
    const bool along_u = (axis + q) % 2 == 0;
    const bool negate = axis == 0 ? (q == 1 || q == 2) : (q >= 2);
    const double offset = value - (axis == 0 ? arc.center.x : arc.center.y);
    const double s = std::clamp(negate ? -offset : offset, 0.0, arc.r);
    const double leg = std::sqrt((arc.r - s) * (arc.r + s));
    const double tau = std::clamp((along_u ? std::atan2(leg, s) : std::atan2(s, leg)) / kHalfPi,
                                  0.0, 1.0);
    return std::clamp(arc.reversed ? 1.0 - tau : tau, lo, hi);
}

namespace {

// --- Crossings: subdividing the boxes of two monotone pieces ---

struct Sub {
    double t0, t1;
    Point a, b;
    double width() const { return std::abs(b.x - a.x); }
    double height() const { return std::abs(b.y - a.y); }
};

bool boxes_overlap(const Sub& p, const Sub& q) {
    return std::max(std::min(p.a.x, p.b.x), std::min(q.a.x, q.b.x)) <=
               std::min(std::max(p.a.x, p.b.x), std::max(q.a.x, q.b.x)) &&
           std::max(std::min(p.a.y, p.b.y), std::min(q.a.y, q.b.y)) <=
               std::min(std::max(p.a.y, p.b.y), std::max(q.a.y, q.b.y));
}

double overlap_mid_y(const Sub& p, const Sub& q) {
    const double lo = std::max(std::min(p.a.y, p.b.y), std::min(q.a.y, q.b.y));
    const double hi = std::min(std::max(p.a.y, p.b.y), std::max(q.a.y, q.b.y));
    return 0.5 * (lo + hi);
}

// Pairs of sub-pieces still overlapping at one subdivision level above which the pieces are
// taken to run together (tangent over a stretch, a cusp, a shared boundary): every pair's
// height becomes a band border and the subdivision stops. The bands are then no taller than
// the boxes, so a crossing among them moves no pixel by more than the boxes' area.
constexpr std::size_t kMaxFrontier = 2048;

void crossings(const BezierPiece& p, const BezierPiece& q, double tolerance,
               std::vector<double>& events) {
    std::vector<std::pair<Sub, Sub>> frontier{{{p.t0, p.t1, p.a, p.b}, {q.t0, q.t1, q.a, q.b}}};
    std::vector<std::pair<Sub, Sub>> next;
    auto split = [](const BezierPiece& s, const Sub& u) {
        const double tm = 0.5 * (u.t0 + u.t1);
        const Point m = piece_at(s, tm);
        return std::pair<Sub, Sub>{{u.t0, tm, u.a, m}, {tm, u.t1, m, u.b}};
    };
    for (int depth = 0; depth < 200 && !frontier.empty(); ++depth) {
        if (frontier.size() > kMaxFrontier) {
            for (const auto& [u, v] : frontier) events.push_back(overlap_mid_y(u, v));
            return;
        }
        next.clear();
        for (const auto& [u, v] : frontier) {
            if (!boxes_overlap(u, v)) continue;
            const double su = std::max(u.width(), u.height());
            const double sv = std::max(v.width(), v.height());
            if ((su <= tolerance && sv <= tolerance) ||
                (u.t1 - u.t0 <= 0.0 && v.t1 - v.t0 <= 0.0)) {
                events.push_back(overlap_mid_y(u, v));
                continue;
            }
            if (su >= sv) {
                const auto [u0, u1] = split(p, u);
                next.push_back({u0, v});
                next.push_back({u1, v});
            } else {
                const auto [v0, v1] = split(q, v);
                next.push_back({u, v0});
                next.push_back({u, v1});
            }
        }
        frontier.swap(next);
    }
    for (const auto& [u, v] : frontier) events.push_back(overlap_mid_y(u, v));
}

// Every crossing height of the pieces (sorted by top), within [y_lo, y_hi].
std::vector<double> crossing_heights(const std::vector<const BezierPiece*>& by_top,
                                     double tolerance, double y_lo, double y_hi) {
    std::vector<double> events;
    std::vector<const BezierPiece*> active;
    for (const BezierPiece* p : by_top) {
        std::erase_if(active, [&](const BezierPiece* q) { return q->y_bottom() < p->y_top(); });
        const double x0 = std::min(p->a.x, p->b.x), x1 = std::max(p->a.x, p->b.x);
        for (const BezierPiece* q : active) {
            // Boxes that meet in no area (disjoint, or touching along a line x = c or y = c)
            // are skipped: a monotone piece that is not vertical reaches its box's border line
            // only at an end, so any point the two share is an end of one of them, whose
            // height is a band border already. Consecutive pieces of a contour meet so (at
            // their shared end), and subdividing them down to the tolerance there cost most of
            // a contour of many short segments (10^5 cubics: 0.45 s). A vertical piece is its
            // box's border line: it meets the other piece inside that piece's box wherever
            // its x lies strictly inside the other's x range (a polygon's vertical edge across
            // a curve), so that case is kept.
            const double q0 = std::min(q->a.x, q->b.x), q1 = std::max(q->a.x, q->b.x);
            const bool x_overlap = std::max(x0, q0) < std::min(x1, q1) ||
                                   (x0 == x1 && q0 < x0 && x0 < q1) ||
                                   (q0 == q1 && x0 < q0 && q0 < x1);
            if (!(x_overlap && p->y_top() < q->y_bottom())) continue;
            crossings(*p, *q, tolerance, events);
        }
        active.push_back(p);
    }
    std::erase_if(events, [&](double y) { return !(y > y_lo && y < y_hi); });
    return events;
}

// Pieces farther apart than this at a band's top are ordered by it: a crossing found to the
// crossing tolerance (1e-12 px boxes) leaves the two pieces far closer than this at its band
// border, so the margin sends every such band to the order at mid-height.
constexpr double kOrderMarginPx = 1e-7;

struct Active {
    const BezierPiece* piece;
    double t_top;
    double t_bottom;
    double x_mid;
    std::size_t order;  // index in by_top: the tie-break
};

}  // namespace

BezierPieces monotone_pieces(const Scene& scene) {
    BezierPieces out;
    std::vector<Segment>& storage = out.storage;
    std::size_t straight = 0, arcs = 0;
    const bool planes = std::any_of(scene.shapes.begin(), scene.shapes.end(),
                                    [](const Shape& shape) { return shape.value_plane.has_value(); });
    for (const Shape& shape : scene.shapes) {
        // An arc's area integrals are in closed form for constant jumps only.
        if (shape.inv_depth || (shape.circle && planes)) {
            throw std::logic_error(
                "Bezier sweep: a shape has a depth plane, or a disc or ring is beside affine "
                "values");
        }
        if (shape.circle) {
            arcs += shape.circle->is_disc() ? 4 : 8;
        } else if (!has_bezier(shape)) {
            for (const Contour& c : shape.contours) straight += c.size();
        }
    }
    storage.clear();
    storage.reserve(straight);  // no reallocation below: the pieces point into it
    out.arcs.reserve(arcs);
    std::vector<std::pair<const Segment*, int>> segments;
    for (std::size_t s = 0; s < scene.shapes.size(); ++s) {
        const Shape& shape = scene.shapes[s];
        if (shape.circle) {  // its circles, not its polygonisation
            const Circle& c = *shape.circle;
            for (const bool inner : {false, true}) {
                const double r = inner ? c.inner : c.outer;
                if (!(r > 0.0)) continue;
                for (int q = 0; q < 4; ++q) {
                    out.arcs.push_back({c.center, r, q, inner});
                    const QuarterArc& arc = out.arcs.back();
                    const Point a = arc_at(arc, 0.0), b = arc_at(arc, 1.0);
                    out.pieces.push_back({nullptr, 0.0, 1.0, a, b, static_cast<int>(s), b.y > a.y,
                                          &arc});
                }
            }
            continue;
        }
        for (const SegmentContour& c : shape.outline) {
            for (const Segment& seg : c) segments.push_back({&seg, static_cast<int>(s)});
        }
        if (has_bezier(shape)) continue;
        for (const Contour& c : shape.contours) {
            for (std::size_t k = 0; k < c.size(); ++k) {
                Segment seg;
                seg.p[0] = c[k];
                seg.p[1] = c[(k + 1) % c.size()];
                storage.push_back(seg);
                segments.push_back({&storage.back(), static_cast<int>(s)});
            }
        }
    }
    std::vector<BezierPiece>& pieces = out.pieces;
    std::vector<double> ts;
    for (const auto& [seg, shape] : segments) {
        ts.assign({0.0, 1.0});
        bezier_extrema(*seg, 0, ts);
        bezier_extrema(*seg, 1, ts);
        std::sort(ts.begin(), ts.end());
        ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
        Point a = seg->p[0];
        for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
            const Point b = bezier_at(*seg, ts[k + 1]);
            if (a.y != b.y) pieces.push_back({seg, ts[k], ts[k + 1], a, b, shape, b.y > a.y});
            a = b;
        }
    }
    return out;
}

void sweep_bezier_bands(const Scene& scene, const BezierPieces& all, double y_lo, double y_hi,
                        const std::function<void(const BezierBand&)>& fn) {
    const std::vector<BezierPiece>& pieces = all.pieces;
    std::vector<const BezierPiece*> by_top;
    double extent = std::max(std::abs(y_lo), std::abs(y_hi));
    for (const BezierPiece& p : pieces) {
        if (p.y_bottom() <= y_lo || p.y_top() >= y_hi) continue;  // no band holds it
        by_top.push_back(&p);
        extent =
            std::max({extent, std::abs(p.a.x), std::abs(p.a.y), std::abs(p.b.x), std::abs(p.b.y)});
    }
    std::stable_sort(by_top.begin(), by_top.end(), [](const BezierPiece* u, const BezierPiece* v) {
        return u->y_top() < v->y_top();
    });
    // Boxes below a few ulps of the coordinates cannot be split further.
    const double tolerance =
        std::max(kIntersectionTolerancePx, 16.0 * std::numeric_limits<double>::epsilon() * extent);
    std::vector<double> events = crossing_heights(by_top, tolerance, y_lo, y_hi);
    events.push_back(y_lo);
    events.push_back(y_hi);
    for (const BezierPiece* p : by_top) {
        for (double y : {p->y_top(), p->y_bottom()}) {
            if (y > y_lo && y < y_hi) events.push_back(y);
        }
    }
    std::sort(events.begin(), events.end());
    events.erase(std::unique(events.begin(), events.end()), events.end());

    std::vector<AffinePlane> values(scene.shapes.size());
    for (std::size_t s = 0; s < values.size(); ++s) {
        const Shape& shape = scene.shapes[s];
        values[s] = shape.value_plane.value_or(AffinePlane{shape.value, 0.0, 0.0});
    }
    const AffinePlane background{scene.background, 0.0, 0.0};
    std::vector<int> winding(scene.shapes.size(), 0);
    std::set<int> inside;  // shapes of nonzero winding number, the last one visible
    std::vector<Active> active;
    std::vector<BandPiece> band_pieces;
    std::size_t next = 0;
    for (std::size_t e = 0; e + 1 < events.size(); ++e) {
        const double top = events[e], bottom = events[e + 1], mid = 0.5 * (top + bottom);
        std::erase_if(active, [&](const Active& a) { return a.piece->y_bottom() <= top; });
        for (Active& a : active) a.t_top = a.t_bottom;
        for (; next < by_top.size() && by_top[next]->y_top() <= top; ++next) {
            const BezierPiece* p = by_top[next];
            if (p->y_bottom() <= top) continue;
            const double t = p->y_top() == top ? p->t_top() : piece_solve(*p, 1, top, p->t0, p->t1);
            active.push_back({p, t, t, 0.0, next});
        }
        for (Active& a : active) {
            const BezierPiece& p = *a.piece;
            // Between the band's top and the piece's bottom (monotone): a narrow bracket.
            const double lo = std::min(a.t_top, p.t_bottom()), hi = std::max(a.t_top, p.t_bottom());
            a.t_bottom =
                p.y_bottom() == bottom ? p.t_bottom() : piece_solve(p, 1, bottom, lo, hi);
            a.x_mid = piece_at(p, a.t_top).x;  // at the top, for now
        }
        // The order inside the band: no two pieces cross in it, so pieces apart at its top keep
        // their order through it. Sorted by x at the top; where two neighbours there lie within
        // kOrderMarginPx (they meet at the top, or cross within the crossing tolerance of it),
        // every piece is placed by its x at mid-height instead, a root each.
        auto by_x = [](const Active& u, const Active& v) {
            return u.x_mid != v.x_mid ? u.x_mid < v.x_mid : u.order < v.order;
        };
        std::sort(active.begin(), active.end(), by_x);
        bool close = false;
        for (std::size_t k = 1; k < active.size() && !close; ++k) {
            close = !(active[k].x_mid - active[k - 1].x_mid > kOrderMarginPx);
        }
        if (close) {
            for (Active& a : active) {
                const BezierPiece& p = *a.piece;
                const double mlo = std::min(a.t_top, a.t_bottom), mhi = std::max(a.t_top, a.t_bottom);
                a.x_mid = piece_at(p, piece_solve(p, 1, mid, mlo, mhi)).x;
            }
            std::sort(active.begin(), active.end(), by_x);
        }
        band_pieces.clear();
        AffinePlane before = background;
        for (const Active& a : active) {
            const int s = a.piece->shape;
            const int was = winding[static_cast<std::size_t>(s)];
            const int now = was + (a.piece->down ? 1 : -1);
            winding[static_cast<std::size_t>(s)] = now;
            if (was == 0) inside.insert(s);
            if (now == 0) inside.erase(s);
            const AffinePlane& after =
                inside.empty() ? background : values[static_cast<std::size_t>(*inside.rbegin())];
            if (after != before) {
                band_pieces.push_back({a.piece, a.t_top, a.t_bottom, after.c - before.c,
                                       after.gx - before.gx, after.gy - before.gy});
            }
            before = after;
        }
        for (const Active& a : active) winding[static_cast<std::size_t>(a.piece->shape)] = 0;
        inside.clear();
        fn(BezierBand{top, bottom, band_pieces});
    }
}

}  // namespace aabench
