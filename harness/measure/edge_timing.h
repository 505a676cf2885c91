// The edge stage's time against pixels and against faces (the paper says its cost is flat in
// faces and linear in pixels), read from the edge-cost benchmarks of aabench_bench
// (harness/cli/bench_main.cpp, --aabench_edge_cost: "cost/edge-pixels/edge-stage/<pixels>",
// "cost/edge-faces/edge-stage/<faces>", "cost/depth-faces/exact/<faces>") in Google
// Benchmark's JSON output, the same file `compare --bench-json` takes. Speed is measured by
// the benchmark binary; this only reads it. The report draws it (harness/report/html_report.cpp,
// with the cost-model plot of harness/report/cost_plot.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace aabench {

// One curve: (axis value, median time of one call in ms), ascending axis value.
struct EdgeTimingSeries {
    std::string name;  // "edge-stage", or "depth image by exact"
    std::vector<std::pair<double, double>> points;
};

struct EdgeTimings {
    std::vector<EdgeTimingSeries> pixels;  // the edge stage against the pixel count
    std::vector<EdgeTimingSeries> faces;   // the edge stage, and the depth image, against faces
    bool empty() const { return pixels.empty() && faces.empty(); }
};

// The edge-cost series of a Google Benchmark JSON document (empty when it has none). One point
// per benchmark: its real time, or with --benchmark_repetitions the median aggregate. Throws
// InputError naming `source` on text that is not Google Benchmark JSON, or on an edge-cost
// benchmark whose name does not end in a number.
EdgeTimings edge_timings_from_benchmark(const std::string& json_text, const std::string& source);

}  // namespace aabench
