// The exact box reference against the slow per-pixel clipping reference on seeded random
// scenes, and against known answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "harness/reference/box_reference.h"
#include "methods/scan/kernel/edge_table.h"
#include "slow_reference.h"

namespace aabench {
namespace {

// docs/architecture.md promises <= 1e-12 per pixel; both sides compute in double with O(10)
// roundings of O(1) quantities per pixel, far below this.
constexpr double kExactTolerance = 1e-12;
// Area sums: the row prefix sums add up to ~100 terms per row, each rounded at 1e-16
// relative; 1e-11 absolute over a whole image of area <= 400 is still tight.
constexpr double kAreaSumTolerance = 1e-10;

Contour random_contour(std::mt19937_64& rng, double lo, double hi, int vertices) {
    std::uniform_real_distribution<double> coord(lo, hi);
    Contour c;
    for (int k = 0; k < vertices; ++k) c.push_back({coord(rng), coord(rng)});
    return c;
}

// Concave, self-intersecting, with holes (reversed contours), overlapping, partly outside.
Scene random_scene(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    Scene scene;
    scene.width = 7 + static_cast<int>(rng() % 6);
    scene.height = 5 + static_cast<int>(rng() % 6);
    scene.background = std::uniform_real_distribution<double>(0.0, 0.3)(rng);
    const int shapes = 1 + static_cast<int>(rng() % 4);
    for (int s = 0; s < shapes; ++s) {
        Shape shape;
        shape.value = std::uniform_real_distribution<double>(0.0, 1.0)(rng);
        const int contours = 1 + static_cast<int>(rng() % 3);
        for (int c = 0; c < contours; ++c) {
            Contour contour = random_contour(rng, -3.0, 14.0, 3 + static_cast<int>(rng() % 7));
            if (rng() % 2) std::reverse(contour.begin(), contour.end());
            shape.contours.push_back(contour);
        }
        scene.shapes.push_back(shape);
    }
    return scene;
}

TEST(BoxReference, MatchesSlowClippingReferenceOnRandomScenes) {
    constexpr int kScenes = 300;
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = random_scene(seed);
        const Coverage fast = box_reference(scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const double slow = testing::slow_box_pixel(scene, i, j);
                const double got = fast.at(i, j);
                ASSERT_TRUE(std::abs(got - slow) <= kExactTolerance)
                    << fmt::format("seed {} pixel ({}, {}): fast {:.17g} slow {:.17g}", seed, i,
                                   j, got, slow);
            }
        }
    }
}

// Many-vertex contours (wobbly rings around random centres), overlapping and crossing each
// other, with holes: long y-monotone chains of short edges that cross other chains between
// their vertices, the case the band sweep's chain handling exists for.
Scene wobbly_scene(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Scene scene;
    scene.width = 12;
    scene.height = 10;
    const int shapes = 1 + static_cast<int>(rng() % 3);
    for (int s = 0; s < shapes; ++s) {
        Shape shape;
        shape.value = 0.2 + 0.8 * unit(rng);
        const double cx = -1.0 + 14.0 * unit(rng), cy = -1.0 + 12.0 * unit(rng);
        const int contours = 1 + static_cast<int>(rng() % 2);
        for (int c = 0; c < contours; ++c) {
            const int n = 12 + static_cast<int>(rng() % 60);
            const double base = (c == 0 ? 3.0 : 1.5) + 2.0 * unit(rng);
            Contour contour;
            for (int k = 0; k < n; ++k) {
                const double a = 2.0 * std::numbers::pi * k / n;
                const double r = base * (0.8 + 0.4 * unit(rng));
                contour.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
            }
            if (c == 1) std::reverse(contour.begin(), contour.end());  // a hole
            shape.contours.push_back(contour);
        }
        scene.shapes.push_back(shape);
    }
    return scene;
}

TEST(BoxReference, MatchesSlowClippingReferenceOnManyVertexScenes) {
    constexpr int kScenes = 150;
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = wobbly_scene(seed);
        const Coverage fast = box_reference(scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const double slow = testing::slow_box_pixel(scene, i, j);
                const double got = fast.at(i, j);
                ASSERT_TRUE(std::abs(got - slow) <= kExactTolerance)
                    << fmt::format("wobbly seed {} pixel ({}, {}): fast {:.17g} slow {:.17g}",
                                   seed, i, j, got, slow);
            }
        }
    }
}

