// The hard-case suite (harness/measure/hardcases.h; cases, bounds and their derivations in
// docs/hardcases.md).
//
// Every case is a pure generator of a small scene with, where it is known in closed form, its
// exact mass: the integral over the image of (visible value - background). Masses come from
// shoelace sums on simple polygons (the self-intersecting pentagram is measured as the simple
// ten-pointed outline its nonzero fill is), never from a renderer, so the area check of the box
// reference is a real check.
//
// Per case, each method (and each reference) renders three scenes: the case itself, the case
// with every vertex moved by at most kContinuityMovePx (continuity), and the case with the
// scene and its window moved together by 2^20 px (translation). The figures:
//   finite       number of non-finite pixels (bound 0);
//   range        largest excursion beyond [min, max] of the background and the shape values;
//   area         |sum of (pixel - background) - exact mass|, for box-filter methods;
//   continuity,  largest per-pixel difference between the two images, with the fraction of
//   translation  pixels that differ by more than the tolerance.
// A nominal violation is a documented property only when hard_case_expected_failures() lists
// the method, invariant and case, and the entry's documented bound holds too; else it fails.
#include "harness/measure/hardcases.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <tuple>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "harness/reference/box_reference.h"
#include "harness/reference/filter_reference.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

constexpr int kCaseWidth = 32;  // not square, so that a swapped x and y shows
constexpr int kCaseHeight = 24;
// Coverage quantisation of the 8-bit peers, per edge pixel (docs/hardcases.md, "area"):
// agg's cover is floor or ceil of 256 c over 255 (within 2/255 of c); cairo's tor converter
// adds its 15 sub-rows in rows where edges start, end or cross (a point rule in y of step 1/15).
constexpr double kAggCoverageStep = 2.0 / 255.0;
constexpr double kCairoCoverageStep = 1.0 / 15.0 + 2.0 / 255.0;
// Both round vertices to 1/256 px: each edge moves by at most 2^-9 px in x and in y, which
// changes the area by at most (edge length) x 2^-9 x sqrt(2) < (edge length) x 2^-8.
constexpr double kPeerVertexShiftPx = 0x1p-8;

// ---- Geometry helpers ----

double polygon_area(const Contour& c) { return 0.5 * std::abs(twice_signed_area(c)); }

Shape polygon(Contour contour, double value) {
    Shape shape;
    shape.value = value;
    shape.contours.push_back(std::move(contour));
    return shape;
}

Contour rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Scene blank(int width, int height, double background, const std::string& name) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.background = background;
    scene.metadata = {{"hardcase", name}, {"size", fmt::format("{}x{}", width, height)}};
    return scene;
}

// Adds a shape whose contour is simple (or whose nonzero fill is the simple `outline`) and
// accumulates its mass; shapes added this way must not overlap one another.
struct MassBuilder {
    Scene scene;
    double mass = 0.0;
    void add(Contour contour, double value) { add_with_outline(contour, contour, value); }
    void add_with_outline(Contour contour, const Contour& outline, double value) {
        mass += (value - scene.background) * polygon_area(outline);
        scene.shapes.push_back(polygon(std::move(contour), value));
    }
    // A shape of no area: adds nothing to the mass whatever it looks like.
    void add_zero_area(std::vector<Contour> contours, double value) {
        Shape shape;
        shape.value = value;
        shape.contours = std::move(contours);
        scene.shapes.push_back(std::move(shape));
    }
    HardCaseScene done() { return {std::move(scene), mass}; }
};

// The triangle-and-rectangle scene several cases share, shifted by (dx, dy).
HardCaseScene corner_scene(const std::string& name, double dx, double dy) {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, name)};
    b.add({{2 + dx, 2 + dy}, {29 + dx, 6 + dy}, {11 + dx, 21 + dy}}, 1.0);
    b.add(rectangle(20 + dx, 14 + dy, 29 + dx, 22 + dy), 0.5);
    return b.done();
}

// Sub-scanline heights exactly as the methods compute them: box-multiscan's lines are
// j + double(l) / n, gauss-multiscan's (j + 0.5) + double(l) / n.
double box_line(int j, int l, int n) { return j + static_cast<double>(l) / n; }
double gauss_line(int j, int l, int n) { return (j + 0.5) + static_cast<double>(l) / n; }

HardCaseScene subscanline_scene(int n) {
    const std::string name = fmt::format("subscanline-n{}", n);
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, name)};
    // Horizontal edges on box lines, vertices on Gaussian lines; simple (left chain x <= 9,
    // right chain x >= 17).
    b.add({{3, box_line(2, 1, n)},
           {28, box_line(2, 1, n)},
           {28, gauss_line(9, 2 % n, n)},
           {17, gauss_line(12, 1 % n, n)},
           {26, box_line(20, n - 1, n)},
           {5, box_line(20, n - 1, n)},
           {9, gauss_line(11, n - 1, n)}},
          1.0);
    // A strip exactly one sub-scanline interval high, its horizontal edges on two lines.
    b.add(rectangle(4, box_line(22, 0, n), 27, box_line(22, 1, n)), 0.75);
    return b.done();
}

HardCaseScene axis_aligned_scene() {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.125, "axis-aligned")};
    b.add(rectangle(3.3, 2.25, 17.7, 11.6), 1.0);
    b.add({{19.1, 3.4}, {30.2, 3.4}, {30.2, 8.9}, {24.6, 8.9}, {24.6, 20.3}, {19.1, 20.3}}, 0.4);
    // A square on the integer grid, and one whose sides run through pixel centres.
    b.add(rectangle(2, 14, 8, 21), 0.9);
    b.add(rectangle(9.5, 13.5, 16.5, 22.5), 0.0);
    return b.done();
}

HardCaseScene slope_small_scene() {
    // Edges with dy/dx = 1e-12: almost horizontal, one starting exactly on a pixel border.
    constexpr double kSlope = 1e-12;
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, "slope-1e-12")};
    b.add({{2, 5.3}, {30, 5.3 + 28 * kSlope}, {30, 9.7}, {2, 9.7 - 28 * kSlope}}, 1.0);
    b.add({{2, 12}, {30, 12 + 28 * kSlope}, {16, 20.5}}, 1.0);
    return b.done();
}

HardCaseScene slope_large_scene() {
    // Edges with dy/dx = 1e12: almost vertical, one through a column of pixel centres.
    constexpr double kRun = 1e-12;  // dx per unit of dy
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, "slope-1e12")};
    b.add({{5, 2}, {5 + 20 * kRun, 22}, {2.2, 22}}, 1.0);
    b.add({{8.5, 2}, {8.5 + 20 * kRun, 22}, {20, 12}}, 1.0);
    b.add({{29.25, 1}, {29.25 - 22 * kRun, 23}, {23, 23}, {23, 1}}, 0.6);
    return b.done();
}

