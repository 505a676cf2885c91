// Exact visibility: a ScreenScene reduced to non-overlapping convex pieces, each the visible
// part of one input shape (docs/world.md, "Exact visibility"). The 2-D references then
// apply unchanged: a scene of disjoint pieces means the same under every composition rule.
// See the essay at the top of visibility.cpp for what "exact" means here and its tolerances.
#pragma once

#include <cstddef>
#include <cstdint>

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
    std::size_t hidden_by_tiles = 0;     // shapes found wholly hidden before any pair test
    std::size_t tiles = 0;               // tiles of the occlusion structure (0: not used)
    std::size_t pending_peak = 0;        // most hiding regions waiting for their source at once
    std::size_t fans = 0;                // fans resolved by their own sweep (fan_groups.h)
    std::size_t fan_triangles = 0;       // the triangles in them
};

struct VisibilityOptions {
    // Drop the shapes the tile occlusion structure finds wholly hidden before the pairwise
    // stage (harness/reference/occlusion_tiles.h). The same visible regions either way; off
    // only to test the two paths against each other.
    bool occlusion_tiles = true;
    // Resolve fans (many triangles of one plane around a shared vertex) by an angular sweep
    // before the pairwise stage (harness/reference/fan_groups.h). The same visible regions
    // either way; off only to test the two paths against each other.
    bool fans = true;
    // The job memory budget of docs/limits.md (kDefaultMemoryBudgetBytes there, which a
    // static_assert keeps equal): the pairwise stage's memory is estimated before it starts
    // (kVisibilityBytesPerPair per candidate pair, from the grid's upper bound on the pairs)
    // and a scene over it is refused with one line.
    std::size_t memory_budget_bytes = std::size_t{8} << 30;
};

// Bytes per candidate pair in the pairwise stage's estimate, counted from what the stage holds
// for every pair at once: the pair in the sorted list (two ints, 8 bytes) and its two entries
// in the sources' partner lists (an int each, 8 bytes). The hiding regions are not held per
// pair: those a source computes for itself are carved and dropped, and those it computes for
// a partner still to come wait in a pool of at most kMaxPendingHiders (estimated apart, below).
// The pair bound is an upper bound (a pair sharing several grid cells counts once per cell),
// so the estimate is too.
inline constexpr std::size_t kVisibilityBytesPerPair = 8 + 8;
// The pool of hiding regions waiting for their source (visibility.cpp, PendingHiders): a source
// whose later partners would take it past this stores none, and they compute the pair again.
// 2^18 regions: the soup of 200,000 triangles peaks at a few thousand in the resolution order.
inline constexpr std::size_t kMaxPendingHiders = std::size_t{1} << 18;
// Bytes of one pending region: about 8 vertices with their edge lines (16 + 40 bytes each),
// bounds, scale, area, partner, link and two vector headers (about 130), with the allocator's
// overhead: 600, counted from the structures, not measured.
inline constexpr std::size_t kPendingHiderBytes = 600;

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
// in the order of their sources. Hand them on as SceneInput::disjoint_pieces
// (patterns/scene/scene_input.h): the references and `exact` then integrate them as they are.
//
// Shapes on the same face (equal face >= 0) never occlude each other. Equal depth planes (to
// the one depth tie, kDepthTieRelative of methods/scan/kernel/visibility_rule.h): the later shape
// is seen.
Scene visible_pieces(const Scene& screen, VisibilityStats* stats = nullptr,
                     const VisibilityOptions& options = {});

// How many times visible_pieces() ran on this thread (a work counter: tests check that a
// prepared frame runs the visibility stage at most once; harness/world/stages.h reads it).
long long& visible_pieces_calls();

}  // namespace aabench
