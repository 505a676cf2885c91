// `circle-radii`: single one-pixel circles of radii 0, 1, 2, 3, 5, 8, 13, 21, 34, 55, 89, 144,
// 200 (Fibonacci, capped at 200), each the ring r - 1/2 <= distance <= r + 1/2 about a pixel
// centre (radius 0: the point, the disc of radius 1/2), value 1 on background 0.
//
// What it shows: how a circle method behaves at each size, small radii above all, where a
// table-driven octant has only a few steps (radius 1 gets no antialiasing in aa-circle's source)
// and the exact answer is far from a thin line.
//
// Layout: shelves, left to right in increasing radius; circle r takes a cell 2r + 3 px wide,
// a shelf as tall as its largest cell; a circle that does not fit the width starts the next
// shelf. At 256 x 256 the radii up to 55 are whole; the larger ones are clipped by the image
// like any shape (their visible arcs still count).
//
// Parameters:
//   max_radius  200  the largest radius drawn (the list is cut there; 0..200).
#include <algorithm>
#include <array>

#include "patterns/pattern.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

constexpr std::array<int, 13> kRadii = {0, 1, 2, 3, 5, 8, 13, 21, 34, 55, 89, 144, 200};

Scene generate_circle_radii(const ParamValues& values, int width, int height) {
    const int max_radius = values.get_int("max_radius");
    Scene scene = begin_pattern_scene("circle-radii", values, width, height);
    int x = 0, y = 0, shelf = 0;
    for (int r : kRadii) {
        if (r > max_radius) break;
        const int cell = 2 * r + 3;
        if (x > 0 && x + cell > width) {  // next shelf
            x = 0;
            y += shelf;
            shelf = 0;
        }
        if (y >= height) break;  // this shelf and the rest lie below the image
        // The centre pixel is the cell's middle one: centre at integer + 1/2.
        const Point centre{x + r + 1.5, y + r + 1.5};
        scene.shapes.push_back(r == 0 ? disc_shape(centre, 0.5, 1.0)
                                      : ring_shape(centre, r - 0.5, r + 0.5, 1.0));
        x += cell;
        shelf = std::max(shelf, cell);
    }
    set_focus(scene, 16.0, 8.0, kFocusSidePx);  // the small radii, top left
    return scene;
}

}  // namespace

PatternInfo circle_radii_pattern() {
    return {"circle-radii",
            "single one-pixel circles of radii 0,1,2,3,5,8,...,200 on shelves",
            {{"max_radius", ParamKind::kInt, 200, 0, 200, {}, "the largest radius drawn"}},
            generate_circle_radii};
}

}  // namespace aabench
