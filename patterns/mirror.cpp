// `mirror`: a box on a floor before a tilted wall mirror, with an `edges` block (Saito &
// Takahashi 1990, §4 and Fig. 7): the reflections stage (harness/world/reflections.h) casts rays
// for the optical-path depth of eq. 9, so that the box's contours and creases seen in the mirror
// are drawn like the ones seen directly.
//
// What it provokes: contours and creases inside a reflection, which the plain depth image z_s
// cannot show (the mirror is one plane there); the mirror's own outline against the floor and
// the background; the reflected floor's far edge against the reflected background (eq. 9's 0 for
// the background keeps it a contour). The mirror is turned about the vertical so that it shows
// a side of the box the eye does not see.
//
// The shaded image does not show the reflection (the methods draw the mirror as a flat face of
// its own reflectance): only the line image, made from the optical-path depth, does.
//
// Parameters:
//   r       0.8    the mirror's `mirror` share (eq. 9's r)
//   style   black  black | white-convex (Fig. 3 h' | h); the paper's k_p, k_l
#include <cmath>
#include <numbers>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

constexpr double kMirrorYawDeg = 40.0;  // turned toward the box's unseen side
const glm::dvec3 kMirrorCentre(-0.55, 1.15, -1.7);
constexpr double kMirrorHalfWidth = 1.6, kMirrorHalfHeight = 0.95;

Scene generate_mirror(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("mirror", values, width, height);
    scene.background = 0.9;  // light paper, so that black lines against it show
    World w;
    w.camera.eye = {1.9, 2.3, 5.2};
    w.camera.target = {-0.3, 0.75, -0.5};
    w.camera.fov_y_deg = 42.0;
    w.ambient = 0.25;
    w.objects.push_back(
        make_quad("floor", {-3.2, 0, 2.6}, {3.2, 0, 2.6}, {3.2, 0, -3.0}, {-3.2, 0, -3.0}, 0.55));
    w.objects.push_back(make_box("box", {0.05, 0.0, -0.55}, {1.05, 0.9, 0.35}, 0.75, 0.85));
    const double yaw = kMirrorYawDeg * std::numbers::pi / 180.0;
    const glm::dvec3 along(std::cos(yaw), 0.0, -std::sin(yaw));  // the mirror's horizontal
    const glm::dvec3 up(0.0, 1.0, 0.0);
    const glm::dvec3 a = kMirrorCentre - kMirrorHalfWidth * along - kMirrorHalfHeight * up;
    const glm::dvec3 b = kMirrorCentre + kMirrorHalfWidth * along - kMirrorHalfHeight * up;
    const glm::dvec3 c = kMirrorCentre + kMirrorHalfWidth * along + kMirrorHalfHeight * up;
    const glm::dvec3 d = kMirrorCentre - kMirrorHalfWidth * along + kMirrorHalfHeight * up;
    Object mirror = make_quad("mirror", a, b, c, d, 0.35);
    mirror.faces[0].mirror = values.get_real("r");
    w.objects.push_back(std::move(mirror));
    Light sun;
    sun.direction = {-0.5, -1.0, -0.7};
    sun.intensity = 0.75;
    w.lights.push_back(sun);
    w.edges = edges_in_style(values.get_choice("style"));
    const glm::dvec2 focus = project_point(w.camera, width, height, kMirrorCentre);
    scene.world = std::move(w);
    set_focus(scene, focus.x, focus.y, kFocusSidePx);  // the reflection
    return scene;
}

}  // namespace

PatternInfo mirror_pattern() {
    PatternInfo info{
        "mirror",
        "3-D box before a wall mirror, edges on: contours inside the reflection (Saito & "
        "Takahashi 1990 eq. 9)",
        // clang-format off
        {
            {"r", ParamKind::kReal, 0.8, 0.01, 1, {},
             "the mirror's reflected share r (eq. 9); the optical-path depth weighs the "
             "reflected path by it"},
            {"style", ParamKind::kChoice, 0, 0, 0, {"black", "white-convex"},
             "edge compositing: every edge black (Fig. 3 h') or convex creases white (h)"},
        },
        // clang-format on
        generate_mirror,
    };
    info.in_default_run = false;
    return info;
}

}  // namespace aabench
