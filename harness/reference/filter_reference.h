// Exact radial-filter references: for every pixel, the integral of a radial filter centred on
// the pixel centre (i + 0.5, j + 0.5) times the scene's visible value, the filter normalised
// to unit volume over its support. Exact to <= 1e-10 per pixel (in practice ~1e-14); see the
// essay at the top of filter_reference.cpp and docs/references.md. The scene is in its window
// frame, as for the box reference (harness/reference/box_reference.h).
//
// Filters (spec `ID[:key=value,...]`, as for methods):
//
//   id        parameter  default  range      why the default
//   gaussian  sigma      0.5      0.05..10   the Gaussian of the multiscan methods (Nishita &
//                                            Nakamae eq. 4-6), truncated at the radius and
//                                            renormalised: f(r) = A exp(-r^2 / (2 sigma^2))
//             radius     1        0.25..8    the paper's one-pixel filter radius
//   cone      radius     1        0.25..8    the paper's cone: f(r) = c (1 - r / radius)
#pragma once

#include <string>
#include <vector>

#include "methods/filter_spec.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/params.h"
#include "patterns/scene/scene.h"

namespace aabench {

struct RadialFilter {
    enum class Kind { kGaussian, kCone };
    Kind kind = Kind::kGaussian;
    double sigma_px = 0.5;   // kGaussian only (0 for the cone)
    double radius_px = 1.0;  // support radius: f(r) = 0 for r > radius_px

    // Canonical spec with every parameter: "gaussian:sigma=0.5,radius=1", "cone:radius=1".
    std::string spec() const;
};

// Parses "gaussian", "gaussian:sigma=0.7,radius=1.5", "cone", "cone:radius=2". Unknown ids or
// keys and out-of-range values are InputErrors that list the valid ones.
RadialFilter parse_radial_filter(const std::string& spec);

// The normalised filter f(r) (2 pi * integral_0^R f(r) r dr = 1); 0 for r > radius_px.
double filter_value(const RadialFilter& filter, double r);

// The closed-form radial integral F(r) = integral_0^min(r, R) f(s) s ds (F(R) = 1 / (2 pi)):
// the filter mass within radius r, divided by 2 pi. For tests and for methods that tabulate.
double filter_radial_integral(const RadialFilter& filter, double r);

// The value at every pixel centre. Cost O(jump-set length x R^2 + pixels); see the .cpp.
Coverage filtered_reference(const Scene& scene, const RadialFilter& filter);

// The reference filters a user can name, with their parameter tables (for `aabench list`).
struct ReferenceFilterInfo {
    std::string id;
    std::string summary;
    std::vector<ParamSpec> params;
};
const std::vector<ReferenceFilterInfo>& reference_filter_registry();

// Any reference by spec: "box" (the exact box reference, harness/reference/box_reference.h) or a
// radial filter spec as parse_radial_filter() reads it. Throws InputError listing the valid
// filters.
Coverage exact_reference(const Scene& scene, const std::string& filter_spec);
Coverage exact_reference(const Scene& scene, const FilterSpec& filter);

// A reference spec as the typed filter methods name (methods/filter_spec.h), range-checked as
// parse_radial_filter() does; InputError as canonical_reference_spec(). Its text() is the
// canonical spec.
FilterSpec parse_filter_spec(const std::string& filter_spec);
// The radial filter of a FilterSpec that is not the box (std::invalid_argument for the box).
RadialFilter radial_filter(const FilterSpec& filter);
// The canonical form of a reference spec ("box", or RadialFilter::spec()), so equal filters
// written differently share one reference computation.
std::string canonical_reference_spec(const std::string& filter_spec);

}  // namespace aabench
