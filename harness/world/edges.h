// The edge stage (Saito & Takahashi 1990, §3.2–3.4): contours and creases drawn by
// image processing on the depth image z_s = f d / z_v that hidden-surface removal gives for
// free, then composited with the shaded image. It runs only for scenes with an `edges` block
// (the plan's edge stage); it does no I/O. docs/edges.md has the equations and the readings.
#pragma once

#include "methods/scan/kernel/image.h"
#include "patterns/scene/world.h"

namespace aabench {

struct EdgeImages {
    Image g;          // first derivative of depth: Sobel (eq. 3) or Prewitt (eq. 4)
    Image l;          // second derivative: Laplacian (eq. 5) or its 8-neighbour form (eq. 6);
                      // zero when crease = "none"
    Image p;          // contour brightness, eq. 7, in [0, 1]
    Image e;          // crease value, eq. 8: > 0 on convex creases, < 0 on concave ones
    Image lines;      // the line drawing (Fig. 3 g / g'): "black" style, darkness in [0, 1];
                      // "white-convex", light minus darkness in [-1, 1]
    Image composite;  // lines over the shaded image (Fig. 3 h / h')
};

// All images have the depth image's size; `shaded` must have it too. Past the frame the depth
// image is continued linearly (no contour or crease is drawn along the frame). Throws InputError
// on a size mismatch.
EdgeImages enhance_edges(const Image& depth, const Image& shaded, const EdgesSpec& spec);

// The same, written into `out`: an image of `out` that already has the depth image's size keeps
// its buffer (every pixel is overwritten), any other is reallocated. The stage's intermediate
// images (the depth continued past the frame, the operators' outputs, g's local max and min)
// are per-thread buffers kept between calls and reused while the size stays the same, so a
// caller that keeps `out` (a benchmark, a video) allocates nothing per call: fresh full-size
// buffers cost page faults that took 10-15x the filtering on a virtual machine (docs/edges.md,
// "Edge-enhanced drawing"). Results are bit-identical to enhance_edges above. The buffers hold
// about 5 float images of (width + 2) x (height + 2) per thread that ran the stage, until the
// thread ends.
void enhance_edges(const Image& depth, const Image& shaded, const EdgesSpec& spec,
                   EdgeImages& out);

}  // namespace aabench
