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
    for (const BenchmarkRun& b : benchmark_runs(doc, "circle/")) {
        const std::string& name = b.name;  // circle/<variant>/r=<R>
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
        Raw run;
        run.ns = b.real_ms * 1e6;
        // The plain count when the benchmark gives it; older files: rate x time (the rate
        // counter is "circle_rate", "circles/s" in files of earlier versions).
        const double rate = benchmark_number(*b.entry, "circle_rate",
                                             benchmark_number(*b.entry, "circles/s", 0.0));
        run.circles = benchmark_number(*b.entry, "circles", rate * run.ns * 1e-9);
        run.table_bytes = benchmark_number(*b.entry, "table_bytes", 0.0);
        if (!std::isfinite(run.ns)) continue;
        raw[variant][radius] = run;
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