// Regression (found through the crawl of `interpenetrate`, motion frame 2 at 64^2): pieces of a
// 3-D scene that share an edge down to a T-junction (the 0.9 piece's vertex near (39.25, 39.72)
// lies on the 0.25 piece's right edge) and then part. Along the shared stretch their gap is a
// few ulps of either sign; with a band cut at a far shape's vertex (the thin 0.75 piece near
// x = 20.5 ends at y = 39.81) the sweep walked the band below the T-junction in the wrong
// order, and pixel (39, 39) came out 0.5286 instead of 0.4842 (the 2000 x 2000 point-sampled
// value: 0.484191). The slow clipping reference and locality (the far piece changes nothing at
// x = 39) both hold now.
TEST(BoxReference, PiecesPartingAtATJunctionKeepTheirOrder) {
    Scene scene;
    scene.width = 64;
    scene.height = 64;
    scene.shapes.push_back({{{{20.532415702407672, 36.48773674152946},
                              {20.600980993145534, 39.804800975506204},
                              {20.406593406796407, 39.813561234390974},
                              {20.33790015527703, 36.546079677672637}}},
                            0.75});
    scene.shapes.push_back({{{{40.050334627764165, 38.058918509837554},
                              {65.73738556412647, 40.192422820150284},
                              {65.619856636318019, 42.112174321729157},
                              {39.249136841293009, 39.716815590395051}}},
                            0.9});
    scene.shapes.push_back({{{{32.545961183838287, 37.435623405682648},
                              {38.03153433161382, 37.891241840991142},
                              {37.228716641706839, 39.533292683031881},
                              {32.54431278494026, 39.107789406419847}}},
                            0.9});
    scene.shapes.push_back({{{{48.450121467565502, 20.677464998403991},
                              {36.142824575901557, 46.144624207759236},
                              {34.430247289656066, 45.257168743227595},
                              {47.512766365030643, 18.498713201195407}}},
                            0.25});
    const Coverage ref = box_reference(scene);
    Scene without_far = scene;
    without_far.shapes.erase(without_far.shapes.begin());
    const Coverage ref_without = box_reference(without_far);
    for (int j = 36; j <= 42; ++j) {
        for (int i = 30; i < 64; ++i) {
            const double slow = testing::slow_box_pixel(scene, i, j);
            ASSERT_NEAR(ref.at(i, j), slow, kExactTolerance) << "pixel (" << i << ", " << j << ")";
            ASSERT_NEAR(ref.at(i, j), ref_without.at(i, j), kExactTolerance)
                << "pixel (" << i << ", " << j << ") changed by a shape 10 px away";
        }
    }
}

TEST(BoxReference, CoverageSumEqualsPolygonArea) {
    // Simple (star-shaped, so non-self-intersecting) polygons wholly inside the image: the sum
    // of coverage is the shoelace area.
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        Scene scene;
        scene.width = 40;
        scene.height = 30;
        Contour c;
        const int n = 3 + trial % 20;
        std::uniform_real_distribution<double> radius(2.0, 12.0);
        for (int k = 0; k < n; ++k) {
            const double a = 2.0 * std::numbers::pi * k / n;
            const double r = radius(rng);
            c.push_back({20.17 + r * std::cos(a), 14.93 + r * std::sin(a)});
        }
        scene.shapes.push_back({{c}, 1.0});
        const Coverage cov = box_reference(scene);
        double sum = 0.0;
        for (double v : cov.data) sum += v;
        EXPECT_NEAR(sum, std::abs(testing::signed_area(c)), kAreaSumTolerance) << "trial " << trial;
    }
}

TEST(BoxReference, PixelAlignedSquareIsExact) {
    Scene scene;
    scene.width = 8;
    scene.height = 8;
    scene.shapes.push_back({{{{2, 3}, {6, 3}, {6, 5}, {2, 5}}}, 1.0});
    const Coverage cov = box_reference(scene);
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
            const double want = (i >= 2 && i < 6 && j >= 3 && j < 5) ? 1.0 : 0.0;
            EXPECT_EQ(cov.at(i, j), want) << i << "," << j;
        }
    }
}

// Exact coverage of a unit pixel by the half-plane x < x0 + s*(y - y_ref): the integral over
// y of clamp(x_edge(y) - i, 0, 1), piecewise linear, integrated exactly by splitting where
// the clamp switches.
double half_plane_pixel(double x0, double slope, double y_ref, int i, int j) {
    auto f = [&](double y) { return std::clamp(x0 + slope * (y - y_ref) - i, 0.0, 1.0); };
    std::vector<double> cuts = {double(j), j + 1.0};
    if (slope != 0.0) {
        for (double level : {0.0, 1.0}) {
            const double y = y_ref + (i + level - x0) / slope;
            if (y > j && y < j + 1) cuts.push_back(y);
        }
    }
    std::sort(cuts.begin(), cuts.end());
    double total = 0.0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        total += 0.5 * (f(cuts[k]) + f(cuts[k + 1])) * (cuts[k + 1] - cuts[k]);
    }
    return total;
}

