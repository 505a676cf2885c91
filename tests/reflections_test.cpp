// The reflections stage (harness/world/reflections.h): the Embree caster against an exact
// brute-force ray / convex-polygon caster written here (double, no code shared), eq. 9 on a
// case computed by hand, the plan's reflections stage (out without edges: no image, no cost),
// and the `mirror` pattern's line image inside the mirror.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <fmt/format.h>

#include "harness/world/edges.h"
#include "harness/world/frame.h"
#include "harness/world/plan.h"
#include "harness/world/reflections.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

// ---- The exact caster: every face, in double ----

struct ExactHit {
    double t = INFINITY;
    int face = -1;
    double margin = INFINITY;  // distance from the hit point to the face's boundary
};

struct ExactFace {
    std::vector<glm::dvec3> loop;
    glm::dvec3 normal;
};

std::vector<ExactFace> exact_faces(const World& w) {
    std::vector<ExactFace> faces;
    for (const Object& o : w.objects) {
        for (const Face& f : o.faces) {
            ExactFace e;
            for (int i : f.loop) e.loop.push_back(o.vertices[i]);
            // Newell's normal: a different computation from face_normal's.
            glm::dvec3 n(0.0);
            for (std::size_t k = 0; k < e.loop.size(); ++k) {
                const glm::dvec3 a = e.loop[k], b = e.loop[(k + 1) % e.loop.size()];
                n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x),
                                (a.x - b.x) * (a.y + b.y));
            }
            e.normal = glm::normalize(n);
            faces.push_back(e);
        }
    }
    return faces;
}

// Signed distance (in the face's plane) from p to the face's boundary: > 0 inside.
double inside_margin(const ExactFace& f, const glm::dvec3& p) {
    double margin = INFINITY;
    for (std::size_t k = 0; k < f.loop.size(); ++k) {
        const glm::dvec3 a = f.loop[k], b = f.loop[(k + 1) % f.loop.size()];
        const glm::dvec3 inward = glm::normalize(glm::cross(f.normal, b - a));
        margin = std::min(margin, glm::dot(p - a, inward));
    }
    return margin;
}

ExactHit exact_cast(const std::vector<ExactFace>& faces, glm::dvec3 o, glm::dvec3 d, double t_min) {
    ExactHit best;
    for (std::size_t k = 0; k < faces.size(); ++k) {
        const ExactFace& f = faces[k];
        const double along = glm::dot(f.normal, d);
        if (along == 0.0) continue;
        const double t = glm::dot(f.normal, f.loop[0] - o) / along;
        if (!(t > t_min) || !(t < best.t)) continue;
        const double m = inside_margin(f, o + t * d);
        if (m < 0.0) continue;
        best = {t, static_cast<int>(k), m};
    }
    return best;
}

// A random planar convex polygon: 3 to 6 points on an ellipse in a random plane.
Object random_polygon(std::mt19937& rng, int index) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_real_distribution<double> size(0.3, 2.0);
    std::uniform_int_distribution<int> corners(3, 6);
    const glm::dvec3 centre(3 * u(rng), 3 * u(rng), 3 * u(rng));
    const glm::dvec3 n =
        glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + glm::dvec3(0, 0, 1e-3));
    const glm::dvec3 e1 = glm::normalize(
        glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 e2 = glm::cross(n, e1);
    const double a = size(rng), b = size(rng);
    Object o;
    o.name = fmt::format("p{}", index);
    o.closed = false;
    const int k = corners(rng);
    std::uniform_real_distribution<double> jitter(0.0, 0.8);
    Face f;
    for (int i = 0; i < k; ++i) {
        const double angle = 2 * M_PI * (i + jitter(rng)) / k;  // increasing: convex
        o.vertices.push_back(centre + a * std::cos(angle) * e1 + b * std::sin(angle) * e2);
        f.loop.push_back(i);
    }
    o.faces.push_back(f);
    return o;
}

// The caster recomputes t in double on the face's plane, so when both casters name the same face
// their t differ by double rounding of one plane intersection: relative 1e-15 times 1/cos of
// the angle to the plane; 1e-9 leaves a factor 1e6 of room (angles down to ~1e-6 rad).
constexpr double kSameFaceRelativeT = 1e-9;
// Embree's float rays and float vertices (relative rounding 6e-8 of coordinates of size ~5,
// a few roundings per intersection) can name another face only for rays within ~1e-6 of an
// edge; a ray whose exact hit lies farther than this from every edge of the faces involved must
// find the same face. 1e-5 world units: ten times that bound.
constexpr double kEdgeMargin = 1e-5;
// Rays closer than kEdgeMargin to an edge cannot be checked and are skipped: on these scenes
// about (perimeter x 2 kEdgeMargin) / area ~ 1e-5 of them; the test fails past 1 in 1,000.
constexpr double kMaxUncheckedShare = 1e-3;

