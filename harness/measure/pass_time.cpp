#include "harness/measure/pass_time.h"

namespace aabench {

MetricId time_pass_metric() {
    static const MetricId id = *metric_registry().find(kTimePassKey);
    return id;
}

TimingStats time_pass(const PostProcessMethod& method, const Image& base, Image& out, int runs) {
    // The warm-up run grows the pass's per-thread scratch.
    return time_runs(runs, [&] { method.pass(base, out); });
}

TimingStats time_pass(const PostProcessMethod& method, const ImagePlanes& base, ImagePlanes& out,
                      int runs) {
    return time_runs(runs, [&] { method.pass(base, out); });
}

}  // namespace aabench
