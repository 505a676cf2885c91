// nishita-d, both lattices (1/3 px, the default, and 1/2 px): a constant scene gives its value;
// the response to one lit lattice point is the normalised radius-1 Gaussian over the window,
// computed here independently; the margin outside the image is sampled; the weights are
// symmetric; the default agrees with a slow implementation (point samples with a brute-force
// winding-number test) on seeded random scenes; parameter range and reference filter.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "methods/method.h"
#include "patterns/pattern.h"
#include "test_scenes.h"

namespace aabench {
namespace {

// Output is float32 rounded once from a double sum of 25 terms in [0, 1] (error ~1e-15): one
// float32 ulp at 1.0 covers it.
constexpr double kFloatSlack = FLT_EPSILON;

// Positions computed here in another way than the method's (i + k/n offsets against its
// (2q + n - 4) / (2n)) differ by an ulp at most; a point is in a window when it is within this
// of the window's edge (a window edge sits exactly on lattice points).
constexpr double kPositionSlack = 1e-9;

// The expected weight of a lattice point at offset (ox, oy) px from a pixel centre, for a
// lattice of n points per pixel side: in the 5 x 5 window (|ox|, |oy| <= 2/n) and within the
// radius r <= 1, the Gaussian normalised over the window's points within the radius.
double expected_weight(double ox, double oy, int n, double sigma) {
    auto g = [&](double r2) { return std::exp(-r2 / (2.0 * sigma * sigma)); };
    double total = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            const double r2 = (dx * dx + dy * dy) / double(n * n);
            if (r2 <= 1.0 + kPositionSlack) total += g(r2);
        }
    }
    const double half_window = 2.0 / n + kPositionSlack, r2 = ox * ox + oy * oy;
    if (std::abs(ox) > half_window || std::abs(oy) > half_window || r2 > 1.0 + kPositionSlack) {
        return 0.0;
    }
    return g(r2) / total;
}

// A square of side 0.1 around (x, y): it contains exactly one lattice point (spacing 1/3 or
// 1/2) and its edges pass through none.
Scene impulse_at(double x, double y, int width = 8, int height = 7) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.shapes.push_back(
        {{{{x - 0.05, y - 0.05}, {x + 0.05, y - 0.05}, {x + 0.05, y + 0.05}, {x - 0.05, y + 0.05}}},
         1.0});
    return scene;
}

void expect_response(const std::string& spec, int n, double sigma, double x, double y) {
    const Image out = render_scene(*make_method(spec).method, impulse_at(x, y));
    int lit = 0;
    for (int j = 0; j < out.height; ++j) {
        for (int i = 0; i < out.width; ++i) {
            const double want = expected_weight(x - (i + 0.5), y - (j + 0.5), n, sigma);
            lit += want > 0.0;
            ASSERT_NEAR(out.at(i, j), want, kFloatSlack)
                << fmt::format("{} impulse at ({}, {}) pixel ({}, {}): got {} want {}", spec, x, y,
                               i, j, out.at(i, j), want);
        }
    }
    EXPECT_GT(lit, 0) << spec << " impulse at (" << x << ", " << y << ") reaches no pixel";
}

TEST(NishitaD, ConstantSceneGivesItsValue) {
    // The shape covers the image and the margin the lattices reach into.
    Scene scene;
    scene.width = 11;
    scene.height = 6;
    scene.background = 0.1;
    scene.shapes.push_back({{{{-2, -2}, {13, -2}, {13, 8}, {-2, 8}}}, 0.7});
    for (const char* lattice : {"third", "half"}) {
        for (double sigma : {0.05, 0.5, 1.0, 10.0}) {
            const MethodInstance m =
                make_method(fmt::format("nishita-d:sigma={},lattice={}", sigma, lattice));
            const Image out = render_scene(*m.method, scene);
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    ASSERT_NEAR(out.at(i, j), 0.7, kFloatSlack)
                        << fmt::format("{} pixel ({}, {}) = {}", m.spec, i, j, out.at(i, j));
                }
            }
        }
    }
}

