// What the scene format demands of a world (docs/scene-format.md, "Version 2 checks";
// docs/world.md, "The world's contracts"), checked after parsing so that geometry errors name their
// JSON path like every other error, and callable on a generator's world, which no reader saw.
//
// Tolerances. Vertices are stored rounded: whoever computed them (a rotation, a file written
// with 17 digits) left each coordinate up to a few ulps of its magnitude off the exact
// geometry. So every "is it zero" below allows a relative part (of the face's extent) and a
// rounding part (of the largest coordinate):
// - planar: each vertex within kPlaneRelative x extent + kCoordinateRounding x max|coordinate|
//   of the plane through the loop's centroid with its Newell normal. 1e-9 of a face 1,000 units
//   across is 1e-6 units: any bend one could see is refused, any rounding accepted;
// - a pattern lies in its face's plane by the same rule (with the larger of the two extents);
// - zero area: the Newell vector (twice the area) at most kCollinearRelative x extent^2;
// - convex: every turn the same way about the normal, a turn within kCollinearRelative of the
//   two edges' lengths (plus the rounding part) counting as straight, so collinear vertices
//   are allowed and reflex ones are not; and the turns adding up to one full turn, which
//   refuses what turns the same way but crosses itself (a pentagram, two full turns) or
//   doubles back on itself (a half turn in one step).
// Not checked: that a closed object's faces really face out. Orientation is only decidable
// for a surface that is closed and consistently connected, which `closed: true` does not
// promise (a lone one-sided quad is a valid closed object); a wrong loop order shows up as a
// culled face, not as a crash.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <string_view>
#include <utility>
#include <vector>

#include "patterns/scene/scene_io_detail.h"
#include "patterns/scene/stable_length.h"

