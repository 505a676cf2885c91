// One image from anywhere (a user's renderer, a file) scored as `compare` scores a method's
// render: every figure of a result row that needs only that one image. Pure computation; the
// CLI reads the image and the report formats the result.
//
// Figures (the same definitions, names and code as compare's rows; docs/metrics.md):
//   box_*, dropout     against the exact box reference
//   own_*              against the exact reference of `filter` (box unless given)
//   edge_rmse, alias   against the own-filter reference, as compare measures them
//   ssim               against the box reference
//   seams_*            3-D scenes whose visible faces share edges
// Not here: captured mass, crawl and popping, which need the renderer run on moved scenes.
#pragma once

#include <string>

#include "harness/measure/compare.h"
#include "methods/scan/kernel/image.h"

namespace aabench {

// `scene` as a pattern or scene file gives it (2-D, or 3-D: it goes through the world pipeline
// first, as in compare); `image` must be of its size (InputError otherwise, naming
// `image_name`). `filter` is a reference spec (box, gaussian:..., cone:...), checked first. A
// job past the memory budget is an InputError before any reference is computed. Fills the
// row's size, edges, world stage costs and figures; pattern, method and timing fields are left
// for the caller.
// A grey image against a colour scene is an InputError saying which is which.
ResultRow score_image(const Image& image, const Scene& scene, const std::string& filter,
                      const std::string& image_name);
// An image of 1 or 3 planes: three against a colour scene score every channel (box_* over the
// channels, luma_rmse, the rest on the luminance, as compare scores a colour scene); three
// against a grey scene, or one against a colour scene, is an InputError saying which is which.
ResultRow score_image(const ImagePlanes& image, const Scene& scene, const std::string& filter,
                      const std::string& image_name);

}  // namespace aabench
