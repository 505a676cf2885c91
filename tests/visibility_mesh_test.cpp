// Exact visibility on the two mesh scenes it was built for: a 1,280-face geodesic sphere
// (front faces touch along shared edges only: nothing may be cut) and a two-sided terrain
// seen at a grazing angle (many real overlaps). The meshes are projected here, in the test,
// with the perspective of docs/world.md ("The world's contracts"), independently of harness/world.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <fmt/format.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "harness/reference/box_reference.h"
#include "harness/reference/visibility.h"
#include "methods/scan/reference/box_coverage.h"
#include "visibility_scenes.h"

namespace aabench {
namespace {

using Triangle = std::array<glm::dvec3, 3>;

// The references promise 1e-9 per pixel; see tests/visibility_test.cpp.
constexpr double kPixelTolerance = 1e-9;
constexpr double kBoundaryMarginPx = 1e-9;

struct Projector {
    int width, height;
    double f;  // focal length in px
    glm::dmat4 view;

    Projector(int w, int h, double fov_y_deg, glm::dvec3 eye, glm::dvec3 target)
        : width(w),
          height(h),
          f(0.5 * h / std::tan(glm::radians(fov_y_deg) / 2.0)),
          view(glm::lookAt(eye, target, glm::dvec3(0.0, 1.0, 0.0))) {}