// The default lattice (1/3 px): one lit lattice point, at a pixel centre (seen by that pixel
// only: the neighbours' windows end 2/3 px from their centres), at a pixel's first sample
// (seen by it and its left neighbour), at corner samples (four pixels) and in the 1/6-px
// margin; every pixel shows the independently computed weight of the point in its window.
TEST(NishitaD, ThirdLatticeResponseIsTheNormalisedGaussianOverAll25) {
    for (double sigma : {0.5, 0.8}) {
        const std::string spec = fmt::format("nishita-d:sigma={}", sigma);
        expect_response(spec, 3, sigma, 3.5, 3.5);                      // a centre: its pixel only
        expect_response(spec, 3, sigma, 4.0 + 1.0 / 6, 3.5);            // first sample: 2 pixels
        expect_response(spec, 3, sigma, 4.0 + 1.0 / 6, 3.0 + 5.0 / 6);  // a corner sample: 4
        expect_response(spec, 3, sigma, 2.0 + 5.0 / 6, 4.0 + 1.0 / 6);  // the other diagonal
    }
    // Margin: the lattice reaches 1/6 px past every border.
    const int w = 8, h = 7;
    expect_response("nishita-d", 3, 0.5, -1.0 / 6, 3.5);
    expect_response("nishita-d", 3, 0.5, 3.5, -1.0 / 6);
    expect_response("nishita-d", 3, 0.5, w + 1.0 / 6, 2.5);
    expect_response("nishita-d", 3, 0.5, 3.5, h + 1.0 / 6);
}

// The weight of a pixel's own corner sample in the default lattice: the window's corner at
// r = sqrt(8)/3 carries a weight (all 25 count), while the half lattice's corner of the window
// (r = sqrt(2)) carries none.
TEST(NishitaD, ThirdLatticeWeightsAll25HalfLatticeOnly13) {
    const Image third =
        render_scene(*make_method("nishita-d").method, impulse_at(4.0 + 1.0 / 6, 3.0 + 1.0 / 6));
    // Pixel (3, 2) sees that point at offset (2/3, 2/3): its window's corner.
    EXPECT_GT(third.at(3, 2), 0.01);
    const Image half =
        render_scene(*make_method("nishita-d:lattice=half").method, impulse_at(4.5, 3.5));
    // Pixel (3, 2) sees (4.5, 3.5) at offset (1, 1): in its 5 x 5 window, beyond the radius.
    EXPECT_EQ(half.at(3, 2), 0.0f);
    EXPECT_GT(half.at(4, 3), 0.1f);  // the point is its own centre
}

// The half-pixel lattice: one lit lattice point at a pixel centre, a pixel corner (shared by
// four pixels) and an edge midpoint (shared by two): every pixel shows the weight of that point
// in its window.
TEST(NishitaD, HalfLatticeResponseIsTheNormalisedGaussian) {
    for (double sigma : {0.5, 0.8}) {
        const std::string spec = fmt::format("nishita-d:sigma={},lattice=half", sigma);
        expect_response(spec, 2, sigma, 3.5, 3.5);  // centre: 1 pixel at r = 0, 4 at r = 1
        expect_response(spec, 2, sigma, 4.0, 3.0);  // corner: 4 pixels at r = sqrt(2)/2
        expect_response(spec, 2, sigma, 3.5, 3.0);  // edge midpoint: 2 pixels at r = 1/2
        expect_response(spec, 2, sigma, 4.0, 3.5);  // vertical edge midpoint
    }
}

// Shapes outside the image reach the border pixels through the half lattice's half-pixel
// margin: the lattice column x = -1/2, the rows y = -1/2, y = h (the bottom border line,
// sampled with the same half-open rule as interior lines) and y = h + 1/2.
TEST(NishitaD, HalfLatticeMarginOutsideTheImageIsSampled) {
    const std::string spec = "nishita-d:lattice=half";
    const double sigma = 0.5;
    const int w = 8, h = 7;
    expect_response(spec, 2, sigma, -0.5, 3.5);
    expect_response(spec, 2, sigma, 3.5, -0.5);
    expect_response(spec, 2, sigma, 3.5, h + 0.5);
    expect_response(spec, 2, sigma, w + 0.5, 2.5);
    expect_response(spec, 2, sigma, 2.0, h);
}

