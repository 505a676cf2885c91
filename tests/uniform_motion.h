// Motion vectors of a uniform translation, for the temporal suites.
#pragma once

#include <cstddef>

#include "methods/motion.h"

namespace aabench::testing {

// Every pixel's surface moved by (dx, dy) px since the previous frame.
inline MotionVectors uniform_motion(int width, int height, float dx, float dy) {
    MotionVectors motion;
    motion.width = width;
    motion.height = height;
    motion.dx.assign(static_cast<std::size_t>(width) * height, dx);
    motion.dy.assign(static_cast<std::size_t>(width) * height, dy);
    return motion;
}

}  // namespace aabench::testing
