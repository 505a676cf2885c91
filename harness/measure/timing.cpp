#include "harness/measure/timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "patterns/scene/scene.h"  // InputError

namespace aabench {

TimingStats time_runs(int runs, const std::function<void()>& body, double budget_ns) {
    body();  // warm-up: caches, page faults, tables, per-thread scratch
    std::vector<double> ns;
    ns.reserve(runs);
    double spent_ns = 0.0;
    for (int r = 0; r < runs; ++r) {
        if (budget_ns > 0.0 && r >= kBudgetMinRuns && spent_ns >= budget_ns) break;
        const auto start = std::chrono::steady_clock::now();
        body();
        const auto stop = std::chrono::steady_clock::now();
        ns.push_back(std::chrono::duration<double, std::nano>(stop - start).count());
        spent_ns += ns.back();
    }
    std::sort(ns.begin(), ns.end());
    TimingStats stats;
    stats.runs = static_cast<int>(ns.size());
    if (ns.empty()) return stats;
    stats.min_ns = ns.front();
    stats.max_ns = ns.back();
    const std::size_t mid = ns.size() / 2;
    stats.median_ns = ns.size() % 2 ? ns[mid] : 0.5 * (ns[mid - 1] + ns[mid]);
    return stats;
}

TimingStats time_render(const Method& method, const SceneInput& scene, Image& out, int runs,
                        int threads, double budget_ns) {
    TimingStats stats =
        time_runs(runs, [&] { render_in_bands(method, scene, out, threads); }, budget_ns);
    stats.threads = threads;
    return stats;
}

TimingStats time_render(const Method& method, const SceneInput& scene, ImagePlanes& out,
                        int runs, int threads, double budget_ns) {
    TimingStats stats =
        time_runs(runs, [&] { render_in_bands(method, scene, out, threads); }, budget_ns);
    stats.threads = threads;
    return stats;
}

nlohmann::json parse_benchmark_json(const std::string& text, const std::string& source) {
    // Bare NaN / Infinity / -Infinity / -nan tokens outside strings become null.
    std::string clean;
    clean.reserve(text.size());
    bool in_string = false;
    for (std::size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (in_string) {
            clean += c;
            if (c == '\\' && k + 1 < text.size()) {
                clean += text[++k];
            } else if (c == '"') {
                in_string = false;
            }
            continue;
        }
        if (c == '"') in_string = true;
        std::size_t skip = 0;
        for (const char* token : {"-Infinity", "Infinity", "-NaN", "NaN", "-nan", "nan"}) {
            const std::string t(token);
            if (text.compare(k, t.size(), t) == 0) {
                skip = t.size();
                break;
            }
        }
        if (skip > 0) {
            clean += "null";
            k += skip - 1;
        } else {
            clean += c;
        }
    }
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(clean);
    } catch (const nlohmann::json::parse_error& e) {
        // The offset is in the text with the bare tokens read as null: near, not at, the byte.
        throw InputError(fmt::format("{}: invalid JSON near byte {}", source, e.byte));
    }
    if (!doc.is_object() || !doc.contains("benchmarks") || !doc["benchmarks"].is_array()) {
        throw InputError(source + ": not Google Benchmark JSON output (no \"benchmarks\" array)");
    }
    return doc;
}

double benchmark_number(const nlohmann::json& entry, const char* key, double fallback) {
    const auto it = entry.find(key);
    return it != entry.end() && it->is_number() ? it->get<double>() : fallback;
}

std::vector<BenchmarkRun> benchmark_runs(const nlohmann::json& doc, const std::string& prefix) {
    std::vector<BenchmarkRun> runs;
    std::map<std::string, std::pair<std::size_t, bool>> seen;  // name -> (index, a median)
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
        std::string name = median && b.contains("run_name") ? b["run_name"].get<std::string>()
                                                            : b["name"].get<std::string>();
        if (name.rfind(prefix, 0) != 0) continue;
        constexpr std::string_view kRealTime = "/real_time";
        if (name.size() > kRealTime.size() &&
            name.compare(name.size() - kRealTime.size(), kRealTime.size(), kRealTime) == 0) {
            name.resize(name.size() - kRealTime.size());
        }
        const std::string unit = b.contains("time_unit") && b["time_unit"].is_string()
                                     ? b["time_unit"].get<std::string>()
                                     : "ns";
        const double to_ms = unit == "ms" ? 1.0 : unit == "us" ? 1e-3 : unit == "s" ? 1e3 : 1e-6;
        BenchmarkRun run{name, benchmark_number(b, "real_time", NAN) * to_ms, &b};
        const auto it = seen.find(name);
        if (it == seen.end()) {
            seen[name] = {runs.size(), median};
            runs.push_back(std::move(run));
        } else if ((median || !it->second.second) &&
                   (std::isfinite(run.real_ms) || !std::isfinite(runs[it->second.first].real_ms))) {
            // A median beats a repetition, a later repetition an earlier one; never a time by
            // a missing one.
            runs[it->second.first] = std::move(run);
            it->second.second = median;
        }
    }
    return runs;
}

double benchmark_name_number(const std::string& name, const std::string& source) {
    const auto last = name.rfind('/');
    double x = NAN;
    if (last != std::string::npos) {
        try {
            std::size_t used = 0;
            x = std::stod(name.substr(last + 1), &used);
            if (used != name.size() - last - 1) x = NAN;
        } catch (const std::exception&) {
        }
    }
    if (!(x > 0.0) || !std::isfinite(x)) {
        throw InputError(fmt::format(
            "{}: benchmark '{}': the size after the last '/' is not a positive number", source,
            name));
    }
    return x;
}

}  // namespace aabench
