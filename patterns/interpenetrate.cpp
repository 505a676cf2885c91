// `interpenetrate`: two boxes passing through each other, and three flat bars in a cyclic
// overlap (A over B over C over A), lit by nothing (the value is the reflectance).
//
// What it provokes: visibility no painter's algorithm can get right. Where the boxes pass
// through each other the visible boundary is the line where two faces intersect, an edge of
// no polygon; the three bars have no back-to-front order at all. A method that draws whole
// faces in a depth order gets one of the three crossings wrong.
//
// The bars: three long flat strips along the sides of a triangle (extended past its corners),
// each rising toward the viewer from one end to the other, so that at each corner the bar
// arriving high crosses over the bar leaving low.
//
// Parameters:
//   bar_width  0.16   width of a bar, world units (about 6 px at 256 px)
#include <cmath>

#include <fmt/format.h>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

// A flat bar along p -> q (screen-facing plane tilted in depth), `width` wide.
Object make_bar(const std::string& name, glm::dvec3 p, glm::dvec3 q, double width,
                double reflectance) {
    // Across the bar, in the image plane: perpendicular to d's x-y direction.
    const glm::dvec3 across =
        0.5 * width * glm::normalize(glm::dvec3(-(q - p).y, (q - p).x, 0.0));
    return make_quad(name, p - across, q - across, q + across, p + across, reflectance);
}

Scene generate_interpenetrate(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("interpenetrate", values, width, height);
    const double bar = values.get_real("bar_width");
    World w;
    w.camera.eye = {0.21, 1.37, 7.13};
    w.camera.target = {0.07, 0.31, 0.02};
    w.camera.fov_y_deg = 42.0;
    // Two boxes through each other, on the left.
    w.objects.push_back(make_box("box a", {-2.6, -0.3, -0.7}, {-1.0, 0.9, 0.5}, 0.21, 0.75));
    w.objects.push_back(make_box("box b", {-2.1, 0.1, -0.4}, {-0.5, 1.5, 0.6}, -0.47, 0.35));
    // The triangle's corners (x, y) on the right, and its sides extended by 0.45 each way.
    const glm::dvec2 c[3] = {{0.55, -0.35}, {2.35, -0.35}, {1.45, 1.35}};
    const double kRise = 0.5;  // depth change along a bar, world units
    const double refl[3] = {0.9, 0.55, 0.25};
    for (int k = 0; k < 3; ++k) {
        const glm::dvec2 a = c[k], b = c[(k + 1) % 3];
        const glm::dvec2 dir = glm::normalize(b - a);
        const glm::dvec2 s = a - 0.45 * dir, e = b + 0.45 * dir;
        // Low (far) at its first corner, high (near) at its second: at corner k+1 this bar
        // is high and the next bar, starting there, is low.
        w.objects.push_back(make_bar(fmt::format("bar {}", k), {s.x, s.y, -kRise},
                                     {e.x, e.y, kRise}, bar, refl[k]));
    }
    const glm::dvec2 focus = project_point(w.camera, width, height, {-1.4, 0.6, 0.4});
    scene.world = std::move(w);
    set_focus(scene, focus.x, focus.y, kFocusSidePx);  // where the boxes pass through
    return scene;
}

}  // namespace

PatternInfo interpenetrate_pattern() {
    return PatternInfo{
        "interpenetrate",
        "3-D boxes passing through each other and three bars in a cycle: no painter's order",
        {
            {"bar_width", ParamKind::kReal, 0.16, 0.005, 1, {},
             "bar width in world units; 0.16 is about 6 px at 256 px"},
        },
        generate_interpenetrate,
    };
}

}  // namespace aabench
