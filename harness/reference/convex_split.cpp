// Splitting convex polygons by lines (see convex_split.h for the contracts).
//
// Why one split is exact up to one rounding per new vertex. A convex polygon meets a line in
// at most two boundary points. Walking the boundary once, every vertex goes to the side its
// value of f says, and every edge whose ends lie strictly on opposite sides contributes the
// point where f = 0 on it, a + t (b - a) with t = f(a) / (f(a) - f(b)) in (0, 1): both parts
// are convex, their union is the polygon and they meet along one segment. The only errors
// are the roundings of t and of the new vertex (a few units in the last place of the
// coordinates); vertices within the caller's tolerance of the line are put on it, which moves
// the cut by at most that tolerance and never makes a vertex a hair away from an old one.
#include "harness/reference/convex_split.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace aabench {

LinearForm edge_form(const Point& a, const Point& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double length = std::hypot(dx, dy);
    // Unit normal pointing left of a -> b, so that f is a distance in pixels.
    return LinearForm{0.0, -dy / length, dx / length, a.x, a.y};
}

std::vector<LinearForm> edge_forms(const Contour& poly) {
    std::vector<LinearForm> forms;
    forms.reserve(poly.size());
    for (std::size_t k = 0; k < poly.size(); ++k) {
        forms.push_back(edge_form(poly[k], poly[(k + 1) % poly.size()]));
    }
    return forms;
}

Bounds bounds_of(const Contour& poly) {
    Bounds b{poly[0].x, poly[0].y, poly[0].x, poly[0].y};
    for (const Point& p : poly) {
        b.x0 = std::min(b.x0, p.x);
        b.x1 = std::max(b.x1, p.x);
        b.y0 = std::min(b.y0, p.y);
        b.y1 = std::max(b.y1, p.y);
    }
    return b;
}

double coordinate_scale(const Contour& poly) {
    double scale = 1.0;
    for (const Point& p : poly) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
    return scale;
}

LinearForm unit_form(const LinearForm& f) {
    const double g = std::hypot(f.nx, f.ny);
    return {f.k / g, f.nx / g, f.ny / g, f.x0, f.y0};
}

bool separated_by_an_edge(const ConvexPolygon& p, const ConvexPolygon& q, double tolerance) {
    auto beyond = [tolerance](const std::vector<LinearForm>& lines, const Contour& other) {
        for (const LinearForm& line : lines) {
            if (std::all_of(other.begin(), other.end(),
                            [&](const Point& v) { return line.at(v) < -tolerance; })) {
                return true;
            }
        }
        return false;
    };
    return beyond(q.e, p.v) || beyond(p.e, q.v);
}

SplitOutcome split_convex(const ConvexPolygon& poly, const LinearForm& f, double tolerance,
                          ConvexPolygon* positive, ConvexPolygon* negative,
                          const LinearForm* cut_edge) {
    // Side of each vertex: +1, -1, or 0 (within the tolerance: on the line).
    const Contour& v = poly.v;
    const std::size_t n = v.size();
    // The sides of the vertices: on the stack for the polygons met in practice (a cut adds at
    // most one vertex to a piece, pieces of triangles and quads rarely pass a dozen), else in a
    // buffer of the thread. A thread_local vector here was a guarded TLS access and a resize
    // per call, millions of calls on a soup of small triangles.
    constexpr std::size_t kOnStack = 32;
    double value_stack[kOnStack];
    int side_stack[kOnStack];
    double* value = value_stack;
    int* side = side_stack;
    if (n > kOnStack) {
        thread_local std::vector<double> value_heap;
        thread_local std::vector<int> side_heap;
        value_heap.resize(n);
        side_heap.resize(n);
        value = value_heap.data();
        side = side_heap.data();
    }
    bool any_positive = false, any_negative = false;
    for (std::size_t k = 0; k < n; ++k) {
        value[k] = f.at(v[k]);
        side[k] = value[k] > tolerance ? 1 : (value[k] < -tolerance ? -1 : 0);
        any_positive |= side[k] > 0;
        any_negative |= side[k] < 0;
    }
    if (!any_negative) return any_positive ? SplitOutcome::kPositive : SplitOutcome::kOnLine;
    if (!any_positive) return SplitOutcome::kNegative;
    const bool track = !poly.e.empty();
    const LinearForm cut_pos = cut_edge ? *cut_edge : f, cut_neg = negated(cut_pos);
    for (ConvexPolygon* part : {positive, negative}) {
        if (!part) continue;
        part->v.clear();
        part->e.clear();
    }
    auto emit = [track](ConvexPolygon* part, const Point& p, const LinearForm& edge) {
        if (!part) return;
        part->v.push_back(p);
        if (track) part->e.push_back(edge);
    };
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t next = (k + 1) % n;
        const LinearForm& edge = track ? poly.e[k] : f;  // f: a placeholder, never stored
        // The edge leaving a vertex: its own, unless it heads into the other side, where the
        // part continues along the cut instead.
        if (side[k] >= 0) emit(positive, v[k], side[k] == 0 && side[next] < 0 ? cut_pos : edge);
        if (side[k] <= 0) emit(negative, v[k], side[k] == 0 && side[next] > 0 ? cut_neg : edge);
        if (side[k] * side[next] < 0) {
            // Both values are beyond the tolerance with opposite signs: t is well inside (0, 1)
            // and the denominator is at least 2 * tolerance away from zero.
            const Point& a = v[k];
            const Point& b = v[next];
            const double t = value[k] / (value[k] - value[next]);
            const Point cut{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
            // Leaving a side, the part follows the cut; entering it, the rest of edge k.
            emit(positive, cut, side[k] > 0 ? cut_pos : edge);
            emit(negative, cut, side[k] < 0 ? cut_neg : edge);
        }
    }
    return SplitOutcome::kSplit;
}

