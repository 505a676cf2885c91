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
// pieces (at most 5 per cubic; a disc's or ring's circle into its four quarters), so each piece meets a horizontal or vertical line at most once
// and its bounding box is the box of its ends. Horizontal pieces are dropped: no horizontal
// line crosses them. The scene is then cut into bands at every piece's top and bottom and at
// every crossing of two pieces (found by subdividing boxes down to kIntersectionTolerancePx),
// so that inside a band each active piece spans it and no two of them cross. Each band is
// walked once, left to right, in the order of the pieces at its mid-height, keeping every
// shape's winding number: a piece's jump is the value after it minus the value before it, so
// the jumps of a band add up along the walk exactly, in whatever order ties were broken.
#pragma once

#include <algorithm>
#include <cmath>
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

// A quarter of a circle (the boundary of a disc or ring, Shape::circle) as a monotone piece:
// the points center + r (cos theta, sin theta) for theta = (quadrant + tau) pi / 2, tau = t
// in [0, 1], or 1 - t when `reversed` (a ring's inner circle runs the other way round, so
// that its winding number cancels the outer circle's in the hole).
struct QuarterArc {
    Point center;
    double r;
    int quadrant;  // 0 .. 3
    bool reversed;
};

// The arc's point at t (its ends exactly: center + r times a unit axis), its derivative, and
// the integral of (x(t) - c) y'(t) dt from ta to tb in closed form: the chord's trapezoid plus
// the circular segment between chord and arc, r^2 / 2 (d - sin d) for the angle d between
// the ends (a series for small d, where the difference cancels).
Point arc_at(const QuarterArc& arc, double t);
Point arc_derivative(const QuarterArc& arc, double t);
double arc_area_integral(const QuarterArc& arc, double ta, double tb, double c);
// The t in [lo, hi] where coordinate `axis` (0 x, 1 y) equals `value` (clamped to the arc's
// range): atan2 of the two legs, the other leg as sqrt((r - s)(r + s)), good to the rounding
// of the coordinates at every angle (an arcsine would lose half the digits near the ends).
double arc_solve(const QuarterArc& arc, int axis, double value, double lo, double hi);

// One monotone piece of a segment or a quarter circle (`arc` set, `segment` null): t from t0
// to t1 (t0 < t1), y increasing with t when `down`.
struct BezierPiece {
    const Segment* segment;
    double t0, t1;
    Point a, b;  // B(t0), B(t1)
    int shape;
    bool down;
    const QuarterArc* arc = nullptr;
    double y_top() const { return down ? a.y : b.y; }
    double y_bottom() const { return down ? b.y : a.y; }
    double t_top() const { return down ? t0 : t1; }
    double t_bottom() const { return down ? t1 : t0; }
};

// The piece's point, derivative and root of coordinate `axis` = value, for either kind: the
// segment's own bezier_at, bezier_derivative and solve_monotone (patterns/scene/bezier.h), or
// the arc's.
inline Point piece_at(const BezierPiece& p, double t) {
    return p.arc ? arc_at(*p.arc, t) : bezier_at(*p.segment, t);
}
inline Point piece_derivative(const BezierPiece& p, double t) {
    return p.arc ? arc_derivative(*p.arc, t) : bezier_derivative(*p.segment, t);
}
inline double piece_solve(const BezierPiece& p, int axis, double value, double lo, double hi) {
    return p.arc ? arc_solve(*p.arc, axis, value, lo, hi)
                 : solve_monotone(*p.segment, axis, value, lo, hi);
}

// piece_solve as a function pointer: the cell cutting's default root finder.
inline double default_piece_solve(const BezierPiece& p, int axis, double value, double lo,
                                  double hi) {
    return piece_solve(p, axis, value, lo, hi);
}

// Gauss-Legendre on 3 nodes over [0, 1]: exact for polynomials of degree <= 5, and the area
// integrand (x(t) - c) y'(t) has degree 2 n - 1 <= 5 for a segment of degree n <= 3.
inline constexpr double kGaussLegendre3Nodes[3] = {0.1127016653792583, 0.5, 0.8872983346207417};
inline constexpr double kGaussLegendre3Weights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

