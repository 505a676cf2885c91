// Exact curves: the closed-form disc ∩ pixel area against adaptive 1-D integration of the chord
// length (an independent formulation), the composite of curve shapes, the polygonisation's
// bound, and the scene file's disc and ring (reader strictness, writer exact).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "filter_quadrature.h"
#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "methods/scan/reference/box_coverage.h"
#include "methods/scan/reference/curve_coverage.h"
#include "patterns/scene/curves.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

// The closed form's promise, per pixel (docs/architecture.md).
constexpr double kAreaTolerance = 1e-12;
// The quadrature's own target per unit of angle, relative to the radius (the integrand is
// r cos(phi) times a chord <= 1.5, so its rounding is ~1e-16 r per unit), times max(r, 1): the
// error summed over the angle range (<= pi; ~2 / r wide for r > 1) stays <= ~3e-14.
constexpr double kQuadratureTolerancePerUnit = 1e-14;

// Area of the disc (centre 0, radius r) in [u0, u0+1] x [v0, v0+1] by integrating the length of
// the vertical chord at u, clipped to the square. With u = r sin(phi) the chord's half-length
// is r cos(phi) and du = r cos(phi) dphi, so the integrand is smooth in phi except where the
// clipped chord changes form (r cos(phi) = |v0| or |v0 + 1|): the pieces are split there.
double chord_integral_area(double u0, double v0, double r) {
    const double v1 = v0 + 1.0;
    const double lo = std::asin(std::clamp(u0 / r, -1.0, 1.0));
    const double hi = std::asin(std::clamp((u0 + 1.0) / r, -1.0, 1.0));
    if (!(lo < hi)) return 0.0;
    auto integrand = [&](double phi) {
        const double h = r * std::cos(phi);
        const double len = std::max(0.0, std::min(v1, h) - std::max(v0, -h));
        return len * r * std::cos(phi);
    };
    std::vector<double> cuts = {lo, hi};
    for (double v : {v0, v1}) {
        if (std::abs(v) < r) {
            const double phi = std::acos(std::abs(v) / r);
            for (double p : {phi, -phi}) {
                if (p > lo && p < hi) cuts.push_back(p);
            }
        }
    }
    std::sort(cuts.begin(), cuts.end());
    double sum = 0.0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double a = cuts[k], b = cuts[k + 1];
        sum += testing::adaptive(integrand, a, b, testing::gauss_legendre(integrand, a, b),
                                 kQuadratureTolerancePerUnit * std::max(r, 1.0), 0);
    }
    return sum;
}

TEST(DiscSquareArea, AgreesWithChordIntegrationOnRandomSquares) {
    std::mt19937_64 rng(12);
    double worst = 0.0;
    for (int trial = 0; trial < 20000; ++trial) {
        // Radii from tiny to 300 px; squares placed around the boundary circle, where it
        // matters (inside and outside are 1 and 0 by the quick tests).
        const double r = std::exp(std::uniform_real_distribution<double>(std::log(0.05), std::log(300.0))(rng));
        const double angle = std::uniform_real_distribution<double>(0.0, 2.0 * std::numbers::pi)(rng);
        const double jitter = std::uniform_real_distribution<double>(-1.5, 0.5)(rng);
        const double u0 = std::floor(r * std::cos(angle) + jitter) + (trial % 3 == 0 ? 0.0 : std::uniform_real_distribution<double>(0, 1)(rng));
        const double v0 = std::floor(r * std::sin(angle) + jitter) + (trial % 5 == 0 ? 0.0 : std::uniform_real_distribution<double>(0, 1)(rng));
        const double got = disc_square_area(u0, v0, r);
        const double want = chord_integral_area(u0, v0, r);
        worst = std::max(worst, std::abs(got - want));
        ASSERT_LE(std::abs(got - want), kAreaTolerance)
            << fmt::format("trial {} r={:.17g} u0={:.17g} v0={:.17g}: closed form {:.17g}, chords {:.17g}",
                           trial, r, u0, v0, got, want);
    }
    RecordProperty("worst_abs_difference", fmt::format("{:.3g}", worst));
    std::printf("disc_square_area vs chord integration: worst |difference| %.3g over 20000 squares\n", worst);
}

