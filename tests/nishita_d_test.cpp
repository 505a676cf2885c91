// nishita-d: a constant scene gives its value; the response to one lit lattice point is the
// normalised radius-1 Gaussian, computed here independently; the weights are symmetric; the
// half-pixel margin outside the image is sampled; parameter range and reference filter.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "methods/method.h"

namespace aabench {
namespace {

// Output is float32 rounded once from a double sum of 25 terms in [0, 1] (error ~1e-15): one
// float32 ulp at 1.0 covers it.
constexpr double kFloatSlack = FLT_EPSILON;

// The expected weight of a lattice point at distance r (px) from a pixel centre: the
// radius-1 Gaussian, normalised over the 13 lattice points of the 5 x 5 window with r <= 1
// (1 centre, 4 at r = 1/2, 4 at r = sqrt(2)/2, 4 at r = 1).
double expected_weight(double r, double sigma) {
    auto g = [&](double d) { return std::exp(-d * d / (2.0 * sigma * sigma)); };
    const double total = g(0.0) + 4.0 * g(0.5) + 4.0 * g(std::sqrt(0.5)) + 4.0 * g(1.0);
    return r <= 1.0 ? g(r) / total : 0.0;
}

// A square of side 0.1 around (x, y): it contains exactly one lattice point (spacing 1/2) and
// its edges pass through none.
Scene impulse_at(double x, double y, int width = 8, int height = 7) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.shapes.push_back(
        {{{{x - 0.05, y - 0.05}, {x + 0.05, y - 0.05}, {x + 0.05, y + 0.05}, {x - 0.05, y + 0.05}}},
         1.0});
    return scene;
}

void expect_response(const std::string& spec, double sigma, double x, double y) {
    const Image out = render_scene(*make_method(spec).method, impulse_at(x, y));
    for (int j = 0; j < out.height; ++j) {
        for (int i = 0; i < out.width; ++i) {
            const double r = std::hypot(i + 0.5 - x, j + 0.5 - y);
            const double want = expected_weight(r, sigma);
            ASSERT_NEAR(out.at(i, j), want, kFloatSlack) << fmt::format(
                "{} impulse at ({}, {}) pixel ({}, {}) r = {}: got {} want {}", spec, x, y, i, j,
                r, out.at(i, j), want);
        }
    }
}

TEST(NishitaD, ConstantSceneGivesItsValue) {
    // The shape covers the image and the half-pixel margin the lattice reaches into.
    Scene scene;
    scene.width = 11;
    scene.height = 6;
    scene.background = 0.1;
    scene.shapes.push_back({{{{-2, -2}, {13, -2}, {13, 8}, {-2, 8}}}, 0.7});
    for (double sigma : {0.05, 0.5, 1.0, 10.0}) {
        const MethodInstance m = make_method(fmt::format("nishita-d:sigma={}", sigma));
        const Image out = render_scene(*m.method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                ASSERT_NEAR(out.at(i, j), 0.7, kFloatSlack)
                    << fmt::format("{} pixel ({}, {}) = {}", m.spec, i, j, out.at(i, j));
            }
        }
    }
}

// One lit lattice point at a pixel centre, a pixel corner (shared by four pixels) and an edge
// midpoint (shared by two): every pixel shows the weight of that point in its window.
TEST(NishitaD, ResponseToOneLatticePointIsTheNormalisedGaussian) {
    for (double sigma : {0.5, 0.8}) {
        const std::string spec = fmt::format("nishita-d:sigma={}", sigma);
        expect_response(spec, sigma, 3.5, 3.5);  // centre: 1 pixel at r = 0, 4 at r = 1
        expect_response(spec, sigma, 4.0, 3.0);  // corner: 4 pixels at r = sqrt(2)/2
        expect_response(spec, sigma, 3.5, 3.0);  // edge midpoint: 2 pixels at r = 1/2
        expect_response(spec, sigma, 4.0, 3.5);  // vertical edge midpoint
    }
}

// Shapes outside the image reach the border pixels through the lattice's half-pixel margin:
// the lattice column x = -1/2, the rows y = -1/2, y = h (the bottom border line, sampled with
// the same half-open rule as interior lines) and y = h + 1/2.
TEST(NishitaD, MarginOutsideTheImageIsSampled) {
    const double sigma = 0.5;
    const int w = 8, h = 7;
    expect_response("nishita-d", sigma, -0.5, 3.5);
    expect_response("nishita-d", sigma, 3.5, -0.5);
    expect_response("nishita-d", sigma, 3.5, h + 0.5);
    expect_response("nishita-d", sigma, w + 0.5, 2.5);
    expect_response("nishita-d", sigma, 2.0, h);
}

// The weights depend on distance only: an image of a mirrored or transposed scene is the
// mirrored or transposed image. Random vertices keep lattice points off edges (the tie rule
// is not symmetric).
TEST(NishitaD, SymmetricUnderMirrorsAndTranspose) {
    // The same 25-term sum in another order: a few double ulps, one float32 step at most.
    constexpr double kSymmetryTolerance = kFloatSlack;
    const MethodInstance m = make_method("nishita-d");
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
                        << fmt::format("seed {} variant {} pixel ({}, {}): {} vs {}", seed,
                                       variant, i, j, base.at(i, j), img.at(px, py));
                }
            }
        }
    }
}

TEST(NishitaD, ParametersAndReferenceFilter) {
    EXPECT_EQ(make_method("nishita-d").spec, "nishita-d:sigma=0.5");
    EXPECT_EQ(make_method("nishita-d").method->filter().text(), "gaussian:sigma=0.5,radius=1");
    EXPECT_EQ(make_method("nishita-d:sigma=1.25").method->filter().text(),
              "gaussian:sigma=1.25,radius=1");
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
