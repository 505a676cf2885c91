// Shared machinery of the circle methods (aa-circle, wu-circle, midpoint-circle): which shapes
// they can draw, and the eight-way plotter that composites one circle's pixels.
//
// The grid. The circle algorithms (aa-circle's source, Wu 1991, Bresenham) put pixel centres on
// integer coordinates and draw circles of integer centre and radius. Here pixel (i, j) covers
// [i, i+1] x [j, j+1], so their circle of centre (cx, cy) and radius r is ours of centre
// (cx + 1/2, cy + 1/2), and their pixel (cx + x, cy + y) is ours (cx + x, cy + y). What they
// draw is a line one pixel wide, so the shape they stand for is the ring between r - 1/2 and
// r + 1/2; radius 0 is a point, the disc of radius 1/2 about the pixel centre.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

struct GridCircle {
    int cx = 0;  // the pixel holding the centre: centre (cx + 1/2, cy + 1/2)
    int cy = 0;
    int radius = 0;  // integer, >= 0
    double value = 1.0;
};

// The scene as grid circles, in shape order. Returns the reason (naming the shape) when some
// shape is not one: a polygon, a ring not one pixel wide, a centre off the pixel centres, a
// non-integer radius; empty when every shape is one. Radii above kMaxGridRadius are refused
// (int arithmetic r^2 must not overflow).
inline constexpr int kMaxGridRadius = 1 << 20;
// Centres beyond this many px of the window's origin are refused too (pixel indices are ints:
// centre + radius must not overflow).
inline constexpr double kMaxGridCentre = 1 << 30;
// Circles whose bounding box (plus 2 px) misses the window draw nothing and are left out,
// unchecked, so a band of the image never refuses what the whole image accepts.
std::string grid_circles(const Scene& scene, std::vector<GridCircle>* circles);

// Collects one circle's pixels with their coverage alpha in [0, 1]; a pixel written twice
// (on the axes and the diagonals, where octants meet) keeps the larger alpha, so the eight
// octants never add ink twice. flush() composites the circle over the image,
// out = out + (value - out) * alpha, and clears for the next circle. Cost O(pixels written).
// Its scratch (a per-pixel alpha, the touched list) is per thread and kept between renders, so
// a warm render allocates nothing (tests/render_alloc_test.cpp).
class CirclePlotter {
public:
    // Pixels outside rows [row_lo, row_hi) (a band of the image) are dropped.
    CirclePlotter(Image& out, int row_lo, int row_hi);
    ~CirclePlotter();  // drops an unflushed circle, leaving the scratch clear for the next
    CirclePlotter(const CirclePlotter&) = delete;
    CirclePlotter& operator=(const CirclePlotter&) = delete;
    // The source's pixel (x, y) of the circle about (cx, cy), all eight symmetric images.
    void plot8(int cx, int cy, int x, int y, float alpha);
    void plot(int i, int j, float alpha);
    void flush(double value);

private:
    Image& out_;
    int row_lo_, row_hi_;
    std::vector<float>& alpha_;  // per pixel, 0 where unwritten (thread-local, >= image size)
    std::vector<std::size_t>& touched_;
};

// Rows [row_lo, row_hi) filled with the background, or NaN if `reason` is not empty (a method
// asked to draw what it cannot: see Method::not_applicable).
// The grid circles of `scene` in a per-thread vector (reused: no allocation once warm), and
// the reason as grid_circles() gives it.
std::string grid_circles_scratch(const Scene& scene, const std::vector<GridCircle>*& circles);

void fill_for_circles(const Scene& scene, const std::string& reason, Image& out, int row_lo,
                      int row_hi);

// What every circle method's draw_rows() does for rows [row_lo, row_hi): the background (or
// NaN everywhere with the reason, when some shape is not a grid circle), then each circle
// drawn by draw(cx, cy, radius, plotter) and composited in shape order, its pixels in the
// rows kept. Allocation-free when warm.
template <class Draw>
void render_grid_circles(const Scene& scene, Image& out, int row_lo, int row_hi, Draw draw) {
    const std::vector<GridCircle>* circles = nullptr;
    const std::string reason = grid_circles_scratch(scene, circles);
    fill_for_circles(scene, reason, out, row_lo, row_hi);
    if (!reason.empty()) return;
    CirclePlotter plotter(out, row_lo, row_hi);
    for (const GridCircle& c : *circles) {
        draw(c.cx, c.cy, c.radius, plotter);
        plotter.flush(c.value);
    }
}

}  // namespace aabench
