// Sequences: a scene and a motion over frames t = 0 .. T-1, with, per frame, its exact motion
// vectors and its disocclusion mask (docs/sequences.md).
//
//   still      nothing moves; t still counts (temporal methods converge on it);
//   translate  a 2-D scene moved by (dx, dy) px per frame; on a world, a camera pan: eye and
//              target moved together so that points at the target's distance move by
//              (dx, dy) px per frame (camera_moved);
//   path       a world whose eye and target move linearly in t (pan, dolly): eye + t eye_step,
//              target + t target_step (world units per frame);
//   orbit      a world whose eye turns about the target, orbit_deg per frame about the
//              camera's up axis through the target.
//
// Motion vectors (methods/motion.h): the surface seen at pixel (x, y)'s centre c was at
// c - (dx, dy) in the previous frame. 2-D: the translation, at every pixel. A world: the point
// of the visible piece's plane at c (its 1/z_v plane in the ScreenScene gives the depth) taken
// back to world space and projected through the previous camera. Where c sees the background,
// the vector is 0 (a renderer clears its velocity buffer so), and the pixel counts as
// disoccluded when the previous frame saw a face there.
//
// Disocclusion: the surface seen at c now was not visible at c - (dx, dy) in the previous frame:
// another face was in front of it there, it was turned away or clipped, or c - (dx, dy) lies
// outside the image (no history exists for it). Frame 0 and a still sequence have none.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "harness/world/frame.h"
#include "methods/motion.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"
#include "patterns/scene/scene_sequence.h"

namespace aabench {

// The scene moved by (dx, dy) px: every shape and every thin object. Metadata unchanged.
Scene translated(const Scene& scene, double dx, double dy);

// A 3-D scene with its camera moved so that points at the target's distance move by (dx, dy)
// px on screen (eye and target shifted together, parallel to the image plane; nearer points
// move more, farther ones less: parallax). A 2-D scene is returned unchanged.
Scene camera_moved(const Scene& scene, double dx_px, double dy_px);

// Default frames of a sequence: 32, so that the steady state (the second half) holds 16 frames,
// twice taa's default 8 jitter positions.
inline constexpr int kDefaultSequenceFrames = 32;
// Default size of a sequence's frames: 96 x 96 keeps a whole `compare --sequences` run (every
// method, every built-in sequence, 32 frames) within a minute or two on two cores.
inline constexpr int kDefaultSequenceSide = 96;

// A sequence's name and motion. The steps (motion, dx_px, dy_px, eye_step, target_step,
// orbit_deg) are SequenceSteps (patterns/scene/scene_sequence.h), which a scene file's
// "sequence" carries one to one (docs/scene-format.md, "Version 3").
struct SequenceSpec : SequenceSteps {
    std::string name;
    std::string summary;
    std::string pattern;  // the pattern spec of frame 0 (a built-in); a scene file's: its path
    // Its pattern reads a model file of a Debian package (PatternInfo::model_file, the mesh
    // models of patterns/models.cpp): the suites that loop over every sequence take it where the
    // file is installed. Such a sequence is not in the default run either (below), so that a run
    // of every built-in neither needs the packages nor spends seconds per frame on a real mesh's
    // visibility.
    bool model_file = false;
    // Run by `compare --sequences` without names; false: only when named (the mesh models', and
    // the colour sequence, whose pattern is not in the default comparison).
    bool in_default_run = true;
};

// The built-in sequences, in the order `aabench list` and `compare --sequences` give them
// (a run of every built-in leaves out those not in_default_run).
const std::vector<SequenceSpec>& sequence_registry();
// The built-in of this name; InputError listing the names for an unknown one.
const SequenceSpec& find_sequence(const std::string& name);

struct Sequence {
    SequenceSpec spec;
    Scene scene;  // frame 0
    int frames = kDefaultSequenceFrames;
};

// `spec`'s pattern made at width x height; frames >= 1 (InputError naming the sequence
// otherwise, and for a path that leaves a frame with no view).
Sequence make_sequence(const SequenceSpec& spec, int width, int height, int frames);
// A sequence on a given scene: the motion of `spec`, frame 0 `scene`.
Sequence make_sequence(const SequenceSpec& spec, Scene scene, int frames);

// A scene file's sequence (Scene::sequence, scene file version 3) named `name` (the rows'
// name: the file stem), from `path`: frame 0 the scene, its frames the file's or, when it
// gives none, `default_frames`. InputError naming `path` when the scene carries no sequence.
Sequence file_sequence(Scene scene, const std::string& name, const std::string& path,
                       int default_frames);
// A built-in sequence as a scene file holds it: its pattern at width x height carrying its
// steps, and `frames` when given (`aabench export --sequence`). file_sequence() of it is the
// built-in, frame for frame.
Scene sequence_scene(const SequenceSpec& spec, int width, int height, std::optional<int> frames);
// "translate (0.6, 0.35) px per frame", "orbit 1 degree per frame": a motion in words.
std::string describe_steps(const SequenceSteps& steps, bool world);

// The scene of frame t (frame 0 is sequence.scene).
Scene frame_scene(const Sequence& sequence, int t);
// The camera of frame t of a world sequence.
Camera frame_camera(const Sequence& sequence, int t);

// A frame's motion: its vectors (empty on frame 0 and on a still sequence) and its
// disocclusion mask (1: disoccluded; all 0 on frame 0 and on a still sequence).
struct FrameMotion {
    MotionVectors vectors;
    Raster<std::uint8_t> disoccluded;
};

// The motion of frame t >= 1 given the prepared frames t - 1 and t (their screen() scenes);
// frame 0's for t = 0 (then `previous` is not read).
FrameMotion frame_motion(const Sequence& sequence, const PreparedFrame& previous,
                         const PreparedFrame& current, int t);

// The point in a ScreenScene seen at (x, y): the index of the nearest shape containing it
// (largest inv_depth; the later one among equals, as 2-D compositing), or -1 for the
// background. Nonzero winding over the shape's contours.
int visible_shape_at(const Scene& screen, double x, double y);

}  // namespace aabench
