// Exact visibility (harness/reference/visibility.h) against an independent oracle (a vertical
// slab decomposition, tests/visibility_oracle.h, sharing no code with it), against point
// queries, and for the properties its pieces must have.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <fmt/format.h>

#include "harness/reference/box_reference.h"
#include "harness/reference/visibility.h"
#include "visibility_oracle.h"
#include "visibility_scenes.h"

namespace aabench {
namespace {

using testing::cross;
using testing::inside_by;
using testing::near_boundary;
using testing::oracle_polygons;
using testing::polygon_area;
using testing::random_depth_scene;

// The references promise 1e-9 per pixel here (docs/architecture.md). Both sides are exact in real
// arithmetic; in double each piece or trapezoid carries a few roundings of O(1) quantities
// (~1e-15), and visible_pieces may drop slivers of at most 2 * 3.6e-15 M per pixel (M ~ 40 px
// here), so the measured differences sit near 1e-14 and 1e-9 catches every real misassignment (the
// smallest real error, a vertex misplaced by 1e-6 px, moves ~1e-6 of area).
constexpr double kOracleTolerance = 1e-9;
constexpr std::uint64_t kBaseSeed = 0x5eed'0000'0000ULL;
constexpr int kOracleScenes = 300;
constexpr int kImageSize = 24;
// Point queries skip points this close to a piece boundary: the pieces there are exact only
// to the tolerances of visibility.cpp (~1e-13 px here), far below this.
constexpr double kBoundaryMarginPx = 1e-9;

// Pairs of shapes whose line of equal depth crosses their overlap, found by sampling (a
// check that the random scenes exercise interpenetration at all).
int interpenetrating_pairs(const Scene& scene) {
    int count = 0;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> coord(-4.0, scene.width + 4.0);
    const std::size_t n = scene.shapes.size();
    std::vector<int> seen(n * n, 0);  // bit 1: a nearer somewhere, bit 2: b nearer
    for (int s = 0; s < 4000; ++s) {
        const Point p{coord(rng), coord(rng)};
        for (std::size_t a = 0; a < n; ++a) {
            if (!inside_by(scene.shapes[a].contours[0], p, 0.0)) continue;
            for (std::size_t b = a + 1; b < n; ++b) {
                if (!inside_by(scene.shapes[b].contours[0], p, 0.0)) continue;
                const double d = scene.shapes[a].inv_depth->at(p.x, p.y) -
                                 scene.shapes[b].inv_depth->at(p.x, p.y);
                seen[a * n + b] |= d > 0.0 ? 1 : 2;
            }
        }
    }
    for (int bits : seen) count += bits == 3;
    return count;
}

TEST(Visibility, BoxReferenceOfPiecesMatchesTheOracleOnRandomScenes) {
    double worst = 0.0;
    int interpenetrating = 0, cyclic_scenes = 0;
    std::size_t overlapping = 0;
    for (int s = 0; s < kOracleScenes; ++s) {
        const std::uint64_t seed = kBaseSeed + s;
        const Scene scene = random_depth_scene(seed, kImageSize, false);
        interpenetrating += interpenetrating_pairs(scene);
        cyclic_scenes += seed % 4 == 0;
        VisibilityStats stats;
        const Scene pieces = visible_pieces(scene, &stats);
        overlapping += stats.overlapping_pairs;
        const Coverage got = box_reference_of_pieces(pieces);
        const std::vector<double> want = oracle::visible_integral(
            oracle_polygons(scene), scene.width, scene.height, scene.background);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const double g = got.at(i, j), w = want[j * scene.width + i];
                const double diff = std::abs(g - w);
                ASSERT_TRUE(diff <= kOracleTolerance)  // NaN fails
                    << fmt::format("seed {:#x} pixel ({}, {}): pieces {:.17g} oracle {:.17g}", seed,
                                   i, j, g, w);
                worst = std::max(worst, diff);
            }
        }
    }
    std::printf(
        "[oracle] %d scenes, %zu overlapping pairs, %d interpenetrating, %d with cyclic "
        "bars; worst |pieces - oracle| = %.3g\n",
        kOracleScenes, overlapping, interpenetrating, cyclic_scenes, worst);
    EXPECT_GT(interpenetrating, kOracleScenes);  // the scenes do exercise crossing planes
}

