// The exact box reference of regions bounded by Bezier segments (bezier_coverage.h) against
// independent computations: Archimedes' rule for parabolic segments, the closed-form area of
// closed cubic paths (power-basis polynomials integrated here), the polygon reference on a
// flattening whose deviation bound is proven (patterns/scene/bezier.h), a brute-force winding
// count at random points, and `exact` against the reference.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "harness/reference/box_reference.h"
#include "harness/reference/filter_reference.h"
#include "methods/method.h"
#include "methods/scan/reference/bezier_coverage.h"
#include "methods/scan/reference/bezier_sweep.h"
#include "methods/scan/reference/box_coverage.h"
#include "patterns/scene/bezier.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

// Rounding of the sweep's areas and roots at coordinates below 100 px: each cell's area is a
// sum of a few products of numbers below 100, ~1e-14 each; 1e-11 leaves room for a thousand.
constexpr double kRoundingTolerance = 1e-11;
// The flattening of the oracle: every point of it within this of the curve.
constexpr double kOracleFlatness = 1e-8;
// A pixel moves by at most the flattening's deviation times the boundary length inside it
// times the largest jump of value (1 here); random curves put less than 50 px of boundary in
// one pixel (checked below), so 50 kOracleFlatness, plus rounding.
constexpr double kOracleTolerance = 50.0 * kOracleFlatness + kRoundingTolerance;

Segment line(Point a, Point b) { return line_segment(a, b); }
Segment quad(Point a, Point c, Point b) { return quad_segment(a, c, b); }
Segment cubic(Point a, Point c1, Point c2, Point b) { return cubic_segment(a, c1, c2, b); }

double total(const Coverage& c) {
    double sum = 0.0;
    for (double v : c.data) sum += v;
    return sum;
}

Scene scene_of(int w, int h, std::vector<Shape> shapes, double background = 0.0) {
    Scene scene;
    scene.width = w;
    scene.height = h;
    scene.background = background;
    scene.shapes = std::move(shapes);
    return scene;
}

// The same scene with every outline flattened at `flatness`: the polygon reference's input.
Scene flattened(const Scene& scene, double flatness) { return flattened_scene(scene, flatness); }

// The oracle of a scene with discs and rings too: each circle an inscribed polygon of its own
// (not the scene's polygonisation) with sagitta <= kOracleFlatness, a ring's inner circle the
// other way round, and the curves flattened to the same bound.
Contour oracle_circle(Point centre, double r, bool reversed) {
    const int n = curve_segment_count(r, kOracleFlatness);
    Contour c;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * std::numbers::pi * (reversed ? n - k : k) / n;
        c.push_back({centre.x + r * std::cos(a), centre.y + r * std::sin(a)});
    }
    return c;
}

Scene polygon_oracle(const Scene& scene) {
    Scene out = flattened(scene, kOracleFlatness);
    for (Shape& shape : out.shapes) {
        if (!shape.circle) continue;
        const Circle c = *shape.circle;
        shape.circle.reset();
        shape.contours = {oracle_circle(c.center, c.outer, false)};
        if (!c.is_disc()) shape.contours.push_back(oracle_circle(c.center, c.inner, true));
    }
    return out;
}

double max_difference(const Coverage& a, const Coverage& b) {
    double worst = 0.0;
    for (std::size_t k = 0; k < a.data.size(); ++k) {
        worst = std::max(worst, std::abs(a.data[k] - b.data[k]));
    }
    return worst;
}

Point random_point(std::mt19937_64& rng, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    return {u(rng), u(rng)};
}

// Archimedes: the region between a parabola arc and its chord is 2/3 of the triangle of its
// control points.
TEST(BezierReference, ArchimedesParabolicSegments) {
    std::mt19937_64 rng(39);
    for (int trial = 0; trial < 40; ++trial) {
        const Point a = random_point(rng, 4, 60), c = random_point(rng, 4, 60),
                    b = random_point(rng, 4, 60);
        const double triangle =
            0.5 * std::abs((c.x - a.x) * (b.y - a.y) - (b.x - a.x) * (c.y - a.y));
        const Scene scene = scene_of(64, 64, {bezier_shape({{quad(a, c, b), line(b, a)}}, 1.0)});
        const Coverage got = bezier_box_coverage(scene);
        EXPECT_NEAR(total(got), 2.0 / 3.0 * triangle, kRoundingTolerance * 64 * 64)
            << "trial " << trial;
        for (double v : got.data)
            ASSERT_TRUE(v >= -kRoundingTolerance && v <= 1.0 + kRoundingTolerance);
    }
}

