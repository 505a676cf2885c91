// Exact visibility: a ScreenScene reduced to non-overlapping convex pieces, each the visible
// part of one input shape (docs/world.md, "Exact visibility"). The 2-D references then
// apply unchanged: a scene of disjoint pieces means the same under every composition rule.
// See the essay at the top of visibility.cpp for what "exact" means here and its tolerances.
#pragma once

#include <cstddef>

#include "patterns/scene/scene.h"

namespace aabench {

// What visible_pieces() did (the caller measures the time).
struct VisibilityStats {
    std::size_t shapes_in = 0;           // input shapes
    std::size_t degenerate_dropped = 0;  // of those, dropped: zero area (or thinner than a sliver)
    std::size_t candidate_pairs = 0;     // pairs whose bounding boxes overlap (uniform grid)
    std::size_t same_face_pairs = 0;     // of those, skipped: cells of one face never occlude
    std::size_t overlapping_pairs = 0;   // pairs whose shapes overlap with positive area
    std::size_t pieces_out = 0;          // shapes of the result
};

// Input: a ScreenScene whose shapes all carry inv_depth (3-D: at each point the shape with the
// largest inv_depth is seen) or none does (2-D: a later shape covers an earlier one); each
// shape one convex contour, either orientation. Degenerate shapes (fewer than three distinct
// vertices, zero area) are dropped. Mixed depth and no depth, several contours, a non-convex
// contour or a non-finite number: InputError.
//
// Output: the same scene (size, origin, background, metadata, thin objects, world) whose
// shapes are disjoint convex pieces (one positively oriented contour each, see
// twice_signed_area) covering exactly the visible part of each input shape, each a copy of
// its source shape but for the contour (value, value_plane, inv_depth, face, role), grouped
// in the order of their sources.
//
// Shapes on the same face (equal face >= 0) never occlude each other. Equal depth planes (to
// the one depth tie, kDepthTieRelative of methods/scan/visibility_rule.h): the later shape
// is seen.
Scene visible_pieces(const Scene& screen, VisibilityStats* stats = nullptr);

// How many times visible_pieces() ran on this thread (a work counter: tests check that a
// prepared frame runs the visibility stage at most once; harness/world/stages.h reads it).
long long& visible_pieces_calls();

}  // namespace aabench
