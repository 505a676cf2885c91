// fast-edge (Kato & Kameyama). The default, inset=0, is the paper's formula: the alphas about
// the true crossing measured from the pixel centres, side-blind, which fattens every edge by
// half a pixel (asserted). The documented variant inset=0.5 (kInsetHalf): exact on
// pixel-aligned shapes; on half-planes within the bounds derived in docs/methods-sampling.md;
// and its known weaknesses shown, each by asserting that the deviation exists, has the size the
// rule predicts, and is bounded: a vertex pixel blended twice, a thin strip whose two edges
// share pixels. Also the z-test, gamma, orientation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "harness/reference/box_reference.h"
#include "methods/method.h"
#include "test_scenes.h"

namespace aabench {
namespace {

// Output is float32: each blend is computed in double and rounded once, so a pixel after one
// or two blends is within a float32 ulp or two of the double computation; the exact reference
// is good to 1e-12. Two ulps at 1.0.
constexpr double kFloatSlack = 2.0 * FLT_EPSILON;
// Half-plane bounds (docs/methods-sampling.md, "fast-edge on a straight edge"), for an edge of
// slope |m| <= 1 along its major axis, with inset = 1/2:
// a pixel whose centre the fill found inside keeps the full value, and a half-plane that
// contains a square's centre covers at least half the square: error <= 1/2.
constexpr double kFilledPixelBound = 0.5 + kFloatSlack;
// A pixel the fill left empty is either the crossing pixel, blended by 1 - frac, which is its
// coverage up to a corner triangle of area <= |m|/8, or an untouched pixel the line clips by
// at most such a triangle: error <= 1/8.
constexpr double kEmptyPixelBound = 0.125 + kFloatSlack;
// Summed squared error against `none`'s on the same half-planes: per column the analysis gives
// (integral of f^2 over f in [0, 1/2]) / (integral of min(f, 1-f)^2 over [0, 1]) = 1/2; the
// corner triangles add a little (measured 0.504 over these 300 seeds).
constexpr double kHalfPlaneSseRatioBound = 0.6;

// The variant with the tent centred half a pixel inside the edge (docs/methods-sampling.md).
constexpr const char* kInsetHalf = "fast-edge:inset=0.5";

double snap(double v) { return std::round(v * 65536.0) / 65536.0; }

Scene rectangle_scene(int width, int height, double x0, double y0, double x1, double y1,
                      double value = 1.0) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.shapes.push_back({{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}, value});
    return scene;
}

void expect_pixel(const Image& img, int i, int j, double want, const std::string& what) {
    EXPECT_NEAR(img.at(i, j), want, kFloatSlack)
        << fmt::format("{} pixel ({}, {}): got {} want {}", what, i, j, img.at(i, j), want);
}

// Pixel-aligned rectangles, some with pixel-aligned holes, overlapping, in either orientation.
TEST(FastEdge, PixelAlignedRectanglesAreExact) {
    const MethodInstance m = make_method(kInsetHalf);
    for (std::uint64_t seed = 1; seed <= 100; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> v(0.0, 1.0);
        Scene scene;
        scene.width = 14;
        scene.height = 11;
        scene.background = v(rng);
        for (int s = 0; s < 4; ++s) {
            const int x0 = static_cast<int>(rng() % 18) - 2, y0 = static_cast<int>(rng() % 15) - 2;
            const int x1 = x0 + 1 + static_cast<int>(rng() % 8);
            const int y1 = y0 + 1 + static_cast<int>(rng() % 8);
            Contour c = {{double(x0), double(y0)}, {double(x1), double(y0)},
                         {double(x1), double(y1)}, {double(x0), double(y1)}};
            Shape shape{{c}, v(rng)};
            if (x1 - x0 >= 3 && y1 - y0 >= 3 && rng() % 2) {
                // A one-pixel-inset hole, drawn in the opposite sense (a hole's edges have the
                // shape's inside on their outer side).
                shape.contours.push_back({{x0 + 1.0, y0 + 1.0}, {x0 + 1.0, y1 - 1.0},
                                          {x1 - 1.0, y1 - 1.0}, {x1 - 1.0, y0 + 1.0}});
            }
            if (rng() % 2) {  // either orientation
                for (Contour& contour : shape.contours) {
                    std::reverse(contour.begin(), contour.end());
                }
            }
            scene.shapes.push_back(shape);
        }
        const Coverage exact = box_reference(scene);
        const Image out = render_scene(*m.method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                ASSERT_NEAR(out.at(i, j), exact.at(i, j), kFloatSlack)
                    << fmt::format("seed {} pixel ({}, {}): fast-edge {} exact {}", seed, i, j,
                                   out.at(i, j), exact.at(i, j));
            }
        }
    }
}

