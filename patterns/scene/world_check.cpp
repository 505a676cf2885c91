// What the scene format demands of a world (DESIGN.md, "Scene file, version 2"), checked after
// parsing so that geometry errors name their JSON path like every other error.
//
// Tolerances. Planarity and "in the face's plane": every vertex within kPlaneRelative of the
// face's extent from the plane through its first vertex with the Newell normal. Vertices of
// ordinary scenes carry ~1e-16 relative rounding; 1e-9 accepts anything written from exact
// geometry (a generator's rotated box, a file written with 17 digits) and refuses any face
// bent visibly (1e-9 of a face 1,000 px across is 1e-6 px). Convexity: every turn the same
// way about the normal, a turn within kCollinearRelative of the edges' lengths counting as
// straight (collinear points are allowed, reflex ones are not).
#include <cmath>

#include <fmt/format.h>

#include "patterns/scene/scene_io_detail.h"

namespace aabench {
namespace {

using scene_io_detail::child_path;
using scene_io_detail::fail;

constexpr double kPlaneRelative = 1e-9;
constexpr double kCollinearRelative = 1e-12;

double extent(const std::vector<glm::dvec3>& pts) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const auto& p : pts) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return glm::length(hi - lo);
}

glm::dvec3 newell(const std::vector<glm::dvec3>& loop) {
    glm::dvec3 n(0.0);
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
        n += glm::cross(loop[i] - loop[0], loop[i + 1] - loop[0]);
    }
    return n;
}

// Planar and convex, or the reason it is not ("" when it is).
std::string planar_convex(const std::vector<glm::dvec3>& loop, glm::dvec3 n) {
    const double ext = extent(loop);
    const double len = glm::length(n);
    if (!(len > kCollinearRelative * ext * ext)) return "has zero area (its points are collinear)";
    n /= len;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const double d = glm::dot(n, loop[i] - loop[0]);
        if (!(std::abs(d) <= kPlaneRelative * ext)) {
            return fmt::format("is not planar: point {} lies {:.3g} off the plane of the others",
                               i, d);
        }
    }
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const glm::dvec3 a = loop[i], b = loop[(i + 1) % loop.size()],
                         c = loop[(i + 2) % loop.size()];
        const double turn = glm::dot(glm::cross(b - a, c - b), n);
        if (turn < -kCollinearRelative * glm::length(b - a) * glm::length(c - b)) {
            return fmt::format("is not convex: it turns back at point {}",
                               (i + 1) % loop.size());
        }
    }
    return "";
}

void check_vec(const std::string& source, const std::string& path, const glm::dvec3& v) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
        fail(source, path, "expected three finite numbers");
    }
}

void check_camera(const Camera& c, const std::string& source) {
    check_vec(source, "camera.eye", c.eye);
    check_vec(source, "camera.target", c.target);
    check_vec(source, "camera.up", c.up);
    const glm::dvec3 view = c.target - c.eye;
    if (!(glm::length(view) > 0.0)) fail(source, "camera.target", "equals camera.eye: no view direction");
    if (!(glm::length(c.up) > 0.0)) fail(source, "camera.up", "has zero length");
    // up parallel to the view leaves the roll undefined (lookAt divides by |view x up|).
    if (!(glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) > 1e-9)) {
        fail(source, "camera.up", "is parallel to the view direction (target - eye)");
    }
    if (!(c.fov_y_deg > 0.0 && c.fov_y_deg < 180.0)) {
        fail(source, "camera.fov_y_deg", fmt::format("{} is outside (0, 180)", c.fov_y_deg));
    }
    if (!(c.near > 0.0)) fail(source, "camera.near", fmt::format("{} is not > 0", c.near));
}

void check_object(const Object& o, const std::string& source, const std::string& path) {
    for (std::size_t f = 0; f < o.faces.size(); ++f) {
        const Face& face = o.faces[f];
        const std::string fpath = child_path(child_path(path, "faces"), f);
        const std::string lpath = child_path(fpath, "loop");
        if (face.loop.size() < 3) {
            fail(source, lpath, fmt::format("a face needs at least 3 vertices, found {}", face.loop.size()));
        }
        std::vector<glm::dvec3> loop;
        for (std::size_t i = 0; i < face.loop.size(); ++i) {
            const int index = face.loop[i];
            if (index < 0 || index >= static_cast<int>(o.vertices.size())) {
                fail(source, child_path(lpath, i),
                     fmt::format("index {} out of range (the object has {} vertices)", index,
                                 o.vertices.size()));
            }
            for (std::size_t j = 0; j < i; ++j) {
                if (face.loop[j] == index) {
                    fail(source, child_path(lpath, i), fmt::format("vertex {} appears twice", index));
                }
            }
            loop.push_back(o.vertices[index]);
        }
        const glm::dvec3 n = newell(loop);
        if (const std::string why = planar_convex(loop, n); !why.empty()) fail(source, lpath, "the face " + why);
        const glm::dvec3 unit = glm::normalize(n);
        const double ext = extent(loop);
        for (std::size_t p = 0; p < face.patterns.size(); ++p) {
            const FacePattern& pat = face.patterns[p];
            const std::string ppath = child_path(child_path(fpath, "patterns"), p);
            if (pat.loop.size() < 3) {
                fail(source, child_path(ppath, "loop"),
                     fmt::format("a pattern needs at least 3 points, found {}", pat.loop.size()));
            }
            for (std::size_t k = 0; k < pat.loop.size(); ++k) {
                const double d = glm::dot(unit, pat.loop[k] - loop[0]);
                if (!(std::abs(d) <= kPlaneRelative * std::max(ext, extent(pat.loop)))) {
                    fail(source, child_path(child_path(ppath, "loop"), k),
                         fmt::format("lies {:.3g} off its face's plane", d));
                }
            }
            if (const std::string why = planar_convex(pat.loop, newell(pat.loop)); !why.empty()) {
                fail(source, child_path(ppath, "loop"), "the pattern " + why);
            }
        }
    }
}

}  // namespace

void check_world(const World& world, const std::string& source) {
    check_camera(world.camera, source);
    for (std::size_t i = 0; i < world.lights.size(); ++i) {
        const Light& l = world.lights[i];
        const std::string path = child_path("lights", i);
        if (l.type == LightType::kParallel) {
            check_vec(source, child_path(path, "direction"), l.direction);
            if (!(glm::length(l.direction) > 0.0)) {
                fail(source, child_path(path, "direction"), "has zero length");
            }
        } else {
            check_vec(source, child_path(path, "position"), l.position);
        }
    }
    for (std::size_t i = 0; i < world.objects.size(); ++i) {
        check_object(world.objects[i], source, child_path("objects", i));
    }
}

}  // namespace aabench