// The weights depend on distance only: an image of a mirrored or transposed scene is the
// mirrored or transposed image. Random vertices keep lattice points off edges (the tie rule
// is not symmetric).
TEST(NishitaD, SymmetricUnderMirrorsAndTranspose) {
    // The same 25-term sum in another order: a few double ulps, one float32 step at most.
    constexpr double kSymmetryTolerance = kFloatSlack;
    for (const char* spec : {"nishita-d", "nishita-d:lattice=half"}) {
        const MethodInstance m = make_method(spec);
        for (std::uint64_t seed = 1; seed <= 30; ++seed) {
            std::mt19937_64 rng(seed);
            std::uniform_real_distribution<double> x(-3.0, 15.0), y(-3.0, 12.0);
            Scene scene;
            scene.width = 12;
            scene.height = 9;
            for (int s = 0; s < 3; ++s) {
                Contour c;
                for (int k = 0; k < 5; ++k) c.push_back({x(rng), y(rng)});
                scene.shapes.push_back({{c}, 0.3 * (s + 1)});
            }
            const Image base = render_scene(*m.method, scene);
            for (int variant = 1; variant < 8; ++variant) {
                const bool mx = variant & 1, my = variant & 2, tr = variant & 4;
                Scene other = scene;
                if (tr) std::swap(other.width, other.height);
                for (Shape& s : other.shapes) {
                    for (Point& p : s.contours[0]) {
                        if (mx) p.x = scene.width - p.x;
                        if (my) p.y = scene.height - p.y;
                        if (tr) std::swap(p.x, p.y);
                    }
                }
                const Image img = render_scene(*m.method, other);
                for (int j = 0; j < scene.height; ++j) {
                    for (int i = 0; i < scene.width; ++i) {
                        int px = mx ? scene.width - 1 - i : i, py = my ? scene.height - 1 - j : j;
                        if (tr) std::swap(px, py);
                        ASSERT_NEAR(base.at(i, j), img.at(px, py), kSymmetryTolerance)
                            << fmt::format("{} seed {} variant {} pixel ({}, {}): {} vs {}", spec,
                                           seed, variant, i, j, base.at(i, j), img.at(px, py));
                    }
                }
            }
        }
    }
}

// The topmost shape whose nonzero winding number is nonzero at (x, y), by a crossing count
// over every edge of the scene (no edge table, no sweep): the scene's value there.
double slow_point_value(const Scene& scene, double x, double y) {
    double value = scene.background;
    for (const Shape& shape : scene.shapes) {
        int winding = 0;
        for (const Contour& c : shape.contours) {
            for (std::size_t k = 0; k < c.size(); ++k) {
                const Point a = c[k], b = c[(k + 1) % c.size()];
                const double side = (b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y);
                if (a.y <= y && y < b.y && side > 0) ++winding;  // upward, point on its left
                if (b.y <= y && y < a.y && side < 0) --winding;  // downward, point on its right
            }
        }
        if (winding != 0) value = shape.value;
    }
    return value;
}

// The default reading written out directly: pixel (i, j) samples the 5 x 5 points
// (i + 1/2 + dx/3, j + 1/2 + dy/3), dx, dy in -2..2 (its own 3 x 3 stratum centres and the
// nearest 16 of its neighbours'), weighted exp(-r^2 / (2 sigma^2)) over all 25, normalised.
double slow_third_lattice_pixel(const Scene& scene, int i, int j, double sigma) {
    double sum = 0.0, total = 0.0;
    for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
            const double ox = dx / 3.0, oy = dy / 3.0;
            const double w = std::exp(-(ox * ox + oy * oy) / (2.0 * sigma * sigma));
            sum += w * slow_point_value(scene, i + 0.5 + ox, j + 0.5 + oy);
            total += w;
        }
    }
    return sum / total;
}

