// Sequences, their frames and their exact motion (harness/world/sequence.h).
#include "harness/world/sequence.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "harness/world/stages.h"
#include "patterns/pattern.h"
#include "patterns/scene/curves.h"

namespace aabench {

Scene translated(const Scene& scene, double dx, double dy) {
    Scene moved = scene;
    // A disc or ring moves its centre with its polygonisation (patterns/scene/curves.h).
    auto move_shape = [dx, dy](Shape& shape) { translate_shape(shape, dx, dy); };
    for (Shape& shape : moved.shapes) move_shape(shape);
    for (ThinObject& object : moved.thin_objects) move_shape(object.shape);
    return moved;
}

Scene camera_moved(const Scene& scene, double dx_px, double dy_px) {
    if (!scene.world) return scene;
    Scene moved = scene;
    Camera& camera = moved.world->camera;
    const glm::dvec3 forward = camera.target - camera.eye;
    const double distance = glm::length(forward);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward / distance);
    const double focal_px = 0.5 * scene.height / std::tan(0.5 * glm::radians(camera.fov_y_deg));
    // A point at the target's distance lands at W/2 + f x_v / z_v: moving the camera by -s along
    // `right` moves it by f s / distance px to the right; screen y grows down, so moving the
    // camera up (+ along `up`) moves the image down.
    const glm::dvec3 shift = (-dx_px * right + dy_px * up) * (distance / focal_px);
    camera.eye += shift;
    camera.target += shift;
    return moved;
}

const std::vector<SequenceSpec>& sequence_registry() {
    // Steps: the drifts move 0.5 to 3 px per frame in directions off the axes (no pixel-grid
    // alignment; the colour drift 0.36 px, slow enough that a history holds its chroma edges
    // over several frames, which is what its rectification is tested on); the strips crawl at 0.1 px per frame, where a spatial method's error changes
    // slowly and a temporal one has time to converge; the orbit's 1 degree per frame moves
    // the nearest block's silhouette by about a pixel at 96 px and uncovers the ground behind.
    static const std::vector<SequenceSpec> registry = [] {
        std::vector<SequenceSpec> r;
        SequenceSpec s;
        s = {};
        s.name = "star-drift";
        s.summary = "the Siemens star drifting 0.6 px right and 0.35 px down per frame";
        s.pattern = "star";
        s.motion = SequenceMotion::kTranslate;
        s.dx_px = 0.6;
        s.dy_px = 0.35;
        r.push_back(s);
        s = {};
        s.name = "zoneplate-drift";
        s.summary = "the zone plate drifting 0.75 px right and 0.5 px up per frame";
        s.pattern = "zoneplate";
        s.motion = SequenceMotion::kTranslate;
        s.dx_px = 0.75;
        s.dy_px = -0.5;
        r.push_back(s);
        s = {};
        s.name = "strips-crawl";
        s.summary = "the thin strips crawling 0.1 px per frame (0.08 right, 0.06 down)";
        s.pattern = "strips";
        s.motion = SequenceMotion::kTranslate;
        s.dx_px = 0.08;
        s.dy_px = 0.06;
        r.push_back(s);
        s = {};
        s.name = "room-pan";
        s.summary =
            "room under a camera pan: eye and target move so the target's depth moves 1 px "
            "left per frame";
        s.pattern = "room";
        s.motion = SequenceMotion::kTranslate;
        s.dx_px = -1.0;
        r.push_back(s);
        const SequenceSpec room_pan = s;
        s = {};
        s.name = "blocks-orbit";
        s.summary = "blocks with the eye orbiting the target by 1 degree per frame (disocclusions)";
        s.pattern = "blocks";
        s.motion = SequenceMotion::kOrbit;
        s.orbit_deg = 1.0;
        r.push_back(s);
        s = {};
        s.name = "fast-pan";
        s.summary = "blocks under a fast camera pan: 3 px per frame at the target's depth";
        s.pattern = "blocks";
        s.motion = SequenceMotion::kTranslate;
        s.dx_px = 3.0;
        r.push_back(s);
        s = {};
        s.name = "isoluminant-drift";
        s.summary =
            "the isoluminant stars (colour) drifting 0.3 px right and 0.2 px down per frame; "
            "not in the default run";
        s.pattern = "isoluminant";
        s.motion = SequenceMotion::kTranslate;
        s.dx_px = 0.3;
        s.dy_px = 0.2;
        s.in_default_run = false;
        r.push_back(s);
        s = room_pan;  // its motion
        s.name = "colour-room-pan";
        s.summary =
            "the colour room (a colour world) under room-pan's camera pan, 1 px left per frame "
            "at the target's depth; not in the default run";
        s.pattern = "colour-room";
        s.in_default_run = false;
        r.push_back(s);
        s = {};
        s.name = "star-still";
        s.summary = "the Siemens star standing still (convergence)";
        s.pattern = "star";
        s.motion = SequenceMotion::kStill;
        r.push_back(s);
        // The mesh models (patterns/models.cpp) in motion: the bunny's silhouette and
        // self-occlusion (the ears over the back) under an orbit of 1.5 degrees per frame, which
        // moves the silhouette by about a pixel per frame at 96 px and turns the bunny by 48
        // degrees over 32 frames; the truck under a pan of (1.25, -0.4) px per frame at the
        // target's depth, off the axes and the pixel grid, the wheels and the body moving
        // against the ground behind (parallax).
        s = {};
        s.name = "bunny-orbit";
        s.summary =
            "the Stanford bunny (glmark2-data), the eye orbiting it by 1.5 degrees per frame (run "
            "when named)";
        s.pattern = "bunny";
        s.motion = SequenceMotion::kOrbit;
        s.orbit_deg = 1.5;
        s.model_file = true;
        s.in_default_run = false;
        r.push_back(s);
        s = {};
        s.name = "truck-pan";
        s.summary =
            "Cesium's milk truck (assimp-testmodels) under a camera pan of (1.25, -0.4) px per "
            "frame at the target's depth (run when named)";
        s.pattern = "truck";
        s.motion = SequenceMotion::kTranslate;
        s.dx_px = 1.25;
        s.dy_px = -0.4;
        s.model_file = true;
        s.in_default_run = false;
        r.push_back(s);
        return r;
    }();
    return registry;
}

