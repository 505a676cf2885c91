// `blocks`: several boxes on a ground plane under two lights with shadows, standing so that
// they hide each other in the image and throw shadows onto the ground and onto each other.
//
// What it provokes: hidden-surface work where projected faces overlap (every box behind
// another), shadow edges falling across faces of other objects (edges with no geometry under
// them), and silhouettes of many depths against each other rather than against the
// background.
//
// Layout: box k stands at an angle along a diagonal row that runs away from the camera, each
// taller than the one before, turned by a different yaw; nothing is pixel-aligned.
//
// Parameters:
//   count   4   boxes (1..8)
#include <cmath>

#include <fmt/format.h>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

Scene generate_blocks(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("blocks", values, width, height);
    const int count = values.get_int("count");
    World w;
    w.camera.eye = {4.31, 3.07, 6.23};
    w.camera.target = {0.11, 0.52, -0.37};
    w.camera.fov_y_deg = 45.0;
    w.ambient = 0.15;
    w.objects.push_back(make_quad("ground", {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}, 0.6));
    for (int k = 0; k < count; ++k) {
        // Along the row x = 1.4 - 0.9 k, z = 1.2 - 1.1 k (away from the eye), growing taller.
        const double x = 1.4 - 0.9 * k, z = 1.2 - 1.1 * k;
        const double half = 0.45 + 0.05 * (k % 3), h = 0.7 + 0.35 * k;
        w.objects.push_back(make_box(fmt::format("box {}", k), {x - half, 0, z - half},
                                     {x + half, h, z + half}, 0.3 + 0.41 * k,
                                     0.5 + 0.1 * (k % 4)));
    }
    Light sun;
    sun.direction = {-1.3, -2.1, 0.4};  // from the right: shadows fall left onto the next box
    sun.intensity = 0.6;
    sun.shadows = true;
    Light lamp;
    lamp.type = LightType::kPoint;
    lamp.position = {3.2, 3.9, 2.7};
    lamp.intensity = 9.0;
    lamp.shadows = true;
    w.lights = {sun, lamp};
    const glm::dvec2 focus = project_point(w.camera, width, height, {0.5, 0.6, 0.1});
    scene.world = std::move(w);
    set_focus(scene, focus.x, focus.y, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo blocks_pattern() {
    return PatternInfo{
        "blocks",
        "3-D boxes on the ground hiding each other, two lights casting shadows across them",
        {
            {"count", ParamKind::kInt, 4, 1, 8, {},
             "boxes in the row; 4 makes each hide part of the next"},
        },
        generate_blocks,
    };
}

}  // namespace aabench
