// The filter a method approximates and an exact reference integrates, as one object: the box
// (the pixel square: exact area coverage) or a radial filter, the Gaussian truncated at its
// radius or the cone. Like pbrt's Filter (Pharr, Jakob & Humphreys 2016, §7.8) it carries its
// value, its radius and its integrals, so no caller compares its name with "box".
//
// Filters (spec `ID[:key=value,...]`, as for methods; docs/references.md):
//
//   id        parameter  default  range      why the default
//   box                                      exact area coverage of each pixel square
//   gaussian  sigma      0.5      0.05..10   the Gaussian of the multiscan methods (Nishita &
//                                            Nakamae 1984, eq. 4-6), truncated at the radius
//                                            and renormalised: f(r) = A exp(-r^2 / (2 sigma^2))
//             radius     1        0.25..8    the paper's one-pixel filter radius
//   cone      radius     1        0.25..8    the paper's cone: f(r) = c (1 - r / radius)
//
// Two forms of each filter. The profile is the unnormalised shape, 1 at the centre
// (exp(-r^2 / (2 sigma^2)), 1 - r / R, 1 inside the box): what methods weigh samples and
// sub-scanlines by before normalising them over their own discrete support. The value is the
// profile times amplitude(), the factor that gives it unit volume over the plane: what the
// exact references integrate.
#pragma once

#include <string>
#include <vector>

#include "patterns/scene/params.h"

namespace aabench {

enum class FilterKind { kBox, kGaussian, kCone };

class Filter {
public:
    Filter() = default;  // the box
    static Filter box() { return {}; }
    static Filter gaussian(double sigma_px, double radius_px = 1.0);
    static Filter cone(double radius_px = 1.0);
    // Reads "box", "gaussian", "gaussian:sigma=0.7,radius=1.5", "cone", "cone:radius=2", with
    // the ranges of the table above. Unknown ids or keys and out-of-range values are
    // InputErrors that list the valid ones.
    static Filter parse(const std::string& text);

    FilterKind kind() const { return kind_; }
    bool is_box() const { return kind_ == FilterKind::kBox; }
    double sigma_px() const { return sigma_px_; }  // the Gaussian's; 0 for the others
    // The support: the value is 0 at distances past it (radial filters: r > radius_px; the
    // box: |dx| or |dy| > radius_px = 0.5).
    double radius_px() const { return radius_px_; }
    // Canonical, every parameter written: "box", "gaussian:sigma=0.5,radius=1", "cone:radius=1".
    // The key the harness shares exact references by.
    std::string text() const;
    bool operator==(const Filter& other) const {
        return kind_ == other.kind_ && sigma_px_ == other.sigma_px_ &&
               radius_px_ == other.radius_px_;
    }

    // The profile at distance r >= 0 from the centre (the box: along an axis), 0 past the
    // radius (a Gaussian truncated at R keeps its value at r = R).
    double profile(double r) const;
    // The Gaussian's profile at squared distance r2 px^2, exp(-r2 / (2 sigma^2)): the weight of
    // a sample whose squared distance is known exactly. The other filters: profile(sqrt(r2)).
    double profile_r2(double r2) const;
    // profile_r2() of a sample on an integer lattice of `units_per_px` steps per pixel at
    // squared distance q2 steps^2 (an integer, exact in double): for the Gaussian
    // exp(-q2 / (units^2 2 sigma^2)), one rounding of the exact q2 times one scale.
    double profile_on_lattice(double q2, double units_per_px) const;
    // The factor that gives the profile unit volume: f(0) of the normalised filter (1 for the
    // box; for the truncated Gaussian 1 / (2 pi sigma^2 (1 - exp(-R^2 / (2 sigma^2)))); for the
    // cone 3 / (pi R^2)).
    double amplitude() const { return amplitude_; }
    // The normalised filter at the offset (dx, dy) from its centre, amplitude() x profile:
    // its integral over the plane is 1.
    double evaluate(double dx, double dy) const;
    // The normalised radial filter at distance r: evaluate() along any direction. NaN for the
    // box, which is not radial.
    double value(double r) const;

    // The closed-form radial integral F(r) = integral_0^min(r, R) f(s) s ds of the normalised
    // filter (F(R) = 1 / (2 pi)): its mass within radius r, divided by 2 pi. NaN for the box.
    double radial_integral(double r) const;
    // The 1-D integral of the profile along the line at distance y from the centre, from the
    // centre's foot to x >= 0: integral_0^x profile(sqrt(s^2 + y^2)) ds (the box: of its
    // profile along x times that along y), in closed form (erf for the Gaussian, asinh for
    // the cone: distance_line_integral); 0 past the support. Multiply by amplitude() for the
    // normalised filter's.
    double profile_line_integral(double y, double x) const;

    // The Gaussian's constants of the exact references' chord integrals
    // (harness/reference/filter_reference.cpp): 1 / (2 sigma^2) and A sigma^2.
    double inv_two_sigma2() const { return inv_two_sigma2_; }
    double amplitude_sigma2() const { return a_sigma2_; }

private:
    Filter(FilterKind kind, double sigma_px, double radius_px);

    FilterKind kind_ = FilterKind::kBox;
    double sigma_px_ = 0.0;
    double radius_px_ = 0.5;
    double inv_two_sigma2_ = 0.0;  // Gaussian
    double a_sigma2_ = 0.0;        // Gaussian: A sigma^2
    double amplitude_ = 1.0;       // A (Gaussian), c (cone), 1 (box): f(0)
};

// integral_0^t sqrt(s^2 + d^2) ds = (t sqrt(t^2 + d^2) + d^2 asinh(t / |d|)) / 2 for any t, its
// limit t |t| / 2 at d = 0: the cone's 1-D integral along a line at distance d from its apex,
// which its sub-scanline weights (profile_line_integral) and the exact reference's chords
// (harness/reference/filter_reference.cpp) both take.
double distance_line_integral(double t, double d);

// The filters a user can name, with their parameter tables (for `aabench list`).
struct FilterInfo {
    std::string id;
    std::string summary;
    std::vector<ParamSpec> params;
};
const std::vector<FilterInfo>& filter_registry();

}  // namespace aabench
