// The optional peer `blend2d` (methods/blend2d.cpp) against the exact box image. Its row exists
// only in a build configured with -DAABENCH_BLEND2D_DIR (docs/peers.md); in every other build
// (the default one, CI) each test here is skipped, not passed.
//
// What is held: whole pixels exact with their values, straight edges within Blend2D's grid of
// the exact reference (its cells accumulate areas on a 1/256 px grid and hand back a byte),
// the built-in 2-D patterns close to `exact`'s image (so the benchmark's `exact` / `blend2d`
// ratio compares two renders of the same picture), and no allocation in a warm render.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "harness/measure/metrics.h"
#include "harness/reference/box_reference.h"
#include "harness/world/alloc_count.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "test_scenes.h"

namespace aabench {
namespace {

// One 8-bit coverage step: Blend2D hands back coverage as a byte of an A8 image.
constexpr double kByteStep = 1.0 / 255.0;
// On one straight edge: the byte is the cell's area rounded (half a step), and the vertices
// and the points where the edge crosses pixel rows and columns are positions on Blend2D's
// 1/256 px grid (each moves the edge across a pixel by at most 1/256 px): AGG's bound, the same
// grid (tests/peers_test.cpp). Measured: 2.2 steps at most on the 1,200 scenes below.
constexpr double kEdgeTolerance = kByteStep + 3.0 / 256.0;
// The built-in 2-D patterns at 128^2 against `exact`: RMSE and largest pixel difference.
// Measured largest (Blend2D 0.21.2): rmse 0.0022 (rings), max 0.0086 (rings; 2.2 byte steps,
// as on straight edges: one fill per run of one value, so no pixel is composited twice).
// Bounds: the measured worst plus about half again.
constexpr double kPatternRmseBound = 0.0035;
constexpr double kPatternMaxBound = 0.013;
constexpr int kPatternSide = 128;
const char* const kPatterns2d[] = {"star",      "strips",  "grating",     "rings",
                                   "zoneplate", "circles", "circle-radii"};

bool blend2d_built() {
    const auto& rows = method_registry();
    return std::any_of(rows.begin(), rows.end(),
                       [](const MethodInfo& row) { return row.id == "blend2d"; });
}

#define SKIP_WITHOUT_BLEND2D()                              \
    if (!blend2d_built())                                   \
    GTEST_SKIP() << "blend2d is not built (configure with " \
                    "-DAABENCH_BLEND2D_DIR, docs/peers.md)"

Shape rectangle(double x0, double y0, double x1, double y1, double value) {
    return {{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}, value};
}

// A convex polygon (points on a circle at sorted random angles), either orientation.
Scene random_convex(std::uint64_t seed, int width, int height, bool clockwise) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> cx(0.0, width), cy(0.0, height),
        radius(1.0, width / 2.0), angle(0.0, 2.0 * std::numbers::pi);
    std::vector<double> angles(3 + rng() % 8);
    for (double& a : angles) a = angle(rng);
    std::sort(angles.begin(), angles.end());
    const double x = cx(rng), y = cy(rng), r = radius(rng);
    Contour c;
    for (double a : angles) c.push_back({x + r * std::cos(a), y + r * std::sin(a)});
    if (clockwise) std::reverse(c.begin(), c.end());
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.shapes.push_back({{c}, 1.0});
    return scene;
}

TEST(Blend2dPeer, PixelAlignedSquaresAreExactWithTheirValues) {
    SKIP_WITHOUT_BLEND2D();
    Scene scene;
    scene.width = 12;
    scene.height = 10;
    scene.background = 0.2;
    scene.shapes.push_back(rectangle(3, 2, 9, 7, 0.7));
    scene.shapes.push_back(rectangle(5, 4, 11, 9, 0.45));
    const Image out = render_scene(*make_method("blend2d").method, scene);
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const bool in_second = i >= 5 && i < 11 && j >= 4 && j < 9;
            const bool in_first = i >= 3 && i < 9 && j >= 2 && j < 7;
            const float want = in_second ? 0.45f : in_first ? 0.7f : 0.2f;
            ASSERT_EQ(out.at(i, j), want) << fmt::format("pixel ({}, {})", i, j);
        }
    }
}