HardCaseScene zero_area_scene() {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.25, "zero-area")};
    b.add_zero_area({{{7, 7}, {7, 7}, {7, 7}}}, 1.0);                    // one point, thrice
    b.add_zero_area({{{3.5, 12.25}, {20.75, 15.5}, {3.5, 12.25}}}, 1.0);  // out and back
    b.add_zero_area({{{12, 3}, {28, 3}, {12, 3}, {28, 3}}}, 0.0);         // horizontal, twice
    b.add_zero_area({{{25.5, 5}, {25.5, 22}, {25.5, 9}}}, 1.0);           // vertical, on centres
    return b.done();
}

HardCaseScene collinear_scene() {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, "collinear")};
    // Exactly collinear in double (slope 2/3 through integers), in non-monotone order.
    b.add_zero_area({{{2, 3}, {20, 15}, {8, 7}, {14, 11}}}, 1.0);
    b.add_zero_area({{{4, 18}, {25, 18}, {10, 18}, {30, 18}}}, 1.0);
    b.add_zero_area({{{29.3, 2.1}, {29.3, 11.9}, {29.3, 6.6}}}, 0.5);
    // A genuine triangle beside them, so the image is not all background.
    b.add({{22, 4}, {27, 14}, {21, 12}}, 1.0);
    return b.done();
}

HardCaseScene repeated_vertices_scene() {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, "repeated-vertices")};
    const Point a{4.3, 3.7}, c{15.6, 3.7}, d{15.6, 13.2}, e{4.3, 13.2};
    // Every vertex repeated, the last equal to the first (the contour closes on itself).
    b.add_with_outline({a, a, c, c, c, d, e, e, a}, {a, c, d, e}, 1.0);
    const Point p{19.5, 5.5}, q{29.5, 9.5}, r{22.5, 20.5};
    b.add_with_outline({p, q, q, q, q, r, r, p, p}, {p, q, r}, 0.7);
    return b.done();
}

HardCaseScene doubling_back_scene() {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, "doubling-back")};
    // A square with an antenna: out to (29.5, 13.7) and back along the same segment.
    b.add_with_outline({{4, 4}, {20, 4}, {20, 10}, {29.5, 13.7}, {20, 10}, {20, 20}, {4, 20}},
                       {{4, 4}, {20, 4}, {20, 20}, {4, 20}}, 1.0);
    // A contour that runs round a square and back the same way: every edge twice, winding 0.
    b.add_zero_area({{{22, 15}, {29, 15}, {29, 22}, {22, 22}, {29, 22}, {29, 15}}}, 0.6);
    // Collinear out and back on a slant.
    b.add_zero_area({{{3, 21}, {28, 22.5}, {15.5, 21.75}}}, 1.0);
    return b.done();
}

HardCaseScene self_intersecting_scene() {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, "self-intersecting")};
    // Pentagram {5/2}: the nonzero rule fills the centre (winding 2) too, so its fill is the
    // ten-pointed outline with inner radius R cos(72 deg) / cos(36 deg).
    const double cx = 9.5, cy = 12.2, radius = 8.5;
    const double inner = radius * std::cos(0.4 * std::numbers::pi) / std::cos(0.2 * std::numbers::pi);
    Contour star, outline;
    for (int k = 0; k < 5; ++k) {
        const double a = -0.5 * std::numbers::pi + 2.0 * std::numbers::pi * (2 * k) / 5.0;
        star.push_back({cx + radius * std::cos(a), cy + radius * std::sin(a)});
    }
    for (int k = 0; k < 10; ++k) {
        const double a = -0.5 * std::numbers::pi + std::numbers::pi * k / 5.0;
        const double r = k % 2 == 0 ? radius : inner;
        outline.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    b.add_with_outline(star, outline, 1.0);
    // A bow tie: two lobes of opposite winding, both filled; each a triangle of area 54.
    const Contour bow = {{18.5, 3}, {30.5, 21}, {30.5, 3}, {18.5, 21}};
    b.scene.shapes.push_back(polygon(bow, 0.6));
    b.mass += 0.6 * polygon_area({{18.5, 3}, {18.5, 21}, {24.5, 12}}) +
              0.6 * polygon_area({{30.5, 3}, {30.5, 21}, {24.5, 12}});
    return b.done();
}

HardCaseScene sliver_scene() {
    constexpr double kWidthPx = 1e-9;
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, "sliver-1e-9")};
    b.add({{3, 4}, {27, 9}, {27, 9 + kWidthPx}, {3, 4 + kWidthPx}}, 1.0);  // slanted
    b.add(rectangle(2, 14.3, 30, 14.3 + kWidthPx), 1.0);                    // horizontal
    b.add(rectangle(16.7, 16, 16.7 + kWidthPx, 23), 1.0);                   // vertical
    b.add(rectangle(5.5, 17, 5.5 + kWidthPx, 22), 1.0);  // vertical, through pixel centres
    return b.done();
}

HardCaseScene star_scene() {
    // 1024 wedges meeting at one point: 2048 edges end inside the centre pixel.
    Scene scene = make_pattern("star:spokes=1024", 48, 48);
    scene.metadata.insert(scene.metadata.begin(), {"hardcase", "star-1024"});
    double mass = 0.0;
    for (const Shape& shape : scene.shapes) {
        for (const Contour& c : shape.contours) mass += (shape.value - scene.background) * polygon_area(c);
    }
    return {std::move(scene), mass};
}

HardCaseScene offset_scene(const std::string& name, double origin) {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, name)};
    // Coordinates with bits below the ulp at the origin: the window frame rounds them once.
    const Contour window_triangle = {{2.3, 3.1}, {29.7, 8.9}, {12.2, 21.6}};
    const Contour window_square = rectangle(20.15, 16.35, 29.85, 22.65);  // below the triangle
    b.scene.origin_x = origin;
    b.scene.origin_y = origin;
    for (const auto& [contour, value] :
         {std::pair{window_triangle, 1.0}, std::pair{window_square, 0.5}}) {
        Contour far;
        for (const Point& p : contour) far.push_back({p.x + origin, p.y + origin});
        // The mass of what is actually stored: the far coordinates, brought back exactly
        // (Sterbenz), measured by shoelace.
        Contour back;
        for (const Point& p : far) back.push_back({p.x - origin, p.y - origin});
        b.add_with_outline(far, back, value);
    }
    return b.done();
}

HardCaseScene outside_scene() {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, "outside")};
    b.add_zero_area({rectangle(-20, 3, -3, 12)}, 1.0);              // left
    b.add_zero_area({rectangle(33, -5, 50, 30)}, 1.0);              // right, taller
    b.add_zero_area({{{5, -9}, {25, -0.5}, {15, -30}}}, 1.0);       // above, touching nothing
    b.add_zero_area({rectangle(1, 24, 31, 24.000001)}, 1.0);        // below, on the border
    b.add_zero_area({{{1e15, 1e15}, {2e15, 1e15}, {1e15, 3e15}}}, 1.0);  // far away
    // A frame around the image: its bounding box holds the window, its fill does not.
    b.add_zero_area({rectangle(-10, -10, 42, 34), {{-1, -1}, {-1, 25}, {33, 25}, {33, -1}}}, 1.0);
    return b.done();
}

