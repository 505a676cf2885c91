// The exact box reference of regions bounded by Bezier segments (bezier_coverage.h) against
// independent computations: Archimedes' rule for parabolic segments, the closed-form area of
// closed cubic paths (power-basis polynomials integrated here), the polygon reference on a
// flattening whose deviation bound is proven (patterns/scene/bezier.h), a brute-force winding
// count at random points, and `exact` against the reference.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "harness/reference/box_reference.h"
#include "harness/reference/filter_reference.h"
#include "methods/method.h"
#include "methods/scan/reference/bezier_coverage.h"
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
    // The disc moved onto the petal: both in part in one pixel, refused, not guessed.
    const Scene overlapping = scene_of(40, 36, {disc_shape({27.0, 10.0}, 4.0, 1.0), petal});
    try {
        box_reference(overlapping);
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("shapes 0 and 1"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace aabench
