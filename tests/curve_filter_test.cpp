// The radial references of discs and rings against brute-force quadrature: the filter's mass
// over a disc by nested Cartesian quadrature (vertical chords of the disc within the support,
// the 2-D integrand itself) against the polar 1-D form of curve_filter_reference.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "filter_quadrature.h"
#include "harness/reference/curve_filter_reference.h"
#include "harness/reference/filter_reference.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

// The radial references' promise, per pixel (docs/architecture.md).
constexpr double kRadialTolerance = 1e-10;
// The brute force's own target, per unit length of each integration (lengths <= 2R <= 5 px,
// so the total stays <= ~1e-11): below the bound.
constexpr double kBruteTolerancePerUnit = 2e-12;

// The filter mass over the disc of radius rho centred at (d, 0), the filter at the origin:
// integral over x of 2 * integral_0^Y(x) f(sqrt(x^2 + y^2)) dy, Y(x) the half-height of the
// disc ∩ support at x. The inner integral in closed form (so the outer integrand is a smooth
// deterministic function of x, which adaptive quadrature can resolve): for the Gaussian
// A exp(-x^2 / 2s^2) s sqrt(pi / 2) erf(Y / (s sqrt 2)); for the cone c (Y - (Y r + x^2
// ln((Y + r) / |x|)) / (2R)), r = sqrt(x^2 + Y^2). The outer integral is split at x = 0 (the
// filter's peak) and where the two circles cross, and integrated by adaptive Gauss-Legendre.
double brute_mass(const Filter& filter, double d, double rho) {
    const double R = filter.radius_px();
    const double lo = std::max(-R, d - rho), hi = std::min(R, d + rho);
    if (!(lo < hi)) return 0.0;
    const double peak = filter.value(0.0);  // A for the Gaussian, c for the cone
    const bool gaussian = filter.kind() == FilterKind::kGaussian;
    auto inner = [&](double x) {
        // Differences of squares factored: rho^2 - (x - d)^2 = (rho - d + x)(rho + d - x), with
        // rho - d exact (Sterbenz), so no cancellation noise near the ends (noise there would
        // keep the adaptive outer integral from ever settling).
        const double y_support = std::sqrt(std::max(0.0, (R - x) * (R + x)));
        const double y_disc = std::sqrt(std::max(0.0, ((rho - d) + x) * ((rho + d) - x)));
        const double top = std::min(y_support, y_disc);
        if (!(top > 0.0)) return 0.0;
        if (gaussian) {
            const double s = filter.sigma_px();
            return 2.0 * peak * std::exp(-x * x / (2 * s * s)) * s * std::sqrt(std::numbers::pi / 2) *
                   std::erf(top / (s * std::sqrt(2.0)));
        }
        const double r = std::hypot(x, top);
        const double log_term = x == 0.0 ? 0.0 : x * x * std::log((top + r) / std::abs(x));
        return 2.0 * peak * (top - (top * r + log_term) / (2.0 * R));
    };
    std::vector<double> cuts = {lo, hi};
    if (lo < 0.0 && hi > 0.0) cuts.push_back(0.0);
    if (d > 0.0) {
        const double x_cross = (R * R - rho * rho + d * d) / (2.0 * d);
        if (x_cross > lo && x_cross < hi) cuts.push_back(x_cross);
    }
    std::sort(cuts.begin(), cuts.end());
    double sum = 0.0;
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        sum += testing::adaptive(inner, cuts[k], cuts[k + 1],
                                 testing::gauss_legendre(inner, cuts[k], cuts[k + 1]),
                                 kBruteTolerancePerUnit, 0);
    }
    return sum;
}

TEST(DiscFilterMass, AgreesWithBruteForceQuadrature) {
    std::mt19937_64 rng(1212);
    for (const std::string& spec : testing::kFilterSpecs) {
        const Filter filter = Filter::parse(spec);
        const double R = filter.radius_px();
        double worst = 0.0;
        for (int trial = 0; trial < 30; ++trial) {
            const double rho = std::exp(std::uniform_real_distribution<double>(std::log(0.2), std::log(200.0))(rng));
            // Centres around the boundary circle, inside and out, within the support's reach.
            double d = rho + std::uniform_real_distribution<double>(-1.2 * R, 1.2 * R)(rng);
            if (trial % 10 == 0) d = rho;  // on the circle
            if (trial % 10 == 1) d = rho * 1e-3;  // near the disc's centre
            d = std::max(0.0, d);
            if (std::getenv("AABENCH_TRACE")) std::fprintf(stderr, "%s d=%.17g rho=%.17g\n", spec.c_str(), d, rho);
            const double got = disc_filter_mass(filter, d, rho);
            if (std::getenv("AABENCH_TRACE")) std::fprintf(stderr, "  polar done\n");
            const double want = brute_mass(filter, d, rho);
            worst = std::max(worst, std::abs(got - want));
            ASSERT_LE(std::abs(got - want), kRadialTolerance)
                << fmt::format("{} d={:.17g} rho={:.17g}: polar {:.17g} brute {:.17g}", spec, d,
                               rho, got, want);
        }
        std::printf("%s: disc filter mass vs brute force, worst |difference| %.3g\n", spec.c_str(), worst);
    }
}

