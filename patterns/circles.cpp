// `circles`: concentric one-pixel circles of integer radii 1..R about a pixel centre, each the
// ring r - 1/2 <= distance <= r + 1/2 (value 1 on background 0), the shape the circle
// methods (aa-circle, wu-circle, midpoint-circle) stand for (methods/scan/circles/circle_raster.h).
//
// Aliasing it provokes: a moiré of its own. The rings tile the disc of radius R + 1/2 less
// the centre's disc of radius 1/2, so the exact image is 1 there, flat: every ring a method
// draws with too little or too much ink, or with ink in the wrong pixels, shows as a pattern
// against a flat answer, strongest where a one-pixel line is thinnest (toward 45 degrees for
// a horizontal-distance rule). The rings are exact curves (scene file `ring`); polygon methods
// draw their polygonisation (patterns/scene/curves.h).
//
// Parameters:
//   max_radius  32   R, the outermost ring (1..2000; clipped by the image like any shape).
//                    32 keeps the polygonisation at ~1.7 million vertices.
#include <algorithm>
#include <cmath>

#include "patterns/pattern.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

Scene generate_circles(const ParamValues& values, int width, int height) {
    const int max_radius = values.get_int("max_radius");
    Scene scene = begin_pattern_scene("circles", values, width, height);
    // A pixel centre near the middle: integer + 1/2, the source's integer centre.
    const Point centre{width / 2 + 0.5, height / 2 + 0.5};
    // Rings wholly outside the image draw nothing and would only cost vertices: stop at the
    // farthest corner.
    const double corner = std::hypot(std::max(centre.x, width - centre.x),
                                     std::max(centre.y, height - centre.y));
    for (int r = 1; r <= max_radius && r - 0.5 < corner; ++r) {
        scene.shapes.push_back(ring_shape(centre, r - 0.5, r + 0.5, 1.0));
    }
    // The outermost ring at 45 degrees, where the line is thinnest.
    const double d = 0.7071067811865476 * max_radius;
    set_focus(scene, centre.x + d, centre.y - d, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo circles_pattern() {
    return {"circles",
            "concentric one-pixel circles (rings r -+ 1/2) of radii 1..R about a pixel centre",
            {{"max_radius", ParamKind::kInt, 32, 1, 2000, {},
              "R, the outermost ring; 32 keeps the polygonisation near 1.7 M vertices"}},
            generate_circles};
}

}  // namespace aabench