// --- Closed-form area of a closed cubic path, from its power-basis polynomials ---

using Poly = std::array<double, 7>;  // coefficients of t^0 .. t^6

Poly power_basis(const Segment& s, int axis) {
    auto c = [&](int k) { return axis == 0 ? s.p[k].x : s.p[k].y; };
    Poly p{};
    if (s.degree == 1) {
        p[0] = c(0);
        p[1] = c(1) - c(0);
    } else if (s.degree == 2) {
        p[0] = c(0);
        p[1] = 2.0 * (c(1) - c(0));
        p[2] = c(0) - 2.0 * c(1) + c(2);
    } else {
        p[0] = c(0);
        p[1] = 3.0 * (c(1) - c(0));
        p[2] = 3.0 * (c(0) - 2.0 * c(1) + c(2));
        p[3] = c(3) - 3.0 * c(2) + 3.0 * c(1) - c(0);
    }
    return p;
}

// The integral over t in [0, 1] of x(t) y'(t): the segment's share of the area (Green).
double green_share(const Segment& s) {
    const Poly x = power_basis(s, 0), y = power_basis(s, 1);
    double sum = 0.0;
    for (int i = 0; i <= 3; ++i) {
        for (int j = 1; j <= 3; ++j)
            sum += x[i] * j * y[j] / (i + j);  // t^(i+j-1) integrates to 1/(i+j)
    }
    return sum;
}

TEST(BezierReference, ClosedCubicPathAreasInClosedForm) {
    std::mt19937_64 rng(4);
    for (int trial = 0; trial < 30; ++trial) {
        // A star-shaped contour around the centre (no self-crossing): cubics between points at
        // increasing angles, controls pulled outwards a little.
        SegmentContour contour;
        const int n = 3 + trial % 5;
        std::vector<Point> pts;
        std::uniform_real_distribution<double> radius(12, 26), bulge(-0.15, 0.25);
        for (int k = 0; k < n; ++k) {
            const double a = 2.0 * M_PI * k / n;
            const double r = radius(rng);
            pts.push_back({32 + r * std::cos(a), 32 + r * std::sin(a)});
        }
        for (int k = 0; k < n; ++k) {
            const Point a = pts[k], b = pts[(k + 1) % n];
            const Point m{0.5 * (a.x + b.x) - 32, 0.5 * (a.y + b.y) - 32};
            const double f1 = 1.0 + bulge(rng), f2 = 1.0 + bulge(rng);
            const Point c1{32 + m.x * f1 + (a.x - b.x) * 0.2, 32 + m.y * f1 + (a.y - b.y) * 0.2};
            const Point c2{32 + m.x * f2 - (a.x - b.x) * 0.2, 32 + m.y * f2 - (a.y - b.y) * 0.2};
            contour.push_back(cubic(a, c1, c2, b));
        }
        double area = 0.0;
        for (const Segment& s : contour) area += green_share(s);
        const Scene scene = scene_of(64, 64, {bezier_shape({contour}, 1.0)});
        EXPECT_NEAR(total(bezier_box_coverage(scene)), std::abs(area), 64 * 64 * kRoundingTolerance)
            << "trial " << trial;
        EXPECT_NEAR(twice_signed_area(contour), 2.0 * area, 1e-9) << "trial " << trial;
    }
}