// Embree's own t, for rays that meet the face at more than ~0.6 degrees off grazing: float
// origin, direction and vertices (relative rounding 6e-8 each) give a t off by ~1e-7 / cos of
// the angle to the plane and a few roundings more, up to ~1e-5 at cos = 0.01; measured 3.1e-5
// at most over the 158,146 hits (RecordProperty, x 1e9); 1e-4 leaves a factor 3. (The caster's
// t is the double one above; this measures what the float rays alone would give.)
constexpr double kFloatCheckMinCos = 0.01;
constexpr double kFloatRelativeT = 1e-4;

TEST(Reflections, EmbreeCasterAgreesWithTheExactCasterOnRandomScenes) {
    constexpr int kScenes = 50, kRaysPerScene = 4000;
    long long checked = 0, unchecked = 0, hits = 0;
    double max_float_relative = 0.0;
    for (int seed = 1; seed <= kScenes; ++seed) {
        std::mt19937 rng(seed);
        World w;
        std::uniform_int_distribution<int> count(1, 12);
        const int n = count(rng);
        for (int i = 0; i < n; ++i) w.objects.push_back(random_polygon(rng, i));
        const RayCaster caster(w);
        const std::vector<ExactFace> faces = exact_faces(w);
        ASSERT_EQ(caster.face_count(), static_cast<int>(faces.size()));
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        for (int k = 0; k < kRaysPerScene; ++k) {
            const glm::dvec3 o(6 * u(rng), 6 * u(rng), 6 * u(rng));
            // Toward a random point of a random face (a convex combination of its corners), so
            // that most rays hit something; other faces may lie in between.
            const ExactFace& aim =
                faces[std::uniform_int_distribution<std::size_t>(0, faces.size() - 1)(rng)];
            glm::dvec3 target(0.0);
            double weights = 0.0;
            for (const glm::dvec3& v : aim.loop) {
                const double wgt = 0.5 + 0.5 * u(rng);
                target += wgt * v;
                weights += wgt;
            }
            // One ray in four toward a random point of the scene's box instead: misses too.
            const glm::dvec3 d =
                (k % 4 == 0 ? glm::dvec3(3 * u(rng), 3 * u(rng), 3 * u(rng)) : target / weights) -
                o;
            const double t_min = 1e-3;
            const RayHit got = caster.cast(o, d, t_min);
            const ExactHit want = exact_cast(faces, o, d, t_min);
            const auto near_edge = [&](int face, double t) {
                return face >= 0 && std::abs(inside_margin(faces[face], o + t * d)) < kEdgeMargin;
            };
            if (near_edge(want.face, want.t) || near_edge(got.face, got.t)) {
                ++unchecked;
                continue;
            }
            ++checked;
            hits += want.face >= 0;
            ASSERT_EQ(got.face, want.face) << fmt::format(
                "seed {} ray {}: o ({}, {}, {}) d ({}, {}, {}); Embree t {}, exact t {}", seed, k,
                o.x, o.y, o.z, d.x, d.y, d.z, got.t, want.t);
            if (want.face >= 0) {
                const double cos_angle =
                    std::abs(glm::dot(faces[want.face].normal, glm::normalize(d)));
                if (cos_angle > kFloatCheckMinCos) {
                    max_float_relative =
                        std::max(max_float_relative, std::abs(got.float_t - want.t) / want.t);
                }
                ASSERT_NEAR(got.t, want.t, kSameFaceRelativeT * want.t)
                    << fmt::format("seed {} ray {} face {}", seed, k, want.face);
            }
        }
    }
    EXPECT_GT(hits, checked / 2) << "the rays must mostly hit faces to test anything";
    EXPECT_LE(unchecked, kMaxUncheckedShare * (checked + unchecked));
    EXPECT_LE(max_float_relative, kFloatRelativeT);
    RecordProperty("max_float_relative_t_x1e9", static_cast<int>(max_float_relative * 1e9));
    RecordProperty("checked", static_cast<int>(checked));
    RecordProperty("unchecked", static_cast<int>(unchecked));
    RecordProperty("hits", static_cast<int>(hits));
}

// ---- eq. 9 by hand ----