TEST(FastEdge, HalfPlaneWithinTheDerivedBounds) {
    const MethodInstance m = make_method(kInsetHalf);
    const MethodInstance none = make_method("none");
    double sse = 0.0, sse_none = 0.0;
    for (std::uint64_t seed = 1; seed <= 300; ++seed) {
        const Scene scene = testing::random_half_plane(seed, 32, 32);
        const Coverage exact = box_reference(scene);
        const Image out = render_scene(*m.method, scene);
        const Image fill = render_scene(*none.method, scene);  // fast-edge's step 1
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const double want = exact.at(i, j), got = out.at(i, j);
                const double err = std::abs(got - want);
                const bool edge_pixel = want > kFloatSlack && want < 1.0 - kFloatSlack;
                const double bound = !edge_pixel          ? kFloatSlack
                                     : fill.at(i, j) == 0 ? kEmptyPixelBound
                                                          : kFilledPixelBound;
                // Written so that NaN fails.
                ASSERT_TRUE(err <= bound) << fmt::format(
                    "seed {} pixel ({}, {}): fast-edge {} exact {} fill {} (bound {})", seed, i,
                    j, got, want, fill.at(i, j), bound);
                sse += err * err;
                sse_none += (fill.at(i, j) - want) * (fill.at(i, j) - want);
            }
        }
    }
    EXPECT_TRUE(sse <= kHalfPlaneSseRatioBound * sse_none)
        << fmt::format("summed squared error {} vs none's {}: ratio {} (bound {})", sse, sse_none,
                       sse / sse_none, kHalfPlaneSseRatioBound);
}

// Weakness: a vertex. Near the tip of a wedge both edges step on the same column and blend
// the same pixel, whose centre the wedge misses: it gets 1 - (1 - a1)(1 - a2) where the true
// coverage is 0.14.
TEST(FastEdge, VertexPixelIsBlendedTwice) {
    // Tip T, the wedge opening to the right; positive shoelace area (inside along (-dy, dx)).
    const Point t{1.2, 5.3}, b{12.0, 2.9}, c{12.0, 7.7};
    Scene scene;
    scene.width = 16;
    scene.height = 10;
    scene.shapes.push_back({{{t, b, c}}, 1.0});
    const Image out = render_scene(*make_method(kInsetHalf).method, scene);
    const double exact = box_reference(scene).at(1, 5);
    // The rule, by hand, at the centre line x = 1.5 of column 1 (docs/methods-sampling.md):
    // edge T -> B has the inside below: crossing y1, pixel floor(y1) = 5 gets 1 - frac(y1);
    // edge C -> T has the inside above: crossing y2, pixel floor(y2) = 5 gets frac(y2).
    const double y1 = t.y + (1.5 - t.x) * (b.y - t.y) / (b.x - t.x);
    const double y2 = c.y + (1.5 - c.x) * (t.y - c.y) / (t.x - c.x);
    ASSERT_EQ(std::floor(y1), 5.0);
    ASSERT_EQ(std::floor(y2), 5.0);
    const double a1 = 1.0 - (y1 - 5.0), a2 = y2 - 5.0;
    const double once = static_cast<float>(a1);
    const double twice = once + a2 * (1.0 - once);
    expect_pixel(out, 1, 5, twice, "vertex, two blends");
    // The deviation exists: the second blend adds at least 0.05 over one blend, the pixel is
    // more than 0.5 off its coverage; and it is bounded: no blend leaves [0, value].
    constexpr double kSecondBlendShown = 0.05;
    constexpr double kVertexDeviationShown = 0.5;
    EXPECT_GT(out.at(1, 5) - once, kSecondBlendShown);
    EXPECT_GT(out.at(1, 5) - exact, kVertexDeviationShown)
        << fmt::format("fast-edge {} exact {}", out.at(1, 5), exact);
    EXPECT_LE(out.at(1, 5), 1.0);
}

