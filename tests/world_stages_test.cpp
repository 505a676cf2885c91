// The world stages against hand-computed answers: projection (a face parallel to the image
// plane, vanishing points, the near plane, depth planes), culling, shading, patterns and
// shadows (one light, two lights, a pattern in shadow).
#include <gtest/gtest.h>

#include <cmath>

#include "harness/world/stages.h"

namespace aabench {
namespace {

// Projection and depth planes are a handful of double operations on inputs of size ~1-1000:
// exact to ~1e-13 relative, so 1e-9 px / 1e-12 in 1/z leaves a wide margin and still catches
// any wrong formula.
constexpr double kPixelTolerance = 1e-9;
constexpr double kInvDepthTolerance = 1e-12;
// Areas of cells in world units, summed over a handful of clipped polygons.
constexpr double kAreaTolerance = 1e-12;
// Shaded values: products and sums of a few doubles.
constexpr double kValueTolerance = 1e-12;

Object quad(const std::string& name, glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d,
            double reflectance, bool closed = false) {
    Object o;
    o.name = name;
    o.closed = closed;
    o.vertices = {a, b, c, d};
    Face f;
    f.loop = {0, 1, 2, 3};
    f.reflectance = reflectance;
    o.faces.push_back(f);
    return o;
}

// An axis-aligned box, faces counter-clockwise seen from outside.
Object box(glm::dvec3 lo, glm::dvec3 hi) {
    Object o;
    o.name = "box";
    o.vertices = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                  {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int loops[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    for (const auto& l : loops) {
        Face f;
        f.loop = {l[0], l[1], l[2], l[3]};
        o.faces.push_back(f);
    }
    return o;
}

World camera_world(glm::dvec3 eye, glm::dvec3 target, double fov_y_deg = 90.0) {
    World w;
    w.camera.eye = eye;
    w.camera.target = target;
    w.camera.fov_y_deg = fov_y_deg;
    return w;
}

struct Staged {
    ViewSetup view;
    std::vector<WorldFace> faces;
    std::vector<std::vector<Cell>> cells;
};

Staged stage_all(const World& w, int width, int height, bool shadows = true) {
    Staged s;
    s.view = ViewSetup::from(w.camera, width, height);
    s.faces = collect_faces(w, s.view);
    cull_back_faces(s.faces, s.view);
    s.cells = initial_cells(s.faces);
    cut_patterns(w, s.faces, s.cells);
    if (shadows) cast_shadows(w, s.faces, s.cells);
    if (w.lights.empty()) {
        unshaded(s.cells);
    } else {
        shade(w, s.faces, s.cells);
    }
    return s;
}

double cells_area(const std::vector<Cell>& cells, double value, bool match_value) {
    double a = 0.0;
    for (const Cell& c : cells) {
        if (!match_value || std::abs(c.value - value) <= kValueTolerance)
            a += 0.5 * std::abs(twice_area(c.loop));
    }
    return a;
}

TEST(Projection, FaceParallelToTheImagePlaneLandsWhereFxOverZSays) {
    // Eye on +z looking at the origin; the square [-1, 1]^2 at z = 0 lies 5 units ahead.
    World w = camera_world({0, 0, 5}, {0, 0, 0}, 90.0);
    w.objects.push_back(quad("q", {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, 1.0));
    const int width = 200, height = 100;
    Staged s = stage_all(w, width, height);
    Scene screen;
    project_cells(s.faces, s.cells, s.view, screen);
    ASSERT_EQ(screen.shapes.size(), 1u);
    const double f = 0.5 * height / std::tan(glm::radians(45.0));  // 50 px
    EXPECT_NEAR(s.view.focal_px, f, kPixelTolerance);
    double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
    for (const Point& p : screen.shapes[0].contours[0]) {
        xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
        ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
    }
    EXPECT_NEAR(xmin, 100 - f / 5, kPixelTolerance);
    EXPECT_NEAR(xmax, 100 + f / 5, kPixelTolerance);
    EXPECT_NEAR(ymin, 50 - f / 5, kPixelTolerance);
    EXPECT_NEAR(ymax, 50 + f / 5, kPixelTolerance);
    // 1/z_v is 1/5 everywhere on a face parallel to the image plane.
    const AffinePlane& d = *screen.shapes[0].inv_depth;
    EXPECT_NEAR(d.at(100, 50), 0.2, kInvDepthTolerance);
    EXPECT_NEAR(d.at(110, 57), 0.2, kInvDepthTolerance);
}

TEST(Projection, TiltedPlaneDepthMatchesRayIntersection) {
    World w = camera_world({0.3, 1.7, 4.2}, {0.1, -0.2, 0.0}, 50.0);
    w.objects.push_back(
        quad("floor", {-3, -1, -3}, {-3, -1.4, 3}, {3, -0.8, 3}, {3, -0.4, -3}, 1.0));
    const int width = 320, height = 240;
    Staged s = stage_all(w, width, height);
    ASSERT_TRUE(s.faces[0].visible);
    const AffinePlane d = inverse_depth_plane(s.faces[0], s.view);
    const glm::dvec3 n = s.faces[0].frame.normal, o = s.faces[0].frame.origin;
    // At a few screen points: cast the ray in world space, intersect the plane, compare z_v.
    const glm::dmat4 inv = glm::inverse(s.view.view);
    for (const glm::dvec2 px :
         {glm::dvec2(160, 120), glm::dvec2(17.5, 200.25), glm::dvec2(300, 33)}) {
        const double f = s.view.focal_px;
        const glm::dvec3 dir_cam((px.x - 160) / f, -(px.y - 120) / f, -1.0);  // lookAt: -z ahead
        const glm::dvec3 dir = glm::dvec3(inv * glm::dvec4(dir_cam, 0.0));
        const double t = glm::dot(n, o - w.camera.eye) / glm::dot(n, dir);
        const double z_v = s.view.to_view(w.camera.eye + t * dir).z;
        EXPECT_NEAR(d.at(px.x, px.y), 1.0 / z_v, kInvDepthTolerance) << px.x << "," << px.y;
    }
}

TEST(Projection, ParallelLinesMeetAtTheVanishingPoint) {
    // A long strip on the ground running away from a horizontal camera: its far end lands on
    // the horizon (y = H/2) at the centre column, as the vanishing point of -z says.
    World w = camera_world({0, 1, 0}, {0, 1, -1}, 60.0);
    w.objects.push_back(quad("road", {-1, 0, -1}, {1, 0, -1}, {1, 0, -1e7}, {-1, 0, -1e7}, 1.0));
    Staged s = stage_all(w, 100, 100);
    Scene screen;
    project_cells(s.faces, s.cells, s.view, screen);
    ASSERT_EQ(screen.shapes.size(), 1u);
    const double f = s.view.focal_px;
    // The far vertices sit f * 1 / 1e7 px below the horizon and f * 1 / 1e7 px off centre.
    constexpr double kFarOffsetPx = 1e-4;
    int far_vertices = 0;
    for (const Point& p : screen.shapes[0].contours[0]) {
        if (std::abs(p.y - 50.0) < kFarOffsetPx) {
            ++far_vertices;
            EXPECT_NEAR(p.x, 50.0, kFarOffsetPx);
        }
    }
    EXPECT_EQ(far_vertices, 2);
    (void)f;
}

TEST(Projection, NearPlaneClipsWhatIsBehindIt) {
    World w = camera_world({0, 1, 0}, {0, 1, -1}, 60.0);
    w.camera.near = 0.5;
    // A ground quad from behind the eye to ahead of it.
    w.objects.push_back(quad("ground", {-1, 0, 3}, {1, 0, 3}, {1, 0, -4}, {-1, 0, -4}, 1.0));
    Staged s = stage_all(w, 100, 100);
    Scene screen;
    project_cells(s.faces, s.cells, s.view, screen);
    ASSERT_EQ(screen.shapes.size(), 1u);
    // The clipped edge lies at z_v = 0.5: y = H/2 + f * 1 / 0.5.
    double ymax = -1e9;
    for (const Point& p : screen.shapes[0].contours[0]) ymax = std::max(ymax, p.y);
    EXPECT_NEAR(ymax, 50 + s.view.focal_px * 2.0, kPixelTolerance);
}

TEST(Culling, ACubeSeenFromACornerShowsThreeFacesAndFromAnAxisOne) {
    World w = camera_world({3, 4, 5}, {0, 0, 0});
    w.objects.push_back(box({-1, -1, -1}, {1, 1, 1}));
    Staged s = stage_all(w, 64, 64);
    int visible = 0;
    for (const WorldFace& f : s.faces) visible += f.visible;
    EXPECT_EQ(visible, 3);
    World axis = camera_world({0, 0, 6}, {0, 0, 0});
    axis.objects.push_back(box({-1, -1, -1}, {1, 1, 1}));
    Staged t = stage_all(axis, 64, 64);
    visible = 0;
    for (const WorldFace& f : t.faces) visible += f.visible;
    EXPECT_EQ(visible, 1);  // in perspective the side faces turn away from an eye on the axis
}

TEST(Shading, ALitQuadIsReflectanceTimesAmbientPlusLambert) {
    World w = camera_world({0, 5, 5}, {0, 0, 0});
    w.ambient = 0.2;
    w.objects.push_back(quad("floor", {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, 0.5));
    Light sun;
    sun.direction = {0, -1, -1};  // 45 degrees: n . l = cos 45
    sun.intensity = 0.8;
    w.lights.push_back(sun);
    Light bulb;
    bulb.type = LightType::kPoint;
    bulb.position = {0, 2, 0};  // 2 above the centroid: falloff 1/4, n . l = 1
    bulb.intensity = 4.0;
    w.lights.push_back(bulb);
    Staged s = stage_all(w, 64, 64);
    ASSERT_EQ(s.cells[0].size(), 1u);
    EXPECT_NEAR(s.cells[0][0].value, 0.5 * (0.2 + 0.8 * std::sqrt(0.5) + 4.0 / 4.0),
                kValueTolerance);
}

World shadow_world() {
    World w = camera_world({0, 6, 6}, {0, 0, 0});
    w.ambient = 0.25;
    w.objects.push_back(quad("floor", {-2, 0, 2}, {2, 0, 2}, {2, 0, -2}, {-2, 0, -2}, 0.5));
    // A unit square hovering at height 1 (two-sided): its shadow straight down has area 1.
    w.objects.push_back(
        quad("roof", {-0.5, 1, 0.5}, {0.5, 1, 0.5}, {0.5, 1, -0.5}, {-0.5, 1, -0.5}, 1.0));
    return w;
}

// A shadow whose caster shares a vertex with its receiver has that vertex twice (it casts onto
// itself, and clipping to the receiver adds it again), exactly or a few ulps apart. The cut is
// the one without the repeat: the inside and the parts outside partition the cell (no part
// both inside and outside, none cut by the direction-less line of a zero-length edge).
TEST(Geometry, ACutterWithARepeatedVertexCutsAsWithoutIt) {
    const Polygon2 cell = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    const double ulp_apart = 3 * 2.220446049250313e-16;  // a few ulps of the coordinate 1
    for (const Polygon2& cutter : {Polygon2{{1, 1}, {1, 1}, {3, 1}, {2, 3}},
                                   Polygon2{{1, 1}, {1 + ulp_apart, 1 - ulp_apart}, {3, 1}, {2, 3}},
                                   Polygon2{{1, 1}, {3, 1}, {2, 3}, {1, 1}}}) {
        std::vector<Polygon2> outside;
        const Polygon2 inside = split_by_convex(cell, cutter, 0.0, outside);
        double outside_area = 0.0;
        for (const Polygon2& o : outside) outside_area += twice_area(o) / 2;
        EXPECT_NEAR(twice_area(inside) / 2, 2.0, kAreaTolerance);
        EXPECT_NEAR(outside_area, 14.0, kAreaTolerance);
        EXPECT_NEAR(twice_area(clip_convex(cell, cutter)) / 2, 2.0, kAreaTolerance);
    }
    // A cutter that is one point repeated has no inside: the whole cell is outside.
    std::vector<Polygon2> outside;
    EXPECT_TRUE(split_by_convex(cell, Polygon2{{1, 1}, {1, 1}, {1, 1}}, 0.0, outside).empty());
    ASSERT_EQ(outside.size(), 1u);
    EXPECT_NEAR(twice_area(outside[0]) / 2, 16.0, kAreaTolerance);
    EXPECT_TRUE(clip_convex(cell, Polygon2{{1, 1}, {1, 1}, {1, 1}}).empty());
}

TEST(Shadows, ParallelLightCastsTheProjectedSquare) {
    World w = shadow_world();
    Light sun;
    sun.direction = {1, -1, 0};  // shifted by +1 in x, still area 1
    sun.intensity = 1.0;
    sun.shadows = true;
    w.lights.push_back(sun);
    Staged s = stage_all(w, 64, 64);
    const double lit = 0.5 * (0.25 + std::sqrt(0.5)), dark = 0.5 * 0.25;
    EXPECT_NEAR(cells_area(s.cells[0], dark, true), 1.0, kAreaTolerance);
    EXPECT_NEAR(cells_area(s.cells[0], lit, true), 15.0, kAreaTolerance);
    for (const Cell& c : s.cells[0]) {
        if (c.shadowed) EXPECT_EQ(c.role, ShapeRole::kShadow);
    }
}

TEST(Shadows, PointLightScalesTheShadowByItsHeight) {
    World w = shadow_world();
    Light bulb;
    bulb.type = LightType::kPoint;
    bulb.position = {0, 2, 0};  // at twice the roof's height: the shadow is the square x2
    bulb.intensity = 4.0;
    bulb.shadows = true;
    w.lights.push_back(bulb);
    Staged s = stage_all(w, 64, 64);
    double shadowed = 0.0;
    for (const Cell& c : s.cells[0]) {
        if (c.shadowed) shadowed += 0.5 * std::abs(twice_area(c.loop));
    }
    EXPECT_NEAR(shadowed, 4.0, kAreaTolerance);
}

TEST(Shadows, TwoLightsGiveEachRegionTheLightsThatReachIt) {
    World w = shadow_world();
    Light a;
    a.direction = {0, -1, 0};
    a.intensity = 0.5;
    a.shadows = true;
    Light b;
    b.direction = {1, -1, 0};
    b.intensity = 0.3;
    b.shadows = true;
    w.lights = {a, b};
    Staged s = stage_all(w, 64, 64);
    const double cb = std::sqrt(0.5);
    // Shadow of a: [-0.5, 0.5] x [-0.5, 0.5]; of b: [0.5, 1.5] x [-0.5, 0.5]: disjoint, each 1.
    EXPECT_NEAR(cells_area(s.cells[0], 0.5 * (0.25 + 0.3 * cb), true), 1.0, kAreaTolerance);
    EXPECT_NEAR(cells_area(s.cells[0], 0.5 * (0.25 + 0.5), true), 1.0, kAreaTolerance);
    EXPECT_NEAR(cells_area(s.cells[0], 0.5 * (0.25 + 0.5 + 0.3 * cb), true), 14.0, kAreaTolerance);
}

TEST(Patterns, APatternInShadowKeepsItsReflectance) {
    World w = shadow_world();
    FacePattern p;  // the left half of the floor, dark
    p.loop = {{-2, 0, 2}, {0, 0, 2}, {0, 0, -2}, {-2, 0, -2}};
    p.reflectance = 0.2;  // lit 0.25, in shadow 0.05: no value shared with the bare floor
    w.objects[0].faces[0].patterns.push_back(p);
    Light sun;
    sun.direction = {0, -1, 0};
    sun.intensity = 1.0;
    sun.shadows = true;
    w.lights.push_back(sun);
    Staged s = stage_all(w, 64, 64);
    // The shadow [-0.5, 0.5]^2 straddles the pattern's edge x = 0: half on the pattern.
    EXPECT_NEAR(cells_area(s.cells[0], 0.2 * 0.25, true), 0.5, kAreaTolerance);
    EXPECT_NEAR(cells_area(s.cells[0], 0.5 * 0.25, true), 0.5, kAreaTolerance);
    EXPECT_NEAR(cells_area(s.cells[0], 0.2 * 1.25, true), 7.5, kAreaTolerance);
    EXPECT_NEAR(cells_area(s.cells[0], 0.5 * 1.25, true), 7.5, kAreaTolerance);
    EXPECT_NEAR(cells_area(s.cells[0], 0, false), 16.0, kAreaTolerance);
}

// Past 4,096 faces a parallel light's casters come from a grid in the light's view
// (harness/world/stages.cpp, find_shadows): the same shadows, in the same order, as trying
// every face against every lit receiver. 4,200 small seeded triangles above a floor.
TEST(Shadows, TheLightViewGridFindsWhatEveryPairFindsInTheSameOrder) {
    World w = camera_world({0.3, 6, 7}, {0, 0.5, 0}, 50.0);
    w.objects.push_back(quad("floor", {-4, 0, 4}, {4, 0, 4}, {4, 0, -4}, {-4, 0, -4}, 0.6));
    Object leaves;
    leaves.name = "leaves";
    leaves.closed = false;
    std::uint64_t state = 12345;
    const auto next = [&] {  // SplitMix64's step: the same on every platform
        state += 0x9e3779b97f4a7c15ull;
        std::uint64_t z = state;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
    };
    constexpr int kTriangles = 4200;
    for (int t = 0; t < kTriangles; ++t) {
        const glm::dvec3 c(6 * next() - 3, 0.2 + 2 * next(), 6 * next() - 3);
        const int base = static_cast<int>(leaves.vertices.size());
        for (int k = 0; k < 3; ++k) {
            leaves.vertices.push_back(c +
                                      0.15 * glm::dvec3(next() - 0.5, next() - 0.5, next() - 0.5));
        }
        Face f;
        f.loop = {base, base + 1, base + 2};
        leaves.faces.push_back(f);
    }
    w.objects.push_back(leaves);
    Light sun;
    sun.direction = {-0.4, -1.0, -0.3};
    sun.shadows = true;
    w.lights.push_back(sun);
    const ViewSetup view = ViewSetup::from(w.camera, 64, 48);
    std::vector<WorldFace> faces = collect_faces(w, view);
    ASSERT_GT(faces.size(), 4096u);
    const ShadowsByFace gridded = find_shadows(w, faces);
    std::size_t shadows = 0;
    for (std::size_t r = 0; r < faces.size(); ++r) {
        std::vector<Polygon2> every_pair;
        if (faces[r].visible && face_is_lit(sun, faces[r])) {
            for (std::size_t c = 0; c < faces.size(); ++c) {
                if (c == r) continue;
                Polygon2 p = shadow_on_face(sun, faces[c], faces[r]);
                if (!p.empty()) every_pair.push_back(std::move(p));
            }
        }
        ASSERT_EQ(gridded[r].size(), every_pair.size()) << "face " << r;
        for (std::size_t k = 0; k < every_pair.size(); ++k) {
            EXPECT_EQ(gridded[r][k].polygon, every_pair[k]) << "face " << r << " shadow " << k;
        }
        shadows += every_pair.size();
    }
    EXPECT_GT(shadows, 1000u);  // the floor and the triangles under others do receive shadows
}

}  // namespace
}  // namespace aabench
