// The edge stage (Saito & Takahashi 1990, seed 002, §3.2–3.4): contours and creases drawn by
// image processing on the depth image z_s = f^2 / z_v that hidden-surface removal gives for
// free, then composited with the shaded image. It runs only for scenes with an `edges` block
// (the plan's edge stage); it does no I/O. docs/edges.md has the equations and the readings.
#pragma once

#include "methods/scan/image.h"
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

// All images have the depth image's size; `shaded` must have it too. Pixels outside the image
// repeat the border (no contour is drawn along the frame). Throws InputError on a size mismatch.
EdgeImages enhance_edges(const Image& depth, const Image& shaded, const EdgesSpec& spec);

}  // namespace aabench
