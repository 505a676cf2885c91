#include "harness/measure/dense_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <stdexcept>

#include "patterns/pattern.h"

namespace aabench {
namespace {

// A double in [0, 1) from the generator's next 32 bits (std::mt19937's sequence is fixed by
// the standard; the library distributions are not).
double unit(std::mt19937& rng) { return rng() * 0x1p-32; }
double between(std::mt19937& rng, double lo, double hi) { return lo + (hi - lo) * unit(rng); }

constexpr std::uint32_t kSeed = 20240601;

// Polygons of 3 to 12 vertices about a random centre, radius 1% to 6% of the side: angles
// sorted (a star-shaped polygon) except every fifth one (shuffled: self-intersecting), every
// other one clockwise. Values 0.25, 0.5, 0.75, 1 on a background of 0.1, so consecutive
// shapes of one value are rare and most overlaps composite different values.
Scene soup(int side) {
    constexpr int kPolygonsPer1024 = 1200;
    Scene scene;
    scene.width = scene.height = side;
    scene.background = 0.1;
    std::mt19937 rng(kSeed);
    const int count = std::max(8, static_cast<int>(std::lround(kPolygonsPer1024 * side / 1024.0)));
    for (int k = 0; k < count; ++k) {
        const double cx = between(rng, 0.0, side), cy = between(rng, 0.0, side);
        const double radius = side * between(rng, 0.01, 0.06);
        const int n = 3 + static_cast<int>(rng() % 10);
        std::vector<double> angles(n);
        for (double& a : angles) a = between(rng, 0.0, 2.0 * std::numbers::pi);
        if (k % 5 != 0) std::sort(angles.begin(), angles.end());
        Contour c;
        for (double a : angles) {
            const double r = radius * between(rng, 0.4, 1.0);
            c.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
        }
        if (k % 2 == 1) std::reverse(c.begin(), c.end());
        scene.shapes.push_back({{std::move(c)}, 0.25 * (1 + rng() % 4)});
    }
    return scene;
}

Contour rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// A stroke from (x0, y0) to (x1, y1) of width w, as a quadrilateral.
Contour stroke(double x0, double y0, double x1, double y1, double w) {
    const double len = std::hypot(x1 - x0, y1 - y0);
    const double nx = -(y1 - y0) / len * 0.5 * w, ny = (x1 - x0) / len * 0.5 * w;
    return {{x0 + nx, y0 + ny}, {x1 + nx, y1 + ny}, {x1 - nx, y1 - ny}, {x0 - nx, y0 - ny}};
}

// Glyph-like outlines in a cell of kCellW x kCellH px, lines of text with slightly slanted,
// sub-pixel positions: an "o" (outer and inner polygon of 24 sides, the hole opposite), an
// "l" (a bar), a "v" (a chevron), an "x" (two crossing strokes in one shape, the same
// orientation: nonzero fills their overlap once).
Scene glyphs(int side) {
    constexpr double kCellW = 9.3, kCellH = 14.0, kStem = 1.3;
    Scene scene;
    scene.width = scene.height = side;
    std::mt19937 rng(kSeed + 1);
    for (double y = 2.0; y + kCellH < side; y += kCellH) {
        for (double x = 2.0; x + kCellW < side; x += kCellW) {
            const double ox = x + 0.37 * unit(rng), oy = y + 0.21 * unit(rng);
            Shape glyph;
            switch (rng() % 5) {
                case 0: {  // o
                    const double cx = ox + 4.0, cy = oy + 7.0;
                    glyph.contours.push_back(circle_contour(cx, cy, 3.6, 0.01, false));
                    glyph.contours.push_back(circle_contour(cx, cy, 3.6 - kStem, 0.01, true));
                    break;
                }
                case 1:  // l
                    glyph.contours.push_back(rectangle(ox + 3.3, oy + 1.0, ox + 3.3 + kStem, oy + 11.0));
                    break;
                case 2:  // v
                    glyph.contours.push_back({{ox + 0.5, oy + 4.0}, {ox + 2.0, oy + 4.0},
                                              {ox + 4.0, oy + 9.5}, {ox + 6.0, oy + 4.0},
                                              {ox + 7.5, oy + 4.0}, {ox + 4.7, oy + 11.0},
                                              {ox + 3.3, oy + 11.0}});
                    break;
                case 3:  // x
                    glyph.contours.push_back(stroke(ox + 0.8, oy + 4.0, ox + 7.2, oy + 11.0, kStem));
                    glyph.contours.push_back(stroke(ox + 0.8, oy + 11.0, ox + 7.2, oy + 4.0, kStem));
                    break;
                default:  // a space
                    continue;
            }
            scene.shapes.push_back(std::move(glyph));
        }
    }
    return scene;
}

}  // namespace

const std::vector<std::string>& dense_scene_names() {
    static const std::vector<std::string> names = {"dense-rings", "dense-zoneplate", "soup",
                                                   "glyphs"};
    return names;
}

Scene make_dense_scene(const std::string& name, int side) {
    if (name == "dense-rings") return make_pattern("rings:period=1.7", side, side);
    if (name == "dense-zoneplate") return make_pattern("zoneplate:nyquist_radius=0.3", side, side);
    if (name == "soup") return soup(side);
    if (name == "glyphs") return glyphs(side);
    throw std::invalid_argument("make_dense_scene: unknown scene '" + name + "'");
}

}  // namespace aabench
