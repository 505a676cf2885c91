// The filter family (methods/scan/kernel/filter.h): construction, parsing, closed forms.
#include "methods/scan/kernel/filter.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "patterns/scene/scene.h"

namespace aabench {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kInvTwoPi = 1.0 / kTwoPi;
// The box's half side: the pixel square [-1/2, 1/2]^2 about the centre.
constexpr double kBoxRadiusPx = 0.5;

const std::vector<ParamSpec>& gaussian_params() {
    // clang-format off
    static const std::vector<ParamSpec> table = {
        {"sigma", ParamKind::kReal, 0.5, 0.05, 10.0, {},
         "standard deviation in pixels; 0.5 is the multiscan methods' default"},
        {"radius", ParamKind::kReal, 1.0, 0.25, 8.0, {},
         "support radius in pixels (truncated and renormalised); the paper's one pixel"},
    };
    // clang-format on
    return table;
}

const std::vector<ParamSpec>& cone_params() {
    // clang-format off
    static const std::vector<ParamSpec> table = {
        {"radius", ParamKind::kReal, 1.0, 0.25, 8.0, {},
         "support radius in pixels; the paper's one pixel"},
    };
    // clang-format on
    return table;
}

// A radial filter's spec ("box" is not one): its own messages, which parse() extends by the box.
Filter parse_radial(const std::string& text) {
    const SpecString spec = parse_spec_string(text);
    if (spec.id == "gaussian") {
        const ParamValues values =
            resolve_params("filter 'gaussian'", gaussian_params(), spec.assignments);
        return Filter::gaussian(values.get_real("sigma"), values.get_real("radius"));
    }
    if (spec.id == "cone") {
        const ParamValues values = resolve_params("filter 'cone'", cone_params(), spec.assignments);
        return Filter::cone(values.get_real("radius"));
    }
    throw InputError(fmt::format("unknown filter '{}'{} (valid: gaussian, cone)", spec.id,
                                 did_you_mean(spec.id, {"box", "gaussian", "cone"})));
}

}  // namespace

Filter::Filter(FilterKind kind, double sigma_px, double radius_px)
    : kind_(kind), sigma_px_(sigma_px), radius_px_(radius_px) {
    // The closed forms (filter_reference.cpp derives them): the Gaussian f = A exp(-r^2 / (2
    // s^2)) has F = A s^2 (1 - exp(-r^2 / (2 s^2))); the cone f = c (1 - r / R) has F = c (r^2 /
    // 2 - r^3 / (3R)). F(R) = 1 / (2 pi) fixes A and c.
    if (kind_ == FilterKind::kGaussian) {
        inv_two_sigma2_ = 1.0 / (2.0 * sigma_px_ * sigma_px_);
        // expm1 keeps 1 - exp(-R^2 / (2 s^2)) accurate when sigma >> R.
        a_sigma2_ = kInvTwoPi / -std::expm1(-radius_px_ * radius_px_ * inv_two_sigma2_);
        amplitude_ = a_sigma2_ / (sigma_px_ * sigma_px_);
    } else if (kind_ == FilterKind::kCone) {
        amplitude_ = 3.0 / (std::numbers::pi * radius_px_ * radius_px_);
    }
}

Filter Filter::gaussian(double sigma_px, double radius_px) {
    return Filter(FilterKind::kGaussian, sigma_px, radius_px);
}

Filter Filter::cone(double radius_px) { return Filter(FilterKind::kCone, 0.0, radius_px); }

Filter Filter::parse(const std::string& text) {
    if (text == "box") return box();
    try {
        return parse_radial(text);
    } catch (const InputError& e) {
        throw InputError(std::string(e.what()) + "; or 'box'");
    }
}

std::string Filter::text() const {
    switch (kind_) {
        case FilterKind::kBox:
            return "box";
        case FilterKind::kGaussian:
            return fmt::format("gaussian:sigma={},radius={}", format_real(sigma_px_),
                               format_real(radius_px_));
        case FilterKind::kCone:
            return fmt::format("cone:radius={}", format_real(radius_px_));
    }
    return "box";
}