    // View space with z_v > 0 ahead (glm looks down -z).
    glm::dvec3 to_view(const glm::dvec3& p) const {
        const glm::dvec4 v = view * glm::dvec4(p, 1.0);
        return {v.x, v.y, -v.z};
    }
    Point to_screen(const glm::dvec3& v) const {
        return {0.5 * width + f * v.x / v.z, 0.5 * height - f * v.y / v.z};
    }
    // The face's plane n . v = d in view space gives 1/z_v = (n_x (x - W/2) / f
    // - n_y (y - H/2) / f + n_z) / d at screen (x, y).
    Shape face(const Triangle& t, int index) const {
        const glm::dvec3 a = to_view(t[0]), b = to_view(t[1]), c = to_view(t[2]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double d = glm::dot(n, a);
        Shape s;
        s.contours = {{to_screen(a), to_screen(b), to_screen(c)}};
        const double gx = n.x / (f * d), gy = -n.y / (f * d);
        s.inv_depth = AffinePlane{n.z / d - gx * 0.5 * width - gy * 0.5 * height, gx, gy};
        s.face = index;
        s.value = 0.2 + 0.6 * static_cast<double>(index % 11) / 11.0;
        return s;
    }
};

std::vector<Triangle> geodesic_sphere(int subdivisions) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                 {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                 {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    const int f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                          {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                          {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                          {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    std::vector<Triangle> tris;
    for (const auto& k : f) {
        tris.push_back({glm::normalize(v[k[0]]), glm::normalize(v[k[1]]), glm::normalize(v[k[2]])});
    }
    for (int s = 0; s < subdivisions; ++s) {
        std::vector<Triangle> next;
        for (const Triangle& tr : tris) {
            // Midpoints computed from the same two endpoints in a fixed order, so that the two
            // triangles sharing an edge get the same vertex to the last bit.
            auto mid = [](glm::dvec3 p, glm::dvec3 q) {
                if (p.x > q.x || (p.x == q.x && (p.y > q.y || (p.y == q.y && p.z > q.z)))) {
                    std::swap(p, q);
                }
                return glm::normalize(p + q);
            };
            const glm::dvec3 ab = mid(tr[0], tr[1]), bc = mid(tr[1], tr[2]), ca = mid(tr[2], tr[0]);
            next.push_back({tr[0], ab, ca});
            next.push_back({ab, tr[1], bc});
            next.push_back({ca, bc, tr[2]});
            next.push_back({ab, bc, ca});
        }
        tris.swap(next);
    }
    return tris;
}

// For every point: the one piece holding it (away from piece boundaries) is a piece of the
// input shape nearest there (largest inv_depth); no piece where no shape is.
void check_point_queries(const Scene& scene, const Scene& pieces, int points, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> x(0.0, scene.width), y(0.0, scene.height);
    int checked = 0;
    for (int q = 0; q < points; ++q) {
        const Point p{x(rng), y(rng)};
        int holder = -1, holders = 0;
        bool near = false;
        for (std::size_t k = 0; k < pieces.shapes.size(); ++k) {
            const Contour& c = pieces.shapes[k].contours[0];
            if (testing::near_boundary(c, p, kBoundaryMarginPx)) near = true;
            if (testing::inside_by(c, p, kBoundaryMarginPx)) {
                holder = static_cast<int>(k);
                ++holders;
            }
        }
        if (near) continue;
        ASSERT_LE(holders, 1) << fmt::format("point ({:.17g}, {:.17g})", p.x, p.y);
        int nearest = -1;
        double best = 0.0;
        for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
            if (!testing::inside_by(scene.shapes[k].contours[0], p, 0.0)) continue;
            const double w = scene.shapes[k].inv_depth->at(p.x, p.y);
            if (nearest < 0 || w >= best) {
                nearest = static_cast<int>(k);
                best = w;
            }
        }
        const int got = holder < 0 ? -1 : pieces.shapes[holder].face;
        ASSERT_EQ(got, nearest) << fmt::format("point ({:.17g}, {:.17g})", p.x, p.y);
        ++checked;
    }
    EXPECT_GT(checked, points * 9 / 10);
}

// Pieces cover the union of the shapes once: with every value 1 the box reference of the
// pieces is the coverage of the union, which box_coverage gives independently.
void check_union_coverage(const Scene& scene, Scene pieces) {
    Scene flat = scene;
    for (Shape& s : flat.shapes) {
        s.inv_depth.reset();
        s.value = 1.0;
    }
    for (Shape& s : pieces.shapes) s.value = 1.0;
    const Coverage got = box_reference_of_pieces(pieces), want = box_coverage(flat);
    double worst = 0.0;
    for (std::size_t k = 0; k < got.data.size(); ++k) {
        ASSERT_NEAR(got.data[k], want.data[k], kPixelTolerance) << "pixel " << k;
        worst = std::max(worst, std::abs(got.data[k] - want.data[k]));
    }
    std::printf("[union] worst |pieces - union coverage| = %.3g\n", worst);
}

TEST(VisibilityMesh, GeodesicSphereFrontFacesComeOutWhole) {
    const std::vector<Triangle> sphere = geodesic_sphere(3);
    ASSERT_EQ(sphere.size(), 1280u);
    const glm::dvec3 eye(0.4, 0.7, 3.2);
    const Projector cam(512, 512, 45.0, eye, glm::dvec3(0.0));
    Scene scene;
    scene.width = scene.height = 512;
    for (const Triangle& t : sphere) {
        Triangle o = t;
        const glm::dvec3 n = glm::cross(o[1] - o[0], o[2] - o[0]);
        if (glm::dot(n, o[0] + o[1] + o[2]) < 0.0) std::swap(o[1], o[2]);  // outward
        const glm::dvec3 out = glm::cross(o[1] - o[0], o[2] - o[0]);
        if (glm::dot(out, eye - o[0]) <= 0.0) continue;  // back face: culled
        scene.shapes.push_back(cam.face(o, static_cast<int>(scene.shapes.size())));
    }
    VisibilityStats stats;
    const auto t0 = std::chrono::steady_clock::now();
    const Scene pieces = visible_pieces(scene, &stats);
    const auto t1 = std::chrono::steady_clock::now();
    std::printf(
        "[sphere] %zu front faces, %zu candidate pairs, %zu overlapping, %zu pieces, "
        "%.1f ms\n",
        scene.shapes.size(), stats.candidate_pairs, stats.overlapping_pairs, stats.pieces_out,
        std::chrono::duration<double, std::milli>(t1 - t0).count());
    EXPECT_GT(stats.candidate_pairs, scene.shapes.size());
    EXPECT_EQ(stats.overlapping_pairs, 0u);
    EXPECT_EQ(stats.pieces_out, scene.shapes.size());
    check_union_coverage(scene, pieces);
}

TEST(VisibilityMesh, TerrainAtAGrazingAngleMatchesPointQueries) {
    constexpr int kCells = 24;  // 24 x 24 quads: 1,152 two-sided triangles
    auto height = [](double x, double z) {
        return 0.35 * std::sin(1.7 * x + 0.3) * std::cos(1.3 * z) + 0.15 * std::sin(3.1 * z + x);
    };
    std::vector<std::vector<glm::dvec3>> node(kCells + 1, std::vector<glm::dvec3>(kCells + 1));
    for (int j = 0; j <= kCells; ++j) {
        for (int i = 0; i <= kCells; ++i) {
            const double x = -3.0 + 6.0 * i / kCells, z = -6.0 + 6.0 * j / kCells;
            node[j][i] = {x, height(x, z), z};
        }
    }
    // Eye just above the ground in front of the terrain, looking across it: hills hide hills.
    const Projector cam(256, 192, 50.0, glm::dvec3(0.0, 0.45, 1.5), glm::dvec3(0.0, 0.1, -6.0));
    Scene scene;
    scene.width = 256;
    scene.height = 192;
    scene.background = 0.05;
    for (int j = 0; j < kCells; ++j) {
        for (int i = 0; i < kCells; ++i) {
            for (const Triangle& t : {Triangle{node[j][i], node[j][i + 1], node[j + 1][i + 1]},
                                      Triangle{node[j][i], node[j + 1][i + 1], node[j + 1][i]}}) {
                scene.shapes.push_back(cam.face(t, static_cast<int>(scene.shapes.size())));
            }
        }
    }
    VisibilityStats stats;
    const auto t0 = std::chrono::steady_clock::now();
    const Scene pieces = visible_pieces(scene, &stats);
    const auto t1 = std::chrono::steady_clock::now();
    std::printf(
        "[terrain] %zu faces, %zu candidate pairs, %zu overlapping, %zu pieces, "
        "%.1f ms\n",
        scene.shapes.size(), stats.candidate_pairs, stats.overlapping_pairs, stats.pieces_out,
        std::chrono::duration<double, std::milli>(t1 - t0).count());
    EXPECT_GT(stats.overlapping_pairs, 100u);  // the grazing view does make hills hide hills
    check_point_queries(scene, pieces, 10000, 42);
    check_union_coverage(scene, pieces);
}

}  // namespace
}  // namespace aabench