HardCaseScene covers_scene() {
    MassBuilder b{blank(kCaseWidth, kCaseHeight, 0.0, "covers-image")};
    b.scene.shapes.push_back(polygon(rectangle(-1e6, -1e6, 1e6, 1e6), 1.0));
    b.scene.shapes.push_back(polygon({{-1e15, -1e15}, {1e15, -1e15}, {0, 1e15}}, 0.5));
    b.mass = 0.5 * kCaseWidth * kCaseHeight;  // the later shape covers the whole image
    return b.done();
}

HardCaseScene one_pixel_scene() {
    MassBuilder b{blank(1, 1, 0.25, "image-1x1")};
    b.add({{0.2, 0.1}, {0.9, 0.4}, {0.3, 0.95}}, 1.0);
    return b.done();
}

HardCaseScene long_image_scene() {
    MassBuilder b{blank(16384, 16, 0.0, "image-16384x16")};
    b.add({{3, 2.5}, {16380.5, 13.2}, {16000, 15.1}, {10, 6.7}}, 1.0);
    return b.done();
}

// ---- Checks ----

Coverage to_coverage(const Image& image) {
    Coverage out(image.width, image.height);
    for (std::size_t k = 0; k < image.data.size(); ++k) out.data[k] = image.data[k];
    return out;
}

double mass_of(const Coverage& c, double background) {
    double sum = 0.0;
    for (double v : c.data) sum += v - background;
    return sum;
}

double abs_sum(const Coverage& c) {
    double sum = 0.0;
    for (double v : c.data) sum += std::abs(v);
    return sum;
}

// True when every pixel differing by more than `tolerance` is marked in `allowed`.
bool changes_within(const Coverage& a, const Coverage& b, double tolerance,
                    const Raster<std::uint8_t>& allowed) {
    for (std::size_t k = 0; k < a.data.size(); ++k) {
        if (!(std::abs(a.data[k] - b.data[k]) <= tolerance) && !allowed.data[k]) return false;
    }
    return true;
}

double marked_fraction(const Raster<std::uint8_t>& mask) {
    std::size_t count = 0;
    for (std::uint8_t m : mask.data) count += m != 0;
    return mask.data.empty() ? 0.0 : static_cast<double>(count) / mask.data.size();
}

// ---- Edge geometry of a window-frame scene (for the documented bounds) ----

template <class Fn>
void for_each_edge(const Scene& scene, Fn&& fn) {
    for (const Shape& shape : scene.shapes) {
        for (const Contour& c : shape.contours) {
            for (std::size_t k = 0; k < c.size(); ++k) fn(c[k], c[(k + 1) % c.size()]);
        }
    }
}

// Liang-Barsky: clips a-b to [x0, x1] x [y0, y1]; false when nothing is left.
bool clip_segment(Point& a, Point& b, double x0, double y0, double x1, double y1) {
    double t0 = 0.0, t1 = 1.0;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {a.x - x0, x1 - a.x, a.y - y0, y1 - a.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0.0) {
            t0 = std::max(t0, t);
        } else {
            t1 = std::min(t1, t);
        }
        if (t0 > t1) return false;
    }
    const Point a0 = a;
    a = {a0.x + t0 * dx, a0.y + t0 * dy};
    b = {a0.x + t1 * dx, a0.y + t1 * dy};
    return true;
}

// Per pixel, the number of edges whose closed segment meets the pixel's closed square (capped
// at 255), over the window grown by `margin` pixels on each side.
Raster<std::uint8_t> edge_counts(const Scene& scene, int margin) {
    const int w = scene.width + 2 * margin, h = scene.height + 2 * margin;
    Raster<std::uint8_t> count(w, h, 0);
    std::vector<int> seen(static_cast<std::size_t>(w) * h, -1);  // last edge that counted
    int edge_index = 0;
    for_each_edge(scene, [&](Point a, Point b) {
        const int id = edge_index++;
        // Clip a little beyond the grown window, so the pixels on its rim are complete.
        if (!clip_segment(a, b, -margin - 1.0, -margin - 1.0, scene.width + margin + 1.0,
                          scene.height + margin + 1.0)) {
            return;
        }
        auto mark = [&](int i, int j) {
            i += margin, j += margin;
            if (i < 0 || j < 0 || i >= w || j >= h) return;
            const std::size_t p = static_cast<std::size_t>(j) * w + i;
            if (seen[p] == id) return;
            seen[p] = id;
            if (count.data[p] < 255) ++count.data[p];
        };
        const double ylo = std::min(a.y, b.y), yhi = std::max(a.y, b.y);
        // Rows whose closed band [r, r+1] meets [ylo, yhi]: an endpoint on a row border
        // touches both rows.
        const int r0 = static_cast<int>(std::ceil(ylo)) - 1, r1 = static_cast<int>(std::floor(yhi));
        for (int r = r0; r <= r1; ++r) {
            const double ya = std::max<double>(ylo, r), yb = std::min<double>(yhi, r + 1.0);
            if (ya > yb) continue;
            double xa, xb;
            if (a.y == b.y) {
                xa = a.x, xb = b.x;
            } else {
                xa = a.x + (b.x - a.x) * ((ya - a.y) / (b.y - a.y));
                xb = a.x + (b.x - a.x) * ((yb - a.y) / (b.y - a.y));
            }
            const double xlo = std::min(xa, xb), xhi = std::max(xa, xb);
            // Columns whose closed band meets [xlo, xhi], with one column of slack for the
            // rounding of the interpolation.
            const int c0 = static_cast<int>(std::ceil(xlo)) - 2, c1 = static_cast<int>(std::floor(xhi)) + 1;
            for (int c = c0; c <= c1; ++c) mark(c, r);
        }
    });
    return count;
}

Raster<std::uint8_t> dilate_and_crop(const Raster<std::uint8_t>& grown, int margin, int reach,
                                     int width, int height) {
    Raster<std::uint8_t> across(grown.width, grown.height, 0);
    for (int j = 0; j < grown.height; ++j) {
        for (int i = 0; i < grown.width; ++i) {
            if (!grown.at(i, j)) continue;
            for (int d = std::max(0, i - reach); d <= std::min(grown.width - 1, i + reach); ++d) {
                across.at(d, j) = 1;
            }
        }
    }
    Raster<std::uint8_t> out(width, height, 0);
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i) {
            for (int d = -reach; d <= reach && !out.at(i, j); ++d) {
                const int gj = j + margin + d;
                if (gj >= 0 && gj < grown.height && across.at(i + margin, gj)) out.at(i, j) = 1;
            }
        }
    }
    return out;
}

double clipped_perimeter(const Scene& scene) {
    double length = 0.0;
    for_each_edge(scene, [&](Point a, Point b) {
        if (clip_segment(a, b, -1.0, -1.0, scene.width + 1.0, scene.height + 1.0)) {
            length += std::hypot(b.x - a.x, b.y - a.y);
        }
    });
    return length;
}

