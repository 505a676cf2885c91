// The fast exact box engine behind the `exact` methods: the same value as the double box
// engine (methods/scan/reference/box_coverage.h, which stays the slow check) for every pixel,
// written as float32, without a double raster, without per-call allocation once warm, and for any
// band of rows (so that threads can split an image in bands). How and why it is exact, and
// where it hands a row to the double engine: the essay at the top of fast_coverage.cpp.
#pragma once

#include <cstdint>

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// How a call's rows went (for tests and the benchmark's notes; costs nothing to fill).
struct FastCoverageStats {
    std::int64_t rows = 0;           // rows written
    std::int64_t empty_rows = 0;     // rows no edge touches: filled with the background
    std::int64_t sub_bands = 0;      // crossing-free sub-bands walked by the fast path
    std::int64_t fallback_rows = 0;  // rows with a crossing: done by the double band sweep
};

// Writes rows [row_lo, row_hi) of the exact box image of `scene` (constant shape values; a
// value_plane is not read, as in box_coverage) into `out`, which has the scene's size; other
// rows are not touched. `scene` is in its window frame (methods/method.h). Safe to call from
// several threads at once, on disjoint row ranges of one image or on different images: each
// thread has its own scratch.
void fast_coverage_rows(const Scene& scene, Image& out, int row_lo, int row_hi,
                        FastCoverageStats* stats = nullptr);

// The same for a colour scene (Scene::channels == 3) into its three planes, in one sweep of the
// geometry: each plane is fast_coverage_rows of that channel's scene (channel_scene) bit for
// bit. Rows with a crossing sweep each channel scene in turn.
void fast_colour_coverage_rows(const Scene& scene, ImagePlanes& out, int row_lo, int row_hi,
                               FastCoverageStats* stats = nullptr);

// All rows.
inline void fast_coverage(const Scene& scene, Image& out, FastCoverageStats* stats = nullptr) {
    fast_coverage_rows(scene, out, 0, scene.height, stats);
}

}  // namespace aabench
