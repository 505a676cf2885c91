// The cost model as a picture: time against one size (pixels, or edges) on log-log axes, one
// curve per method, and the least-squares line of log(time) against log(size) drawn dashed
// with its slope in the legend. A slope of 1 is cost proportional to the size; 0.5 would be
// cost growing with the image's side, not its area. Pure functions: the CLI writes the file.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "harness/measure/cost_timing.h"  // CostSeries

namespace aabench {

// log(time) = intercept + slope * log(size), least squares over the points with finite
// positive coordinates (natural logs; the slope does not depend on the base). NaN slope when
// fewer than two distinct sizes remain.
struct LogLogFit {
    double slope;
    double intercept;
};
LogLogFit fit_log_log(const std::vector<std::pair<double, double>>& points);

// The plot as a standalone SVG document (no ids, no <style>: it can be inlined in HTML too).
// For readers and tests: one <g class="series"> per method with a <polyline class="curve">,
// one <circle class="point"> per measurement and a <line class="fit"> when the fit exists;
// the legend text carries "slope 0.93".
std::string cost_model_svg(const std::vector<CostSeries>& series, const std::string& x_label,
                           const std::string& title);

}  // namespace aabench
