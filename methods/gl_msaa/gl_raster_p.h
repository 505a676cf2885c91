// A real OpenGL driver's multisample rasteriser for gl-msaa (methods/gl_msaa/gl_msaa.cpp): Mesa's
// llvmpipe through OSMesa, off-screen, no GPU and no window system. docs/gl-msaa.md says what
// it computes and how it is tested against ssaa at the driver's own sample positions.
//
// One GL context per thread, made on the thread's first draw and kept until the thread ends
// (a context is current on one thread only; a Method's render is const and called from several
// threads at once). The driver is told to rasterise in the calling thread (LP_NUM_THREADS=0,
// unless the environment sets it) and never to touch a disk cache (MESA_SHADER_CACHE_DISABLE),
// so a render is single-threaded and does no I/O like every other method's.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// The side of the square tile the driver draws at a time (an image is cut into tiles of at
// most this many pixels each way). Fixed, so that the vertex transform is the same for every
// tile and every band of rows: see gl_raster.cpp, "Exact vertices".
inline constexpr int kGlTileSidePx = 512;

// Vertices are rounded to this grid (px) before the driver sees them: llvmpipe's own
// sub-pixel precision (8 fractional bits), applied by us so that it is the same in every tile.
inline constexpr double kGlVertexGridPx = 1.0 / 256.0;

// Discs and rings (Shape::circle) are drawn as inscribed polygons of this sagitta, half the
// vertex grid, as a renderer tessellates a curve to its device's precision: their scene
// polygons (patterns/scene/curves.h, 1e-7 px, about 7000 sqrt(r) vertices per circle) would
// cost llvmpipe about 4 us a triangle for detail it rounds away (about 50 sqrt(r) here).
inline constexpr double kGlCurveSagittaPx = kGlVertexGridPx / 2.0;

// Rows [row_lo, row_hi) of `scene` (no window origin) drawn by the driver into `out`:
// samples = 1 (one sample at each pixel centre) or 4 (4x MSAA: a float32 multisample target,
// resolved by glBlitFramebuffer, the driver's box average in linear float). Shapes are drawn
// in order with stencil-then-cover (nonzero winding over all contours of a shape, a later
// shape covering an earlier one); a ScreenScene (shapes with depth planes) through the
// driver's depth test, one depth per sample. Throws std::runtime_error when the driver cannot
// give what is asked (no context, fewer than 4 samples).
void gl_draw_rows(const Scene& scene, int samples, Image& out, int row_lo, int row_hi);

// The driver's sample positions for `samples` (1 or 4), as offsets in the image's pixel
// [0, 1)^2 from its top-left corner, y down, in the driver's sample order. GL reports them y up
// from the pixel's bottom in its window frame; gl_draw_rows draws the image with its row j at
// window row j (upside down in GL's frame), so GL's y up within a pixel is the image's y down
// and the positions need no flip (gl_raster.cpp says why this is the one consistent reading).
std::vector<std::array<double, 2>> gl_sample_positions(int samples);

// The driver as it names itself: "Mesa <version>, <renderer>" (GL_VERSION, GL_RENDERER).
std::string gl_driver_name();

}  // namespace aabench
