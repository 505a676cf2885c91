// Shared by the pattern tests (patterns_test.cpp, patterns_geometry_test.cpp): the image sizes
// every pattern is generated at, and the shoelace area computed from first principles, not
// with library code.
#pragma once

#include <cstddef>

#include "patterns/scene/scene.h"

namespace aabench::testing {

struct Size {
    int width;
    int height;
};
inline constexpr Size kSizes[] = {{16, 16}, {256, 256}, {300, 200}};

// Signed area by the shoelace formula, about the first vertex so large coordinates do not
// cancel. Positive for the generators' counter-clockwise (y-down) orientation.
inline double signed_area(const Contour& contour) {
    const Point o = contour.front();
    double twice = 0.0;
    for (std::size_t i = 0; i < contour.size(); ++i) {
        const Point& a = contour[i];
        const Point& b = contour[(i + 1) % contour.size()];
        twice += (a.x - o.x) * (b.y - o.y) - (b.x - o.x) * (a.y - o.y);
    }
    return 0.5 * twice;
}

}  // namespace aabench::testing
