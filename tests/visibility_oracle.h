// visibility_oracle.h - slow, exact reference ("oracle") for per-pixel integrals of the visible
// value of a set of planar convex polygons with per-polygon depth planes.
//
// PROBLEM
//   v(x,y) = value of the polygon that contains (x,y) and has the largest w(x,y) = w0 + wx*x + wy*y
//            (larger w = nearer; exact ties in w -> larger polygon index wins), or `background`.
//   out[j*width + i] = integral of v over the pixel square [i,i+1] x [j,j+1].
//
// ALGORITHM: vertical slab decomposition of a line arrangement.
//   1. "Curves" are straight, non-vertical lines or segments:
//        - every non-vertical polygon edge (a segment over its x-extent),
//        - for every pair of polygons whose bounding boxes overlap, the depth-equality line
//          w_A(x,y) = w_B(x,y) (taken as an infinite line - a superset of what is needed),
//        - the horizontal pixel-row boundaries y = 0, 1, ..., height (infinite lines).
//      Vertical things (vertical edges, vertical depth-equality lines x = const) are not curves;
//      their x goes straight into the event list.
//   2. Events = all vertex x, all vertical-edge / vertical-depth-line x, every x where two curves
//      intersect (all pairs, infinite-line intersection filtered by the segments' x-extents), and
//      the pixel column boundaries x = 0..width. Events are clipped to [0,width], sorted, deduplicated.
//      Extra events never hurt correctness; they only cut slabs finer.
//   3. In each open slab (xa, xb) between consecutive events:
//        - every curve present in the slab spans it completely (segment endpoints are events),
//        - no two curves cross inside it (every crossing is an event),
//      so the curves are totally ordered by y, the same order at every x in the slab. Curves whose
//      y at the slab middle lies in [0,height] are sorted by that y; y = 0 and y = height are
//      always among them, so consecutive curves bound trapezoids that tile the slab x [0,height].
//   4. Inside one such trapezoid no polygon edge passes (containment of every polygon is constant)
//      and no depth-equality line passes (for every pair of polygons that can both contain a point,
//      the sign of w_A - w_B is constant; pairs with disjoint bounding boxes never both contain a
//      point). Hence the winner - and the visible value - is constant on the trapezoid, and is found
//      by testing one interior point (slab-middle x, midway between the two curves).
//   5. The trapezoid's area is exact: (xb - xa) * (h(xa) + h(xb)) / 2 with h = y_upper - y_lower,
//      because both bounds are linear in x on the slab. Since integer x are events and the lines
//      y = j are curves, each trapezoid lies inside exactly one pixel, so value * area is added to
//      that pixel. Background trapezoids (no polygon contains the test point) get `background`.
//   Everything is exact in real arithmetic; in floating point the only errors are rounding in the
//   event positions / curve evaluations, which perturb areas by O(eps * coordinate scale) per piece.
//
// Robustness: polygons with < 3 vertices, non-finite data or (relatively) zero area are ignored.
// Vertical edges contribute only events. Parallel curves simply have no intersection event.
// Curve heights at the slab ends are clamped to [0,height] (monotone, so order-preserving) to keep
// near-vertical lines well-behaved. Complexity is O(C^2 + E * C * (log C + P*V)) for C curves,
// E events, P polygons with V vertices: slow but fine for ~12 polygons and 32x32 images.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace aabench::oracle {

struct OraclePolygon {
    std::vector<std::array<double, 2>> vertices;  // convex, either orientation, may be degenerate
    double w0 = 0.0, wx = 0.0, wy = 0.0;          // w(x,y) = w0 + wx*x + wy*y; larger w = nearer
    double value = 0.0;                           // constant value of the polygon
};

