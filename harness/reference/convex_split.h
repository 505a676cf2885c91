// Convex polygons in the pixel frame cut by lines: the geometry of exact visibility
// (harness/reference/visibility.cpp). Everything here is a function of its arguments; the
// tolerances are the caller's, passed in and named there.
//
// A polygon here is a Contour with positive twice_signed_area() (patterns/scene/scene.h:
// clockwise on the y-down screen, counter-clockwise in the usual y-up drawing). Its inside is
// then on the left of every edge a -> b: cross(b - a, p - a) > 0.
#pragma once

#include <vector>

#include "patterns/scene/scene.h"

namespace aabench {

// An affine function of the position, f(p) = k + nx * (p.x - x0) + ny * (p.y - y0), kept
// relative to an anchor (x0, y0) near where it is evaluated: for an edge the anchor is one of
// its endpoints, so f at points near the edge is a product of small differences, not the
// cancellation of two large products (a x + b y + c far from the origin).
struct LinearForm {
    double k = 0.0;
    double nx = 0.0;
    double ny = 0.0;
    double x0 = 0.0;
    double y0 = 0.0;
    double at(const Point& p) const { return k + nx * (p.x - x0) + ny * (p.y - y0); }
};

// The signed distance from the line through a and b, positive on its left (inside of a
// positively oriented polygon). a != b.
LinearForm edge_form(const Point& a, const Point& b);

// The inside of a positively oriented convex polygon: one edge_form per edge.
std::vector<LinearForm> edge_forms(const Contour& poly);

struct Bounds {
    double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
    // Overlap with positive area: boxes that only touch along a side cannot hold a
    // positive-area overlap of their polygons.
    bool overlaps(const Bounds& o) const {
        return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
};
Bounds bounds_of(const Contour& poly);

// max(1, largest |coordinate|) over the polygon: the size that rounding errors of positions
// scale with (one unit in the last place of a coordinate is 2^-52 of it).
double coordinate_scale(const Contour& poly);

// A convex polygon with, optionally, the line each edge lies on: e[k] is the form of the edge
// v[k] -> v[k+1], positive inside. Why carry the lines rather than recompute them from the
// vertices: a vertex made by a cut carries a rounding error of a few ulps of the coordinates,
// so the line through two cut vertices a few ulps apart points anywhere and, used to clip
// another polygon, would cut through the middle of it. The lines carried here are always the
// lines of input edges or of cuts (long-lived, exact to the rounding of their own data), so
// every clip by this polygon is by the right line however short its edge has become.
struct ConvexPolygon {
    Contour v;
    std::vector<LinearForm> e;  // empty: not tracked (pieces that are never clipped against)
};

inline LinearForm negated(const LinearForm& f) { return {-f.k, -f.nx, -f.ny, f.x0, f.y0}; }
// The same line with a unit gradient, so that the form is a distance in pixels. |grad| > 0.
LinearForm unit_form(const LinearForm& f);

// True when an edge line of one polygon has every vertex of the other more than `tolerance`
// outside it (both polygons track their edge lines): a separating axis, so the two do not
// overlap. Two convex polygons that are disjoint by more than the tolerance always have one
// among their edge lines; this finds it with no cut made.
bool separated_by_an_edge(const ConvexPolygon& p, const ConvexPolygon& q, double tolerance);

// What split_convex found.
enum class SplitOutcome {
    kPositive,  // no vertex below -tolerance, at least one above +tolerance: all positive
    kNegative,  // the mirror image: all negative
    kOnLine,    // every vertex within the tolerance of the line: a degenerate polygon
    kSplit,     // vertices on both sides: both parts written
};

// Splits a convex polygon by the line f = 0. A vertex with |f| <= tolerance counts as on the
// line and goes into both parts (no new vertex is made next to it); an edge whose ends lie
// strictly on opposite sides gets one new vertex, computed once and shared by both parts, so
// the two parts meet along the same segment. Outputs are written only for kSplit. When the
// polygon tracks its edge lines, the parts do too: old edges keep theirs, the new edge gets
// `cut_edge` (default f; it must be positive where f is) in the positive part and its negation
// in the negative part. A part not wanted may be null (a clip keeps one side only).
SplitOutcome split_convex(const ConvexPolygon& poly, const LinearForm& f, double tolerance,
                          ConvexPolygon* positive, ConvexPolygon* negative,
                          const LinearForm* cut_edge = nullptr);

// True when the polygon is thinner than `width` in the sense that 2 * area <= width * D,
// with D the diagonal of its bounding box. For a convex polygon with diameter D' (D / sqrt 2
// <= D' <= D) the minimal width w satisfies area >= w D' / 2 (it holds a triangle of base D'
// and height w), so "sliver" implies w <= sqrt 2 * width, and the part of it inside any one
// unit pixel (a strip of width w across a square) has area <= 2 * width.
bool is_sliver(const Contour& poly, double width);

// An input contour made fit for the above: exact repeats and vertices within `slack` of the
// chord of their neighbours removed (changing the area by at most slack x the chord, per
// pixel at most slack x 1.5), positively oriented. Fewer than three vertices left: empty.
Contour cleaned_contour(const Contour& contour, double slack);
// The same in place: no allocation (what a loop over many small polygons wants).
void clean_contour(Contour& poly, double slack);

// Convexity check for input shapes: every vertex lies on the inner side of every edge line
// (or within `slack` of it) and the boundary turns once around (not a star, not a polygon
// traversed twice). `poly` must be positively oriented and have no repeated vertices.
bool is_convex(const Contour& poly, double slack);

}  // namespace aabench
