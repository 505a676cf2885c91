// Time per circle against radius (harness/measure/circle_timing.h) as a standalone SVG
// document: log-log, one line per variant (the table, on the fly, wu-circle, midpoint-circle,
// `exact` on the polygonised ring), with each line's fitted log-log slope in the legend and the
// table's memory beside its name.
#pragma once

#include <string>
#include <vector>

#include "harness/measure/circle_timing.h"

namespace aabench {

// Least-squares slope of log(ns) against log(radius) over the points with radius >= 1 (radius
// 0 is a point, not on a log axis); NaN with fewer than two such points.
double circle_timing_slope(const CircleTimingSeries& series);

std::string circle_timing_svg(const std::vector<CircleTimingSeries>& series,
                              const std::string& title);

}  // namespace aabench
