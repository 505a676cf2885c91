// The fast exact engine (methods/scan/exact/fast_coverage.cpp, behind `exact` and `exact-8bit`)
// against the double box engine (methods/scan/reference/box_coverage.cpp, the slow check) on seeded
// random scenes and on every hard case; bands and threads against the whole image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "harness/measure/hardcases.h"
#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "methods/scan/exact/fast_coverage.h"
#include "methods/scan/reference/box_coverage.h"
#include "patterns/pattern.h"
#include "test_scenes.h"

namespace aabench {
namespace {

// The engine's bound (docs/architecture.md): float32 output within 1e-6 of the double reference.
// Values here lie in [0, 1], where float32 rounding is <= 2^-25 = 3e-8, and the double accumulation
// adds ~1e-13; the bound is what the engine promises, with room for the certificate's slivers
// (fast_coverage.cpp: a crossing missed by rounding moves ~1e-16 px^2).
constexpr double kExactTolerance = 1e-6;
// Hard cases carry values up to 4 and coordinates at 2^30: float32 rounding of a value v is
// <= 2^-24 |v|, so the bound scales with the largest |value| when that exceeds 1.
double hard_case_tolerance(const Scene& scene) {
    const auto [lo, hi] = scene.value_range();
    return kExactTolerance * std::max({1.0, std::abs(lo), std::abs(hi)});
}

constexpr int kRandomScenes = 1200;   // general scenes: crossings, overlaps, self-intersections
constexpr int kNestedScenes = 600;    // crossing-free scenes: the certificate's fast path

// Worst |fast - reference| over the image; on failure, the seed, the pixel and both values.
double compare_images(const Image& fast, const Coverage& ref, const Scene& scene,
                      const std::string& what, double tolerance) {
    double worst = 0.0;
    for (int j = 0; j < ref.height; ++j) {
        for (int i = 0; i < ref.width; ++i) {
            const double d = std::abs(fast.at(i, j) - ref.at(i, j));
            // Written so that NaN fails.
            if (!(d <= tolerance)) {
                ADD_FAILURE() << fmt::format("{} pixel ({}, {}): fast {:.9g} reference {:.17g}\n",
                                             what, i, j, fast.at(i, j), ref.at(i, j))
                              << testing::describe(scene);
                return d;
            }
            worst = std::max(worst, d);
        }
    }
    return worst;
}

// Star-shaped (concave) polygons around a few centres, nested at disjoint radii so that no
// two contours cross; orientations random (so some holes cancel and some double the winding
// number), values random per shape, some reaching past the image. Crossing-free: the fast path
// must take every row.
Scene nested_scene(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Scene scene;
    scene.width = 8 + static_cast<int>(rng() % 40);
    scene.height = 8 + static_cast<int>(rng() % 40);
    scene.background = u(rng);
    const int clusters = 1 + static_cast<int>(rng() % 3);
    // Clusters side by side in x so that their discs never meet.
    const double slot = (scene.width + 8.0) / clusters;
    for (int c = 0; c < clusters; ++c) {
        const double radius_max = 0.5 * slot * 0.95;
        const double cx = -4.0 + slot * (c + 0.5);
        const double cy = -4.0 + (scene.height + 8.0) * u(rng);
        const int rings = 1 + static_cast<int>(rng() % 4);
        // Radii bands [k w, (k + 1) w) disjoint; a contour's vertices wobble within 30-70 % of
        // its band. An edge dips inside its vertices' radii by at most the factor cos(pi / n):
        // with n >= 6 and k <= 3, (k + 0.3) cos(pi / 6) > k - 0.3, so the edges of
        // neighbouring contours stay apart too.
        for (int k = 0; k < rings; ++k) {
            const double band_lo = radius_max * k / rings, band_hi = radius_max * (k + 1) / rings;
            const int vertices = 6 + static_cast<int>(rng() % 40);
            const double phase = 2.0 * std::numbers::pi * u(rng);
            Contour contour;
            for (int v = 0; v < vertices; ++v) {
                const double a = phase + 2.0 * std::numbers::pi * v / vertices;
                const double r = band_lo + (band_hi - band_lo) * (0.3 + 0.4 * u(rng));
                contour.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
            }
            if (rng() % 2) std::reverse(contour.begin(), contour.end());
            // Either a shape of its own or a hole/extra contour of the previous shape.
            if (scene.shapes.empty() || rng() % 2) {
                scene.shapes.push_back({{contour}, u(rng)});
            } else {
                scene.shapes.back().contours.push_back(contour);
            }
        }
    }
    return scene;
}

TEST(FastCoverage, MatchesTheBoxEngineOnRandomScenes) {
    double worst = 0.0;
    FastCoverageStats stats;
    for (std::uint64_t seed = 1; seed <= kRandomScenes; ++seed) {
        const int w = 6 + static_cast<int>(seed % 23), h = 5 + static_cast<int>(seed % 17);
        const Scene scene = testing::random_scene(seed, w, h, seed % 3 == 0);
        Image fast(w, h, -1.0f);
        fast_coverage(scene, fast, &stats);
        worst = std::max(worst, compare_images(fast, box_coverage(scene), scene,
                                               fmt::format("random seed {}", seed),
                                               kExactTolerance));
        if (HasFailure()) return;
    }
    // Both paths must have been exercised, or the test proves less than it says.
    EXPECT_GT(stats.sub_bands, 0);
    EXPECT_GT(stats.fallback_rows, 0);
    RecordProperty("worst", fmt::format("{:.3g}", worst));
    std::printf("random: %d scenes, worst |fast - box| = %.3g; rows %lld, fallback %lld\n",
                kRandomScenes, worst, static_cast<long long>(stats.rows),
                static_cast<long long>(stats.fallback_rows));
}

TEST(FastCoverage, CrossingFreeScenesTakeTheFastPathExactly) {
    double worst = 0.0;
    for (std::uint64_t seed = 1; seed <= kNestedScenes; ++seed) {
        const Scene scene = nested_scene(seed);
        Image fast(scene.width, scene.height, -1.0f);
        FastCoverageStats stats;
        fast_coverage(scene, fast, &stats);
        worst = std::max(worst, compare_images(fast, box_coverage(scene), scene,
                                               fmt::format("nested seed {}", seed),
                                               kExactTolerance));
        if (HasFailure()) return;
        ASSERT_EQ(stats.fallback_rows, 0) << "nested seed " << seed << " has no crossing\n"
                                          << testing::describe(scene);
    }
    std::printf("nested: %d scenes, worst |fast - box| = %.3g\n", kNestedScenes, worst);
}

TEST(FastCoverage, HugeWindowOriginsMatchTheBoxEngine) {
    for (const double origin : {std::ldexp(1.0, 20), std::ldexp(1.0, 30), -std::ldexp(1.0, 30)}) {
        for (std::uint64_t seed = 1; seed <= 100; ++seed) {
            Scene scene = seed % 2 ? nested_scene(seed) : testing::random_scene(seed, 17, 13, false);
            for (Shape& s : scene.shapes) {
                for (Contour& c : s.contours) {
                    for (Point& p : c) p = {p.x + origin, p.y - origin};
                }
            }
            scene.origin_x = origin;
            scene.origin_y = -origin;
            scene = window_scene(std::move(scene));
            Image fast(scene.width, scene.height, -1.0f);
            fast_coverage(scene, fast);
            compare_images(fast, box_coverage(scene), scene,
                           fmt::format("origin {} seed {}", origin, seed), kExactTolerance);
            if (HasFailure()) return;
        }
    }
}

TEST(FastCoverage, EveryHardCaseMatchesTheBoxReference) {
    const MethodInstance exact = make_method("exact");
    for (const HardCase& hc : hard_cases()) {
        const Scene scene = window_scene(hc.make().scene);
        if (!scene.world && !has_planes(scene)) {
            const Image image = render_scene(*exact.method, scene);
            compare_images(image, box_reference(scene), scene, "hard case " + hc.name,
                           hard_case_tolerance(scene));
        }
        if (HasFailure()) return;
    }
}

// The visible pieces of the 3-D patterns: many convex pieces sharing edges split at different
// vertices (T-junctions), the case the order certificate's slack is for.
TEST(FastCoverage, PiecesOfThe3DPatternsMatchTheBoxEngine) {
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        // The circle patterns' polygonisations (~7000 sqrt(r) vertices per ring) are edge-heavy
        // chains for the fast engine; small radii keep the double engine's check affordable.
        const std::string spec = p.id == "circles"        ? "circles:max_radius=8"
                                 : p.id == "circle-radii" ? "circle-radii:max_radius=13"
                                                          : p.id;
        for (const int side : {64, 200}) {
            const Scene scene = PreparedFrame::prepare(make_pattern(spec, side, side)).pieces().scene();
            Image fast(scene.width, scene.height, -1.0f);
            fast_coverage(scene, fast);
            compare_images(fast, box_coverage(scene), scene,
                           fmt::format("pattern {} at {}", p.id, side), hard_case_tolerance(scene));
            if (HasFailure()) return;
        }
    }
}

TEST(FastCoverage, BandsAndThreadsGiveTheWholeImage) {
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        const Scene scene = seed % 2 ? nested_scene(seed) : testing::random_scene(seed, 31, 29, true);
        Image whole(scene.width, scene.height, -1.0f);
        fast_coverage(scene, whole);
        // Bands of 1..5 rows, in an odd order: each band touches only its rows.
        Image banded(scene.width, scene.height, -1.0f);
        const int step = 1 + static_cast<int>(seed % 5);
        for (int lo = (scene.height - 1) / step * step; lo >= 0; lo -= step) {
            fast_coverage_rows(scene, banded, lo, lo + step);
        }
        compare_images(banded, box_coverage(scene), scene, fmt::format("bands seed {}", seed),
                       kExactTolerance);
        for (const char* spec : {"exact", "exact-8bit"}) {
            const MethodInstance m = make_method(spec);
            const Image one = render_scene(*m.method, scene);
            Image four(scene.width, scene.height, -1.0f);
            render_in_bands(*m.method, scene, four, 2);
            ASSERT_EQ(one.data, four.data) << spec << " seed " << seed;
        }
        if (HasFailure()) return;
    }
}

}  // namespace
}  // namespace aabench