namespace aabench {
namespace {

using scene_io_detail::child_path;
using scene_io_detail::fail;
using scene_io_detail::LazyPath;

constexpr double kPlaneRelative = 1e-9;
constexpr double kCollinearRelative = 1e-12;
// A few operations' rounding of the largest coordinate (64 ulps): a generator's rotated,
// translated vertex is off its exact place by a few half-ulps of its magnitude.
constexpr double kCoordinateRounding = 64 * std::numeric_limits<double>::epsilon();
// The sine of the angle between `up` and the view direction: below 1e-9 the camera's roll is
// decided by rounding (lookAt normalises view x up), not by the file.
constexpr double kMinUpViewSine = 1e-9;
// A closed loop's turns add up to a whole number of half turns; a convex one to exactly one
// full turn. A quarter turn of slack separates 2 pi from pi and 3 pi whatever the rounding.
constexpr double kTurningSlack = std::numbers::pi / 2;
// World coordinates and vectors within +-1e100: the checks and the world stages square them
// (cross products, Newell normals, the 1/d^2 of a point light), and 1e200 stays far inside the
// range of a double (1.8e308), where 1e160 squared would not.
constexpr double kMaxWorldCoordinate = 1e100;

// A loop's plane and how far off it a point may lie.
struct Plane {
    glm::dvec3 normal{0.0};  // Newell: twice the vector area, not normalised
    glm::dvec3 centroid{0.0};
    double extent = 0.0;   // bounding-box diagonal
    double max_abs = 0.0;  // largest coordinate magnitude
};

Plane plane_of(const std::vector<glm::dvec3>& loop) {
    Plane p;
    glm::dvec3 lo(std::numeric_limits<double>::infinity());
    glm::dvec3 hi = -lo;
    for (const glm::dvec3& v : loop) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
        p.centroid += v;
        p.max_abs = std::max({p.max_abs, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    }
    p.centroid /= static_cast<double>(loop.size());
    p.extent = glm::length(hi - lo);
    // Newell's normal, summed about the first vertex (smaller terms than about the origin).
    for (std::size_t i = 1; i + 1 < loop.size(); ++i) {
        p.normal += glm::cross(loop[i] - loop[0], loop[i + 1] - loop[0]);
    }
    return p;
}

// How far off the plane a point may lie, for loops of the given extent and magnitude.
double plane_slack(double extent, double max_abs) {
    return kPlaneRelative * extent + kCoordinateRounding * max_abs;
}

// Planar and convex, or the reason it is not ("" when it is). Comparisons are written so that
// NaN fails them.
std::string planar_convex(const std::vector<glm::dvec3>& loop, const Plane& plane) {
    const double area2 = stable_length(plane.normal);
    if (!(area2 > kCollinearRelative * plane.extent * plane.extent)) {
        return "has zero area (its points are collinear)";
    }
    const glm::dvec3 n = plane.normal / area2;
    const double slack = plane_slack(plane.extent, plane.max_abs);
    // Name the farthest point: in a long loop, the one that is off (in a quad, the four are
    // off by the same amount, and the first is named). The distances are finite: the points
    // were checked to lie within kMaxWorldCoordinate, and the normal has nonzero length.
    std::size_t farthest = 0;
    double farthest_d = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const double d = glm::dot(n, loop[i] - plane.centroid);
        if (std::abs(d) > std::abs(farthest_d)) {
            farthest = i;
            farthest_d = d;
        }
    }
    if (!(std::abs(farthest_d) <= slack)) {
        return fmt::format("is not planar: loop[{}] lies {:.3g} off the loop's plane", farthest,
                           farthest_d);
    }
    const std::size_t k = loop.size();
    double turning = 0.0;
    for (std::size_t i = 0; i < k; ++i) {
        const glm::dvec3 e1 = loop[(i + 1) % k] - loop[i];
        const glm::dvec3 e2 = loop[(i + 2) % k] - loop[(i + 1) % k];
        const double l1 = glm::length(e1);
        const double l2 = glm::length(e2);
        const double sine = glm::dot(glm::cross(e1, e2), n);  // |e1| |e2| sin(turn)
        const double straight =
            kCollinearRelative * l1 * l2 + kCoordinateRounding * plane.max_abs * (l1 + l2);
        if (!(sine >= -straight)) {
            return fmt::format("is not convex: it turns back at loop[{}]", (i + 1) % k);
        }
        turning += std::atan2(sine, glm::dot(e1, e2));
    }
    if (!(std::abs(turning - 2 * std::numbers::pi) <= kTurningSlack)) {
        return fmt::format(
            "is not convex: its turns add up to {:.0f} degrees, not 360 (it crosses itself or "
            "doubles back)",
            turning * 180 / std::numbers::pi);
    }
    return "";
}

// The first index that repeats an earlier one, in loop order: (its position, the position of
// the earlier one), or (0, 0) when none does. Sorting (index, position) pairs keeps this
// O(n log n): a hostile file's face of a million indices must not take 10^12 steps.
std::pair<std::size_t, std::size_t> first_repeat(const std::vector<int>& loop) {
    std::vector<std::pair<int, std::size_t>> sorted(loop.size());
    for (std::size_t i = 0; i < loop.size(); ++i) sorted[i] = {loop[i], i};
    std::sort(sorted.begin(), sorted.end());
    std::pair<std::size_t, std::size_t> repeat{0, 0};
    for (std::size_t k = 1; k < sorted.size(); ++k) {
        // Within a run of one index, the run's first pair is its first occurrence and the
        // second pair its first repeat.
        const bool second_of_run = sorted[k].first == sorted[k - 1].first &&
                                   (k < 2 || sorted[k - 2].first != sorted[k].first);
        if (second_of_run && (repeat.first == 0 || sorted[k].second < repeat.first)) {
            repeat = {sorted[k].second, sorted[k - 1].second};
        }
    }
    return repeat;
}

class WorldChecker {
public:
    explicit WorldChecker(const std::string& source) : source_(source) {}

    void check(const World& world) {
        check_camera(world.camera);
        number(world.ambient, "ambient");
        for (std::size_t i = 0; i < world.lights.size(); ++i) {
            check_light(world.lights[i], child_path("lights", i));
        }
        for (std::size_t i = 0; i < world.objects.size(); ++i) {
            check_object(world.objects[i], child_path("objects", i));
        }
        for (std::size_t i = 0; i < world.lights.size(); ++i) {
            check_falloff(world, world.lights[i], child_path("lights", i));
        }
        if (world.edges) check_edges(*world.edges);
    }

private:
    // A point light's falloff 1/d^2 is taken at each face's centroid (flat shading,
    // docs/scene-format.md): a light there (or so near that intensity / d^2 overflows) would
    // make the face's value infinite. Refused here, where the path can be named; the shading
    // stage checks its values too (a centroid computed in another order may differ by an ulp).
    void check_falloff(const World& world, const Light& light, const std::string& path) {
        if (light.type != LightType::kPoint || !world.effects.shading) return;
        for (std::size_t o = 0; o < world.objects.size(); ++o) {
            const Object& object = world.objects[o];
            for (std::size_t f = 0; f < object.faces.size(); ++f) {
                const glm::dvec3 d = light.position - area_centroid_3d(object, object.faces[f]);
                const double d2 = glm::dot(d, d);
                // As the shading stage computes it: the falloff first, then the intensity.
                if (std::isfinite(1.0 / d2) && std::isfinite(light.intensity * (1.0 / d2))) {
                    continue;
                }
                fail(source_, child_path(path, "position"),
                     fmt::format("the point light lies at or too near the centroid of {} "
                                 "(distance {:g}), where its falloff 1/d^2 is infinite",
                                 child_path(child_path(child_path("objects", o), "faces"), f),
                                 std::sqrt(d2)));
            }
        }
    }