// Random shapes of cubic and quadratic contours that overlap each other and themselves (loops),
// beside polygons, against the polygon reference of a fine flattening.
Shape random_curved_shape(std::mt19937_64& rng, double value) {
    std::vector<SegmentContour> outline;
    const int contours = 1 + static_cast<int>(rng() % 2);
    for (int k = 0; k < contours; ++k) {
        SegmentContour c;
        const int n = 1 + static_cast<int>(rng() % 4);
        const Point start = random_point(rng, -6, 54);
        Point cur = start;
        for (int s = 0; s < n; ++s) {
            const Point end = s + 1 == n ? start : random_point(rng, -6, 54);
            switch (rng() % 3) {
                case 0:
                    c.push_back(line(cur, end));
                    break;
                case 1:
                    c.push_back(quad(cur, random_point(rng, -10, 58), end));
                    break;
                default:
                    c.push_back(
                        cubic(cur, random_point(rng, -10, 58), random_point(rng, -10, 58), end));
            }
            cur = end;
        }
        if (n == 1 && c.front().degree == 1)
            c.front() = cubic(start, random_point(rng, -10, 58), random_point(rng, -10, 58), start);
        outline.push_back(c);
    }
    return bezier_shape(outline, value);
}

TEST(BezierReference, AgreesWithThePolygonReferenceOfAFineFlattening) {
    std::mt19937_64 rng(2011);
    double worst = 0.0;
    for (int trial = 0; trial < 12; ++trial) {
        std::vector<Shape> shapes;
        const int count = 1 + trial % 4;
        for (int s = 0; s < count; ++s) shapes.push_back(random_curved_shape(rng, 0.25 + 0.25 * s));
        const Scene scene = scene_of(48, 40, shapes, 0.1);
        const Coverage exact = bezier_box_coverage(scene);
        const Coverage oracle = box_coverage(flattened(scene, kOracleFlatness));
        const double diff = max_difference(exact, oracle);
        worst = std::max(worst, diff);
        EXPECT_LE(diff, kOracleTolerance) << "trial " << trial;
    }
    RecordProperty("worst", fmt::format("{:.3g}", worst));
}

// Nonzero winding at random points, by brute force on a fine flattening: a pixel the
// reference calls fully covered (or empty) holds no point of the other kind.
int winding_at(const Shape& flat, Point q) {
    int w = 0;
    for (const Contour& c : flat.contours) {
        for (std::size_t k = 0; k < c.size(); ++k) {
            const Point a = c[k], b = c[(k + 1) % c.size()];
            if ((a.y <= q.y) != (b.y <= q.y)) {
                const double x = a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x);
                if (x < q.x) w += b.y > a.y ? 1 : -1;
            }
        }
    }
    return w;
}

