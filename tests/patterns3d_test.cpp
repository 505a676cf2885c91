// The 3-D patterns: pure functions of their parameters, recorded in metadata, and worlds that
// keep the scene format's promises (check_world: planar convex faces, indices in range,
// patterns in their faces' planes; closed objects turned outward) with the objects in view,
// off the pixel grid, and each showing what its file says it provokes (boxes through each
// other, bars in a cycle, boxes hiding and shadowing boxes, the block's shadows in the room,
// thin mat borders, a grazing view of the terrain).
//
// Projection, ray casting and the convex solids here are written from the camera conventions
// (world.h) with glm::lookAt, sharing no code with the generators' project_point or with
// harness/world/, so they check the patterns rather than repeat them.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

// Vertices are built from a handful of double operations on coordinates of size ~1-10:
// planarity holds to ~1e-15 relative; 1e-9 of the face's extent is the format's own bound
// (patterns/scene/world_check.cpp) and far above that rounding.
constexpr double kPlaneRelative = 1e-9;
// project_point and the projection written here differ only by rounding of a few operations
// on coordinates ~1e2 px: 1e-9 px is a million times that and far below anything visible.
constexpr double kProjectionPx = 1e-9;
// An edge whose ends lie within this of one pixel line is pixel-aligned for every method:
// float32 coverage cannot tell 1e-6 px from 0.
constexpr double kAlignedPx = 1e-6;
// A segment counts as passing through a solid when it runs inside it for more than this share
// of its length: clear of the rounding (~1e-15) of points that lie on the solid's surface.
constexpr double kInsideShare = 1e-9;
// Beyond everything in the scenes (they span ~10 world units): a parallel light's shadow test
// runs the segment this far toward the light.
constexpr double kFarWorld = 1000.0;
// The room's mat borders are "a few px wide or less at 256 x 256": where in view, no border is
// wider than 5 px (the default's widest, nearest the eye, is 4.3 px).
constexpr double kMaxBorderPx = 5.0;
// "Grazing": the terrain's view direction within 20 degrees of horizontal, so far faces are
// foreshortened to sin(20 deg) = 0.34 of their width or less.
constexpr double kGrazingDeg = 20.0;

const std::vector<std::string> k3dPatterns = {"room",    "colour-room", "blocks",
                                              "interpenetrate", "mesh", "terrain", "torus",
                                              "checkerboard", "terrain-edges", "mirror",
                                              "foliage"};

// ---- Geometry written from the conventions, independent of the generators ----

struct Screen {
    glm::dmat4 view;
    double f;
    int width, height;
    Screen(const Camera& c, int w, int h)
        : view(glm::lookAt(c.eye, c.target, c.up)),
          f(0.5 * h / std::tan(0.5 * glm::radians(c.fov_y_deg))),
          width(w),
          height(h) {}
    double depth(glm::dvec3 p) const { return -(view * glm::dvec4(p, 1.0)).z; }  // z_v
    // world.h: x = W/2 + f x_v / z_v, y = H/2 - f y_v / z_v (lookAt looks down -z).
    glm::dvec2 project(glm::dvec3 p) const {
        const glm::dvec4 q = view * glm::dvec4(p, 1.0);
        return {0.5 * width + f * q.x / -q.z, 0.5 * height - f * q.y / -q.z};
    }
    // The world direction of the view ray through pixel-frame point s.
    glm::dvec3 ray(glm::dvec2 s) const {
        const glm::dvec3 v((s.x - 0.5 * width) / f, -(s.y - 0.5 * height) / f, -1.0);
        return glm::transpose(glm::dmat3(view)) * v;  // the rotation's inverse
    }
    bool inside(glm::dvec2 s) const {
        return s.x >= 0 && s.x <= width && s.y >= 0 && s.y <= height;
    }
};

double extent(const std::vector<glm::dvec3>& pts) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const auto& p : pts) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return glm::length(hi - lo);
}

std::vector<glm::dvec3> face_points(const Object& o, const Face& f) {
    std::vector<glm::dvec3> loop;
    for (int i : f.loop) loop.push_back(o.vertices.at(i));
    return loop;
}

const Object& object_named(const World& w, const std::string& name) {
    for (const Object& o : w.objects) {
        if (o.name == name) return o;
    }
    throw std::runtime_error("no object " + name);
}

