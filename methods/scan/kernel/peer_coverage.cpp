#include "methods/scan/kernel/peer_coverage.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "patterns/scene/bezier.h"

namespace aabench {

PeerPaths peer_paths_from_name(const std::string& name) {
    if (name == "merged") return PeerPaths::kMerged;
    if (name == "per-shape") return PeerPaths::kPerShape;
    throw std::logic_error("peer paths: unknown choice '" + name + "'");  // the table admits none
}

ShapeRun next_shape_run(const std::vector<Shape>& shapes, std::size_t first, PeerPaths paths) {
    std::size_t last = first + 1;
    if (paths == PeerPaths::kMerged && !shapes[first].value_plane) {
        while (last < shapes.size() && !shapes[last].value_plane &&
               shapes[last].value == shapes[first].value) {
            ++last;
        }
    }
    return {first, last};
}

bool reverse_for_run(const Shape& shape, PeerPaths paths) {
    if (paths != PeerPaths::kMerged) return false;
    double twice_area = 0.0;
    for (const Contour& c : shape.contours) twice_area += twice_signed_area(c);
    return twice_area < 0.0;
}

PixelBox run_pixel_box(const std::vector<Shape>& shapes, ShapeRun run, int width, int height) {
    PixelBox out;
    for (std::size_t k = run.first; k < run.last; ++k) {
        const PixelBox box = shape_pixel_box(shapes[k], width, height);
        if (box.empty()) continue;
        if (out.empty()) {
            out = box;
            continue;
        }
        out = {std::min(out.x0, box.x0), std::min(out.y0, box.y0), std::max(out.x1, box.x1),
               std::max(out.y1, box.y1)};
    }
    return out;
}

PixelBox shape_pixel_box(const Shape& shape, int width, int height) {
    double min_x = HUGE_VAL, min_y = HUGE_VAL, max_x = -HUGE_VAL, max_y = -HUGE_VAL;
    for (const Contour& c : shape.contours) {
        for (const Point& p : c) {
            min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x);
            min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
        }
    }
    if (!(min_x <= max_x)) return {};
    auto clamp_floor = [](double v, int hi) {
        return static_cast<int>(std::clamp(std::floor(v) - 1.0, 0.0, double(hi)));
    };
    auto clamp_ceil = [](double v, int hi) {
        return static_cast<int>(std::clamp(std::ceil(v) + 1.0, 0.0, double(hi)));
    };
    return {clamp_floor(min_x, width), clamp_floor(min_y, height), clamp_ceil(max_x, width),
            clamp_ceil(max_y, height)};
}

bool draws_outline(const Shape& shape, double limit) {
    if (shape.outline.empty()) return false;
    for (const SegmentContour& c : shape.outline) {
        for (const Segment& s : c) {
            for (int k = 0; k <= s.degree; ++k) {
                if (!(std::abs(s.p[k].x) <= limit && std::abs(s.p[k].y) <= limit)) {
                    return false;
                }
            }
        }
    }
    return true;
}

bool needs_clipping(const Contour& contour, double limit) {
    for (const Point& p : contour) {
        if (!(std::abs(p.x) <= limit && std::abs(p.y) <= limit)) {
            return true;
        }
    }
    return false;
}

Contour clip_contour(const Contour& contour, double x0, double y0, double x1, double y1) {
    Contour poly = contour;
    auto clip_side = [&poly](auto inside, auto intersect) {
        Contour out;
        if (poly.empty()) return;
        Point prev = poly.back();
        for (const Point& cur : poly) {
            const bool cur_in = inside(cur), prev_in = inside(prev);
            if (cur_in != prev_in) out.push_back(intersect(prev, cur));
            if (cur_in) out.push_back(cur);
            prev = cur;
        }
        poly = std::move(out);
    };
    // The fraction first: (b.y - a.y) (x - a.x) overflows for coordinates near 1e300.
    auto at_x = [](double x) {
        return [x](Point a, Point b) {
            return Point{x, a.y + (b.y - a.y) * ((x - a.x) / (b.x - a.x))};
        };
    };
    auto at_y = [](double y) {
        return [y](Point a, Point b) {
            return Point{a.x + (b.x - a.x) * ((y - a.y) / (b.y - a.y)), y};
        };
    };
    clip_side([=](Point p) { return p.x >= x0; }, at_x(x0));
    clip_side([=](Point p) { return p.x <= x1; }, at_x(x1));
    clip_side([=](Point p) { return p.y >= y0; }, at_y(y0));
    clip_side([=](Point p) { return p.y <= y1; }, at_y(y1));
    return poly;
}

