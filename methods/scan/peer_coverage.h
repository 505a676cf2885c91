// Shared machinery of the peer-library methods (cairo, agg): both let the library compute an
// 8-bit coverage mask per shape and composite it over the frame buffer in float themselves.
#pragma once

#include <cstdint>

#include "patterns/scene/scene.h"

namespace aabench {

// Both libraries keep coordinates in fixed point or multiply coordinate differences, which
// overflows far from the image; contours reaching beyond this are clipped first. 2^20 px is
// far beyond any image side (kMaxImageSide = 2^16), so ordinary contours reach the library
// untouched.
inline constexpr double kPeerSafeCoordinate = 1048576.0;

struct PixelBox {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // [x0, x1) x [y0, y1)
    bool empty() const { return x0 >= x1 || y0 >= y1; }
};

// The pixels a shape can touch, grown by one pixel (a rasteriser's vertex rounding to 1/256 px
// never reaches further) and clamped to the image.
PixelBox shape_pixel_box(const Shape& shape, int width, int height);

// True when a vertex lies beyond kPeerSafeCoordinate (or is not finite).
bool needs_clipping(const Contour& contour);

// Sutherland–Hodgman against the rectangle [x0, x1] x [y0, y1], one side at a time: an
// outside run is replaced by a segment of the side's line, and run plus segment form a loop in
// the outside half-plane (convex), which winds around no inside point, so every point inside
// keeps its winding number.
Contour clip_contour(const Contour& contour, double x0, double y0, double x1, double y1);

// out = out + a (value - out), a = coverage / 255, in double, rounded once to float. Full
// coverage writes the value itself (the lerp would round), none leaves the pixel alone.
void composite_coverage_row(const std::uint8_t* coverage, float* out, int count, double value);

}  // namespace aabench
