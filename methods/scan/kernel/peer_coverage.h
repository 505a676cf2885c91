// Shared machinery of the peer-library methods (cairo, agg, blend2d, freetype, stb-truetype):
// each lets the library compute an 8-bit coverage mask per fill and composites it over the
// frame buffer in float itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

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

// How the peers hand shapes to their library (parameter `paths`, docs/methods-peers.md).
//   kMerged    each run of consecutive shapes of one value is one fill, as a user drawing
//              the scene would give it: no compositing of coverage where shapes of one run
//              meet or overlap (the conflation a fill per shape shows at the star's centre).
//   kPerShape  one fill per shape, each composited over the result so far.
enum class PeerPaths { kMerged, kPerShape };
PeerPaths peer_paths_from_name(const std::string& name);  // "merged" | "per-shape"

// Shapes [first, last) of a scene, drawn as one fill.
struct ShapeRun {
    std::size_t first = 0, last = 0;
};

// The run that starts at shapes[first]: with kMerged, the consecutive shapes of one constant
// value (an affine value_plane joins no run); with kPerShape, the shape alone.
ShapeRun next_shape_run(const std::vector<Shape>& shapes, std::size_t first, PeerPaths paths);

// Whether a shape's contours go to the library reversed: with kMerged, when the shape's total
// signed area is negative. Nonzero winding then adds the shapes of a run (every shape winds
// positively around its inside) instead of cancelling where a clockwise shape overlaps a
// counter-clockwise one; a shape's own fill is unchanged by reversing all its contours.
bool reverse_for_run(const Shape& shape, PeerPaths paths);

// Calls add_point(p) for each vertex of `contour`, in reverse order when `reverse`.
template <typename AddPoint>
void for_each_vertex(const Contour& contour, bool reverse, AddPoint&& add_point) {
    const std::size_t n = contour.size();
    for (std::size_t k = 0; k < n; ++k) add_point(contour[reverse ? n - 1 - k : k]);
}

// The pixels a shape can touch, grown by one pixel (a rasteriser's vertex rounding to 1/256 px
// never reaches further) and clamped to the image.
PixelBox shape_pixel_box(const Shape& shape, int width, int height);
// The union of the boxes of a run's shapes (empty when every one is).
PixelBox run_pixel_box(const std::vector<Shape>& shapes, ShapeRun run, int width, int height);

// True when a vertex lies beyond `limit` (kPeerSafeCoordinate unless a library's own is
// smaller) or is not finite.
bool needs_clipping(const Contour& contour, double limit = kPeerSafeCoordinate);

// True when the shape has Bezier segments (Shape::outline) whose control points all lie within
// kPeerSafeCoordinate: the peers then draw the curves themselves, at their own tolerance (a
// curve lies in the hull of its control points, so no point of it needs clipping). Otherwise
// they draw the shape's contours, its flattening at kBezierViewFlatnessPx, clipped as needed.
bool draws_outline(const Shape& shape, double limit = kPeerSafeCoordinate);

// How a user of a curve rasterizer (freetype, stb-truetype) draws a disc or a ring: each
// circle as kCircleArcs cubic arcs of 45 degrees, controls on the tangents at 4/3 tan(pi/16) r
// from the ends (the usual cubic arc: its radius errs by at most 4.2e-6 r, 4e-4 px at
// r = 100), not as the scene's polygonisation (finer than those libraries are made for).
inline constexpr int kCircleArcs = 8;

// True when the circle's arcs stay within kPeerSafeCoordinate (centre and radius); the others
// are drawn as their clipped polygonisation.
bool draws_circle_as_arcs(const Circle& circle, double limit = kPeerSafeCoordinate);

// The disc's circle, or the ring's outer circle and its inner one run the other way.
std::vector<SegmentContour> circle_arc_contours(const Circle& circle);

// Calls segment(s) for each segment of `contour` in order, or all reversed (last first, each
// with its control points in reverse order) when `reverse`.
template <typename OnSegment>
void for_each_segment(const SegmentContour& contour, bool reverse, OnSegment&& segment) {
    const std::size_t n = contour.size();
    for (std::size_t k = 0; k < n; ++k) {
        if (!reverse) {
            segment(contour[k]);
            continue;
        }
        Segment r = contour[n - 1 - k];
        for (int i = 0; i <= r.degree / 2; ++i) std::swap(r.p[i], r.p[r.degree - i]);
        segment(r);
    }
}

// Sutherland–Hodgman against the rectangle [x0, x1] x [y0, y1], one side at a time: an
// outside run is replaced by a segment of the side's line, and run plus segment form a loop in
// the outside half-plane (convex), which winds around no inside point, so every point inside
// keeps its winding number.
Contour clip_contour(const Contour& contour, double x0, double y0, double x1, double y1);

// True when an edge of `polygon` passes through the open rectangle (x0, x1) x (y0, y1)
// (Liang–Barsky, strict: an edge along its border does not); otherwise the polygon's winding
// number is the same at every point inside it.
bool crosses_rectangle(const Contour& polygon, double x0, double y0, double x1, double y1);

// The winding number of `polygon` about (x, y): a crossing count signed by direction.
int winding_number(const Contour& polygon, double x, double y);

// How a coverage is blended into the frame buffer. kLinear: in linear light, the values
// themselves (what coverage means, and what the exact reference is). kSrgbCodes: in sRGB codes,
// as a text stack that blends glyph coverage into an sRGB frame buffer without linearising it:
// out = dec(enc(out) + a (enc(value) - enc(out))), enc and dec the IEC 61966-2-1 transfer
// functions in double. White text on black comes out thinner, black on white bolder.
enum class PeerBlend { kLinear, kSrgbCodes };
PeerBlend peer_blend_from_name(const std::string& name);  // "linear" | "srgb"

// out = out + a (value - out), a = coverage / 255, in double, rounded once to float (or the
// same in sRGB codes, `blend`). Full coverage writes the value itself (the lerp would round),
// none leaves the pixel alone.
void composite_coverage_row(const std::uint8_t* coverage, float* out, int count, double value,
                            PeerBlend blend = PeerBlend::kLinear);

}  // namespace aabench
