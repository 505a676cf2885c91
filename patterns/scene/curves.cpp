// Curve shapes and their polygonisation (curves.h).
#include "patterns/scene/curves.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace aabench {

double polygon_sagitta(double radius_px, int segments) {
    const double h = std::sin(std::numbers::pi / (2.0 * segments));
    return 2.0 * radius_px * h * h;
}

int curve_segment_count(double radius_px, double sagitta_px) {
    if (!(radius_px > 0.0) || !(sagitta_px > 0.0)) {
        throw std::invalid_argument("curve_segment_count: radius and sagitta must be > 0");
    }
    if (sagitta_px >= radius_px) return kMinCurveSegments;
    // s = 2 r sin^2(pi / 2n)  <=>  n = pi / (2 asin(sqrt(s / 2r))); rounded up, then checked
    // (the rounding of asin may leave n one short).
    double n = std::ceil(std::numbers::pi / (2.0 * std::asin(std::sqrt(sagitta_px / (2.0 * radius_px)))));
    n = std::max<double>(n, kMinCurveSegments);
    if (n > 1e8) throw std::invalid_argument("curve_segment_count: more than 1e8 segments");
    int count = static_cast<int>(n);
    while (polygon_sagitta(radius_px, count) > sagitta_px) ++count;
    return count;
}

Contour circle_polygon(Point center, double radius_px, bool clockwise) {
    const int n = curve_segment_count(radius_px);
    Contour contour(static_cast<std::size_t>(n));
    const double step = 2.0 * std::numbers::pi / n;
    for (int k = 0; k < n; ++k) {
        // Increasing angle is clockwise on screen (y grows down).
        const double a = (clockwise ? k : -k) * step;
        contour[k] = {center.x + radius_px * std::cos(a), center.y + radius_px * std::sin(a)};
    }
    return contour;
}

Shape disc_shape(Point center, double radius_px, double value) {
    if (!(radius_px > 0.0) || !std::isfinite(radius_px)) {
        throw std::invalid_argument("disc_shape: radius must be finite and > 0");
    }
    Shape shape;
    shape.value = value;
    shape.circle = Circle{center, 0.0, radius_px};
    shape.contours.push_back(circle_polygon(center, radius_px, true));
    return shape;
}

Shape ring_shape(Point center, double inner_px, double outer_px, double value) {
    if (!(inner_px > 0.0 && inner_px < outer_px) || !std::isfinite(outer_px)) {
        throw std::invalid_argument("ring_shape: radii must satisfy 0 < inner < outer < inf");
    }
    Shape shape;
    shape.value = value;
    shape.circle = Circle{center, inner_px, outer_px};
    shape.contours.push_back(circle_polygon(center, outer_px, true));
    shape.contours.push_back(circle_polygon(center, inner_px, false));
    return shape;
}

bool has_curves(const Scene& scene) {
    return std::any_of(scene.shapes.begin(), scene.shapes.end(),
                       [](const Shape& s) { return s.circle.has_value(); });
}

bool circles_disjoint(const Circle& a, const Circle& b) {
    const double d = std::hypot(a.center.x - b.center.x, a.center.y - b.center.y);
    if (d >= a.outer + b.outer) return true;
    return d + b.outer <= a.inner || d + a.outer <= b.inner;
}

void translate_shape(Shape& shape, double dx, double dy) {
    for (Contour& contour : shape.contours) {
        for (Point& p : contour) p = {p.x + dx, p.y + dy};
    }
    if (shape.circle) shape.circle->center = {shape.circle->center.x + dx, shape.circle->center.y + dy};
    for (SegmentContour& contour : shape.outline) {
        for (Segment& s : contour) {
            for (int k = 0; k <= s.degree; ++k) s.p[k] = {s.p[k].x + dx, s.p[k].y + dy};
        }
    }
}

}  // namespace aabench
