// The ink-against-angle plot of a concentric-circles pattern (harness/measure/circle_angle.h)
// as a standalone SVG document: x the angle along the circle folded into one octant (0° on the
// axes, 45° on the diagonals), y the rendered ink as a share of the exact ink, one line per
// method, with the line 1 (exact) and cos(theta) (one unit of ink per pixel row, what a
// horizontal-distance rule predicts) drawn dashed for reference.
#pragma once

#include <string>
#include <vector>

#include "harness/measure/circle_angle.h"

namespace aabench {

struct AngleSeries {
    std::string method;
    AngleProfile profile;
};

std::string angle_profile_svg(const std::vector<AngleSeries>& series, const std::string& title);

}  // namespace aabench