// Snapped scenes: the degenerate cases (shared coordinates, vertices on edges, lines of equal
// depth through vertices, equal planes) that random reals never produce.
TEST(Visibility, BoxReferenceOfPiecesMatchesTheOracleOnSnappedScenes) {
    double worst = 0.0;
    int ties = 0;
    for (int s = 0; s < kOracleScenes; ++s) {
        const std::uint64_t seed = kBaseSeed + 10000 + s;
        const Scene scene = random_depth_scene(seed, kImageSize, false, true);
        for (std::size_t a = 0; a < scene.shapes.size(); ++a) {
            for (std::size_t b = a + 1; b < scene.shapes.size(); ++b) {
                ties += scene.shapes[a].inv_depth == scene.shapes[b].inv_depth;
            }
        }
        const Coverage got = box_reference_of_pieces(visible_pieces(scene));
        const std::vector<double> want = oracle::visible_integral(
            oracle_polygons(scene), scene.width, scene.height, scene.background);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const double g = got.at(i, j), w = want[j * scene.width + i];
                ASSERT_TRUE(std::abs(g - w) <= kOracleTolerance) << fmt::format(
                    "seed {:#x} pixel ({}, {}): pieces {:.17g} oracle {:.17g}", seed, i, j, g, w);
                worst = std::max(worst, std::abs(g - w));
            }
        }
    }
    std::printf("[snapped] %d scenes, %d pairs of equal planes; worst |pieces - oracle| = %.3g\n",
                kOracleScenes, ties, worst);
}

// box_reference() on a ScreenScene is the same path (visible pieces, then moments).
TEST(Visibility, BoxReferenceOfAScreenSceneGoesThroughVisiblePieces) {
    for (int s = 0; s < 20; ++s) {
        const Scene scene = random_depth_scene(kBaseSeed + 1000 + s, kImageSize, false);
        EXPECT_EQ(box_reference(scene).data, box_reference_of_pieces(visible_pieces(scene)).data);
    }
}

TEST(Visibility, PointQueriesFindTheNearestShape) {
    constexpr int kScenes = 24, kPoints = 10000;
    int checked = 0, skipped = 0;
    for (int s = 0; s < kScenes; ++s) {
        const std::uint64_t seed = kBaseSeed + 2000 + s;
        Scene scene = random_depth_scene(seed, kImageSize, false);
        for (std::size_t k = 0; k < scene.shapes.size(); ++k) scene.shapes[k].value = k;
        const Scene pieces = visible_pieces(scene);
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> coord(-4.0, kImageSize + 4.0);
        for (int q = 0; q < kPoints; ++q) {
            const Point p{coord(rng), coord(rng)};
            int holder = -1, holders = 0;
            bool near = false;
            for (std::size_t k = 0; k < pieces.shapes.size(); ++k) {
                const Contour& c = pieces.shapes[k].contours[0];
                if (near_boundary(c, p, kBoundaryMarginPx)) near = true;
                if (inside_by(c, p, kBoundaryMarginPx)) {
                    holder = static_cast<int>(k);
                    ++holders;
                }
            }
            if (near) {
                ++skipped;
                continue;
            }
            ASSERT_LE(holders, 1) << fmt::format(
                "seed {:#x} point ({:.17g}, {:.17g}): {} "
                "pieces contain it",
                seed, p.x, p.y, holders);
            int nearest = -1;
            double best = 0.0;
            for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
                if (!inside_by(scene.shapes[k].contours[0], p, 0.0)) continue;
                const double w = scene.shapes[k].inv_depth->at(p.x, p.y);
                if (nearest < 0 || w >= best) {
                    nearest = static_cast<int>(k);
                    best = w;
                }
            }
            const int got = holder < 0 ? -1 : static_cast<int>(pieces.shapes[holder].value);
            ASSERT_EQ(got, nearest)
                << fmt::format("seed {:#x} point ({:.17g}, {:.17g})", seed, p.x, p.y);
            ++checked;
        }
    }
    std::printf("[points] %d checked, %d skipped near a piece boundary\n", checked, skipped);
    EXPECT_GT(checked, kScenes * kPoints * 9 / 10);
}

