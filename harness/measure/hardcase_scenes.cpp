// The hard cases (harness/measure/hardcases.h): the scene generators, the hard_cases() list in
// report order, the default method specs (each row's hard-case settings) and the case sets
// the rows' documented properties name (case_in_set()). Cases and their reasons:
// docs/hardcases.md.
//
// Every case is a pure generator of a small scene with, where it is known in closed form, its
// exact mass: the integral over the image of (visible value - background). Masses come from
// shoelace sums on simple polygons (the self-intersecting pentagram is measured as the simple
// ten-pointed outline its nonzero fill is), never from a renderer, so the area check of the box
// reference is a real check.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "harness/measure/hardcases.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

constexpr int kCaseWidth = 32;  // not square, so that a swapped x and y shows
constexpr int kCaseHeight = 24;

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
    const double inner =
        radius * std::cos(0.4 * std::numbers::pi) / std::cos(0.2 * std::numbers::pi);
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
        for (const Contour& c : shape.contours) {
            mass += (shape.value - scene.background) * polygon_area(c);
        }
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

// ---- Bezier curves (scene file version 4) ----

// Twice the signed area swept by B over [t0, t1] (x y' - y x', a polynomial of degree <= 5:
// 3-point Gauss-Legendre is exact), relative to `o`.
double twice_swept(const Segment& s, double t0, double t1, Point o) {
    static constexpr double kNodes[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
    static constexpr double kWeights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double t = t0 + kNodes[k] * (t1 - t0);
        const Point b = bezier_at(s, t), d = bezier_derivative(s, t);
        sum += kWeights[k] * ((b.x - o.x) * d.y - (b.y - o.y) * d.x);
    }
    return sum * (t1 - t0);
}

// The self-crossing B(s) = B(t), s < t, of a cubic with a loop: the closest pair on a grid,
// then Newton's method on the two coordinates (Jacobian [B'(s), -B'(t)]) to the last bits;
// {1, 1} when the cubic does not cross itself.
std::pair<double, double> self_crossing(const Segment& c) {
    double best = HUGE_VAL, s = 0.0, t = 0.0;
    constexpr int kGrid = 128;
    for (int i = 0; i <= kGrid; ++i) {
        for (int j = i + kGrid / 16; j <= kGrid; ++j) {
            const Point a = bezier_at(c, double(i) / kGrid), b = bezier_at(c, double(j) / kGrid);
            const double d = std::hypot(a.x - b.x, a.y - b.y);
            if (d < best) best = d, s = double(i) / kGrid, t = double(j) / kGrid;
        }
    }
    for (int k = 0; k < 50; ++k) {
        const Point a = bezier_at(c, s), b = bezier_at(c, t);
        const Point da = bezier_derivative(c, s), db = bezier_derivative(c, t);
        const double fx = a.x - b.x, fy = a.y - b.y;
        const double det = da.x * -db.y - -db.x * da.y;
        if (det == 0.0) break;
        const double ds = (fx * -db.y - -db.x * fy) / det, dt = (da.x * fy - da.y * fx) / det;
        s -= ds;
        t -= dt;
        if (std::abs(ds) + std::abs(dt) < 1e-16) break;
    }
    // No crossing (Newton went elsewhere): the contour is simple, no loop to split off.
    const Point a = bezier_at(c, s), b = bezier_at(c, t);
    if (!(s > 0.0 && s < t && t < 1.0 && std::hypot(a.x - b.x, a.y - b.y) < 1e-9))
        return {1.0, 1.0};
    return {s, t};
}