namespace detail {

// A usable (finite, non-degenerate, >= 3 vertices) input polygon.
struct UsablePoly {
    const OraclePolygon* src = nullptr;
    double orient = 1.0;  // +1 counter-clockwise, -1 clockwise (sign of the signed area)
    double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
};

inline bool make_usable(const OraclePolygon& p, UsablePoly& out) {
    const auto& v = p.vertices;
    if (v.size() < 3) return false;
    if (!std::isfinite(p.w0) || !std::isfinite(p.wx) || !std::isfinite(p.wy)) return false;
    out.src = &p;
    out.xmin = out.ymin = std::numeric_limits<double>::infinity();
    out.xmax = out.ymax = -std::numeric_limits<double>::infinity();
    double area2 = 0.0;  // twice the signed area, shoelace relative to v[0]
    for (std::size_t k = 0; k < v.size(); ++k) {
        if (!std::isfinite(v[k][0]) || !std::isfinite(v[k][1])) return false;
        const auto& a = v[k];
        const auto& b = v[(k + 1) % v.size()];
        area2 += (a[0] - v[0][0]) * (b[1] - v[0][1]) - (b[0] - v[0][0]) * (a[1] - v[0][1]);
        out.xmin = std::min(out.xmin, a[0]);
        out.xmax = std::max(out.xmax, a[0]);
        out.ymin = std::min(out.ymin, a[1]);
        out.ymax = std::max(out.ymax, a[1]);
    }
    const double scale = std::max(out.xmax - out.xmin, out.ymax - out.ymin);
    if (!(scale > 0.0) || std::abs(area2) <= 1e-12 * scale * scale) return false;  // zero area
    out.orient = area2 > 0.0 ? 1.0 : -1.0;
    return true;
}

// Closed containment test for a convex polygon: the point is on the inner side of every edge.
inline bool contains(const UsablePoly& p, double x, double y) {
    const auto& v = p.src->vertices;
    for (std::size_t k = 0; k < v.size(); ++k) {
        const auto& a = v[k];
        const auto& b = v[(k + 1) % v.size()];
        const double cross = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
        if (cross * p.orient < 0.0) return false;
    }
    return true;
}

// A non-vertical line A*x + B*y + C = 0 (B != 0), optionally a segment over [x0, x1].
struct Curve {
    double A = 0, B = 1, C = 0;
    bool segment = false;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // segment endpoints, x0 < x1
    double xlo() const { return segment ? x0 : -std::numeric_limits<double>::infinity(); }
    double xhi() const { return segment ? x1 : std::numeric_limits<double>::infinity(); }
    double y_at(double x) const {
        if (segment) {  // interpolate between endpoints: bounded by them, well conditioned
            const double t = std::clamp((x - x0) / (x1 - x0), 0.0, 1.0);
            return y0 + t * (y1 - y0);
        }
        return -(A * x + C) / B;
    }
};

inline Curve edge_curve(std::array<double, 2> a, std::array<double, 2> b) {
    if (b[0] < a[0]) std::swap(a, b);
    Curve c;
    c.segment = true;
    c.x0 = a[0]; c.y0 = a[1]; c.x1 = b[0]; c.y1 = b[1];
    c.A = b[1] - a[1];
    c.B = a[0] - b[0];  // = -(x1 - x0) != 0 for non-vertical edges
    c.C = -(c.A * a[0] + c.B * a[1]);
    return c;
}

inline Curve line_curve(double A, double B, double C) {
    Curve c;
    c.A = A; c.B = B; c.C = C;
    return c;
}

}  // namespace detail

