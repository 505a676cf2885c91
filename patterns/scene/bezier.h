// Bezier segments in the scene (scene file version 4, docs/scene-format.md, "Curve segments"):
// evaluation, the flattening that methods without Bezier support draw, and its proven bound.
//
// A shape with Bezier segments keeps its exact boundary in Shape::outline (scene.h) and a
// flattening of it in Shape::contours, made here once when the shape is built, as for discs
// and rings (curves.h): code that knows only polygons sees the polygon, code that knows
// Beziers (the box reference, methods/scan/reference/bezier_coverage.h; `exact`) reads the
// outline.
//
// The flattening's bound. A segment is cut into n pieces of equal parameter length h = 1/n
// and each piece replaced by its chord. On a piece [a, a + h] the chord is the linear
// interpolant L of B at a and a + h, and per coordinate B(t) - L(t) = B''(xi) (t - a)(t - a - h)
// / 2 for some xi in the piece, so |B(t) - L(t)| <= h^2 / 8 * hypot(max |x''|, max |y''|): the
// distance from every point of the curve to its chord point, so a bound on the Hausdorff
// distance too. For a quadratic B'' = 2 (p0 - 2 p1 + p2) is constant; for a cubic B'' =
// 6 ((1 - t) d1 + t d2) with d1 = p0 - 2 p1 + p2, d2 = p1 - 2 p2 + p3, so max |x''| <=
// 6 max(|d1.x|, |d2.x|) (and y alike). flatten_count() is the smallest n meeting a tolerance.
#pragma once

#include <span>
#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {

// The flattening in Shape::contours: no point of it farther than this from the curve. 1e-4 px
// moves a box-filtered pixel by at most the bound times the boundary length inside it
// (<= ~1.5 px), 1.5e-4: below a seventh of the 8-bit peers' quantisation floor (~1.1e-3 rms
// on an edge pixel), at about 1 + sqrt(3 M / 4e-4) points a segment (M the second
// difference's size in px: ~90 for a cubic of 100 px with a bend of 60 px).
inline constexpr double kBezierViewFlatnessPx = 1e-4;
// A flattening finer than a bound of 1e-9 px would need more than 1e4 points per px of bend,
// and no segment is cut into more than this many pieces (the reader's vertex limit counts
// them first).
inline constexpr long long kMaxFlattenPieces = 1LL << 24;

// A straight edge a -> b, a quadratic a, control c, b, and a cubic a, c1, c2, b.
Segment line_segment(Point a, Point b);
Segment quad_segment(Point a, Point c, Point b);
Segment cubic_segment(Point a, Point c1, Point c2, Point b);

// B(t) for t in [0, 1]; B(0) is p[0] and B(1) the end point exactly.
Point bezier_at(const Segment& s, double t);
// dB/dt.
Point bezier_derivative(const Segment& s, double t);
// hypot(max |x''|, max |y''|) over t in [0, 1] (0 for a line), the bound's M.
double bezier_second_derivative_bound(const Segment& s);
// The largest distance between the segment and its flattening into n equal pieces: M / (8 n^2).
double flatten_deviation_bound(const Segment& s, long long pieces);
// The fewest equal pieces whose chords lie within tolerance_px (> 0) of the segment; 1 for a
// line. Throws std::invalid_argument past kMaxFlattenPieces.
long long flatten_count(const Segment& s, double tolerance_px);
// The contour's flattening: each segment's B(k / n) for k = 0 .. n - 1, n = flatten_count()
// (raised so that the contour has at least 3 points: a lone curve is cut into 3 or more).
Contour flatten(const SegmentContour& contour, double tolerance_px);
// Twice the signed area enclosed (Green's theorem, exact polynomial integrals): positive when
// the contour runs clockwise in the y-down frame, like twice_signed_area() of a polygon.
double twice_signed_area(const SegmentContour& contour);

// Appends to `out` the t in (0, 1) where the derivative of coordinate `axis` (0 x, 1 y)
// vanishes (unsorted; none for a line): cut there, a segment is monotone in that coordinate.
void bezier_extrema(const Segment& s, int axis, std::vector<double>& out);
// The t in [lo, hi] where coordinate `axis` (0 x, 1 y) of a monotone piece equals `value`
// (clamped to the piece's range), to full double precision.
double solve_monotone(const Segment& s, int axis, double value, double lo, double hi);

// The contour as a sampler on the horizontal lines y = ys[k] (ascending) sees it exactly, into
// `out` (cleared first): the polygon through every segment's start, its y-extrema, and its
// crossings with those lines (on each y-monotone piece, the root of y(t) = ys[k] strictly
// inside the piece's y-range, x to full double precision, y the line's exactly). On each line
// the polygon meets the outline at the same x with the same winding, so crossings counted on
// the lines are the curve's; between two lines its chords may lie off the curve. Lines inside
// a segment's y-range cost a root each, the others a binary search per piece.
void polygon_on_lines(const SegmentContour& contour, std::span<const double> ys, Contour& out);

// True when one of the contours has a curve (a segment of degree 2 or 3).
bool has_curve_segment(const std::vector<SegmentContour>& contours);

// A shape with this outline and value, its contours the flattening at kBezierViewFlatnessPx.
// An outline of straight segments only is the polygon of their start points (no outline: a
// scene file cannot tell the two apart, and polygons keep their engines). Every contour must
// be closed (each segment starting where the previous one ends, the last ending at the first's
// start); throws std::invalid_argument otherwise.
Shape bezier_shape(std::vector<SegmentContour> outline, double value);
// The same with contours flattened at `tolerance_px` (the methods that flatten, the oracle).
Shape flattened_shape(const Shape& shape, double tolerance_px);

// The scene with every outline flattened at `tolerance_px` (its shapes then polygons): what a
// method that flattens curves draws.
Scene flattened_scene(const Scene& scene, double tolerance_px);

// True when the shape or some shape of the scene has Bezier segments (an outline).
bool has_bezier(const Shape& shape);
bool has_bezier(const Scene& scene);

}  // namespace aabench
