// The plan and the pipeline: the plan follows from the scene (each built-in pattern and
// hand-made scenes), and a stage the plan leaves out is never called: no time, no allocation,
// no depth plane.
#include <gtest/gtest.h>

#include "harness/world/alloc_count.h"
#include "harness/world/pipeline.h"
#include "harness/world/plan.h"
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
        const WorldRender r = render_world(scene, plan);
        // Edges run after the method (render_depth_image, run_edge_stage); reflections only
        // with mirrors (tests/reflections_test.cpp): none of these patterns has either.
        for (int k = 0; k < static_cast<int>(Stage::kEdges); ++k) {
            EXPECT_EQ(r.costs[k].ran, plan.stages[k].in) << id << " " << stage_name(static_cast<Stage>(k));
            if (!plan.stages[k].in) EXPECT_EQ(r.costs[k].bytes, 0u) << id;
        }
        EXPECT_FALSE(r.pieces.shapes.empty()) << id;
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
    EXPECT_NE(plan[Stage::kShadows].reason.find("light 0 casts: 'block' -> 'floor'"),
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
    const WorldRender r = render_world(star, make_plan(star));
    for (const StageCost& c : r.costs) {
        EXPECT_FALSE(c.ran);
        EXPECT_EQ(c.bytes, 0u);
        EXPECT_EQ(c.time_ms, 0.0);
    }
    EXPECT_FALSE(r.depth.has_value());
    for (const Shape& s : r.pieces.shapes) EXPECT_FALSE(s.inv_depth.has_value());
    EXPECT_EQ(r.pieces, star);
}

TEST(ZeroCost, LeftOutStagesAreNotCalledAndRunStagesAreMeasured) {
    World w;  // one closed convex box, no lights, no patterns: projection and culling only
    w.objects.push_back(unit_box("box", {-1, -1, -1}, {1, 1, 1}));
    const Scene scene = world_scene(w);
    const WorldRender r = render_world(scene, make_plan(scene));
    for (Stage s : {Stage::kPatterns, Stage::kShadows, Stage::kShading, Stage::kVisibility,
                    Stage::kDepthImage, Stage::kEdges, Stage::kReflections}) {
        const StageCost& c = r.costs[static_cast<int>(s)];
        EXPECT_FALSE(c.ran) << stage_name(s);
        EXPECT_EQ(c.bytes, 0u) << stage_name(s);
        EXPECT_EQ(c.allocations, 0u) << stage_name(s);
    }
    const StageCost& proj = r.costs[static_cast<int>(Stage::kProjection)];
    EXPECT_TRUE(proj.ran);
    EXPECT_GT(proj.bytes, 0u);  // the counter sees the faces being built
    EXPECT_GT(proj.time_ms, 0.0);
    EXPECT_TRUE(r.costs[static_cast<int>(Stage::kCulling)].ran);
    EXPECT_FALSE(r.depth.has_value());
    EXPECT_EQ(r.pieces.shapes.size(), 3u);  // three faces of a box seen from a corner
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
    const WorldRender r = render_world(scene, make_plan(scene, {.depth_image = true}));
    ASSERT_TRUE(r.depth.has_value());
    EXPECT_EQ(r.depth->background, 0.0);
    ASSERT_EQ(r.depth->shapes.size(), r.pieces.shapes.size());
    for (const Shape& s : r.depth->shapes) {
        ASSERT_TRUE(s.value_plane.has_value());
        // Positive depth everywhere on the screen near the box: z_s = f^2 / z_v > 0.
        EXPECT_GT(s.value_plane->at(32, 24), 0.0);
    }
}

}  // namespace
}  // namespace aabench
