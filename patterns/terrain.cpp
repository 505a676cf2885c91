// `terrain`: a height field of cells x cells squares, each split into two triangles
// (2 cells^2 faces, two-sided: closed: false), seen from low over its near edge at a grazing
// angle, under one parallel light.
//
// What it provokes: faces foreshortened to slivers far away, a ridge line of many silhouettes
// against the background and against farther hills (real hidden-surface work: an open surface
// folds over itself in the image), and moiré in the distance where many faces fall in one
// pixel. The heights are a sum of a few sines, so the field is reproducible without a random
// generator.
//
// `terrain-edges` is the same field with an `edges` block (Saito & Takahashi 1990, Fig. 6: a
// bird's-eye view of hills whose overlaps the contours make clear): ridges seen against farther
// hills are contours, the folds between facets creases; the paper's k_p and k_l, the background
// light paper (0.9) so that lines against it show.
//
// Parameters:
//   cells   24     cells per side (1,152 triangles)
//   height  0.9    amplitude of the hills, world units (the field is 8 wide)
//   style   black  terrain-edges only: black | white-convex (Fig. 3 h' | h)
#include <cmath>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

constexpr double kHalf = 4.0;  // the field spans [-4, 4] in x and z

double terrain_height(double amplitude, double x, double z) {
    return amplitude * (0.5 * std::sin(0.9 * x + 0.3) * std::cos(0.7 * z) +
                        0.3 * std::sin(1.7 * x - 1.1 * z + 0.5) + 0.2 * std::cos(2.3 * z + 0.4 * x));
}

// The height field, its camera and its light; `terrain-edges` adds an edges block.
Scene terrain_scene(const std::string& id, bool edges, const ParamValues& values, int width,
                    int height) {
    Scene scene = begin_pattern_scene(id, values, width, height);
    const int n = values.get_int("cells");
    const double amplitude = values.get_real("height");
    Object field;
    field.name = "terrain";
    field.closed = false;
    const double step = 2.0 * kHalf / n;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const double x = -kHalf + i * step, z = -kHalf + j * step;
            field.vertices.push_back({x, terrain_height(amplitude, x, z), z});
        }
    }
    auto at = [n](int i, int j) { return j * (n + 1) + i; };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            // Both triangles counter-clockwise seen from above (normal +y for a flat field).
            Face a, b;
            a.loop = {at(i, j), at(i, j + 1), at(i + 1, j + 1)};
            b.loop = {at(i, j), at(i + 1, j + 1), at(i + 1, j)};
            a.reflectance = b.reflectance = 0.7;
            field.faces.push_back(a);
            field.faces.push_back(b);
        }
    }
    World w;
    w.camera.eye = {0.37, 1.31 + amplitude, 6.9};
    w.camera.target = {-0.21, 0.1, -1.3};
    w.camera.fov_y_deg = 50.0;
    w.ambient = 0.15;
    w.objects.push_back(std::move(field));
    Light sun;
    sun.direction = {-0.6, -1.0, -0.4};
    sun.intensity = 0.9;
    w.lights.push_back(sun);
    if (edges) {
        scene.background = 0.9;  // light paper, so that the ridge lines against the sky show
        w.edges = edges_in_style(values.get_choice("style"));
    }
    const glm::dvec2 focus = project_point(w.camera, width, height, {0.0, 0.0, -kHalf});
    scene.world = std::move(w);
    set_focus(scene, focus.x, focus.y, kFocusSidePx);  // the far edge, where faces are slivers
    return scene;
}

}  // namespace

PatternInfo terrain_pattern() {
    return PatternInfo{
        "terrain",
        "3-D height field at a grazing angle: sliver faces, many silhouettes, open surface",
        {
            {"cells", ParamKind::kInt, 24, 1, 200, {}, "cells per side: 2 cells^2 triangles"},
            {"height", ParamKind::kReal, 0.9, 0, 10, {},
             "hill amplitude in world units (the field is 8 wide)"},
        },
        [](const ParamValues& values, int width, int height) {
            return terrain_scene("terrain", false, values, width, height);
        },
    };
}

PatternInfo terrain_edges_pattern() {
    PatternInfo info{
        "terrain-edges",
        "the terrain with edges on (Saito & Takahashi 1990 Fig. 6): ridge contours over farther "
        "hills",
        {
            {"cells", ParamKind::kInt, 24, 1, 200, {}, "cells per side: 2 cells^2 triangles"},
            {"height", ParamKind::kReal, 0.9, 0, 10, {},
             "hill amplitude in world units (the field is 8 wide)"},
            {"style", ParamKind::kChoice, 0, 0, 0, {"black", "white-convex"},
             "edge compositing: every edge black (Fig. 3 h') or convex creases white (h), the "
             "paper's k_p and k_l"},
        },
        [](const ParamValues& values, int width, int height) {
            return terrain_scene("terrain-edges", true, values, width, height);
        },
    };
    info.in_default_run = false;
    return info;
}

}  // namespace aabench