// The part of segment a -> b inside a closed convex object (the intersection of its faces'
// inner half-spaces), as a share of the segment's length (Cyrus-Beck clipping).
double share_inside(const Object& solid, glm::dvec3 a, glm::dvec3 b) {
    double t0 = 0.0, t1 = 1.0;
    for (const Face& f : solid.faces) {
        const glm::dvec3 n = face_normal(solid, f), v = solid.vertices[f.loop[0]];
        const double d0 = glm::dot(n, a - v), dd = glm::dot(n, b - a);
        if (dd == 0.0) {
            if (d0 > 0.0) return 0.0;
        } else if (dd > 0.0) {
            t1 = std::min(t1, -d0 / dd);
        } else {
            t0 = std::max(t0, -d0 / dd);
        }
    }
    return std::max(0.0, t1 - t0);
}

// Points spread over a convex face: from its centroid toward each vertex and edge midpoint.
std::vector<glm::dvec3> samples_on(const std::vector<glm::dvec3>& loop) {
    glm::dvec3 c(0.0);
    for (const auto& p : loop) c += p;
    c /= static_cast<double>(loop.size());
    std::vector<glm::dvec3> out = {c};
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const glm::dvec3 mid = 0.5 * (loop[i] + loop[(i + 1) % loop.size()]);
        for (double s : {0.3, 0.6, 0.9}) {
            out.push_back(c + s * (loop[i] - c));
            out.push_back(c + s * (mid - c));
        }
    }
    return out;
}

// Where the light comes from, seen from p: a point light's position, or far up a parallel
// light's beam.
glm::dvec3 light_source(const Light& l, glm::dvec3 p) {
    return l.type == LightType::kPoint ? l.position : p - kFarWorld * glm::normalize(l.direction);
}

// Some point of `receiver`'s faces that are turned toward the light lies in `caster`'s shadow.
bool shadows(const Light& light, const Object& caster, const Object& receiver) {
    for (const Face& f : receiver.faces) {
        const std::vector<glm::dvec3> loop = face_points(receiver, f);
        const glm::dvec3 n = face_normal(receiver, f);
        for (const glm::dvec3& p : samples_on(loop)) {
            const glm::dvec3 src = light_source(light, p);
            // A two-sided face is lit on either side; a closed one only on its outer side.
            const double facing = glm::dot(n, src - p);
            if (receiver.closed && !(facing > 0.0)) continue;
            if (share_inside(caster, p, src) > kInsideShare) return true;
        }
    }
    return false;
}

// The narrowest and widest screen width of a thin rectangle (a rect_pattern loop) over the
// part of it in view: at points along one long side, the distance of the matching point on the
// other long side from the first side's projected line (a straight line projects straight).
std::pair<double, double> border_width_px(const Screen& screen,
                                          const std::vector<glm::dvec3>& loop) {
    // Loop: origin + s0 u + t0 v, s1 t0, s1 t1, s0 t1; sides 0-1 and 3-2 run along u.
    const bool along_u = glm::length(loop[1] - loop[0]) > glm::length(loop[3] - loop[0]);
    const glm::dvec3 a0 = loop[0], a1 = along_u ? loop[1] : loop[3];
    const glm::dvec3 b0 = along_u ? loop[3] : loop[1], b1 = loop[2];
    const glm::dvec2 pa0 = screen.project(a0), pa1 = screen.project(a1);
    const glm::dvec2 dir = glm::normalize(pa1 - pa0);
    double lo = INFINITY, hi = 0.0;
    constexpr int kSteps = 200;
    for (int i = 0; i <= kSteps; ++i) {
        const double s = static_cast<double>(i) / kSteps;
        const glm::dvec3 a = a0 + s * (a1 - a0), b = b0 + s * (b1 - b0);
        if (!(screen.depth(a) > 0.0 && screen.depth(b) > 0.0)) continue;
        const glm::dvec2 pa = screen.project(a), pb = screen.project(b);
        if (!screen.inside(pa)) continue;
        const glm::dvec2 d = pb - pa0;
        const double across = std::abs(d.x * dir.y - d.y * dir.x);
        lo = std::min(lo, across);
        hi = std::max(hi, across);
    }
    return {lo, hi};
}

