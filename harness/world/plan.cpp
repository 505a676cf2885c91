#include "harness/world/plan.h"


#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace aabench {
namespace {

// A vertex counts as in front of a plane when it is more than this share of the object's
// extent above it: coordinates of ordinary scenes carry ~1e-16 relative rounding, so 1e-9
// separates "on the plane" (shared edges, a box standing on the floor) from "in front" with
// a wide margin on both sides.
constexpr double kRelativePlaneTolerance = 1e-9;

double extent_of(const std::vector<glm::dvec3>& vertices) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& v : vertices) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    return vertices.empty() ? 0.0 : glm::length(hi - lo);
}

std::string object_label(const Object& o, std::size_t index) {
    return o.name.empty() ? fmt::format("#{}", index) : fmt::format("'{}'", o.name);
}

// Above this many (caster face, receiver face) pairs per light the planner does not test
// pairs: the shadow stage, which clips each pair exactly, decides (a planner that cost as much
// as the stage would defeat its purpose).
constexpr long long kMaxPlannedShadowPairs = 4'000'000;

// The signed distance of p from the plane through `origin` with unit normal n.
double height_above(const glm::dvec3& n, const glm::dvec3& origin, const glm::dvec3& p) {
    return glm::dot(n, p - origin);
}

// The unit direction from p toward the light (a parallel light: against its travel).
glm::dvec3 toward_light(const Light& light, const glm::dvec3& p) {
    return light.type == LightType::kParallel ? glm::normalize(-light.direction)
                                              : glm::normalize(light.position - p);
}

// A cheap necessary condition for face `cas` of object a to cast a shadow of positive area onto
// face `rec` of object b (no clipping, no projection): some vertex of the caster lies strictly
// on the light's side of the receiver's plane, and some vertex of the receiver lies strictly on
// the far side of the caster's plane, seen from the light. A light between two planes, or a
// receiver wholly in front of the caster, fails one of the two. `tol`: the plane tolerance.
bool may_cast(const Light& light, const Object& a, const Face& cas, const Object& b,
              const Face& rec, double tol) {
    const glm::dvec3 rn = face_normal(b, rec);
    const glm::dvec3 ro = b.vertices[rec.loop[0]];
    const glm::dvec3 cn = face_normal(a, cas);
    const glm::dvec3 co = a.vertices[cas.loop[0]];
    // The light's side of each plane: the sign of the light direction along the normal.
    const double r_side = glm::dot(rn, toward_light(light, ro));
    const double c_side = glm::dot(cn, toward_light(light, co));
    if (r_side == 0.0 || c_side == 0.0) return false;  // light along the plane: no area
    if (b.closed && r_side < 0.0) return false;  // a closed object's face turned from the light
    bool caster_in_front = false;
    for (int v : cas.loop) {
        const double h = height_above(rn, ro, a.vertices[v]);
        if ((r_side > 0.0 ? h : -h) > tol) {
            caster_in_front = true;
            break;
        }
    }
    if (!caster_in_front) return false;
    for (int v : rec.loop) {
        const double h = height_above(cn, co, b.vertices[v]);
        if ((c_side > 0.0 ? -h : h) > tol) return true;
    }
    return false;
}

// Could some face of object a cast a shadow from `light` onto object b? `budget`: pairs left to
// test before the planner gives up and lets the stage decide (then true).
bool object_may_cast(const Light& light, const Object& a, const Object& b, double tol,
                     long long& budget) {
    for (const Face& rec : b.faces) {
        for (const Face& cas : a.faces) {
            if (&cas == &rec) continue;
            if (--budget < 0) return true;
            if (may_cast(light, a, cas, b, rec, tol)) return true;
        }
    }
    return false;
}

