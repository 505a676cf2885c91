// The plan and the pipeline: the plan follows from the scene (each built-in pattern and
// hand-made scenes), and a stage the plan leaves out is never called: no time, no allocation,
// no depth plane.
#include <gtest/gtest.h>

#include "harness/world/alloc_count.h"
#include "harness/world/frame.h"
#include "harness/world/plan.h"
#include "harness/world/stages.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

Object unit_box(const std::string& name, glm::dvec3 lo, glm::dvec3 hi) {
    Object o;
    o.name = name;
    o.vertices = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                  {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    const int loops[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    for (const auto& l : loops) {
        Face f;
        f.loop = {l[0], l[1], l[2], l[3]};
        o.faces.push_back(f);
    }
    return o;
}

Scene world_scene(World w) {
    Scene s;
    s.width = 64;
    s.height = 48;
    w.camera.eye = {3.1, 2.3, 4.7};
    w.camera.target = {0.01, 0.02, -0.03};
    s.world = std::move(w);
    return s;
}

Object floor_quad() {
    Object o;
    o.name = "floor";
    o.closed = false;
    o.vertices = {{-3, -1, 3}, {3, -1, 3}, {3, -1, -3}, {-3, -1, -3}};
    Face f;
    f.loop = {0, 1, 2, 3};
    o.faces.push_back(f);
    return o;
}

TEST(Plan, TwoDimensionalPatternsRunNoStage) {
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(p.id, 32, 32);
        if (scene.world) continue;
        const Plan plan = make_plan(scene);
        for (int k = 0; k < kStageCount; ++k) {
            EXPECT_FALSE(plan.stages[k].in) << p.id << " " << stage_name(static_cast<Stage>(k));
        }
    }
}

TEST(Plan, EachThreeDimensionalPatternGetsTheStagesItCallsFor) {
    struct Expect {
        const char* id;
        bool culling, patterns, shadows, shading, visibility;
    };
    for (const Expect& e : {Expect{"room", true, true, true, true, true},
                            Expect{"blocks", true, false, true, true, true},
                            Expect{"interpenetrate", true, false, false, false, true},
                            Expect{"mesh", true, false, false, true, false},
                            Expect{"terrain", false, false, false, true, true}}) {
        const Plan plan = make_plan(make_pattern(e.id, 64, 64));
        EXPECT_TRUE(plan.in(Stage::kProjection)) << e.id;
        EXPECT_EQ(plan.in(Stage::kCulling), e.culling) << e.id;
        EXPECT_EQ(plan.in(Stage::kPatterns), e.patterns) << e.id;
        EXPECT_EQ(plan.in(Stage::kShadows), e.shadows) << e.id;
        EXPECT_EQ(plan.in(Stage::kShading), e.shading) << e.id;
        EXPECT_EQ(plan.in(Stage::kVisibility), e.visibility) << e.id;
        EXPECT_FALSE(plan.in(Stage::kDepthImage)) << e.id;
        for (const StageDecision& d : plan.stages) EXPECT_FALSE(d.reason.empty()) << e.id;
    }
}

TEST(ZeroCost, ThreeDimensionalPatternsRunExactlyThePlannedStages) {
    for (const char* id : {"room", "blocks", "interpenetrate", "mesh", "terrain"}) {
        const Scene scene = make_pattern(id, 64, 64);
        const Plan plan = make_plan(scene);
        const PreparedFrame r = PreparedFrame::prepare(scene);
        EXPECT_FALSE(r.pieces().scene().shapes.empty()) << id;  // the visible pieces, built on demand
        // Edges run after the method (PreparedFrame::after_method); reflections only with
        // mirrors (tests/reflections_test.cpp): none of these patterns has either.
        const StageCosts costs = r.costs();
        for (int k = 0; k < static_cast<int>(Stage::kEdges); ++k) {
            EXPECT_EQ(costs[k].ran, plan.stages[k].in) << id << " " << stage_name(static_cast<Stage>(k));
            if (!plan.stages[k].in) {
                EXPECT_EQ(costs[k].bytes, 0u) << id;
            }
        }
    }
}

TEST(Plan, OneClosedConvexBoxNeedsCullingOnly) {
    World w;
    w.objects.push_back(unit_box("box", {-1, -1, -1}, {1, 1, 1}));
    const Plan plan = make_plan(world_scene(w));
    EXPECT_TRUE(plan.in(Stage::kProjection));
    EXPECT_TRUE(plan.in(Stage::kCulling));
    EXPECT_FALSE(plan.in(Stage::kVisibility));
    EXPECT_NE(plan[Stage::kVisibility].reason.find("one closed convex object"), std::string::npos);
    EXPECT_FALSE(plan.in(Stage::kShading));
    EXPECT_NE(plan[Stage::kShading].reason.find("no lights"), std::string::npos);
    EXPECT_FALSE(plan.in(Stage::kShadows));
    EXPECT_FALSE(plan.in(Stage::kPatterns));
    EXPECT_FALSE(plan.in(Stage::kDepthImage));
    EXPECT_EQ(plan[Stage::kDepthImage].reason, "no edges asked");
    EXPECT_TRUE(make_plan(world_scene(w), {.depth_image = true}).in(Stage::kDepthImage));
}

TEST(Plan, ABoxOnAFloorUnderAShadowingLightCastsOntoTheFloor) {
    World w;
    w.objects.push_back(floor_quad());
    w.objects.push_back(unit_box("block", {-0.5, -1, -0.5}, {0.5, 0, 0.5}));
    Light sun;
    sun.direction = {-1, -2, -1.5};
    sun.shadows = true;
    w.lights.push_back(sun);
    const Plan plan = make_plan(world_scene(w));
    EXPECT_TRUE(plan.in(Stage::kShadows));
    EXPECT_NE(plan[Stage::kShadows].reason.find("light 0 may cast: 'block' -> 'floor'"),
              std::string::npos)
        << plan[Stage::kShadows].reason;
    // The floor is below the block: it casts onto nothing.
    EXPECT_EQ(plan[Stage::kShadows].reason.find("'floor' ->"), std::string::npos);
    EXPECT_TRUE(plan.in(Stage::kVisibility));
    EXPECT_TRUE(plan.in(Stage::kShading));
    w.effects.shadows = false;
    EXPECT_FALSE(make_plan(world_scene(w)).in(Stage::kShadows));
}

TEST(Plan, EdgesAskForTheDepthImage) {
    World w;
    w.objects.push_back(unit_box("box", {-1, -1, -1}, {1, 1, 1}));
    w.edges = EdgesSpec{};
    const Plan plan = make_plan(world_scene(w));
    EXPECT_TRUE(plan.in(Stage::kDepthImage));
    EXPECT_TRUE(plan.in(Stage::kEdges));
    EXPECT_FALSE(plan.in(Stage::kReflections));
    w.effects.edges = false;
    EXPECT_FALSE(make_plan(world_scene(w)).in(Stage::kDepthImage));
}

TEST(ZeroCost, ATwoDimensionalPatternCallsNoStageAndBuildsNoDepth) {
    const Scene star = make_pattern("star", 64, 64);
    reset_stage_work_counts();
    const PreparedFrame r = PreparedFrame::prepare(star);
    EXPECT_EQ(r.pieces().scene(), star);
    EXPECT_EQ(&r.input_for(*make_method("none").method).scene(), &r.input_for(*make_method("exact").method).scene());
    for (const StageCost& c : r.costs()) {
        EXPECT_FALSE(c.ran);
        EXPECT_EQ(c.bytes, 0u);
        EXPECT_EQ(c.time_ms, 0.0);
    }
    EXPECT_FALSE(r.has_depth_stage());
    for (const Shape& s : r.pieces().scene().shapes) EXPECT_FALSE(s.inv_depth.has_value());
    const StageWorkCounts n = stage_work_counts();
    EXPECT_EQ(n.collect_faces + n.cull_back_faces + n.cut_patterns + n.cast_shadows +
                  n.shadow_on_face + n.shade + n.project_cells + n.visible_pieces +
                  n.optical_path_depth,
              0);
}

TEST(ZeroCost, LeftOutStagesAreNotCalledAndRunStagesAreMeasured) {
    World w;  // one closed convex box, no lights, no patterns: projection and culling only
    w.objects.push_back(unit_box("box", {-1, -1, -1}, {1, 1, 1}));
    const Scene scene = world_scene(w);
    const PreparedFrame r = PreparedFrame::prepare(scene);
    EXPECT_EQ(r.pieces().scene().shapes.size(), 3u);  // three faces of a box seen from a corner
    const StageCosts costs = r.costs();
    for (Stage s : {Stage::kPatterns, Stage::kShadows, Stage::kShading, Stage::kVisibility,
                    Stage::kDepthImage, Stage::kEdges, Stage::kReflections}) {
        const StageCost& c = costs[static_cast<int>(s)];
        EXPECT_FALSE(c.ran) << stage_name(s);
        EXPECT_EQ(c.bytes, 0u) << stage_name(s);
        EXPECT_EQ(c.allocations, 0u) << stage_name(s);
    }
    const StageCost& proj = costs[static_cast<int>(Stage::kProjection)];
    EXPECT_TRUE(proj.ran);
    EXPECT_GT(proj.bytes, 0u);  // the counter sees the faces being built
    EXPECT_GT(proj.time_ms, 0.0);
    EXPECT_TRUE(costs[static_cast<int>(Stage::kCulling)].ran);
    EXPECT_FALSE(r.has_depth_stage());
}

TEST(ZeroCost, TheAllocationCounterCountsThisThread) {
    const AllocCounts before = thread_alloc_counts();
    std::vector<double> v(1000);
    const AllocCounts after = thread_alloc_counts();
    EXPECT_GE(after.bytes - before.bytes, v.size() * sizeof(double));
    EXPECT_GE(after.allocations - before.allocations, 1u);
}

TEST(Pipeline, DepthSceneCarriesFSquaredOverZ) {
    World w;
    w.objects.push_back(unit_box("box", {-1, -1, -1}, {1, 1, 1}));
    const Scene scene = world_scene(w);
    const PreparedFrame r = PreparedFrame::prepare(scene, {.depth_image = true});
    ASSERT_TRUE(r.has_depth_stage());
    EXPECT_EQ(r.depth_pieces().scene().background, 0.0);
    ASSERT_EQ(r.depth_pieces().scene().shapes.size(), r.pieces().scene().shapes.size());
    for (const Shape& s : r.depth_pieces().scene().shapes) {
        ASSERT_TRUE(s.value_plane.has_value());
        // Positive depth everywhere on the screen near the box: z_s = f^2 / z_v > 0.
        EXPECT_GT(s.value_plane->at(32, 24), 0.0);
    }
}


// Each stage's work runs at most once per prepared frame, the planner's decisions included (the
// counters sit in the functions that do the work), whatever is asked of the frame afterwards:
// every method's input, the pieces again, the depth scenes, the stages after a method.
TEST(PreparedFrame, EveryStageRunsAtMostOncePerFrameOnEvery3DPattern) {
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(p.id, 48, 40);
        if (!scene.world) continue;
        reset_stage_work_counts();
        const PreparedFrame frame = PreparedFrame::prepare(scene, {.depth_image = true});
        for (const MethodInfo& info : method_registry()) {
            const MethodInstance m = make_method(info.id);
            const SceneInput input = frame.input_for(*m.method);
            if (!m.method->affine_values() || !m.method->not_applicable(input.scene()).empty()) {
                continue;
            }
            const Image shaded = render_scene(*m.method, input);
            (void)frame.after_method(*m.method, m.spec, shaded, /*want_depth=*/true);
        }
        (void)frame.pieces();
        (void)frame.depth_pieces();
        const StageWorkCounts n = stage_work_counts();
        const Plan& plan = frame.plan();
        EXPECT_EQ(n.collect_faces, 1) << p.id;
        EXPECT_EQ(n.cull_back_faces, plan.in(Stage::kCulling) ? 1 : 0) << p.id;
        EXPECT_EQ(n.cut_patterns, plan.in(Stage::kPatterns) ? 1 : 0) << p.id;
        EXPECT_EQ(n.cast_shadows, plan.in(Stage::kShadows) ? 1 : 0) << p.id;
        EXPECT_EQ(n.shade, plan.in(Stage::kShading) ? 1 : 0) << p.id;
        EXPECT_EQ(n.project_cells, 1) << p.id;
        EXPECT_EQ(n.visible_pieces, plan.in(Stage::kVisibility) ? 1 : 0) << p.id;
        EXPECT_EQ(n.optical_path_depth, plan.in(Stage::kReflections) ? 1 : 0) << p.id;
        // Shadow clipping happens only inside the shadow stage: at most one clipping per
        // (light, caster face, receiver face), never in the planner.
        if (!plan.in(Stage::kShadows)) {
            EXPECT_EQ(n.shadow_on_face, 0) << p.id;
        } else {
            const long long faces = static_cast<long long>(scene.world->face_count());
            const long long lights = static_cast<long long>(scene.world->lights.size());
            EXPECT_LE(n.shadow_on_face, lights * faces * faces) << p.id;
        }
    }
}

