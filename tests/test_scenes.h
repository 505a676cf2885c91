// Seeded random scenes shared by the method test suites (the slow references they are checked
// against live in each suite; this is only the input).
#pragma once

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <string>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "patterns/scene/scene.h"

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

// The values of `scene` replaced by random multiples of powers of two (0, 1, 1/4, 3, -1/2, 3/4:
// integers in units of 1/4), the values the run sums take exactly
// (methods/scan/sampling/run_sums.h).
inline Scene with_dyadic_values(Scene scene, std::uint64_t seed) {
    constexpr double kValues[] = {0.0, 1.0, 0.25, 3.0, -0.5, 0.75};
    std::mt19937_64 rng(seed);
    scene.background = kValues[rng() % 6];
    for (Shape& shape : scene.shapes) shape.value = kValues[rng() % 6];
    return scene;
}

// The same scene with every value given as a constant plane: no longer flat, so the point
// samplers sum it sample by sample (methods/scan/sampling/point_sampling.h, PointSampler::flat()).
inline Scene with_constant_planes(Scene scene) {
    for (Shape& shape : scene.shapes) shape.value_plane = AffinePlane{shape.value, 0.0, 0.0};
    return scene;
}

// The shape of a random small scene for the sub-scanline methods' differential tests.
struct SmallSceneShape {
    int min_width, width_choices;    // width = min_width + rng() % width_choices
    int min_height, height_choices;  // likewise
    double margin_px;                // vertices reach this far past the image
    int shape_choices;               // 1 + rng() % shape_choices shapes
    int vertex_choices;              // 3 + rng() % vertex_choices vertices per contour
    int rect_quarter_choices;        // the snapped rectangle's sides: 1..this quarters
};

// 1..shape_choices shapes of 1–2 contours, random values and background, contours reversed at
// random (holes). `snapped`: every vertex on the 1/4-pixel grid, plus an axis-aligned
// rectangle on it, so vertices and horizontal edges land on sub-scanlines.
inline Scene random_small_scene(std::uint64_t seed, bool snapped, const SmallSceneShape& shape_of) {
    std::mt19937_64 rng(seed);
    auto snap = [&](double v) { return snapped ? std::round(v * 4.0) / 4.0 : v; };
    Scene scene;
    scene.width = shape_of.min_width + static_cast<int>(rng() % shape_of.width_choices);
    scene.height = shape_of.min_height + static_cast<int>(rng() % shape_of.height_choices);
    scene.background = std::uniform_real_distribution<double>(0.0, 0.4)(rng);
    const double m = shape_of.margin_px;
    std::uniform_real_distribution<double> coord_x(-m, scene.width + m);
    std::uniform_real_distribution<double> coord_y(-m, scene.height + m);
    std::uniform_real_distribution<double> value(0.0, 1.0);
    const int shapes = 1 + static_cast<int>(rng() % shape_of.shape_choices);
    for (int s = 0; s < shapes; ++s) {
        Shape shape;
        shape.value = value(rng);
        const int contours = 1 + static_cast<int>(rng() % 2);
        for (int c = 0; c < contours; ++c) {
            Contour contour;
            const int vertices = 3 + static_cast<int>(rng() % shape_of.vertex_choices);
            for (int k = 0; k < vertices; ++k) {
                contour.push_back({snap(coord_x(rng)), snap(coord_y(rng))});
            }
            if (rng() % 2) std::reverse(contour.begin(), contour.end());
            shape.contours.push_back(contour);
        }
        scene.shapes.push_back(shape);
    }
    if (snapped) {
        const auto q = static_cast<unsigned>(shape_of.rect_quarter_choices);
        const double x0 = snap(coord_x(rng)), y0 = snap(coord_y(rng));
        const double x1 = x0 + 0.25 * (1 + rng() % q), y1 = y0 + 0.25 * (1 + rng() % q);
        scene.shapes.push_back({{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}, value(rng)});
    }
    return scene;
}

// The scene as text, for failure messages.
inline std::string describe(const Scene& scene) {
    std::string text = fmt::format("{}x{} background {}", scene.width, scene.height,
                                   scene.background);
    for (const Shape& shape : scene.shapes) {
        text += fmt::format("\n  shape value {}:", shape.value);
        for (const Contour& c : shape.contours) {
            text += "\n    ";
            for (const Point& p : c) text += fmt::format("({}, {}) ", p.x, p.y);
        }
    }
    return text;
}

// The half-plane on the +n side (n = (-dy, dx)) of a line through a random point of the image
// at a random angle: a quadrilateral of positive shoelace area whose other corners lie `far`
// away (default 10 (width + height): far outside the image).
inline Scene random_half_plane(std::uint64_t seed, int width, int height, double far = 0.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi), px(0.0, width),
        py(0.0, height);
    const double a = angle(rng), x = px(rng), y = py(rng);
    const double dx = std::cos(a), dy = std::sin(a);
    if (far == 0.0) far = 10.0 * (width + height);
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
