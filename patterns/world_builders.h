// Building blocks of the 3-D patterns: boxes, quads, patterns on faces, and where a world
// point lands on the screen (for a pattern's focus region). Pure functions of their inputs.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "patterns/scene/scene.h"

namespace aabench {

// An axis-aligned box [lo, hi], turned by `yaw_rad` about the vertical axis through its
// centre, as a closed object: 6 faces counter-clockwise seen from outside. Face order:
// -z, +z, -y (bottom), +y (top), -x, +x.
Object make_box(const std::string& name, glm::dvec3 lo, glm::dvec3 hi, double yaw_rad,
                double reflectance);
inline constexpr int kBoxTopFace = 3;

// A two-sided quad (closed: false) a -> b -> c -> d.
Object make_quad(const std::string& name, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c,
                 glm::dvec3 d, double reflectance);

// A rectangle pattern on a planar face: origin + s * u + t * v for s in [s0, s1], t in
// [t0, t1] (u, v spanning the face's plane), counter-clockwise like the face when u x v
// points along its normal.
FacePattern rect_pattern(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, double s0, double s1,
                         double t0, double t1, double reflectance);

// An `edges` block in `style` with the paper's constants k_p = 10, k_l = 2: the depth image
// z_s = f d / z_v reads a surface's slope at the target's depth at every scale, resolution and
// field of view (docs/edges.md, "The scale of k_p and k_l"), so no scene scales them.
EdgesSpec edges_in_style(const std::string& style);

// Where a world point lands in the pixel frame of a width x height image seen by `camera`
// (docs/world.md: x = W/2 + f x_v / z_v, y = H/2 - f y_v / z_v).
glm::dvec2 project_point(const Camera& camera, int width, int height, glm::dvec3 p);

}  // namespace aabench
