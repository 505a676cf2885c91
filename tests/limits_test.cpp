// Job limits and the memory estimate (harness/measure/limits.h, docs/limits.md): the scene measure
// counts what the allocations scale with, without overflowing on far-away coordinates; the
// estimate grows with what it should and refuses a job over budget with the estimate in the
// message; the task limit names where it was exceeded.
#include "harness/measure/limits.h"

#include <gtest/gtest.h>

#include <string>

#include "harness/world/frame.h"
#include "methods/method.h"

namespace aabench {
namespace {

Scene triangle_scene(int width, int height) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    // Rows 2..9 and columns 1..7 for the slanted edges; the horizontal edge spans no rows.
    scene.shapes.push_back({{{{1.5, 2.5}, {7.5, 2.5}, {4.0, 9.5}}}, 1.0});
    return scene;
}

TEST(Limits, MeasureCountsVerticesRowsAndColumns) {
    const SceneSize s = measure_scene(triangle_scene(16, 12));
    EXPECT_EQ(s.width, 16);
    EXPECT_EQ(s.height, 12);
    EXPECT_EQ(s.shapes, 1);
    EXPECT_EQ(s.contours, 1);
    EXPECT_EQ(s.vertices, 3);
    // Two slanted edges over rows 2..9 (8 rows each); the horizontal one over none.
    EXPECT_EQ(s.edge_rows, 16);
    // Columns: [1, 8) for the top edge, [4, 8) and [1, 4) for the others.
    EXPECT_EQ(s.edge_columns, 7 + 4 + 3);
}

TEST(Limits, MeasureClipsFarCoordinatesAndHonoursTheOrigin) {
    Scene scene = triangle_scene(16, 12);
    scene.shapes.push_back({{{{-1e300, -1e300}, {1e300, -1e300}, {0, 1e300}}}, 1.0});
    const SceneSize s = measure_scene(scene);
    // The huge triangle's two slanted edges overlap every row: clipped, not overflowed.
    EXPECT_EQ(s.edge_rows, 16 + 2 * 12);
    Scene far = triangle_scene(16, 12);
    far.origin_x = far.origin_y = 0x1p30;
    for (Point& p : far.shapes[0].contours[0]) p = {p.x + 0x1p30, p.y + 0x1p30};
    EXPECT_EQ(measure_scene(window_scene(far)).edge_rows, 16);
}

TEST(Limits, EstimateGrowsWithPixelsRowsAndMethods) {
    const SceneSize small = measure_scene(triangle_scene(64, 64));
    const SceneSize large = measure_scene(triangle_scene(1024, 1024));
    const std::vector<std::string> methods = {"none", "exact", "ssaa:filter=gaussian"};
    const std::size_t a = estimate_job_bytes(small, methods, {"box"});
    const std::size_t b = estimate_job_bytes(large, methods, {"box"});
    EXPECT_GT(b, a);
    // At least the kept images: three float32 images and one double raster.
    EXPECT_GE(b, (3u * 4u + 8u) * 1024u * 1024u);
    // More references, more kept rasters; parallel tasks, more working memory.
    EXPECT_GT(estimate_job_bytes(large, methods, {"box", "gaussian", "cone"}), b);
    EXPECT_GT(estimate_job_bytes(large, methods, {"box"}, 4), b);
    // Tall edges make the edge table's buckets the big part.
    SceneSize tall = large;
    tall.vertices = 1'000'000;
    tall.edge_rows = 1'000'000LL * 60000;
    EXPECT_GT(estimate_job_bytes(tall, {"none"}, {}), std::size_t{200} << 30);
}

TEST(Limits, EstimateChecksSpecs) {
    const SceneSize s = measure_scene(triangle_scene(8, 8));
    EXPECT_THROW(estimate_job_bytes(s, {"no-such-method"}, {}), InputError);
    EXPECT_THROW(estimate_job_bytes(s, {"none"}, {"triangle"}), InputError);
    // Every registered method is known to the estimate.
    for (const MethodInfo& info : method_registry()) {
        EXPECT_GT(estimate_job_bytes(s, {info.id}, {}), 0u) << info.id;
    }
}

TEST(Limits, OverBudgetJobIsRefusedWithTheEstimate) {
    EXPECT_NO_THROW(check_job_memory(std::size_t{1} << 30, kDefaultMemoryBudgetBytes, "job"));
    try {
        check_job_memory((std::size_t{123} << 30) / 10, kDefaultMemoryBudgetBytes,
                         "compare --size 65536x1024");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "compare --size 65536x1024: needs about 12.3 GiB by estimate, more than the "
                  "memory budget of 8.0 GiB (docs/limits.md)");
    }
}

TEST(Limits, TaskCountIsLimited) {
    EXPECT_NO_THROW(check_task_count(kMaxCompareTasks, "--sweep"));
    try {
        check_task_count(kMaxCompareTasks + 1, "--sweep");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("--sweep: 100001 tasks", 0), 0u) << e.what();
    }
}

TEST(Limits, FormatsBytesReadably) {
    EXPECT_EQ(format_bytes(17), "17 bytes");
    EXPECT_EQ(format_bytes(5 * 1024), "5.0 KiB");
    EXPECT_EQ(format_bytes(std::size_t{840} << 20), "840 MiB");
    EXPECT_EQ(format_bytes(std::size_t{8} << 30), "8.0 GiB");
}

}  // namespace
}  // namespace aabench