TEST(DiscSquareArea, SpecialCases) {
    EXPECT_EQ(disc_square_area(-0.5, -0.5, 0.25), std::numbers::pi * 0.0625);  // inside
    EXPECT_EQ(disc_square_area(2.0, 2.0, 1.0), 0.0);
    EXPECT_EQ(disc_square_area(-0.5, -0.5, 10.0), 1.0);
    EXPECT_NEAR(disc_square_area(0.0, 0.0, 1.0), std::numbers::pi / 4.0, 1e-15);  // a quarter
    EXPECT_NEAR(disc_square_area(-0.5, 0.0, 0.5), std::numbers::pi / 8.0, 1e-15);  // a half
    // A disc through the four corners: the square is inside, up to the corners.
    EXPECT_NEAR(disc_square_area(-0.5, -0.5, std::sqrt(0.5)), 1.0, 1e-15);
}

Scene blank(int w, int h) {
    Scene s;
    s.width = w;
    s.height = h;
    return s;
}

TEST(CurveCoverage, RingAreaIsConserved) {
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 50; ++trial) {
        Scene s = blank(64, 64);
        const Point c{32.0 + std::uniform_real_distribution<double>(-1, 1)(rng),
                      32.0 + std::uniform_real_distribution<double>(-1, 1)(rng)};
        const double inner = std::uniform_real_distribution<double>(0.1, 10.0)(rng);
        const double outer = inner + std::uniform_real_distribution<double>(0.01, 20.0)(rng);
        s.shapes.push_back(ring_shape(c, inner, outer, 1.0));
        const Coverage cov = box_reference(s);
        double sum = 0.0;
        for (double v : cov.data) sum += v;
        const double want = std::numbers::pi * (outer * outer - inner * inner);
        // Sum of 4096 pixels each within 1e-12 (a bound per pixel, not relative).
        EXPECT_NEAR(sum, want, 4096 * kAreaTolerance) << trial;
    }
}

TEST(CurveCoverage, CompositesInShapeOrder) {
    // Touching concentric rings (disjoint), a disc on a square covering whole pixels, a disc
    // under a later square: each pixel composited exactly.
    Scene s = blank(32, 32);
    s.background = 0.25;
    s.shapes.push_back({{{{2, 2}, {30, 2}, {30, 30}, {2, 30}}}, 0.5});
    s.shapes.push_back(ring_shape({16.5, 16.5}, 3.5, 4.5, 1.0));
    s.shapes.push_back(ring_shape({16.5, 16.5}, 4.5, 5.5, 0.75));
    s.shapes.push_back(disc_shape({8.3, 8.7}, 2.2, 0.0));
    const Coverage cov = box_reference(s);
    for (int j = 0; j < 32; ++j) {
        for (int i = 0; i < 32; ++i) {
            const bool in_square = i >= 2 && i < 30 && j >= 2 && j < 30;
            const double a1 = disc_square_area(i - 16.5, j - 16.5, 4.5) - disc_square_area(i - 16.5, j - 16.5, 3.5);
            const double a2 = disc_square_area(i - 16.5, j - 16.5, 5.5) - disc_square_area(i - 16.5, j - 16.5, 4.5);
            const double a3 = disc_square_area(i - 8.3, j - 8.7, 2.2);
            const double base = in_square ? 0.5 : 0.25;
            const double want = base * (1 - a1 - a2 - a3) + 1.0 * a1 + 0.75 * a2 + 0.0 * a3;
            ASSERT_NEAR(cov.at(i, j), want, 4 * kAreaTolerance) << i << "," << j;
        }
    }
}

// Float32 output of a value within [0, 1]: rounded once, 2^-24 relative, well below this.
constexpr double kFloatOutputTolerance = 1e-7;

