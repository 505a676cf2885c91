// Seeded random ScreenScenes for the visibility and affine box reference tests, and the bridge
// to the independent oracle (tests/visibility_oracle.h). Nothing here uses the code under
// test: hulls, containment and areas are written out again.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "patterns/scene/scene.h"
#include "visibility_oracle.h"

namespace aabench::testing {

inline double cross(const Point& o, const Point& a, const Point& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain: the convex hull, counter-clockwise in the y-up drawing (positive
// twice_signed_area), collinear points left out.
inline Contour convex_hull(std::vector<Point> pts) {
    std::sort(pts.begin(), pts.end(), [](const Point& a, const Point& b) {
        return a.x < b.x || (a.x == b.x && a.y < b.y);
    });
    if (pts.size() < 3) return pts;
    Contour hull(2 * pts.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
        hull[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i - 1]) <= 0) --k;
        hull[k++] = pts[i - 1];
    }
    hull.resize(k - 1);
    return hull;
}

// The hull of 3..8 random points in a disc; reversed half of the time (either orientation).
// `grid` > 0: the points snapped to multiples of it first (shared coordinates, collinear
// vertices of different shapes, edges through other shapes' vertices).
inline Contour random_convex(std::mt19937_64& rng, double cx, double cy, double radius,
                             double grid = 0.0) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Contour hull;
    while (hull.size() < 3) {
        std::vector<Point> pts;
        const int n = 3 + static_cast<int>(rng() % 6);
        for (int k = 0; k < n; ++k) {
            const double r = radius * std::sqrt(unit(rng)), a = 2.0 * std::numbers::pi * unit(rng);
            Point p{cx + r * std::cos(a), cy + r * std::sin(a)};
            if (grid > 0.0) p = {grid * std::round(p.x / grid), grid * std::round(p.y / grid)};
            pts.push_back(p);
        }
        hull = convex_hull(pts);
    }
    if (rng() % 2) std::reverse(hull.begin(), hull.end());
    return hull;
}

// Three bars, each over the next where they cross and under the previous one: no painter's
// order exists. The bars run along the sides of a triangle around (cx, cy), rotated by
// `angle`; each bar's depth plane rises from 0 at one end to 1 at the other, so at every
// corner one bar is near 1 and the other near 0 (a decided, cyclic order).
inline std::vector<Shape> cyclic_bars(double cx, double cy, double radius, double angle,
                                      double half_width, int first_face) {
    std::vector<Point> corner;
    for (int k = 0; k < 3; ++k) {
        const double a = angle + 2.0 * std::numbers::pi * k / 3.0;
        corner.push_back({cx + radius * std::cos(a), cy + radius * std::sin(a)});
    }
    std::vector<Shape> bars;
    for (int k = 0; k < 3; ++k) {
        // Bar k from corner k (low: this bar is under the previous bar there) to corner k+1.
        const Point a = corner[k], b = corner[(k + 1) % 3];
        const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
        const double ux = dx / len, uy = dy / len, nx = -uy * half_width, ny = ux * half_width;
        // Extend past the corners so that neighbouring bars overlap in a full parallelogram.
        const double ext = 3.0 * half_width;
        const Point s{a.x - ux * ext, a.y - uy * ext}, e{b.x + ux * ext, b.y + uy * ext};
        Shape bar;
        bar.contours = {{{s.x + nx, s.y + ny},
                         {e.x + nx, e.y + ny},
                         {e.x - nx, e.y - ny},
                         {s.x - nx, s.y - ny}}};
        // w = (t - t_a) / len with t the position along the bar: 0 at corner k, 1 at k+1.
        const double gx = ux / len, gy = uy / len;
        bar.inv_depth = AffinePlane{1.0 - gx * a.x - gy * a.y, gx, gy};
        bar.face = first_face + k;
        bars.push_back(bar);
    }
    return bars;
}

