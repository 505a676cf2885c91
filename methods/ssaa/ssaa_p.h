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
// k x k grid, a radius-1 Gaussian `filter` over the pixel and its neighbours.
std::unique_ptr<Method> make_ssaa_grid_gaussian(int k, const Filter& filter);
// One sample row per sample of `pattern`, `filter` the box or a radius-1 Gaussian.
std::unique_ptr<Method> make_ssaa_pattern(SamplePattern pattern, const Filter& filter);

}  // namespace aabench
