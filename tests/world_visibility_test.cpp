// Exact visibility seen from the world: at random screen points, the visible piece the
// pipeline produced lies on the face that a ray cast from the eye through that point hits
// first. The ray caster here works in world space (ray-plane intersection, point in convex
// polygon) and shares nothing with the projection, the depth planes or the screen-space
// visibility it checks.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "tests/random_world.h"
#include "harness/world/frame.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

constexpr int kRandomScenes = 60;
constexpr int kPointsPerScene = 10000;
// Points this close (px) to a piece's boundary are skipped: there the answer depends on
// rounding of the boundary, not on visibility (two faces meet or one ends).
constexpr double kBoundaryMarginPx = 1e-6;
// Two faces hit at view depths within this relative difference are a tie (a shared edge, an
// intersection line): skipped, since either answer is right there.
constexpr double kDepthTieRelative = 1e-9;

// Is p inside the convex polygon (either orientation), at least `margin` from its edges?
bool inside_convex(const Contour& c, double x, double y, double margin) {
    int sign = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
        const Point& a = c[i];
        const Point& b = c[(i + 1) % c.size()];
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        if (len == 0.0) continue;
        const double d = ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)) / len;
        if (std::abs(d) <= margin) return false;
        const int s = d > 0 ? 1 : -1;
        if (sign == 0) sign = s;
        if (s != sign) return false;
    }
    return sign != 0;
}

struct Hit {
    int face = -1;
    double depth = INFINITY;
    double second = INFINITY;
};

// Casts the ray through screen point (x, y) against every face of the world (both sides:
// back faces of closed objects are hidden by nearer front faces anyway, except when the eye
// is inside, which no test scene has). Depth is the view depth z_v.
Hit cast(const World& w, int width, int height, double x, double y) {
    const glm::dmat4 view = glm::lookAt(w.camera.eye, w.camera.target, w.camera.up);
    const glm::dmat4 inv = glm::inverse(view);
    const double f = 0.5 * height / std::tan(0.5 * glm::radians(w.camera.fov_y_deg));
    const glm::dvec3 dir_cam((x - 0.5 * width) / f, -(y - 0.5 * height) / f, -1.0);
    const glm::dvec3 dir = glm::dvec3(inv * glm::dvec4(dir_cam, 0.0));  // z_v = 1 per unit t
    Hit hit;
    int global = 0;
    for (const Object& o : w.objects) {
        for (const Face& face : o.faces) {
            const int id = global++;
            const glm::dvec3 n = face_normal(o, face);
            const glm::dvec3 p0 = o.vertices[face.loop[0]];
            const double denom = glm::dot(n, dir);
            if (denom == 0.0) continue;
            const double t = glm::dot(n, p0 - w.camera.eye) / denom;  // t is z_v
            if (!(t > w.camera.near)) continue;
            const glm::dvec3 p = w.camera.eye + t * dir;
            // Inside the convex face: p on the inner side of every edge (about the normal).
            bool in = true;
            for (std::size_t i = 0; i < face.loop.size() && in; ++i) {
                const glm::dvec3 a = o.vertices[face.loop[i]];
                const glm::dvec3 b = o.vertices[face.loop[(i + 1) % face.loop.size()]];
                in = glm::dot(glm::cross(b - a, p - a), n) > 0.0;
            }
            if (!in) continue;
            if (t < hit.depth) {
                hit.second = hit.depth;
                hit.depth = t;
                hit.face = id;
            } else if (t < hit.second) {
                hit.second = t;
            }
        }
    }
    return hit;
}

struct Checked {
    int points = 0;
    int checked = 0;
    int mismatches = 0;
};

Checked check_scene(const Scene& scene, std::uint64_t seed) {
    const PreparedFrame r = PreparedFrame::prepare(scene);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ux(0.0, scene.width), uy(0.0, scene.height);
    Checked c;
    for (int k = 0; k < kPointsPerScene; ++k) {
        const double x = ux(rng), y = uy(rng);
        ++c.points;
        int piece_face = -1;
        bool near_boundary = false;
        for (const Shape& s : r.pieces().scene().shapes) {
            if (inside_convex(s.contours[0], x, y, kBoundaryMarginPx)) {
                piece_face = s.face;
                break;
            }
            if (inside_convex(s.contours[0], x, y, -kBoundaryMarginPx)) near_boundary = true;
        }
        if (near_boundary && piece_face < 0) continue;
        const Hit hit = cast(*scene.world, scene.width, scene.height, x, y);
        if (hit.second - hit.depth <= kDepthTieRelative * hit.depth) continue;
        ++c.checked;
        if (piece_face != hit.face) {
            ++c.mismatches;
            ADD_FAILURE() << "seed " << seed << " point (" << x << ", " << y << "): piece on face "
                          << piece_face << ", ray hits face " << hit.face << " at z_v "
                          << hit.depth;
            if (c.mismatches > 5) break;
        }
    }
    return c;
}


TEST(WorldVisibility, RandomWorldsAgreeWithRayCasting) {
    long long checked = 0;
    for (int k = 0; k < kRandomScenes; ++k) {
        const std::uint64_t seed = 0x5eed0000 + k;
        const Checked c = check_scene(random_world(seed, 6), seed);
        EXPECT_EQ(c.mismatches, 0) << "seed " << seed;
        EXPECT_GT(c.checked, kPointsPerScene / 2) << "seed " << seed << ": too many skipped";
        checked += c.checked;
    }
    RecordProperty("points_checked", std::to_string(checked));
}

TEST(WorldVisibility, ThreeDimensionalPatternsAgreeWithRayCasting) {
    int patterns = 0;
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(p.id, 64, 64);
        if (!scene.world) continue;
        ++patterns;
        const Checked c = check_scene(scene, 0xabc + patterns);
        EXPECT_EQ(c.mismatches, 0) << p.id;
        EXPECT_GT(c.checked, kPointsPerScene / 4) << p.id;
    }
    RecordProperty("patterns", std::to_string(patterns));
}

}  // namespace
}  // namespace aabench
