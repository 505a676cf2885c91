// Wall-clock timing of one method on one scene: a warm-up run, then `runs` timed runs into a
// buffer allocated by the caller (so allocation is never timed). Single-threaded unless
// `threads` > 1 (compare --render-threads): then each run is render_in_bands (methods/method.h)
// on that many threads, and the stats say so.
// Benchmarks (harness/cli/bench_main.cpp) are the careful measurement; this is the quick figure
// that `compare` prints beside the errors.
#pragma once

#include "methods/method.h"

namespace aabench {

struct TimingStats {
    double median_ns = 0.0;
    double min_ns = 0.0;
    double max_ns = 0.0;
    int runs = 0;
    int threads = 1;  // threads of each timed render
};

TimingStats time_render(const Method& method, const Scene& scene, Image& out, int runs,
                        int threads = 1);

}  // namespace aabench
