// Shapes wholly hidden, found before any pair is tested: a tile occlusion structure for exact
// visibility at depth (docs/world.md, "Exact visibility at depth").
//
// A uniform grid of square tiles covers the shapes. Each tile keeps the nearest depth that is
// certain over all of it: the largest, over the shapes that contain the whole tile, of the
// shape's smallest 1/z_v on the tile (an affine plane's minimum over a square is at a corner).
// A shape is wholly hidden when every tile its bounding box touches holds such a depth, nearer
// than the shape's own nearest point there by a margin of four depth ties: then at every point
// of the shape some other shape is strictly nearer, so nothing of it is visible, and dropping
// it changes no other shape's visible part (wherever it would beat a shape P, the shape that
// hides it beats P too). So the answer is the same set of visible regions as the pairwise
// subtraction's, at a cost linear in the tiles the shapes touch, and the pairs left are those
// among the shapes that may be seen: the visible result and the depth complexity actually
// seen, not every overlapping pair.
//
// Conservative by construction: a tile no single shape contains (a shape's border, a shared
// fan vertex) decides nothing, and a shape touching it is kept for the pairwise stage.
#pragma once

#include <cstddef>
#include <vector>

#include "harness/reference/convex_split.h"

namespace aabench {

struct OcclusionInput {
    const Contour* poly = nullptr;  // positively oriented, convex
    const std::vector<LinearForm>* edges = nullptr;  // its edge lines (unit: distances in px)
    Bounds box;
    AffinePlane inv_depth;  // 1/z_v: larger is nearer
    double side_tolerance = 0.0;  // a tile corner this near an edge line is not inside
};

struct OcclusionStats {
    std::size_t tiles = 0;         // tiles of the grid
    std::size_t covered_tiles = 0; // tiles some shape contains
    std::size_t hidden = 0;        // shapes found wholly hidden
};

// hidden[k] is true for each shape wholly hidden by others (see above).
std::vector<char> wholly_hidden(const std::vector<OcclusionInput>& shapes,
                                OcclusionStats* stats = nullptr);

}  // namespace aabench
