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
    // axis -> series name -> x -> (ms, from a median aggregate)
    std::map<std::string, std::map<std::string, std::map<double, std::pair<double, bool>>>> raw;
    for (const auto& b : doc["benchmarks"]) {
        if (!b.is_object() || !b.contains("name") || !b["name"].is_string()) continue;
        if (b.contains("run_type") && !b["run_type"].is_string()) continue;
        if (b.contains("aggregate_name") && !b["aggregate_name"].is_string()) continue;
        if (b.contains("run_name") && !b["run_name"].is_string()) continue;
        // One run per benchmark, or with --benchmark_repetitions the median aggregate (its
        // run_name is the benchmark's name).
        const bool median = b.value("run_type", "") == "aggregate" &&
                            b.value("aggregate_name", "") == "median";
        if (b.contains("run_type") && b["run_type"] != "iteration" && !median) continue;
        std::string name =  // cost/<axis>/<series>/<x>[/real_time]
            median && b.contains("run_name") ? b["run_name"].get<std::string>()
                                             : b["name"].get<std::string>();
        const std::string suffix = "/real_time";
        if (name.size() > suffix.size() &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
            name.resize(name.size() - suffix.size());
        }
        std::string axis;
        for (const char* a : {"edge-pixels", "edge-faces", "depth-faces"}) {
            if (name.rfind(fmt::format("cost/{}/", a), 0) == 0) axis = a;
        }
        if (axis.empty()) continue;
        const auto first = 5 + axis.size() + 1, last = name.rfind('/');
        if (last <= first) {
            throw InputError(fmt::format("{}: benchmark '{}': no series and size", source, name));
        }
        double x = NAN;
        try {
            std::size_t used = 0;
            x = std::stod(name.substr(last + 1), &used);
            if (used != name.size() - last - 1) x = NAN;
        } catch (const std::exception&) {
        }
        if (!(x > 0.0)) {
            throw InputError(fmt::format("{}: benchmark '{}': no positive number at its end",
                                         source, name));
        }
        const std::string unit = b.contains("time_unit") && b["time_unit"].is_string()
                                     ? b["time_unit"].get<std::string>()
                                     : "ns";
        const double to_ms = unit == "ms" ? 1.0 : unit == "us" ? 1e-3 : unit == "s" ? 1e3 : 1e-6;
        const double ms = benchmark_number(b, "real_time", NAN) * to_ms;
        if (!std::isfinite(ms)) continue;
        std::string series = name.substr(first, last - first);
        if (axis == "depth-faces") series = "depth image by " + series;
        auto& cell = raw[axis == "edge-pixels" ? "pixels" : "faces"][series];
        // A median beats a single repetition of the same benchmark.
        if (median || !cell.count(x)) cell[x] = {ms, median};
    }
    EdgeTimings out;
    for (const auto& [axis, by_series] : raw) {
        for (const auto& [series, by_x] : by_series) {
            EdgeTimingSeries s{series, {}};
            for (const auto& [x, t] : by_x) s.points.push_back({x, t.first});
            (axis == "pixels" ? out.pixels : out.faces).push_back(std::move(s));
        }
    }
    return out;
}

}  // namespace aabench
