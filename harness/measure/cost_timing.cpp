// Reads the cost-model benchmarks (cost_timing.h).
#include "harness/measure/cost_timing.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "harness/measure/timing.h"
#include "patterns/scene/scene.h"

namespace aabench {

CostModel cost_model_from_benchmark(const std::string& json_text, const std::string& source) {
    const nlohmann::json doc = parse_benchmark_json(json_text, source);
    // axis -> method -> size -> ms
    std::map<std::string, std::map<std::string, std::map<double, double>>> raw;
    for (const BenchmarkRun& run : benchmark_runs(doc, "cost/")) {
        const std::string& name = run.name;  // cost/<axis>/<method>/<size>
        const auto second = name.find('/', 5), last = name.rfind('/');
        if (second == std::string::npos || last <= second + 1) continue;
        const std::string axis = name.substr(5, second - 5);
        if (axis != "pixels" && axis != "edges") continue;  // edge_timing.h reads the others
        const double size = benchmark_name_number(name, source);
        if (!std::isfinite(run.real_ms) || !(run.real_ms > 0.0)) continue;
        raw[axis][name.substr(second + 1, last - second - 1)][size] = run.real_ms;
    }
    CostModel out;
    for (const auto& [axis, methods] : raw) {
        auto& series = axis == "pixels" ? out.pixels : out.edges;
        for (const auto& [method, points] : methods) {
            CostSeries s{method, {}};
            for (const auto& [size, ms] : points) s.points.push_back({size, ms});
            series.push_back(std::move(s));
        }
    }
    return out;
}

}  // namespace aabench
