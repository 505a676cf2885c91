// Ground truth for the edge stage (Saito & Takahashi 1990; docs/edges.md, "Ground truth"): the
// lines a perfect line drawing of a 3-D scene has, read off the exact visible pieces, and their
// exact antialiased image (each line a one-pixel-wide strip, box-filtered exactly).
//
// A line is a piece of the boundary between two visible pieces of different faces, or between a
// piece and the background, inside the window:
//   - a contour where depth jumps across it (silhouettes, occluding edges, the outline against
//     the background);
//   - a crease where depth is continuous across it but its slope is not (two faces meeting at
//     an edge), convex where the depth image has a ridge (z_s larger on the line than either
//     plane continued across it: the surface turns away from the eye on both sides), concave
//     where it has a valley. This is the dihedral angle seen from the viewing side, read from
//     the two depth planes alone: for faces that face the eye, the solid lies behind both, so
//     the visible surface is the nearer-of / farther-of the two planes exactly when the edge is
//     concave / convex. It is the sign the crease operators give (e > 0 convex, edges.h).
// Boundaries between pieces of one face (pattern and shadow cells, splits made by visibility)
// and between coplanar faces are no line; nor is the window's frame.
#pragma once

#include <cstdint>
#include <vector>

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

enum class LineKind : std::uint8_t { kContour, kConvexCrease, kConcaveCrease };

const char* line_kind_name(LineKind kind);  // "contour", "convex crease", "concave crease"

struct LineSegment {
    Point a, b;  // in the window frame (pixel (i, j) covers [i, i+1] x [j, j+1])
    LineKind kind = LineKind::kContour;
    int face = -1;        // the nearer side's face (a contour), the first piece's (a crease)
    int other_face = -1;  // the other side's face; -1 for the background
};

// The lines of `depth_pieces`: disjoint convex pieces (what visible_pieces() returns, or
// PreparedFrame::depth_pieces), each with a depth plane (`value_plane` as z_s = f d / z_v, else
// `inv_depth`; larger is nearer) and its face. Segments are clipped to the window; collinear
// pieces of one line stay separate segments (they abut exactly). Throws InputError for a shape
// without a depth plane or with several contours.
std::vector<LineSegment> true_lines(const Scene& depth_pieces);

// What a line image is made of: the exact box coverage of the union of the one-pixel-wide
// strips (the segment swept by ±0.5 px along its normal, square ends at its endpoints — butt
// caps, so abutting pieces of one line do not overlap) of the lines of one kind.
struct LineCoverage {
    Coverage contour;
    Coverage convex;
    Coverage concave;
};
LineCoverage line_coverage(const std::vector<LineSegment>& lines, int width, int height);

// The perfect antialiased line drawing in the edge stage's own terms (edges.h, `lines`): the
// style's formula with p replaced by the contour coverage and e by the crease coverages
// (+convex, -concave): "black" L = clamp(w_c C_contour + w_k (C_convex + C_concave), 0, 1);
// "white-convex" W - D with D = clamp(w_c C_contour + w_k C_concave), W = clamp(w_k C_convex).
// With spec.crease == "none", creases are not drawn.
Coverage line_drawing_reference(const LineCoverage& coverage, const EdgesSpec& spec);

}  // namespace aabench
