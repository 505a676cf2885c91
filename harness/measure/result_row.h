// One result row: what was measured (identity: task, pattern, method, sweep point, size, ...)
// and its figures, held by metric (harness/measure/metric_registry.h says what each one is).
// The helpers put the figures of one measurement (ErrorStats, TimingStats, world stage costs)
// into a row, so that every producer of rows (compare, score, --external) fills them alike.
#pragma once

#include <limits>
#include <string>

#include "harness/measure/line_scores.h"
#include "harness/measure/metric_registry.h"
#include "harness/measure/metrics.h"
#include "harness/measure/timing.h"

namespace aabench {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct ResultRow {
    long long task = 0;   // index in the unsharded task order (for merging shards)
    std::string pattern;  // canonical pattern spec (every parameter)
    std::string pattern_id;
    std::string scene_file;  // the scene file's path as given (compare --scenes); empty for a
                             // built-in pattern. pattern and pattern_id are then its stem.
    std::string method;      // canonical method spec (every parameter)
    std::string method_id;
    bool sweep_point = false;  // false: the method as asked for; true: a point of its sweep
    std::string cost_param;    // "n", "k" or empty
    double cost_value = 0.0;
    int width = 0;
    int height = 0;
    long long edges = 0;
    // Non-empty when the method cannot draw this scene (Method::not_applicable: aa-circle on a
    // polygon): the reason, shown as "n/a" with it; every error and time is then NaN.
    std::string not_applicable;
    std::string reference_filter;  // the method's own filter (canonical spec): own_* against it
    // The thin objects named by mass_worst and popping (empty where those do not apply).
    std::string mass_worst_label;
    std::string popping_worst_label;
    // How the time was taken: the timed runs and threads of each render, and the source:
    // "compare", "benchmark" (from --bench-json) or "process" (compare --external: the
    // renderer's whole process).
    int time_runs = 0;
    int time_threads = 1;
    std::string time_source = "compare";
    // The figures, by metric id: row[metric::kBoxRmse]. NaN: does not apply, or not measured
    // (the symptoms of sweep points, the line scores of scenes without `edges`, ...).
    MetricValues values;

    double operator[](MetricId id) const { return values[id]; }
    double& operator[](MetricId id) { return values[id]; }
};

// True when the row has a line score (a scene with `edges`): the line columns are written then.
bool has_line_scores(const ResultRow& row);

// The figures against the box reference (box_*, dropout*, nonfinite).
void set_box_stats(ResultRow& row, const ErrorStats& stats);
// The figures against the method's own filter's reference (own_*).
void set_own_stats(ResultRow& row, const ErrorStats& stats);
// time_median_ns, _min_ns, _max_ns, time_runs, time_threads, the method / stage split and the
// throughputs (mpixel_per_s, medges_per_s from width, height and edges). `time` is the method's
// own render; `relied_stages_ms` the world stages it relies on (PreparedFrame::relied_stage_ms,
// 0 on a 2-D scene): time_method_ms is the method's median, time_stages_ms the stages, and the
// time_*_ns figures and throughputs are of the total, what tables and plots show.
void set_timing(ResultRow& row, const TimingStats& time, double relied_stages_ms = 0.0);
// The line scores (scenes with `edges`) of the edge stage on the method's own depth image
// (line_*), or on the exact depth image (exact_depth_line_*).
void set_line_scores(ResultRow& row, const LineScores& scores, bool exact_depth);
// The world stage costs of a 3-D scene: one stage's time (ms) and heap bytes, added to world_ms.
void add_stage_cost(ResultRow& row, int stage, double time_ms, double bytes);

}  // namespace aabench
