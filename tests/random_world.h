// A seeded random world shared by the world tests (tests/world_visibility_test.cpp,
// tests/sequence_test.cpp): random two-sided convex polygons (triangles to pentagons from a
// random plane) in a box in front of a random camera, interpenetrating, cyclically overlapping
// and partly behind the near plane; 3 + seed % object_spread of them, 48 x 40 pixels.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include <glm/glm.hpp>

#include "patterns/scene/scene.h"
#include "patterns/scene/world.h"

namespace aabench {

inline Scene random_world(std::uint64_t seed, int object_spread) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    World w;
    w.camera.eye = {3 * u(rng), 3 * u(rng), 6 + u(rng)};
    w.camera.target = {0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)};
    w.camera.fov_y_deg = 45.0;
    const int objects = 3 + static_cast<int>(seed % object_spread);
    for (int k = 0; k < objects; ++k) {
        Object o;
        o.closed = false;
        const glm::dvec3 c(1.5 * u(rng), 1.5 * u(rng), 1.5 * u(rng));
        const glm::dvec3 n = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + glm::dvec3(0, 0, 1e-3));
        const glm::dvec3 a = glm::normalize(glm::cross(n, glm::dvec3(0.3, 0.7, 0.1)));
        const glm::dvec3 b = glm::cross(n, a);
        const int sides = 3 + static_cast<int>(rng() % 3);
        const double r = 0.8 + 0.8 * std::abs(u(rng));
        for (int i = 0; i < sides; ++i) {
            const double t = 2 * M_PI * (i + 0.3 * u(rng)) / sides;
            o.vertices.push_back(c + r * std::cos(t) * a + 0.6 * r * std::sin(t) * b);
        }
        Face f;
        for (int i = 0; i < sides; ++i) f.loop.push_back(i);
        f.reflectance = 0.1 + 0.1 * k;
        o.faces.push_back(f);
        w.objects.push_back(o);
    }
    Scene s;
    s.width = 48;
    s.height = 40;
    s.world = w;
    return s;
}

}  // namespace aabench
