// Time per circle against radius ("does the table still pay?"), read from the
// circle benchmarks of aabench_bench (harness/cli/bench_main.cpp, "circle/<variant>/r=<R>")
// in Google Benchmark's JSON output, the same file `compare --bench-json` takes. Speed is
// measured by the benchmark binary; this only reads it. The report draws it
// (harness/report/circle_timing_plot.h).
#pragma once

#include <string>
#include <vector>

namespace aabench {

struct CircleTimingPoint {
    int radius = 0;
    double ns_per_circle = 0.0;  // (time - the empty canvas's fill time) / circles drawn
};

struct CircleTimingSeries {
    std::string variant;  // aa-circle-table, aa-circle-on-the-fly, wu-circle, ...
    std::vector<CircleTimingPoint> points;  // ascending radius
    double table_bytes = 0.0;  // the table's memory (aa-circle-table), else 0
};

// The circle series of a Google Benchmark JSON document (empty when it has none). Per
// benchmark, circles = its circles counter (or circle_rate x its real time); the fill time of the same
// radius ("circle/fill/r=<R>", when present) is subtracted first, as the table of docs/methods-circles.md does.
// With --benchmark_repetitions the median aggregate is taken.
// Throws InputError naming `source` on text that is not Google Benchmark JSON.
std::vector<CircleTimingSeries> circle_timings_from_benchmark(const std::string& json_text,
                                                              const std::string& source);

}  // namespace aabench
