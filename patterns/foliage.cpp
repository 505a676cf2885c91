// `foliage`: many small leaves (flat rhombi, two-sided) at seeded random positions, depths and
// orientations in a box in front of a backdrop wall, under one parallel light that may cast
// shadows.
//
// What it provokes: the hardest antialiasing case people actually render: many small
// silhouettes of many depths over each other and over the backdrop, leaves seen edge-on as
// slivers, leaves that pierce each other, gaps of a pixel or less between them, and (with
// shadows) shadow edges on the backdrop and on other leaves. It is also the benchmark's
// cost-model pattern for deep overlap (docs/benchmarks.md): `leaves` runs from 10^2 to 10^5.
//
// Layout: the leaves fill the box x in [-2.2, 2.2], y in [-1.6, 1.6], z in [-2, 2] in front of
// a wall at z = -3.2 (6.4 x 6 world units, a little less than the view there), seen from
// z = 6.5. A leaf's size shrinks as 1/sqrt(leaves), so the total
// leaf area (and with it the mean depth complexity: 200 rhombi of 0.04 world units^2, half of
// that seen on average over random orientations, over the box's 14 world units^2 front, about
// 0.3) stays the same at every count: more leaves means smaller ones, not a solid wall.
// Each leaf comes from its own hash of (seed, index) (SplitMix64), not from a standard
// library distribution, so the scene is the same bit for bit on every platform.
//
// Parameters:
//   leaves   200   leaves (100..100000)
//   seed     1     which random arrangement (1..1000000)
//   shadows  off   off | on: the light casts shadows (leaves onto the wall and each other)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

// Half-length (tip to centre) and half-width of a leaf at 200 leaves, world units: a rhombus
// of 0.04 world units^2, a few pixels across at 256 x 256 (the box spans about 180 px).
constexpr double kLeafHalfLength200 = 0.2;
constexpr double kLeafHalfWidth200 = 0.1;
constexpr int kLeavesAtReferenceSize = 200;

// SplitMix64 (Steele, Lea & Flood 2014): a small counter-based generator whose output is
// fixed by its integer arithmetic alone.
std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// Uniform draws in [0, 1) from one leaf's stream: 53 bits of each step, exact in a double.
class LeafRandom {
public:
    LeafRandom(int seed, int leaf)
        : state_(splitmix64((static_cast<std::uint64_t>(seed) << 32) ^
                            static_cast<std::uint64_t>(leaf))) {}
    double next() {
        state_ = splitmix64(state_);
        return static_cast<double>(state_ >> 11) * 0x1.0p-53;
    }
    double in(double lo, double hi) { return lo + (hi - lo) * next(); }

private:
    std::uint64_t state_;
};

// A leaf: the rhombus centre +- half_length u, centre +- half_width v, counter-clockwise about
// n = u x v, with n uniform on the sphere and u turned about it by a uniform angle.
void add_leaf(Object& leaves, LeafRandom& random, double half_length, double half_width) {
    const glm::dvec3 centre{random.in(-2.2, 2.2), random.in(-1.6, 1.6), random.in(-2.0, 2.0)};
    const double cos_polar = random.in(-1.0, 1.0);
    const double azimuth = random.in(0.0, 2.0 * std::numbers::pi);
    const double sin_polar = std::sqrt(std::max(0.0, 1.0 - cos_polar * cos_polar));
    const glm::dvec3 n{sin_polar * std::cos(azimuth), cos_polar, sin_polar * std::sin(azimuth)};
    // Any axis far from n gives a first tangent; the turn below makes its choice irrelevant.
    const glm::dvec3 axis = std::abs(n.x) < 0.6 ? glm::dvec3{1, 0, 0} : glm::dvec3{0, 0, 1};
    const glm::dvec3 t = glm::normalize(glm::cross(n, axis));
    const double turn = random.in(0.0, 2.0 * std::numbers::pi);
    const glm::dvec3 u = std::cos(turn) * t + std::sin(turn) * glm::cross(n, t);
    const glm::dvec3 v = glm::cross(n, u);
    const int first = static_cast<int>(leaves.vertices.size());
    leaves.vertices.push_back(centre + half_length * u);
    leaves.vertices.push_back(centre + half_width * v);
    leaves.vertices.push_back(centre - half_length * u);
    leaves.vertices.push_back(centre - half_width * v);
    Face face;
    face.loop = {first, first + 1, first + 2, first + 3};
    face.reflectance = random.in(0.35, 0.85);
    leaves.faces.push_back(std::move(face));
}

Scene generate_foliage(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("foliage", values, width, height);
    const int count = values.get_int("leaves");
    const int seed = values.get_int("seed");
    const double scale = std::sqrt(static_cast<double>(kLeavesAtReferenceSize) / count);
    World w;
    w.camera.eye = {0.23, 0.41, 6.5};
    w.camera.target = {0.0, 0.0, 0.0};
    w.camera.fov_y_deg = 40.0;
    w.ambient = 0.2;
    // The wall stops short of the image's edges (its corners in view at any aspect of 1 or
    // wider): its outline against the dark background is a long near-axis edge besides.
    w.objects.push_back(make_quad("backdrop", {-3.17, -2.93, -3.2}, {3.21, -2.93, -3.2},
                                  {3.21, 3.04, -3.2}, {-3.17, 3.04, -3.2}, 0.9));
    Object leaves;
    leaves.name = "leaves";
    leaves.closed = false;
    leaves.vertices.reserve(4 * static_cast<std::size_t>(count));
    leaves.faces.reserve(count);
    for (int k = 0; k < count; ++k) {
        LeafRandom random(seed, k);
        add_leaf(leaves, random, kLeafHalfLength200 * scale, kLeafHalfWidth200 * scale);
    }
    w.objects.push_back(std::move(leaves));
    Light sun;
    sun.direction = {-0.45, -0.7, -0.55};  // from the upper right and the front: shadows fall
                                           // down-left onto the wall, visible past the leaves
    sun.intensity = 0.8;
    sun.shadows = values.get_choice("shadows") == "on";
    w.lights.push_back(sun);
    const glm::dvec2 focus = project_point(w.camera, width, height, {0.0, 0.0, 0.0});
    scene.world = std::move(w);
    set_focus(scene, focus.x, focus.y, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo foliage_pattern() {
    return PatternInfo{
        "foliage",
        "3-D leaves at random depths and orientations before a wall: many small silhouettes",
        {
            {"leaves", ParamKind::kInt, kLeavesAtReferenceSize, 100, 100000, {},
             "leaves; their size shrinks as 1/sqrt(leaves), so the cover stays the same"},
            {"seed", ParamKind::kInt, 1, 1, 1000000, {}, "which random arrangement"},
            {"shadows", ParamKind::kChoice, 0, 0, 0, {"off", "on"},
             "the light casts shadows (leaves onto the wall and onto each other)"},
        },
        generate_foliage,
    };
}

}  // namespace aabench
