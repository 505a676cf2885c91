// Exact radial-filter references of scenes with curves (disc and ring shapes): the filter's
// mass over a disc by one-dimensional quadrature in polar form about the pixel centre, and the
// scene composed from it. docs/references.md ("Curves") has the derivation.
#pragma once

#include "harness/reference/filter_reference.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// The integral of the normalised filter f(|p - c|) over the disc of radius rho whose centre is
// at distance d from c. Error <= ~3e-14 max(1, d) (adaptive Gauss-Legendre; see the .cpp).
double disc_filter_mass(const Filter& filter, double d, double rho);

// filtered_reference() of a scene with curves. Exact when every curve shape is disjoint from
// every other shape (curves by their radii, polygons by bounding boxes; touching is fine):
// then the value is the polygons' own reference plus, for each curve, (value - background)
// times its filter mass (outer disc less inner disc). Otherwise the scene goes to
// bezier_filtered_reference, which sweeps the circles as quarter arcs with the other shapes.
Coverage curve_filtered_reference(const Scene& scene, const Filter& filter);

}  // namespace aabench
