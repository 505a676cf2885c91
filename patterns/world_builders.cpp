#include "patterns/world_builders.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace aabench {

Object make_box(const std::string& name, glm::dvec3 lo, glm::dvec3 hi, double yaw_rad,
                double reflectance) {
    Object o;
    o.name = name;
    o.closed = true;
    const glm::dvec3 c = 0.5 * (lo + hi);
    const double cs = std::cos(yaw_rad), sn = std::sin(yaw_rad);
    for (int k = 0; k < 8; ++k) {
        const glm::dvec3 p((k & 1) == ((k >> 1) & 1) ? lo.x : hi.x, (k & 2) ? hi.y : lo.y,
                           (k & 4) ? hi.z : lo.z);
        const glm::dvec3 d = p - c;
        o.vertices.push_back(c + glm::dvec3(cs * d.x + sn * d.z, d.y, -sn * d.x + cs * d.z));
    }
    // Vertices: 0 (lo,lo,lo) 1 (hi,lo,lo) 2 (hi,hi,lo) 3 (lo,hi,lo), 4-7 the same at hi z;
    // each loop turns counter-clockwise about its outward normal (checked in the tests).
    const int loops[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    for (const auto& l : loops) {
        Face f;
        f.loop = {l[0], l[1], l[2], l[3]};
        f.reflectance = reflectance;
        o.faces.push_back(f);
    }
    return o;
}

Object make_quad(const std::string& name, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c,
                 glm::dvec3 d, double reflectance) {
    Object o;
    o.name = name;
    o.closed = false;
    o.vertices = {a, b, c, d};
    Face f;
    f.loop = {0, 1, 2, 3};
    f.reflectance = reflectance;
    o.faces.push_back(f);
    return o;
}

FacePattern rect_pattern(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, double s0, double s1,
                         double t0, double t1, double reflectance) {
    FacePattern p;
    p.loop = {origin + s0 * u + t0 * v, origin + s1 * u + t0 * v, origin + s1 * u + t1 * v,
              origin + s0 * u + t1 * v};
    p.reflectance = reflectance;
    return p;
}

glm::dvec2 project_point(const Camera& camera, int width, int height, glm::dvec3 p) {
    const glm::dvec4 q = glm::lookAt(camera.eye, camera.target, camera.up) * glm::dvec4(p, 1.0);
    const double f = 0.5 * height / std::tan(0.5 * glm::radians(camera.fov_y_deg));
    const double z = -q.z;
    return {0.5 * width + f * q.x / z, 0.5 * height - f * q.y / z};
}

EdgesSpec edges_in_style(const std::string& style) {
    EdgesSpec spec;
    spec.style = style;
    return spec;
}

}  // namespace aabench