TEST(CurveCoverage, RowsOfAnyBandAreTheCompositeOfDisjointCurves) {
    // Discs and rings about centres 30 px apart (so disjoint), some partly or wholly outside
    // the image, on a background: every pixel is background + sum of (value - background) x
    // area, from disc_square_area directly. curve_rows computes only the rows asked and only
    // the pixels the curves' boxes reach; the rest of each row must be the background, and
    // rows outside the band untouched.
    std::mt19937_64 rng(20261124);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        const int w = 20 + static_cast<int>(rng() % 90), h = 20 + static_cast<int>(rng() % 90);
        Scene s = blank(w, h);
        s.background = 0.1 + 0.3 * u(rng);
        struct Placed {
            Point c;
            double inner, outer, value;
        };
        std::vector<Placed> placed;
        for (double cy = -10.0; cy < h + 10.0; cy += 30.0) {
            for (double cx = -10.0; cx < w + 10.0; cx += 30.0) {
                const Point c{cx + 3.0 * u(rng), cy + 3.0 * u(rng)};
                const double outer = 0.3 + 12.0 * u(rng);
                const double inner = u(rng) < 0.5 ? 0.0 : outer * u(rng);
                const double value = u(rng);
                placed.push_back({c, inner, outer, value});
                s.shapes.push_back(inner > 0.0 ? ring_shape(c, inner, outer, value)
                                               : disc_shape(c, outer, value));
            }
        }
        const int lo = static_cast<int>(rng() % h), hi = lo + 1 + static_cast<int>(rng() % (h - lo));
        Image out(w, h, -1.0f);
        curve_rows(s, out, lo, hi);
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                if (j < lo || j >= hi) {
                    ASSERT_EQ(out.at(i, j), -1.0f) << "trial " << trial << ": row " << j
                                                   << " outside the band [" << lo << ", " << hi << ")";
                    continue;
                }
                double want = s.background;
                for (const Placed& p : placed) {
                    const double a = disc_square_area(i - p.c.x, j - p.c.y, p.outer) -
                                     (p.inner > 0.0 ? disc_square_area(i - p.c.x, j - p.c.y, p.inner) : 0.0);
                    want += (p.value - s.background) * a;
                }
                ASSERT_NEAR(out.at(i, j), want, kFloatOutputTolerance)
                    << "trial " << trial << ": pixel (" << i << ", " << j << ")";
            }
        }
    }
}

// Where two shapes cover a pixel in part and may overlap there, the rows of such pixels are
// swept with the circles as quarter arcs: the totals of the images equal the closed forms of
// the areas (a lens of two discs, a disc's segment beyond a chord), every pixel of the overlap
// a partial cover of both.
TEST(CurveCoverage, ResolvesPartialOverlapsExactly) {
    double total = 0.0;
    Scene s = blank(16, 16);
    const double r1 = 3.3, r2 = 2.7, d = std::hypot(10.1 - 8.2, 8.4 - 8.1);
    s.shapes.push_back(disc_shape({8.2, 8.1}, r1, 1.0));
    s.shapes.push_back(disc_shape({10.1, 8.4}, r2, 0.5));  // over the first one's edge
    for (double v : box_reference(s).data) total += v;
    const double lens = r1 * r1 * std::acos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1)) +
                        r2 * r2 * std::acos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2)) -
                        0.5 * std::sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) *
                                        (d + r1 + r2));
    EXPECT_NEAR(total, std::numbers::pi * r1 * r1 - lens + 0.5 * std::numbers::pi * r2 * r2,
                kAreaTolerance * 16 * 16);
    Scene p = blank(16, 16);
    p.shapes.push_back(disc_shape({8.2, 8.1}, r1, 1.0));
    p.shapes.push_back({{{{8.5, 0.3}, {15, 0.3}, {15, 15}, {8.5, 15}}}, 0.5});  // edge in the disc
    total = 0.0;
    for (double v : box_reference(p).data) total += v;
    const double h = 8.5 - 8.2;
    const double beyond = r1 * r1 * std::acos(h / r1) - h * std::sqrt(r1 * r1 - h * h);
    EXPECT_NEAR(total, std::numbers::pi * r1 * r1 - beyond + 0.5 * (15 - 8.5) * (15 - 0.3),
                kAreaTolerance * 16 * 16);
}

TEST(CurveCoverage, FarWindowOriginDrawsNothingAndStaysInIntRange) {
    // A window 3e9 px from a disc: the centre in the window frame is beyond int range (the
    // bounding box was once cast to int before clamping, undefined behaviour under UBSan).
    Scene scene;
    scene.width = 8;
    scene.height = 6;
    scene.background = 0.25;
    scene.origin_x = 3e9;
    scene.origin_y = -3e9;
    scene.shapes.push_back(disc_shape({0.5, 0.5}, 3.0, 1.0));
    const Scene window = window_scene(scene);
    const Coverage ref = box_reference(window);
    for (double v : ref.data) ASSERT_EQ(v, 0.25);
    Image out(scene.width, scene.height, -1.0f);
    curve_rows(window, out, 0, scene.height);
    for (float v : out.data) ASSERT_EQ(v, 0.25f);
}