// All the specs the geometry tests run: defaults, and each parameter alone at its min and max.
std::vector<std::string> specs_to_check() {
    std::vector<std::string> specs;
    for (const std::string& id : k3dPatterns) {
        specs.push_back(id);
        for (const ParamSpec& p : resolve_pattern(id).info->params) {
            if (p.kind == ParamKind::kChoice) {
                for (const std::string& c : p.choices) {
                    specs.push_back(fmt::format("{}:{}={}", id, p.name, c));
                }
                continue;
            }
            for (double v : {p.min_value, p.max_value}) {
                specs.push_back(fmt::format("{}:{}={}", id, p.name, format_real(v)));
            }
        }
    }
    return specs;
}

// ---- The tests ----

TEST(Patterns3d, TheRegistrysWorldPatternsAreTheseEleven) {
    std::vector<std::string> ids;
    for (const PatternInfo& info : pattern_registry()) {
        if (info.model_file) continue;  // tests/mesh_patterns_test.cpp
        if (make_pattern(info.id, 8, 8).world) ids.push_back(info.id);
    }
    EXPECT_EQ(ids, k3dPatterns);
}

TEST(Patterns3d, AreDeterministicAndRecordIdEveryParameterAndSize) {
    for (const std::string& id : k3dPatterns) {
        const Scene a = make_pattern(id, 64, 48), b = make_pattern(id, 64, 48);
        EXPECT_TRUE(a == b) << id;
        ASSERT_TRUE(a.world.has_value()) << id;
        EXPECT_TRUE(a.shapes.empty()) << id;
        EXPECT_EQ(a.width, 64) << id;
        EXPECT_EQ(a.height, 48) << id;
        // The edge patterns sit on light paper so that their black lines show (torus.cpp).
        const bool paper = id == "torus" || id == "terrain-edges" || id == "mirror";
        // The checkerboard's sky is grey, so that the horizon shows against both colours.
        EXPECT_EQ(a.background, paper ? 0.9 : id == "checkerboard" ? 0.3 : 0.0) << id;
        // A non-default value of every parameter (its max) is what the metadata records.
        std::vector<std::string> given;
        for (const ParamSpec& p : resolve_pattern(id).info->params) {
            given.push_back(fmt::format("{}={}", p.name,
                                        p.kind == ParamKind::kChoice ? p.choices.back()
                                                                     : format_real(p.max_value)));
        }
        const PatternInstance inst =
            resolve_pattern(given.empty() ? id : fmt::format("{}:{}", id, fmt::join(given, ",")));
        const Scene scene = make_pattern(inst.spec, 40, 30);
        std::vector<std::pair<std::string, std::string>> expected = {{"pattern", id}};
        for (const auto& item : inst.params.items()) expected.push_back(item);
        expected.emplace_back("size", "40x30");
        ASSERT_GT(scene.metadata.size(), expected.size()) << id;
        for (std::size_t i = 0; i < expected.size(); ++i) {
            EXPECT_EQ(scene.metadata[i], expected[i]) << id << " metadata " << i;
        }
        for (const ParamSpec& p : inst.info->params) {
            EXPECT_EQ(scene.metadata[1 + (&p - inst.info->params.data())].second,
                      p.kind == ParamKind::kChoice ? p.choices.back() : format_real(p.max_value))
                << id << " " << p.name;
        }
        // The focus region: whole pixels inside the image.
        const auto& [key, value] = scene.metadata[expected.size()];
        EXPECT_EQ(key, "focus") << id;
        int x = -1, y = -1, w = -1, h = -1;
        ASSERT_EQ(std::sscanf(value.c_str(), "%d,%d,%d,%d", &x, &y, &w, &h), 4) << value;
        EXPECT_TRUE(x >= 0 && y >= 0 && w > 0 && h > 0 && x + w <= 40 && y + h <= 30) << value;
    }
}