// The method against the slow implementation on seeded random scenes: overlapping, self-
// intersecting polygons (nonzero winding) with holes, reaching past the image. Random vertices
// keep the lattice points off the edges, where the two position formulas could take different
// sides of a tie.
TEST(NishitaD, DefaultAgreesWithASlowImplementationOnRandomScenes) {
    // The method's float32 output against the slow double value: half a float32 ulp of
    // rounding plus a few double ulps of summation order, within one float32 ulp at 1.0.
    constexpr double kAgreement = kFloatSlack;
    double worst = 0.0;
    int pixels = 0;
    for (double sigma : {0.5, 0.3, 1.0}) {
        const MethodInstance m = make_method(fmt::format("nishita-d:sigma={}", sigma));
        for (std::uint64_t seed = 1; seed <= 40; ++seed) {
            std::mt19937_64 rng(seed);
            Scene scene;
            scene.width = 9 + static_cast<int>(seed % 7);
            scene.height = 7 + static_cast<int>(seed % 5);
            std::uniform_real_distribution<double> x(-2.0, scene.width + 2.0),
                y(-2.0, scene.height + 2.0), value(0.0, 1.0);
            std::uniform_int_distribution<int> vertices(3, 9), contours(1, 2);
            scene.background = value(rng);
            for (int s = 0; s < 4; ++s) {
                Shape shape;
                shape.value = value(rng);
                const int nc = contours(rng);
                for (int ci = 0; ci < nc; ++ci) {
                    Contour c;
                    const int nv = vertices(rng);
                    for (int k = 0; k < nv; ++k) c.push_back({x(rng), y(rng)});
                    shape.contours.push_back(c);
                }
                scene.shapes.push_back(shape);
            }
            const Image out = render_scene(*m.method, scene);
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    const double want = slow_third_lattice_pixel(scene, i, j, sigma);
                    worst = std::max(worst, std::abs(out.at(i, j) - want));
                    ++pixels;
                    ASSERT_NEAR(out.at(i, j), want, kAgreement)
                        << fmt::format("{} seed {} pixel ({}, {})", m.spec, seed, i, j);
                }
            }
        }
    }
    RecordProperty("worst_difference", fmt::format("{:.3g}", worst));
    std::printf("nishita-d vs slow implementation: worst |difference| %.3g over %d pixels\n", worst,
                pixels);
}

// On a flat scene whose values are multiples of one power of two, the rows with few changes are
// summed from the steps in fixed point, the float32 decided within a bounded slack (and summed in
// window order where undecided); the same scene with its values as constant planes is summed in
// window order at every pixel. The two images must be the same bit for bit, for small sigmas
// too (weights that the fixed point loses) and on the half lattice.
TEST(NishitaD, StepSumsEqualWindowOrderSumsBitForBit) {
    std::vector<Scene> scenes;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        scenes.push_back(
            testing::with_dyadic_values(testing::random_scene(seed, 23, 17, true), seed));
    }
    scenes.push_back(make_pattern("star", 48, 40));
    for (const char* spec :
         {"nishita-d", "nishita-d:sigma=0.05", "nishita-d:sigma=3", "nishita-d:lattice=half"}) {
        const MethodInstance m = make_method(spec);
        for (std::size_t n = 0; n < scenes.size(); ++n) {
            const Image by_steps = render_scene(*m.method, scenes[n]);
            const Image in_order =
                render_scene(*m.method, testing::with_constant_planes(scenes[n]));
            for (std::size_t p = 0; p < by_steps.data.size(); ++p) {
                ASSERT_EQ(std::bit_cast<std::uint32_t>(by_steps.data[p]),
                          std::bit_cast<std::uint32_t>(in_order.data[p]))
                    << fmt::format("{} scene {} pixel {}: {} against {}", m.spec, n, p,
                                   by_steps.data[p], in_order.data[p]);
            }
        }
    }
}

TEST(NishitaD, ParametersAndReferenceFilter) {
    EXPECT_EQ(make_method("nishita-d").spec, "nishita-d:sigma=0.5,lattice=third");
    EXPECT_EQ(make_method("nishita-d:lattice=half").spec, "nishita-d:sigma=0.5,lattice=half");
    EXPECT_EQ(make_method("nishita-d").method->filter().text(), "gaussian:sigma=0.5,radius=1");
    EXPECT_EQ(make_method("nishita-d:sigma=1.25").method->filter().text(),
              "gaussian:sigma=1.25,radius=1");
    EXPECT_THROW(make_method("nishita-d:lattice=quarter"), InputError);
    for (const char* spec : {"nishita-d:sigma=0.01", "nishita-d:sigma=11"}) {
        try {
            make_method(spec);
            FAIL() << spec << ": no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("0.05..10"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace aabench
