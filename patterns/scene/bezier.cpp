// Bezier segments and their flattening (bezier.h).
#include "patterns/scene/bezier.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace aabench {

Segment line_segment(Point a, Point b) {
    Segment s;
    s.p[0] = a;
    s.p[1] = b;
    return s;
}

Segment quad_segment(Point a, Point c, Point b) {
    Segment s;
    s.degree = 2;
    s.p = {a, c, b, Point{}};
    return s;
}

Segment cubic_segment(Point a, Point c1, Point c2, Point b) {
    Segment s;
    s.degree = 3;
    s.p = {a, c1, c2, b};
    return s;
}

Point bezier_at(const Segment& s, double t) {
    if (t <= 0.0) return s.p[0];
    if (t >= 1.0) return s.end();
    const double u = 1.0 - t;
    const auto& p = s.p;
    switch (s.degree) {
        case 1:
            return {u * p[0].x + t * p[1].x, u * p[0].y + t * p[1].y};
        case 2: {
            const double a = u * u, b = 2.0 * u * t, c = t * t;
            return {a * p[0].x + b * p[1].x + c * p[2].x, a * p[0].y + b * p[1].y + c * p[2].y};
        }
        default: {
            const double a = u * u * u, b = 3.0 * u * u * t, c = 3.0 * u * t * t, d = t * t * t;
            return {a * p[0].x + b * p[1].x + c * p[2].x + d * p[3].x,
                    a * p[0].y + b * p[1].y + c * p[2].y + d * p[3].y};
        }
    }
}

Point bezier_derivative(const Segment& s, double t) {
    const double u = 1.0 - t;
    const auto& p = s.p;
    switch (s.degree) {
        case 1:
            return {p[1].x - p[0].x, p[1].y - p[0].y};
        case 2:
            return {2.0 * (u * (p[1].x - p[0].x) + t * (p[2].x - p[1].x)),
                    2.0 * (u * (p[1].y - p[0].y) + t * (p[2].y - p[1].y))};
        default:
            return {3.0 * (u * u * (p[1].x - p[0].x) + 2.0 * u * t * (p[2].x - p[1].x) +
                           t * t * (p[3].x - p[2].x)),
                    3.0 * (u * u * (p[1].y - p[0].y) + 2.0 * u * t * (p[2].y - p[1].y) +
                           t * t * (p[3].y - p[2].y))};
    }
}

double bezier_second_derivative_bound(const Segment& s) {
    const auto& p = s.p;
    if (s.degree == 1) return 0.0;
    if (s.degree == 2) {
        return 2.0 * std::hypot(p[0].x - 2.0 * p[1].x + p[2].x, p[0].y - 2.0 * p[1].y + p[2].y);
    }
    const double mx = std::max(std::abs(p[0].x - 2.0 * p[1].x + p[2].x),
                               std::abs(p[1].x - 2.0 * p[2].x + p[3].x));
    const double my = std::max(std::abs(p[0].y - 2.0 * p[1].y + p[2].y),
                               std::abs(p[1].y - 2.0 * p[2].y + p[3].y));
    return 6.0 * std::hypot(mx, my);
}

double flatten_deviation_bound(const Segment& s, long long pieces) {
    const double n = static_cast<double>(pieces);
    return bezier_second_derivative_bound(s) / (8.0 * n * n);
}

long long flatten_count(const Segment& s, double tolerance_px) {
    if (!(tolerance_px > 0.0)) throw std::invalid_argument("flatten_count: tolerance must be > 0");
    const double m = bezier_second_derivative_bound(s);
    if (m == 0.0) return 1;
    const double n = std::ceil(std::sqrt(m / (8.0 * tolerance_px)));
    if (!(n <= static_cast<double>(kMaxFlattenPieces))) {
        throw std::invalid_argument("flatten_count: more than 2^24 pieces for one segment");
    }
    auto count = std::max(1LL, static_cast<long long>(n));
    while (flatten_deviation_bound(s, count) > tolerance_px) ++count;  // sqrt's rounding
    return count;
}