StageDecision shadows_decision(const Scene& scene) {
    const World& w = *scene.world;
    if (!w.effects.shadows) return {false, "switched off by the scene's effects.shadows"};
    // Strictly positive heights, no tolerance: the test must never say "out" where the shadow
    // stage (whose on-plane tolerance is relative to each receiver) would find a shadow; a
    // rounding-noise "in" only runs the stage, which then finds none.
    const double tol = 0.0;
    std::string pairs;
    bool any_light = false;
    bool gave_up = false;
    for (std::size_t l = 0; l < w.lights.size(); ++l) {
        if (!w.lights[l].shadows) continue;
        any_light = true;
        long long budget = kMaxPlannedShadowPairs;
        std::string these;
        for (std::size_t a = 0; a < w.objects.size(); ++a) {
            for (std::size_t b = 0; b < w.objects.size(); ++b) {
                if (a == b && w.objects[a].closed && is_convex_object(w.objects[a])) continue;
                if (!object_may_cast(w.lights[l], w.objects[a], w.objects[b], tol, budget)) {
                    continue;
                }
                if (budget < 0) {
                    gave_up = true;
                    break;
                }
                these += fmt::format("{}{} -> {}", these.empty() ? "" : ", ",
                                     object_label(w.objects[a], a), object_label(w.objects[b], b));
            }
            if (budget < 0) break;
        }
        if (!these.empty()) {
            pairs += fmt::format("{}light {} may cast: {}", pairs.empty() ? "" : "; ", l, these);
        }
    }
    if (!any_light) return {false, w.lights.empty() ? "no lights" : "no light has shadows: true"};
    if (gave_up) {
        return {true, fmt::format("more than {} face pairs per light: the stage decides which "
                                  "cast",
                                  kMaxPlannedShadowPairs)};
    }
    if (pairs.empty()) return {false, "no face lies between a shadowing light and another face"};
    return {true, pairs};
}

StageDecision visibility_decision(const World& w) {
    if (w.objects.size() == 1) {
        const Object& o = w.objects[0];
        if (o.closed && is_convex_object(o)) {
            return {false, fmt::format("one closed convex object ({}), back-face culling suffices",
                                       object_label(o, 0))};
        }
        return {true, o.closed ? fmt::format("object {} is not convex", object_label(o, 0))
                               : fmt::format("object {} is open: two-sided faces may overlap",
                                             object_label(o, 0))};
    }
    if (w.objects.empty()) return {false, "no objects"};
    return {true, fmt::format("{}; hidden-surface work only where projected faces overlap",
                              count_of(w.objects.size(), "object", "objects"))};
}

Plan plan_2d(const Scene& scene, const PlanRequest& request) {
    Plan p;
    const std::string flat = "2-D scene";
    for (auto& s : p.stages) s = {false, flat};
    p.stages[static_cast<int>(Stage::kVisibility)] = {
        false, "2-D scene: shapes composite in order, no depth"};
    if (request.depth_image) {
        p.stages[static_cast<int>(Stage::kDepthImage)] = {false,
                                                          "2-D scene has no depth (asked for)"};
    }
    (void)scene;
    return p;
}

}  // namespace

const char* stage_name(Stage stage) {
    static const char* const kNames[kStageCount] = {
        "projection", "culling", "patterns",    "shadows",    "shading",
        "visibility", "depth",   "edges",       "reflections"};
    return kNames[static_cast<int>(stage)];
}

bool is_convex_object(const Object& object) {
    const double tol = kRelativePlaneTolerance * extent_of(object.vertices);
    for (const Face& f : object.faces) {
        const glm::dvec3 n = face_normal(object, f);
        const glm::dvec3 o = object.vertices[f.loop[0]];
        for (const glm::dvec3& p : object.vertices) {
            if (glm::dot(n, p - o) > tol) return false;
        }
    }
    return true;
}