TEST(DiscFilterMass, LimitsAreExact) {
    const Filter g = Filter::parse("gaussian");
    EXPECT_EQ(disc_filter_mass(g, 0.3, 5.0), 1.0);   // support inside the disc
    EXPECT_EQ(disc_filter_mass(g, 6.1, 5.0), 0.0);   // apart
    // On a nearly straight edge: a half-plane through the centre, up to the curvature
    // (the support's second moment over the radius, ~1e-4 here).
    EXPECT_NEAR(disc_filter_mass(g, 1e4, 1e4 + 1e-9), 0.5, 1e-3);
}

TEST(CurveFilteredReference, RingsAndAFarPolygonComposeExactly) {
    Scene s;
    s.width = 24;
    s.height = 20;
    s.background = 0.25;
    s.shapes.push_back(ring_shape({10.5, 9.5}, 3.5, 4.5, 1.0));
    s.shapes.push_back(ring_shape({10.5, 9.5}, 4.5, 5.5, 0.5));
    s.shapes.push_back(disc_shape({20.2, 4.7}, 1.3, 0.0));
    s.shapes.push_back({{{{18, 12}, {23, 12}, {23, 19}, {18, 19}}}, 0.75});
    Scene polygon_only = s;
    polygon_only.shapes = {s.shapes[3]};
    for (const std::string& spec : {std::string("gaussian"), std::string("cone:radius=2.5")}) {
        const Filter f = Filter::parse(spec);
        const Coverage got = filtered_reference(s, f);
        const Coverage poly = filtered_reference(polygon_only, f);
        for (int j = 1; j < s.height; j += 5) {
            for (int i = 1; i < s.width; i += 4) {
                double want = poly.at(i, j);
                for (int k = 0; k < 3; ++k) {
                    const Circle& c = *s.shapes[k].circle;
                    const double d = std::hypot(i + 0.5 - c.center.x, j + 0.5 - c.center.y);
                    double mass = brute_mass(f, d, c.outer);
                    if (!c.is_disc()) mass -= brute_mass(f, d, c.inner);
                    want += (s.shapes[k].value - s.background) * mass;
                }
                ASSERT_NEAR(got.at(i, j), want, kRadialTolerance) << spec << " " << i << "," << j;
            }
        }
    }
}

// A disc on a square (their boxes overlap, so the closed form per curve does not apply and the
// scene is swept with the disc's quarter arcs): the visible value is the square's plus
// (1 - 0.5) over the disc, so the reference is the square's own plus 0.5 times the disc's
// filter mass at each pixel centre in polar form (disc_filter_mass, independent of the sweep).
TEST(CurveFilteredReference, DiscOnASquareIsTheSquarePlusTheDiscsMass) {
    Scene s;
    s.width = s.height = 16;
    s.shapes.push_back({{{{2, 2}, {14, 2}, {14, 14}, {2, 14}}}, 0.5});
    Scene square = s;
    s.shapes.push_back(disc_shape({8.5, 8.3}, 3.0, 1.0));  // on the square
    for (const char* spec : {"gaussian", "cone"}) {
        const Filter filter = Filter::parse(spec);
        const Coverage got = filtered_reference(s, filter);
        const Coverage base = filtered_reference(square, filter);
        for (int j = 0; j < 16; ++j) {
            for (int i = 0; i < 16; ++i) {
                const double d = std::hypot(i + 0.5 - 8.5, j + 0.5 - 8.3);
                ASSERT_NEAR(got.at(i, j), base.at(i, j) + 0.5 * disc_filter_mass(filter, d, 3.0),
                            kRadialTolerance)
                    << spec << " pixel (" << i << ", " << j << ")";
            }
        }
    }
}

}  // namespace
}  // namespace aabench
