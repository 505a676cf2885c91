// The prepared frame: everything a method, a reference or a metric needs for one image of one
// scene, built once by this room and then only read (docs/world.md, "The prepared frame").
//
//   request  the scene, what is asked beyond what it calls for (a depth image), and the frame's
//            place in a sequence (time t);
//   plan     which stages run, and why (harness/world/plan.h), decided from cheap tests on the
//            scene: the planner never does a stage's work;
//   window   a 2-D scene's window origin (Scene::origin_x/y) taken out, once: every input
//            below is in the window frame (in_window_frame, patterns/scene/scene.h), which is
//            what methods, references and metrics take (methods/method.h);
//   stages   run once each: for a 2-D scene nothing runs and every input is the scene itself
//            in its window frame; for a world the ScreenScene (every visible face's cells with
//            their depth planes, overlapping), the exact visible pieces (disjoint; built on first
//            use, when a reference, a metric or a method that draws pieces asks), the depth
//            scenes and the optical-path depth;
//   input_for(method)  what that method draws: the ScreenScene for a method that removes hidden
//            surfaces itself, the visible pieces for the others;
//   after the method: its depth image and the edge stage, run by the frame (after_method);
//   cost     per stage its time and heap bytes; relied_stage_ms(method) is the share of the
//            world stages a method's reported time includes (the visibility stage only for a
//            method that draws the visible pieces).
//
// A frame is read from many threads at once (compare scores its tasks in parallel): every
// accessor is const and thread-safe, the lazily built visible pieces included.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "harness/world/edges.h"
#include "harness/world/plan.h"
#include "methods/method.h"
#include "patterns/scene/scene.h"

namespace aabench {

struct StageCost {
    bool ran = false;  // false: the plan left it out (or it was not needed) and was never called
    double time_ms = 0.0;
    std::uint64_t bytes = 0;  // heap bytes allocated by the stage (harness/world/alloc_count.h)
    std::uint64_t allocations = 0;
    std::string detail;  // what it did: "culled 6 of 12 faces", "3 shadows fell", ...

    // Another run (or part) of the same stage added to this one; a part that did not run adds
    // nothing.
    void add(const StageCost& part) {
        if (!part.ran) return;
        ran = true;
        time_ms += part.time_ms;
        bytes += part.bytes;
        allocations += part.allocations;
        if (!part.detail.empty()) detail = part.detail;
    }
};

using StageCosts = std::array<StageCost, kStageCount>;

// What is asked of a frame beyond what the scene calls for.
struct FrameRequest {
    bool depth_image = false;  // render --depth-out, reference --depth, plan --depth
    // The frame's place in a sequence: its index and time t (frames of one sequence differ by
    // the motion applied to the scene before it is prepared; a still image is frame 0, t = 0).
    int frame_index = 0;
    double time = 0.0;
};

// The stages that run after a method, on its image: its depth image (drawn the way it draws
// values) and the edge stage on it, with what each cost.
struct AfterMethod {
    std::optional<Image> depth;       // the method's depth image, when asked or needed
    std::optional<EdgeImages> edges;  // the edge stage's output, when the plan has it
    StageCost depth_cost;
    StageCost edge_cost;
};

class PreparedFrame {
public:
    // Plans the scene and runs the stages the plan keeps (all but the visible pieces, which are
    // built on first use). 2-D scenes run no stage.
    static PreparedFrame prepare(const Scene& scene, const FrameRequest& request = {});

    PreparedFrame(PreparedFrame&&) noexcept;
    PreparedFrame& operator=(PreparedFrame&&) noexcept;
    ~PreparedFrame();