TEST(Patterns3d, WorldsPassCheckWorldAndClosedObjectsTurnOutward) {
    for (const std::string& spec : specs_to_check()) {
        const Scene scene = make_pattern(spec, 64, 48);
        EXPECT_NO_THROW(check_world(*scene.world, spec)) << spec;
        for (const Object& o : scene.world->objects) {
            ASSERT_FALSE(o.faces.empty()) << spec << " " << o.name;
            glm::dvec3 centre(0.0);
            for (const auto& v : o.vertices) centre += v;
            centre /= static_cast<double>(o.vertices.size());
            for (std::size_t f = 0; f < o.faces.size(); ++f) {
                const std::vector<glm::dvec3> loop = face_points(o, o.faces[f]);
                const glm::dvec3 n = face_normal(o, o.faces[f]);
                const std::string what = fmt::format("{} {} face {}", spec, o.name, f);
                // Planar and convex, counted here too: every turn the same way about n.
                for (const auto& p : loop) {
                    EXPECT_LE(std::abs(glm::dot(n, p - loop[0])), kPlaneRelative * extent(loop))
                        << what;
                }
                for (std::size_t i = 0; i < loop.size(); ++i) {
                    const glm::dvec3 a = loop[i], b = loop[(i + 1) % loop.size()],
                                     c = loop[(i + 2) % loop.size()];
                    EXPECT_GT(glm::dot(glm::cross(b - a, c - b), n), 0.0) << what << " turn " << i;
                }
                // Closed objects here are convex (boxes, the sphere): outward means away from
                // the centroid. The torus is not: outward is away from the tube's centre
                // line, the circle of its mean horizontal radius about the centroid.
                if (o.closed && o.name != "torus") {
                    EXPECT_GT(glm::dot(n, loop[0] - centre), 0.0) << what;
                } else if (o.closed) {
                    double ring = 0.0;
                    for (const auto& v : o.vertices) {
                        ring += glm::length(glm::dvec2(v.x - centre.x, v.z - centre.z));
                    }
                    ring /= static_cast<double>(o.vertices.size());
                    glm::dvec3 mid(0.0);
                    for (const auto& p : loop) mid += p;
                    mid /= static_cast<double>(loop.size());
                    const glm::dvec2 out = glm::normalize(glm::dvec2(mid.x - centre.x, mid.z - centre.z));
                    const glm::dvec3 axis = centre + ring * glm::dvec3(out.x, 0.0, out.y);
                    EXPECT_GT(glm::dot(n, mid - axis), 0.0) << what;
                }
            }
        }
    }
}

TEST(Patterns3d, EveryObjectIsInViewAndProjectPointAgrees) {
    for (const std::string& spec : specs_to_check()) {
        const Scene scene = make_pattern(spec, 96, 64);
        const Camera& cam = scene.world->camera;
        const Screen screen(cam, 96, 64);
        // The target lands at the image centre.
        const glm::dvec2 centre = screen.project(cam.target);
        EXPECT_NEAR(centre.x, 48.0, kProjectionPx) << spec;
        EXPECT_NEAR(centre.y, 32.0, kProjectionPx) << spec;
        for (const Object& o : scene.world->objects) {
            int seen = 0;
            for (const auto& v : o.vertices) {
                if (!(screen.depth(v) > cam.near)) continue;
                const glm::dvec2 p = screen.project(v);
                const glm::dvec2 q = project_point(cam, 96, 64, v);
                EXPECT_NEAR(p.x, q.x, kProjectionPx) << spec;
                EXPECT_NEAR(p.y, q.y, kProjectionPx) << spec;
                seen += screen.inside(p);
            }
            EXPECT_GT(seen, 0) << spec << ": " << o.name << " is out of view";
        }
    }
}

TEST(Patterns3d, ProjectionPutsUpUpAndRightRight) {
    // Independent of lookAt: a point above the target (world up) lands higher in the image
    // (smaller y), a point to the right of the view (forward x up) lands to the right.
    Camera cam;
    cam.eye = {0.3, 1.1, 4.0};
    cam.target = {0.0, 0.2, 0.0};
    const glm::dvec3 forward = glm::normalize(cam.target - cam.eye);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, cam.up));
    const glm::dvec2 c = project_point(cam, 64, 64, cam.target);
    EXPECT_LT(project_point(cam, 64, 64, cam.target + 0.1 * cam.up).y, c.y);
    EXPECT_GT(project_point(cam, 64, 64, cam.target + 0.1 * right).x, c.x);
    // f = (H/2)/tan(fov/2): the point at the top edge of the field of view lands on row 0.
    const double half = 0.5 * glm::radians(cam.fov_y_deg);
    const glm::dvec3 up_view = glm::cross(right, forward);
    const glm::dvec3 top = cam.eye + forward + std::tan(half) * up_view;
    EXPECT_NEAR(project_point(cam, 64, 64, top).y, 0.0, kProjectionPx);
}

