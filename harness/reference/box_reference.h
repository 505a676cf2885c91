// The exact box reference every method is scored against: the exact area-weighted value of
// the scene over each pixel square, in double (error <= 1e-12 per pixel for scenes of
// ordinary coordinates and values of order one).
//
// A 2-D scene of constant values goes to the engine in methods/scan/reference/box_coverage.cpp,
// shared with the `exact` methods (bit for bit what it always gave). A ScreenScene with depth
// planes or affine values (docs/architecture.md, "What the references promise") is first reduced to
// its visible pieces (harness/reference/visibility.h), whose values are then integrated exactly,
// pixel by pixel, from their areas and first moments (box_reference.cpp).
//
// Every reference here takes a scene in its window frame (no window origin, as methods do:
// methods/method.h); the prepared frame (harness/world/frame.h) is what takes the origin out.
// A scene with one is refused (std::logic_error), never converted.
#pragma once

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"
#include "patterns/scene/scene_input.h"

namespace aabench {

// `in` is a Scene, or a prepared frame's visible pieces (patterns/scene/scene_input.h), which
// are integrated as they are (box_reference_of_pieces) instead of being resolved again.
Coverage box_reference(const SceneInput& in);

// The box reference of a scene that is already a set of disjoint pieces (what
// visible_pieces() returns): each shape one simple contour (convex or not, either
// orientation), no two overlapping, value `value_plane` where set, else `value`; background
// where no piece is. Overlapping pieces would add up, not cover each other. For callers that
// reduce a ScreenScene once and use the pieces for several references.
Coverage box_reference_of_pieces(const Scene& pieces);

// True when the scene needs the piece path: some shape has a depth plane or an affine value.
bool has_planes(const Scene& scene);

}  // namespace aabench
