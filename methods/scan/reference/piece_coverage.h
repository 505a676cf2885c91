// The exact box filter of a scene of disjoint pieces whose values may be affine in screen
// position (a depth image: z_s = f d / z_v on each visible piece): exact areas and first
// moments per pixel (piece_coverage.cpp says why that is exact).
#pragma once

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// Each shape one simple contour (convex or not, either orientation), no two overlapping (what
// visible_pieces() returns); value `value_plane` where set, else `value`; the background where
// no piece is. Overlapping pieces would add up, not cover each other.
Coverage piece_box_coverage(const Scene& pieces);

// True when some shape has an affine value (value_plane).
bool has_affine_values(const Scene& scene);

}  // namespace aabench
