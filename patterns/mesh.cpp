// `mesh`: a geodesic sphere, an icosahedron subdivided `subdivisions` times (20 * 4^s
// triangles: 1,280 at the default) as one closed object whose faces share their edges exactly
// (the same vertex indices), under one parallel light.
//
// What it provokes: conflation. Every edge between two visible faces is covered on both sides
// by the object, so the exact answer there has no background at all; a method that composites
// coverage face by face (coverage a and b of a pixel cut by a shared edge, a + b = 1, blended
// as 1 - (1 - a)(1 - b) < 1) lets the background leak through as a faint web of seams. It is
// also the case where visibility needs no work: a closed convex object needs back-face
// culling only, and the plan says so.
//
// Parameters:
//   subdivisions  3   0..5 (20 to 20,480 triangles)
#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

constexpr double kRadius = 1.0;
const glm::dvec3 kCentre(0.013, -0.021, 0.0);  // off the grid

Object geodesic_sphere(int subdivisions) {
    const double phi = 0.5 * (1.0 + std::sqrt(5.0));
    std::vector<glm::dvec3> v = {{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0},
                                 {0, -1, phi}, {0, 1, phi}, {0, -1, -phi}, {0, 1, -phi},
                                 {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
    for (auto& p : v) p = glm::normalize(p);
    std::vector<std::array<int, 3>> tris = {
        {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
        {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<int, int>, int> midpoint;  // shared by the two triangles of an edge
        auto mid = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            const auto it = midpoint.find(key);
            if (it != midpoint.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return midpoint[key] = static_cast<int>(v.size()) - 1;
        };
        std::vector<std::array<int, 3>> next;
        next.reserve(tris.size() * 4);
        for (const auto& t : tris) {
            const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
            next.push_back({t[0], ab, ca});
            next.push_back({t[1], bc, ab});
            next.push_back({t[2], ca, bc});
            next.push_back({ab, bc, ca});
        }
        tris = std::move(next);
    }
    Object o;
    o.name = "sphere";
    o.closed = true;
    for (const auto& p : v) o.vertices.push_back(kCentre + kRadius * p);
    for (const auto& t : tris) {
        Face f;
        f.loop = {t[0], t[1], t[2]};
        f.reflectance = 0.8;
        // Counter-clockwise seen from outside: the right-hand normal points away from the
        // centre (the icosahedron table above is, and subdivision keeps the turn; this only
        // guards the table).
        const glm::dvec3 a = v[t[0]], b = v[t[1]], c = v[t[2]];
        if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0.0) std::swap(f.loop[1], f.loop[2]);
        o.faces.push_back(f);
    }
    return o;
}

Scene generate_mesh(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("mesh", values, width, height);
    World w;
    w.camera.eye = {0.31, 0.52, 3.37};
    w.camera.target = {0.0, 0.0, 0.0};
    w.camera.fov_y_deg = 42.0;
    w.ambient = 0.15;
    w.objects.push_back(geodesic_sphere(values.get_int("subdivisions")));
    Light sun;
    sun.direction = {-1.0, -1.3, -1.0};
    sun.intensity = 0.9;
    w.lights.push_back(sun);
    const glm::dvec2 focus = project_point(w.camera, width, height, kCentre);
    scene.world = std::move(w);
    set_focus(scene, focus.x, focus.y, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo mesh_pattern() {
    return PatternInfo{
        "mesh",
        "3-D geodesic sphere of 1,280 faces sharing edges: conflation seams, culling only",
        {
            {"subdivisions", ParamKind::kInt, 3, 0, 5, {},
             "icosahedron subdivisions: 20 * 4^s triangles; 3 gives 1,280, faces ~5 px at 256"},
        },
        generate_mesh,
    };
}

}  // namespace aabench
