// Bezier segments and their flattening (bezier.h).
#include "patterns/scene/bezier.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
