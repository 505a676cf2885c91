// The sizes the rows' memory estimates (MethodTraits::working_bytes) are built from. Every
// constant is the size of a data structure the code really allocates, rounded up, with the
// vector growth slack where a vector grows by push_back (up to 2x its final size). How the
// whole job's estimate is made: harness/measure/limits.h, docs/limits.md.
#pragma once

#include "methods/method_traits.h"

namespace aabench::memory_model {

// EdgeTable: one Edge (7 doubles/ints, 56 bytes) per edge, in a vector grown by push_back
// (x2), plus the per-contour index (4 bytes per edge), plus one 4-byte bucket entry per
// (edge, row) pair and 4 bytes per row.
inline constexpr double kEdgeBytes = 2.0 * 56.0 + 4.0;
inline constexpr double kEdgeRowBytes = 4.0;
inline constexpr double kRowBytes = 4.0;
// Sub-scanline tracer and band sweep: sorted endpoint heights (16 bytes per edge) and chain
// bookkeeping (about 48 bytes per edge in the worst row).
inline constexpr double kSweepBytesPerEdge = 64.0;
// box-multiscan's whole-row sums, per chain besides its x and places per line: first and end
// lines and edge (4 each), its change (8), its entry in the list handed to the sweep (24),
// rounded up, and vectors grown by resize (x2).
inline constexpr double kRowTrackBytes = 2.0 * 48.0;
// The fast exact engine (fast_coverage.cpp, its Scratch in fast_engine_p.h), per edge at most:
// the Edge record (56 bytes) grown by push_back (x2), the contour index, bucket entry, active
// entry and rank (4 each), an event height (8, x2), a Chain (48 bytes) in each of three
// vectors (chains, ranked, starts; x2), and the steady rows' arrays, one entry per chain
// (x2): the edge and its index at the row's top (4 each), x, dv and x at the bottom (8 each),
// the edge's five fields (8 each) and the chain's dv (8).
inline constexpr double kFastSteadyBytes = 4.0 + 4.0 + 3 * 8.0 + 5 * 8.0 + 8.0;
inline constexpr double kFastEdgeBytes =
    2.0 * 56.0 + 4 * 4.0 + 2.0 * 8.0 + 3 * 2.0 * 48.0 + 2.0 * kFastSteadyBytes;
// Per pixel, the most `exact` keeps for affine values or curves: the curve compositing's 21
// bytes (value, base, flag, list head) plus, for a run of polygons among curves, its two
// double rasters and the polygon engine's one (24), rounded up: 48.
inline constexpr double kCurvePixelBytes = 48.0;
// AGG's rasteriser keeps one 16-byte cell per pixel an edge passes through (grown in blocks);
// Cairo's tor converter keeps per-edge records and a cell per crossed pixel, about the same.
inline constexpr double kPeerCellBytes = 32.0;
// The grid-circle methods (methods/scan/circles/circle_raster.h): a float alpha per pixel, and the
// index (8 bytes) of each touched pixel, at most every pixel, in a vector grown by push_back
// (x2); a GridCircle record (centre, radius, value: 32 bytes, x2) per shape.
inline constexpr double kCircleAlphaBytes = 4.0;
inline constexpr double kCircleTouchedBytes = 2.0 * 8.0;
inline constexpr double kGridCircleBytes = 2.0 * 32.0;

inline double edge_table_bytes(const SceneSize& s) {
    return kEdgeBytes * s.vertices + kEdgeRowBytes * s.edge_rows + kRowBytes * (s.height + 1);
}

// The edge table and a few double rows: the point samplers' and the fallback's floor.
inline double edge_table_and_rows_bytes(const SceneSize& s, double rows) {
    return edge_table_bytes(s) + rows * 8.0 * s.width;
}

// What every grid-circle method keeps while drawing (besides aa-circle's table).
inline double grid_circle_bytes(const SceneSize& s) {
    return (kCircleAlphaBytes + kCircleTouchedBytes) * s.pixels() + kGridCircleBytes * s.shapes;
}

// What the exact image keeps (methods/scan/exact/exact_image.h; `exact`, `exact-8bit`).
// The fast engine (fast_coverage.cpp): its own edge records, chains and events, one row of
// double accumulators; rows where boundaries cross also build the edge table and the band
// sweep. Per-pixel state only for affine values and curves: affine values take one double
// raster (piece_coverage.h); curves (curve_coverage.cpp) keep value and base (doubles), a flag
// and a list head per pixel (21 bytes) over the curves' boxes, and each run of polygons among
// them two double rasters plus the polygon engine's own: kCurvePixelBytes covers the lot.
inline double exact_image_bytes(const SceneSize& s) {
    return kFastEdgeBytes * s.vertices + 8.0 * (s.width + 32) + kRowBytes * (s.height + 1) +
           edge_table_bytes(s) + kSweepBytesPerEdge * s.vertices +
           (s.exact_raster ? kCurvePixelBytes * s.pixels() : 0.0);
}

// The bytes of a colour value (methods/scan/kernel/channel_values.h: four doubles, two SSE2
// pairs), a colour engine's cell, step and palette entry.
inline constexpr double kChannelValuesBytes = 32.0;

// `exact` on a colour scene (s.channels == 3), whose fast engine has a colour instance: its row
// of cells holds colour values, each shape a palette entry, and rows where boundaries cross
// build the edge table and the band sweep of each of the three channel scenes, with the
// scenes themselves (a point, two doubles, a vertex). The engines it leaves per channel
// (curves, affine values) draw one channel at a time: the grey figure.
inline double exact_colour_bytes(const SceneSize& s) {
    if (s.channels != 3 || s.exact_raster) return exact_image_bytes(s);
    return kFastEdgeBytes * s.vertices + kChannelValuesBytes * (s.width + 32 + s.shapes) +
           kRowBytes * (s.height + 1) +
           3.0 * (edge_table_bytes(s) + kSweepBytesPerEdge * s.vertices + 16.0 * s.vertices);
}

}  // namespace aabench::memory_model
