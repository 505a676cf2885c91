// The pass alone of a post-process row (methods/post_process.h): how compare times it and the
// metric that holds it (time_pass_ms, appended to the metric registry after the generated
// families: harness/measure/metric_registry.cpp).
#pragma once

#include "harness/measure/metric_registry.h"
#include "harness/measure/timing.h"
#include "methods/post_process.h"

namespace aabench {

inline constexpr char kTimePassKey[] = "time_pass_ms";

// The registry index of time_pass_ms.
MetricId time_pass_metric();

// The pass alone, single-threaded, on `base`, the base method's image rendered once by the
// caller: a warm-up, then `runs` timed passes into `out` (allocated by the caller).
TimingStats time_pass(const PostProcessMethod& method, const Image& base, Image& out, int runs);
// The same on a colour scene's base planes: the colour pass (pass_colour_rows), `out` three
// planes of the same size; a grey image's one plane takes the grey pass.
TimingStats time_pass(const PostProcessMethod& method, const ImagePlanes& base, ImagePlanes& out,
                      int runs);

}  // namespace aabench