TEST(Blend2dPeer, WithinItsGridOfExactOnStraightEdges) {
    SKIP_WITHOUT_BLEND2D();
    const MethodInstance m = make_method("blend2d");
    double worst = 0.0;
    std::string where;
    auto track = [&](const Scene& scene, const std::string& what) {
        const Image out = render_scene(*m.method, scene);
        const Coverage exact = box_reference(scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const double err = std::abs(out.at(i, j) - exact.at(i, j));
                if (!(err <= worst)) {  // written so that NaN is reported
                    worst = err;
                    where = fmt::format("{} pixel ({}, {})", what, i, j);
                }
            }
        }
    };
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        track(testing::random_half_plane(seed, 32, 24, 640.0), fmt::format("half-plane {}", seed));
        track(testing::random_half_plane(seed, 32, 24, 1e8),
              fmt::format("far half-plane {}", seed));
        for (bool clockwise : {false, true}) {
            track(random_convex(seed, 32, 24, clockwise),
                  fmt::format("convex {} clockwise {}", seed, clockwise));
        }
    }
    EXPECT_TRUE(worst <= kEdgeTolerance) << fmt::format(
        "{}: {} steps (bound {})", where, worst / kByteStep, kEdgeTolerance / kByteStep);
}

TEST(Blend2dPeer, BuiltInPatternsCloseToExact) {
    SKIP_WITHOUT_BLEND2D();
    const MethodInstance blend2d = make_method("blend2d");
    const MethodInstance exact = make_method("exact");
    for (const char* pattern : kPatterns2d) {
        const Scene scene = make_pattern(pattern, kPatternSide, kPatternSide);
        const Image want = render_scene(*exact.method, scene);
        Coverage reference(scene.width, scene.height);
        for (std::size_t k = 0; k < want.data.size(); ++k) reference.data[k] = want.data[k];
        const ErrorStats stats =
            compare_to_reference(render_scene(*blend2d.method, scene), reference);
        EXPECT_TRUE(stats.rmse <= kPatternRmseBound)
            << fmt::format("{}: rmse {} (bound {})", pattern, stats.rmse, kPatternRmseBound);
        EXPECT_TRUE(stats.max_abs <= kPatternMaxBound)
            << fmt::format("{}: max {} at ({}, {}) (bound {})", pattern, stats.max_abs, stats.max_x,
                           stats.max_y, kPatternMaxBound);
    }
}

// The curve patterns go in as Blend2D's quad_to / cubic_to and are flattened by Blend2D:
// its flattening adds to the grid's error on every curved edge, as AGG's and FreeType's do.
// Measured at 128^2 against the exact box image (Blend2D 0.21.2): rmse 0.0201 and max 0.180
// (curves), 0.0122 and 0.112 (text), 0.0025 and 0.039 (crescents); `agg` on the same: 0.0129
// and 0.127, 0.0092 and 0.105, 0.0089 and 0.161. Bounds: the measured worst plus half again.
const char* const kCurvePatterns[] = {"curves", "crescents", "text"};
constexpr double kCurveRmseBound = 0.03;
constexpr double kCurveMaxBound = 0.27;

TEST(Blend2dPeer, CurvePatternsFedAsCurvesCloseToExact) {
    SKIP_WITHOUT_BLEND2D();
    const MethodInstance blend2d = make_method("blend2d");
    for (const char* pattern : kCurvePatterns) {
        const Scene scene = make_pattern(pattern, kPatternSide, kPatternSide);
        const ErrorStats stats =
            compare_to_reference(render_scene(*blend2d.method, scene), box_reference(scene));
        EXPECT_TRUE(stats.rmse <= kCurveRmseBound)
            << fmt::format("{}: rmse {} (bound {})", pattern, stats.rmse, kCurveRmseBound);
        EXPECT_TRUE(stats.max_abs <= kCurveMaxBound)
            << fmt::format("{}: max {} at ({}, {}) (bound {})", pattern, stats.max_abs, stats.max_x,
                           stats.max_y, kCurveMaxBound);
    }
}

TEST(Blend2dPeer, WarmRenderAllocatesNothing) {
    SKIP_WITHOUT_BLEND2D();
    const MethodInstance m = make_method("blend2d");
    std::vector<const char*> patterns(std::begin(kPatterns2d), std::end(kPatterns2d));
    patterns.insert(patterns.end(), std::begin(kCurvePatterns), std::end(kCurvePatterns));
    for (const char* pattern : patterns) {
        const Scene scene = make_pattern(pattern, 256, 256);
        Image out(scene.width, scene.height);
        m.method->render(scene, out);  // warm-up: the per-thread target and path grow here
        const AllocCounts before = thread_alloc_counts();
        m.method->render(scene, out);
        const std::uint64_t count = thread_alloc_counts().allocations - before.allocations;
        EXPECT_EQ(count, 0u) << pattern;
    }
}

}  // namespace
}  // namespace aabench
