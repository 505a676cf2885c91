// The filter family (methods/scan/kernel/filter.h), every member through the same checks, as
// pbrt's filter tests loop over every filter: zero past the radius, the closed-form 1-D
// integral along a line against numerical integration of the profile, unit volume, and the
// forms of the profile agreeing with each other. The references built on it are checked in
// filter_reference_test.cpp and filter_reference_brute_test.cpp, the methods' tables in
// gauss_multiscan_test.cpp.
#include "methods/scan/kernel/filter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "filter_quadrature.h"
#include "patterns/scene/scene.h"

namespace aabench {
namespace {

using testing::adaptive;
using testing::gauss_legendre;

constexpr double kPi = std::numbers::pi;

// Composite 10-point Gauss-Legendre on pieces of at most 1/32 px, each halved until its halves
// agree to kAdaptivePerUnit per unit length (filter_quadrature.h): the cone's sqrt(s^2 + y^2)
// bends within |y| of its apex, and its whole-line integral has a y^2 log|y| term there, where
// fixed pieces err by 1e-9; adaptively all the integrands below reach ~1e-15. The closed forms
// add a few roundings of O(1) terms.
constexpr double kQuadratureTolerance = 1e-13;
constexpr double kAdaptivePerUnit = 1e-15;
constexpr int kPiecesPerPx = 32;
// Two evaluations of the same exp or division in another order: a few ulps of values <= 1.
constexpr double kRoundingTolerance = 1e-15;

// Every filter a user or a method can name: the references' test set, the box, and the
// Gaussian of gauss_multiscan_test.cpp.
std::vector<Filter> family() {
    std::vector<Filter> out = {Filter::box(), Filter::parse("gaussian:sigma=0.3")};
    for (const std::string& spec : testing::kFilterSpecs) out.push_back(Filter::parse(spec));
    return out;
}

int pieces_over(double length) {
    return std::max(1, static_cast<int>(std::ceil(length * kPiecesPerPx)));
}

// The integral of fn over [lo, hi], lo <= hi, as kQuadratureTolerance above says.
double integrate(const std::function<double(double)>& fn, double lo, double hi) {
    const int pieces = pieces_over(hi - lo);
    double sum = 0.0;
    for (int k = 0; k < pieces; ++k) {
        const double a = lo + (hi - lo) * k / pieces, b = lo + (hi - lo) * (k + 1) / pieces;
        sum += adaptive(fn, a, b, gauss_legendre(fn, a, b), kAdaptivePerUnit, 0);
    }
    return sum;
}

TEST(Filter, ParsesBackFromItsTextAndRejectsWhatIsNotInTheFamily) {
    for (const Filter& f : family()) {
        EXPECT_EQ(Filter::parse(f.text()), f) << f.text();
        EXPECT_EQ(f.is_box(), f.kind() == FilterKind::kBox) << f.text();
    }
    EXPECT_EQ(Filter::parse("box"), Filter::box());
    EXPECT_EQ(Filter::box().text(), "box");
    try {
        Filter::parse("gausian");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "unknown filter 'gausian'; did you mean 'gaussian'? (valid: gaussian, cone); "
                  "or 'box'");
    }
}

TEST(Filter, VanishesPastItsRadius) {
    for (const Filter& f : family()) {
        const double radius = f.radius_px();
        ASSERT_GT(radius, 0.0) << f.text();
        EXPECT_GT(f.evaluate(0.0, 0.0), 0.0) << f.text();
        EXPECT_EQ(f.profile(0.0), 1.0) << f.text();
        for (const double beyond : {1.0000001, 1.5, 4.0}) {
            const double r = beyond * radius;
            EXPECT_EQ(f.profile(r), 0.0) << f.text() << " r " << r;
            EXPECT_EQ(f.evaluate(r, 0.0), 0.0) << f.text();
            EXPECT_EQ(f.evaluate(0.0, -r), 0.0) << f.text();
            // Past the radius in y, the whole line misses the support.
            EXPECT_EQ(f.profile_line_integral(r, 10.0 * radius), 0.0) << f.text();
            EXPECT_EQ(f.profile_line_integral(-r, 10.0 * radius), 0.0) << f.text();
            if (!f.is_box()) {
                EXPECT_EQ(f.evaluate(r / std::numbers::sqrt2, r / std::numbers::sqrt2), 0.0)
                    << f.text();
                EXPECT_EQ(f.profile_r2(r * r), 0.0) << f.text();
                // F stops growing at the radius.
                EXPECT_EQ(f.radial_integral(r), f.radial_integral(radius)) << f.text();
            }
        }
        // The line integral stops growing where the line leaves the support.
        for (const double y : {0.0, 0.3 * radius, 0.9 * radius}) {
            const double end = f.is_box() ? radius : std::sqrt(radius * radius - y * y);
            EXPECT_EQ(f.profile_line_integral(y, 1.5 * end), f.profile_line_integral(y, end))
                << f.text() << " y " << y;
            EXPECT_EQ(f.profile_line_integral(y, 0.0), 0.0) << f.text();
        }
    }
}

TEST(Filter, LineIntegralMatchesQuadratureOfTheProfile) {
    for (const Filter& f : family()) {
        const double radius = f.radius_px();
        for (const double fraction : {0.0, 1e-3, 0.2, 1.0 / 3.0, 0.5, 0.7, 0.99}) {
            const double y = fraction * radius;
            const double support = f.is_box() ? radius : std::sqrt(radius * radius - y * y);
            // The box's profile is separable: along x times along y.
            auto integrand = [&](double s) {
                return f.is_box() ? f.profile(s) * f.profile(y) : f.profile(std::hypot(s, y));
            };
            for (const double x_fraction : {0.05, 0.3, 0.5, 0.9, 1.0, 1.7}) {
                const double x = x_fraction * radius;
                const double end = std::min(x, support);
                const double want = integrate(integrand, 0.0, end);
                EXPECT_NEAR(f.profile_line_integral(y, x), want, kQuadratureTolerance)
                    << f.text() << " y " << y << " x " << x;
                // The line is symmetric about the centre's foot.
                EXPECT_EQ(f.profile_line_integral(-y, x), f.profile_line_integral(y, x))
                    << f.text();
            }
        }
    }
}

TEST(Filter, HasUnitVolume) {
    for (const Filter& f : family()) {
        // Volume = amplitude * integral over y of the whole line's integral, 2 L(y, R); with
        // y = R sin(theta) the integrand is smooth up to the support's ends (L ~ R cos(theta)
        // there); the cone's apex at theta = 0 is a cut.
        const double radius = f.radius_px();
        auto slice = [&](double theta) {
            return 2.0 * f.profile_line_integral(radius * std::sin(theta), radius) * radius *
                   std::cos(theta);
        };
        const double volume =
            f.amplitude() * (integrate(slice, -0.5 * kPi, 0.0) + integrate(slice, 0.0, 0.5 * kPi));
        EXPECT_NEAR(volume, 1.0, kQuadratureTolerance) << f.text();
        if (f.is_box()) {
            EXPECT_TRUE(std::isnan(f.value(0.0)));
            EXPECT_TRUE(std::isnan(f.radial_integral(0.5)));
            continue;
        }
        // The polar form: 2 pi F(R) = 1, and F against quadrature of f(r) r.
        EXPECT_NEAR(2.0 * kPi * f.radial_integral(radius), 1.0, kQuadratureTolerance) << f.text();
        auto ring = [&](double r) { return f.value(r) * r; };
        for (const double fraction : {0.1, 0.5, 0.9}) {
            const double r = fraction * radius;
            EXPECT_NEAR(f.radial_integral(r), integrate(ring, 0.0, r), kQuadratureTolerance)
                << f.text() << " r " << r;
        }
    }
}

TEST(Filter, ProfileFormsAgree) {
    for (const Filter& f : family()) {
        const double radius = f.radius_px();
        for (const double fraction : {0.0, 0.25, 0.5, 0.8, 1.0}) {
            const double r = fraction * radius;
            const double p = f.profile(r);
            EXPECT_NEAR(f.evaluate(r, 0.0), f.amplitude() * p, kRoundingTolerance * f.amplitude())
                << f.text();
            if (f.is_box()) continue;
            EXPECT_NEAR(f.value(r), f.amplitude() * p, kRoundingTolerance * f.amplitude());
            EXPECT_NEAR(f.profile_r2(r * r), p, kRoundingTolerance) << f.text() << " r " << r;
            // On a lattice of 6 steps per pixel, the point (3, 4) steps is 5/6 px away.
            if (5.0 / 6.0 <= radius) {
                EXPECT_NEAR(f.profile_on_lattice(25.0, 6.0), f.profile(5.0 / 6.0),
                            kRoundingTolerance)
                    << f.text();
            }
        }
    }
}

// The cone's 1-D integral, written once for the methods and the references.
TEST(Filter, DistanceLineIntegralMatchesQuadrature) {
    for (const double d : {0.0, 1e-9, 0.1, 0.5, -0.5, 2.0}) {
        auto distance = [&](double s) { return std::hypot(s, d); };
        for (const double t : {0.0, 0.3, 1.0, 2.5, -0.7}) {
            const double lo = std::min(0.0, t), hi = std::max(0.0, t);
            const double want = (t < 0.0 ? -1.0 : 1.0) * integrate(distance, lo, hi);
            EXPECT_NEAR(distance_line_integral(t, d), want, kQuadratureTolerance)
                << "t " << t << " d " << d;
        }
    }
}

}  // namespace
}  // namespace aabench
