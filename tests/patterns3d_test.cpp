// The 3-D patterns: pure functions of their parameters, recorded in metadata, and worlds that
// keep the scene format's promises (planar convex faces, indices in range, closed objects
// turned outward, patterns in their faces' planes) with the objects in view.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

// Vertices are built from a handful of double operations on coordinates of size ~1-10:
// planarity holds to ~1e-15 relative; 1e-9 of the face's extent is the format's own bound
// (patterns/scene/world_check.cpp) and far above that rounding.
constexpr double kPlaneRelative = 1e-9;

const std::vector<std::string> k3dPatterns = {"room", "blocks", "interpenetrate", "mesh",
                                              "terrain"};

double extent(const std::vector<glm::dvec3>& pts) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const auto& p : pts) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return glm::length(hi - lo);
}

// Every vertex within kPlaneRelative of the plane through the first with normal n, and every
// turn the same way about n: planar and convex.
void expect_planar_convex(const std::vector<glm::dvec3>& loop, const glm::dvec3& n,
                          const std::string& what) {
    ASSERT_GE(loop.size(), 3u) << what;
    const double tol = kPlaneRelative * extent(loop);
    for (const auto& p : loop) EXPECT_LE(std::abs(glm::dot(n, p - loop[0])), tol) << what;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const glm::dvec3 a = loop[i], b = loop[(i + 1) % loop.size()],
                         c = loop[(i + 2) % loop.size()];
        EXPECT_GT(glm::dot(glm::cross(b - a, c - b), n), 0.0) << what << " turn " << i;
    }
}

TEST(Patterns3d, AreDeterministicAndRecordTheirParameters) {
    for (const std::string& id : k3dPatterns) {
        const Scene a = make_pattern(id, 64, 48), b = make_pattern(id, 64, 48);
        EXPECT_EQ(a, b) << id;
        ASSERT_TRUE(a.world.has_value()) << id;
        EXPECT_TRUE(a.shapes.empty()) << id;
        const PatternInstance inst = resolve_pattern(id);
        ASSERT_GE(a.metadata.size(), inst.info->params.size() + 2) << id;
        EXPECT_EQ(a.metadata[0], (std::pair<std::string, std::string>{"pattern", id}));
        for (const ParamSpec& p : inst.info->params) {
            bool found = false;
            for (const auto& [k, v] : a.metadata) found |= k == p.name;
            EXPECT_TRUE(found) << id << " " << p.name;
        }
    }
}

TEST(Patterns3d, FacesArePlanarConvexAndClosedObjectsTurnOutward) {
    for (const std::string& id : k3dPatterns) {
        const Scene scene = make_pattern(id, 64, 48);
        for (const Object& o : scene.world->objects) {
            glm::dvec3 centre(0.0);
            for (const auto& v : o.vertices) centre += v;
            centre /= static_cast<double>(o.vertices.size());
            for (std::size_t f = 0; f < o.faces.size(); ++f) {
                const Face& face = o.faces[f];
                std::vector<glm::dvec3> loop;
                for (int i : face.loop) {
                    ASSERT_GE(i, 0);
                    ASSERT_LT(i, static_cast<int>(o.vertices.size()));
                    loop.push_back(o.vertices[i]);
                }
                const glm::dvec3 n = face_normal(o, face);
                const std::string what = id + " " + o.name + " face " + std::to_string(f);
                expect_planar_convex(loop, n, what);
                // Closed objects here are convex (boxes, the sphere): outward means away from
                // the centroid.
                if (o.closed) EXPECT_GT(glm::dot(n, loop[0] - centre), 0.0) << what;
                for (const FacePattern& p : face.patterns) {
                    const glm::dvec3 pn = glm::normalize(
                        glm::cross(p.loop[1] - p.loop[0], p.loop[2] - p.loop[1]));
                    EXPECT_GT(std::abs(glm::dot(pn, n)), 1.0 - 1e-12) << what << " pattern";
                    for (const auto& q : p.loop) {
                        EXPECT_LE(std::abs(glm::dot(n, q - loop[0])),
                                  kPlaneRelative * extent(loop))
                            << what << " pattern off its face's plane";
                    }
                }
            }
        }
    }
}

TEST(Patterns3d, EveryObjectIsInView) {
    for (const std::string& id : k3dPatterns) {
        const Scene scene = make_pattern(id, 96, 64);
        const Camera& cam = scene.world->camera;
        const glm::dmat4 view = glm::lookAt(cam.eye, cam.target, cam.up);
        for (const Object& o : scene.world->objects) {
            int seen = 0;
            for (const auto& v : o.vertices) {
                if (-(view * glm::dvec4(v, 1.0)).z <= cam.near) continue;
                const glm::dvec2 p = project_point(cam, 96, 64, v);
                seen += p.x >= 0 && p.x <= 96 && p.y >= 0 && p.y <= 64;
            }
            EXPECT_GT(seen, 0) << id << " " << o.name << " is out of view";
        }
    }
}

TEST(Patterns3d, FaceCountsFollowTheirParameters) {
    EXPECT_EQ(make_pattern("mesh", 32, 32).world->face_count(), 1280u);  // 20 * 4^3
    EXPECT_EQ(make_pattern("mesh:subdivisions=1", 32, 32).world->face_count(), 80u);
    EXPECT_EQ(make_pattern("terrain", 32, 32).world->face_count(), 2u * 24 * 24);
    EXPECT_EQ(make_pattern("terrain:cells=5", 32, 32).world->face_count(), 50u);
    EXPECT_EQ(make_pattern("blocks:count=2", 32, 32).world->objects.size(), 3u);
    // A shared-edge mesh: every edge of the closed sphere belongs to exactly two faces.
    const Scene mesh = make_pattern("mesh:subdivisions=2", 32, 32);
    std::map<std::pair<int, int>, int> edges;
    for (const Face& f : mesh.world->objects[0].faces) {
        for (std::size_t i = 0; i < f.loop.size(); ++i) {
            ++edges[std::minmax(f.loop[i], f.loop[(i + 1) % f.loop.size()])];
        }
    }
    for (const auto& [e, count] : edges) EXPECT_EQ(count, 2);
}

TEST(Patterns3d, ParametersOutOfRangeAreRejected) {
    EXPECT_THROW(make_pattern("mesh:subdivisions=6", 32, 32), InputError);
    EXPECT_THROW(make_pattern("terrain:cells=0", 32, 32), InputError);
    EXPECT_THROW(make_pattern("room:mats=0", 32, 32), InputError);
    EXPECT_THROW(make_pattern("blocks:count=9", 32, 32), InputError);
    EXPECT_THROW(make_pattern("interpenetrate:bar_width=5", 32, 32), InputError);
}

}  // namespace
}  // namespace aabench
