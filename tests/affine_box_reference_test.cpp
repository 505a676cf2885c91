// The box reference with affine values (harness/reference/box_reference.h): closed forms by
// hand, an independent per-pixel computation on random pieces (clip with tests/slow_reference.h,
// then triangles integrated at their centroids: no moment formulas), the window origin, and
// constant 2-D scenes unchanged bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include <fmt/format.h>

#include "harness/reference/box_reference.h"
#include "harness/reference/visibility.h"
#include "harness/world/frame.h"
#include "methods/scan/reference/box_coverage.h"
#include "patterns/pattern.h"
#include "slow_reference.h"
#include "visibility_scenes.h"

namespace aabench {
namespace {

// docs/architecture.md promises <= 1e-12 per pixel. Both sides are exact identities evaluated in
// double: O(10) roundings of O(1) terms per piece and pixel (coordinates < 64 px, values < 3), so
// the differences sit at ~1e-15 and 1e-12 still has room.
constexpr double kExactTolerance = 1e-12;
constexpr std::uint64_t kBaseSeed = 0xaff1'0000'0000ULL;

Scene square_scene(double x0, double y0, double x1, double y1, AffinePlane value, double bg) {
    Scene scene;
    scene.width = scene.height = 8;
    scene.background = bg;
    Shape shape;
    shape.contours = {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
    shape.value_plane = value;
    scene.shapes.push_back(shape);
    return scene;
}

TEST(AffineBoxReference, FullyCoveredPixelsTakeThePlaneAtTheirCentre) {
    const AffinePlane v{0.3, 0.05, -0.02};
    const double bg = 0.25;
    const Coverage got = box_reference(square_scene(2, 1, 6, 5, v, bg));
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
            const bool inside = i >= 2 && i < 6 && j >= 1 && j < 5;
            // The mean of an affine function over a square is its value at the centre.
            const double want = inside ? v.at(i + 0.5, j + 0.5) : bg;
            EXPECT_NEAR(got.at(i, j), want, kExactTolerance) << i << "," << j;
        }
    }
}

TEST(AffineBoxReference, PartlyCoveredPixelsByHand) {
    const AffinePlane v{0.3, 0.05, -0.02};
    const double bg = 0.25;
    // Right half of column 6 uncovered: the covered half [6, 6.5] has its centre at x = 6.25.
    const Coverage half = box_reference(square_scene(2, 1, 6.5, 5, v, bg));
    for (int j = 1; j < 5; ++j) {
        EXPECT_NEAR(half.at(6, j), 0.5 * v.at(6.25, j + 0.5) + 0.5 * bg, kExactTolerance) << j;
    }
    // The triangle (0,0), (1,0), (0,1): area 1/2, centroid (1/3, 1/3).
    Scene tri = square_scene(0, 0, 1, 1, v, bg);
    tri.shapes[0].contours = {{{0, 0}, {1, 0}, {0, 1}}};
    EXPECT_NEAR(box_reference(tri).at(0, 0), 0.5 * v.at(1.0 / 3, 1.0 / 3) + 0.5 * bg,
                kExactTolerance);
    // The same triangle moved to pixel (5, 3), walked the other way round.
    tri.shapes[0].contours = {{{5, 3}, {5, 4}, {6, 3}}};
    EXPECT_NEAR(box_reference(tri).at(5, 3), 0.5 * v.at(5 + 1.0 / 3, 3 + 1.0 / 3) + 0.5 * bg,
                kExactTolerance);
}

// Independent per-pixel value of disjoint pieces: each piece clipped to the pixel by
// Sutherland-Hodgman (tests/slow_reference.h), fanned into triangles, each triangle's
// integral = its signed area x the plane at its centroid (exact for an affine function).
double slow_affine_pixel(const Scene& pieces, int i, int j) {
    double integral = 0.0, area = 0.0;
    for (const Shape& piece : pieces.shapes) {
        const AffinePlane v =
            piece.value_plane ? *piece.value_plane : AffinePlane{piece.value, 0.0, 0.0};
        const Contour c = testing::clip_polygon(piece.contours[0], i, j, i + 1.0, j + 1.0);
        double piece_integral = 0.0, piece_area = 0.0;
        for (std::size_t k = 1; k + 1 < c.size(); ++k) {
            const double a = 0.5 * testing::cross(c[0], c[k], c[k + 1]);
            const double cx = (c[0].x + c[k].x + c[k + 1].x) / 3.0;
            const double cy = (c[0].y + c[k].y + c[k + 1].y) / 3.0;
            piece_integral += a * v.at(cx, cy);
            piece_area += a;
        }
        const double sign = piece_area < 0.0 ? -1.0 : 1.0;  // either orientation
        integral += sign * piece_integral;
        area += sign * piece_area;
    }
    return integral + pieces.background * (1.0 - area);
}

TEST(AffineBoxReference, RandomPiecesMatchCentroidTriangles) {
    constexpr int kScenes = 150;
    double worst = 0.0;
    for (int s = 0; s < kScenes; ++s) {
        const std::uint64_t seed = kBaseSeed + s;
        Scene scene = testing::random_depth_scene(seed, 24, true);
        if (s % 3 == 0) {  // 2-D scenes with affine values go the same way
            for (Shape& shape : scene.shapes) shape.inv_depth.reset();
        }
        const Scene pieces = visible_pieces(scene);
        const Coverage got = box_reference(scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const double want = slow_affine_pixel(pieces, i, j);
                const double diff = std::abs(got.at(i, j) - want);
                ASSERT_TRUE(diff <= kExactTolerance)  // NaN fails
                    << fmt::format("seed {:#x} pixel ({}, {}): moments {:.17g} triangles {:.17g}",
                                   seed, i, j, got.at(i, j), want);
                worst = std::max(worst, diff);
            }
        }
    }
    std::printf("[affine] %d scenes, worst |moments - centroid triangles| = %.3g\n", kScenes,
                worst);
}