const SequenceSpec& find_sequence(const std::string& name) {
    std::vector<std::string> names;
    for (const SequenceSpec& s : sequence_registry()) {
        if (s.name == name) return s;
        names.push_back(s.name);
    }
    throw InputError(
        fmt::format("unknown sequence '{}' (sequences: {})", name, fmt::join(names, ", ")));
}

Sequence make_sequence(const SequenceSpec& spec, Scene scene, int frames) {
    if (frames < 1 || frames > 100000) {
        throw InputError(
            fmt::format("sequence {}: frames {} is not in 1..100000", spec.name, frames));
    }
    if (spec.motion != SequenceMotion::kStill && spec.motion != SequenceMotion::kTranslate &&
        !scene.world) {
        throw InputError(fmt::format("sequence {}: a camera path needs a 3-D scene", spec.name));
    }
    if (spec.motion == SequenceMotion::kPath) {
        const PathProblem p = first_path_problem(scene.world->camera, spec, frames);
        if (p.frame > 0) {
            throw InputError(
                fmt::format("sequence {}: at frame {}, {}", spec.name, p.frame, p.problem));
        }
    }
    return Sequence{spec, std::move(scene), frames};
}

Sequence file_sequence(Scene scene, const std::string& name, const std::string& path,
                       int default_frames) {
    if (!scene.sequence) {
        throw InputError(
            fmt::format("{}: has no \"sequence\" (a scene file of version 3 carries one; "
                        "docs/scene-format.md)",
                        path));
    }
    SequenceSpec spec;
    static_cast<SequenceSteps&>(spec) = *scene.sequence;
    spec.name = name;
    spec.pattern = path;
    spec.summary = fmt::format("{}: {}", path, describe_steps(spec, scene.world.has_value()));
    const int frames = scene.sequence->frames.value_or(default_frames);
    return make_sequence(spec, std::move(scene), frames);
}

Scene sequence_scene(const SequenceSpec& spec, int width, int height, std::optional<int> frames) {
    Scene scene = make_pattern(spec.pattern, width, height);
    SceneSequence sequence;
    static_cast<SequenceSteps&>(sequence) = spec;
    sequence.frames = frames;
    scene.sequence = sequence;
    return scene;
}

std::string describe_steps(const SequenceSteps& steps, bool world) {
    switch (steps.motion) {
        case SequenceMotion::kStill:
            return "still";
        case SequenceMotion::kTranslate:
            return fmt::format("{} ({}, {}) px per frame{}", world ? "camera pan" : "translate",
                               steps.dx_px, steps.dy_px, world ? " at the target's depth" : "");
        case SequenceMotion::kPath:
            return fmt::format("camera path: eye ({}, {}, {}), target ({}, {}, {}) per frame",
                               steps.eye_step.x, steps.eye_step.y, steps.eye_step.z,
                               steps.target_step.x, steps.target_step.y, steps.target_step.z);
        case SequenceMotion::kOrbit:
            return fmt::format("orbit {} degrees per frame", steps.orbit_deg);
    }
    return "";
}

