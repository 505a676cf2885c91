// Reads the circle benchmarks (circle_timing.h).
#include "harness/measure/circle_timing.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "patterns/scene/scene.h"

namespace aabench {

std::vector<CircleTimingSeries> circle_timings_from_benchmark(const std::string& json_text,
                                                              const std::string& source) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(json_text);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(fmt::format("{}: byte {}: invalid JSON", source, e.byte));
    }
    if (!doc.is_object() || !doc.contains("benchmarks") || !doc["benchmarks"].is_array()) {
        throw InputError(source + ": not Google Benchmark JSON output (no \"benchmarks\" array)");
    }
    struct Raw {
        double ns = 0.0, circles = 0.0, table_bytes = 0.0;
    };
    std::map<std::string, std::map<int, Raw>> raw;  // variant -> radius -> run
    for (const auto& b : doc["benchmarks"]) {
        if (!b.is_object() || !b.contains("name") || !b.contains("real_time")) continue;
        if (b.contains("run_type") && b["run_type"] != "iteration") continue;
        const std::string name = b["name"].get<std::string>();  // circle/<variant>/r=<R>[/real_time]
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
        const std::string unit = b.value("time_unit", "ns");
        const double scale = unit == "ms" ? 1e6 : unit == "us" ? 1e3 : unit == "s" ? 1e9 : 1.0;
        Raw run;
        run.ns = b["real_time"].get<double>() * scale;
        run.circles = b.value("circles/s", 0.0) * run.ns * 1e-9;
        run.table_bytes = b.value("table_bytes", 0.0);
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
