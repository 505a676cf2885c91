// `room`: a room interior after Nishita & Nakamae 1984, Fig. 6 (section 3): a floor
// laid with tatami-like mats whose thin dark borders are patterns on the floor face, two walls
// with window patterns, and a block on the floor casting shadows from one parallel and one
// point light.
//
// What it provokes: the mat borders are thin dark strips seen at a slant (from 0.3 px far away
// to 4.3 px nearest the eye at 256 px, measured in tests/patterns3d_test.cpp): they vanish
// and break up under point sampling; the shadow boundaries are edges inside faces (no
// geometry there), with two lights making shadows of two depths; the block's silhouette
// against the floor and walls, and the window frames, add long straight edges at every slope.
//
// Walls and floor are two-sided quads (closed: false): the room is seen from inside, and a
// two-sided face is lit on the side the eye sees, so no wall needs its normal flipped by hand.
// The block is a closed box (back faces culled). Lights: parallel from above-left-front,
// point light near the ceiling; both cast shadows.
//
// Parameters:
//   mats     3      mats per side of the floor (borders at every mat edge)
//   border   0.05   width of a mat border, world units (the floor is 6 units wide)
//   windows  2      windows per wall
//   edges    none   none | black | white-convex: an `edges` block (Saito & Takahashi 1990,
//                   docs/edges.md) in that compositing style, with the paper's k_p and k_l:
//                   the depth image z_s = f d / z_v reads the room's slopes as they are at
//                   every image size (docs/edges.md, "The scale of k_p and k_l")
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

constexpr double kHalf = 3.0;      // the floor is [-3, 3] x [-3, 3], walls 2.4 high
constexpr double kWallHeight = 2.4;
constexpr double kFloorReflectance = 0.7;
constexpr double kBorderReflectance = 0.12;
constexpr double kWallReflectance = 0.6;
constexpr double kWindowReflectance = 0.95;

Scene generate_room(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("room", values, width, height);
    const int mats = values.get_int("mats");
    const double border = values.get_real("border");
    const int windows = values.get_int("windows");
    World w;
    w.camera.eye = {1.37, 2.05, 5.41};
    w.camera.target = {-0.43, 0.71, -0.93};
    w.camera.fov_y_deg = 55.0;
    w.ambient = 0.2;

    Object floor = make_quad("floor", {-kHalf, 0, kHalf}, {kHalf, 0, kHalf}, {kHalf, 0, -kHalf},
                             {-kHalf, 0, -kHalf}, kFloorReflectance);
    // Mat borders: strips along x = const and z = const at every mat edge, inside the floor.
    // u = +x, v = -z keeps them counter-clockwise like the floor (normal +y).
    const glm::dvec3 corner(-kHalf, 0, kHalf), ux(1, 0, 0), vz(0, 0, -1);
    const double side = 2 * kHalf, step = side / mats;
    for (int k = 0; k <= mats; ++k) {
        const double at = std::clamp(k * step, 0.5 * border, side - 0.5 * border);
        floor.faces[0].patterns.push_back(rect_pattern(corner, ux, vz, at - 0.5 * border,
                                                       at + 0.5 * border, 0, side,
                                                       kBorderReflectance));
        floor.faces[0].patterns.push_back(rect_pattern(corner, ux, vz, 0, side,
                                                       at - 0.5 * border, at + 0.5 * border,
                                                       kBorderReflectance));
    }
    // Back wall (z = -3, facing +z) and left wall (x = -3, facing +x), with windows.
    Object back = make_quad("back wall", {-kHalf, 0, -kHalf}, {kHalf, 0, -kHalf},
                            {kHalf, kWallHeight, -kHalf}, {-kHalf, kWallHeight, -kHalf},
                            kWallReflectance);
    Object left = make_quad("left wall", {-kHalf, 0, kHalf}, {-kHalf, 0, -kHalf},
                            {-kHalf, kWallHeight, -kHalf}, {-kHalf, kWallHeight, kHalf},
                            kWallReflectance);
    for (int k = 0; k < windows; ++k) {
        const double s0 = (k + 0.25) * side / windows, s1 = (k + 0.75) * side / windows;
        back.faces[0].patterns.push_back(rect_pattern({-kHalf, 0, -kHalf}, {1, 0, 0}, {0, 1, 0},
                                                      s0, s1, 0.9, 1.9, kWindowReflectance));
        left.faces[0].patterns.push_back(rect_pattern({-kHalf, 0, kHalf}, {0, 0, -1}, {0, 1, 0},
                                                      s0, s1, 0.9, 1.9, kWindowReflectance));
    }
    w.objects = {floor, back, left,
                 make_box("block", {-0.3, 0.0, -1.1}, {0.9, 0.85, 0.1}, 0.35, 0.8)};

    Light sun;
    sun.direction = {-1.0, -2.0, -1.5};
    sun.intensity = 0.7;
    sun.shadows = true;
    Light lamp;
    lamp.type = LightType::kPoint;
    lamp.position = {1.6, 2.3, 1.1};
    lamp.intensity = 2.5;
    lamp.shadows = true;
    w.lights = {sun, lamp};
    const std::string edges = values.get_choice("edges");
    if (edges != "none") {
        EdgesSpec spec = edges_in_style(edges);
        spec.contour = values.get_choice("contour");
        spec.crease = values.get_choice("crease");
        spec.kp = values.get_real("kp");
        spec.kl = values.get_real("kl");
        w.edges = spec;
    }
    const glm::dvec2 focus = project_point(w.camera, width, height, {0.3, 0.0, 0.6});
    scene.world = std::move(w);
    set_focus(scene, focus.x, focus.y, kFocusSidePx);  // the block's foot and its shadows
    return scene;
}

}  // namespace

PatternInfo room_pattern() {
    return PatternInfo{
        "room",
        "3-D room after Nishita & Nakamae Fig. 6: tatami borders, windows, a block, two shadows",
        // clang-format off
        {
            {"mats", ParamKind::kInt, 3, 1, 24, {},
             "mats per side of the floor; 3 gives borders from about 0.3 px (far) to 4 px "
             "(near) wide at 256 px"},
            {"border", ParamKind::kReal, 0.05, 0.001, 1, {},
             "mat border width in world units (the floor is 6 wide): thin dark strips"},
            {"windows", ParamKind::kInt, 2, 0, 8, {}, "windows per wall"},
            {"edges", ParamKind::kChoice, 0, 0, 0, {"none", "black", "white-convex"},
             "edge enhancement (Saito & Takahashi 1990) in this compositing style; none: no "
             "edges block"},
            {"contour", ParamKind::kChoice, 0, 0, 0, {"sobel", "prewitt"},
             "with edges: contour operator, Sobel (eq. 3) or Prewitt (eq. 4)"},
            {"crease", ParamKind::kChoice, 0, 0, 0, {"laplacian8", "laplacian4", "none"},
             "with edges: crease operator, eq. 6, eq. 5 or none"},
            {"kp", ParamKind::kReal, 10, 1e-6, 1e9, {},
             "with edges: eq. 7's k_p (the paper's 10)"},
            {"kl", ParamKind::kReal, 2, 1e-6, 1e9, {},
             "with edges: eq. 8's k_l (the paper's 2)"},
        },
        // clang-format on
        generate_room,
    };
}

}  // namespace aabench