    // The area centroid of a planar polygon: the triangle fan's centroids weighted by area.
    static glm::dvec3 area_centroid_3d(const Object& object, const Face& face) {
        const glm::dvec3 a = object.vertices[face.loop[0]];
        glm::dvec3 sum(0.0);
        double total = 0.0;
        for (std::size_t k = 1; k + 1 < face.loop.size(); ++k) {
            const glm::dvec3 b = object.vertices[face.loop[k]];
            const glm::dvec3 c = object.vertices[face.loop[k + 1]];
            const double area = stable_length(glm::cross(b - a, c - a));
            sum += area * (a + b + c) / 3.0;
            total += area;
        }
        return total > 0.0 ? sum / total : a;
    }

    void number(double v, const LazyPath& path) {
        if (!std::isfinite(v)) {
            fail(source_, path.str(), fmt::format("{} is not a finite number", v));
        }
    }

    void point(const glm::dvec3& v, const LazyPath& path) {
        for (int k = 0; k < 3; ++k) {
            if (!(std::abs(v[k]) <= kMaxWorldCoordinate)) {
                fail(source_, LazyPath(path, static_cast<std::size_t>(k)).str(),
                     fmt::format("{} is not a finite number within the limit of 1e100", v[k]));
            }
        }
    }

    void choice(const std::string& value, const std::string& path,
                std::initializer_list<std::string_view> allowed) {
        for (std::string_view a : allowed) {
            if (value == a) return;
        }
        fail(source_, path,
             fmt::format("expected one of \"{}\", found \"{}\"", fmt::join(allowed, "\", \""),
                         scene_io_detail::printable(value, /*escape_quotes=*/true)));
    }

    void check_camera(const Camera& c) {
        point(c.eye, "camera.eye");
        point(c.target, "camera.target");
        point(c.up, "camera.up");
        const glm::dvec3 view = c.target - c.eye;
        if (!(glm::length(view) > 0.0)) {
            fail(source_, "camera.target", "equals camera.eye: no view direction");
        }
        if (!(glm::length(c.up) > 0.0)) fail(source_, "camera.up", "has zero length");
        if (!(glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) >
              kMinUpViewSine)) {
            fail(source_, "camera.up", "is parallel to the view direction (target - eye)");
        }
        if (!(c.fov_y_deg > 0.0 && c.fov_y_deg < 180.0)) {
            fail(source_, "camera.fov_y_deg", fmt::format("{} is outside (0, 180)", c.fov_y_deg));
        }
        if (!(c.near > 0.0 && std::isfinite(c.near))) {
            fail(source_, "camera.near", fmt::format("{} is not a finite number > 0", c.near));
        }
    }

    void check_light(const Light& l, const std::string& path) {
        if (l.type == LightType::kParallel) {
            const std::string dpath = child_path(path, "direction");
            point(l.direction, dpath);
            if (!(glm::length(l.direction) > 0.0)) fail(source_, dpath, "has zero length");
        } else {
            point(l.position, child_path(path, "position"));
        }
        number(l.intensity, child_path(path, "intensity"));
    }

    void check_object(const Object& o, const std::string& path) {
        const std::string vpath = child_path(path, "vertices");
        const std::string fpath = child_path(path, "faces");
        for (std::size_t i = 0; i < o.vertices.size(); ++i)
            point(o.vertices[i], LazyPath(vpath, i));
        for (std::size_t f = 0; f < o.faces.size(); ++f) {
            check_face(o, o.faces[f], LazyPath(fpath, f));
        }
    }