TEST(Patterns3d, NoEdgeIsPixelAlignedByDefault) {
    for (const std::string& id : k3dPatterns) {
        for (const auto& [w, h] : {std::pair{256, 256}, std::pair{64, 48}}) {
            const Scene scene = make_pattern(id, w, h);
            const Screen screen(scene.world->camera, w, h);
            const auto aligned = [&](glm::dvec3 a, glm::dvec3 b) {
                if (!(screen.depth(a) > 0.0 && screen.depth(b) > 0.0)) return false;
                const glm::dvec2 p = screen.project(a), q = screen.project(b);
                const auto on_line = [](double u, double v) {
                    return std::abs(u - std::round(u)) <= kAlignedPx &&
                           std::abs(v - std::round(u)) <= kAlignedPx;
                };
                return on_line(p.x, q.x) || on_line(p.y, q.y);
            };
            int count = 0;
            for (const Object& o : scene.world->objects) {
                for (const Face& f : o.faces) {
                    std::vector<std::vector<glm::dvec3>> loops = {face_points(o, f)};
                    for (const FacePattern& pat : f.patterns) loops.push_back(pat.loop);
                    for (const auto& loop : loops) {
                        for (std::size_t i = 0; i < loop.size(); ++i) {
                            count += aligned(loop[i], loop[(i + 1) % loop.size()]);
                        }
                    }
                }
            }
            EXPECT_EQ(count, 0) << id << " at " << w << "x" << h << ": pixel-aligned edges";
        }
    }
}

TEST(Patterns3d, FaceCountsFollowTheirParameters) {
    EXPECT_EQ(make_pattern("mesh", 32, 32).world->face_count(), 1280u);  // 20 * 4^3
    EXPECT_EQ(make_pattern("mesh:subdivisions=0", 32, 32).world->face_count(), 20u);
    EXPECT_EQ(make_pattern("mesh:subdivisions=1", 32, 32).world->face_count(), 80u);
    EXPECT_EQ(make_pattern("terrain", 32, 32).world->face_count(), 2u * 24 * 24);
    EXPECT_EQ(make_pattern("terrain:cells=5", 32, 32).world->face_count(), 50u);
    EXPECT_EQ(make_pattern("blocks:count=2", 32, 32).world->objects.size(), 3u);
    EXPECT_EQ(make_pattern("blocks", 32, 32).world->objects.size(), 5u);  // ground + 4
    // Mats: 2 (mats + 1) border strips; windows: two walls.
    const World room = *make_pattern("room:mats=4,windows=3", 32, 32).world;
    EXPECT_EQ(object_named(room, "floor").faces[0].patterns.size(), 10u);
    EXPECT_EQ(object_named(room, "back wall").faces[0].patterns.size(), 3u);
    EXPECT_EQ(object_named(room, "left wall").faces[0].patterns.size(), 3u);
}

TEST(Patterns3d, MeshIsOneClosedObjectSharingEveryEdge) {
    for (const char* spec : {"mesh", "mesh:subdivisions=0", "mesh:subdivisions=2"}) {
        const World w = *make_pattern(spec, 32, 32).world;
        ASSERT_EQ(w.objects.size(), 1u) << spec;
        EXPECT_TRUE(w.objects[0].closed) << spec;
        ASSERT_EQ(w.lights.size(), 1u) << spec;
        EXPECT_EQ(w.lights[0].type, LightType::kParallel) << spec;
        // A shared-edge mesh: every edge of the closed sphere belongs to exactly two faces,
        // once in each direction (both faces counter-clockwise from outside).
        std::map<std::pair<int, int>, int> directed;
        for (const Face& f : w.objects[0].faces) {
            for (std::size_t i = 0; i < f.loop.size(); ++i) {
                ++directed[{f.loop[i], f.loop[(i + 1) % f.loop.size()]}];
            }
        }
        for (const auto& [e, count] : directed) {
            EXPECT_EQ(count, 1) << spec << " edge " << e.first << "-" << e.second;
            EXPECT_EQ(directed.count({e.second, e.first}), 1u)
                << spec << " edge " << e.first << "-" << e.second << " has one face";
        }
    }
}

