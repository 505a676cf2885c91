// Exact radial-filter references of scenes with Bezier segments: the value at every pixel
// centre of a radial filter (the truncated Gaussian, the cone) times the visible value, with
// no flattening. docs/references.md ("Curves: Bezier segments", "Radial") has the derivation.
#pragma once

#include "methods/scan/kernel/filter.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// The adaptive quadrature's target per piece and pixel: 1e-13, so that a pixel whose support
// holds up to 1e3 band pieces stays within 1e-10 (the bound stated is 1e-9).
inline constexpr double kBezierFilterQuadratureTolerance = 1e-13;

// `filter` radial (std::invalid_argument for the box); the scene's shapes are polygons, have
// an outline or are discs and rings, as for bezier_box_coverage (no depth planes or affine
// values: std::logic_error).
Coverage bezier_filtered_reference(const Scene& scene, const Filter& filter);

}  // namespace aabench
