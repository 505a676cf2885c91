// The version-3 "sequence" of a scene file (docs/scene-format.md, "Version 3"): a motion over
// frames, read strictly and written exactly like the rest of the file.
//
// The keys are SequenceSteps' fields one to one (patterns/scene/scene_sequence.h), with one
// exception that keeps a file's meaning visible in it: SequenceMotion::kTranslate is written
// "translate" on a 2-D scene (the shapes move) and "pan" on a 3-D one (the camera moves, so
// that the target's depth moves by dx_px, dy_px: nearer points more, farther ones less). The
// reader refuses either on the other kind of scene, and "pan", "path" and "orbit" on a 2-D one.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <initializer_list>
#include <string_view>

#include "patterns/scene/scene_io_detail.h"

namespace aabench::scene_io_detail {
namespace {

// A translation of more than the largest image side per frame leaves no pixel with a history
// in any image; larger steps would only carry the scene towards the coordinate limit.
constexpr double kMaxStepPx = kMaxImageSide;
// A path step within +-1e96 world units keeps the eye and the target of 10,000 frames
// (kMaxSequenceFrames) within 1e100 of where they start, the world coordinate limit.
constexpr double kMaxPathStep = 1e96;
// Any turn is within one whole turn either way of a turn of the same effect.
constexpr double kMaxOrbitDeg = 360.0;

constexpr const char* kPath = "sequence";

const char* motion_name(SequenceMotion motion, bool world) {
    switch (motion) {
        case SequenceMotion::kStill:
            return "still";
        case SequenceMotion::kTranslate:
            return world ? "pan" : "translate";
        case SequenceMotion::kPath:
            return "path";
        case SequenceMotion::kOrbit:
            return "orbit";
    }
    return "still";
}

class SequenceReader {
public:
    explicit SequenceReader(const std::string& source) : source_(source) {}

    SceneSequence read(const Json& value, const Scene& scene) {
        if (!value.is_object()) {
            fail(source_, kPath, "expected a sequence object, found " + describe(value));
        }
        const bool world = scene.world.has_value();
        SceneSequence sequence;
        sequence.motion = read_motion(value, world);
        switch (sequence.motion) {
            case SequenceMotion::kStill:
                keys(value, {"frames", "motion"});
                break;
            case SequenceMotion::kTranslate:
                keys(value, {"frames", "motion", "dx_px", "dy_px"});
                sequence.dx_px = step_px(value, "dx_px");
                sequence.dy_px = step_px(value, "dy_px");
                break;
            case SequenceMotion::kPath:
                keys(value, {"frames", "motion", "eye_step", "target_step"});
                sequence.eye_step = path_step(value, "eye_step");
                sequence.target_step = path_step(value, "target_step");
                break;
            case SequenceMotion::kOrbit: {
                keys(value, {"frames", "motion", "orbit_deg"});
                const std::string path = child_path(kPath, "orbit_deg");
                sequence.orbit_deg = real(require(value, "orbit_deg"), path);
                if (!(std::abs(sequence.orbit_deg) <= kMaxOrbitDeg)) {
                    fail(source_, path,
                         fmt::format("{} is outside [-360, 360] degrees per frame",
                                     Json(sequence.orbit_deg).dump()));
                }
                break;
            }
        }
        if (value.contains("frames")) sequence.frames = read_frames(value["frames"]);
        // A path that runs the eye into the target (or along `up`) has frames with no view.
        // Checked here for the file's own frames; the sequence runner checks the frames it is
        // given (harness/world/sequence.h, make_sequence) when the file leaves them to it.
        if (sequence.motion == SequenceMotion::kPath && sequence.frames) {
            const PathProblem p =
                first_path_problem(scene.world->camera, sequence, *sequence.frames);
            if (p.frame > 0) {
                fail(source_, kPath, fmt::format("at frame {}, {}", p.frame, p.problem));
            }
        }
        return sequence;
    }

private:
    SequenceMotion read_motion(const Json& value, bool world) {
        const std::string path = child_path(kPath, "motion");
        const Json& text = require(value, "motion");
        static constexpr std::string_view kNames[] = {"still", "translate", "pan", "path", "orbit"};
        std::string name;
        if (text.is_string()) {
            for (std::string_view n : kNames) {
                if (text.get_ref<const std::string&>() == n) name = n;
            }
        }
        if (name.empty()) {
            fail(source_, path,
                 fmt::format("expected one of \"{}\", found {}", fmt::join(kNames, "\", \""),
                             describe(text)));
        }
        if (name == "translate" && world) {
            fail(source_, path,
                 "\"translate\" moves a 2-D scene's shapes; a 3-D scene moves its camera: "
                 "\"pan\" (px at the target's depth), \"path\" or \"orbit\"");
        }
        if ((name == "pan" || name == "path" || name == "orbit") && !world) {
            fail(source_, path,
                 fmt::format("\"{}\" moves a 3-D scene's camera, and this file has no "
                             "\"objects\" (a 2-D scene has \"still\" and \"translate\")",
                             name));
        }
        if (name == "still") return SequenceMotion::kStill;
        if (name == "translate" || name == "pan") return SequenceMotion::kTranslate;
        return name == "path" ? SequenceMotion::kPath : SequenceMotion::kOrbit;
    }