// The degenerate curves, each closed by a straight edge, apart from each other. The mass is
// Green's theorem on the segments (exact polynomial integrals) of each simple contour; the
// loop's nonzero region is its two faces, the loop B[s, t] and the rest B[0, s] + B[t, 1] +
// the chord, each of winding +-1: the sum of their areas, not the signed area.
std::vector<Shape> bezier_degenerate_shapes(Point o, double* mass) {
    auto at = [o](double x, double y) { return Point{o.x + x, o.y + y}; };
    std::vector<Shape> shapes;
    auto closed = [&](Segment s, double value) {
        shapes.push_back(bezier_shape({{s, line_segment(s.end(), s.start())}}, value));
        const auto [t0, t1] = s.degree == 3 ? self_crossing(s) : std::pair{1.0, 1.0};
        const Point a = s.start(), b = s.end();
        // The chord's share: twice the swept area of the line from b back to a.
        const double chord = (b.x - o.x) * (a.y - o.y) - (a.x - o.x) * (b.y - o.y);
        const double rest = twice_swept(s, 0.0, t0, o) + twice_swept(s, t1, 1.0, o) + chord;
        const double loop = twice_swept(s, t0, t1, o);
        *mass += value * 0.5 * (std::abs(rest) + std::abs(loop));
    };
    // A cusp: control points crossed over.
    closed(cubic_segment(at(1.3, 1.2), at(9.7, 8.4), at(1.1, 8.6), at(9.6, 1.4)), 1.0);
    // A loop.
    closed(cubic_segment(at(12.2, 2.3), at(22.9, 9.8), at(9.7, 9.6), at(20.4, 2.1)), 0.8);
    // A quadratic whose control point lies on its chord (a straight curve).
    closed(quad_segment(at(23.3, 1.6), at(26.3, 4.6), at(29.3, 7.6)), 0.6);
    // Coincident control points (both on the start).
    closed(cubic_segment(at(1.4, 12.3), at(1.4, 12.3), at(9.1, 19.7), at(9.8, 12.6)), 0.9);
    // Extrema exactly on a pixel row (y = 14), on a column (x = 26) and on a row of centres.
    // (A quadratic's extremum lies halfway between its ends' mean and its control point.)
    closed(quad_segment(at(12.3, 19.6), at(16.1, 8.4), at(19.9, 19.6)), 0.7);
    closed(quad_segment(at(22.4, 12.2), at(29.6, 15.6), at(22.4, 19.0)), 0.5);
    closed(quad_segment(at(1.2, 22.9), at(5.4, 18.1), at(9.6, 22.9)), 0.4);
    // Curves a hundredth of a pixel across.
    closed(quad_segment(at(12.21, 22.31), at(12.215, 22.30), at(12.22, 22.31)), 1.0);
    closed(cubic_segment(at(16.3, 22.1), at(20.4, 22.11), at(24.6, 22.115), at(28.7, 22.105)), 1.0);
    return shapes;
}

HardCaseScene bezier_degenerate_scene() {
    Scene scene = blank(kCaseWidth, kCaseHeight, 0.0, "bezier-degenerate");
    double mass = 0.0;
    scene.shapes = bezier_degenerate_shapes({0.0, 0.0}, &mass);
    return {std::move(scene), mass};
}

// The same curves at 1e6 px, with a window origin that cancels the offset: the window frame
// subtracts it once (exact for these coordinates, Sterbenz), so every method and reference
// must give the image of bezier-degenerate.
HardCaseScene bezier_far_scene() {
    Scene scene = blank(kCaseWidth, kCaseHeight, 0.0, "bezier-offset-1e6");
    scene.origin_x = 1e6;
    scene.origin_y = 1e6;
    double mass = 0.0;
    scene.shapes = bezier_degenerate_shapes({1e6, 1e6}, &mass);
    return {std::move(scene), mass};
}

// One contour of kManySegments cubic segments: the wavy ring r(a) = 9 + 0.8 sin(40 a) about
// the window's centre, each segment the Hermite cubic of its arc (controls a third of the
// parameter step along the tangents), so a segment spans about 6e-4 px and the pixels on the
// ring hold hundreds of them. The ring is simple (r > 0, segments far shorter than its
// bends): its mass is its area, Green's theorem on every segment.
constexpr int kManySegments = 100000;

