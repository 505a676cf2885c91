// The methods of the scanline and z-buffer families keep their scratch per thread and reuse it:
// once a thread has rendered a scene, rendering it (or a smaller one) again allocates nothing
// (compare --jobs renders one Method from several TBB threads; the timing loop renders the
// same scene many times). Counted with harness/world/alloc_count.h around Method::render.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <thread>

#include "harness/world/alloc_count.h"
#include "harness/world/pipeline.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

const char* const kSpecs[] = {
    "none",          "ssaa",         "ssaa:filter=gaussian", "ssaa:k=2,pattern=rgss",
    "ssaa:k=4,pattern=msaa,filter=gaussian", "nishita-d", "fast-edge", "box-multiscan",
    "box-multiscan:n=7", "gauss-multiscan", "gauss-multiscan:n=6,filter=cone,lut=0"};

TEST(RenderAllocations, WarmRendersAllocateNothing) {
    for (const char* pattern : {"star", "zoneplate", "room", "mesh", "interpenetrate"}) {
        const Scene given = make_pattern(pattern, 96, 80);
        for (const char* spec : kSpecs) {
            const MethodInstance m = make_method(spec);
            const Scene drawn = drawable_scene(given, *m.method);
            Image out(drawn.width, drawn.height);
            std::uint64_t cold = 0, warm = 0;
            std::thread([&] {  // a fresh thread: its scratch starts empty
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