TEST(BezierReference, FullAndEmptyPixelsMatchABruteForceWindingCount) {
    std::mt19937_64 rng(77);
    int checked = 0;
    for (int trial = 0; trial < 6; ++trial) {
        const Shape shape = random_curved_shape(rng, 1.0);
        const Scene scene = scene_of(48, 48, {shape});
        const Coverage exact = bezier_box_coverage(scene);
        const Shape flat = flattened_shape(shape, 1e-5);  // samples lie 0.01 px inside the pixel
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int j = 0; j < 48; ++j) {
            for (int i = 0; i < 48; ++i) {
                const double v = exact.at(i, j);
                if (v > 1e-9 && v < 1.0 - 1e-9) continue;
                for (int k = 0; k < 4; ++k) {
                    const Point q{i + 0.01 + 0.98 * u(rng), j + 0.01 + 0.98 * u(rng)};
                    ASSERT_EQ(winding_at(flat, q) != 0, v > 0.5)
                        << "trial " << trial << " pixel " << i << "," << j << " value " << v;
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 10000);
}

// Degenerate and touching curves: a cusp, a loop, a quadratic with its control point on its
// chord, coincident control points, extrema exactly on pixel rows and columns, the same shape
// twice (coincident boundaries), two shapes sharing a curved edge, a curve tangent to another.
TEST(BezierReference, HardCurvesAgreeWithTheOracle) {
    auto scaled = [](Point p) { return Point{6 + 36 * p.x, 6 + 36 * p.y}; };
    auto cub = [&](Point a, Point b, Point c, Point d) {
        return cubic(scaled(a), scaled(b), scaled(c), scaled(d));
    };
    const Segment cusp = cub({0, 0}, {1, 1}, {0, 1}, {1, 0});
    const Segment loop = cub({0, 0.2}, {1.4, 1}, {-0.4, 1}, {1, 0.2});
    const Segment arc = quad({10, 30}, {25, 10}, {40, 30});  // top exactly at y = 20
    const std::vector<std::pair<const char*, std::vector<Shape>>> cases = {
        {"cusp", {bezier_shape({{cusp, line(cusp.end(), cusp.start())}}, 1.0)}},
        {"loop", {bezier_shape({{loop, line(loop.end(), loop.start())}}, 1.0)}},
        {"control on chord",
         {bezier_shape(
             {{quad({5, 5}, {20, 20}, {40, 40}), line({40, 40}, {40, 5}), line({40, 5}, {5, 5})}},
             1.0)}},
        {"coincident controls",
         {bezier_shape({{cubic({5, 30}, {5, 30}, {40, 5}, {40, 30}), line({40, 30}, {5, 30})}},
                       1.0)}},
        {"extremum on a row", {bezier_shape({{arc, line(arc.end(), arc.start())}}, 1.0)}},
        {"extremum on a column",
         {bezier_shape({{quad({30, 5}, {10, 20}, {30, 35}), line({30, 35}, {30, 5})}}, 1.0)}},
        {"the same shape twice",
         {bezier_shape({{loop, line(loop.end(), loop.start())}}, 0.4),
          bezier_shape({{loop, line(loop.end(), loop.start())}}, 0.9)}},
        {"a shared curved edge",
         {bezier_shape({{arc, line(arc.end(), arc.start())}}, 0.6),
          bezier_shape(
              {{arc, line(arc.end(), {40, 8}), line({40, 8}, {10, 8}), line({10, 8}, arc.start())}},
              0.3)}},
        {"tangent curves",
         {bezier_shape({{arc, line(arc.end(), arc.start())}}, 0.7),
          bezier_shape({{quad({10, 10}, {25, 30}, {40, 10}), line({40, 10}, {10, 10})}}, 0.2)}},
    };
    for (const auto& [name, shapes] : cases) {
        const Scene scene = scene_of(48, 48, shapes, 0.05);
        const double diff = max_difference(bezier_box_coverage(scene),
                                           box_coverage(flattened(scene, kOracleFlatness)));
        EXPECT_LE(diff, kOracleTolerance) << name;
    }
}

// The radial filters along curve pieces against the polygon radial reference (its own bound
// 1e-10) of the fine flattening: a filtered value moves by at most the filter's peak A times
// the flattening's deviation times the boundary length inside the support (< 50 px here).
TEST(BezierReference, RadialFiltersAgreeWithThePolygonReferenceOfAFineFlattening) {
    std::mt19937_64 rng(1984);
    double worst = 0.0;
    for (const char* spec : {"gaussian", "cone", "gaussian:sigma=0.7,radius=1.5"}) {
        const Filter filter = Filter::parse(spec);
        const double tolerance = 50.0 * filter.amplitude() * kOracleFlatness + 1e-10;
        for (int trial = 0; trial < 4; ++trial) {
            std::vector<Shape> shapes;
            for (int s = 0; s <= trial % 3; ++s)
                shapes.push_back(random_curved_shape(rng, 0.3 + 0.3 * s));
            const Scene scene = scene_of(40, 36, shapes, 0.1);
            const Coverage exact = exact_reference(scene, filter);
            const Coverage oracle = exact_reference(flattened(scene, kOracleFlatness), filter);
            const double diff = max_difference(exact, oracle);
            worst = std::max(worst, diff);
            EXPECT_LE(diff, tolerance) << spec << " trial " << trial;
        }
    }
    RecordProperty("worst", fmt::format("{:.3g}", worst));
}

// Inside a region that covers every filter's support the radial references are exactly the
// shape's value: the filters' masses (the strip-mass table) add up to 1.
TEST(BezierReference, RadialFiltersOfAFullCoverAreOne) {
    const Scene scene = scene_of(
        8, 8, {bezier_shape({{line({-5, -5}, {13, -5}), quad({13, -5}, {14, 4}, {13, 13}),
                              line({13, 13}, {-5, 13}), line({-5, 13}, {-5, -5})}},
                            1.0)});
    for (const char* spec : {"gaussian", "cone", "gaussian:sigma=0.7,radius=1.5"}) {
        const Coverage c = exact_reference(scene, Filter::parse(spec));
        for (double v : c.data) ASSERT_NEAR(v, 1.0, 1e-12) << spec;
    }
}

TEST(BezierReference, ExactMethodsEqualTheReferenceWithinFloatRounding) {
    std::mt19937_64 rng(5);
    const Scene scene =
        scene_of(40, 36, {random_curved_shape(rng, 0.8), random_curved_shape(rng, 0.3)}, 0.05);
    const Coverage reference = box_reference(scene);
    for (const char* spec : {"exact", "exact-8bit"}) {
        const MethodInstance m = make_method(spec);
        const Image got = render_scene(*m.method, scene);
        // float32 rounding (2^-24 relative), or the 8-bit code's half step.
        const double tolerance = std::string(spec) == "exact" ? 1e-7 : 0.5 / 255.0 + 1e-7;
        for (std::size_t k = 0; k < got.data.size(); ++k) {
            ASSERT_NEAR(got.data[k], reference.data[k], tolerance) << spec << " pixel " << k;
        }
    }
}

}  // namespace
}  // namespace aabench