// Pieces may be non-convex (box_reference_of_pieces takes simple polygons): an L-shaped piece
// equals its two rectangles.
TEST(AffineBoxReference, SimpleNonConvexPieceEqualsItsConvexParts) {
    const AffinePlane v{0.7, -0.03, 0.04};
    Scene ell = square_scene(0, 0, 1, 1, v, 0.1);
    ell.shapes[0].contours = {
        {{0.5, 0.5}, {6.5, 0.5}, {6.5, 2.5}, {2.5, 2.5}, {2.5, 7.5}, {0.5, 7.5}}};
    Scene parts = ell;
    parts.shapes[0].contours = {{{0.5, 0.5}, {6.5, 0.5}, {6.5, 2.5}, {0.5, 2.5}}};
    parts.shapes.push_back(parts.shapes[0]);
    parts.shapes[1].contours = {{{0.5, 2.5}, {2.5, 2.5}, {2.5, 7.5}, {0.5, 7.5}}};
    const Coverage a = box_reference_of_pieces(ell), b = box_reference_of_pieces(parts);
    for (std::size_t k = 0; k < a.data.size(); ++k) {
        EXPECT_NEAR(a.data[k], b.data[k], kExactTolerance) << k;
    }
}

// A plane is written in scene coordinates, like the vertices: with the window moved far away,
// the scene must give what the same scene written in window coordinates gives.
TEST(AffineBoxReference, WindowOriginMovesThePlanesAlong) {
    // Far from 0 every coordinate carries ulp(1000) ~ 1e-13 of its own rounding.
    constexpr double kFarTolerance = 1e-11;
    const double ox = 1000.5, oy = -300.25;
    const AffinePlane v{0.3, 0.05, -0.02};
    Scene near = square_scene(1.3, 0.7, 6.6, 5.2, v, 0.2);
    Scene far = near;
    far.origin_x = ox;
    far.origin_y = oy;
    for (Point& p : far.shapes[0].contours[0]) p = {p.x + ox, p.y + oy};
    far.shapes[0].value_plane = AffinePlane{v.c - v.gx * ox - v.gy * oy, v.gx, v.gy};
    const Coverage a = box_reference(near), b = box_reference(window_scene(far));
    for (std::size_t k = 0; k < a.data.size(); ++k) {
        EXPECT_NEAR(a.data[k], b.data[k], kFarTolerance) << k;
    }
}

// Without planes box_reference is box_coverage: every result on constant-valued scenes stands.
TEST(AffineBoxReference, ConstantTwoDimensionalScenesAreUnchangedBitForBit) {
    for (const char* spec : {"star", "strips", "grating", "rings", "zoneplate"}) {
        const Scene scene = make_pattern(spec, 64, 64);
        ASSERT_FALSE(has_planes(scene));
        EXPECT_EQ(box_reference(scene).data, box_coverage(scene).data) << spec;
    }
}

}  // namespace
}  // namespace aabench