    const FrameRequest& request() const;
    const Plan& plan() const;
    bool is_world() const;
    // The scene as given (a world keeps its camera, lights and objects; a 2-D scene its window
    // origin): for what moves or rewrites the scene before preparing it anew (the motion
    // symptoms), never an input of a method, a reference or a metric.
    const Scene& given() const;
    // The ScreenScene: every visible face's cells, with depth planes, overlapping (3-D); the
    // scene itself in its window frame (2-D).
    const Scene& screen() const;
    // The exact visible pieces, disjoint, constant-valued, depth planes dropped: what every
    // reference measures (3-D; built on first call, the visibility stage's cost recorded then);
    // the scene itself in its window frame (2-D). Handed on as disjoint pieces when exact
    // visibility made them (patterns/scene/scene_input.h), so references and `exact` integrate
    // them as they are: pass the SceneInput on, not its scene().
    SceneInput pieces() const;
    // The overlay (harness/world/overlay.h): every visible face whole with its patterns and
    // its shadow layer laid over it, depth planes kept, built on first call (3-D); the scene
    // itself in its window frame (2-D).
    const Scene& overlay() const;
    // What `method` draws (its traits decide): screen() for a method that removes hidden
    // surfaces itself, overlay() in its place for one that takes coplanar overlays (the
    // scanline methods) on a world with patterns or shadows, pieces() for the others.
    SceneInput input_for(const Method& method) const;
    // True when input_for(method) is the overlay.
    bool draws_overlay(const MethodTraits& traits) const;
    // True when input_for(method) needs the visible pieces of a world: the one place that
    // decides it, from the method's traits (a method without own visibility draws pieces).
    bool needs_pieces(const MethodTraits& traits) const;
    bool needs_pieces(const Method& method) const { return needs_pieces(method.traits()); }

    double focal_px() const;
    // Edges shared by two visible faces of one object, on screen (3-D; the seams symptom).
    const std::vector<std::array<Point, 2>>& shared_edges() const;

    // Post-method inputs (the plan's depth stage): the depth pieces (value z_s = f d / z_v on
    // each visible piece, background 0), and the ScreenScene with each cell's value its z_s
    // plane and depth planes kept (what a method with its own visibility draws for depth).
    bool has_depth_stage() const;
    SceneInput depth_pieces() const;  // disjoint as pieces() are
    const Scene& depth_screen() const;
    // The optical-path depth of eq. 9 (Saito & Takahashi 1990), ray cast: with mirrors and edges.
    const std::optional<Image>& optical_depth() const;

    // The stages after `method` drew `shaded`: the method's depth image when `want_depth` or
    // when the edge stage needs it (not with an optical-path depth, which the edge stage reads
    // instead), then the edge stage when the plan has it. A method that cannot draw a depth
    // image it needs is an InputError naming it (`method_name`).
    AfterMethod after_method(const Method& method, const std::string& method_name,
                             const Image& shaded, bool want_depth = false) const;
    // The edge stage alone on a given depth and shaded image (the reference's line scores, the
    // report's figures and the benchmark), into `out` (whose buffers are reused;
    // harness/world/edges.h); `spec` replaces the scene's edges block (another style) if given.
    void edge_stage(const Image& depth, const Image& shaded, EdgeImages& out,
                    const EdgesSpec* spec = nullptr) const;

    // The cost of each stage that ran so far (the visible pieces' only once built).
    StageCosts costs() const;
    // What the two ways of putting patterns and shadows on faces cost on this frame: the cells'
    // cutting (the patterns stage and the shadows stage's cuts, without casting the shadows,
    // which both need) against the overlay's layering (its shadow layers), each with the shapes
    // it puts on screen. The overlay's figures are zero until it is built.
    struct LayerCosts {
        double cell_cutting_ms = 0.0;
        std::size_t cell_shapes = 0;
        bool overlay_built = false;
        double overlay_layering_ms = 0.0;
        std::size_t overlay_shapes = 0;
        StageCost overlay;  // the whole overlay build: layering, shading, projection
    };
    LayerCosts layer_costs() const;
    // The time of the world stages `method` relies on (ms): every stage that made its input,
    // i.e. all stages before the method except visibility for a method with its own; 0 for a
    // 2-D scene. A method that draws the overlay relies on the faces (projection's first
    // half), culling, the shadows' casting and the overlay's build, not on the cells' cutting,
    // shading and projection. A method's reported time on a world is its own time plus this.
    double relied_stage_ms(const Method& method) const;

private:
    struct State;
    explicit PreparedFrame(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

// `scene` in its window frame, as a prepared frame's inputs are (the same subtraction, for code
// that makes its own variants of a 2-D scene and needs no frame: the hard cases' moved and
// shifted copies, harness/measure/hardcases.h). A scene already in it is returned as it is.
Scene window_scene(Scene scene);

// The one decision of what a method draws: true when `scene` is a world and the method does not
// remove hidden surfaces itself, so it draws the exact visible pieces (PreparedFrame::input_for
// asks it; `aabench plan` lists it per method without preparing the frame).
bool draws_visible_pieces(const Scene& scene, const MethodTraits& traits);

// "stage  plan  time_ms  bytes  allocs  detail" lines, as render --stats and plan --run print.
std::string format_stage_costs(const Plan& plan, const StageCosts& costs);


}  // namespace aabench