Contour flatten(const SegmentContour& contour, double tolerance_px) {
    // At least 3 points, as every polygon contour has: a lone closed curve in 3 pieces or more,
    // each of two segments in 2 or more (a curve and a line: 2 + 1).
    const long long at_least = contour.size() == 1 ? 3 : contour.size() == 2 ? 2 : 1;
    Contour out;
    for (const Segment& s : contour) {
        const long long n = s.degree == 1 ? 1 : std::max(at_least, flatten_count(s, tolerance_px));
        out.push_back(s.p[0]);
        for (long long k = 1; k < n; ++k) {
            out.push_back(bezier_at(s, static_cast<double>(k) / static_cast<double>(n)));
        }
    }
    return out;
}

double twice_signed_area(const SegmentContour& contour) {
    // 2 A = integral of (x dy - y dx) over the boundary; along a segment the integrand
    // x y' - y x' is a polynomial of degree 2 degree - 1 <= 5, which 3-point Gauss-Legendre
    // integrates exactly. Relative to the first point, to keep the products small.
    static constexpr double kNodes[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
    static constexpr double kWeights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    if (contour.empty()) return 0.0;
    const Point o = contour.front().p[0];
    double sum = 0.0;
    for (const Segment& s : contour) {
        Segment r = s;
        for (int k = 0; k <= s.degree; ++k) r.p[k] = {s.p[k].x - o.x, s.p[k].y - o.y};
        for (int k = 0; k < 3; ++k) {
            const Point b = bezier_at(r, kNodes[k]), d = bezier_derivative(r, kNodes[k]);
            sum += kWeights[k] * (b.x * d.y - b.y * d.x);
        }
    }
    return sum;
}

namespace {

void check_closed(const std::vector<SegmentContour>& outline) {
    for (const SegmentContour& contour : outline) {
        if (contour.empty()) throw std::invalid_argument("bezier_shape: an empty contour");
        for (std::size_t k = 0; k < contour.size(); ++k) {
            const Segment& s = contour[k];
            if (s.degree < 1 || s.degree > 3) {
                throw std::invalid_argument("bezier_shape: a segment's degree is 1, 2 or 3");
            }
            if (!(contour[(k + 1) % contour.size()].p[0] == s.end())) {
                throw std::invalid_argument("bezier_shape: a contour is not closed");
            }
        }
    }
}

}  // namespace

void bezier_extrema(const Segment& s, int axis, std::vector<double>& out) {
    auto c = [&](int k) { return axis == 0 ? s.p[k].x : s.p[k].y; };
    auto keep = [&](double t) {
        if (t > 0.0 && t < 1.0) out.push_back(t);
    };
    if (s.degree == 2) {
        const double den = c(0) - 2.0 * c(1) + c(2);
        if (den != 0.0) keep((c(0) - c(1)) / den);
        return;
    }
    if (s.degree != 3) return;
    // d/dt / 3 = A t^2 + B t + C.
    const double a = c(3) - 3.0 * c(2) + 3.0 * c(1) - c(0);
    const double b = 2.0 * (c(2) - 2.0 * c(1) + c(0));
    const double cc = c(1) - c(0);
    const double scale = std::abs(a) + std::abs(b) + std::abs(cc);
    if (scale == 0.0) return;
    if (std::abs(a) <= 1e-15 * scale) {
        if (b != 0.0) keep(-cc / b);
        return;
    }
    const double disc = b * b - 4.0 * a * cc;
    if (disc < 0.0) return;
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    if (q != 0.0) {
        keep(q / a);
        keep(cc / q);
    } else {
        keep(0.0);  // b == 0 and disc == 0: a double root at 0, outside (0, 1)
    }
}

namespace {
double coordinate(const Point& p, int axis) { return axis == 0 ? p.x : p.y; }
}  // namespace

double solve_monotone(const Segment& s, int axis, double value, double lo, double hi) {
    double flo = coordinate(bezier_at(s, lo), axis) - value;
    double fhi = coordinate(bezier_at(s, hi), axis) - value;
    if (flo == 0.0) return lo;
    if (fhi == 0.0) return hi;
    if ((flo > 0.0) == (fhi > 0.0)) return std::abs(flo) <= std::abs(fhi) ? lo : hi;
    // Newton's method kept inside the bracket [lo, hi], which every step narrows: a step that
    // would leave it, or fail to halve it, is a bisection instead. Quadratic convergence from
    // the secant start (a handful of steps on a monotone piece), and safe on a piece whose
    // monotonicity rounding spoilt; it ends when the bracket is two doubles wide or f is 0.
    double t = lo + (hi - lo) * (flo / (flo - fhi));
    double width = hi - lo;
    for (int k = 0; k < 200; ++k) {
        if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
        if (!(t > lo && t < hi)) break;
        const double f = coordinate(bezier_at(s, t), axis) - value;
        if (f == 0.0) return t;
        if ((f > 0.0) == (flo > 0.0)) {
            lo = t;
            flo = f;
        } else {
            hi = t;
            fhi = f;
        }
        const double d = coordinate(bezier_derivative(s, t), axis);
        double next = d != 0.0 ? t - f / d : 0.5 * (lo + hi);
        // Halve the bracket at least every other step: Newton near a flat end can crawl.
        if (!(next > lo && next < hi) || hi - lo > 0.5 * width) next = 0.5 * (lo + hi);
        width = hi - lo;
        t = next;
    }
    return std::abs(flo) <= std::abs(fhi) ? lo : hi;
}

void polygon_on_lines(const SegmentContour& contour, std::span<const double> ys, Contour& out) {
    out.clear();
    // At most 4 parameters a segment (its ends and a cubic's two extrema); kept per thread so
    // that a warm render, which calls this for every curved contour, allocates nothing.
    thread_local std::vector<double> ts;
    for (const Segment& s : contour) {
        out.push_back(s.p[0]);
        if (s.degree == 1) continue;
        ts.assign({0.0, 1.0});
        bezier_extrema(s, 1, ts);
        std::sort(ts.begin(), ts.end());
        Point a = s.p[0];
        for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
            const double t0 = ts[k], t1 = ts[k + 1];
            const Point b = bezier_at(s, t1);
            if (t1 > t0 && a.y != b.y) {
                // The lines strictly between a.y and b.y, in the order the piece meets them.
                const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
                const auto first = std::upper_bound(ys.begin(), ys.end(), lo);
                const auto last = std::lower_bound(first, ys.end(), hi);
                auto add = [&](double y) {
                    out.push_back({bezier_at(s, solve_monotone(s, 1, y, t0, t1)).x, y});
                };
                if (b.y > a.y) {
                    for (auto it = first; it != last; ++it) add(*it);
                } else {
                    for (auto it = last; it != first;) add(*--it);
                }
            }
            if (k + 2 < ts.size()) out.push_back(b);  // the extremum (the end is the next start)
            a = b;
        }
    }
}