// Sum of the piece areas equals the area of the union (oracle, all values 1): pieces neither
// overlap nor leave holes.
TEST(Visibility, PieceAreasAddUpToTheUnion) {
    // Both sides sum O(100) exact areas of O(10) px^2, each rounded at ~1e-15 relative; the
    // smallest real overlap a bug could leave is orders above this.
    constexpr double kAreaTolerance = 1e-9;
    // random_depth_scene(.., 24, ..) reaches at most 4 + 0.6 * 24 px past the image: moved by
    // kShift, everything lies inside a kSize image, so the oracle sees the whole union.
    constexpr double kShift = 19.0;
    constexpr int kSize = 62;
    for (int s = 0; s < 40; ++s) {
        const std::uint64_t seed = kBaseSeed + 3000 + s;
        Scene scene = random_depth_scene(seed, kImageSize, false);
        scene.width = scene.height = kSize;
        for (Shape& shape : scene.shapes) {
            for (Point& p : shape.contours[0]) p = {p.x + kShift, p.y + kShift};
            AffinePlane& w = *shape.inv_depth;
            w.c -= (w.gx + w.gy) * kShift;  // the same depth at the same (moved) point
            shape.value = 1.0;
        }
        const Scene pieces = visible_pieces(scene);
        double piece_sum = 0.0;
        for (const Shape& piece : pieces.shapes) piece_sum += polygon_area(piece.contours[0]);
        double union_area = 0.0;
        for (double v : oracle::visible_integral(oracle_polygons(scene), kSize, kSize, 0.0)) {
            union_area += v;
        }
        EXPECT_NEAR(piece_sum, union_area, kAreaTolerance) << fmt::format("seed {:#x}", seed);
    }
}

TEST(Visibility, PiecesAreConvexAndPositivelyOriented) {
    // A piece vertex may sit off the line of its neighbours by the rounding of a cut vertex
    // (a few ulps of coordinates ~30 px: ~1e-14), never more.
    constexpr double kConvexSlackPx = 1e-12;
    for (int s = 0; s < 100; ++s) {
        const Scene pieces =
            visible_pieces(random_depth_scene(kBaseSeed + 4000 + s, kImageSize, false));
        for (const Shape& piece : pieces.shapes) {
            ASSERT_EQ(piece.contours.size(), 1u);
            const Contour& c = piece.contours[0];
            ASSERT_GE(c.size(), 3u);
            EXPECT_GT(twice_signed_area(c), 0.0);
            for (std::size_t k = 0; k < c.size(); ++k) {
                const Point& a = c[k];
                const Point& b = c[(k + 1) % c.size()];
                const double len = std::hypot(b.x - a.x, b.y - a.y);
                for (const Point& p : c) {
                    ASSERT_GE(cross(a, b, p) / len, -kConvexSlackPx)
                        << fmt::format("seed {:#x}", kBaseSeed + 4000 + s);
                }
            }
        }
    }
}

