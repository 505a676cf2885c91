// Seeded random scenes shared by the method test suites (the slow references they are checked
// against live in each suite; this is only the input).
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "patterns/scene.h"

namespace aabench::testing {

// Overlapping, possibly self-intersecting polygons (1–4 shapes of 1–2 contours of 3–8
// vertices, reaching 4 px past the image) with random values and background. With
// `snap_half_pixel`, half of the contours have their vertices on the 1/2-pixel grid, so that
// edges run through sample points and tie rules are exercised; without it no random number is
// spent on that choice (the sequences of older seeds stay as they were).
inline Scene random_scene(std::uint64_t seed, int width, int height, bool snap_half_pixel) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> x(-4.0, width + 4.0), y(-4.0, height + 4.0), v(0, 1);
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.background = v(rng);
    const int shapes = 1 + static_cast<int>(rng() % 4);
    for (int s = 0; s < shapes; ++s) {
        Shape shape;
        shape.value = v(rng);
        const int contours = 1 + static_cast<int>(rng() % 2);
        for (int c = 0; c < contours; ++c) {
            Contour contour;
            const int n = 3 + static_cast<int>(rng() % 6);
            const bool on_grid = snap_half_pixel && rng() % 2 == 0;
            for (int k = 0; k < n; ++k) {
                Point p{x(rng), y(rng)};
                if (on_grid) p = {std::round(2.0 * p.x) / 2.0, std::round(2.0 * p.y) / 2.0};
                contour.push_back(p);
            }
            shape.contours.push_back(contour);
        }
        scene.shapes.push_back(shape);
    }
    return scene;
}

// The half-plane on the +n side (n = (-dy, dx)) of a line through a random point of the image
// at a random angle: a quadrilateral of positive shoelace area whose other edges lie far
// outside the image.
inline Scene random_half_plane(std::uint64_t seed, int width, int height) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi), px(0.0, width),
        py(0.0, height);
    const double a = angle(rng), x = px(rng), y = py(rng);
    const double dx = std::cos(a), dy = std::sin(a), far = 10.0 * (width + height);
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.shapes.push_back({{{{x - far * dx, y - far * dy},
                              {x + far * dx, y + far * dy},
                              {x + far * (dx - dy), y + far * (dy + dx)},
                              {x - far * (dx + dy), y + far * (dx - dy)}}},
                            1.0});
    return scene;
}

}  // namespace aabench::testing