bool has_curve_segment(const std::vector<SegmentContour>& contours) {
    for (const SegmentContour& c : contours) {
        for (const Segment& s : c) {
            if (s.degree > 1) return true;
        }
    }
    return false;
}

Shape bezier_shape(std::vector<SegmentContour> outline, double value) {
    check_closed(outline);
    Shape shape;
    shape.value = value;
    if (!has_curve_segment(outline)) {
        for (const SegmentContour& c : outline) {
            Contour& contour = shape.contours.emplace_back();
            for (const Segment& s : c) contour.push_back(s.p[0]);
        }
        return shape;
    }
    shape.outline = std::move(outline);
    shape.contours.reserve(shape.outline.size());
    for (const SegmentContour& c : shape.outline) {
        shape.contours.push_back(flatten(c, kBezierViewFlatnessPx));
    }
    return shape;
}

Shape flattened_shape(const Shape& shape, double tolerance_px) {
    Shape out = shape;
    if (shape.outline.empty()) return out;
    out.contours.clear();
    for (const SegmentContour& c : shape.outline) out.contours.push_back(flatten(c, tolerance_px));
    out.outline.clear();
    return out;
}

Scene flattened_scene(const Scene& scene, double tolerance_px) {
    Scene out = scene;
    for (Shape& shape : out.shapes) {
        if (has_bezier(shape)) shape = flattened_shape(shape, tolerance_px);
    }
    for (ThinObject& object : out.thin_objects) {
        if (has_bezier(object.shape)) object.shape = flattened_shape(object.shape, tolerance_px);
    }
    return out;
}

bool has_bezier(const Shape& shape) { return !shape.outline.empty(); }

bool has_bezier(const Scene& scene) {
    return std::any_of(scene.shapes.begin(), scene.shapes.end(),
                       [](const Shape& s) { return has_bezier(s); });
}

}  // namespace aabench
