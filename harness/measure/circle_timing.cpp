// Reads the circle benchmarks (circle_timing.h).
#include "harness/measure/circle_timing.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "harness/measure/timing.h"
#include "patterns/scene/scene.h"

namespace aabench {

std::vector<CircleTimingSeries> circle_timings_from_benchmark(const std::string& json_text,
                                                              const std::string& source) {
    const nlohmann::json doc = parse_benchmark_json(json_text, source);
    struct Raw {
        double ns = 0.0, circles = 0.0, table_bytes = 0.0;
    };
    std::map<std::string, std::map<int, Raw>> raw;  // variant -> radius -> run
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
        const std::string name =  // circle/<variant>/r=<R>[/real_time]
            median && b.contains("run_name") ? b["run_name"].get<std::string>()
                                             : b["name"].get<std::string>();
        if (name.rfind("circle/", 0) != 0) continue;
        const auto slash = name.find('/', 7);
        const auto r_at = name.find("/r=", 7);
        if (slash == std::string::npos || r_at != slash) continue;
        const std::string variant = name.substr(7, slash - 7);
        int radius = 0;
        try {
            radius = std::stoi(name.substr(r_at + 3));
        } catch (const std::exception&) {
            throw InputError(fmt::format("{}: benchmark '{}': no radius after r=", source, name));
        }
        const std::string unit = b.contains("time_unit") && b["time_unit"].is_string()
                                     ? b["time_unit"].get<std::string>()
                                     : "ns";
        const double scale = unit == "ms" ? 1e6 : unit == "us" ? 1e3 : unit == "s" ? 1e9 : 1.0;
        Raw run;
        run.ns = benchmark_number(b, "real_time", NAN) * scale;
        // The plain count when the benchmark gives it; older files: rate x time.
        run.circles = benchmark_number(b, "circles",
                                       benchmark_number(b, "circles/s", 0.0) * run.ns * 1e-9);
        run.table_bytes = benchmark_number(b, "table_bytes", 0.0);
        if (!std::isfinite(run.ns)) continue;
        // A median beats a single repetition of the same benchmark.
        if (median || !raw[variant].count(radius)) raw[variant][radius] = run;
    }
    std::vector<CircleTimingSeries> out;
    const auto fill = raw.find("fill");
    for (const auto& [variant, runs] : raw) {
        if (variant == "fill") continue;
        CircleTimingSeries series{variant, {}, 0.0};
        for (const auto& [radius, run] : runs) {
            const double circles = std::round(run.circles);
            if (!(circles >= 1.0)) continue;
            double ns = run.ns;
            if (fill != raw.end()) {
                const auto f = fill->second.find(radius);
                if (f != fill->second.end()) ns -= f->second.ns;
            }
            series.points.push_back({radius, std::max(ns, 0.0) / circles});
            series.table_bytes = std::max(series.table_bytes, run.table_bytes);
        }
        if (!series.points.empty()) out.push_back(std::move(series));
    }
    return out;
}

}  // namespace aabench