namespace aabench {
namespace {

// Discs and rings beside Bezier shapes: where no pixel holds a part of both, the scene's
// reference is the background plus each shape's own contribution (the references are exact,
// and disjoint regions add). Checked for the box and the radial filters against the
// references of each shape alone, and `exact` against the box reference; where a disc and a
// curve share a pixel the box reference refuses in one line.
TEST(BezierReference, DiscsAndRingsBesideCurvesAddUpToTheirOwnReferences) {
    const Shape petal = bezier_shape(
        {{cubic({24.3, 6.2}, {36.0, 2.1}, {38.5, 14.0}, {30.2, 20.7}),
          quad({30.2, 20.7}, {22.0, 16.0}, {24.3, 6.2})}},
        0.8);
    const Shape disc = disc_shape({9.4, 9.1}, 6.3, 1.0);
    const Shape ring = ring_shape({12.2, 27.6}, 2.1, 5.4, 0.6);
    const double background = 0.1;
    const Scene scene = scene_of(40, 36, {disc, petal, ring}, background);
    for (const char* spec : {"box", "gaussian", "cone"}) {
        const Filter filter = Filter::parse(spec);
        const Coverage all = exact_reference(scene, filter);
        Coverage sum(scene.width, scene.height, background);
        for (const Shape& shape : scene.shapes) {
            const Coverage alone = exact_reference(scene_of(40, 36, {shape}, background), filter);
            for (std::size_t k = 0; k < sum.data.size(); ++k) sum.data[k] += alone.data[k] - background;
        }
        EXPECT_LE(max_difference(all, sum), kRoundingTolerance) << spec;
    }
    const Coverage reference = box_reference(scene);
    const Image got = render_scene(*make_method("exact").method, scene);
    for (std::size_t k = 0; k < reference.data.size(); ++k) {
        ASSERT_NEAR(got.data[k], reference.data[k], 1e-6) << k;  // float32 rounding
    }
    // The disc moved onto the petal: both in part in one pixel, resolved by the sweep (the
    // rows of such pixels), equal to the fine flattening's polygon reference.
    const Scene overlapping = scene_of(40, 36, {disc_shape({27.0, 10.0}, 4.0, 1.0), petal});
    EXPECT_LE(max_difference(box_reference(overlapping), box_coverage(polygon_oracle(overlapping))),
              kOracleTolerance);
}

// --- Discs and rings overlapping other shapes: their circles swept as quarter arcs ---

// The quarter arcs' closed forms against direct computation: a root's point lies on its line,
// and the area integral equals 16-point Gauss-Legendre of (x - c) y' (smooth; exact to
// rounding on a quarter circle of these sizes).
TEST(BezierReference, QuarterArcRootsAndAreaIntegrals) {
    constexpr double kGl16X[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                                  0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                                  0.9445750230732326, 0.9894009349916499};
    constexpr double kGl16W[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                                  0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                                  0.0622535239386479, 0.0271524594117541};
    std::mt19937_64 rng(1984);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const QuarterArc arc{random_point(rng, -50, 50), 0.1 + 40.0 * unit(rng),
                             static_cast<int>(rng() % 4), rng() % 2 == 0};
        const double ta = unit(rng), tb = unit(rng), c = 100.0 * unit(rng) - 50.0;
        for (int axis = 0; axis < 2; ++axis) {
            const Point p = arc_at(arc, ta);
            const double t = arc_solve(arc, axis, axis == 0 ? p.x : p.y, 0.0, 1.0);
            const Point q = arc_at(arc, t);
            // On the line, to the rounding of coordinates below ~100 px.
            EXPECT_NEAR(axis == 0 ? q.x : q.y, axis == 0 ? p.x : p.y, 1e-12) << trial;
        }
        const double m = 0.5 * (ta + tb), h = 0.5 * (tb - ta);
        double direct = 0.0;
        for (int k = 0; k < 8; ++k) {
            for (const double sign : {-1.0, 1.0}) {
                const double t = m + sign * h * kGl16X[k];
                direct += kGl16W[k] * (arc_at(arc, t).x - c) * arc_derivative(arc, t).y;
            }
        }
        direct *= h;
        EXPECT_NEAR(arc_area_integral(arc, ta, tb, c), direct, 1e-9 * (1.0 + std::abs(direct)))
            << trial;
    }
}

// A disc centred on a rectangle's edge, over it: the rectangle loses exactly half the disc,
// so the image's total is 0.5 (A_rect - pi r^2 / 2) + pi r^2, every pixel of the disc's edge
// along the rectangle's being a partial overlap of the two.
TEST(BezierReference, DiscOverARectanglesEdgeHasTheClosedFormTotal) {
    const double r = 7.3;
    const Shape rect{{{{3.25, 16.2}, {28.5, 16.2}, {28.5, 29.0}, {3.25, 29.0}}}, 0.5};
    const Scene scene = scene_of(32, 32, {rect, disc_shape({15.6, 16.2}, r, 1.0)});
    const double want =
        0.5 * ((28.5 - 3.25) * (29.0 - 16.2) - std::numbers::pi * r * r / 2.0) +
        std::numbers::pi * r * r;
    EXPECT_NEAR(total(box_reference(scene)), want, kRoundingTolerance * 32 * 32);
}

// Random discs and rings placed on the boundaries of random curved shapes and polygons (so
// that they share pixels in part), in random order, against the polygon reference of a scene
// whose circles are inscribed polygons with sagitta kOracleFlatness and whose curves are
// flattened to it: box and radial references, `exact` within float rounding of the box, and
// `exact` in bands (1 to 3 threads) the same image to the bit.
TEST(BezierReference, OverlappingDiscsAndRingsAgreeWithAFineOracle) {
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst_box = 0.0, worst_radial = 0.0;
    const MethodInstance exact = make_method("exact");
    for (int trial = 0; trial < 8; ++trial) {
        std::vector<Shape> shapes;
        shapes.push_back(random_curved_shape(rng, 0.6));
        if (trial % 2 == 1) shapes.push_back({{{{2.5, 3.1}, {30.4, 5.0}, {21.7, 33.2}}}, 0.35});
        const int circles = 1 + trial % 3;
        for (int k = 0; k < circles; ++k) {
            const Shape& on = shapes[rng() % shapes.size()];
            Point centre = on.contours.front()[rng() % on.contours.front().size()];
            centre.x += unit(rng) - 0.5;
            const double outer = 1.5 + 8.0 * unit(rng);
            const double value = 0.2 + 0.7 * unit(rng);
            const auto at = shapes.begin() + static_cast<long>(rng() % (shapes.size() + 1));
            shapes.insert(at, k % 2 == 0 ? disc_shape(centre, outer, value)
                                         : ring_shape(centre, 0.3 * outer, outer, value));
        }
        const Scene scene = scene_of(40, 36, shapes, 0.1);
        const Scene oracle = polygon_oracle(scene);
        const Coverage box = box_reference(scene);
        const double diff = max_difference(box, box_coverage(oracle));
        worst_box = std::max(worst_box, diff);
        EXPECT_LE(diff, kOracleTolerance) << "trial " << trial;
        for (const char* spec : {"gaussian", "cone"}) {
            const Filter filter = Filter::parse(spec);
            const double tolerance = 50.0 * filter.amplitude() * kOracleFlatness + 1e-10;
            const double d =
                max_difference(exact_reference(scene, filter), exact_reference(oracle, filter));
            worst_radial = std::max(worst_radial, d);
            EXPECT_LE(d, tolerance) << spec << " trial " << trial;
        }
        const Image whole = render_scene(*exact.method, scene);
        for (std::size_t k = 0; k < whole.data.size(); ++k) {
            ASSERT_NEAR(whole.data[k], box.data[k], 1e-7) << "trial " << trial << " pixel " << k;
        }
        for (int threads = 2; threads <= 3; ++threads) {
            Image banded(scene.width, scene.height);
            render_in_bands(*exact.method, scene, banded, threads);
            EXPECT_EQ(banded.data, whole.data) << "trial " << trial << ", " << threads << " threads";
        }
    }
    RecordProperty("worst_box", fmt::format("{:.3g}", worst_box));
    RecordProperty("worst_radial", fmt::format("{:.3g}", worst_radial));
}

}  // namespace
}  // namespace aabench

