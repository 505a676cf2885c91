// Reads the edge-cost benchmarks (edge_timing.h).
#include "harness/measure/edge_timing.h"

#include <cmath>
#include <map>

#include <fmt/format.h>

#include "harness/measure/timing.h"
#include "patterns/scene/scene.h"

namespace aabench {

EdgeTimings edge_timings_from_benchmark(const std::string& json_text, const std::string& source) {
    const nlohmann::json doc = parse_benchmark_json(json_text, source);
    // axis -> series name -> x -> ms
    std::map<std::string, std::map<std::string, std::map<double, double>>> raw;
    for (const BenchmarkRun& run : benchmark_runs(doc, "cost/")) {
        const std::string& name = run.name;  // cost/<axis>/<series>/<x>
        std::string axis;
        for (const char* a : {"edge-pixels", "edge-faces", "depth-faces"}) {
            if (name.rfind(fmt::format("cost/{}/", a), 0) == 0) axis = a;
        }
        if (axis.empty()) continue;  // cost_timing.h reads the others
        const auto first = 5 + axis.size() + 1, last = name.rfind('/');
        if (last <= first) {
            throw InputError(fmt::format("{}: benchmark '{}': no series and size", source, name));
        }
        const double x = benchmark_name_number(name, source);
        if (!std::isfinite(run.real_ms)) continue;
        std::string series = name.substr(first, last - first);
        if (axis == "depth-faces") series = "depth image by " + series;
        raw[axis == "edge-pixels" ? "pixels" : "faces"][series][x] = run.real_ms;
    }
    EdgeTimings out;
    for (const auto& [axis, by_series] : raw) {
        for (const auto& [series, by_x] : by_series) {
            EdgeTimingSeries s{series, {}};
            for (const auto& [x, ms] : by_x) s.points.push_back({x, ms});
            (axis == "pixels" ? out.pixels : out.faces).push_back(std::move(s));
        }
    }
    return out;
}

}  // namespace aabench