HardCaseScene bezier_many_scene() {
    Scene scene = blank(kCaseWidth, kCaseHeight, 0.0, "bezier-1e5");
    const Point o{kCaseWidth / 2.0, kCaseHeight / 2.0};
    const double h = 2.0 * std::numbers::pi / kManySegments;
    auto at = [&](int k, Point* tangent) {
        const double a = k * h, r = 9.0 + 0.8 * std::sin(40.0 * a), dr = 32.0 * std::cos(40.0 * a);
        *tangent = {dr * std::cos(a) - r * std::sin(a), dr * std::sin(a) + r * std::cos(a)};
        return Point{o.x + r * std::cos(a), o.y + r * std::sin(a)};
    };
    SegmentContour ring;
    Point d0, d1;
    const Point start = at(0, &d0);
    Point p0 = start;
    for (int k = 0; k < kManySegments; ++k) {
        Point p1 = at(k + 1, &d1);
        if (k + 1 == kManySegments) p1 = start;  // closed exactly
        ring.push_back(cubic_segment(p0, {p0.x + h / 3 * d0.x, p0.y + h / 3 * d0.y},
                                     {p1.x - h / 3 * d1.x, p1.y - h / 3 * d1.y}, p1));
        p0 = p1;
        d0 = d1;
    }
    double twice_area = 0.0;
    for (const Segment& s : ring) twice_area += twice_swept(s, 0.0, 1.0, o);
    scene.shapes.push_back(bezier_shape({std::move(ring)}, 1.0));
    return {std::move(scene), 0.5 * std::abs(twice_area)};
}

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
        {"offset-2^20", "scene and window at 2^20 px",
         [] { return offset_scene("offset-2^20", 0x1p20); }},
        {"offset-2^30", "scene and window at 2^30 px",
         [] { return offset_scene("offset-2^30", 0x1p30); }},
        {"outside", "shapes wholly outside the image, one framing it, one at 1e15 px",
         outside_scene},
        {"covers-image", "shapes reaching 1e6 and 1e15 px that cover the whole image",
         covers_scene},
        {"image-1x1", "a 1x1 image, a triangle inside the pixel", one_pixel_scene},
        {"image-16384x16", "a 16384x16 image, one long slanted quadrilateral", long_image_scene},
        {"bezier-degenerate",
         "Bezier curves: a cusp, a loop, a straight quadratic, coincident controls, extrema on "
         "a row, a column and a row of centres, curves 0.01 px across",
         bezier_degenerate_scene},
        {"bezier-offset-1e6", "the same curves at 1e6 px, the window origin cancelling it",
         bezier_far_scene},
        {"bezier-1e5", "one contour of 10^5 cubic segments, hundreds in a pixel",
         bezier_many_scene},
    };
    return cases;
}

std::vector<std::string> default_hard_case_methods() {
    std::vector<std::string> specs;
    for (const MethodInfo& info : method_registry()) specs.push_back(info.id);
    // The settings the on-sub-scanline cases are for; then the parameter maxima.
    for (const MethodInfo& info : method_registry()) {
        for (const std::string& s : info.traits->hard_cases.line_settings) {
            specs.push_back(info.id + ":" + s);
        }
    }
    for (const MethodInfo& info : method_registry()) {
        for (const std::string& s : info.traits->hard_cases.maximum_settings) {
            specs.push_back(info.id + ":" + s);
        }
    }
    return specs;
}

bool case_in_set(CaseSet set, const std::string& case_name) {
    // Cases with horizontal (or, slope-1e-12, nearly horizontal) edges exactly on sub-scanlines
    // of the multiscan methods: on integer or half-integer heights (every n has lines there, or
    // every even n), on j + l/n by construction, or on the image's bottom border (outside).
    static const std::vector<std::string> kHorizontalOnLine = {
        "boundary-vertices", "centre-vertices", "subscanline-n3", "subscanline-n6",
        "subscanline-n12",   "axis-aligned",    "slope-1e-12",    "slope-1e12",
        "collinear",         "doubling-back",   "outside"};
    switch (set) {
        case CaseSet::kAll:
            return true;
        case CaseSet::kHorizontalOnSubscanline:
            return std::find(kHorizontalOnLine.begin(), kHorizontalOnLine.end(), case_name) !=
                   kHorizontalOnLine.end();
        case CaseSet::kCurveExtremumOnSubscanline:
            // Quadratics whose extremum lies on a pixel row and on a row of centres.
            return case_name == "bezier-degenerate" || case_name == "bezier-offset-1e6";
    }
    return false;
}

}  // namespace aabench
