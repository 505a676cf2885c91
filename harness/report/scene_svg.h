// A 2-D scene as SVG, for renderers that read SVG (aabench export --out F.svg, the {svg} of
// compare --external; docs/external.md). Pure text; the caller writes it (write_text_file).
//
// What is written: the image size as the SVG's width, height and viewBox (1 user unit = 1 px,
// y down, as in the scene), the background as a rectangle covering the viewBox, then every shape
// in order as one <path> of all its contours with fill-rule="nonzero" (the scene's rule), later
// paths over earlier ones (the scene's compositing). Bezier segments are written as curves (Q, C)
// and discs and rings as circles (two half-circle arcs A each, a ring's hole the other way
// round), not as their polygonisation: each renderer draws them as its users' SVG would. A value v is the grey #cccccc with
// c = round(clamp(v, 0, 1) x 255): linear codes, so a renderer that blends in its codes (as
// Cairo, and so rsvg-convert, does) blends linearly, and its output is read without --srgb.
// The 8-bit quantisation of values is the floor of this route (exact-8bit shows its size).
// The scene is in its window frame (a prepared frame's pieces: harness/world/frame.h), and its
// coordinates are written as the shortest text that reads back to the same double.
#pragma once

#include <string>

#include "patterns/scene/scene.h"

namespace aabench {

// Throws InputError for a scene SVG cannot hold this way: a 3-D scene whose world has not been
// drawn (give its visible pieces, harness/world/frame.h) or a shape with an affine value.
std::string scene_to_svg(const Scene& scene);

}  // namespace aabench