namespace aabench {
namespace {

// A polygon's vertical edge across a curve's interior: the edge's box is a line, which the
// crossing search once skipped as "touching" (misordering the two in the band above the
// crossing). Against the fine oracle, with the curve's crossing well inside a pixel row.
TEST(BezierReference, VerticalEdgeAcrossACurve) {
    const Shape petal = bezier_shape(
        {{cubic({4.3, 20.2}, {9.0, 2.1}, {30.5, 3.4}, {34.2, 19.7}), line({34.2, 19.7}, {4.3, 20.2})}},
        0.9);
    const Shape bar{{{{17.5, 1.3}, {21.25, 1.3}, {21.25, 27.0}, {17.5, 27.0}}}, 0.4};
    for (const auto& shapes : {std::vector<Shape>{petal, bar}, std::vector<Shape>{bar, petal}}) {
        const Scene scene = scene_of(40, 30, shapes, 0.0);
        EXPECT_LE(max_difference(box_reference(scene), box_coverage(flattened(scene, kOracleFlatness))),
                  kOracleTolerance);
    }
}

// --- Affine values on curved shapes: first moments ---

// A simple closed outline of four cubics round (cx, cy): a circle's Bezier approximation with
// its control points moved by up to `wobble` times the radius (it stays simple at 0.1, and
// convex at 0.02).
Shape wobbly_blob(std::mt19937_64& rng, Point centre, double radius, double wobble) {
    std::uniform_real_distribution<double> jitter(-wobble * radius, wobble * radius);
    constexpr double kKappa = 0.5522847498;
    const Point d[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    SegmentContour c;
    for (int q = 0; q < 4; ++q) {
        const Point u = d[q], v = d[(q + 1) % 4];
        const Point a{centre.x + radius * u.x, centre.y + radius * u.y};
        const Point b{centre.x + radius * v.x, centre.y + radius * v.y};
        const Point c1{a.x + kKappa * radius * v.x + jitter(rng), a.y + kKappa * radius * v.y + jitter(rng)};
        const Point c2{b.x + kKappa * radius * u.x + jitter(rng), b.y + kKappa * radius * u.y + jitter(rng)};
        c.push_back(cubic(a, c1, c2, b));
    }
    return bezier_shape({c}, 1.0);
}

// The integrals over the region of 1, x and y by Green's theorem on the segments' polynomials:
// the contour integrals of x dy, x^2 / 2 dy and x y dy (degree <= 8 along a cubic, so 8-point
// Gauss-Legendre on [0, 1] is exact to rounding), signed by the orientation.
std::array<double, 3> green_moments(const Shape& shape) {
    constexpr double kX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                              0.9602898564975363};
    constexpr double kW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                              0.1012285362903763};
    std::array<double, 3> m{0.0, 0.0, 0.0};
    for (const SegmentContour& contour : shape.outline) {
        for (const Segment& s : contour) {
            for (int k = 0; k < 4; ++k) {
                for (const double sign : {-1.0, 1.0}) {
                    const double t = 0.5 + 0.5 * sign * kX[k];
                    const Point b = bezier_at(s, t);
                    const double dy = 0.5 * kW[k] * bezier_derivative(s, t).y;
                    m[0] += b.x * dy;
                    m[1] += 0.5 * b.x * b.x * dy;
                    m[2] += b.x * b.y * dy;
                }
            }
        }
    }
    if (m[0] < 0.0) {
        for (double& v : m) v = -v;
    }
    return m;
}

// An affine value on one curved region inside the window: the image's total is the integral
// of the plane over the region (c A + gx Mx + gy My) plus the background over the rest.
TEST(BezierReference, AffineValuesIntegrateToTheRegionsMoments) {
    std::mt19937_64 rng(2011);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 20; ++trial) {
        Shape blob = wobbly_blob(rng, {20.0 + 8.0 * unit(rng), 18.0 + 6.0 * unit(rng)},
                                 4.0 + 8.0 * unit(rng), 0.1);
        const AffinePlane plane{0.2 + 0.6 * unit(rng), 0.04 * unit(rng) - 0.02,
                                0.04 * unit(rng) - 0.02};
        blob.value_plane = plane;
        const double background = 0.1;
        const Scene scene = scene_of(48, 40, {blob}, background);
        const auto [area, mx, my] = green_moments(blob);
        const double want = plane.c * area + plane.gx * mx + plane.gy * my +
                            background * (48.0 * 40.0 - area);
        EXPECT_NEAR(total(box_reference(scene)), want, kRoundingTolerance * 48 * 40) << trial;
    }
}

