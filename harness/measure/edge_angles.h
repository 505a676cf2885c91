// Jagged edges by edge angle: the edge error of harness/measure/symptoms.h split by the angle of
// the edge each pixel lies near, in the bins of the metric registry's per-angle family
// (edge_angle_metric, kEdgeAngleBinDeg). The papers' claims about edge angles (near-horizontal
// edges improve less, supersampling is weak near the axes: docs/claims.md) read these figures.
// Pure functions: no I/O.
#pragma once

#include <cstdint>
#include <vector>

#include "harness/measure/metric_registry.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// A pixel of the band near edges of two bins (a star's centre, a corner) says nothing about
// either angle: it is left out.
inline constexpr std::int8_t kNoAngleBin = -1;
inline constexpr std::int8_t kMixedAngleBins = -2;

// The bin of an edge from a to b: its angle from the horizontal folded into [0°, 90°]
// (the direction and the side do not matter), divided into kEdgeAngleBins bins.
int edge_angle_bin(Point a, Point b);

// Per pixel: the bin of the edges whose band (kEdgeBandPx) holds its centre, kNoAngleBin
// outside every band, kMixedAngleBins where edges of two bins meet. Made once per scene.
Raster<std::int8_t> edge_angle_bins(const Scene& scene);

// rmse of (rendered - reference) over the pixels of each bin; NaN for a bin without pixels.
struct EdgeAngleErrors {
    std::vector<double> rmse;       // kEdgeAngleBins values
    std::vector<long long> pixels;  // pixels per bin
};
EdgeAngleErrors edge_errors_by_angle(const Image& rendered, const Coverage& reference,
                                     const Raster<std::int8_t>& bins);

// The bin's centre angle (degrees), for tables.
double edge_angle_bin_centre_deg(int bin);

}  // namespace aabench
