// Fans for exact visibility: many triangles that share one vertex (the apex) and one depth plane,
// resolved among themselves by an angular sweep instead of pair by pair (docs/world.md, "Exact
// visibility at depth").
//
// Why: n triangles fanned around a common vertex all overlap near it, so the pairwise stage
// (visibility.cpp) meets n^2 / 2 pairs (5 * 10^9 for 100,000) although what is seen of them is
// a few thousand angular sectors. Among shapes of one plane the later is seen (the one depth
// tie, methods/scan/kernel/visibility_rule.h), so a fan is a 2-D problem around its apex: taken
// from the last triangle to the first, each is seen where it reaches farther from the apex than the
// union of the later ones. That union is star-shaped around the apex and kept as its outline
// in polar form: angular intervals, each with the chord of the triangle that reaches farthest
// there (the "envelope"). A triangle's visible part in one interval is the region of the wedge
// between the owner's chord and its own: convex, one piece (two where the chords cross, split
// at the ray through their crossing). So the cost follows the envelope the triangles meet, not
// the pairs, and the pieces are those of the pairwise answer's regions.
//
// The pieces of a fan are disjoint from each other and keep their triangle's plane, so the
// pairwise stage then resolves them against every other shape as usual, never against each
// other (same group).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "harness/reference/convex_split.h"

namespace aabench {

struct FanInput {
    const Contour* poly = nullptr;  // positively oriented, convex, no repeated vertex
    const std::optional<AffinePlane>* inv_depth = nullptr;  // none: 2-D, the later is seen
    double side_tolerance = 0.0;  // kSideRelative of the coordinate scale (visibility.cpp)
};

struct FanResult {
    std::vector<int> group;  // per input: its fan (0, 1, ...) or -1 when in none
    struct Piece {
        int input = 0;          // the triangle it is a visible part of
        std::size_t first = 0;  // its vertices: vertices[first, first + size), positively
        std::size_t size = 0;   // oriented, convex
    };
    // The visible parts of the fans' triangles among themselves, in the order the sweeps made
    // them. Flat: one vertex array for all of them, so that half a million pieces cost no
    // allocation each.
    std::vector<Piece> pieces;
    std::vector<Point> vertices;
    std::size_t fans = 0;

    std::span<const Point> contour(const Piece& piece) const {
        return {vertices.data() + piece.first, piece.size};
    }
};

// A fan needs this many triangles: below it the pairwise stage is as quick and a group is not
// worth its setup.
inline constexpr int kMinFanTriangles = 64;

// Finds the fans among the inputs (triangles around one shared vertex, of one depth plane to
// within half a depth tie at their vertices, so that any two of them tie everywhere they
// overlap and the later is seen) and resolves each.
FanResult resolve_fans(const std::vector<FanInput>& inputs);

// The pieces grouped by their triangle in the input's order, each triangle's in the order its
// sweep made them: piece order[q] for q in [first[k], first[k + 1]) is a part of input k (a
// counting sort: linear, and stable).
std::vector<std::size_t> fan_pieces_by_input(const FanResult& fans,
                                             std::vector<std::size_t>& first);

// The visible pieces of a scene that is one fan and nothing else (every input in fan 0): input
// k is screen.shapes[shapes[k]]; each piece is a copy of its shape but for the contour, in
// the input's order (visibility.h's output: disjoint convex pieces). Written
// straight from the flat result, with no source, edge lines or carve per piece.
Scene one_fan_scene(const Scene& screen, const std::vector<int>& shapes, const FanResult& fans);

}  // namespace aabench
