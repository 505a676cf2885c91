#include "methods/scan/peer_coverage.h"

#include <algorithm>
#include <cmath>

namespace aabench {

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

bool needs_clipping(const Contour& contour) {
    for (const Point& p : contour) {
        if (!(std::abs(p.x) <= kPeerSafeCoordinate && std::abs(p.y) <= kPeerSafeCoordinate)) {
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

void composite_coverage_row(const std::uint8_t* coverage, float* out, int count, double value) {
    const float value_f = static_cast<float>(value);
    for (int i = 0; i < count; ++i) {
        const unsigned a = coverage[i];
        if (a == 0) continue;
        if (a == 255) {
            out[i] = value_f;
        } else {
            const double o = out[i];
            out[i] = static_cast<float>(o + (a / 255.0) * (value - o));
        }
    }
}

}  // namespace aabench
