// The exact box engine: for every pixel, the exact area-weighted value of the scene over the
// pixel square, in double precision (error <= 1e-12 per pixel for scenes of ordinary
// coordinates). For a 0/1 scene this is the covered area. See the essay at the top of
// box_coverage.cpp and docs/references.md.
//
// It lives in the scan-conversion room because two rooms above share it: the `exact` methods
// (methods/exact.cpp, methods/exact_8bit.cpp) and the references (harness/reference/).
#pragma once

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

Coverage box_coverage(const Scene& scene);

}  // namespace aabench