// Overlapping curved shapes with affine values against the exact reference of their fine
// flattening (the visible pieces' areas and first moments, which needs convex pieces of one
// contour: convex blobs here; loops and several contours have constant values elsewhere in
// this file, and the jumps are the same code): a pixel moves by at most the deviation times
// the boundary inside it (< 50 px) times the largest jump (< 3 here: values within
// [-0.6, 1.6]), and
// `exact` equals the reference within float rounding.
// Exact visibility's pieces grow with the vertices faster than linearly: this oracle flattens
// at 1e-6 px (a few thousand points per shape), not kOracleFlatness (10^5 and minutes).
constexpr double kPieceOracleFlatness = 1e-6;

TEST(BezierReference, AffineValuesAgreeWithTheFlatteningsPieceReference) {
    std::mt19937_64 rng(1990);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst = 0.0;
    const MethodInstance exact = make_method("exact");
    for (int trial = 0; trial < 8; ++trial) {
        std::vector<Shape> shapes;
        for (int s = 0; s <= 1 + trial % 3; ++s) {
            Shape shape = wobbly_blob(rng, random_point(rng, 8, 40), 3.0 + 12.0 * unit(rng), 0.0);
            shape.value = 0.5;
            if (s != 1) {
                shape.value_plane = AffinePlane{0.2 + 0.6 * unit(rng), 0.03 * unit(rng) - 0.015,
                                                0.03 * unit(rng) - 0.015};
            }
            shapes.push_back(shape);
        }
        const Scene scene = scene_of(48, 40, shapes, 0.1);
        const Coverage got = box_reference(scene);
        const double diff =
            max_difference(got, box_reference(flattened(scene, kPieceOracleFlatness)));
        worst = std::max(worst, diff);
        EXPECT_LE(diff, 3.0 * 50.0 * kPieceOracleFlatness + kRoundingTolerance) << "trial " << trial;
        const Image image = render_scene(*exact.method, scene);
        for (std::size_t k = 0; k < image.data.size(); ++k) {
            ASSERT_NEAR(image.data[k], got.data[k], 2e-7) << "trial " << trial << " pixel " << k;
        }
    }
    RecordProperty("worst", fmt::format("{:.3g}", worst));
}

}  // namespace
}  // namespace aabench
