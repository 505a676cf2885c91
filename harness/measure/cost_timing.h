// The cost model read back from aabench_bench: its `--aabench_cost_model` runs are
// named "cost/<axis>/<method>/<x>" — axis "pixels" (star, 128^2 .. 4096^2, its edges fixed) or
// "edges" (rings at 1024^2, the period shrinking) — and Google Benchmark's JSON output holds
// their times. `compare --bench-json FILE` reads them with this, and the report draws them
// (harness/report/cost_plot.h). Speed is measured by the benchmark binary; this only reads it.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace aabench {

// One method's measurements: (size, time in ms), any order; sizes and times > 0.
struct CostSeries {
    std::string method;
    std::vector<std::pair<double, double>> points;
};

struct CostModel {
    std::vector<CostSeries> pixels;  // time against pixels, one series per method
    std::vector<CostSeries> edges;   // time against edges
    bool empty() const { return pixels.empty() && edges.empty(); }
};

// The cost series of a Google Benchmark JSON document (empty when it has none), points in
// ascending size. One point per benchmark: the median aggregate when repeated, else the run.
// Throws InputError naming `source` on text that is not Google Benchmark JSON, or on a cost
// benchmark whose size is not a number.
CostModel cost_model_from_benchmark(const std::string& json_text, const std::string& source);

}  // namespace aabench