Shape square(double x0, double y0, double x1, double y1, AffinePlane w, int face) {
    Shape shape;
    shape.contours = {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
    shape.inv_depth = w;
    shape.face = face;
    return shape;
}

Scene screen(int size, std::vector<Shape> shapes) {
    Scene scene;
    scene.width = scene.height = size;
    scene.shapes = std::move(shapes);
    return scene;
}

double area_of_source(const Scene& pieces, int face) {
    double sum = 0.0;
    for (const Shape& p : pieces.shapes) sum += p.face == face ? polygon_area(p.contours[0]) : 0.0;
    return sum;
}

// Vertex lists equal up to where the loop starts and which way it runs.
bool same_polygon(const Contour& a, const Contour& b) {
    if (a.size() != b.size()) return false;
    auto sorted = [](Contour c) {
        std::sort(c.begin(), c.end(), [](const Point& p, const Point& q) {
            return p.x < q.x || (p.x == q.x && p.y < q.y);
        });
        return c;
    };
    return sorted(a) == sorted(b);
}

// Exact areas here are sums of a few products of small binary fractions.
constexpr double kAreaExactTolerance = 1e-12;

TEST(Visibility, InterpenetratingSquaresSplitAlongTheLineOfEqualDepth) {
    // w_a - w_b = 0.2 (x - 12): a is nearer right of x = 12.
    const Scene scene = screen(24, {square(4, 4, 20, 20, {1.0 - 1.2, 0.1, 0.0}, 0),
                                    square(4, 4, 20, 20, {1.0 + 1.2, -0.1, 0.0}, 1)});
    const Scene pieces = visible_pieces(scene);
    EXPECT_NEAR(area_of_source(pieces, 0), 128.0, kAreaExactTolerance);
    EXPECT_NEAR(area_of_source(pieces, 1), 128.0, kAreaExactTolerance);
    // The cut vertices carry one rounding of the interpolation along the square's sides.
    constexpr double kCutRoundingPx = 1e-13;
    for (const Shape& p : pieces.shapes) {
        for (const Point& v : p.contours[0]) {
            EXPECT_TRUE(p.face == 0 ? v.x >= 12.0 - kCutRoundingPx : v.x <= 12.0 + kCutRoundingPx)
                << p.face << " " << v.x;
        }
    }
}

TEST(Visibility, CyclicBarsAreExact) {
    std::vector<Shape> bars = testing::cyclic_bars(12.0, 12.0, 8.0, 0.3, 1.0, 0);
    for (int k = 0; k < 3; ++k) bars[k].value = 0.2 + 0.3 * k;
    Scene scene = screen(24, bars);
    scene.background = 0.05;
    const Scene pieces = visible_pieces(scene);
    // Each bar loses area (no painter's order: in one, the last bar would lose none).
    for (int k = 0; k < 3; ++k) {
        const double full = polygon_area(bars[k].contours[0]);
        EXPECT_LT(area_of_source(pieces, k), full - 1.0) << "bar " << k;
    }
    const Coverage got = box_reference_of_pieces(pieces);
    const std::vector<double> want =
        oracle::visible_integral(oracle_polygons(scene), 24, 24, scene.background);
    for (int j = 0; j < 24; ++j) {
        for (int i = 0; i < 24; ++i) {
            EXPECT_NEAR(got.at(i, j), want[j * 24 + i], kOracleTolerance) << i << "," << j;
        }
    }
}

TEST(Visibility, TwoDimensionalScenesKeepTheLaterShapeOnTop) {
    double worst = 0.0;
    for (int s = 0; s < 60; ++s) {
        const std::uint64_t seed = kBaseSeed + 5000 + s;
        Scene scene = random_depth_scene(seed, kImageSize, false);
        for (Shape& shape : scene.shapes) {
            shape.inv_depth.reset();
            shape.face = -1;
        }
        const Coverage got = box_reference_of_pieces(visible_pieces(scene));
        const Coverage want = box_reference(scene);  // no planes: the 2-D engine, box_coverage
        const std::vector<double> oracle_want = oracle::visible_integral(
            oracle_polygons(scene), scene.width, scene.height, scene.background);
        for (std::size_t k = 0; k < got.data.size(); ++k) {
            ASSERT_NEAR(got.data[k], want.data[k], kOracleTolerance)
                << fmt::format("seed {:#x} pixel {}", seed, k);
            ASSERT_NEAR(got.data[k], oracle_want[k], kOracleTolerance)
                << fmt::format("seed {:#x} pixel {}", seed, k);
            worst = std::max(worst, std::abs(got.data[k] - want.data[k]));
        }
    }
    std::printf("[2-D] worst |pieces - box_coverage| = %.3g\n", worst);
}

TEST(Visibility, CellsOfOneFaceNeverOccludeEachOther) {
    // b is nearer everywhere; on the same face it must not cut a, on different faces it does.
    const AffinePlane far{1.0, 0.0, 0.0}, near{2.0, 0.0, 0.0};
    VisibilityStats stats;
    const Scene same = visible_pieces(
        screen(16, {square(2, 2, 10, 10, far, 3), square(6, 6, 14, 14, near, 3)}), &stats);
    ASSERT_EQ(same.shapes.size(), 2u);
    EXPECT_EQ(stats.same_face_pairs, 1u);
    EXPECT_EQ(stats.overlapping_pairs, 0u);
    EXPECT_NEAR(polygon_area(same.shapes[0].contours[0]), 64.0, kAreaExactTolerance);
    const Scene other = visible_pieces(
        screen(16, {square(2, 2, 10, 10, far, 3), square(6, 6, 14, 14, near, 4)}), &stats);
    EXPECT_EQ(stats.overlapping_pairs, 1u);
    EXPECT_NEAR(area_of_source(other, 3), 64.0 - 16.0, kAreaExactTolerance);
}

TEST(Visibility, EqualPlanesLetTheLaterShapeWin) {
    const AffinePlane w{1.5, 0.01, -0.02};
    // Within kDepthTieRelative (methods/scan/kernel/visibility_rule.h) of each other: a tie,
    // decided by order.
    AffinePlane w_close = w;
    w_close.c *= 1.0 + 1e-13;
    for (const AffinePlane& second : {w, w_close}) {
        const Scene pieces = visible_pieces(
            screen(16, {square(2, 2, 10, 10, w, 0), square(6, 6, 14, 14, second, 1)}));
        EXPECT_NEAR(area_of_source(pieces, 0), 48.0, kAreaExactTolerance);
        EXPECT_NEAR(area_of_source(pieces, 1), 64.0, kAreaExactTolerance);
        const Scene swapped = visible_pieces(
            screen(16, {square(6, 6, 14, 14, second, 1), square(2, 2, 10, 10, w, 0)}));
        EXPECT_NEAR(area_of_source(swapped, 0), 64.0, kAreaExactTolerance);
        EXPECT_NEAR(area_of_source(swapped, 1), 48.0, kAreaExactTolerance);
    }
}

// A jittered triangulated grid (every edge shared by two triangles, every vertex by up to six)
// and a fan around one vertex: neighbours touch along edges only, so nothing may be cut.
TEST(Visibility, SharedEdgesDoNotFragment) {
    std::mt19937_64 rng(kBaseSeed + 6000);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3), slope(-0.1, 0.1), base(1.0, 2.0);
    constexpr int kCells = 12;
    std::vector<std::vector<Point>> node(kCells + 1, std::vector<Point>(kCells + 1));
    for (int j = 0; j <= kCells; ++j) {
        for (int i = 0; i <= kCells; ++i)
            node[j][i] = {2.0 * i + jitter(rng), 2.0 * j + jitter(rng)};
    }
    std::vector<Shape> tris;
    auto add = [&](Point a, Point b, Point c) {
        Shape t;
        t.contours = {{a, b, c}};
        t.inv_depth = AffinePlane{base(rng), slope(rng), slope(rng)};
        t.face = static_cast<int>(tris.size());
        tris.push_back(t);
    };
    for (int j = 0; j < kCells; ++j) {
        for (int i = 0; i < kCells; ++i) {
            add(node[j][i], node[j][i + 1], node[j + 1][i + 1]);
            add(node[j][i], node[j + 1][i + 1], node[j + 1][i]);
        }
    }
    constexpr int kFan = 17;
    const Point hub{12.3, 12.1};
    for (int k = 0; k < kFan; ++k) {  // a second layer: the fan lies over the grid
        const double a0 = 2.0 * std::numbers::pi * k / kFan,
                     a1 = 2.0 * std::numbers::pi * (k + 1) / kFan;
        add(hub, {hub.x + 9.0 * std::cos(a0), hub.y + 9.0 * std::sin(a0)},
            {hub.x + 9.0 * std::cos(a1), hub.y + 9.0 * std::sin(a1)});
        tris.back().inv_depth->c += 10.0;  // nearer than the grid
    }
    // The fan alone (pairs that only touch) and the grid alone: unchanged.
    for (const auto& [first, count] : {std::pair<int, int>{0, 2 * kCells * kCells},
                                       std::pair<int, int>{2 * kCells * kCells, kFan}}) {
        const std::vector<Shape> layer(tris.begin() + first, tris.begin() + first + count);
        VisibilityStats stats;
        const Scene pieces = visible_pieces(screen(24, layer), &stats);
        EXPECT_GT(stats.candidate_pairs, static_cast<std::size_t>(count));
        EXPECT_EQ(stats.overlapping_pairs, 0u);
        ASSERT_EQ(pieces.shapes.size(), layer.size());
        for (std::size_t k = 0; k < layer.size(); ++k) {
            EXPECT_TRUE(same_polygon(pieces.shapes[k].contours[0], layer[k].contours[0])) << k;
        }
    }
    // Both layers: the fan stays whole, the grid is cut by the fan's outline only.
    VisibilityStats stats;
    const Scene both = visible_pieces(screen(24, tris), &stats);
    int fan_pieces = 0;
    for (const Shape& p : both.shapes) fan_pieces += p.face >= 2 * kCells * kCells;
    EXPECT_EQ(fan_pieces, kFan);
    // The fan is nearer than the whole grid, and each layer is disjoint in itself: the
    // visible value is the 2-D scene grid-then-fan, which box_coverage (an independent exact
    // engine) renders. The oracle is too slow for 300 shapes.
    Scene flat = screen(24, tris);
    for (std::size_t k = 0; k < flat.shapes.size(); ++k) {
        flat.shapes[k].inv_depth.reset();
        flat.shapes[k].value = 0.1 + 0.8 * static_cast<double>(k % 7) / 7.0;
        tris[k].value = flat.shapes[k].value;
    }
    const Coverage got = box_reference_of_pieces(visible_pieces(screen(24, tris)));
    const Coverage want = box_reference(flat);
    for (std::size_t k = 0; k < got.data.size(); ++k) {
        ASSERT_NEAR(got.data[k], want.data[k], kOracleTolerance) << "pixel " << k;
    }
}

