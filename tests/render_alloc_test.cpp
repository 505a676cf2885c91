// No heap allocation inside a timed render: after one warm-up render on this thread, a second
// render of the same scene into the same buffer must make no call to operator new (counted by
// harness/world/alloc_count.h), for every registered method.
//
// What the counter sees: C++ operator new/new[] on the calling thread. Allocations by C
// libraries (Cairo's malloc for paths and patterns) are not seen; cairo keeps its surface
// and context per thread so a warm render creates neither (methods/cairo.cpp).
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "harness/world/alloc_count.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

// The built-in 2-D patterns at 256^2, where every row of them takes exact's crossing-free path.
// A scene whose boundaries cross sends rows to the double band sweep, which builds an
// EdgeTable and so allocates (methods/scan/exact/fast_coverage.cpp): strips at 96^2 is one, its
// strips poking into their neighbours' cells (patterns/strips.cpp).
const std::vector<std::string> kPatterns = {"star", "strips", "grating", "rings", "zoneplate"};
constexpr int kSide = 256;

std::uint64_t allocations_in_render(const Method& method, const Scene& scene, Image& out) {
    const AllocCounts before = thread_alloc_counts();
    method.render(scene, out);
    const AllocCounts after = thread_alloc_counts();
    return after.allocations - before.allocations;
}

TEST(RenderAllocations, WarmRendersAllocateNothing) {
    int checked = 0;
    for (const MethodInfo& info : method_registry()) {
        const MethodInstance m = make_method(info.id);
        for (const std::string& pattern : kPatterns) {
            const Scene scene = make_pattern(pattern, kSide, kSide);
            // A scene the method cannot draw is never timed (compare shows n/a): not checked.
            if (!m.method->not_applicable(scene).empty()) continue;
            Image out(scene.width, scene.height);
            m.method->render(scene, out);  // warm-up: per-thread buffers grow here
            const std::uint64_t count = allocations_in_render(*m.method, scene, out);
            EXPECT_EQ(count, 0u) << m.spec << " on " << pattern << ": " << count
                                 << " allocations in a warm render";
            ++checked;
        }
    }
    EXPECT_GT(checked, 0);
}

// The circle methods on the circle patterns (what they draw), warm: nothing. `exact` and
// `exact-8bit` draw these rings with the closed-form curve engine, which computes the whole
// image per call and allocates (methods/scan/reference/curve_coverage.h): not checked here, and
// their times on circles include those allocations.
TEST(RenderAllocations, CircleMethodsOnCirclePatternsAllocateNothingWhenWarm) {
    int checked = 0;
    for (const char* spec : {"aa-circle", "aa-circle:radius_max=0", "aa-circle:alpha_max=0",
                             "wu-circle", "midpoint-circle"}) {
        const MethodInstance m = make_method(spec);
        for (const char* pattern : {"circles", "circle-radii"}) {
            const Scene scene = make_pattern(pattern, 96, 96);
            ASSERT_EQ(m.method->not_applicable(scene), "") << spec << " on " << pattern;
            Image out(scene.width, scene.height);
            m.method->render(scene, out);
            const std::uint64_t count = allocations_in_render(*m.method, scene, out);
            EXPECT_EQ(count, 0u) << spec << " on " << pattern << ": " << count
                                 << " allocations in a warm render";
            ++checked;
        }
    }
    EXPECT_EQ(checked, 10);
}

// A smaller scene after a larger one reuses the larger buffers: still nothing.
TEST(RenderAllocations, ExactAfterALargerSceneAllocatesNothing) {
    for (const char* spec : {"exact", "exact-8bit", "agg", "cairo"}) {
        const MethodInstance m = make_method(spec);
        const Scene large = make_pattern("rings", 2 * kSide, 2 * kSide);
        Image large_out(large.width, large.height);
        m.method->render(large, large_out);
        const Scene small = make_pattern("rings", kSide, kSide);
        Image out(small.width, small.height);
        if (std::string(spec) == "cairo") m.method->render(small, out);  // its surface is per size
        EXPECT_EQ(allocations_in_render(*m.method, small, out), 0u) << spec;
    }
}

// The scanline and z-buffer families on 3-D scenes (the ScreenScene they draw), each on a
// fresh thread whose scratch starts empty: the second render allocates nothing.
const char* const kScanlineSpecs[] = {
    "none",          "ssaa",         "ssaa:filter=gaussian", "ssaa:k=2,pattern=rgss",
    "ssaa:k=4,pattern=msaa,filter=gaussian", "nishita-d", "fast-edge", "box-multiscan",
    "box-multiscan:n=7", "gauss-multiscan", "gauss-multiscan:n=6,filter=cone,lut=0"};

TEST(RenderAllocations, ScanlineFamiliesOnScreenScenesAllocateNothingWhenWarm) {
    for (const char* pattern : {"star", "zoneplate", "room", "mesh", "interpenetrate"}) {
        const Scene given = make_pattern(pattern, 96, 80);
        for (const char* spec : kScanlineSpecs) {
            const MethodInstance m = make_method(spec);
            const Scene drawn = PreparedFrame::prepare(given).input_for(*m.method).scene();
            Image out(drawn.width, drawn.height);
            std::uint64_t cold = 0, warm = 0;
            std::thread([&] {
                const AllocCounts a = thread_alloc_counts();
                m.method->render(drawn, out);
                const AllocCounts b = thread_alloc_counts();
                m.method->render(drawn, out);
                const AllocCounts c = thread_alloc_counts();
                cold = b.bytes - a.bytes;
                warm = c.allocations - b.allocations;
            }).join();
            EXPECT_EQ(warm, 0u) << spec << " on " << pattern << " (first render: " << cold
                                << " bytes)";
        }
    }
}

}  // namespace
}  // namespace aabench
