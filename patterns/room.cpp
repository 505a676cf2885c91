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
//
// `colour-room`: the same room in colour (docs/colour.md, "Colour worlds"), a colour world:
// warm floor, teal back wall, lilac left wall and a green block of about one luminance
// (0.46 to 0.51), so that where they meet the chroma changes more than the luma; dark borders,
// pale windows; a warm sun and a cool lamp, whose two shadows differ in hue as well as depth,
// and a slightly cool ambient. Parameters: mats, border, windows as above (a colour world has
// no edge stage).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

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
constexpr double kAmbient = 0.2;
constexpr double kSunIntensity = 0.7;
constexpr double kLampIntensity = 2.5;

// A reflectance or an intensity: grey, or a colour (the grey then its luminance, as the scene
// reader makes it).
struct Tone {
    double grey = 1.0;
    std::optional<Rgb> rgb;
    static Tone of(const Rgb& c) { return {luminance(c), c}; }
    static Tone scaled(double k, const Rgb& c) { return of({k * c[0], k * c[1], k * c[2]}); }
};

// What the room is made of: the grey room's numbers, or the colour room's.
struct RoomLook {
    Tone floor{kFloorReflectance}, border{kBorderReflectance}, wall_back{kWallReflectance},
        wall_left{kWallReflectance}, window{kWindowReflectance}, block{0.8};
    Tone ambient{kAmbient}, sun{kSunIntensity}, lamp{kLampIntensity};
};

// Luminances: floor 0.499, back wall 0.490, left wall 0.464, block 0.511 (Rec. 709).
RoomLook colour_look() {
    RoomLook look;
    look.floor = Tone::of({0.75, 0.45, 0.25});
    look.border = Tone::of({0.10, 0.12, 0.08});
    look.wall_back = Tone::of({0.25, 0.55, 0.60});
    look.wall_left = Tone::of({0.60, 0.40, 0.70});
    look.window = Tone::of({0.85, 0.92, 0.98});
    look.block = Tone::of({0.30, 0.60, 0.25});
    look.ambient = Tone::of({0.18, 0.20, 0.24});
    look.sun = Tone::scaled(kSunIntensity, {1.0, 0.80, 0.55});   // warm
    look.lamp = Tone::scaled(kLampIntensity, {0.60, 0.80, 1.0});  // cool
    return look;
}

void paint(Object& object, const Tone& tone) {
    for (Face& f : object.faces) {
        f.reflectance = tone.grey;
        f.reflectance_rgb = tone.rgb;
    }
}

FacePattern painted(FacePattern pattern, const Tone& tone) {
    pattern.reflectance = tone.grey;
    pattern.reflectance_rgb = tone.rgb;
    return pattern;
}

