// Exact curves in the scene: the `disc` and `ring` shapes of scene file version 2
// (docs/scene-format.md, "Version 2 keys"), and the polygonisation that methods without curve
// support draw.
//
// A curve shape is a Shape with `circle` set (scene.h). Its `contours` hold an inscribed
// regular polygon per boundary circle (the outer one clockwise in the y-down frame, the inner
// one of a ring counter-clockwise, so the hole has winding number 0), made here once, when the
// shape is built, so every piece of code that knows only polygons (methods, symptoms, edge
// masks, timing) sees the polygon and every piece that knows curves (the box reference,
// methods/scan/reference/curve_coverage.h; aa-circle, wu-circle, midpoint-circle) reads the circle.
//
// The polygon's error bound. An inscribed regular n-gon of a circle of radius r departs from
// it by at most the sagitta s = r (1 - cos(pi / n)) (the gap at the middle of each chord); n is
// the smallest count with s <= kCurveSagittaPx (at least kMinCurveSegments). Every point of the
// polygon's region is within s of the exact region and vice versa, so a box-filtered pixel
// changes by at most s times the boundary length in the pixel (<= ~1.5 px for r >= 1/2): the
// polygonisation moves no pixel by more than 1.5e-7. docs/scene-format.md states it and
// tests/curves_test.cpp measures it against the exact curve reference.
#pragma once

#include "patterns/scene/scene.h"

namespace aabench {

// The largest gap between a boundary circle and its polygon, in px. 1e-7 px keeps the
// polygonisation's pixel errors (<= 1.5e-7) below 1e-4 of the 8-bit peers' quantisation floor
// (~1.1e-3 rms on an edge pixel, 1/510 at most): tests/curves_test.cpp checks the ratio on the
// circle patterns. The cost: n ~ pi sqrt(r / (2 s)) ~ 7000 sqrt(r) vertices per circle.
inline constexpr double kCurveSagittaPx = 1e-7;
inline constexpr int kMinCurveSegments = 8;

// Segments of the inscribed polygon of a circle of radius r (> 0) with sagitta <= the bound.
int curve_segment_count(double radius_px, double sagitta_px = kCurveSagittaPx);
// The sagitta of the inscribed n-gon of radius r: r (1 - cos(pi / n)), computed without
// cancellation as 2 r sin^2(pi / (2n)).
double polygon_sagitta(double radius_px, int segments);

// The inscribed polygon; clockwise in the y-down frame (positive twice_signed_area) or not.
Contour circle_polygon(Point center, double radius_px, bool clockwise);

// A disc (radius > 0) or a ring (0 < inner < outer) with its polygonisation. Throw
// std::invalid_argument on radii out of that range (the scene reader checks first).
Shape disc_shape(Point center, double radius_px, double value);
Shape ring_shape(Point center, double inner_px, double outer_px, double value);

// True when some shape of the scene is a disc or ring.
bool has_curves(const Scene& scene);

// True when two curves provably share no area (touching allowed): apart, or one within the
// other's hole.
bool circles_disjoint(const Circle& a, const Circle& b);

// Moves a shape by (dx, dy): its contours, its Bezier outline and, for a curve, its centre.
void translate_shape(Shape& shape, double dx, double dy);

}  // namespace aabench