Plan make_plan(const Scene& scene, const PlanRequest& request) {
    if (!scene.world) return plan_2d(scene, request);
    const World& w = *scene.world;
    Plan p;
    auto set = [&](Stage s, bool in, std::string reason) {
        p.stages[static_cast<int>(s)] = {in, std::move(reason)};
    };
    set(Stage::kProjection, true,
        fmt::format("3-D scene: {}, {}", count_of(w.objects.size(), "object", "objects"),
                    count_of(w.face_count(), "face", "faces")));
    const auto closed = std::count_if(w.objects.begin(), w.objects.end(),
                                      [](const Object& o) { return o.closed; });
    set(Stage::kCulling, closed > 0,
        closed > 0 ? fmt::format("{}: faces turned away are dropped",
                                 count_of(closed, "closed object", "closed objects"))
                   : "no closed object: every face is two-sided");
    std::size_t pattern_faces = 0;
    for (const Object& o : w.objects) {
        for (const Face& f : o.faces) pattern_faces += f.patterns.empty() ? 0 : 1;
    }
    if (!w.effects.patterns) {
        set(Stage::kPatterns, false, "switched off by the scene's effects.patterns");
    } else {
        set(Stage::kPatterns, pattern_faces > 0,
            pattern_faces > 0 ? fmt::format("{} patterns",
                                                count_of(pattern_faces, "face carries",
                                                         "faces carry"))
                              : "no face has patterns");
    }
    const StageDecision shadows = shadows_decision(scene);
    const bool shading_on = w.effects.shading && !w.lights.empty();
    set(Stage::kShadows, shadows.in && shading_on,
        shading_on || !shadows.in ? shadows.reason : "shading is off, so shadows are too");
    set(Stage::kShading, shading_on,
        !w.effects.shading ? "switched off by the scene's effects.shading (illuminance 1)"
        : w.lights.empty() ? "no lights: illuminance 1, the value is the reflectance"
        : w.is_colour()
            ? fmt::format("{}, ambient {}; a colour world, per channel",
                          count_of(w.lights.size(), "light", "lights"),
                          w.ambient_rgb ? fmt::format("[{}]", fmt::join(*w.ambient_rgb, ", "))
                                        : fmt::format("{}", w.ambient))
            : fmt::format("{}, ambient {}", count_of(w.lights.size(), "light", "lights"),
                          w.ambient));
    const StageDecision vis = visibility_decision(w);
    set(Stage::kVisibility, vis.in, vis.reason);
    const bool edges = w.edges.has_value() && w.effects.edges;
    set(Stage::kDepthImage, edges || request.depth_image,
        edges ? "edges ask for the depth image"
        : request.depth_image ? "asked for (--depth)"
                              : "no edges asked");
    set(Stage::kEdges, edges,
        edges ? "the scene has an edges block: contours and creases from the depth image"
        : w.edges ? "switched off by the scene's effects.edges"
                  : "no edges block");
    bool mirrors = false;
    for (const Object& o : w.objects) {
        for (const Face& f : o.faces) mirrors |= f.mirror > 0.0;
    }
    const bool reflections = mirrors && edges && w.effects.reflections;
    set(Stage::kReflections, reflections,
        reflections ? "mirror faces with edges: optical-path depth by casting rays (eq. 9)"
        : !mirrors  ? "no mirror faces"
        : !edges    ? "mirrors, but no edges asked"
                    : "switched off by the scene's effects.reflections");
    for (std::size_t i = 0; i < w.objects.size(); ++i) {
        const Object& o = w.objects[i];
        if (o.mesh.file.empty()) continue;
        p.notes.push_back(fmt::format(
            "objects[{}] {}: {}, {}, {} degenerate left out; closed: {}, {}: {}", i,
            object_label(o, i), o.mesh.file, count_of(o.mesh.triangles, "triangle", "triangles"),
            o.mesh.degenerate_dropped, o.mesh.closed_mode, o.mesh.closure,
            o.closed ? "back faces culled" : "two-sided faces"));
    }
    return p;
}

std::string format_plan(const Plan& plan) {
    std::string out;
    for (int k = 0; k < kStageCount; ++k) {
        const StageDecision& d = plan.stages[k];
        out += fmt::format("  {:<12} {:<4} {}\n", stage_name(static_cast<Stage>(k)),
                           d.in ? "in" : "out", d.reason);
    }
    for (const std::string& note : plan.notes) out += fmt::format("  {:<12} {}\n", "mesh", note);
    return out;
}

std::string count_of(std::size_t n, const char* one, const char* many) {
    return fmt::format("{} {}", n, n == 1 ? one : many);
}

}  // namespace aabench
