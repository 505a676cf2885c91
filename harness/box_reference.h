// The exact box reference: for every pixel, the exact area-weighted value of the scene over
// the pixel square, in double precision (error <= 1e-12 per pixel for scenes of ordinary
// coordinates). For a 0/1 scene this is the covered area. See the essay at the top of
// box_reference.cpp and docs/references.md.
#pragma once

#include "methods/image.h"
#include "patterns/scene.h"

namespace aabench {

Coverage box_reference(const Scene& scene);

}  // namespace aabench