Sequence make_sequence(const SequenceSpec& spec, int width, int height, int frames) {
    return make_sequence(spec, make_pattern(spec.pattern, width, height), frames);
}

Camera frame_camera(const Sequence& sequence, int t) {
    if (!sequence.scene.world) throw std::logic_error("frame_camera: a 2-D sequence");
    const SequenceSpec& spec = sequence.spec;
    if (spec.motion == SequenceMotion::kTranslate) {
        return camera_moved(sequence.scene, t * spec.dx_px, t * spec.dy_px).world->camera;
    }
    if (spec.motion == SequenceMotion::kPath) {
        return path_camera(sequence.scene.world->camera, spec, t);
    }
    Camera camera = sequence.scene.world->camera;
    if (spec.motion == SequenceMotion::kOrbit) {
        const glm::dmat4 turn = glm::rotate(glm::dmat4(1.0), glm::radians(t * spec.orbit_deg),
                                            glm::normalize(camera.up));
        camera.eye = camera.target + glm::dvec3(turn * glm::dvec4(camera.eye - camera.target, 0.0));
    }
    return camera;
}

Scene frame_scene(const Sequence& sequence, int t) {
    const SequenceSpec& spec = sequence.spec;
    if (t == 0 || spec.motion == SequenceMotion::kStill) return sequence.scene;
    if (!sequence.scene.world) return translated(sequence.scene, t * spec.dx_px, t * spec.dy_px);
    Scene scene = sequence.scene;
    scene.world->camera = frame_camera(sequence, t);
    return scene;
}

namespace {

// Nonzero winding number of the contours about (x, y) (Sunday's crossing rule): a point on an
// edge counts on one side only, consistently for the two shapes that share the edge.
bool winding_contains(const Shape& shape, double x, double y) {
    int winding = 0;
    for (const Contour& c : shape.contours) {
        const std::size_t n = c.size();
        for (std::size_t k = 0; k < n; ++k) {
            const Point& a = c[k];
            const Point& b = c[(k + 1) % n];
            const double side = (b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y);
            if (a.y <= y) {
                if (b.y > y && side > 0) ++winding;
            } else if (b.y <= y && side < 0) {
                --winding;
            }
        }
    }
    return winding != 0;
}

struct Box {
    double lo_x, hi_x, lo_y, hi_y;
    bool outside(double x, double y) const { return x < lo_x || x > hi_x || y < lo_y || y > hi_y; }
};

Box box_of(const Shape& shape) {
    Box b{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const Contour& c : shape.contours) {
        for (const Point& p : c) {
            b.lo_x = std::min(b.lo_x, p.x);
            b.hi_x = std::max(b.hi_x, p.x);
            b.lo_y = std::min(b.lo_y, p.y);
            b.hi_y = std::max(b.hi_y, p.y);
        }
    }
    return b;
}

std::vector<Box> boxes_of(const Scene& screen) {
    std::vector<Box> boxes;
    boxes.reserve(screen.shapes.size());
    for (const Shape& shape : screen.shapes) boxes.push_back(box_of(shape));
    return boxes;
}

int visible_shape_in_boxes(const Scene& screen, const std::vector<Box>& boxes, double x, double y) {
    int best = -1;
    double best_depth = -std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < screen.shapes.size(); ++s) {
        const Shape& shape = screen.shapes[s];
        if (boxes[s].outside(x, y) || !winding_contains(shape, x, y)) continue;
        const double depth = shape.inv_depth ? shape.inv_depth->at(x, y) : 0.0;
        if (depth >= best_depth) {
            best_depth = depth;
            best = static_cast<int>(s);
        }
    }
    return best;
}

// Every visible shape found per pixel centre at once: each shape tested only at the pixel
// centres inside its bounding box (the brute force over every shape and pixel, pruned).
std::vector<int> visible_shapes_at_centres(const Scene& screen) {
    const int w = screen.width, h = screen.height;
    std::vector<int> best(static_cast<std::size_t>(w) * h, -1);
    std::vector<double> best_depth(best.size(), -std::numeric_limits<double>::infinity());
    for (std::size_t s = 0; s < screen.shapes.size(); ++s) {
        const Shape& shape = screen.shapes[s];
        const Box b = box_of(shape);
        // Clamped in double first: a shape far outside the window must not overflow an int.
        const auto index = [](double v, int hi) {
            return static_cast<int>(std::clamp(v, -1.0, static_cast<double>(hi)));
        };
        const int i0 = std::max(0, index(std::ceil(b.lo_x - 0.5), w));
        const int i1 = std::min(w - 1, index(std::floor(b.hi_x - 0.5), w));
        const int j0 = std::max(0, index(std::ceil(b.lo_y - 0.5), h));
        const int j1 = std::min(h - 1, index(std::floor(b.hi_y - 0.5), h));
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                const double x = i + 0.5, y = j + 0.5;
                if (!winding_contains(shape, x, y)) continue;
                const double depth = shape.inv_depth ? shape.inv_depth->at(x, y) : 0.0;
                const std::size_t k = static_cast<std::size_t>(j) * w + i;
                if (depth >= best_depth[k]) {
                    best_depth[k] = depth;
                    best[k] = static_cast<int>(s);
                }
            }
        }
    }
    return best;
}

}  // namespace