TEST(BoxReference, HalfPlanesMatchClosedForm) {
    for (double slope : {0.0, 0.1, -0.37, 1.0, 2.5, -8.0}) {
        Scene scene;
        scene.width = 16;
        scene.height = 16;
        const double x0 = 7.3, y_ref = 8.1, far = 1000.0;
        // The polygon is the half-plane left of the line, cut off far outside the image.
        auto edge_x = [&](double y) { return x0 + slope * (y - y_ref); };
        scene.shapes.push_back(
            {{{{-far, -2.0}, {edge_x(-2.0), -2.0}, {edge_x(18.0), 18.0}, {-far, 18.0}}}, 1.0});
        const Coverage cov = box_reference(scene);
        for (int j = 0; j < 16; ++j) {
            for (int i = 0; i < 16; ++i) {
                EXPECT_NEAR(cov.at(i, j), half_plane_pixel(x0, slope, y_ref, i, j),
                            kExactTolerance)
                    << "slope " << slope << " pixel " << i << "," << j;
            }
        }
    }
}

TEST(BoxReference, LaterShapeHidesEarlierExactly) {
    // Two identical squares: only the later one's value shows, nowhere a mix.
    Scene scene;
    scene.width = 6;
    scene.height = 6;
    const Contour square = {{1.25, 1.5}, {4.75, 1.5}, {4.75, 4.4}, {1.25, 4.4}};
    scene.shapes.push_back({{square}, 1.0});
    scene.shapes.push_back({{square}, 0.5});
    const Coverage cov = box_reference(scene);
    Scene only_last = scene;
    only_last.shapes.erase(only_last.shapes.begin());
    const Coverage want = box_reference(only_last);
    for (std::size_t k = 0; k < cov.data.size(); ++k) {
        EXPECT_NEAR(cov.data[k], want.data[k], kExactTolerance);
    }
}

TEST(BoxReference, NonzeroWindingCountsOverlapOnce) {
    // One shape whose two contours overlap (winding 2 in the middle): still covered once.
    Scene scene;
    scene.width = 10;
    scene.height = 4;
    scene.shapes.push_back(
        {{{{1, 1}, {6, 1}, {6, 3}, {1, 3}}, {{4, 1}, {9, 1}, {9, 3}, {4, 3}}}, 1.0});
    const Coverage cov = box_reference(scene);
    double sum = 0.0;
    for (double v : cov.data) sum += v;
    EXPECT_NEAR(sum, 16.0, kAreaSumTolerance);  // union [1, 9] x [1, 3]
    EXPECT_NEAR(cov.at(5, 1), 1.0, kExactTolerance);
}

}  // namespace
}  // namespace aabench

namespace aabench {
namespace {

// Regression (found by the render fuzzer): an edge from (-1e300, -1e300) to (12.37, 9.5).
// Edge::x_at interpolated from the far endpoint, where y - y0 rounds to 1e300 for every y in
// the image, so the edge sat at x = 0 down to its end, and the box reference came out 3e-7
// above the scene's value range. From the nearer endpoint it is where it should be.
TEST(EdgeTable, XAtInterpolatesFromTheNearerEndpointOfAnEdge1e300Long) {
    Scene scene;
    scene.width = 16;
    scene.height = 16;
    scene.background = 1.0;
    scene.shapes.push_back(
        {{{{12.368408203125, 9.5}, {9.5, 9.5}, {3.167236328125, -1e300}, {-1e300, -1e300}}}, 0.5});
    const EdgeTable table(scene);
    bool found = false;
    for (const Edge& e : table.edges()) {
        if (e.x1 != 12.368408203125) continue;
        found = true;
        // Slope 1 to within 1e-299: 0.5 px above its lower end, 0.5 px left of it.
        EXPECT_EQ(e.x_at(9.0), 12.368408203125 - 0.5);
    }
    EXPECT_TRUE(found);
    const Coverage ref = box_reference(scene);
    for (double v : ref.data) {
        ASSERT_TRUE(v >= 0.5 && v <= 1.0) << v;  // NaN fails
    }
}

}  // namespace
}  // namespace aabench