TEST(Patterns3d, TerrainIsAnOpenHeightFieldSeenAtAGrazingAngle) {
    const World w = *make_pattern("terrain", 32, 32).world;
    ASSERT_EQ(w.objects.size(), 1u);
    EXPECT_FALSE(w.objects[0].closed);
    ASSERT_EQ(w.lights.size(), 1u);
    EXPECT_EQ(w.lights[0].type, LightType::kParallel);
    const glm::dvec3 view = glm::normalize(w.camera.target - w.camera.eye);
    EXPECT_LT(std::abs(glm::degrees(std::asin(view.y))), kGrazingDeg);
    // Hills, not a plane: the heights vary, and they scale with `height`.
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& v : w.objects[0].vertices) lo = std::min(lo, v.y), hi = std::max(hi, v.y);
    EXPECT_GT(hi - lo, 0.5 * 0.9);
    const World flat = *make_pattern("terrain:height=0", 32, 32).world;
    for (const auto& v : flat.objects[0].vertices) EXPECT_EQ(v.y, 0.0);
}

TEST(Patterns3d, InterpenetrateBoxesPassThroughEachOther) {
    const World w = *make_pattern("interpenetrate", 64, 64).world;
    EXPECT_TRUE(w.lights.empty());
    const Object& a = object_named(w, "box a");
    const Object& b = object_named(w, "box b");
    // Each box has corners inside and outside the other: their surfaces cross.
    for (const auto& [x, y] : {std::pair{&a, &b}, std::pair{&b, &a}}) {
        int inside = 0;
        for (const glm::dvec3& v : x->vertices) {
            bool in = true;
            for (const Face& f : y->faces) {
                in &= glm::dot(face_normal(*y, f), v - y->vertices[f.loop[0]]) < 0.0;
            }
            inside += in;
        }
        EXPECT_GT(inside, 0) << x->name << " has no corner inside " << y->name;
        EXPECT_LT(inside, 8) << x->name << " lies inside " << y->name;
    }
    // Every object has its own reflectance (no lights: the value is the reflectance).
    std::vector<double> seen;
    for (const Object& o : w.objects) {
        for (double r : seen) EXPECT_NE(o.faces[0].reflectance, r) << o.name;
        seen.push_back(o.faces[0].reflectance);
    }
}

TEST(Patterns3d, InterpenetrateBarsOverlapInACycle) {
    for (const char* spec : {"interpenetrate", "interpenetrate:bar_width=0.005"}) {
        const World w = *make_pattern(spec, 256, 256).world;
        const Screen screen(w.camera, 256, 256);
        const Object* bars[3];
        for (int k = 0; k < 3; ++k) bars[k] = &object_named(w, fmt::format("bar {}", k));
        // Centre line of a bar (quad p-across, q-across, q+across, p+across) on the screen.
        const auto centre_line = [&](const Object& o) {
            return std::pair{screen.project(0.5 * (o.vertices[0] + o.vertices[3])),
                             screen.project(0.5 * (o.vertices[1] + o.vertices[2]))};
        };
        // Depth along the view ray through s to the plane of a bar.
        const auto ray_depth = [&](const Object& o, glm::dvec2 s) {
            const glm::dvec3 d = screen.ray(s), n = face_normal(o, o.faces[0]);
            return glm::dot(n, o.vertices[0] - w.camera.eye) / glm::dot(n, d);
        };
        int over_next = 0;  // crossings where bar k is nearer than bar k+1
        for (int k = 0; k < 3; ++k) {
            const Object& u = *bars[k];
            const Object& v = *bars[(k + 1) % 3];
            const auto [p0, p1] = centre_line(u);
            const auto [q0, q1] = centre_line(v);
            // Intersect the two screen segments: p0 + s (p1 - p0) = q0 + t (q1 - q0).
            const glm::dvec2 r = p1 - p0, e = q1 - q0, g = q0 - p0;
            const double den = r.x * e.y - r.y * e.x;
            ASSERT_NE(den, 0.0) << spec;
            const double s = (g.x * e.y - g.y * e.x) / den, t = (g.x * r.y - g.y * r.x) / den;
            ASSERT_TRUE(s > 0 && s < 1 && t > 0 && t < 1)
                << spec << ": bars " << k << " and " << (k + 1) % 3 << " do not cross";
            const glm::dvec2 x = p0 + s * r;
            EXPECT_TRUE(screen.inside(x)) << spec << " crossing " << k;
            const double du = ray_depth(u, x), dv = ray_depth(v, x);
            ASSERT_GT(du, 0.0);
            ASSERT_GT(dv, 0.0);
            EXPECT_NE(du, dv) << spec << " crossing " << k;
            over_next += du < dv;
        }
        // A cycle: at every crossing the same way round (A over B over C over A), so no
        // back-to-front order of the three exists.
        EXPECT_TRUE(over_next == 0 || over_next == 3) << spec << ": " << over_next;
    }
}