int visible_shape_at(const Scene& screen, double x, double y) {
    return visible_shape_in_boxes(screen, boxes_of(screen), x, y);
}

FrameMotion frame_motion(const Sequence& sequence, const PreparedFrame& previous,
                         const PreparedFrame& current, int t) {
    const Scene& scene = sequence.scene;
    const int w = scene.width, h = scene.height;
    FrameMotion motion;
    motion.disoccluded = Raster<std::uint8_t>(w, h, 0);
    if (t == 0 || sequence.spec.motion == SequenceMotion::kStill) return motion;
    MotionVectors& v = motion.vectors;
    v.width = w;
    v.height = h;
    v.dx.assign(static_cast<std::size_t>(w) * h, 0.0f);
    v.dy.assign(v.dx.size(), 0.0f);
    const auto outside_image = [w, h](double x, double y) {
        return !(x >= 0.0 && x < w && y >= 0.0 && y < h);
    };

    if (!scene.world) {
        const SequenceSpec& spec = sequence.spec;
        for (int j = 0; j < h; ++j) {
            for (int i = 0; i < w; ++i) {
                const std::size_t k = static_cast<std::size_t>(j) * w + i;
                v.dx[k] = static_cast<float>(spec.dx_px);
                v.dy[k] = static_cast<float>(spec.dy_px);
                motion.disoccluded.data[k] =
                    outside_image(i + 0.5 - spec.dx_px, j + 0.5 - spec.dy_px) ? 1 : 0;
            }
        }
        return motion;
    }

    const ViewSetup now = ViewSetup::from(frame_camera(sequence, t), w, h);
    const ViewSetup before = ViewSetup::from(frame_camera(sequence, t - 1), w, h);
    const glm::dmat4 view_to_world = glm::inverse(now.view);
    const Scene& screen = current.screen();
    const Scene& previous_screen = previous.screen();
    const std::vector<int> seen = visible_shapes_at_centres(screen);
    const std::vector<int> seen_before = visible_shapes_at_centres(previous_screen);
    const std::vector<Box> previous_boxes = boxes_of(previous_screen);
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * w + i;
            const double x = i + 0.5, y = j + 0.5;
            const int s = seen[k];
            if (s < 0) {
                // The background: no motion; uncovered when a face was there before.
                motion.disoccluded.data[k] = seen_before[k] >= 0 ? 1 : 0;
                continue;
            }
            const Shape& shape = screen.shapes[static_cast<std::size_t>(s)];
            if (!shape.inv_depth) {  // not a ScreenScene's shape: no depth to reproject
                motion.disoccluded.data[k] = 1;
                continue;
            }
            // 1/z_v is affine in screen position on a plane (the ScreenScene's inv_depth).
            const double z_v = 1.0 / shape.inv_depth->at(x, y);
            const glm::dvec3 p_view((x - 0.5 * w) * z_v / now.focal_px,
                                    (0.5 * h - y) * z_v / now.focal_px, z_v);
            // lookAt's camera space looks down -z: flip back before leaving it.
            const glm::dvec3 p_world(view_to_world * glm::dvec4(p_view.x, p_view.y, -p_view.z, 1));
            const glm::dvec3 q = before.to_view(p_world);
            if (q.z <= before.near) {
                motion.disoccluded.data[k] = 1;  // behind the previous camera or clipped
                continue;
            }
            const double px = 0.5 * w + before.focal_px * q.x / q.z;
            const double py = 0.5 * h - before.focal_px * q.y / q.z;
            v.dx[k] = static_cast<float>(x - px);
            v.dy[k] = static_cast<float>(y - py);
            if (outside_image(px, py)) {
                motion.disoccluded.data[k] = 1;
                continue;
            }
            const int was = visible_shape_in_boxes(previous_screen, previous_boxes, px, py);
            motion.disoccluded.data[k] =
                was < 0 || previous_screen.shapes[static_cast<std::size_t>(was)].face != shape.face
                    ? 1
                    : 0;
        }
    }
    return motion;
}

}  // namespace aabench
