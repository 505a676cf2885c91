// Wall-clock timing of one method on one scene: a warm-up run, then `runs` timed runs into a
// buffer allocated by the caller (so allocation is never timed). Single-threaded unless
// `threads` > 1 (compare --render-threads): then each run is render_in_bands (methods/method.h)
// on that many threads, and the stats say so.
// Benchmarks (harness/cli/bench_main.cpp) are the careful measurement; this is the quick figure
// that `compare` prints beside the errors.
#pragma once

#include <functional>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "methods/method.h"

namespace aabench {

struct TimingStats {
    double median_ns = 0.0;
    double min_ns = 0.0;
    double max_ns = 0.0;
    int runs = 0;
    int threads = 1;  // threads of each timed render
};

// With `budget_ns` > 0 the runs stop early, after kBudgetMinRuns at least, once the timed runs
// have taken that long (compare --time-budget): a slow render's median of 3 is as steady as a
// fast one's of 7, and the default comparison stays within its time.
TimingStats time_render(const Method& method, const SceneInput& scene, Image& out, int runs,
                        int threads = 1, double budget_ns = 0.0);
// Every plane of a colour scene (a grey scene's one plane as above).
TimingStats time_render(const Method& method, const SceneInput& scene, ImagePlanes& out,
                        int runs, int threads = 1, double budget_ns = 0.0);

// `body` run once to warm up, then `runs` times, each timed alone (steady clock): the median,
// minimum and maximum in ns. The one timing loop of time_render and of a post-process pass
// alone (harness/measure/pass_time.h).
// With `budget_ns` > 0: stops after kBudgetMinRuns runs or more once they took budget_ns.
inline constexpr int kBudgetMinRuns = 3;  // the fewest runs whose median drops one outlier
TimingStats time_runs(int runs, const std::function<void()>& body, double budget_ns = 0.0);

// Google Benchmark's JSON output (--benchmark_format=json / --benchmark_out) parsed. It is not
// always JSON: a counter that is NaN or infinite (the coefficient of variation of a zero
// counter over repetitions) is written as a bare NaN / Infinity token; those become null here.
// Throws InputError naming `source` when the text is not JSON or has no "benchmarks" array.
nlohmann::json parse_benchmark_json(const std::string& text, const std::string& source);

// A number field of a benchmark entry, or `fallback` when it is missing or null.
double benchmark_number(const nlohmann::json& entry, const char* key, double fallback);

// One benchmark's timing in a parsed document, as the report's plot readers take it
// (circle_timing, cost_timing, edge_timing).
struct BenchmarkRun {
    std::string name;  // without the "/real_time" that UseRealTime() appends
    double real_ms = 0.0;  // real time converted from its time_unit; NaN when absent
    const nlohmann::json* entry = nullptr;  // the entry, for counters (valid while doc lives)
};

// The runs of the benchmarks whose name starts with `prefix`, one per benchmark: its median
// aggregate when it was repeated, else its run (the last, when the file holds repetitions
// without aggregates); a run with a real time never gives way to one without. Other
// aggregates (mean, stddev, cv) and entries whose name, run_type, aggregate_name or run_name
// is not a string are skipped.
std::vector<BenchmarkRun> benchmark_runs(const nlohmann::json& doc, const std::string& prefix);

// The positive number after the last '/' of a benchmark's name (its size or count). Throws
// InputError naming `source` and the benchmark when there is none.
double benchmark_name_number(const std::string& name, const std::string& source);

}  // namespace aabench
