// Error figures of a rendered image against a reference. Pure functions: no I/O.
// Definitions (docs/metrics.md):
//   rmse      sqrt(mean((rendered - reference)^2)) over all pixels;
//   max_abs   max |rendered - reference|, with the first pixel (row-major) where it occurs;
//   bias      mean(rendered - reference): the signed error, >0 means too bright;
//   dropout   of the pixels whose reference coverage exceeds kDropoutCoverage, the fraction
//             rendered below kDropoutRendered: thin or small objects that vanished. The
//             reference value is the coverage for 0/1 scenes (background 0, shapes 1),
//             which all built-in patterns are.
//   nonfinite pixels of the rendered image that are NaN or infinite (should be 0).
#pragma once

#include "methods/scan/kernel/image.h"

namespace aabench {

inline constexpr double kDropoutCoverage = 0.1;
inline constexpr double kDropoutRendered = 0.01;

struct ErrorStats {
    double rmse = 0.0;
    double max_abs = 0.0;
    int max_x = 0;
    int max_y = 0;
    double bias = 0.0;
    double dropout = 0.0;            // fraction in [0, 1]
    long long dropout_pixels = 0;    // rendered < kDropoutRendered among the candidates
    long long dropout_candidates = 0;  // reference > kDropoutCoverage
    long long nonfinite = 0;
};

ErrorStats compare_to_reference(const Image& rendered, const Coverage& reference);

}  // namespace aabench
