// The motion of a sequence, as a scene file carries it (version 3, docs/scene-format.md) and as
// the built-in sequences do (harness/world/sequence.h, which says what each motion moves and
// how frames, motion vectors and disocclusions follow from it). Pure data here, below the
// world stages, so that a Scene can hold its sequence.
#pragma once

#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "patterns/scene/world.h"

namespace aabench {

enum class SequenceMotion { kStill, kTranslate, kPath, kOrbit };

// What moves from one frame to the next. Only the fields of `motion` are read.
struct SequenceSteps {
    SequenceMotion motion = SequenceMotion::kStill;
    double dx_px = 0.0;  // kTranslate: per frame (a world: its camera pan at the target's depth)
    double dy_px = 0.0;
    glm::dvec3 eye_step{0.0};  // kPath: world units per frame
    glm::dvec3 target_step{0.0};
    double orbit_deg = 0.0;  // kOrbit: per frame
    bool operator==(const SequenceSteps&) const = default;
};

// A scene file's sequence: its steps and, when the file gives it, its number of frames (else
// the runner's, `compare --frames`, default 32).
struct SceneSequence : SequenceSteps {
    std::optional<int> frames;
    bool operator==(const SceneSequence&) const = default;
};

// The frames a sequence may have: the runner's range (`compare --frames`): two frames are the
// least with a motion, 10,000 bound the run's memory (a reference image per frame).
inline constexpr int kMinSequenceFrames = 2;
inline constexpr int kMaxSequenceFrames = 10000;

// The camera of frame t of a path: eye + t eye_step, target + t target_step (the rest kept).
inline Camera path_camera(const Camera& camera, const SequenceSteps& steps, int t) {
    Camera moved = camera;
    moved.eye += static_cast<double>(t) * steps.eye_step;
    moved.target += static_cast<double>(t) * steps.target_step;
    return moved;
}

// The first frame t in 1..frames-1 at which a camera path leaves no view (the eye on the
// target, or `up` parallel to the view direction, by check_world's rule), with what is wrong;
// {0, ""} when every frame has a view.
struct PathProblem {
    int frame = 0;
    std::string problem;
};
PathProblem first_path_problem(const Camera& camera, const SequenceSteps& steps, int frames);

}  // namespace aabench