    void check_face(const Object& o, const Face& face, const LazyPath& path) {
        const LazyPath lpath(path, "loop");
        if (face.loop.size() < 3) {
            fail(source_, lpath.str(),
                 fmt::format("a face needs at least 3 vertices, found {}", face.loop.size()));
        }
        std::vector<glm::dvec3> loop;
        loop.reserve(face.loop.size());
        for (std::size_t i = 0; i < face.loop.size(); ++i) {
            const int index = face.loop[i];
            if (index < 0 || static_cast<std::size_t>(index) >= o.vertices.size()) {
                fail(source_, LazyPath(lpath, i).str(),
                     fmt::format("index {} out of range (the object has {} vertices)", index,
                                 o.vertices.size()));
            }
            loop.push_back(o.vertices[index]);
        }
        if (const auto [at, first] = first_repeat(face.loop); at != 0) {
            fail(source_, LazyPath(lpath, at).str(),
                 fmt::format("vertex {} appears twice (first at loop[{}])", face.loop[at], first));
        }
        const Plane plane = plane_of(loop);
        if (const std::string why = planar_convex(loop, plane); !why.empty()) {
            fail(source_, lpath.str(), "the face " + why);
        }
        number(face.reflectance, LazyPath(path, "reflectance"));
        number(face.mirror, LazyPath(path, "mirror"));
        for (std::size_t p = 0; p < face.patterns.size(); ++p) {
            check_pattern(face.patterns[p], plane,
                          child_path(child_path(path.str(), "patterns"), p));
        }
    }

    void check_pattern(const FacePattern& pattern, const Plane& face, const std::string& path) {
        const std::string lpath = child_path(path, "loop");
        if (pattern.loop.size() < 3) {
            fail(source_, lpath,
                 fmt::format("a pattern needs at least 3 points, found {}", pattern.loop.size()));
        }
        for (std::size_t k = 0; k < pattern.loop.size(); ++k) {
            point(pattern.loop[k], child_path(lpath, k));
        }
        const Plane own = plane_of(pattern.loop);
        const glm::dvec3 n = glm::normalize(face.normal);
        const double slack =
            plane_slack(std::max(face.extent, own.extent), std::max(face.max_abs, own.max_abs));
        for (std::size_t k = 0; k < pattern.loop.size(); ++k) {
            const double d = glm::dot(n, pattern.loop[k] - face.centroid);
            if (!(std::abs(d) <= slack)) {
                fail(source_, child_path(lpath, k),
                     fmt::format("lies {:.3g} off its face's plane", d));
            }
        }
        if (const std::string why = planar_convex(pattern.loop, own); !why.empty()) {
            fail(source_, lpath, "the pattern " + why);
        }
        number(pattern.reflectance, child_path(path, "reflectance"));
    }

    void check_edges(const EdgesSpec& e) {
        choice(e.contour, "edges.contour", {"sobel", "prewitt"});
        choice(e.crease, "edges.crease", {"laplacian4", "laplacian8", "none"});
        // kp divides (eq. 7) and kl is a limit a ratio is taken against (eq. 8): both > 0.
        positive(e.kp, "edges.kp");
        positive(e.kl, "edges.kl");
        choice(e.style, "edges.style", {"black", "white-convex"});
        non_negative(e.contour_weight, "edges.contour_weight");
        non_negative(e.crease_weight, "edges.crease_weight");
    }

    void positive(double v, const std::string& path) {
        number(v, path);
        if (!(v > 0.0)) fail(source_, path, fmt::format("{} is not > 0", v));
    }
    void non_negative(double v, const std::string& path) {
        number(v, path);
        if (!(v >= 0.0)) fail(source_, path, fmt::format("{} is negative", v));
    }

    const std::string& source_;
};

}  // namespace

bool triangle_has_zero_area(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const Plane plane = plane_of({a, b, c});
    return !(stable_length(plane.normal) > kCollinearRelative * plane.extent * plane.extent);
}

void check_world(const World& world, const std::string& source) {
    WorldChecker(source).check(world);
}

PathProblem first_path_problem(const Camera& camera, const SequenceSteps& steps, int frames) {
    for (int t = 1; t < frames; ++t) {
        const Camera c = path_camera(camera, steps, t);
        const glm::dvec3 view = c.target - c.eye;
        if (!(glm::length(view) > 0.0)) return {t, "the eye reaches the target: no view direction"};
        // The same rule as check_camera's, so that no frame's roll is left to rounding.
        if (!(glm::length(glm::cross(glm::normalize(view), glm::normalize(c.up))) >
              kMinUpViewSine)) {
            return {t, "up is parallel to the view direction (target - eye)"};
        }
    }
    return {};
}

}  // namespace aabench
