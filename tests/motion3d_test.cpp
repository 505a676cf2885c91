// Motion in 3-D (harness/measure/symptoms.h): the camera moved in sub-pixel steps, each frame
// through the world stages again; methods with their own visibility draw each frame's
// ScreenScene.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/glm.hpp>

#include "harness/measure/symptoms.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

// The projection of a point 1e2 world units away in double: a few ulps of 1e2 px.
constexpr double kProjectionTolerancePx = 1e-9;

Point project(const Camera& camera, int width, int height, const glm::dvec3& p) {
    const glm::dvec3 f = glm::normalize(camera.target - camera.eye);
    const glm::dvec3 r = glm::normalize(glm::cross(f, camera.up));
    const glm::dvec3 u = glm::cross(r, f);
    const glm::dvec3 d = p - camera.eye;
    const double zv = glm::dot(d, f);
    const double focal = 0.5 * height / std::tan(0.5 * glm::radians(camera.fov_y_deg));
    return {0.5 * width + focal * glm::dot(d, r) / zv, 0.5 * height - focal * glm::dot(d, u) / zv};
}

TEST(Motion3D, CameraMoveShiftsTheTargetByTheAskedPixels) {
    for (const PatternInfo& info : pattern_registry()) {
        if (info.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(info.id, 64, 48);
        if (!scene.world) continue;
        const Camera& before = scene.world->camera;
        const Point p0 = project(before, 64, 48, before.target);
        const Scene moved = camera_moved(scene, 0.375, -0.25);
        const Point p1 = project(moved.world->camera, 64, 48, before.target);
        EXPECT_NEAR(p1.x - p0.x, 0.375, kProjectionTolerancePx) << info.id;
        EXPECT_NEAR(p1.y - p0.y, -0.25, kProjectionTolerancePx) << info.id;
    }
}

TEST(Motion3D, FramesGoThroughTheWorldStagesAndOwnVisibilityDrawsScreens) {
    const Scene scene = make_pattern("blocks", 48, 36);
    const MotionReference motion = prepare_motion_reference(scene, 4);
    ASSERT_EQ(motion.prepared.size(), 4u);
    const PreparedFrame still = PreparedFrame::prepare(scene);
    EXPECT_EQ(motion.prepared[0].pieces().scene(), still.pieces().scene());  // offset 0: the scene itself
    EXPECT_EQ(motion.prepared[0].screen(), still.screen());
    EXPECT_NE(motion.prepared[1].pieces().scene(), still.pieces().scene());  // the camera did move
    for (const char* spec : {"box-multiscan", "none", "cairo"}) {
        const MotionStats stats = motion_symptoms(*make_method(spec).method, motion);
        EXPECT_TRUE(std::isfinite(stats.crawl)) << spec;
        EXPECT_GE(stats.crawl, 0.0) << spec;
        std::printf("blocks 48x36, 4 camera steps: crawl of %s = %.5f\n", spec, stats.crawl);
    }
}

}  // namespace
}  // namespace aabench
