// The world pipeline: a scene (2-D or 3-D) through the stages its plan keeps, each timed and
// its heap allocation counted. A 2-D scene passes through untouched: no stage is called.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "harness/world/edges.h"
#include "harness/world/plan.h"
#include "methods/method.h"
#include "patterns/scene/scene.h"

namespace aabench {

struct StageCost {
    bool ran = false;  // false: the plan left it out and it was never called
    double time_ms = 0.0;
    std::uint64_t bytes = 0;        // heap bytes allocated by the stage (harness/world/alloc_count.h)
    std::uint64_t allocations = 0;
    std::string detail;  // what it did: "culled 6 of 12 faces", "3 shadows fell", ...
};

struct WorldRender {
    Plan plan;
    // The ScreenScene: every visible face's cells as 2-D convex shapes with their face's depth
    // plane, value, face and role; they may overlap (hidden surfaces are still in it).
    Scene screen;
    // What every method draws and every reference measures: the visible pieces, disjoint,
    // constant-valued, depth planes dropped (faces and roles kept). For a 2-D scene, the scene.
    Scene pieces;
    // The depth image's scene (value z_s = f^2 / z_v, affine on each piece; background 0), only
    // when the plan has the depth stage.
    std::optional<Scene> depth;
    // The optical-path depth image of eq. 9 (harness/world/reflections.h), ray cast, only when
    // the plan has the reflections stage (mirrors and edges): the edge stage reads it instead of
    // the method's depth image.
    std::optional<Image> optical_depth;
    double focal_px = 0.0;
    // Edges shared by two visible faces of one object, on screen (3-D only; the seams
    // symptom measures the error where they run).
    std::vector<std::array<Point, 2>> shared_edges;
    std::array<StageCost, kStageCount> costs;
};

WorldRender render_world(const Scene& scene, const Plan& plan);

// The depth image drawn by `method` from render.depth (the plan must have the depth stage), so
// that it is antialiased the way the method antialiases values (Saito & Takahashi 1990, §3.5); its
// time and bytes are added to the depth stage's cost. A method that cannot draw affine values
// (Method::affine_values) is an InputError naming it (`method_name`).
Image render_depth_image(WorldRender& render, const Method& method, const std::string& method_name);

// The ScreenScene with each cell's value its z_s plane and its depth plane kept: what a method
// with its own visibility draws for the depth image (render_depth_image). Needs the depth stage.
Scene depth_valued_screen(const WorldRender& render);

// The edge stage (harness/world/edges.h) on a method's depth and shaded images, timed and its
// allocations counted as the plan's edge stage. Throws std::logic_error when the plan has no
// edge stage (the caller asked for what the scene does not call for).
EdgeImages run_edge_stage(WorldRender& render, const EdgesSpec& spec, const Image& depth,
                          const Image& shaded);

// The scene methods draw: the scene itself when 2-D, the visible pieces when 3-D.
Scene drawable_scene(const Scene& scene);
// The scene `method` draws: for a method with its own visibility (Method::own_visibility())
// the ScreenScene, for the others the visible pieces; for a 2-D scene the scene itself.
Scene drawable_scene(const Scene& scene, const Method& method);
const Scene& scene_for(const WorldRender& render, const Method& method);

// "stage  ran  time_ms  bytes  allocations  detail" lines for render --stats.
std::string format_stage_costs(const WorldRender& render);

}  // namespace aabench