// Weakness: a strip thinner than a pixel, y in [2.55, 2.95]. No centre is inside, so the fill
// is empty; the top edge blends rows 2 and 3 as if everything below were inside, the bottom
// edge rows 1 and 2 as if everything above were: the strip's 0.4 per column comes out as 1.57.
TEST(FastEdge, ThinStripEdgesSharePixels) {
    const Scene scene = rectangle_scene(16, 6, -5.0, 2.55, 21.0, 2.95);
    const Image out = render_scene(*make_method(kInsetHalf).method, scene);
    const Coverage exact = box_reference(scene);
    // Top edge (inside below): frac = 0.55, row 2 gets 0.45, row 3 gets 0.55.
    // Bottom edge (inside above): frac = 0.95, row 2 gets 0.95, row 1 gets 0.05.
    const double row2 = static_cast<float>(0.45) + 0.95 * (1.0 - static_cast<float>(0.45));
    constexpr double kStripDeviationShown = 0.5;  // row 2: 0.97 where the coverage is 0.4
    for (int i = 0; i < scene.width; ++i) {
        expect_pixel(out, i, 1, 0.05, "strip row 1");
        expect_pixel(out, i, 2, row2, "strip row 2");
        expect_pixel(out, i, 3, 0.55, "strip row 3");
        expect_pixel(out, i, 0, 0.0, "strip row 0");
        EXPECT_GT(out.at(i, 2) - exact.at(i, 2), kStripDeviationShown);
        // Bounded: each edge adds at most one pixel's worth per column.
        EXPECT_LE(out.at(i, 1) + out.at(i, 2) + out.at(i, 3), 2.0);
    }
}

// Weakness of the paper's formula taken about the true edge (inset=0): each straddling pixel
// gets one minus its distance to the crossing, so the outside pixel next to a pixel-aligned
// edge gets 0.5. The square grows a ring of 0.5 along its sides (the corner pixels diagonal to
// the square are outside both edges' step ranges), i.e. half a pixel times the perimeter.
TEST(FastEdge, InsetZeroIsHalfAPixelTooFat) {
    const Scene scene = rectangle_scene(12, 10, 3, 2, 9, 7);
    const Image out = render_scene(*make_method("fast-edge:inset=0").method, scene);
    double excess = 0.0;
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const bool inside = i >= 3 && i < 9 && j >= 2 && j < 7;
            const bool side_ring = (!inside) && ((j >= 2 && j < 7 && (i == 2 || i == 9)) ||
                                                 (i >= 3 && i < 9 && (j == 1 || j == 7)));
            expect_pixel(out, i, j, inside ? 1.0 : side_ring ? 0.5 : 0.0, "inset=0 square");
            excess += out.at(i, j) - (inside ? 1.0 : 0.0);
        }
    }
    constexpr double kPerimeter = 2 * (6 + 5);
    EXPECT_NEAR(excess, 0.5 * kPerimeter, kPerimeter * kFloatSlack);
}

// The default is the paper's formula, I_Q = Filter(1 - D_Q), I_P = Filter(D_Q), D_Q the
// distance from the centre of Q (the pixel above the crossing) to the crossing: on the
// horizontal edge y = 2.7 with the inside below, row 2's centre (2.5) is 0.2 from the edge and
// gets 0.8 though only 0.3 of it is covered; row 3 (centre inside) is filled; row 1 untouched.
// The variant puts the coverage, 0.3, there.
TEST(FastEdge, DefaultIsThePapersFormulaAboutTheTrueCrossing) {
    const Scene scene = rectangle_scene(16, 8, -5.0, 2.7, 21.0, 20.0);
    EXPECT_EQ(make_method("fast-edge").spec, "fast-edge:gamma=1,inset=0,flatness=0.25");
    const Image paper = render_scene(*make_method("fast-edge").method, scene);
    const Image variant = render_scene(*make_method(kInsetHalf).method, scene);
    for (int i = 0; i < scene.width; ++i) {
        expect_pixel(paper, i, 1, 0.0, "paper, row 1");
        expect_pixel(paper, i, 2, 0.8, "paper, row 2");
        expect_pixel(paper, i, 3, 1.0, "paper, row 3");
        expect_pixel(variant, i, 2, 0.3, "inset=0.5, row 2");
    }
}

// z-test without z-write: an edge of shape 0 blends only pixels whose centre no later shape
// covers. Shape 1 (pixel-aligned, value 0.5) covers the right part of shape 0: every pixel
// whose centre is in shape 1 stays exactly 0.5, though shape 0's edges run through them.
TEST(FastEdge, LaterShapeHidesEarlierEdges) {
    Scene scene = rectangle_scene(14, 12, 2.3, 2.3, 10.3, 8.3, 1.0);
    scene.shapes.push_back({{{{6, 0}, {14, 0}, {14, 12}, {6, 12}}}, 0.5});
    const Image out = render_scene(*make_method(kInsetHalf).method, scene);
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 6; i < scene.width; ++i) expect_pixel(out, i, j, 0.5, "under shape 1");
    }
    // Where shape 0's top edge (y = 2.3, inside below) is not hidden, it blends as usual:
    // row 2 is the crossing pixel (frac 0.3, alpha 0.7) but its centre is inside, so it stays 1;
    // row 1 is not one of the two straddling pixels and stays empty.
    expect_pixel(out, 3, 2, 1.0, "shape 0 top edge, centre inside");
    expect_pixel(out, 3, 1, 0.0, "shape 0 top edge, outer neighbour untouched");
}

