// Slow, obviously-correct references for the tests. Independent of methods/edge_table and of
// harness/box_reference: nothing here accumulates, buckets or sorts edges globally.
//
// slow_box_pixel: the exact area-weighted value of a scene over one pixel, by
//   1. clipping every contour to the pixel square (Sutherland–Hodgman against a convex
//      window keeps the winding number of every point inside the window), then
//   2. cutting the pixel into horizontal slabs at every vertex and every pairwise edge
//      intersection of the clipped contours, so that inside a slab the visible value's
//      boundaries are straight and never cross; the covered length on a horizontal line is
//      then linear in y and the midpoint rule integrates it exactly: area = height x length
//      at mid-height.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench::testing {

inline std::vector<Point> clip_polygon(const std::vector<Point>& poly, double x0, double y0,
                                       double x1, double y1) {
    auto clip_edge = [](const std::vector<Point>& in, auto inside, auto intersect) {
        std::vector<Point> out;
        if (in.empty()) return out;
        Point prev = in.back();
        for (const Point& cur : in) {
            const bool cin = inside(cur), pin = inside(prev);
            if (cin) {
                if (!pin) out.push_back(intersect(prev, cur));
                out.push_back(cur);
            } else if (pin) {
                out.push_back(intersect(prev, cur));
            }
            prev = cur;
        }
        return out;
    };
    auto at_x = [](Point a, Point b, double x) {
        const double t = (x - a.x) / (b.x - a.x);
        return Point{x, a.y + t * (b.y - a.y)};
    };
    auto at_y = [](Point a, Point b, double y) {
        const double t = (y - a.y) / (b.y - a.y);
        return Point{a.x + t * (b.x - a.x), y};
    };
    std::vector<Point> p = poly;
    p = clip_edge(p, [&](Point q) { return q.x >= x0; }, [&](Point a, Point b) { return at_x(a, b, x0); });
    p = clip_edge(p, [&](Point q) { return q.x <= x1; }, [&](Point a, Point b) { return at_x(a, b, x1); });
    p = clip_edge(p, [&](Point q) { return q.y >= y0; }, [&](Point a, Point b) { return at_y(a, b, y0); });
    p = clip_edge(p, [&](Point q) { return q.y <= y1; }, [&](Point a, Point b) { return at_y(a, b, y1); });
    return p;
}

inline double slow_box_pixel(const Scene& scene, int i, int j) {
    struct Seg {
        Point a, b;
        int shape;
    };
    std::vector<Seg> segs;
    std::vector<double> ys = {double(j), j + 1.0};
    for (int s = 0; s < static_cast<int>(scene.shapes.size()); ++s) {
        for (const Contour& c : scene.shapes[s].contours) {
            const std::vector<Point> clipped = clip_polygon(c, i, j, i + 1.0, j + 1.0);
            for (std::size_t k = 0; k < clipped.size(); ++k) {
                const Point a = clipped[k], b = clipped[(k + 1) % clipped.size()];
                ys.push_back(a.y);
                if (a.y != b.y) segs.push_back({a, b, s});
            }
        }
    }
    // Pairwise intersections.
    for (std::size_t p = 0; p < segs.size(); ++p) {
        for (std::size_t q = p + 1; q < segs.size(); ++q) {
            const Point a = segs[p].a, b = segs[p].b, c = segs[q].a, d = segs[q].b;
            const double den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
            if (den == 0.0) continue;
            const double t = ((c.x - a.x) * (d.y - c.y) - (c.y - a.y) * (d.x - c.x)) / den;
            const double u = ((c.x - a.x) * (b.y - a.y) - (c.y - a.y) * (b.x - a.x)) / den;
            if (t > 0.0 && t < 1.0 && u > 0.0 && u < 1.0) ys.push_back(a.y + t * (b.y - a.y));
        }
    }
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    const int shape_count = static_cast<int>(scene.shapes.size());
    double total = 0.0;
    for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
        const double ya = std::max<double>(ys[k], j), yb = std::min(ys[k + 1], j + 1.0);
        if (!(yb > ya)) continue;
        const double ym = 0.5 * (ya + yb);
        struct Hit {
            double x;
            int shape, winding;
        };
        std::vector<Hit> hits;
        for (const Seg& sg : segs) {
            const double lo = std::min(sg.a.y, sg.b.y), hi = std::max(sg.a.y, sg.b.y);
            if (!(ym > lo && ym < hi)) continue;
            const double x = sg.a.x + (ym - sg.a.y) / (sg.b.y - sg.a.y) * (sg.b.x - sg.a.x);
            hits.push_back({x, sg.shape, sg.a.y < sg.b.y ? 1 : -1});
        }
        std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.x < b.x; });
        std::vector<int> winding(shape_count, 0);
        auto visible = [&] {
            for (int s = shape_count - 1; s >= 0; --s) {
                if (winding[s] != 0) return scene.shapes[s].value;
            }
            return scene.background;
        };
        double x = i, line = 0.0;
        for (const Hit& h : hits) {
            line += visible() * (h.x - x);
            winding[h.shape] += h.winding;
            x = h.x;
        }
        line += visible() * (i + 1.0 - x);
        total += line * (yb - ya);
    }
    return total;
}

// Shoelace area of a closed polygon (positive for clockwise in the y-down frame).
inline double signed_area(const Contour& c) {
    double a = 0.0;
    for (std::size_t k = 0; k < c.size(); ++k) {
        const Point p = c[k], q = c[(k + 1) % c.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return 0.5 * a;
}

}  // namespace aabench::testing