// A method that removes hidden surfaces itself never waits for the exact visible pieces: the
// frame builds them only when a reference or a pieces-drawing method asks.
TEST(PreparedFrame, OwnVisibilityMethodsDoNotBuildTheVisiblePieces) {
    const Scene scene = make_pattern("blocks", 48, 40);
    reset_stage_work_counts();
    const PreparedFrame frame = PreparedFrame::prepare(scene);
    const MethodInstance none = make_method("none");
    ASSERT_TRUE(none.method->own_visibility());
    EXPECT_EQ(&frame.input_for(*none.method).scene(), &frame.screen());
    EXPECT_EQ(stage_work_counts().visible_pieces, 0);
    EXPECT_FALSE(frame.costs()[static_cast<int>(Stage::kVisibility)].ran);
    EXPECT_EQ(frame.relied_stage_ms(*none.method), frame.relied_stage_ms(*none.method));
    const MethodInstance exact = make_method("exact");
    EXPECT_EQ(&frame.input_for(*exact.method).scene(), &frame.pieces().scene());
    EXPECT_EQ(stage_work_counts().visible_pieces, 1);
    // Charged to the method that draws the pieces, not to the one that does its own.
    const double vis_ms = frame.costs()[static_cast<int>(Stage::kVisibility)].time_ms;
    EXPECT_GT(vis_ms, 0.0);
    EXPECT_DOUBLE_EQ(frame.relied_stage_ms(*exact.method) - frame.relied_stage_ms(*none.method),
                     vis_ms);
}

}  // namespace
}  // namespace aabench