// The trapezoidal rule's error bound for box-multiscan with n sub-scanlines (docs/
// hardcases.md): L(y) = integral over [0, W] of (v - background) dx is linear in y between
// kinks (vertex heights, heights where two edges cross or an edge crosses x = 0 or x = W),
// and the rule is exact on every sub-band without one. On a sub-band with a kink both the
// integral and the rule's value lie in h [min L, max L], so the error there is at most
// h x osc(L), and osc(L) <= span x the x-extent (clipped to [0, W]) of the edges in the band.
double trapezoid_bound(const Scene& scene, int n, double span) {
    struct Seg {
        Point a, b;
    };
    std::vector<Seg> segs;
    std::vector<double> kinks;
    const double width = scene.width;
    for_each_edge(scene, [&](Point a, Point b) {
        if (!clip_segment(a, b, -1e300, -1.0, 1e300, scene.height + 1.0)) return;
        segs.push_back({a, b});
        kinks.push_back(a.y);
        kinks.push_back(b.y);
        for (const double side : {0.0, width}) {
            if ((a.x - side) * (b.x - side) < 0.0) {
                kinks.push_back(a.y + (b.y - a.y) * ((side - a.x) / (b.x - a.x)));
            }
        }
    });
    // Crossings of two edges (bounding boxes first: most pairs are far apart).
    for (std::size_t i = 0; i < segs.size(); ++i) {
        const Seg& s = segs[i];
        const double sx0 = std::min(s.a.x, s.b.x), sx1 = std::max(s.a.x, s.b.x);
        const double sy0 = std::min(s.a.y, s.b.y), sy1 = std::max(s.a.y, s.b.y);
        for (std::size_t k = i + 1; k < segs.size(); ++k) {
            const Seg& t = segs[k];
            if (std::max(t.a.x, t.b.x) < sx0 || std::min(t.a.x, t.b.x) > sx1 ||
                std::max(t.a.y, t.b.y) < sy0 || std::min(t.a.y, t.b.y) > sy1) {
                continue;
            }
            const double rx = s.b.x - s.a.x, ry = s.b.y - s.a.y;
            const double qx = t.b.x - t.a.x, qy = t.b.y - t.a.y;
            const double denom = rx * qy - ry * qx;
            if (denom == 0.0) continue;  // parallel: no kink between them
            const double u = ((t.a.x - s.a.x) * qy - (t.a.y - s.a.y) * qx) / denom;
            if (u >= 0.0 && u <= 1.0) kinks.push_back(s.a.y + u * ry);
        }
    }
    // Sub-bands g = j n + l ([j + l/n, j + (l+1)/n]) holding a kink, with a neighbour on each
    // side so that rounding of y n cannot miss the right one.
    const long long bands = static_cast<long long>(scene.height) * n;
    std::vector<long long> marked;
    for (const double y : kinks) {
        if (!(y >= -1.0 && y <= scene.height + 1.0)) continue;
        const long long g = static_cast<long long>(std::floor(y * n));
        for (long long d = g - 1; d <= g + 1; ++d) {
            if (d >= 0 && d < bands) marked.push_back(d);
        }
    }
    std::sort(marked.begin(), marked.end());
    marked.erase(std::unique(marked.begin(), marked.end()), marked.end());
    const double h = 1.0 / n;
    double bound = 0.0;
    for (const Seg& s : segs) {
        const double y0 = std::min(s.a.y, s.b.y), y1 = std::max(s.a.y, s.b.y);
        auto it = std::lower_bound(marked.begin(), marked.end(),
                                   static_cast<long long>(std::floor(y0 * n)) - 1);
        for (; it != marked.end() && static_cast<double>(*it) <= y1 * n + 1.0; ++it) {
            const double ya = std::max(y0, static_cast<double>(*it) * h);
            const double yb = std::min(y1, static_cast<double>(*it + 1) * h);
            if (ya > yb) continue;
            double xa, xb;
            if (s.a.y == s.b.y) {
                xa = s.a.x, xb = s.b.x;
            } else {
                xa = s.a.x + (s.b.x - s.a.x) * ((ya - s.a.y) / (s.b.y - s.a.y));
                xb = s.a.x + (s.b.x - s.a.x) * ((yb - s.a.y) / (s.b.y - s.a.y));
            }
            xa = std::clamp(xa, 0.0, width);
            xb = std::clamp(xb, 0.0, width);
            bound += h * span * std::abs(xb - xa);
        }
    }
    return bound;
}

// ---- Methods and references under test ----

struct Subject {
    std::string spec;  // row name
    std::string id;    // registry id, or "ref:box" / "ref:gaussian" / "ref:cone"
    bool reference = false;
    bool box = false;  // box filter: area applies
    bool heavy = false;
    int samples_per_side = 1;  // point samplers' k (none: 1)
    int sub_scanlines = 0;     // box-multiscan's n
    std::function<Coverage(const Scene&)> render;
};

std::vector<Subject> subjects_for(const std::vector<std::string>& specs) {
    std::vector<Subject> out;
    for (const std::string& spec : specs) {
        auto instance = std::make_shared<MethodInstance>(make_method(spec));
        Subject s;
        s.spec = instance->spec;
        s.id = instance->id;
        s.box = instance->method->reference_filter() == "box";
        if (s.id == "ssaa") s.samples_per_side = instance->params.get_int("k");
        if (s.id == "box-multiscan") s.sub_scanlines = instance->params.get_int("n");
        const bool multiscan = s.id == "box-multiscan" || s.id == "gauss-multiscan";
        s.heavy = (multiscan && instance->params.get_int("n") >= 128) ||
                  (s.id == "ssaa" && instance->params.get_int("k") >= 32);
        s.render = [instance](const Scene& scene) {
            Image out(scene.width, scene.height, std::numeric_limits<float>::quiet_NaN());
            instance->method->render(scene, out);
            return to_coverage(out);
        };
        out.push_back(std::move(s));
    }
    const RadialFilter gaussian = parse_radial_filter("gaussian");
    const RadialFilter cone = parse_radial_filter("cone");
    out.push_back({"ref:box", "ref:box", true, true, false, 1, 0,
                   [](const Scene& scene) { return box_reference(scene); }});
    out.push_back({"ref:" + gaussian.spec(), "ref:gaussian", true, false, false, 1, 0,
                   [gaussian](const Scene& scene) { return filtered_reference(scene, gaussian); }});
    out.push_back({"ref:" + cone.spec(), "ref:cone", true, false, false, 1, 0,
                   [cone](const Scene& scene) { return filtered_reference(scene, cone); }});
    return out;
}

const ExpectedFailure* find_expected(const std::string& id, Invariant invariant,
                                     const std::string& case_name) {
    for (const ExpectedFailure& e : hard_case_expected_failures()) {
        if (e.method_id != id || e.invariant != invariant) continue;
        if (e.cases.empty() ||
            std::find(e.cases.begin(), e.cases.end(), case_name) != e.cases.end()) {
            return &e;
        }
    }
    return nullptr;
}

// What a case needs once, whatever the method.
struct PreparedCase {
    const HardCase* info = nullptr;
    HardCaseScene base;
    Scene moved;    // continuity
    Scene shifted;  // translation
    Scene window;   // base.scene in window coordinates
    double lo = 0.0, hi = 0.0, span = 0.0;
    Raster<std::uint8_t> flip_zone;       // pixels within kFlipReachPx of an edge
    Raster<std::uint8_t> touched;         // pixels touched by an edge
    long long touched_pixels = 0;
    long long multi_edge_pixels = 0;      // touched by two or more edges
    long long zone_pixels = 0;
    double perimeter = 0.0;
};

