// Shapes wholly hidden, found before any pair is tested: a union coverage structure over
// screen tiles for exact visibility at depth (docs/world.md, "Exact visibility at depth").
//
// A uniform grid of square cells, 1/24 of the typical shape's smaller side, grouped into tiles
// of 16 x 16 cells, covers the shapes. The shapes are taken front to back (by their nearest
// 1/z_v). Each is first tested: it is wholly hidden when every cell it may reach (every cell of
// its box not wholly outside one of its edge lines) is certainly covered, nearer than the
// shape's own nearest point there by a margin of four depth ties. If not, it is inserted: the
// cells wholly inside it (four corners inside every edge line) are OR-ed into its tiles' cell
// masks, with its farthest 1/z_v over them. Each tile keeps two depth layers (masked occlusion
// culling, Hasselgren, Andersson and Akenine-Möller 2016): the cells of its mask are covered
// at least as near as one depth, all its cells at least as near as another; a mask that fills
// the tile becomes the latter, so coverage saturates. So a shape behind the UNION of nearer
// shapes is dropped, not only one behind a single shape that contains it.
//
// Then at every point of a dropped shape some other shape is strictly nearer, so nothing of it
// is visible, and dropping it changes no other shape's visible part (wherever it would beat a
// shape P, the shape nearest at that point, which is kept, beats P too). So the answer is the
// same set of visible regions as the pairwise subtraction's, at a cost linear in the cell
// rows and tiles the shapes span, and the pairs left are those among the shapes that may be
// seen.
//
// Conservative by construction: a cell no shape contains wholly (along a seam between two
// hiding shapes, a shape's border) decides nothing until a third shape covers it, and every
// rounding is on the side of "not covered" and "reached".
#pragma once

#include <cstddef>
#include <vector>

#include "harness/reference/convex_split.h"

namespace aabench {

struct OcclusionInput {
    const Contour* poly = nullptr;                   // positively oriented, convex
    const std::vector<LinearForm>* edges = nullptr;  // its edge lines (unit: distances in px)
    Bounds box;
    AffinePlane inv_depth;        // 1/z_v: larger is nearer
    double side_tolerance = 0.0;  // a tile corner this near an edge line is not inside
};

struct OcclusionStats {
    std::size_t tiles = 0;          // tiles of the grid
    std::size_t covered_tiles = 0;  // tiles whose every cell is covered (saturated)
    std::size_t hidden = 0;         // shapes found wholly hidden
};

// hidden[k] is true for each shape wholly hidden by others (see above).
std::vector<char> wholly_hidden(const std::vector<OcclusionInput>& shapes,
                                OcclusionStats* stats = nullptr);

}  // namespace aabench