TEST(Patterns3d, BlocksHideAndShadowEachOtherWithoutTouching) {
    for (const char* spec : {"blocks", "blocks:count=3", "blocks:count=8"}) {
        const World w = *make_pattern(spec, 256, 256).world;
        std::vector<const Object*> boxes;
        for (const Object& o : w.objects) {
            if (o.closed) boxes.push_back(&o);
        }
        ASSERT_GE(boxes.size(), 3u) << spec;
        // Standing on the ground, not through each other: no edge of one runs inside another.
        for (const Object* x : boxes) {
            double bottom = INFINITY;
            for (const auto& v : x->vertices) bottom = std::min(bottom, v.y);
            EXPECT_EQ(bottom, 0.0) << spec << ": " << x->name << " does not stand on the ground";
            for (const Object* y : boxes) {
                if (x == y) continue;
                for (const Face& f : x->faces) {
                    const auto loop = face_points(*x, f);
                    for (std::size_t i = 0; i < loop.size(); ++i) {
                        EXPECT_LE(share_inside(*y, loop[i], loop[(i + 1) % loop.size()]),
                                  kInsideShare)
                            << spec << ": " << x->name << " runs into " << y->name;
                    }
                }
            }
        }
        // Each box hides part of the next one along the row: a point on the next box's faces
        // whose view ray passes through this box.
        for (std::size_t k = 0; k + 1 < boxes.size(); ++k) {
            bool hidden = false;
            for (const Face& f : boxes[k + 1]->faces) {
                for (const glm::dvec3& p : samples_on(face_points(*boxes[k + 1], f))) {
                    hidden |= share_inside(*boxes[k], w.camera.eye, p) > kInsideShare;
                }
            }
            EXPECT_TRUE(hidden) << spec << ": " << boxes[k]->name << " hides nothing of "
                                << boxes[k + 1]->name;
        }
        // Every light casts shadows, and each throws one box's shadow onto another box.
        ASSERT_EQ(w.lights.size(), 2u);
        for (const Light& l : w.lights) {
            EXPECT_TRUE(l.shadows);
            bool across = false;
            for (const Object* x : boxes) {
                for (const Object* y : boxes) across |= x != y && shadows(l, *x, *y);
            }
            EXPECT_TRUE(across) << spec << ": a light throws no box's shadow onto another box";
        }
    }
}

TEST(Patterns3d, RoomHasTwoShadowingLightsThinBordersAndWindows) {
    const World w = *make_pattern("room", 256, 256).world;
    EXPECT_EQ(w.ambient, 0.2);
    ASSERT_EQ(w.lights.size(), 2u);
    EXPECT_EQ(w.lights[0].type, LightType::kParallel);
    EXPECT_EQ(w.lights[1].type, LightType::kPoint);
    const Object& floor = object_named(w, "floor");
    const Object& block = object_named(w, "block");
    EXPECT_FALSE(floor.closed);
    EXPECT_TRUE(block.closed);
    for (const Light& l : w.lights) {
        EXPECT_TRUE(l.shadows);
        EXPECT_TRUE(shadows(l, block, floor)) << "the block throws no shadow on the floor";
    }
    // Mat borders: thin dark strips, darker than the floor, at most a few px wide where they
    // are in view at 256 x 256, and somewhere under a pixel (where point sampling loses them).
    const Screen screen(w.camera, 256, 256);
    ASSERT_FALSE(floor.faces[0].patterns.empty());
    double widest = 0.0, narrowest = INFINITY;
    for (const FacePattern& p : floor.faces[0].patterns) {
        EXPECT_LT(p.reflectance, floor.faces[0].reflectance);
        const auto [lo, hi] = border_width_px(screen, p.loop);
        narrowest = std::min(narrowest, lo);
        widest = std::max(widest, hi);
    }
    EXPECT_LT(narrowest, 1.0);
    EXPECT_LT(widest, kMaxBorderPx);
    // Windows: brighter than their wall, on both walls.
    for (const char* name : {"back wall", "left wall"}) {
        const Face& wall = object_named(w, name).faces[0];
        ASSERT_EQ(wall.patterns.size(), 2u) << name;
        for (const FacePattern& p : wall.patterns) EXPECT_GT(p.reflectance, wall.reflectance);
    }
}

