// The fast exact engine for scenes with Bezier segments: the exact box image of the band sweep
// (methods/scan/reference/bezier_coverage.h, which stays the slow check), pixel row by pixel
// row, without finding every crossing of the scene first. How and why it is exact, and where
// it hands a row to the band sweep: the essay at the top of fast_bezier.cpp.
#pragma once

#include <cstdint>

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// How a call's rows went (for tests and the benchmark's notes).
struct FastBezierStats {
    std::int64_t rows = 0;           // rows written
    std::int64_t empty_rows = 0;     // rows no boundary reaches: filled with the background
    std::int64_t sub_bands = 0;      // sub-bands walked by the fast path
    std::int64_t refined_pairs = 0;  // neighbour pairs whose order needed the bisection
    std::int64_t fallback_rows = 0;  // rows whose order was not proven: done by the band sweep
};

// Whether fast_bezier_rows draws `scene`: shapes with Bezier outlines or polygon contours,
// constant values, no disc or ring, no depth or value planes.
bool fast_bezier_draws(const Scene& scene);

// Writes rows [row_lo, row_hi) of the exact box image of `scene` (fast_bezier_draws) rounded
// to float32 into `out`; other rows are not touched. A row's values do not depend on which
// other rows the call writes, so bands on several threads give the image of one call. Safe
// from several threads at once (per-thread scratch); a warm call allocates nothing unless a
// row falls back to the band sweep.
void fast_bezier_rows(const Scene& scene, Image& out, int row_lo, int row_hi,
                      FastBezierStats* stats = nullptr);

}  // namespace aabench
