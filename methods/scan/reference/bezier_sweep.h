// The visible value's jumps in a scene with Bezier segments, band by band: the machinery the
// exact references of curved regions share (bezier_coverage.h for the box filter; radial
// filters integrate the same pieces).
//
// The visible value v(x, y) (the value of the last shape whose nonzero winding number is
// nonzero there, else the background) is constant between boundary crossings along every
// horizontal line. So along the line at height y,
//
//     v(x, y) = background + sum of jump_k over the boundary pieces k that the line crosses
//               left of x,
//
// where jump_k is v just right of piece k minus v just left of it. Integrating that identity
// over any region reduces a filter's integral to one integral per piece (docs/references.md,
// "Curves: Bezier segments"), with no flattening, provided each piece's jump is right.
//
// The sweep makes it right. Every segment is cut where x' or y' vanishes into monotone
// pieces (at most 5 per cubic), so each piece meets a horizontal or vertical line at most once
// and its bounding box is the box of its ends. Horizontal pieces are dropped: no horizontal
// line crosses them. The scene is then cut into bands at every piece's top and bottom and at
// every crossing of two pieces (found by subdividing boxes down to kIntersectionTolerancePx),
// so that inside a band each active piece spans it and no two of them cross. Each band is
// walked once, left to right, in the order of the pieces at its mid-height, keeping every
// shape's winding number: a piece's jump is the value after it minus the value before it, so
// the jumps of a band add up along the walk exactly, in whatever order ties were broken.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "patterns/scene/bezier.h"
#include "patterns/scene/scene.h"

namespace aabench {

// Two pieces whose boxes overlap are subdivided until both boxes are smaller than this: where
// they cross, the band border lies within it of the crossing, which moves the area of any
// pixel by less than the tolerance times the pieces' separation there (<= 1e-12 px^2 for
// crossings at any angle at ordinary sizes; docs/references.md).
inline constexpr double kIntersectionTolerancePx = 1e-12;

// One monotone piece of a segment: t from t0 to t1 (t0 < t1), y increasing with t when `down`.
struct BezierPiece {
    const Segment* segment;
    double t0, t1;
    Point a, b;  // B(t0), B(t1)
    int shape;
    bool down;
    double y_top() const { return down ? a.y : b.y; }
    double y_bottom() const { return down ? b.y : a.y; }
    double t_top() const { return down ? t0 : t1; }
    double t_bottom() const { return down ? t1 : t0; }
};

// A piece crossing a band, from its top (t_top, y_top) to its bottom, with its jump.
struct BandPiece {
    const BezierPiece* piece;
    double t_top, t_bottom;
    double jump;
};

struct BezierBand {
    double y_top, y_bottom;
    std::span<const BandPiece> pieces;  // left to right; only those with a nonzero jump
};

// The scene's shapes as monotone pieces: each shape's outline, or its polygon contours as
// straight segments (held in `storage`; the pieces point into it and into the scene, so they
// live as long as both).
struct BezierPieces {
    std::vector<Segment> storage;
    std::vector<BezierPiece> pieces;
};
BezierPieces monotone_pieces(const Scene& scene);

// Calls fn for every band of the scene within y_lo <= y <= y_hi, top to bottom, with the pieces
// of monotone_pieces(scene) (the band's pieces point into `pieces`). The scene has no circles
// and no depth planes (monotone_pieces throws std::logic_error otherwise).
void sweep_bezier_bands(const Scene& scene, const BezierPieces& pieces, double y_lo, double y_hi,
                        const std::function<void(const BezierBand&)>& fn);

}  // namespace aabench
