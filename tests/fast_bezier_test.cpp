// The fast exact Bezier engine (methods/scan/exact/fast_bezier.h) against the band sweep it
// replaces (methods/scan/reference/bezier_coverage.h, tested on its own against independent
// oracles in bezier_reference_test.cpp): on seeded random curved scenes that do not cross
// (which the fast path must draw itself) and that do (which it must hand to the band sweep
// row by row), on the curve patterns, in bands, and warm without allocation.
#include "methods/scan/exact/fast_bezier.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "harness/world/alloc_count.h"
#include "methods/scan/reference/bezier_coverage.h"
#include "patterns/pattern.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// The two engines integrate the same pieces with the same quadrature and root finder, cut at
// different heights (the fast one at row borders and chain ends only, the sweep also at every
// piece's end): their doubles differ by rounding (~1e-14 at these sizes), and the fast engine
// rounds once to float32 (2^-24 relative, 6e-8 for values up to 1).
constexpr double kFloatTolerance = 1e-7;

Point random_point(std::mt19937_64& rng, double lo, double hi) {
    std::uniform_real_distribution<double> u(lo, hi);
    return {u(rng), u(rng)};
}

// A star-shaped closed curve about `centre`: n >= 5 points at angles 72 degrees apart at
// most 94 (jittered by 30% of the step) and radii in [r/2, r], joined by lines, or quadratics
// and cubics bulging out from the chord by at most a fifth of its length: every chord is at
// least r/2 cos 47 = 0.34 r from the centre, so the curve is simple and lies within 1.13 r.
SegmentContour blob(std::mt19937_64& rng, Point centre, double r) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 5 + static_cast<int>(rng() % 5);
    std::vector<Point> points;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * std::numbers::pi * (k + 0.3 * u(rng)) / n;
        const double radius = r * (0.5 + 0.5 * u(rng));
        points.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
    }
    SegmentContour c;
    for (int k = 0; k < n; ++k) {
        const Point a = points[k], b = points[(k + 1) % n];
        // Controls pushed out from the chord by up to a fifth of its length, towards the outside.
        const Point mid{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
        const Point out{mid.x - centre.x, mid.y - centre.y};
        const double len = std::hypot(out.x, out.y);
        const double push = 0.2 * std::hypot(b.x - a.x, b.y - a.y) * u(rng);
        const Point bulge{mid.x + out.x / len * push, mid.y + out.y / len * push};
        switch (rng() % 3) {
            case 0:
                c.push_back(line_segment(a, b));
                break;
            case 1:
                c.push_back(quad_segment(a, bulge, b));
                break;
            default: {
                const Point c1{(2.0 * a.x + bulge.x) / 3.0 + 0.1 * push * (u(rng) - 0.5),
                               (2.0 * a.y + bulge.y) / 3.0};
                const Point c2{(2.0 * b.x + bulge.x) / 3.0, (2.0 * b.y + bulge.y) / 3.0};
                c.push_back(cubic_segment(a, c1, c2, b));
            }
        }
    }
    return c;
}

// A box with rounded corners (quadratics) and a notch in its top side: horizontal lines at
// heights off the pixel grid, where one chain ends and the next begins beside it, within
// `half` of `centre`.
SegmentContour notched_box(std::mt19937_64& rng, Point centre, double half) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double w = half * (0.6 + 0.4 * u(rng)), h = half * (0.6 + 0.4 * u(rng));
    const double r = std::min(w, h) * 0.3 * u(rng), notch = 0.5 * h * u(rng);
    const double x0 = centre.x - w, x1 = centre.x + w, y0 = centre.y - h, y1 = centre.y + h;
    const double n0 = centre.x - 0.3 * w, n1 = centre.x + 0.3 * w;
    std::vector<Point> p = {{x0 + r, y0},     {n0, y0}, {n0, y0 + notch},
                            {n1, y0 + notch}, {n1, y0}, {x1 - r, y0}};
    SegmentContour c;
    for (std::size_t k = 0; k + 1 < p.size(); ++k) c.push_back(line_segment(p[k], p[k + 1]));
    c.push_back(quad_segment({x1 - r, y0}, {x1, y0}, {x1, y0 + r}));
    c.push_back(line_segment({x1, y0 + r}, {x1, y1 - r}));
    c.push_back(quad_segment({x1, y1 - r}, {x1, y1}, {x1 - r, y1}));
    c.push_back(line_segment({x1 - r, y1}, {x0 + r, y1}));
    c.push_back(quad_segment({x0 + r, y1}, {x0, y1}, {x0, y1 - r}));
    c.push_back(line_segment({x0, y1 - r}, {x0, y0 + r}));
    c.push_back(quad_segment({x0, y0 + r}, {x0, y0}, {x0 + r, y0}));
    return c;
}