Contour cleaned_contour(const Contour& contour, double slack) {
    Contour poly = contour;
    clean_contour(poly, slack);
    return poly;
}

void clean_contour(Contour& poly, double slack) {
    // Consecutive repeats out, in place (the first of each run kept).
    std::size_t kept = 0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        if (kept == 0 || !(poly[k] == poly[kept - 1])) poly[kept++] = poly[k];
    }
    poly.resize(kept);
    while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
    // Drop a vertex within `slack` of the chord of its neighbours until none is left; a
    // removal changes the neighbours' chords, hence the loop.
    for (bool removed = true; removed && poly.size() >= 3;) {
        removed = false;
        for (std::size_t k = 0; k < poly.size() && poly.size() >= 3;) {
            const Point& a = poly[(k + poly.size() - 1) % poly.size()];
            const Point& p = poly[k];
            const Point& b = poly[(k + 1) % poly.size()];
            const double chord = std::hypot(b.x - a.x, b.y - a.y);
            const double off = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
            // Also catches a repeat of a neighbour (off = 0) and a spike back onto a (chord 0).
            if (std::abs(off) <= slack * chord) {
                poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(k));
                removed = true;
            } else {
                ++k;
            }
        }
    }
    if (poly.size() < 3) {
        poly.clear();
        return;
    }
    if (twice_signed_area(poly) < 0.0) std::reverse(poly.begin(), poly.end());
}

bool is_sliver(const Contour& poly, double width) {
    if (poly.size() < 3) return true;
    const Bounds b = bounds_of(poly);
    const double area2 = std::abs(twice_signed_area(poly));
    // The diagonal lies between max(w, h) and w + h: outside those bounds, widened by 8 units
    // in the last place (more than the roundings of hypot and of the products), the answer is
    // that of the comparison with hypot below, without calling it (millions of calls on a
    // soup, nearly all far from the threshold).
    const double w = b.x1 - b.x0, h = b.y1 - b.y0;
    constexpr double kUlps8 = 8.0 * std::numeric_limits<double>::epsilon();
    if (area2 > width * (w + h) * (1.0 + kUlps8)) return false;
    if (area2 <= width * std::max(w, h) * (1.0 - kUlps8)) return true;
    const double diagonal = std::hypot(w, h);
    return !(area2 > width * diagonal);  // NaN counts as a sliver
}

bool is_convex(const Contour& poly, double slack) {
    const std::size_t n = poly.size();
    for (std::size_t e = 0; e < n; ++e) {
        const LinearForm f = edge_form(poly[e], poly[(e + 1) % n]);
        for (const Point& p : poly) {
            if (f.at(p) < -slack) return false;
        }
    }
    // Every vertex on the inner side of every edge still admits a boundary that winds around
    // twice (a pentagram's edges do not pass this, but a square traversed twice does): the
    // turning angles of a simple convex polygon add up to 2 pi, of a k-fold one to 2 k pi.
    double turning = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const Point& a = poly[k];
        const Point& b = poly[(k + 1) % n];
        const Point& c = poly[(k + 2) % n];
        const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - b.x, vy = c.y - b.y;
        turning += std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
    }
    return turning < 3.0 * std::numbers::pi;
}

}  // namespace aabench