// The room of `values` (mats, border, windows) made of `look`, without its edges block.
World room_world(const ParamValues& values, const RoomLook& look) {
    const int mats = values.get_int("mats");
    const double border = values.get_real("border");
    const int windows = values.get_int("windows");
    World w;
    w.camera.eye = {1.37, 2.05, 5.41};
    w.camera.target = {-0.43, 0.71, -0.93};
    w.camera.fov_y_deg = 55.0;
    w.ambient = look.ambient.grey;
    w.ambient_rgb = look.ambient.rgb;

    Object floor = make_quad("floor", {-kHalf, 0, kHalf}, {kHalf, 0, kHalf}, {kHalf, 0, -kHalf},
                             {-kHalf, 0, -kHalf}, kFloorReflectance);
    paint(floor, look.floor);
    // Mat borders: strips along x = const and z = const at every mat edge, inside the floor.
    // u = +x, v = -z keeps them counter-clockwise like the floor (normal +y).
    const glm::dvec3 corner(-kHalf, 0, kHalf), ux(1, 0, 0), vz(0, 0, -1);
    const double side = 2 * kHalf, step = side / mats;
    for (int k = 0; k <= mats; ++k) {
        const double at = std::clamp(k * step, 0.5 * border, side - 0.5 * border);
        floor.faces[0].patterns.push_back(
            painted(rect_pattern(corner, ux, vz, at - 0.5 * border, at + 0.5 * border, 0, side,
                                 kBorderReflectance),
                    look.border));
        floor.faces[0].patterns.push_back(
            painted(rect_pattern(corner, ux, vz, 0, side, at - 0.5 * border, at + 0.5 * border,
                                 kBorderReflectance),
                    look.border));
    }
    // Back wall (z = -3, facing +z) and left wall (x = -3, facing +x), with windows.
    Object back = make_quad("back wall", {-kHalf, 0, -kHalf}, {kHalf, 0, -kHalf},
                            {kHalf, kWallHeight, -kHalf}, {-kHalf, kWallHeight, -kHalf},
                            kWallReflectance);
    Object left = make_quad("left wall", {-kHalf, 0, kHalf}, {-kHalf, 0, -kHalf},
                            {-kHalf, kWallHeight, -kHalf}, {-kHalf, kWallHeight, kHalf},
                            kWallReflectance);
    paint(back, look.wall_back);
    paint(left, look.wall_left);
    for (int k = 0; k < windows; ++k) {
        const double s0 = (k + 0.25) * side / windows, s1 = (k + 0.75) * side / windows;
        back.faces[0].patterns.push_back(painted(rect_pattern({-kHalf, 0, -kHalf}, {1, 0, 0},
                                                              {0, 1, 0}, s0, s1, 0.9, 1.9,
                                                              kWindowReflectance),
                                                 look.window));
        left.faces[0].patterns.push_back(painted(rect_pattern({-kHalf, 0, kHalf}, {0, 0, -1},
                                                              {0, 1, 0}, s0, s1, 0.9, 1.9,
                                                              kWindowReflectance),
                                                 look.window));
    }
    Object block = make_box("block", {-0.3, 0.0, -1.1}, {0.9, 0.85, 0.1}, 0.35, 0.8);
    paint(block, look.block);
    w.objects = {floor, back, left, block};

    Light sun;
    sun.direction = {-1.0, -2.0, -1.5};
    sun.intensity = look.sun.grey;
    sun.intensity_rgb = look.sun.rgb;
    sun.shadows = true;
    Light lamp;
    lamp.type = LightType::kPoint;
    lamp.position = {1.6, 2.3, 1.1};
    lamp.intensity = look.lamp.grey;
    lamp.intensity_rgb = look.lamp.rgb;
    lamp.shadows = true;
    w.lights = {sun, lamp};
    return w;
}

// The block's foot and its shadows.
void focus_on_block(Scene& scene, const Camera& camera) {
    const glm::dvec2 focus = project_point(camera, scene.width, scene.height, {0.3, 0.0, 0.6});
    set_focus(scene, focus.x, focus.y, kFocusSidePx);
}

Scene generate_room(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("room", values, width, height);
    World w = room_world(values, RoomLook{});
    const std::string edges = values.get_choice("edges");
    if (edges != "none") {
        EdgesSpec spec = edges_in_style(edges);
        spec.contour = values.get_choice("contour");
        spec.crease = values.get_choice("crease");
        spec.kp = values.get_real("kp");
        spec.kl = values.get_real("kl");
        w.edges = spec;
    }
    scene.world = std::move(w);
    focus_on_block(scene, scene.world->camera);
    return scene;
}

Scene generate_colour_room(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("colour-room", values, width, height);
    scene.world = room_world(values, colour_look());
    scene.channels = 3;
    scene.background_rgb = Rgb{0.0, 0.0, 0.0};  // as the scene file holds it: a colour scene's
    focus_on_block(scene, scene.world->camera);
    return scene;
}

// The room's size parameters, shared by both rooms.
std::vector<ParamSpec> room_size_params() {
    // clang-format off
    return {
        {"mats", ParamKind::kInt, 3, 1, 24, {},
         "mats per side of the floor; 3 gives borders from about 0.3 px (far) to 4 px "
         "(near) wide at 256 px"},
        {"border", ParamKind::kReal, 0.05, 0.001, 1, {},
         "mat border width in world units (the floor is 6 wide): thin dark strips"},
        {"windows", ParamKind::kInt, 2, 0, 8, {}, "windows per wall"},
    };
    // clang-format on
}

}  // namespace

PatternInfo room_pattern() {
    std::vector<ParamSpec> params = room_size_params();
    // clang-format off
    const std::vector<ParamSpec> edge_params{
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
    };
    // clang-format on
    params.insert(params.end(), edge_params.begin(), edge_params.end());
    return PatternInfo{
        "room",
        "3-D room after Nishita & Nakamae Fig. 6: tatami borders, windows, a block, two shadows",
        std::move(params),
        generate_room,
    };
}

PatternInfo colour_room_pattern() {
    PatternInfo info{
        "colour-room",
        "colour: the room with faces of one luma and different chroma, a warm and a cool light",
        room_size_params(),
        generate_colour_room,
    };
    // Not in the default run: its baseline rows and the default comparison's time stay as they
    // were (docs/colour.md, "Colour worlds").
    info.in_default_run = false;
    return info;
}

}  // namespace aabench
