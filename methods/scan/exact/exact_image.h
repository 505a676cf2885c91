// The exact image: the engine that suits a scene, chosen once for `exact` and `exact-8bit`.
//
// Curves (discs, rings) go to the closed-form curve engine (reference/curve_coverage.h), affine
// values and visible pieces that outnumber the pixels to the piece engine
// (reference/piece_coverage.h), everything else to the fast engine (fast_coverage.h). Each is
// the box reference's answer; the choice is one of speed only.
#pragma once

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene_input.h"

namespace aabench {

// Rows [row_lo, row_hi) of the exact image of `in`'s scene (window frame) into `out`; whether
// it is disjoint pieces only chooses the engine.
void exact_image_rows(const SceneInput& in, Image& out, int row_lo, int row_hi);

// The same for every plane of a colour scene, in one sweep of the geometry where the fast
// engine is the one exact_image_rows chooses (each plane then exact_image_rows of its channel's
// scene, bit for bit); false, having drawn nothing, where another engine is (curves, Bezier
// segments, affine values, dense disjoint pieces), which the caller draws per channel.
bool exact_colour_image_rows(const SceneInput& in, ImagePlanes& out, int row_lo, int row_hi);

}  // namespace aabench
