// The exact box engine for scenes with curves (disc and ring shapes, patterns/scene/curves.h):
// the area of disc ∩ pixel in closed form, and the scene composited in shape order from the
// shapes' areas. docs/references.md ("Curves") has the derivation.
//
// It lives in the scan-conversion room, beside the polygon engine (box_coverage.h), because
// the box reference (harness/reference/box_reference.h) and the `exact` methods share it.
#pragma once

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// Area of the disc of radius r about the origin within the axis-aligned unit square
// [u0, u0 + 1] x [v0, v0 + 1] (coordinates relative to the disc's centre). Error <= ~4
// ulp(max(|u0|, |v0|, r)) (the crossing points carry the rounding of the coordinates; every
// other term is taken relative to the square's corner): 1.5e-13 for r ~ 300.
double disc_square_area(double u0, double v0, double r);

// The exact box-filtered scene (as box_coverage() for polygons) when some shapes are curves.
// Runs of consecutive polygon shapes go to the polygon engine as one layer (to the Bezier engine,
// bezier_coverage.h, when the run has Bezier segments); each curve shape is a layer of its own (area per pixel: disc(outer) - disc(inner)). Layers composite per
// pixel in order, exactly, where in each pixel the layers that cover it partly are pairwise
// disjoint there (concentric rings that only touch, discs apart, a curve on a region that
// covers the whole pixel). A row with a pixel where they may meet (a disc's edge across a
// polygon's, two discs overlapping) is computed instead by the band sweep of the whole scene
// with the circles as quarter arcs (bezier_coverage.h, bezier_rows_each): exact too, by
// another route. Areas within 1e-13 of 0 or 1 count as empty or full (the rounding of the
// areas themselves is larger).
Coverage curve_box_coverage(const Scene& scene);

// Rows [row_lo, row_hi) of curve_box_coverage rounded to float32, for the `exact` methods (the
// scene in its window frame, methods/method.h). Only those rows are computed, and
// only the pixels the shapes' boxes reach (concentric rings of radius 32 are 65 x 65 pixels of
// work at any image size); the rest of each row is a fill with the background. The per-pixel
// state is kept per thread, but the layers are built per call: the curve path is not among
// the allocation-free renders (tests/render_alloc_test.cpp says so). Rows where shapes may
// overlap go to the sweep row by row, as in curve_box_coverage, so the image does not depend
// on how the rows are split into bands.
void curve_rows(const Scene& scene, Image& out, int row_lo, int row_hi);

}  // namespace aabench
