// `checkerboard`: the classic moiré scene, a checkerboard floor receding to the horizon. One
// face (the floor, squares x squares, seen from above the middle of its near edge) with the
// dark squares as patterns on it, no lights (each value is its reflectance), a grey sky.
//
// What it provokes: squares shrinking without bound toward the horizon, so that far away
// many fall in one pixel, where point sampling turns the even grey the exact reference shows
// into moiré (false, coarse waves of light and dark); near the eye long straight edges at
// every slope converging on the vanishing point. All of it is patterns on one face: the
// scanline methods draw the squares laid over the floor, every other method the floor cut
// into cells around them (docs/world.md, "The overlay").
//
// Squares the camera cannot see (every corner beyond one side of the view, with a pixel of
// margin, or behind the near plane) are left out: they change no pixel, and a floor thousands
// of squares deep would otherwise be mostly squares outside the view.
//
// The eye stands above the floor's near edge, a third of a square off its middle line (a square
// edge under the eye would project onto the image's centre column, pixel-aligned).
//
// Parameters (their ranges keep the horizon and the floor's far corners in view):
//   squares  48    squares along each side of the floor (4..1536: at 1536 about 710,000 dark
//                  squares lie in view of a 64 x 48 image, 2.8 million vertices)
//   square   1     side of a square, world units (0.1..10)
//   height   1.5   the eye's height above the floor, world units (0.05..20)
//   pitch    12    the view's angle below the horizontal, degrees (0..24: below the half
//                  field of view, 25 degrees, so the horizon, f tan(pitch) px above the
//                  image centre, stays in view)
#include <cmath>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

constexpr double kFovYDeg = 50.0;
constexpr double kLightReflectance = 0.85;
constexpr double kDarkReflectance = 0.15;
constexpr double kSkyValue = 0.3;
// A square is left out only when all its corners lie this far (px) beyond one side of the
// image: a pixel of margin over the rounding of the projection.
constexpr double kCullMarginPx = 1.0;

// The view's bounding planes in view space (x_v, y_v, z_v; z_v ahead): a point is outside
// plane k when its value is negative. Sides through the eye, and the near plane.
struct ViewBounds {
    glm::dmat4 view;
    double tan_x = 0.0, tan_y = 0.0, near = 0.0;

    glm::dvec3 to_view(const glm::dvec3& p) const {
        const glm::dvec4 q = view * glm::dvec4(p, 1.0);
        return {q.x, q.y, -q.z};
    }
    static double side(const glm::dvec3& v, int k, double tan_x, double tan_y, double near) {
        switch (k) {
            case 0: return v.z * tan_x - v.x;
            case 1: return v.z * tan_x + v.x;
            case 2: return v.z * tan_y - v.y;
            case 3: return v.z * tan_y + v.y;
            default: return v.z - near;
        }
    }
    bool sees_any(const glm::dvec3 (&corners)[4]) const {
        glm::dvec3 v[4];
        for (int c = 0; c < 4; ++c) v[c] = to_view(corners[c]);
        for (int k = 0; k < 5; ++k) {
            bool all_out = true;
            for (int c = 0; c < 4 && all_out; ++c) all_out = side(v[c], k, tan_x, tan_y, near) < 0;
            if (all_out) return false;
        }
        return true;
    }
};

Scene generate_checkerboard(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("checkerboard", values, width, height);
    const int n = values.get_int("squares");
    const double size = values.get_real("square");
    const double eye_height = values.get_real("height");
    const double pitch = glm::radians(values.get_real("pitch"));
    scene.background = kSkyValue;
    World w;
    w.camera.eye = {size / 3.0, eye_height, 0.0};
    w.camera.target = w.camera.eye + glm::dvec3(0.0, -std::sin(pitch), -std::cos(pitch));
    w.camera.fov_y_deg = kFovYDeg;
    w.ambient = 1.0;

    const double side = n * size, half = 0.5 * side;
    // The floor: x in [-side/2, side/2], z from 0 (under the eye) to -side; normal +y.
    Object floor = make_quad("floor", {-half, 0, 0}, {half, 0, 0}, {half, 0, -side},
                             {-half, 0, -side}, kLightReflectance);
    const double focal_px = 0.5 * height / std::tan(0.5 * glm::radians(kFovYDeg));
    ViewBounds bounds;
    bounds.view = glm::lookAt(w.camera.eye, w.camera.target, w.camera.up);
    bounds.tan_x = (0.5 * width + kCullMarginPx) / focal_px;
    bounds.tan_y = (0.5 * height + kCullMarginPx) / focal_px;
    bounds.near = w.camera.near;
    const glm::dvec3 corner(-half, 0, 0), ux(1, 0, 0), vz(0, 0, -1);
    std::size_t vertices = 4;
    for (int j = 0; j < n; ++j) {
        for (int i = (j + 1) % 2; i < n; i += 2) {  // dark where i + j is odd
            const double s0 = i * size, s1 = (i + 1) * size, t0 = j * size, t1 = (j + 1) * size;
            const glm::dvec3 c[4] = {corner + s0 * ux + t0 * vz, corner + s1 * ux + t0 * vz,
                                     corner + s1 * ux + t1 * vz, corner + s0 * ux + t1 * vz};
            if (!bounds.sees_any(c)) continue;
            vertices += 4;
            if (vertices > kMaxPatternVertices) {
                throw InputError(fmt::format(
                    "pattern 'checkerboard': squares={} puts more than {} vertices in view; "
                    "lower squares or raise pitch",
                    n, kMaxPatternVertices));
            }
            floor.faces[0].patterns.push_back(
                rect_pattern(corner, ux, vz, s0, s1, t0, t1, kDarkReflectance));
        }
    }
    w.objects.push_back(std::move(floor));
    // The focus: where the squares shrink below a pixel, halfway from the image centre to the
    // horizon (the horizon lies f tan(pitch) px above the centre).
    const double horizon_y = 0.5 * height - focal_px * std::tan(pitch);
    scene.world = std::move(w);
    set_focus(scene, 0.5 * width, 0.5 * (horizon_y + 0.5 * height), kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo checkerboard_pattern() {
    return PatternInfo{
        "checkerboard",
        "3-D checkerboard floor receding to the horizon: the classic moiré scene, squares as "
        "patterns on one face",
        {
            {"squares", ParamKind::kInt, 48, 4, 1536, {},
             "squares along each side of the floor; the squares out of view are left out"},
            {"square", ParamKind::kReal, 1, 0.1, 10, {}, "side of a square, world units"},
            {"height", ParamKind::kReal, 1.5, 0.05, 20, {},
             "the eye's height above the floor, world units"},
            {"pitch", ParamKind::kReal, 12, 0, 24, {},
             "the view's angle below the horizontal, degrees (the horizon stays in view)"},
        },
        generate_checkerboard,
    };
}

}  // namespace aabench