// Per-pixel exact integral of the visible value; see the comment at the top of this file.
inline std::vector<double> visible_integral(const std::vector<OraclePolygon>& polys, int width,
                                            int height, double background) {
    using namespace detail;
    if (width <= 0 || height <= 0) return {};
    std::vector<double> out(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0);
    const double W = width, H = height;

    // 1. Usable polygons (kept in input order, so "later index wins" is "later in this list").
    std::vector<UsablePoly> ps;
    for (const auto& p : polys) {
        UsablePoly u;
        if (make_usable(p, u)) ps.push_back(u);
    }

    // 2. Curves and the events that do not come from curve-curve intersections.
    std::vector<Curve> curves;
    std::vector<double> events;
    for (int i = 0; i <= width; ++i) events.push_back(i);
    for (const auto& p : ps) {
        const auto& v = p.src->vertices;
        for (std::size_t k = 0; k < v.size(); ++k) {
            const auto& a = v[k];
            const auto& b = v[(k + 1) % v.size()];
            events.push_back(a[0]);                               // every vertex x
            if (a[0] != b[0]) curves.push_back(edge_curve(a, b));  // vertical edges: event only
        }
    }
    for (std::size_t i = 0; i < ps.size(); ++i) {
        for (std::size_t j = i + 1; j < ps.size(); ++j) {
            const auto& a = ps[i];
            const auto& b = ps[j];
            if (a.xmax < b.xmin || b.xmax < a.xmin || a.ymax < b.ymin || b.ymax < a.ymin) continue;
            // w_a - w_b = C + A x + B y
            const double A = a.src->wx - b.src->wx;
            const double B = a.src->wy - b.src->wy;
            const double C = a.src->w0 - b.src->w0;
            if (B != 0.0) curves.push_back(line_curve(A, B, C));
            else if (A != 0.0) events.push_back(-C / A);  // vertical depth-equality line
            // A == B == 0: parallel planes, their order never changes (or exact tie).
        }
    }
    for (int j = 0; j <= height; ++j) curves.push_back(line_curve(0.0, 1.0, -static_cast<double>(j)));

    // 3. Every pairwise crossing of curves (as lines), kept if inside both x-extents (with slack;
    //    superfluous events are harmless).
    for (std::size_t p = 0; p < curves.size(); ++p) {
        for (std::size_t q = p + 1; q < curves.size(); ++q) {
            const Curve& c1 = curves[p];
            const Curve& c2 = curves[q];
            const double det = c1.A * c2.B - c2.A * c1.B;
            if (det == 0.0) continue;  // parallel
            const double x = (c1.B * c2.C - c2.B * c1.C) / det;
            if (!std::isfinite(x)) continue;
            const double tol = 1e-7 * (1.0 + std::abs(x));
            if (x < c1.xlo() - tol || x > c1.xhi() + tol) continue;
            if (x < c2.xlo() - tol || x > c2.xhi() + tol) continue;
            events.push_back(x);
        }
    }
    std::vector<double> ev;
    for (double x : events)
        if (std::isfinite(x) && x >= 0.0 && x <= W) ev.push_back(x);
    std::sort(ev.begin(), ev.end());
    ev.erase(std::unique(ev.begin(), ev.end()), ev.end());

    // Visible value at a point: max w among containing polygons, ties -> later index.
    auto visible_value = [&](double x, double y) {
        const OraclePolygon* best = nullptr;
        double best_w = 0.0;
        for (const auto& p : ps) {
            if (!contains(p, x, y)) continue;
            const double w = p.src->w0 + p.src->wx * x + p.src->wy * y;
            if (best == nullptr || w >= best_w) {
                best = p.src;
                best_w = w;
            }
        }
        return best ? best->value : background;
    };

    // 4./5. Slabs.
    struct Active {
        double ym, ya, yb;  // y at the slab middle, left end, right end
    };
    std::vector<Active> act;
    for (std::size_t s = 0; s + 1 < ev.size(); ++s) {
        const double xa = ev[s], xb = ev[s + 1];
        if (!(xb > xa)) continue;
        const double xm = 0.5 * (xa + xb);
        const int col = std::clamp(static_cast<int>(std::floor(xm)), 0, width - 1);
        act.clear();
        for (const Curve& c : curves) {
            if (c.segment && !(c.x0 < xm && xm < c.x1)) continue;  // segment not in this slab
            const double ym = c.y_at(xm);
            if (!(ym >= 0.0 && ym <= H)) continue;  // entirely outside [0,H] within the slab
            act.push_back({ym, std::clamp(c.y_at(xa), 0.0, H), std::clamp(c.y_at(xb), 0.0, H)});
        }
        std::sort(act.begin(), act.end(), [](const Active& a, const Active& b) {
            if (a.ym != b.ym) return a.ym < b.ym;
            return a.ya + a.yb < b.ya + b.yb;
        });
        for (std::size_t k = 0; k + 1 < act.size(); ++k) {
            const Active& lo = act[k];
            const Active& hi = act[k + 1];
            if (!(hi.ym > lo.ym)) continue;  // coincident curves: zero-area piece
            const double ha = std::max(0.0, hi.ya - lo.ya);
            const double hb = std::max(0.0, hi.yb - lo.yb);
            const double area = (xb - xa) * 0.5 * (ha + hb);
            if (area == 0.0) continue;
            const double ymid = 0.5 * (lo.ym + hi.ym);
            const int row = std::clamp(static_cast<int>(std::floor(ymid)), 0, height - 1);
            out[static_cast<std::size_t>(row) * width + col] += visible_value(xm, ymid) * area;
        }
    }
    return out;
}

}  // namespace aabench::oracle