// Blobs on a grid of cells, one per cell and inside it (r = 0.35 cell: within 0.4 cell of its
// centre, no two touch), some with a hole (r = 0.1 cell, within 0.113 cell: inside every
// chord of the outer curve, 0.119 cell from the centre), run the other way round, values in
// [0.2, 1]; or a notched box (within 0.4 cell); a scene with no crossing.
Scene disjoint_blobs(std::uint64_t seed, int width, int height) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.background = 0.1 * u(rng);
    const double cell = 6.0 + 14.0 * u(rng);
    for (double y = -0.5 * cell; y < height + cell; y += cell) {
        for (double x = -0.5 * cell; x < width + cell; x += cell) {
            if (u(rng) < 0.3) continue;
            const Point centre{x + 0.5 * cell, y + 0.5 * cell};
            if (u(rng) < 0.3) {
                scene.shapes.push_back(
                    bezier_shape({notched_box(rng, centre, 0.4 * cell)}, 0.2 + 0.8 * u(rng)));
                continue;
            }
            std::vector<SegmentContour> outline{blob(rng, centre, 0.35 * cell)};
            if (u(rng) < 0.4) {
                SegmentContour hole = blob(rng, centre, 0.1 * cell);
                SegmentContour reversed;
                for (auto it = hole.rbegin(); it != hole.rend(); ++it) {
                    Segment s = *it;
                    std::reverse(s.p.begin(), s.p.begin() + s.degree + 1);
                    reversed.push_back(s);
                }
                outline.push_back(reversed);
            }
            scene.shapes.push_back(bezier_shape(outline, 0.2 + 0.8 * u(rng)));
        }
    }
    return scene;
}

// Blobs anywhere, overlapping each other: many rows cross.
Scene overlapping_blobs(std::uint64_t seed, int width, int height) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.background = 0.05;
    const int count = 2 + static_cast<int>(rng() % 6);
    for (int k = 0; k < count; ++k) {
        const Point centre = random_point(rng, -5.0, width + 5.0);
        scene.shapes.push_back(
            bezier_shape({blob(rng, centre, 4.0 + 20.0 * u(rng))}, 0.2 + 0.8 * u(rng)));
    }
    // A polygon beside the curves, across them.
    scene.shapes.push_back(
        {{{{-3.0, 0.3 * height}, {width + 2.5, 0.45 * height}, {0.6 * width, 0.9 * height}}}, 0.6});
    return scene;
}

Image fast_image(const Scene& scene, FastBezierStats* stats = nullptr) {
    Image out(scene.width, scene.height);
    fast_bezier_rows(scene, out, 0, scene.height, stats);
    return out;
}

void expect_near_sweep(const Scene& scene, const Image& got, const std::string& what) {
    const Coverage want = bezier_box_coverage(scene);
    double worst = 0.0;
    std::size_t at = 0;
    for (std::size_t k = 0; k < got.data.size(); ++k) {
        const double d = std::abs(got.data[k] - want.data[k]);
        if (!(d <= worst)) {
            worst = d;
            at = k;
        }
    }
    EXPECT_LE(worst, kFloatTolerance)
        << what << ": pixel (" << at % scene.width << ", " << at / scene.width << ")";
}

TEST(FastBezier, DisjointCurvedShapesAreDrawnByTheFastPathAndEqualTheSweep) {
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const Scene scene = disjoint_blobs(seed, 61 + static_cast<int>(seed % 7), 47);
        ASSERT_TRUE(fast_bezier_draws(scene));
        FastBezierStats stats;
        const Image got = fast_image(scene, &stats);
        expect_near_sweep(scene, got, fmt::format("seed {}", seed));
        EXPECT_EQ(stats.rows, scene.height);
        // No two boundaries cross or touch: every row is proven, none falls back.
        EXPECT_EQ(stats.fallback_rows, 0) << "seed " << seed;
    }
}

TEST(FastBezier, CrossingShapesFallBackRowByRowAndEqualTheSweep) {
    std::int64_t fallback = 0, rows = 0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const Scene scene = overlapping_blobs(seed, 53, 41);
        FastBezierStats stats;
        const Image got = fast_image(scene, &stats);
        expect_near_sweep(scene, got, fmt::format("seed {}", seed));
        fallback += stats.fallback_rows;
        rows += stats.rows;
    }
    // The crossings send rows to the band sweep, and only those: some rows, not all.
    EXPECT_GT(fallback, 0);
    EXPECT_LT(fallback, rows);
}

TEST(FastBezier, CurvePatternsEqualTheSweep) {
    for (const char* pattern : {"curves", "crescents", "text"}) {
        const Scene scene = make_pattern(pattern, 96, 80);
        ASSERT_TRUE(fast_bezier_draws(scene)) << pattern;
        FastBezierStats stats;
        const Image got = fast_image(scene, &stats);
        expect_near_sweep(scene, got, pattern);
        RecordProperty(fmt::format("{}_fallback_rows", pattern),
                       std::to_string(stats.fallback_rows));
    }
}

TEST(FastBezier, BandsGiveTheImageOfOneCall) {
    for (const char* pattern : {"curves", "text"}) {
        const Scene scene = make_pattern(pattern, 90, 77);
        const Image whole = fast_image(scene);
        Image banded(scene.width, scene.height);
        for (int lo = 0; lo < scene.height; lo += 13) {
            fast_bezier_rows(scene, banded, lo, std::min(lo + 13, scene.height));
        }
        ASSERT_EQ(whole.data, banded.data) << pattern;
    }
}

TEST(FastBezier, AWarmRenderWithoutFallbackAllocatesNothing) {
    const Scene scene = disjoint_blobs(7, 128, 96);
    Image out(scene.width, scene.height);
    FastBezierStats stats;
    fast_bezier_rows(scene, out, 0, scene.height, &stats);
    ASSERT_EQ(stats.fallback_rows, 0);
    const AllocCounts before = thread_alloc_counts();
    fast_bezier_rows(scene, out, 0, scene.height);
    EXPECT_EQ(thread_alloc_counts().allocations - before.allocations, 0u);
}

}  // namespace
}  // namespace aabench
