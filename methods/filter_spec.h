// The filter a method approximates, as a typed value: the box (area coverage) or a radial
// filter with its parameters. Its canonical text is the reference spec the harness keys exact
// references by ("box", "gaussian:sigma=0.5,radius=1", "cone:radius=1"); the harness parses
// and range-checks user text into one (harness/reference/filter_reference.h,
// parse_filter_spec), so a method's filter is built once, never re-parsed.
#pragma once

#include <string>

namespace aabench {

enum class FilterKind { kBox, kGaussian, kCone };

struct FilterSpec {
    FilterKind kind = FilterKind::kBox;
    double sigma_px = 0.0;   // kGaussian only
    double radius_px = 0.0;  // kGaussian, kCone: f(r) = 0 for r > radius_px

    static FilterSpec box() { return {}; }
    static FilterSpec gaussian(double sigma_px, double radius_px = 1.0) {
        return {FilterKind::kGaussian, sigma_px, radius_px};
    }
    static FilterSpec cone(double radius_px = 1.0) { return {FilterKind::kCone, 0.0, radius_px}; }

    bool is_box() const { return kind == FilterKind::kBox; }
    // Canonical, every parameter written: "box", "gaussian:sigma=0.5,radius=1", "cone:radius=1".
    std::string text() const;
    bool operator==(const FilterSpec&) const = default;
};

}  // namespace aabench