TEST(Polygonisation, SagittaWithinTheBound) {
    for (double r : {0.5, 1.0, 3.7, 10.0, 99.5, 200.5, 1000.0}) {
        const int n = curve_segment_count(r);
        EXPECT_LE(polygon_sagitta(r, n), kCurveSagittaPx) << r;
        EXPECT_GT(polygon_sagitta(r, n - 1), kCurveSagittaPx) << r;  // and no more segments than needed
        const Contour c = circle_polygon({3.5, 4.5}, r, true);
        EXPECT_GT(twice_signed_area(c), 0.0);
        // Every chord's midpoint lies within the sagitta of the circle.
        for (std::size_t k = 0; k < c.size(); k += std::max<std::size_t>(1, c.size() / 97)) {
            const Point& a = c[k];
            const Point& b = c[(k + 1) % c.size()];
            const double d = std::hypot(0.5 * (a.x + b.x) - 3.5, 0.5 * (a.y + b.y) - 4.5);
            EXPECT_LE(r - d, kCurveSagittaPx * (1 + 1e-6) + 1e-13 * r) << r;
        }
    }
}

TEST(Polygonisation, MovesNoPixelByMoreThanItsBound) {
    // The polygon engine on the polygonisation against the curve engine: within the sagitta
    // times the boundary length in a pixel (<= ~1.5 px of arc per circle; two circles a ring).
    constexpr double kBound = 2 * 1.5 * kCurveSagittaPx;
    Scene s = blank(48, 48);
    s.shapes.push_back(ring_shape({20.5, 22.5}, 6.5, 7.5, 1.0));
    s.shapes.push_back(disc_shape({38.3, 9.9}, 5.25, 1.0));
    s.shapes.push_back(disc_shape({5.5, 40.5}, 0.5, 1.0));
    const Coverage exact = box_reference(s);
    Scene polygons = s;
    for (Shape& shape : polygons.shapes) shape.circle.reset();
    const Coverage poly = box_coverage(polygons);
    double worst = 0.0;
    for (std::size_t k = 0; k < exact.data.size(); ++k) {
        worst = std::max(worst, std::abs(exact.data[k] - poly.data[k]));
    }
    EXPECT_LE(worst, kBound);
    EXPECT_GT(worst, 0.0);  // the test sees the polygonisation at all
}

TEST(SceneFile, DiscAndRingRoundTrip) {
    Scene s = blank(20, 10);
    s.shapes.push_back(disc_shape({4.25, 5.5}, 3.0, 0.75));
    s.shapes.push_back(ring_shape({14.5, 5.5}, 2.5, 3.5, 1.0));
    s.shapes.push_back({{{{1, 1}, {2, 1}, {2, 2}}}, 0.5});
    const std::string text = scene_to_json(s);
    EXPECT_NE(text.find("\"version\": 2"), std::string::npos);
    EXPECT_NE(text.find("\"type\": \"disc\""), std::string::npos);
    EXPECT_NE(text.find("\"inner\": 2.5"), std::string::npos);
    EXPECT_EQ(parse_scene_json(text, "t.json"), s);
}

void expect_error(const std::string& text, const std::string& path_and_message) {
    try {
        parse_scene_json(text, "t.json");
        FAIL() << "accepted: " << text;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(path_and_message), std::string::npos) << e.what();
    }
}

TEST(SceneFile, DiscAndRingErrorsNameTheirPath) {
    const std::string head = R"({"version": 2, "width": 8, "height": 8, "shapes": [)";
    expect_error(head + R"({"type": "disc", "center": [1, 2]}]})", "shapes[0].radius");
    expect_error(head + R"({"type": "disc", "center": [1, 2], "radius": -1}]})", "shapes[0].radius");
    expect_error(head + R"({"type": "disc", "center": [1], "radius": 1}]})", "shapes[0].center");
    expect_error(head + R"({"type": "disc", "center": [1, 2], "radius": 1, "inner": 0.5}]})",
                 "shapes[0].inner");
    expect_error(head + R"({"type": "ring", "center": [1, 2], "inner": 3, "outer": 2}]})",
                 "shapes[0].inner");
    expect_error(head + R"({"type": "ring", "center": [1, 2], "inner": 3}]})", "shapes[0].outer");
    expect_error(head + R"({"type": "ring", "center": [1, 2], "inner": 1, "outer": 2, "value": "x"}]})",
                 "shapes[0].value");
    expect_error(R"({"width": 8, "height": 8, "shapes": [{"type": "disc", "center": [1, 2], "radius": 1}]})",
                 "shapes[0].type");
}

}  // namespace
}  // namespace aabench
