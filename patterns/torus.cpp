// `torus`: a faceted torus seen from above at an angle, with an `edges` block (Saito &
// Takahashi 1990, Fig. 5): the edge stage draws its contours (the outer silhouette, the rim of
// the hole, the inner part hiding behind the front) and the creases between its facets.
//
// What it provokes: contours of every kind on one object (silhouettes against the background
// and against the torus itself), creases of both signs (the outer half is convex, the inner
// half saddle-shaped), and hidden surfaces on one closed object that is not convex (the plan
// keeps visibility in). Each facet is an isosceles trapezoid (its four corners are symmetric
// about the plane halfway between their two meridians), so it is planar and convex exactly.
//
// The scale: with z_s = f d / z_v (docs/world.md; d = |target - eye|) the first derivative of
// depth on a face of slope s is s d / z_v per pixel, the slope itself at the target's depth, as
// the paper's normalisation and its constants k_p = 10, k_l = 2 assume, at every size, image
// resolution and field of view (docs/edges.md). A ring of radius 1 seen from about 4.3 units.
//
// Parameters:
//   major_segments  48      facets around the ring, 8..256
//   minor_segments  24      facets around the tube, 4..128
//   style           black   black | white-convex (Fig. 3 h' | h)
//   kp              10      eq. 7 (the paper's value)
//   kl              2       eq. 8 (the paper's value)
#include <cmath>
#include <numbers>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

constexpr double kMajorRadius = 1.0;
constexpr double kMinorRadius = 0.38;
const glm::dvec3 kCentre(0.011, -0.017, 0.007);  // off the grid

Object faceted_torus(int major, int minor) {
    Object o;
    o.name = "torus";
    o.closed = true;
    const double two_pi = 2.0 * std::numbers::pi;
    // Offsets of half a step keep facet corners off the symmetry planes of the view.
    for (int i = 0; i < major; ++i) {
        const double u = two_pi * (i + 0.25) / major;
        for (int j = 0; j < minor; ++j) {
            const double v = two_pi * (j + 0.5) / minor;
            const double ring = kMajorRadius + kMinorRadius * std::cos(v);
            o.vertices.push_back(kCentre + glm::dvec3(ring * std::cos(u), kMinorRadius * std::sin(v),
                                                      ring * std::sin(u)));
        }
    }
    auto index = [&](int i, int j) { return (i % major) * minor + (j % minor); };
    for (int i = 0; i < major; ++i) {
        for (int j = 0; j < minor; ++j) {
            Face f;
            f.loop = {index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)};
            f.reflectance = 0.8;
            // Counter-clockwise seen from outside: the normal must point away from the tube's
            // centre line.
            const glm::dvec3 a = o.vertices[f.loop[0]], b = o.vertices[f.loop[1]],
                             c = o.vertices[f.loop[2]];
            const double u = two_pi * (i + 0.75) / major;
            const glm::dvec3 axis =
                kCentre + kMajorRadius * glm::dvec3(std::cos(u), 0.0, std::sin(u));
            if (glm::dot(glm::cross(b - a, c - a), a - axis) < 0.0) {
                std::swap(f.loop[1], f.loop[3]);
            }
            o.faces.push_back(f);
        }
    }
    return o;
}

Scene generate_torus(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("torus", values, width, height);
    scene.background = 0.9;  // light paper, so that the silhouette's black line shows
    World w;
    w.camera.eye = {0.23, 2.75, 3.2};
    w.camera.target = {0.0, -0.05, 0.0};
    w.camera.fov_y_deg = 40.0;
    w.ambient = 0.2;
    w.objects.push_back(
        faceted_torus(values.get_int("major_segments"), values.get_int("minor_segments")));
    Light sun;
    sun.direction = {-0.8, -1.6, -0.9};
    sun.intensity = 0.8;
    w.lights.push_back(sun);
    EdgesSpec edges;
    edges.style = values.get_choice("style");
    edges.contour = values.get_choice("contour");
    edges.crease = values.get_choice("crease");
    edges.kp = values.get_real("kp");
    edges.kl = values.get_real("kl");
    w.edges = edges;
    const glm::dvec2 focus = project_point(w.camera, width, height, kCentre);
    scene.world = std::move(w);
    set_focus(scene, focus.x, focus.y, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo torus_pattern() {
    return PatternInfo{
        "torus",
        "3-D faceted torus with edge enhancement (Saito & Takahashi 1990 Fig. 5): contours and "
        "creases",
        {
            {"major_segments", ParamKind::kInt, 48, 8, 1024, {},
             "facets around the ring; 48 x 24 = 1,152 facets"},
            {"minor_segments", ParamKind::kInt, 24, 4, 512, {}, "facets around the tube"},
            {"style", ParamKind::kChoice, 0, 0, 0, {"black", "white-convex"},
             "edge compositing: every edge black (Fig. 3 h') or convex creases white (h)"},
            {"contour", ParamKind::kChoice, 0, 0, 0, {"sobel", "prewitt"},
             "first-derivative operator for contours: Sobel (eq. 3) or Prewitt (eq. 4)"},
            {"crease", ParamKind::kChoice, 0, 0, 0, {"laplacian8", "laplacian4", "none"},
             "second-derivative operator for creases: the 8-neighbour Laplacian (eq. 6), the "
             "4-neighbour one (eq. 5), or none"},
            {"kp", ParamKind::kReal, 10, 1e-6, 1e9, {},
             "eq. 7: a local range of g below it is a slope, not a contour (the paper's 10)"},
            {"kl", ParamKind::kReal, 2, 1e-6, 1e9, {},
             "eq. 8: where g passes it, creases fade as (g_max / k_l)^2 (the paper's 2)"},
        },
        generate_torus,
    };
}

}  // namespace aabench