// The integral of (x(t) - c) y'(t) dt from ta to tb (in either order); an arc's in closed form.
inline double piece_area_integral(const BezierPiece& p, double ta, double tb, double c) {
    if (p.arc) return arc_area_integral(*p.arc, ta, tb, c);
    const Segment& s = *p.segment;
    const double h = tb - ta;
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double t = ta + kGaussLegendre3Nodes[k] * h;
        sum += kGaussLegendre3Weights[k] * (bezier_at(s, t).x - c) * bezier_derivative(s, t).y;
    }
    return sum * h;
}

// The piece inside one row, from (ta, ya) to (tb, yb) (ya < yb), cut at every integer x in the
// window [0, width]: fn(cell, t0, t1, y0, y1) for each part inside one cell, top to bottom,
// cell -1 for a part left of the window (the whole piece when it lies there); nothing for a
// part right of it. `solve(p, axis, value, lo, hi)` finds the cuts (piece_solve by default).
template <class Fn, class Solve = decltype(&default_piece_solve)>
void for_each_piece_cell(const BezierPiece& p, double ta, double tb, double ya, double yb,
                         int width, const Fn& fn, const Solve& solve = &default_piece_solve) {
    const double xa = piece_at(p, ta).x, xb = piece_at(p, tb).x;
    const double lo = std::min(xa, xb), hi = std::max(xa, xb);
    if (lo >= width) return;  // right of every pixel: changes none
    if (hi <= 0.0) {
        fn(-1.0, ta, tb, ya, yb);
        return;
    }
    // Cut points: integers strictly inside (lo, hi), limited to [0, width].
    const double first = std::max(std::floor(lo) + 1.0, 0.0);
    const double last = std::min(std::ceil(hi) - 1.0, static_cast<double>(width));
    double t0 = ta, y0 = ya, x0 = xa;
    const bool increasing = xb > xa;
    const long long count = last >= first ? static_cast<long long>(last - first) + 1 : 0;
    for (long long k = 0; k <= count; ++k) {
        double t1 = tb, y1 = yb, x1 = xb;
        if (k < count) {
            x1 = increasing ? first + static_cast<double>(k) : last - static_cast<double>(k);
            t1 = solve(p, 0, x1, std::min(t0, tb), std::max(t0, tb));
            y1 = std::clamp(piece_at(p, t1).y, y0, yb);
        }
        const double cell = std::floor(0.5 * (x0 + x1));
        if (cell < width) fn(std::max(cell, -1.0), t0, t1, y0, y1);
        t0 = t1;
        y0 = y1;
        x0 = x1;
    }
}

// A piece crossing a band, from its top (t_top, y_top) to its bottom, with its jump: the
// visible value right of it minus left of it, jump + jump_gx x + jump_gy y at (x, y) (the
// difference of two shapes' affine values, Shape::value_plane; 0 gradients for constants).
struct BandPiece {
    const BezierPiece* piece;
    double t_top, t_bottom;
    double jump;
    double jump_gx = 0.0, jump_gy = 0.0;
};

struct BezierBand {
    double y_top, y_bottom;
    std::span<const BandPiece> pieces;  // left to right; only those with a nonzero jump
};

// The scene's shapes as monotone pieces: each shape's outline, its polygon contours as
// straight segments (held in `storage`), or its circles as quarter arcs (held in `arcs`;
// the pieces point into both and into the scene, so they live as long as all three).
struct BezierPieces {
    std::vector<Segment> storage;
    std::vector<QuarterArc> arcs;
    std::vector<BezierPiece> pieces;
};
BezierPieces monotone_pieces(const Scene& scene);

// Calls fn for every band of the scene within y_lo <= y <= y_hi, top to bottom, with the pieces
// of monotone_pieces(scene) (the band's pieces point into `pieces`). The scene has no depth
// planes, and no disc or ring beside affine values (monotone_pieces throws std::logic_error
// otherwise).
void sweep_bezier_bands(const Scene& scene, const BezierPieces& pieces, double y_lo, double y_hi,
                        const std::function<void(const BezierBand&)>& fn);

}  // namespace aabench