PreparedCase prepare(const HardCase& hc) {
    PreparedCase p;
    p.info = &hc;
    p.base = hc.make();
    const Scene& scene = p.base.scene;
    p.moved = perturbed(scene, kContinuityMovePx);
    p.shifted = offset_with_window(scene, kTranslationOffsetPx);
    p.window = in_window_frame(scene);
    std::tie(p.lo, p.hi) = scene.value_range();
    p.span = p.hi - p.lo;
    p.flip_zone = edge_neighbourhood(scene, kFlipReachPx);
    constexpr int kMargin = 1;
    const Raster<std::uint8_t> counts = edge_counts(p.window, kMargin);
    p.touched = dilate_and_crop(counts, kMargin, 0, scene.width, scene.height);
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const std::uint8_t c = counts.at(i + kMargin, j + kMargin);
            p.touched_pixels += c >= 1;
            p.multi_edge_pixels += c >= 2;
        }
    }
    for (std::uint8_t m : p.flip_zone.data) p.zone_pixels += m != 0;
    p.perimeter = clipped_perimeter(p.window);
    return p;
}

// The documented bound of an entry, for this case and subject.
double documented_area_bound(DocumentedBound kind, const PreparedCase& c, const Subject& s) {
    const double rounding = kFloat32Rounding * (std::abs(c.base.exact_mass.value_or(0.0)) +
                                                c.window.width * c.window.height *
                                                    std::max(std::abs(c.lo), std::abs(c.hi)));
    switch (kind) {
        case DocumentedBound::kSamplingArea:
            // A pixel crossed by one straight edge errs by at most span / k; one holding a
            // vertex or several edges by at most span.
            return c.span * (static_cast<double>(c.touched_pixels - c.multi_edge_pixels) /
                                 s.samples_per_side +
                             static_cast<double>(c.multi_edge_pixels)) +
                   rounding;
        case DocumentedBound::kTrapezoidArea:
            return trapezoid_bound(c.window, s.sub_scanlines, c.span) + rounding;
        case DocumentedBound::kQuantisedArea: {
            const double step = s.id == "cairo" ? kCairoCoverageStep : kAggCoverageStep;
            return c.span * (c.zone_pixels * step + c.perimeter * kPeerVertexShiftPx) + rounding;
        }
        case DocumentedBound::kAnyArea:
            return c.span * static_cast<double>(c.zone_pixels) + rounding;
        case DocumentedBound::kRoundingStep:
            return c.span * 0.5 * kEightBitStep * c.window.width * c.window.height + rounding;
        case DocumentedBound::kLocalChanges:
            break;
    }
    return 0.0;
}

Outcome worst(Outcome a, Outcome b) { return static_cast<int>(a) >= static_cast<int>(b) ? a : b; }

void settle_same(InvariantResult& r, const Coverage& a, const Coverage& b, double tolerance,
                 const PreparedCase& c, const Subject& s, Invariant invariant) {
    r = check_same(a, b, tolerance);
    r.allowed_fraction = marked_fraction(c.flip_zone);
    if (r.outcome != Outcome::kFail) return;
    const ExpectedFailure* e = find_expected(s.id, invariant, c.info->name);
    if (e != nullptr && e->bound == DocumentedBound::kRoundingStep) {
        // One step, plus the float32 rounding of the two values compared.
        const double step = c.span * kEightBitStep * (1.0 + 1e-6) + tolerance;
        if (r.value <= step) {
            r.outcome = Outcome::kDocumented;
            r.documented_bound = step;
            r.note = e->reason;
        } else {
            r.note = "a change larger than one 8-bit step; " + e->reason;
        }
        return;
    }
    if (e == nullptr || e->bound != DocumentedBound::kLocalChanges) return;
    if (changes_within(a, b, tolerance, c.flip_zone)) {
        r.outcome = Outcome::kDocumented;
        r.documented_bound = r.allowed_fraction;
        r.note = e->reason;
    } else {
        r.note = "changes reach pixels farther than 2 px from every edge; " + e->reason;
    }
}

HardCaseRow run_one(const PreparedCase& c, const Subject& s) {
    HardCaseRow row;
    row.case_name = c.info->name;
    row.method = s.spec;
    row.reference = s.reference;
    row.width = c.base.scene.width;
    row.height = c.base.scene.height;
    const long long pixels = static_cast<long long>(row.width) * row.height;
    if (s.heavy && pixels > kHeavySpecMaxPixels) {
        for (InvariantResult& r : row.results) r.note = "not run: size cap of the heaviest specs";
        return row;
    }
    const Coverage image = s.render(c.base.scene);

    row.at(Invariant::kFinite) = check_finite(image);
    const double scale = std::max({1.0, std::abs(c.lo), std::abs(c.hi)});
    row.at(Invariant::kRange) =
        check_range(image, c.lo, c.hi, (s.reference ? kReferenceRangeSlack : kRangeSlack) * scale);

    if (s.box && c.base.exact_mass) {
        const double exact = *c.base.exact_mass;
        // Nominal: the box reference's own error per pixel, the exact mass's shoelace rounding
        // and, for methods, one float32 rounding per pixel.
        double bound = pixels * kBoxReferencePixelError + 1e-12 * std::max(1.0, std::abs(exact));
        if (!s.reference) bound += kFloat32Rounding * abs_sum(image);
        InvariantResult& r = row.at(Invariant::kArea);
        r = check_area(mass_of(image, c.base.scene.background), exact, bound);
        if (r.outcome == Outcome::kFail) {
            if (const ExpectedFailure* e = find_expected(s.id, Invariant::kArea, c.info->name)) {
                r.documented_bound = documented_area_bound(e->bound, c, s);
                if (r.value <= r.documented_bound) {
                    r.outcome = Outcome::kDocumented;
                    r.note = e->reason;
                } else {
                    r.note = "beyond the documented bound too; " + e->reason;
                }
            }
        }
    }

    settle_same(row.at(Invariant::kContinuity), image, s.render(c.moved), kContinuityTolerance, c,
                s, Invariant::kContinuity);
    settle_same(row.at(Invariant::kTranslation), image, s.render(c.shifted),
                kTranslationTolerance, c, s, Invariant::kTranslation);
    for (const InvariantResult& r : row.results) row.outcome = worst(row.outcome, r.outcome);
    return row;
}

std::uint64_t splitmix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

// A uniform double in [-1, 1] from a hash.
double unit(std::uint64_t h) { return static_cast<double>(h >> 11) * 0x1p-52 - 1.0; }

std::string short_number(double v) { return fmt::format("{:.3g}", v); }

}  // namespace

// ---- Public: cases, specs, expected failures ----

