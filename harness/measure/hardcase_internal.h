// Internal to the hard-case suite (hardcase_*.cpp): the edge geometry behind the documented
// bounds (hardcase_checks.cpp) that running the cases needs, and the number format the table
// and the run share. Nothing outside harness/measure/hardcase_*.cpp includes this.
#pragma once

#include <cstdint>
#include <string>

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench::hardcase_detail {

// Per pixel, the number of edges whose closed segment meets the pixel's closed square (capped
// at 255), over the window grown by `margin` pixels on each side.
Raster<std::uint8_t> edge_counts(const Scene& scene, int margin);

// `grown` (the window grown by `margin`) dilated by `reach` pixels, cropped to width x height.
Raster<std::uint8_t> dilate_and_crop(const Raster<std::uint8_t>& grown, int margin, int reach,
                                     int width, int height);

// Total length of the scene's edges clipped to the window.
double clipped_perimeter(const Scene& scene);

// The trapezoidal rule's error bound for box-multiscan with n sub-scanlines (docs/hardcases.md).
double trapezoid_bound(const Scene& scene, int n, double span);

// A figure in 3 significant digits, as the table prints it.
std::string short_number(double v);

}  // namespace aabench::hardcase_detail
