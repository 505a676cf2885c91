// Error against angle along concentric circles (the `circles` pattern): how much ink a method
// puts down at each angle, as a share of the exact ink. A horizontal-distance rule (aa-circle,
// wu-circle: docs/methods-circles.md) gives each pixel row one unit of ink where the exact
// one-pixel ring crosses a row over 1 / cos(theta) pixels, so its share falls from 1 on the axes
// to cos 45° = 1/sqrt 2 on the diagonals. Pure computation; the report draws it
// (harness/report/angle_plot.h).
#pragma once

#include <optional>
#include <vector>

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// Angles are folded into one octant: theta = atan2(min(|dx|, |dy|), max(|dx|, |dy|)) in
// [0°, 45°], (dx, dy) from the common centre to the pixel centre.
struct AngleProfile {
    std::vector<double> angle_deg;  // bin centres
    std::vector<double> ink_ratio;  // sum of rendered / sum of exact over the bin's pixels
    std::vector<double> mean_error; // mean (rendered - exact) over the bin's pixels
};

// The common centre and the radial range [inner, outer] of a scene made only of curves about
// one centre (the `circles` pattern); nullopt for any other scene.
struct ConcentricCurves {
    Point center;
    double inner = 0.0;
    double outer = 0.0;
};
std::optional<ConcentricCurves> concentric_curves(const Scene& scene);

// The profile of `rendered` against `reference` over the pixels whose centres lie within
// [inner - 1.5, outer + 1.5] (all the ink a method may put down), in `bins` bins over
// [0°, 45°]. Bins without pixels get NaN.
AngleProfile angle_profile(const Image& rendered, const Coverage& reference,
                           const ConcentricCurves& curves, int bins);

}  // namespace aabench
