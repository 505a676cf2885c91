// The three engines of `ssaa` (methods/ssaa/ssaa.cpp: parameters, traits and the documentation of
// what each computes), one file each: the box filter on the k x k grid and the grid's Gaussian
// (methods/ssaa/ssaa_grid.cpp), and any listed sample pattern under either filter
// (methods/ssaa/ssaa_pattern.cpp).
#pragma once

#include <memory>

#include "methods/method.h"
#include "methods/scan/sampling/sample_patterns.h"

namespace aabench {

// k x k grid, box filter: the mean of the pixel's own samples.
std::unique_ptr<Method> make_ssaa_grid_box(int k);
// k x k grid, radius-1 Gaussian of `sigma` px over the pixel and its neighbours.
std::unique_ptr<Method> make_ssaa_grid_gaussian(int k, double sigma);
// One sample row per sample of `pattern`, box or radius-1 Gaussian.
std::unique_ptr<Method> make_ssaa_pattern(SamplePattern pattern, bool gaussian, double sigma);

}  // namespace aabench