TEST(Visibility, RejectsWhatItCannotDoAndDropsDegenerateShapes) {
    const AffinePlane w{1.0, 0.0, 0.0};
    Shape flat = square(1, 1, 5, 5, w, 0);
    flat.inv_depth.reset();
    EXPECT_THROW(visible_pieces(screen(8, {square(1, 1, 5, 5, w, 0), flat})), InputError);
    Shape two = square(1, 1, 3, 3, w, 0);
    two.contours.push_back({{4, 4}, {6, 4}, {6, 6}});
    EXPECT_THROW(visible_pieces(screen(8, {two})), InputError);
    Shape ell = square(0, 0, 1, 1, w, 0);
    ell.contours = {{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 6}, {0, 6}}};
    EXPECT_THROW(visible_pieces(screen(8, {ell})), InputError);
    ell.inv_depth.reset();  // 2-D: the same rule
    EXPECT_THROW(visible_pieces(screen(8, {ell})), InputError);
    Shape twice = square(1, 1, 5, 5, w, 0);  // a square traversed twice: not a convex piece
    Contour loop = twice.contours[0];
    twice.contours[0].insert(twice.contours[0].end(), loop.begin(), loop.end());
    EXPECT_THROW(visible_pieces(screen(8, {twice})), InputError);

    Shape line = square(0, 0, 1, 1, w, 1);
    line.contours = {{{1, 1}, {3, 2}, {5, 3}}};  // collinear: zero area
    Shape empty = square(0, 0, 1, 1, w, 2);
    empty.contours.clear();
    VisibilityStats stats;
    const Scene pieces = visible_pieces(screen(8, {line, square(1, 1, 5, 5, w, 0), empty}), &stats);
    EXPECT_EQ(stats.degenerate_dropped, 2u);
    ASSERT_EQ(pieces.shapes.size(), 1u);
    EXPECT_EQ(pieces.shapes[0].face, 0);
}