// The eye at the origin looking down -z; a mirror plane z = -kMirrorZ facing it (r); behind the
// eye a face z = +kBackZ parallel to the image plane. A primary ray (a, b, -1) meets the mirror
// at t = kMirrorZ (its view depth), is reflected to (a, b, 1) and meets the back face after
// kMirrorZ + kBackZ more: z_r = (1 - r) f d / D + r f d / (2 D + B) for every pixel, with d
// the eye's distance to its target (kTargetDistance).
constexpr double kMirrorZ = 5.0, kBackZ = 3.0, kR = 0.7, kTargetDistance = 2.5;

Scene analytic_scene(bool back_face) {
    Scene s;
    s.width = 48;
    s.height = 40;
    World w;
    w.camera.eye = {0, 0, 0};
    w.camera.target = {0, 0, -kTargetDistance};
    w.camera.fov_y_deg = 50.0;
    Object mirror = make_quad("mirror", {-100, -100, -kMirrorZ}, {100, -100, -kMirrorZ},
                              {100, 100, -kMirrorZ}, {-100, 100, -kMirrorZ}, 0.5);
    mirror.faces[0].mirror = kR;
    w.objects.push_back(mirror);
    if (back_face) {
        w.objects.push_back(make_quad("back", {-100, -100, kBackZ}, {-100, 100, kBackZ},
                                      {100, 100, kBackZ}, {100, -100, kBackZ}, 0.5));
    }
    w.edges = EdgesSpec{};
    s.world = w;
    return s;
}

// float32 image of values ~ f d / D ~ 20: rounding 1e-6; the mean of 9 samples in double, then
// one rounding. 1e-6 relative is 30 times float's 6e-8.
constexpr double kImageRelative = 1e-6;
// A single sample is double all through (plane intersections): rounding of a few operations.
constexpr double kSampleRelative = 1e-12;

TEST(Reflections, OpticalPathDepthOfAMirrorFacingTheEyeIsEquationNine) {
    const Scene scene = analytic_scene(true);
    const double f = 0.5 * scene.height / std::tan(0.5 * glm::radians(50.0));
    const double fd = f * kTargetDistance;
    const double expected = (1 - kR) * fd / kMirrorZ + kR * fd / (2 * kMirrorZ + kBackZ);
    const RayCaster caster(*scene.world);
    for (const auto& [x, y] : {std::pair{24.0, 20.0}, {0.5, 0.5}, {47.3, 39.9}, {10.1, 33.3}}) {
        EXPECT_NEAR(
            optical_path_sample(caster, scene.world->camera, scene.width, scene.height, x, y),
            expected, kSampleRelative * expected)
            << x << ", " << y;
    }
    const Image image = optical_path_depth(scene);
    for (float v : image.data) ASSERT_NEAR(v, expected, kImageRelative * expected);
    // Without the back face the reflected ray meets the background (0): the mirror keeps its
    // own share, unlike the background (eq. 9's purpose).
    const Scene open = analytic_scene(false);
    const RayCaster open_caster(*open.world);
    EXPECT_NEAR(
        optical_path_sample(open_caster, open.world->camera, open.width, open.height, 7.5, 30.5),
        (1 - kR) * fd / kMirrorZ, kSampleRelative * fd / kMirrorZ);
}

TEST(Reflections, WithoutMirrorsTheOpticalPathDepthIsTheDepthImage) {
    Scene scene = analytic_scene(false);
    scene.world->objects[0].faces[0].mirror = 0.0;
    const double f = 0.5 * scene.height / std::tan(0.5 * glm::radians(50.0));
    const Image image = optical_path_depth(scene);
    const double fd = f * kTargetDistance;
    for (float v : image.data) ASSERT_NEAR(v, fd / kMirrorZ, kImageRelative * fd / kMirrorZ);
}

// ---- The plan: the stage only with mirrors and edges ----