// The checkerboard: one face, its dark squares as patterns (alternating, each a square of
// `size`), the horizon in view, and squares out of view left out (none of them can reach the
// image: every corner beyond one side of the view).
TEST(Patterns3d, CheckerboardIsOneFaceOfSquarePatternsRecedingToTheHorizon) {
    for (const char* spec : {"checkerboard", "checkerboard:squares=200,pitch=3",
                             "checkerboard:square=0.25,height=0.4"}) {
        const Scene scene = make_pattern(spec, 96, 64);
        const World& w = *scene.world;
        ASSERT_EQ(w.objects.size(), 1u) << spec;
        ASSERT_EQ(w.objects[0].faces.size(), 1u) << spec;
        EXPECT_TRUE(w.lights.empty()) << spec;
        const Face& floor = w.objects[0].faces[0];
        const PatternInstance inst = resolve_pattern(spec);
        const double size = inst.params.get_real("square");
        const int n = inst.params.get_int("squares");
        const Screen screen(w.camera, 96, 64);
        std::size_t in_image = 0;
        for (const FacePattern& p : floor.patterns) {
            EXPECT_LT(p.reflectance, floor.reflectance) << spec;
            ASSERT_EQ(p.loop.size(), 4u) << spec;
            EXPECT_NEAR(glm::length(p.loop[1] - p.loop[0]), size, kPlaneRelative * size);
            EXPECT_NEAR(glm::length(p.loop[2] - p.loop[1]), size, kPlaneRelative * size);
            // Dark squares alternate: (column + row) odd, counted from the floor's corner.
            double x_min = INFINITY, z_max = -INFINITY;
            for (const glm::dvec3& v : p.loop) {
                x_min = std::min(x_min, v.x);
                z_max = std::max(z_max, v.z);
            }
            const long column = std::lround((x_min + 0.5 * n * size) / size);
            const long row = std::lround(-z_max / size);
            EXPECT_EQ((column + row) % 2, 1) << spec;
            bool seen = false;
            for (const glm::dvec3& v : p.loop) {
                seen |= screen.depth(v) > w.camera.near && screen.inside(screen.project(v));
            }
            in_image += seen;
        }
        // Most squares kept have a corner in the image (the rest straddle its border).
        EXPECT_GT(in_image, floor.patterns.size() / 2) << spec;
        EXPECT_LT(floor.patterns.size(), static_cast<std::size_t>(n) * n / 2 + 1) << spec;
        // The horizon (a floor point far ahead) lies inside the image: the floor recedes to it.
        const glm::dvec3 ahead = w.camera.target - w.camera.eye;
        const glm::dvec3 far_point =
            w.camera.eye + 1e6 * glm::normalize(glm::dvec3(ahead.x, 0.0, ahead.z)) -
            glm::dvec3(0.0, w.camera.eye.y, 0.0);
        const glm::dvec2 h = screen.project(far_point);
        EXPECT_TRUE(screen.inside(h)) << spec << " horizon at y " << h.y;
    }
    // A floor too large for the image is refused, naming the parameter.
    try {
        (void)make_pattern("checkerboard:squares=1536", 512, 128);
        ADD_FAILURE() << "a floor of 1536 squares in a 512 x 128 image was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("squares=1536"), std::string::npos) << e.what();
    }
}

TEST(Patterns3d, ParametersOutOfRangeAreRejected) {
    for (const std::string& id : k3dPatterns) {
        for (const ParamSpec& p : resolve_pattern(id).info->params) {
            // One below the minimum and one above the maximum: integers stay integers.
            for (double v : {p.min_value - 1.0, p.max_value + 1.0}) {
                const std::string spec = fmt::format("{}:{}={}", id, p.name, format_real(v));
                EXPECT_THROW(make_pattern(spec, 32, 32), InputError) << spec;
            }
        }
    }
    EXPECT_THROW(make_pattern("mesh:subdivisions=6", 32, 32), InputError);
    EXPECT_THROW(make_pattern("terrain:cells=0", 32, 32), InputError);
    EXPECT_THROW(make_pattern("room:mats=0", 32, 32), InputError);
    EXPECT_THROW(make_pattern("blocks:count=9", 32, 32), InputError);
    EXPECT_THROW(make_pattern("interpenetrate:bar_width=5", 32, 32), InputError);
    EXPECT_THROW(make_pattern("room:sofa=1", 32, 32), InputError);
}

}  // namespace
}  // namespace aabench