const std::vector<HardCase>& hard_cases() {
    static const std::vector<HardCase> cases = {
        {"boundary-vertices", "every vertex on a pixel corner, edges along pixel borders",
         [] { return corner_scene("boundary-vertices", 0.0, 0.0); }},
        {"centre-vertices", "every vertex on a pixel centre, edges through rows of centres",
         [] { return corner_scene("centre-vertices", 0.5, 0.5); }},
        {"subscanline-n3", "vertices and horizontal edges on the sub-scanlines of n = 3",
         [] { return subscanline_scene(3); }},
        {"subscanline-n6", "vertices and horizontal edges on the sub-scanlines of n = 6",
         [] { return subscanline_scene(6); }},
        {"subscanline-n12", "vertices and horizontal edges on the sub-scanlines of n = 12",
         [] { return subscanline_scene(12); }},
        {"axis-aligned", "exactly horizontal and vertical edges, off and on the grid",
         axis_aligned_scene},
        {"slope-1e-12", "edges with dy/dx = 1e-12, one starting on a pixel border",
         slope_small_scene},
        {"slope-1e12", "edges with dy/dx = 1e12, one through a column of pixel centres",
         slope_large_scene},
        {"zero-area", "contours of one repeated point and out-and-back segments",
         zero_area_scene},
        {"collinear", "contours whose points all lie on one line, in non-monotone order",
         collinear_scene},
        {"repeated-vertices", "every vertex repeated, the last equal to the first",
         repeated_vertices_scene},
        {"doubling-back", "an antenna out and back, a square run round and back",
         doubling_back_scene},
        {"self-intersecting", "a pentagram (winding 2 inside) and a bow tie (windings +1, -1)",
         self_intersecting_scene},
        {"sliver-1e-9", "parallelograms 1e-9 px wide: slanted, horizontal, vertical",
         sliver_scene},
        {"star-1024", "1024 wedges meeting in one pixel (2048 edges end there)", star_scene},
        {"offset-2^20", "scene and window at 2^20 px", [] { return offset_scene("offset-2^20", 0x1p20); }},
        {"offset-2^30", "scene and window at 2^30 px", [] { return offset_scene("offset-2^30", 0x1p30); }},
        {"outside", "shapes wholly outside the image, one framing it, one at 1e15 px",
         outside_scene},
        {"covers-image", "shapes reaching 1e6 and 1e15 px that cover the whole image",
         covers_scene},
        {"image-1x1", "a 1x1 image, a triangle inside the pixel", one_pixel_scene},
        {"image-16384x16", "a 16384x16 image, one long slanted quadrilateral", long_image_scene},
    };
    return cases;
}

std::vector<std::string> default_hard_case_methods() {
    std::vector<std::string> specs;
    for (const MethodInfo& info : method_registry()) specs.push_back(info.id);
    // The on-sub-scanline cases are for these n; then the parameter maxima.
    for (const char* spec : {"box-multiscan:n=6", "box-multiscan:n=12", "gauss-multiscan:n=6",
                             "gauss-multiscan:n=12", "box-multiscan:n=256",
                             "gauss-multiscan:n=256", "ssaa:k=64"}) {
        specs.push_back(spec);
    }
    return specs;
}

// Cases with horizontal (or, slope-1e-12, nearly horizontal) edges exactly on sub-scanlines of
// the multiscan methods: on integer or half-integer heights (every n has lines there, or every
// even n), on j + l/n by construction, or on the image's bottom border (outside).
const std::vector<std::string> kHorizontalOnLine = {
    "boundary-vertices", "centre-vertices", "subscanline-n3", "subscanline-n6", "subscanline-n12",
    "axis-aligned", "slope-1e-12", "slope-1e12", "collinear", "doubling-back", "outside"};