// Not a test of speed (tests never time, docs/architecture.md): prints the figure the report
// quotes.
TEST(Visibility, PrintsTheTimeOfTwoThousandOverlappingTriangles) {
    std::mt19937_64 rng(kBaseSeed + 7000);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Scene scene = screen(256, {});
    for (int k = 0; k < 2000; ++k) {
        const double cx = 256.0 * unit(rng), cy = 256.0 * unit(rng);
        Shape t;
        Contour tri;
        for (int v = 0; v < 3; ++v) {
            const double r = 12.0 * std::sqrt(unit(rng)), a = 2.0 * std::numbers::pi * unit(rng);
            tri.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
        }
        t.contours = {tri};
        const double gx = 0.02 * (unit(rng) - 0.5), gy = 0.02 * (unit(rng) - 0.5);
        t.inv_depth = AffinePlane{1.0 + unit(rng) - gx * cx - gy * cy, gx, gy};
        t.value = unit(rng);
        t.face = k;
        scene.shapes.push_back(t);
    }
    VisibilityStats stats;
    const auto t0 = std::chrono::steady_clock::now();
    const Scene pieces = visible_pieces(scene, &stats);
    const auto t1 = std::chrono::steady_clock::now();
    const Coverage ref = box_reference_of_pieces(pieces);
    const auto t2 = std::chrono::steady_clock::now();
    std::printf(
        "[timing] 2000 triangles at 256x256: visible_pieces %.1f ms (%zu candidate "
        "pairs, %zu overlapping, %zu pieces), box_reference_of_pieces %.1f ms\n",
        std::chrono::duration<double, std::milli>(t1 - t0).count(), stats.candidate_pairs,
        stats.overlapping_pairs, stats.pieces_out,
        std::chrono::duration<double, std::milli>(t2 - t1).count());
    EXPECT_EQ(stats.shapes_in, 2000u);
    EXPECT_EQ(ref.pixel_count(), 256u * 256u);
}

}  // namespace
}  // namespace aabench