namespace {

// IEC 61966-2-1, clamped to [0, 1].
double srgb_encode_unit(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}
double srgb_decode_unit(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

PeerBlend peer_blend_from_name(const std::string& name) {
    if (name == "linear") return PeerBlend::kLinear;
    if (name == "srgb") return PeerBlend::kSrgbCodes;
    throw std::invalid_argument("peer_blend_from_name: " + name);
}

void composite_coverage_row(const std::uint8_t* coverage, float* out, int count, double value,
                            PeerBlend blend) {
    const float value_f = static_cast<float>(value);
    const double value_code = srgb_encode_unit(value);
    for (int i = 0; i < count; ++i) {
        const unsigned a = coverage[i];
        if (a == 0) continue;
        if (a == 255) {
            out[i] = value_f;
        } else if (blend == PeerBlend::kLinear) {
            const double o = out[i];
            out[i] = static_cast<float>(o + (a / 255.0) * (value - o));
        } else {
            const double o = srgb_encode_unit(out[i]);
            out[i] = static_cast<float>(srgb_decode_unit(o + (a / 255.0) * (value_code - o)));
        }
    }
}

bool draws_circle_as_arcs(const Circle& c, double limit) {
    return std::abs(c.center.x) + c.outer <= limit && std::abs(c.center.y) + c.outer <= limit;
}

std::vector<SegmentContour> circle_arc_contours(const Circle& circle) {
    std::vector<SegmentContour> out;
    const double k = 4.0 / 3.0 * std::tan(std::numbers::pi / (2.0 * kCircleArcs));
    for (const double r : {circle.outer, circle.inner}) {
        if (!(r > 0.0)) continue;
        const bool reverse = r == circle.inner;
        SegmentContour contour;
        auto at = [&](int i, double along) {
            const double a = 2.0 * std::numbers::pi * (i % kCircleArcs) / kCircleArcs;
            const double ca = std::cos(a), sa = std::sin(a);
            // The point at angle a, moved `along` x r along the tangent (counter-clockwise).
            return Point{circle.center.x + r * (ca - along * sa),
                         circle.center.y + r * (sa + along * ca)};
        };
        for (int i = 0; i < kCircleArcs; ++i) {
            const Point a = at(i, 0.0), b = at(i + 1, 0.0);
            const Point c1 = at(i, k), c2 = at(i + 1, -k);
            contour.push_back(reverse ? cubic_segment(b, c2, c1, a) : cubic_segment(a, c1, c2, b));
        }
        if (reverse) std::reverse(contour.begin(), contour.end());
        out.push_back(std::move(contour));
    }
    return out;
}

// True when an edge of `polygon` passes through the open rectangle (x0, x1) x (y0, y1)
// (Liang–Barsky on each edge, strict: an edge along its border, as a parent tile's clip leaves
// them, does not): otherwise its winding number is the same at every point inside.
bool crosses_rectangle(const Contour& polygon, double x0, double y0, double x1, double y1) {
    Point a = polygon.back();
    for (const Point& b : polygon) {
        double t0 = 0.0, t1 = 1.0;
        const double dx = b.x - a.x, dy = b.y - a.y;
        bool meets = true;
        const double p[4] = {-dx, dx, -dy, dy};
        const double q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
        for (int k = 0; k < 4 && meets; ++k) {
            if (p[k] == 0.0) {
                meets = q[k] > 0.0;
            } else {
                const double t = q[k] / p[k];
                if (p[k] < 0.0) {
                    t0 = std::max(t0, t);
                } else {
                    t1 = std::min(t1, t);
                }
                meets = t0 < t1;
            }
        }
        if (meets) return true;
        a = b;
    }
    return false;
}

// The winding number of `polygon` about (x, y) (a crossing count signed by direction).
int winding_number(const Contour& polygon, double x, double y) {
    int w = 0;
    Point a = polygon.back();
    for (const Point& b : polygon) {
        if ((a.y <= y) != (b.y <= y)) {
            const double cross = (b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y);
            if (b.y > a.y ? cross > 0.0 : cross < 0.0) w += b.y > a.y ? 1 : -1;
        }
        a = b;
    }
    return w;
}

}  // namespace aabench