    void keys(const Json& value, std::initializer_list<std::string_view> allowed) {
        for (const auto& item : value.items()) {
            bool known = false;
            for (std::string_view name : allowed) known = known || item.key() == name;
            if (!known) {
                fail(source_, child_path(kPath, item.key()),
                     fmt::format("unknown key for this motion (expected one of: {})",
                                 fmt::join(allowed, ", ")));
            }
        }
    }

    const Json& require(const Json& object, const char* key) {
        const auto it = object.find(key);
        if (it == object.end()) {
            fail(source_, child_path(kPath, key), "required key is missing");
        }
        return *it;
    }

    double real(const Json& value, const std::string& path) {
        if (!value.is_number() || !std::isfinite(value.get<double>())) {
            fail(source_, path, "expected a finite number, found " + describe(value));
        }
        return value.get<double>();
    }

    int read_frames(const Json& value) {
        const std::string path = child_path(kPath, "frames");
        if (!value.is_number_integer()) {
            fail(source_, path, "expected an integer number of frames, found " + describe(value));
        }
        // Compared as JSON so that a value past long long is refused, not wrapped.
        if (value < Json(kMinSequenceFrames) || value > Json(kMaxSequenceFrames)) {
            fail(source_, path,
                 fmt::format("{} is not in {}..{}", value.dump(), kMinSequenceFrames,
                             kMaxSequenceFrames));
        }
        return value.get<int>();
    }

    // dx_px, dy_px: optional, 0 by default (a pan along one axis names one).
    double step_px(const Json& object, const char* key) {
        if (!object.contains(key)) return 0.0;
        const std::string path = child_path(kPath, key);
        const double v = real(object[key], path);
        if (!(std::abs(v) <= kMaxStepPx)) {
            fail(source_, path,
                 fmt::format("{} is beyond the limit of {} px per frame", Json(v).dump(),
                             kMaxStepPx));
        }
        return v;
    }

    // eye_step, target_step: optional, [0, 0, 0] by default (a dolly moves the eye only).
    glm::dvec3 path_step(const Json& object, const char* key) {
        if (!object.contains(key)) return glm::dvec3(0.0);
        const std::string path = child_path(kPath, key);
        const Json& value = object[key];
        if (!(value.is_array() && value.size() == 3)) {
            fail(source_, path,
                 "expected a vector [x, y, z] of three finite numbers, found " + describe(value));
        }
        glm::dvec3 v;
        for (std::size_t k = 0; k < 3; ++k) {
            v[k] = real(value[k], child_path(path, k));
            if (!(std::abs(v[k]) <= kMaxPathStep)) {
                fail(source_, child_path(path, k),
                     fmt::format("{} is beyond the limit of 1e96 world units per frame",
                                 Json(v[k]).dump()));
            }
        }
        return v;
    }

    const std::string& source_;
};

std::string number(double value, const std::string& path) {
    if (!std::isfinite(value)) {
        throw InputError(fmt::format("scene_to_json: {}: {} is not finite and JSON cannot hold it",
                                     path, value));
    }
    return Json(value).dump();
}

std::string vector3(const glm::dvec3& v, const std::string& path) {
    return fmt::format("[{},{},{}]", number(v.x, child_path(path, 0)),
                       number(v.y, child_path(path, 1)), number(v.z, child_path(path, 2)));
}

}  // namespace

SceneSequence read_sequence(const Json& value, const std::string& source, const Scene& scene) {
    return SequenceReader(source).read(value, scene);
}

std::string sequence_to_json(const SceneSequence& sequence, bool world) {
    std::string out = "{";
    if (sequence.frames) out += fmt::format("\"frames\": {}, ", *sequence.frames);
    out += fmt::format("\"motion\": \"{}\"", motion_name(sequence.motion, world));
    const std::string path = kPath;
    switch (sequence.motion) {
        case SequenceMotion::kStill:
            break;
        case SequenceMotion::kTranslate:
            out += fmt::format(", \"dx_px\": {}, \"dy_px\": {}",
                               number(sequence.dx_px, child_path(path, "dx_px")),
                               number(sequence.dy_px, child_path(path, "dy_px")));
            break;
        case SequenceMotion::kPath:
            out += fmt::format(", \"eye_step\": {}, \"target_step\": {}",
                               vector3(sequence.eye_step, child_path(path, "eye_step")),
                               vector3(sequence.target_step, child_path(path, "target_step")));
            break;
        case SequenceMotion::kOrbit:
            out += fmt::format(", \"orbit_deg\": {}",
                               number(sequence.orbit_deg, child_path(path, "orbit_deg")));
            break;
    }
    return out + "}";
}

}  // namespace aabench::scene_io_detail