// 3..12 random convex shapes (each a face of its own) with depth planes in [1, 2] at their
// centres and slopes up to 0.15 per px, so that across an overlap several pixels wide the
// depth difference changes by about as much as it is: the line of equal depth often crosses
// the overlap (interpenetration); every fourth scene adds a cyclic triple of bars. Values are
// random constants; `affine` adds a random value plane to every shape. `snapped`: vertices
// on the 1/4-pixel grid and depth planes from a few exact values (multiples of 1/32), so
// that vertices lie on other shapes' edges, lines of equal depth run through vertices, and
// some planes are exactly equal (ties, decided by order).
inline Scene random_depth_scene(std::uint64_t seed, int size, bool affine, bool snapped = false) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
    Scene scene;
    scene.width = scene.height = size;
    scene.background = uniform(0.0, 0.3);
    const int n = 3 + static_cast<int>(rng() % 10);
    for (int k = 0; k < n; ++k) {
        Shape shape;
        auto snap = [snapped](double v, double grid) {
            return snapped ? grid * std::round(v / grid) : v;
        };
        const double cx = snap(uniform(-4.0, size + 4.0), 0.25);
        const double cy = snap(uniform(-4.0, size + 4.0), 0.25);
        shape.contours = {random_convex(rng, cx, cy, uniform(3.0, 0.6 * size), snapped ? 0.25 : 0)};
        shape.value = uniform(0.0, 1.0);
        // w = w0 + g . (p - centre): anchored at the shape, so that the line where two planes
        // meet falls near the shapes rather than near the origin.
        const double w0 = snap(uniform(1.0, 2.0), 0.25), gx = snap(uniform(-0.15, 0.15), 1.0 / 32);
        const double gy = snap(uniform(-0.15, 0.15), 1.0 / 32);
        shape.inv_depth = AffinePlane{w0 - gx * cx - gy * cy, gx, gy};
        if (snapped && k > 0 && rng() % 4 == 0) {  // coplanar with an earlier shape: a tie
            shape.inv_depth = scene.shapes[rng() % k].inv_depth;
        }
        shape.face = k;
        scene.shapes.push_back(shape);
    }
    if (seed % 4 == 0) {
        for (Shape& bar :
             cyclic_bars(uniform(0.3, 0.7) * size, uniform(0.3, 0.7) * size,
                         uniform(0.25, 0.4) * size, uniform(0.0, 6.3), uniform(0.8, 2.5), n)) {
            bar.value = uniform(0.0, 1.0);
            scene.shapes.push_back(bar);
        }
    }
    if (affine) {
        for (Shape& shape : scene.shapes) {
            shape.value_plane =
                AffinePlane{uniform(0.0, 1.0), uniform(-0.05, 0.05), uniform(-0.05, 0.05)};
        }
    }
    return scene;
}

// The oracle's input: every shape with its depth plane (2-D scenes: w = shape index, so the
// later shape is nearer, as the oracle breaks exact ties toward the later polygon anyway)
// and its constant value.
inline std::vector<oracle::OraclePolygon> oracle_polygons(const Scene& scene) {
    std::vector<oracle::OraclePolygon> polys;
    for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
        const Shape& s = scene.shapes[k];
        oracle::OraclePolygon p;
        for (const Point& v : s.contours.at(0)) p.vertices.push_back({v.x, v.y});
        if (s.inv_depth) {
            p.w0 = s.inv_depth->c;
            p.wx = s.inv_depth->gx;
            p.wy = s.inv_depth->gy;
        } else {
            p.w0 = static_cast<double>(k);
        }
        p.value = s.value;
        polys.push_back(p);
    }
    return polys;
}

// Strictly inside a convex polygon (either orientation) by more than `margin` px.
inline bool inside_by(const Contour& poly, const Point& p, double margin) {
    double area2 = 0.0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        area2 += cross(poly[0], poly[k], poly[(k + 1) % poly.size()]);
    }
    const double orient = area2 > 0.0 ? 1.0 : -1.0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const Point& a = poly[k];
        const Point& b = poly[(k + 1) % poly.size()];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        if (len == 0.0) continue;
        if (!(orient * cross(a, b, p) / len > margin)) return false;
    }
    return true;
}

// Within `margin` of the polygon's boundary (inside or out).
inline bool near_boundary(const Contour& poly, const Point& p, double margin) {
    for (std::size_t k = 0; k < poly.size(); ++k) {
        const Point& a = poly[k];
        const Point& b = poly[(k + 1) % poly.size()];
        const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
        double t = len2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
        t = std::clamp(t, 0.0, 1.0);
        if (std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy)) <= margin) return true;
    }
    return false;
}

inline double polygon_area(const Contour& poly) {
    double area2 = 0.0;
    for (std::size_t k = 0; k < poly.size(); ++k) {
        area2 += cross(poly[0], poly[k], poly[(k + 1) % poly.size()]);
    }
    return 0.5 * std::abs(area2);
}

}  // namespace aabench::testing
