// The exact box reference every method is scored against: the exact area-weighted value of
// the scene over each pixel square, in double (error <= 1e-12 per pixel for scenes of
// ordinary coordinates). The engine is methods/scan/box_coverage.cpp, shared with the `exact`
// methods; this is the name the harness uses for it.
#pragma once

#include "methods/scan/image.h"
#include "methods/scan/box_coverage.h"
#include "patterns/scene/scene.h"

namespace aabench {

inline Coverage box_reference(const Scene& scene) { return box_coverage(scene); }

}  // namespace aabench