double Filter::profile(double r) const {
    switch (kind_) {
        case FilterKind::kBox:
            return std::abs(r) <= kBoxRadiusPx ? 1.0 : 0.0;
        case FilterKind::kGaussian:
            if (!(r <= radius_px_)) return 0.0;
            return std::exp(-r * r / (2.0 * sigma_px_ * sigma_px_));
        case FilterKind::kCone:
            if (!(r <= radius_px_)) return 0.0;
            return 1.0 - r / radius_px_;
    }
    return 0.0;
}

double Filter::profile_r2(double r2) const {
    if (kind_ != FilterKind::kGaussian) return profile(std::sqrt(r2));
    if (!(r2 <= radius_px_ * radius_px_)) return 0.0;
    return std::exp(-r2 / (2.0 * sigma_px_ * sigma_px_));
}

double Filter::profile_on_lattice(double q2, double units_per_px) const {
    const double units2 = units_per_px * units_per_px;
    if (kind_ != FilterKind::kGaussian) return profile(std::sqrt(q2 / units2));
    if (!(q2 <= units2 * radius_px_ * radius_px_)) return 0.0;
    const double scale = 1.0 / (units2 * 2.0 * sigma_px_ * sigma_px_);
    return std::exp(-q2 * scale);
}

double Filter::evaluate(double dx, double dy) const {
    if (kind_ == FilterKind::kBox) return profile(dx) * profile(dy);
    return value(std::hypot(dx, dy));
}

double Filter::value(double r) const {
    if (kind_ == FilterKind::kBox) return std::numeric_limits<double>::quiet_NaN();
    return amplitude_ * profile(r);
}

double Filter::radial_integral(double r) const {
    const double m = std::min(std::abs(r), radius_px_);
    switch (kind_) {
        case FilterKind::kBox:
            break;
        case FilterKind::kGaussian:
            return a_sigma2_ * -std::expm1(-m * m * inv_two_sigma2_);
        case FilterKind::kCone:
            return amplitude_ * m * m * (0.5 - m / (3.0 * radius_px_));
    }
    return std::numeric_limits<double>::quiet_NaN();
}

double Filter::profile_line_integral(double y, double x) const {
    if (kind_ == FilterKind::kBox) {
        if (!(std::abs(y) <= kBoxRadiusPx)) return 0.0;
        return std::clamp(x, 0.0, kBoxRadiusPx);
    }
    const double y2 = y * y;
    const double r2 = radius_px_ * radius_px_;
    if (!(y2 < r2)) return 0.0;
    const double m = std::min(x, std::sqrt(r2 - y2));  // the support ends at the circle
    if (!(m > 0.0)) return 0.0;
    if (kind_ == FilterKind::kGaussian) {
        // exp(-(s^2 + y^2) / 2 sigma^2) = exp(-y^2 / 2 sigma^2) * exp(-s^2 / 2 sigma^2), and
        // the integral of the latter over [0, m] is sigma sqrt(pi/2) erf(m / (sigma sqrt 2)).
        const double s = sigma_px_;
        return std::exp(-y2 / (2.0 * s * s)) * s * std::sqrt(std::numbers::pi / 2.0) *
               std::erf(m / (s * std::numbers::sqrt2));
    }
    // integral_0^m (1 - sqrt(s^2 + y^2) / R) ds.
    return m - distance_line_integral(m, y) / radius_px_;
}

double distance_line_integral(double t, double d) {
    // On d = 0 the d^2 asinh term tends to 0 (asinh grows only like a logarithm).
    const double d2 = d * d;
    const double ad = std::abs(d);
    const double log_term = ad > 0.0 ? d2 * std::asinh(t / ad) : 0.0;
    return 0.5 * (t * std::sqrt(t * t + d2) + log_term);
}

const std::vector<FilterInfo>& filter_registry() {
    static const std::vector<FilterInfo> registry = {
        {"box", "exact area coverage of each pixel square (the default)", {}},
        {"gaussian", "exact integral of a radial Gaussian, truncated at radius, unit volume",
         gaussian_params()},
        {"cone", "exact integral of the cone 1 - r/radius, unit volume", cone_params()},
    };
    return registry;
}

}  // namespace aabench
