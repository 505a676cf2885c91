// The exact box engine for scenes with Bezier segments (scene file version 4, Shape::outline):
// per pixel the exact area-weighted visible value, with no flattening. Every shape's nonzero
// winding region, shapes composited in order where they overlap, contours crossing each other
// and themselves (a cubic's loop), straight edges of polygon shapes beside them.
//
// The jumps of the visible value come from the band sweep (bezier_sweep.h); each piece of a
// band adds its jump times its area right of it to every pixel, ftgrays-style: the piece is
// cut at every integer y and x into pieces inside one cell, and a cell's cover (the jump times
// the height) and area (the jump times the integral of x - cell's left edge over y, an exact
// polynomial integral in t: 3-point Gauss-Legendre is exact to degree 5) give each pixel its
// value by one prefix sum along the row. docs/references.md ("Curves: Bezier segments") has the
// derivation and the error bound (<= 1e-9 per pixel; rounding and the crossings' tolerance
// give ~1e-12 at ordinary sizes).
//
// It lives in the scan-conversion room, beside the polygon and circle engines, because the box
// reference (harness/reference/box_reference.h) and the `exact` methods share it.
#pragma once

#include <span>

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// The exact box-filtered scene. Shapes are polygons, have an outline, or are discs and rings
// (their circles swept as quarter arcs, bezier_sweep.h); affine values (Shape::value_plane)
// are integrated exactly as first moments (5-point Gauss-Legendre on the polynomials), beside
// polygons and outlines only. No depth planes, no disc or ring beside affine values
// (std::logic_error: the callers refuse those first).
Coverage bezier_box_coverage(const Scene& scene);

// Rows [row_lo, row_hi) of it rounded to float32 into `out` (the `exact` methods).
void bezier_rows(const Scene& scene, Image& out, int row_lo, int row_hi);

// Each row of `rows` (within the image) as the sweep gives it over that one row alone, into
// `out` (double or rounded to float32): a row's values do not depend on which other rows are
// asked, so the curve engine (curve_coverage.h) resolves its rows of overlapping discs or rings
// with it and renders in bands the same image at any thread count.
void bezier_rows_each(const Scene& scene, std::span<const int> rows, Coverage& out);
void bezier_rows_each(const Scene& scene, std::span<const int> rows, Image& out);

}  // namespace aabench
