// The comparison run: every method on every pattern, each scored against the exact box
// reference and against the exact reference of its own filter, and timed. Pure computation:
// the report stage writes the files.
//
// Work is a list of tasks (pattern x method spec, plus each method's sweep over its cost
// parameter with --sweep), numbered in one fixed order. A run does all tasks or one shard
// of them (task t belongs to shard t mod N), so N machines can split a sweep and
// merge_shard_rows() puts the rows back in the unsharded order.
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
#include "harness/measure/timing.h"
#include "harness/world/plan.h"
#include "methods/scan/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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
    int runs = 7;        // timed runs after one warm-up; the median is reported
    bool sweep = false;  // also run each method across its cost parameter's sweep values
    int jobs = 1;        // parallel render-and-score tasks; timing is always serial
    int render_threads = 1;  // bands per render (render_in_bands), scored and timed renders
    int shard_index = 0;  // this run does the tasks t with t % shard_count == shard_index
    int shard_count = 1;
    bool keep_images = true;  // keep the default rows' images for the report's figures
    bool symptoms = true;     // measure the five symptoms and SSIM for the default rows
    int motion_frames = 16;   // T, the sub-pixel offsets of the crawl and popping figures
};

inline std::array<double, kStageCount> nan_stages() {
    std::array<double, kStageCount> a;
    a.fill(kNaN);
    return a;
}

struct ResultRow {
    long long task = 0;   // index in the unsharded task order (for merging shards)
    std::string pattern;  // canonical pattern spec (every parameter)
    std::string pattern_id;
    std::string scene_file;  // the scene file's path as given (compare --scenes); empty for a
                             // built-in pattern. pattern and pattern_id are then its stem.
    std::string method;  // canonical method spec (every parameter)
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
    ErrorStats box;                // against the exact box reference
    std::string reference_filter;  // the method's own filter (canonical spec)
    ErrorStats own;                // against the exact reference of that filter
    // The five aliasing symptoms and SSIM (docs/metrics.md), for the rows that are not sweep
    // points (NaN there, and where a figure does not apply, e.g. popping without thin objects).
    // Against the method's own filter: edge_rmse, alias energy, crawl (aliasing is what the
    // discretisation adds, not the choice of filter). Against the box reference: captured
    // mass and popping (every unit-volume filter keeps the mass), SSIM.
    double edge_rmse = kNaN;
    double mass_worst = kNaN;
    std::string mass_worst_label;
    double mass_mean = kNaN;
    double alias_total_db = kNaN;
    double alias_low_db = kNaN;
    double crawl = kNaN;
    double popping = kNaN;  // +inf when an object vanishes in some frame
    std::string popping_worst_label;
    double ssim = kNaN;
    // Seams (conflation, 3-D patterns): |error| on the pixels crossed by edges two visible
    // faces of one object share and wholly covered by the exact answer; worst and mean.
    double seams_max = kNaN;
    double seams_mean = kNaN;
    // The world stages that made the pattern's scene (3-D patterns; harness/world/plan.h): the
    // time (ms, one run) and heap bytes of each stage the plan kept, NaN for stages left out
    // (and for every stage of a 2-D pattern). The same for every row of one pattern.
    // Lines (scenes with `edges`; harness/measure/line_scores.h): the edge stage on
    // the method's own depth image against the ground-truth lines, NaN for a method that draws
    // no depth image; and the same with the edge stage on the exact depth image (the same for
    // every row of one pattern: what the operator loses without any depth antialiasing error).
    // NaN everywhere for a scene without `edges`.
    double line_precision = kNaN;
    double line_recall = kNaN;
    double line_rmse = kNaN;
    double exact_depth_line_precision = kNaN;
    double exact_depth_line_recall = kNaN;
    double exact_depth_line_rmse = kNaN;
    // Contours and creases apart (LineScores::contour_*, crease_*), on the method's depth image
    // and on the exact one.
    double line_contour_precision = kNaN;
    double line_contour_recall = kNaN;
    double line_crease_precision = kNaN;
    double line_crease_recall = kNaN;
    double exact_depth_line_contour_precision = kNaN;
    double exact_depth_line_contour_recall = kNaN;
    double exact_depth_line_crease_precision = kNaN;
    double exact_depth_line_crease_recall = kNaN;
    std::array<double, kStageCount> stage_ms = nan_stages();
    std::array<double, kStageCount> stage_bytes = nan_stages();
    double world_ms = kNaN;  // their sum
    // time = method_ms + relied_stages_ms: the method's own render time (median) and the world
    // stages it relies on (PreparedFrame::relied_stage_ms: 0 on a 2-D scene; on a world every
    // stage that made its input, the visibility stage only for a method that draws the exact
    // visible pieces).
    double method_ms = kNaN;
    double relied_stages_ms = kNaN;
    TimingStats time;
    std::string time_source = "compare";  // or "benchmark" (from --bench-json), or "process"
                                          // (compare --external: the renderer's whole process)
    double external_startup_ns = kNaN;    // --external: the same process on an empty scene
    double external_reported_ms = kNaN;   // --external: what it printed as aabench-time-ms
    double mpixel_per_s = 0.0;
    double medges_per_s = 0.0;
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
};

struct CompareResult {
    std::vector<ResultRow> rows;  // in task order
    std::vector<ComparisonFigures> figures;
    long long task_count = 0;  // tasks in the unsharded run
};

// Called as tasks finish: (tasks done, tasks in this run, phase and task just done).
// Calls are serialised; they may come from any thread.
using ProgressFn = std::function<void(std::size_t, std::size_t, const std::string&)>;

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
