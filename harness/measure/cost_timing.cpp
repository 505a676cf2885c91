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
    // axis -> method -> size -> (ms, from a median)
    std::map<std::string, std::map<std::string, std::map<double, std::pair<double, bool>>>> raw;
    for (const auto& b : doc["benchmarks"]) {
        if (!b.is_object() || !b.contains("name") || !b["name"].is_string()) continue;
        if (b.contains("run_type") && !b["run_type"].is_string()) continue;
        if (b.contains("aggregate_name") && !b["aggregate_name"].is_string()) continue;
        if (b.contains("run_name") && !b["run_name"].is_string()) continue;
        const bool median = b.value("run_type", "") == "aggregate" &&
                            b.value("aggregate_name", "") == "median";
        if (b.contains("run_type") && b["run_type"] != "iteration" && !median) continue;
        std::string name = median && b.contains("run_name") ? b["run_name"].get<std::string>()
                                                            : b["name"].get<std::string>();
        if (name.rfind("cost/", 0) != 0) continue;
        // UseRealTime() appends "/real_time" to the name.
        constexpr std::string_view kRealTime = "/real_time";
        if (name.size() > kRealTime.size() &&
            name.compare(name.size() - kRealTime.size(), kRealTime.size(), kRealTime) == 0) {
            name.resize(name.size() - kRealTime.size());
        }
        const auto second = name.find('/', 5), last = name.rfind('/');
        if (second == std::string::npos || last <= second + 1) continue;
        const std::string axis = name.substr(5, second - 5);
        if (axis != "pixels" && axis != "edges") continue;
        const std::string method = name.substr(second + 1, last - second - 1);
        double size = NAN;
        try {
            std::size_t used = 0;
            size = std::stod(name.substr(last + 1), &used);
            if (used != name.size() - last - 1) size = NAN;
        } catch (const std::exception&) {
        }
        if (!(size > 0.0) || !std::isfinite(size)) {
            throw InputError(fmt::format("{}: benchmark '{}': the size after the last '/' is not "
                                         "a positive number",
                                         source, name));
        }
        const std::string unit = b.contains("time_unit") && b["time_unit"].is_string()
                                     ? b["time_unit"].get<std::string>()
                                     : "ns";
        const double to_ms = unit == "ms" ? 1.0 : unit == "us" ? 1e-3 : unit == "s" ? 1e3 : 1e-6;
        const double ms = benchmark_number(b, "real_time", NAN) * to_ms;
        if (!std::isfinite(ms) || !(ms > 0.0)) continue;
        auto& slot = raw[axis][method];
        // A median beats a single repetition of the same benchmark.
        if (median || !slot.count(size) || !slot[size].second) slot[size] = {ms, median};
    }
    CostModel out;
    for (const auto& [axis, methods] : raw) {
        auto& series = axis == "pixels" ? out.pixels : out.edges;
        for (const auto& [method, points] : methods) {
            CostSeries s{method, {}};
            for (const auto& [size, value] : points) s.points.push_back({size, value.first});
            series.push_back(std::move(s));
        }
    }
    return out;
}

}  // namespace aabench