// gamma: Filter(a) = a^(1/gamma). A horizontal edge at y = 2.7 with the inside below leaves
// row 2's centre outside; row 2 is the crossing pixel with frac = 0.7 and gets Filter(0.3).
TEST(FastEdge, GammaShapesTheAlpha) {
    const Scene scene = rectangle_scene(16, 8, -5.0, 2.7, 21.0, 20.0);
    for (double gamma : {1.0, 2.0, 0.5, 2.2}) {
        const std::string spec = fmt::format("fast-edge:gamma={},inset=0.5", gamma);
        const Image out = render_scene(*make_method(spec).method, scene);
        for (int i = 0; i < scene.width; ++i) {
            expect_pixel(out, i, 2, std::pow(0.3, 1.0 / gamma), spec);
            expect_pixel(out, i, 3, 1.0, spec);
            expect_pixel(out, i, 1, 0.0, spec);
        }
    }
}

// The side of an edge comes from the shape's orientation: reversing every contour (all
// winding numbers change sign) leaves the image unchanged, holes included.
TEST(FastEdge, ContourOrientationDoesNotMatter) {
    const MethodInstance m = make_method(kInsetHalf);
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> x(-3.0, 19.0), y(-3.0, 15.0), v(0.0, 1.0);
        Scene scene;
        scene.width = 16;
        scene.height = 12;
        for (int s = 0; s < 3; ++s) {
            Shape shape;
            shape.value = v(rng);
            // An outer square and a hole, drawn in opposite senses.
            const double cx = x(rng), cy = y(rng), r = 2.0 + 4.0 * v(rng), h = r * v(rng);
            shape.contours.push_back({{snap(cx - r), snap(cy - r)}, {snap(cx + r), snap(cy - r)},
                                      {snap(cx + r), snap(cy + r)}, {snap(cx - r), snap(cy + r)}});
            shape.contours.push_back({{snap(cx - h), snap(cy - h)}, {snap(cx - h), snap(cy + h)},
                                      {snap(cx + h), snap(cy + h)}, {snap(cx + h), snap(cy - h)}});
            scene.shapes.push_back(shape);
        }
        Scene reversed = scene;
        for (Shape& s : reversed.shapes) {
            for (Contour& c : s.contours) std::reverse(c.begin(), c.end());
        }
        const Image a = render_scene(*m.method, scene);
        const Image b = render_scene(*m.method, reversed);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                ASSERT_NEAR(a.at(i, j), b.at(i, j), kFloatSlack)
                    << fmt::format("seed {} pixel ({}, {}): {} vs reversed {}", seed, i, j,
                                   a.at(i, j), b.at(i, j));
            }
        }
    }
}

// Regression (found by the hard-case suite, case "outside"): an edge wholly right of or below
// the image converted its first DDA step, up to 1e15, to int (undefined behaviour; in practice
// INT_MIN, and a loop of 2^31 steps that took 30 s). Such edges must cost nothing and change
// nothing.
TEST(FastEdge, EdgesFarPastTheImageAreSkipped) {
    Scene scene;
    scene.width = 8;
    scene.height = 6;
    scene.background = 0.25;
    scene.shapes.push_back({{{{1e15, 1e15}, {2e15, 1e15}, {1e15, 3e15}}}, 1.0});  // x- and y-major
    scene.shapes.push_back({{{{40, 2}, {90, 3}, {60, 5}}}, 1.0});                  // right of it
    scene.shapes.push_back({{{{2, 30}, {3, 90}, {5, 60}}}, 1.0});                  // below it
    const Image out = render_scene(*make_method(kInsetHalf).method, scene);
    for (float v : out.data) ASSERT_EQ(v, 0.25f);
}

TEST(FastEdge, OutOfRangeParametersNameTheRange) {
    EXPECT_EQ(make_method("fast-edge").spec, "fast-edge:gamma=1,inset=0,flatness=0.25");
    EXPECT_EQ(make_method("fast-edge").method->filter().text(), "box");
    const std::pair<const char*, const char*> cases[] = {{"fast-edge:gamma=0", "0.1..10"},
                                                         {"fast-edge:gamma=11", "0.1..10"},
                                                         {"fast-edge:inset=-0.1", "0..1"},
                                                         {"fast-edge:inset=1.5", "0..1"},
                                                         {"fast-edge:flatness=0", "0.0001..10"}};
    for (const auto& [spec, range] : cases) {
        try {
            make_method(spec);
            FAIL() << spec << ": no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(range), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace aabench