TEST(Reflections, MirrorWithoutEdgesRunsNoReflectionsStage) {
    Scene scene = make_pattern("mirror", 64, 64);
    {
        const Plan plan = make_plan(scene);
        ASSERT_TRUE(plan.in(Stage::kReflections));
        EXPECT_EQ(plan[Stage::kReflections].reason.find("not built"), std::string::npos);
        const PreparedFrame r = PreparedFrame::prepare(scene);
        const StageCost c = r.costs()[static_cast<int>(Stage::kReflections)];
        EXPECT_TRUE(c.ran);
        EXPECT_GE(c.bytes, 64u * 64u * sizeof(float)) << "the optical-path image is counted";
        ASSERT_TRUE(r.optical_depth().has_value());
        EXPECT_EQ(r.optical_depth()->width, 64);
    }
    scene.world->edges.reset();
    const Plan plan = make_plan(scene);
    EXPECT_FALSE(plan.in(Stage::kReflections));
    EXPECT_EQ(plan[Stage::kReflections].reason, "mirrors, but no edges asked");
    const PreparedFrame r = PreparedFrame::prepare(scene);
    const StageCost c = r.costs()[static_cast<int>(Stage::kReflections)];
    EXPECT_FALSE(c.ran);
    EXPECT_EQ(c.bytes, 0u);
    EXPECT_EQ(c.allocations, 0u);
    EXPECT_EQ(c.time_ms, 0.0);
    EXPECT_FALSE(r.optical_depth().has_value());
    EXPECT_FALSE(r.has_depth_stage());
    // Switched off by the scene, edges kept: out as well.
    Scene off = make_pattern("mirror", 64, 64);
    off.world->effects.reflections = false;
    EXPECT_FALSE(PreparedFrame::prepare(off).optical_depth().has_value());
    for (const char* id : {"torus", "terrain-edges", "room:edges=black"}) {
        EXPECT_FALSE(make_plan(make_pattern(id, 32, 32)).in(Stage::kReflections)) << id;
    }
}

// ---- The mirror pattern: lines inside the reflection ----

// "Line pixel": the black style's darkness over half (a drawn line, not a slope's residue).
constexpr float kLinePixel = 0.5f;
// Pixels counted lie this many pixels (Chebyshev) inside the mirror's visible area.
constexpr int kInsetPx = 2;
// Measured 220 line pixels at 128^2 (RecordProperty optical_line_px: the reflected box's outline
// and creases, the reflected floor's far edge); a quarter of it still means a reflection drawn.
constexpr int kMinOpticalLinePixels = 55;

TEST(Reflections, MirrorPatternDrawsLinesInsideTheReflection) {
    const int size = 128;
    const Scene scene = make_pattern("mirror", size, size);
    const Plan plan = make_plan(scene);
    const PreparedFrame r = PreparedFrame::prepare(scene);
    ASSERT_TRUE(r.optical_depth().has_value());
    const MethodInstance exact = make_method("exact");
    const Image shaded(size, size);
    const Image depth = *r.after_method(*exact.method, exact.spec, shaded, true).depth;
    EdgeImages plain, optical;
    r.edge_stage(depth, shaded, plain);
    r.edge_stage(*r.optical_depth(), shaded, optical);
    // Where the mirror is seen: pixel centres inside a visible piece of the mirror's face (the
    // box hides part of it), then only those whose 5 x 5 neighbourhood is all mirror, clear of
    // the mirror's own contour and the box's, which are two pixels wide (eq. 3's 3 x 3 stencil
    // straddles them from both sides).
    const int mirror_face = 7;  // floor 0, the box's six faces 1..6, the mirror 7
    ASSERT_EQ(scene.world->objects[2].name, "mirror");
    Raster<std::uint8_t> seen(size, size);
    for (const Shape& piece : r.pieces().scene().shapes) {
        if (piece.face != mirror_face) continue;
        const Contour& c = piece.contours[0];
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                bool pos = false, neg = false;
                for (std::size_t k = 0; k < c.size(); ++k) {
                    const Point a = c[k], b = c[(k + 1) % c.size()];
                    const double cross =
                        (b.x - a.x) * (y + 0.5 - a.y) - (b.y - a.y) * (x + 0.5 - a.x);
                    pos |= cross > 0;
                    neg |= cross < 0;
                }
                if (!(pos && neg)) seen.at(x, y) = 1;
            }
        }
    }
    const auto inside = [&](int x, int y) {
        for (int dy = -kInsetPx; dy <= kInsetPx; ++dy) {
            for (int dx = -kInsetPx; dx <= kInsetPx; ++dx) {
                const int u = x + dx, v = y + dy;
                if (u < 0 || v < 0 || u >= size || v >= size || !seen.at(u, v)) return false;
            }
        }
        return true;
    };
    int area = 0, plain_lines = 0, optical_lines = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            if (!inside(x, y)) continue;
            ++area;
            plain_lines += plain.lines.at(x, y) > kLinePixel;
            optical_lines += optical.lines.at(x, y) > kLinePixel;
        }
    }
    RecordProperty("mirror_area_px", area);
    RecordProperty("optical_line_px", optical_lines);
    RecordProperty("plain_line_px", plain_lines);
    EXPECT_GT(area, 500);
    // The mirror is one plane in z_s: no line inside it.
    EXPECT_EQ(plain_lines, 0);
    EXPECT_GT(optical_lines, kMinOpticalLinePixels);
}

}  // namespace
}  // namespace aabench