const std::vector<ExpectedFailure>& hard_case_expected_failures() {
    // clang-format off
    static const std::vector<ExpectedFailure> list = {
        // Point sampling and 8-bit coverage: discontinuous by nature.
        {"none", Invariant::kContinuity, {}, DocumentedBound::kLocalChanges,
         "point sampling: a sample on an edge flips when the edge moves by any amount"},
        {"ssaa", Invariant::kContinuity, {}, DocumentedBound::kLocalChanges,
         "point sampling: a sample on an edge flips when the edge moves by any amount"},
        {"nishita-d", Invariant::kContinuity, {}, DocumentedBound::kLocalChanges,
         "point sampling on the half-pixel lattice: samples on edges flip"},
        {"fast-edge", Invariant::kContinuity, {}, DocumentedBound::kLocalChanges,
         "aliased fill by pixel centres: a centre on an edge flips"},
        {"cairo", Invariant::kContinuity, {}, DocumentedBound::kLocalChanges,
         "vertices rounded to 1/256 px and coverage to 8 bits: steps, not a continuum"},
        {"agg", Invariant::kContinuity, {}, DocumentedBound::kLocalChanges,
         "vertices rounded to 1/256 px and coverage to 8 bits: steps, not a continuum"},
        // Line sampling in y: a horizontal (or nearly horizontal) edge on a sub-scanline takes
        // the mean of the line's two limits; moved off it by any amount, the line sees one limit:
        // a jump of up to (edge length in the pixel) x span / n.
        {"box-multiscan", Invariant::kContinuity, kHorizontalOnLine, DocumentedBound::kLocalChanges,
         "line sampling in y: a horizontal edge moved across a sub-scanline jumps by up to 1/n"},
        {"gauss-multiscan", Invariant::kContinuity, kHorizontalOnLine,
         DocumentedBound::kLocalChanges,
         "line sampling in y: a horizontal edge moved across a sub-scanline jumps"},
        // The same, for the rounding of 2^20 + y: a line j + l/n that is not a dyadic fraction
        // cannot hold a vertex both before and after the move.
        {"box-multiscan", Invariant::kTranslation, kHorizontalOnLine,
         DocumentedBound::kLocalChanges,
         "2^20 + y rounds y by up to 2^-33 px, off a sub-scanline it lay on: the same jump"},
        {"gauss-multiscan", Invariant::kTranslation, kHorizontalOnLine,
         DocumentedBound::kLocalChanges,
         "2^20 + y rounds y by up to 2^-33 px, off a sub-scanline it lay on: the same jump"},
        // Point samples exactly on an edge flip under the rounding of 2^20 + x too.
        {"none", Invariant::kTranslation, {}, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a sample exactly on an edge flips"},
        {"ssaa", Invariant::kTranslation, {}, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a sample exactly on an edge flips"},
        {"nishita-d", Invariant::kTranslation, {}, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a sample exactly on an edge flips"},
        {"fast-edge", Invariant::kTranslation, {}, DocumentedBound::kLocalChanges,
         "2^20 + x rounds x by up to 2^-33 px: a centre exactly on an edge flips"},
        // Area is exact only for exact integration.
        {"none", Invariant::kArea, {}, DocumentedBound::kSamplingArea,
         "one sample per pixel: area is conserved only on average (a sliver is lost)"},
        {"ssaa", Invariant::kArea, {}, DocumentedBound::kSamplingArea,
         "k x k samples per pixel: a pixel crossed by one edge errs by up to 1/k"},
        {"fast-edge", Invariant::kArea, {}, DocumentedBound::kAnyArea,
         "edge blending by distance, not area: thin shapes come out too heavy, fills too light"},
        {"box-multiscan", Invariant::kArea, {}, DocumentedBound::kTrapezoidArea,
         "trapezoidal rule in y: exact only where L(y) has no kink inside a sub-band"},
        {"cairo", Invariant::kArea, {}, DocumentedBound::kQuantisedArea,
         "8-bit coverage on a 1/256 px vertex grid, 15 sub-rows where edges start or cross"},
        {"agg", Invariant::kArea, {}, DocumentedBound::kQuantisedArea,
         "8-bit coverage (floor or ceil of 256 c) on a 1/256 px vertex grid"},
        // The exact image rounded to 8 bits: half a step per edge pixel, and a value within
        // rounding of a half step flips under any move.
        {"exact-8bit", Invariant::kArea, {}, DocumentedBound::kRoundingStep,
         "exact coverage rounded to 8 bits: up to half a step per pixel"},
        {"exact-8bit", Invariant::kContinuity, {}, DocumentedBound::kRoundingStep,
         "rounding to 8 bits: a value at half a step flips when anything moves by any amount"},
        {"exact-8bit", Invariant::kTranslation, {}, DocumentedBound::kRoundingStep,
         "rounding to 8 bits: a value at half a step flips under the rounding of 2^20 + x"},
    };
    // clang-format on
    return list;
}

const char* invariant_name(Invariant invariant) {
    switch (invariant) {
        case Invariant::kFinite: return "finite";
        case Invariant::kRange: return "range";
        case Invariant::kArea: return "area";
        case Invariant::kContinuity: return "continuity";
        case Invariant::kTranslation: return "translation";
    }
    return "?";
}

const char* outcome_name(Outcome outcome) {
    switch (outcome) {
        case Outcome::kNotApplicable: return "n/a";
        case Outcome::kPass: return "pass";
        case Outcome::kDocumented: return "documented";
        case Outcome::kFail: return "FAIL";
    }
    return "?";
}

// ---- Public: checks and scene transforms ----

InvariantResult check_finite(const Coverage& image) {
    InvariantResult r;
    r.bound = 0.0;
    long long bad = 0;
    for (int j = 0; j < image.height; ++j) {
        for (int i = 0; i < image.width; ++i) {
            if (std::isfinite(image.at(i, j))) continue;
            if (bad++ == 0) r.x = i, r.y = j;
        }
    }
    r.value = static_cast<double>(bad);
    r.outcome = bad == 0 ? Outcome::kPass : Outcome::kFail;
    if (bad) r.note = fmt::format("{} non-finite pixels", bad);
    return r;
}

InvariantResult check_range(const Coverage& image, double lo, double hi, double slack) {
    InvariantResult r;
    r.bound = slack;
    for (int j = 0; j < image.height; ++j) {
        for (int i = 0; i < image.width; ++i) {
            const double v = image.at(i, j);
            // A NaN is out of every range: its excursion is infinite.
            const double excursion = v >= lo && v <= hi ? 0.0
                                     : v < lo          ? lo - v
                                     : v > hi          ? v - hi
                                                       : HUGE_VAL;
            if (excursion > r.value) r.value = excursion, r.x = i, r.y = j;
        }
    }
    r.outcome = r.value <= slack ? Outcome::kPass : Outcome::kFail;
    if (r.outcome == Outcome::kFail) {
        r.note = fmt::format("value {} outside [{}, {}]", image.at(r.x, r.y), lo, hi);
    }
    return r;
}

InvariantResult check_area(double mass, double exact_mass, double bound) {
    InvariantResult r;
    r.bound = bound;
    r.value = std::abs(mass - exact_mass);
    // Written so that a NaN mass fails.
    r.outcome = r.value <= bound ? Outcome::kPass : Outcome::kFail;
    if (r.outcome == Outcome::kFail) {
        r.note = fmt::format("mass {} against exact {}", mass, exact_mass);
    }
    return r;
}

InvariantResult check_same(const Coverage& a, const Coverage& b, double tolerance) {
    InvariantResult r;
    r.bound = tolerance;
    long long changed = 0;
    for (int j = 0; j < a.height; ++j) {
        for (int i = 0; i < a.width; ++i) {
            double d = std::abs(a.at(i, j) - b.at(i, j));
            if (std::isnan(d)) d = HUGE_VAL;  // a NaN in either is the worst difference
            if (d > tolerance) ++changed;
            if (d > r.value) r.value = d, r.x = i, r.y = j;
        }
    }
    r.changed_fraction = a.data.empty() ? 0.0 : static_cast<double>(changed) / a.data.size();
    r.outcome = changed == 0 ? Outcome::kPass : Outcome::kFail;
    if (changed) {
        r.note = fmt::format("{} pixels differ by more than {}", changed, short_number(tolerance));
    }
    return r;
}

Scene perturbed(const Scene& scene, double move_px) {
    Scene out = scene;
    for (Shape& shape : out.shapes) {
        for (Contour& contour : shape.contours) {
            for (Point& p : contour) {
                const std::uint64_t h = splitmix(std::bit_cast<std::uint64_t>(p.x) ^
                                                 splitmix(std::bit_cast<std::uint64_t>(p.y)));
                p.x += move_px * unit(h);
                p.y += move_px * unit(splitmix(h));
            }
        }
    }
    return out;
}

Scene offset_with_window(const Scene& scene, double offset_px) {
    Scene out = scene;
    out.origin_x += offset_px;
    out.origin_y += offset_px;
    auto shift = [offset_px](Shape& shape) {
        for (Contour& contour : shape.contours) {
            for (Point& p : contour) p = {p.x + offset_px, p.y + offset_px};
        }
    };
    for (Shape& shape : out.shapes) shift(shape);
    for (ThinObject& object : out.thin_objects) shift(object.shape);
    return out;
}

Raster<std::uint8_t> edge_neighbourhood(const Scene& scene, int reach) {
    const Scene window = in_window_frame(scene);
    const int margin = reach + 1;
    return dilate_and_crop(edge_counts(window, margin), margin, reach, window.width,
                           window.height);
}

// ---- Public: the run ----

std::vector<HardCaseRow> run_hard_cases(const std::vector<std::string>& method_specs,
                                        const ProgressFn& progress) {
    const std::vector<Subject> subjects =
        subjects_for(method_specs.empty() ? default_hard_case_methods() : method_specs);
    const std::vector<HardCase>& cases = hard_cases();
    const std::size_t total = cases.size() * subjects.size();
    std::vector<HardCaseRow> rows;
    rows.reserve(total);
    for (const HardCase& hc : cases) {
        const PreparedCase prepared = prepare(hc);
        for (const Subject& s : subjects) {
            rows.push_back(run_one(prepared, s));
            if (progress) progress(rows.size(), total, hc.name + " " + s.spec);
        }
    }
    return rows;
}

// ---- Public: formatting ----

std::string format_hard_case_table(const std::vector<HardCaseRow>& rows) {
    std::vector<std::string> cases, methods;
    for (const HardCaseRow& r : rows) {
        if (std::find(cases.begin(), cases.end(), r.case_name) == cases.end()) {
            cases.push_back(r.case_name);
        }
        if (std::find(methods.begin(), methods.end(), r.method) == methods.end()) {
            methods.push_back(r.method);
        }
    }
    auto find_row = [&](const std::string& c, const std::string& m) -> const HardCaseRow* {
        for (const HardCaseRow& r : rows) {
            if (r.case_name == c && r.method == m) return &r;
        }
        return nullptr;
    };
    std::string out = "Hard cases: pass, doc (a documented property of the method, within its "
                      "documented bound), FAIL, - (not run)\n\ncolumns:\n";
    for (std::size_t m = 0; m < methods.size(); ++m) {
        out += fmt::format("  {:>2}  {}\n", m + 1, methods[m]);
    }
    std::size_t name_width = 4;
    for (const std::string& c : cases) name_width = std::max(name_width, c.size());
    out += fmt::format("\n{:<{}}", "case", name_width);
    for (std::size_t m = 0; m < methods.size(); ++m) out += fmt::format(" {:>4}", m + 1);
    out += "\n";
    for (const std::string& c : cases) {
        out += fmt::format("{:<{}}", c, name_width);
        for (const std::string& m : methods) {
            const HardCaseRow* r = find_row(c, m);
            const Outcome o = r ? r->outcome : Outcome::kNotApplicable;
            out += fmt::format(" {:>4}", o == Outcome::kPass         ? "ok"
                                         : o == Outcome::kDocumented ? "doc"
                                         : o == Outcome::kFail       ? "FAIL"
                                                                     : "-");
        }
        out += "\n";
    }

    // Failures, each with its worst value and pixel.
    std::string failures;
    for (const HardCaseRow& r : rows) {
        for (std::size_t i = 0; i < kInvariantCount; ++i) {
            const InvariantResult& res = r.results[i];
            if (res.outcome != Outcome::kFail) continue;
            failures += fmt::format("  {} / {} / {}: {} > bound {}", r.case_name, r.method,
                                    invariant_name(static_cast<Invariant>(i)),
                                    short_number(res.value), short_number(res.bound));
            if (res.x >= 0) failures += fmt::format(" at pixel ({}, {})", res.x, res.y);
            failures += fmt::format(": {}\n", res.note);
        }
    }
    out += "\nfailures:\n" + (failures.empty() ? std::string("  none\n") : failures);

    // Documented properties seen: per method and invariant, how often and the worst case.
    struct Seen {
        std::string method;
        Invariant invariant;
        int count = 0;
        const HardCaseRow* worst = nullptr;
        double worst_ratio = -1.0;
    };
    std::vector<Seen> seen;
    for (const HardCaseRow& r : rows) {
        for (std::size_t i = 0; i < kInvariantCount; ++i) {
            const InvariantResult& res = r.results[i];
            if (res.outcome != Outcome::kDocumented) continue;
            const auto inv = static_cast<Invariant>(i);
            auto it = std::find_if(seen.begin(), seen.end(), [&](const Seen& s) {
                return s.method == r.method && s.invariant == inv;
            });
            if (it == seen.end()) it = seen.insert(seen.end(), Seen{r.method, inv});
            ++it->count;
            const double ratio = res.documented_bound > 0.0 ? res.value / res.documented_bound
                                                            : res.changed_fraction;
            if (ratio > it->worst_ratio) it->worst_ratio = ratio, it->worst = &r;
        }
    }
    out += "\ndocumented properties (method, invariant: cases; worst case):\n";
    if (seen.empty()) out += "  none\n";
    for (const Seen& s : seen) {
        const InvariantResult& res = s.worst->at(s.invariant);
        out += fmt::format("  {}, {}: {} case{}; worst {}: ", s.method, invariant_name(s.invariant),
                           s.count, s.count == 1 ? "" : "s", s.worst->case_name);
        if (s.invariant == Invariant::kArea) {
            out += fmt::format("|error| {} (documented bound {})", short_number(res.value),
                               short_number(res.documented_bound));
        } else {
            out += fmt::format("max change {}, {:.2g}% of pixels changed (allowed: the {:.2g}% "
                               "within {} px of an edge)",
                               short_number(res.value), 100.0 * res.changed_fraction,
                               100.0 * res.allowed_fraction, kFlipReachPx);
        }
        out += fmt::format("\n      {}\n", res.note);
    }

    // The worst value per invariant among passing results: how close to its bound it came.
    out += "\nworst passing value per invariant (value / bound):\n";
    for (std::size_t i = 0; i < kInvariantCount; ++i) {
        const HardCaseRow* worst_row = nullptr;
        double worst_ratio = -1.0;
        int passes = 0, documented = 0, failed = 0;
        for (const HardCaseRow& r : rows) {
            const InvariantResult& res = r.results[i];
            passes += res.outcome == Outcome::kPass;
            documented += res.outcome == Outcome::kDocumented;
            failed += res.outcome == Outcome::kFail;
            if (res.outcome != Outcome::kPass) continue;
            const double ratio = res.bound > 0.0 ? res.value / res.bound : res.value;
            if (ratio > worst_ratio) worst_ratio = ratio, worst_row = &r;
        }
        out += fmt::format("  {:<12} {} pass, {} documented, {} failed", 
                           invariant_name(static_cast<Invariant>(i)), passes, documented, failed);
        if (worst_row) {
            const InvariantResult& res = worst_row->results[i];
            out += fmt::format("; worst {} (bound {}) on {} / {}", short_number(res.value),
                               short_number(res.bound), worst_row->case_name, worst_row->method);
        }
        out += "\n";
    }
    return out;
}

std::string format_hard_case_json(const std::vector<HardCaseRow>& rows) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const HardCaseRow& r : rows) {
        nlohmann::ordered_json row;
        row["case"] = r.case_name;
        row["method"] = r.method;
        row["reference"] = r.reference;
        row["width"] = r.width;
        row["height"] = r.height;
        row["outcome"] = outcome_name(r.outcome);
        nlohmann::ordered_json invariants = nlohmann::ordered_json::object();
        for (std::size_t i = 0; i < kInvariantCount; ++i) {
            const InvariantResult& res = r.results[i];
            nlohmann::ordered_json item;
            item["outcome"] = outcome_name(res.outcome);
            // JSON has no infinity: an infinite figure (a NaN pixel) is written as null.
            auto number = [](double v) {
                return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
            };
            item["value"] = number(res.value);
            item["bound"] = number(res.bound);
            if (res.outcome == Outcome::kDocumented || res.documented_bound > 0.0) {
                item["documented_bound"] = number(res.documented_bound);
            }
            if (static_cast<Invariant>(i) == Invariant::kContinuity ||
                static_cast<Invariant>(i) == Invariant::kTranslation) {
                item["changed_fraction"] = res.changed_fraction;
                item["allowed_fraction"] = res.allowed_fraction;
            }
            if (res.x >= 0) item["pixel"] = {res.x, res.y};
            if (!res.note.empty()) item["note"] = res.note;
            invariants[invariant_name(static_cast<Invariant>(i))] = std::move(item);
        }
        row["invariants"] = std::move(invariants);
        out.push_back(std::move(row));
    }
    return out.dump(1);
}

}  // namespace aabench
