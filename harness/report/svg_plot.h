// The accuracy-time plot of one pattern as a standalone SVG document: what accuracy costs in
// time, one curve per method through its sweep points. Pure functions: text in, text out; the
// report stage (harness/report/html_report.h) writes the file. Reading guide: docs/report.md.
//
//   x  median time of one render (ns, shown as ns/us/ms/s), log scale, decade ticks;
//   y  box_rmse (against the exact box reference), log scale, decade ticks;
//   one curve per method id through its rows ordered by cost_value, each point labelled with
//   its parameter ("n=6"), the default-parameter row drawn larger with a dark outline;
//   the Pareto front over all points: a step line and a ring round every point on it.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "harness/measure/compare.h"

namespace aabench {

// Errors below this are float32 rounding (the `exact` method renders the exact coverage as
// float32, ~6e-8 relative), not a method's error: on a log axis they (and errors of exactly 0)
// would go to -infinity, so they are drawn at this floor, which the plot states. When the floor
// lies far below every other error, the y axis breaks and the floor gets a band of its own.
inline constexpr double kPlotErrorFloor = 1e-7;

// Text made safe for XML and HTML, in text and in double-quoted attributes.
std::string xml_escape(const std::string& text);

// Indices of the points on the Pareto front of (x, y), both to be minimised: no other point
// has x <= and y <= with one of them strictly smaller. Returned in increasing x (and so
// decreasing y). Points with a non-finite coordinate are never on the front; exact duplicates
// are both kept.
std::vector<std::size_t> pareto_front(const std::vector<double>& x, const std::vector<double>& y);

// The plot of `rows` (all of one pattern) as an SVG document, headed by `title`. It has no
// element ids and no <style>, so several plots can be inlined in one HTML page. Rows without a
// finite positive time or a finite error are left out and counted in a note on the plot.
// Element classes, for readers and tests: one <g class="series"> per method id, holding a
// <polyline class="curve"> when it has two points or more, and one class="point" element per
// row (class "point default" for the default-parameter row); <path class="pareto-front"> and
// one <circle class="pareto-ring"> per point on the front; two class="axis-break" marks when
// the y axis is broken.
std::string accuracy_time_svg(const std::vector<ResultRow>& rows, const std::string& title);

}  // namespace aabench
