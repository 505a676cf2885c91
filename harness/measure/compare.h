// The comparison run: every method on every pattern, each scored against the exact box
// reference and against the exact reference of its own filter, and timed. Pure computation:
// the report stage writes the files.
//
// Work is a list of tasks (pattern x method spec, plus each method's sweep over its cost
// parameter with --sweep), numbered in one fixed order. A run does all tasks or one shard
// of them, so N machines can split a sweep and merge_shard_rows() puts the rows back in the
// unsharded order. Shards are balanced by the tasks' estimated cost (shard_plan.h,
// plan_shards below), not by their count: every shard computes the same split.
//
// Parallelism (--jobs): rendering and scoring run as parallel tasks (TBB); timing does not.
// After the parallel pass, each task is timed alone in a serial pass on one thread, so no
// timing ever shares the machine with another of our tasks.
#pragma once

#include <array>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "harness/measure/line_scores.h"
#include "harness/measure/metrics.h"
#include "harness/measure/result_row.h"
#include "harness/measure/shard_plan.h"
#include "harness/measure/timing.h"
#include "harness/world/plan.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// A user's scene file for the comparison (compare --scenes), read by the caller (this room does
// no I/O). Its rows are named by the file's stem (pattern = pattern_id = stem) and record `path`
// in ResultRow::scene_file; the scene keeps its own size.
struct SceneFileInput {
    std::string path;
    Scene scene;
};

struct CompareOptions {
    std::vector<std::string> method_specs;   // empty: every registered method, defaults
    std::vector<std::string> pattern_specs;  // empty: every built-in pattern, defaults, unless
                                             // scene_files are given (then none)
    std::vector<SceneFileInput> scene_files;  // after the patterns, in this order
    int width = 256;  // of the patterns; a scene file has its own size
    int height = 256;
    int runs = 7;        // timed runs after one warm-up, at most; the median is reported
    // A render's runs stop after kBudgetMinRuns once they took this long (0: always `runs`).
    double time_budget_ms = 50.0;
    bool sweep = false;  // also run each method across its cost parameter's sweep values
    int jobs = 1;        // parallel render-and-score tasks; timing is always serial
    int render_threads = 1;  // bands per render (render_in_bands), scored and timed renders
    int shard_index = 0;  // this run does the tasks plan_shards() gives shard_index
    int shard_count = 1;
    bool keep_images = true;  // keep the default rows' images for the report's figures
    bool symptoms = true;     // measure the five symptoms and SSIM for the default rows
    int motion_frames = 16;   // T, the sub-pixel offsets of the crawl and popping figures
};

// The images of one pattern's default rows, kept for the report's figure grid.
struct ComparisonFigures {
    std::string pattern_id;
    std::string pattern_spec;
    Scene scene;
    Coverage reference;  // exact box reference
    std::vector<std::string> methods;  // method specs of the default rows, in run order
    std::vector<Image> images;         // their renders, same order
    std::optional<EdgeFigures> edges;  // scenes with `edges` (compare runs only, not merge)
    // A colour scene's: the reference's planes and each render's, in the order of `images`,
    // which then hold their luminances (docs/colour.md); empty for a grey scene.
    std::optional<CoveragePlanes> colour_reference;
    std::vector<ImagePlanes> colour_images;
};

// One task of the unsharded run as the shard plan sees it.
struct PlannedTask {
    long long task = 0;
    std::string pattern_id;
    std::string method;  // canonical spec
    bool sweep_point = false;
    // Everything the run does for the task (its renders: scored, timed, motion frames), in ms
    // on the cost model's machine (methods/cost_model.h); not a measurement.
    double estimate_ms = 0.0;
    int shard = 0;  // 0-based
};

// The split of a run's tasks into options.shard_count shards by estimated cost.
struct ShardPlan {
    ShardSplit split;
    std::vector<PlannedTask> tasks;        // every task, in task order
    std::vector<double> shard_peak_bytes;  // per shard: memory by estimate (harness/measure/
                                           // limits.h), each touched pattern's job added up
    std::vector<std::string> pattern_specs;  // canonical (scene files: their stems), run order
    std::vector<std::string> method_specs;   // canonical, run order
};

struct CompareResult {
    std::vector<ResultRow> rows;  // in task order
    std::vector<ComparisonFigures> figures;
    long long task_count = 0;  // tasks in the unsharded run
    ShardPlan plan;            // the split this run took its shard from
};

// Called as tasks finish: (tasks done, tasks in this run, phase and task just done).
// Calls are serialised; they may come from any thread.
using ProgressFn = std::function<void(std::size_t, std::size_t, const std::string&)>;

// The split of the run into options.shard_count shards, without running anything but the
// patterns' world stages (cheap); options.shard_index is ignored. InputErrors as the run's.
ShardPlan plan_shards(const CompareOptions& options);

// Checks every spec first (InputError before any work), then runs.
CompareResult run_comparison(const CompareOptions& options, const ProgressFn& progress = {});

// Splits a comma-separated list of specs whose own parameters are also comma-separated:
// an item with '=' but no ':' continues the previous spec ("ssaa:k=3,filter=box,none" is
// two specs).
std::vector<std::string> split_spec_list(const std::string& text);

// Replaces the timings of rows found in a Google Benchmark JSON file (aabench_bench
// --benchmark_format=json; names "METHOD_SPEC/PATTERN_ID/SIZE", square sizes, default pattern
// parameters) with the benchmark's real time, and marks them time_source = "benchmark".
// Returns the number of rows updated. Throws InputError for unreadable JSON.
int apply_benchmark_timings(std::vector<ResultRow>& rows, const std::string& json_text,
                            const std::string& source);

// The figures for rows read back from results files (for `aabench merge`): each pattern's
// default-row methods rendered again at the rows' size. Rendering is deterministic, so these
// are the images the shards saw; nothing is timed. Rows of a scene file take their scene from
// `scene_files` (by path); one that is not there gets no figures.
std::vector<ComparisonFigures> render_figures(const std::vector<ResultRow>& rows,
                                              const std::vector<SceneFileInput>& scene_files = {});

// Rows of several shards (read back from their results.json) in unsharded order; throws
// InputError if two shards hold the same task or the runs differ in size (of the built-in
// patterns' rows: a scene file has its own size) or options.
std::vector<ResultRow> merge_shard_rows(std::vector<std::vector<ResultRow>> shards);

}  // namespace aabench
