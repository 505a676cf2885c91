// aabench compare and merge: the comparison run (every method on every pattern, scored and
// timed) with its results files and report, and the join of sharded runs.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <tbb/global_control.h>

#include "harness/cli/command.h"
#include "harness/cli/external.h"
#include "harness/cli/web_peers.h"
#include "harness/measure/claims.h"
#include "harness/measure/compare.h"
#include "harness/measure/hardcases.h"
#include "harness/measure/sequence_run.h"
#include "harness/report/claims_table.h"
#include "harness/report/context.h"
#include "harness/report/html_report.h"
#include "harness/report/image_io.h"
#include "harness/report/report.h"
#include "harness/report/sequence_report.h"
#include "harness/report/shards.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// "K/N" with 1 <= K <= N -> (K - 1, N).
std::pair<int, int> parse_shard(const std::string& text) {
    int k = 0, n = 0;
    char slash = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &k, &slash, &n, &extra) != 3 || slash != '/' ||
        n < 1 || n > 100000 || k < 1 || k > n) {
        throw InputError(fmt::format("--shard: '{}' is not K/N with 1 <= K <= N", text));
    }
    return {k - 1, n};
}

// What "every built-in pattern" means: the default run's patterns, and the ones it leaves out.
std::string default_patterns_text() {
    std::vector<std::string> left_out;
    for (const PatternInfo& info : pattern_registry()) {
        if (!info.in_default_run) left_out.push_back(info.id);
    }
    if (left_out.empty()) return "every built-in pattern";
    std::string names = left_out.back();
    if (left_out.size() > 1) {
        left_out.pop_back();
        names = fmt::format("{} and {}", fmt::join(left_out, ", "), names);
    }
    return fmt::format(
        "every built-in pattern but {}, which the default run leaves out (the colour patterns, a "
        "page of text, the edge-drawing scenes, the mesh models); name them to run them",
        names);
}

class CompareCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand(
            "compare", "every method on every pattern against the exact reference, timed");
        cmd->add_option("--methods", methods_,
                        "method specs, comma-separated (default: every registered method)");
        cmd->add_option("--patterns", patterns_,
                        "pattern specs, comma-separated (default: " + default_patterns_text() +
                            ")");
        cmd->add_option("--scenes", scenes_,
                        "scene files (JSON, version 1 to 4), comma-separated, compared beside the "
                        "patterns (alone when --patterns is not given); rows are named by the "
                        "file stem. With --sequences: files carrying a sequence (version 3), "
                        "run after the named built-ins (alone when none is named)");
        cmd->add_option("--external", externals_,
                        "NAME[:srgb]='COMMAND {svg} {out}': another renderer, run as a process on "
                        "every scene, scored and timed like a method (repeatable; "
                        "docs/external.md)");
        cmd->add_flag("--web-peers", web_peers_,
                      "add Skia (@napi-rs/canvas) and tiny-skia (@resvg/resvg-js) as external "
                      "renderers through node (scripts/web-peers; each missing one is left out "
                      "in one line; docs/external.md)");
        size_option_ = cmd->add_option("--size", size_,
                                       "image size WxH of the patterns (scene files keep their "
                                       "own; refused with --scenes and no --patterns)")
                           ->capture_default_str();
        cmd->add_option("--runs", runs_,
                        "timed runs after one warm-up, at most, 1..1000 (median reported)")
            ->capture_default_str();
        cmd->add_option("--time-budget", time_budget_ms_,
                        "ms: a render's timed runs stop after 3 once they took this long "
                        "(0: always --runs), 0..1e6")
            ->capture_default_str();
        cmd->add_option("--out", out_,
                        "results directory (default: results/compare-<UTC date-time>)");
        cmd->add_flag("--sweep", sweep_,
                      "also run each method across its cost parameter (n or k): curves, not "
                      "points");
        cmd->add_option("--jobs", jobs_,
                        "parallel render-and-score tasks, 1..256; timing always runs alone, "
                        "serially, after them")
            ->capture_default_str();
        cmd->add_option("--render-threads", render_threads_,
                        "threads per render, 1..256: each image split in horizontal bands "
                        "(TBB); the timings then use as many threads, and the table says so")
            ->capture_default_str();
        auto* shard = cmd->add_option(
            "--shard", shard_,
            "K/N: run only the K-th of N disjoint slices of the tasks, balanced by estimated "
            "cost (see merge, docs/cluster.md)");
        cmd->add_option("--plan-shards", plan_shards_,
                        "N: print the split into N shards (each task's shard and estimate, "
                        "each shard's estimate and memory) and exit; runs nothing")
            ->check(CLI::Range(1, 100000))
            ->excludes(shard);
        cmd->add_option("--bench-json", bench_json_,
                        "take timings from aabench_bench --benchmark_format=json output where "
                        "it has them; its circle, cost-model and edge-stage benchmarks become "
                        "plots in the report");
        auto* hardcases = cmd->add_flag(
            "--hardcases", hardcases_,
            "run the hard-case suite for the report's table (the default without --scenes)");
        cmd->add_flag("--no-hardcases", no_hardcases_,
                      "leave the hard-case suite and its table out (the default with --scenes: "
                      "it takes seconds your scenes do not need)")
            ->excludes(hardcases);
        cmd->add_flag("--claims", claims_,
                      "also measure the papers' claims (aabench claims, about 30 s) and show "
                      "their table in the report");
        sequences_option_ =
            cmd->add_option("--sequences", sequences_,
                            "run every method on frame sequences instead of still patterns "
                            "(temporal measures; docs/sequences.md): the named ones, "
                            "comma-separated, or every built-in (aabench list) when no name and "
                            "no --scenes is given; a scene file's sequence: --sequences --scenes "
                            "FILE.json; --size (of the built-ins) then defaults to " +
                                fmt::format("{0}x{0}", kDefaultSequenceSide))
                ->expected(0, 1);
        frames_option_ =
            cmd->add_option("--frames", frames_,
                            "frames per sequence, 2..10000 (with --sequences; a scene file's "
                            "\"frames\" is its own)")
                ->capture_default_str();
        cmd->add_flag("--quiet", quiet_, "no table on stdout, no progress on stderr");
        return cmd;
    }

    int run(const Invocation& inv) override {
        if (sequences_option_->count() > 0) return run_sequence_mode(inv);
        if (frames_option_->count() > 0) {
            throw InputError("--frames: applies to --sequences only; give --sequences too");
        }
        const auto start = std::chrono::steady_clock::now();
        CompareOptions options = parse_options();
        if (plan_shards_ > 0) options.shard_count = plan_shards_;
        std::vector<ExternalRenderer> externals;
        for (const std::string& text : externals_) externals.push_back(parse_external(text));
        if (web_peers_) {
            WebPeers peers = find_web_peers();
            for (const std::string& line : peers.left_out) fmt::print(stderr, "{}\n", line);
            for (ExternalRenderer& r : peers.renderers) externals.push_back(std::move(r));
        }
        check_externals(externals, options);
        if (plan_shards_ > 0) {
            fmt::print("{}", format_shard_plan(plan_shards(options)));
            return 0;
        }
        std::string bench_json;
        // Read and checked before any work, so a bad file costs no run and writes nothing.
        std::vector<CircleTimingSeries> circle_timings;
        CostModel cost_model;
        EdgeTimings edge_timings;
        if (!bench_json_.empty()) {
            bench_json = read_text(bench_json_);
            circle_timings = circle_timings_from_benchmark(bench_json, bench_json_);
            cost_model = cost_model_from_benchmark(bench_json, bench_json_);
            edge_timings = edge_timings_from_benchmark(bench_json, bench_json_);
        }
        const RunContext context = capture_context(inv.argc, inv.argv);
        ProgressBar bar(!quiet_ && stderr_is_terminal());
        const std::string dir = out_.empty() ? default_results_dir("compare") : out_;
        const auto tasks_start = std::chrono::steady_clock::now();
        CompareResult result = run_comparison(options, std::ref(bar));
        const double tasks_s = seconds_since(tasks_start);
        add_external_rows(externals, options, result, std::ref(bar));
        if (!bench_json_.empty()) {
            const int updated = apply_benchmark_timings(result.rows, bench_json, bench_json_);
            if (!quiet_) {
                fmt::print(stderr, "timings of {} of {} rows taken from {}\n", updated,
                           result.rows.size(), bench_json_);
            }
        }
        std::string hard_table;
        // The suite is about the methods, not the user's scenes: a run of one's own scenes
        // does not wait for it unless asked.
        if (hardcases_ || (!no_hardcases_ && scenes_.empty())) {
            std::vector<std::string> specs = options.method_specs;
            if (specs.empty()) specs = default_hard_case_methods();
            // As parallel as the comparison: --jobs threads (run_hard_cases runs on TBB).
            const tbb::global_control threads(tbb::global_control::max_allowed_parallelism,
                                              static_cast<std::size_t>(options.jobs));
            hard_table = format_hard_case_table(run_hard_cases(specs, std::ref(bar)));
        }
        const std::string claims =
            claims_ ? claims_html_section(measure_claims(ClaimsOptions{})) : std::string();
        // A marker left by an earlier run into this folder must not vouch for this one's files
        // while they are being written: it goes now, and comes back last.
        std::error_code ec;
        std::filesystem::remove(std::filesystem::path(dir) / kShardMarkerFile, ec);
        write_compare_results(dir, result.rows, context);
        write_html_report(dir, ReportData{context, result.rows, std::move(result.figures),
                                          hard_table, std::move(circle_timings),
                                          std::move(cost_model), std::move(edge_timings),
                                          claims});
        ShardMarker marker = make_shard_marker(options, result);
        marker.tasks_s = tasks_s;
        marker.wall_s = seconds_since(start);
        // Last: its presence says every other file of the folder is complete.
        write_text_file((std::filesystem::path(dir) / kShardMarkerFile).string(),
                        shard_marker_json(marker));
        if (!quiet_) {
            fmt::print("{}\nresults written to {}/: index.html (the report), table.txt, "
                       "results.csv, results.json\n",
                       format_compare_tables(result.rows), dir);
        }
        return 0;
    }

private:
    // compare --sequences: every method on every sequence (harness/measure/sequence_run.h).
    int run_sequence_mode(const Invocation& inv) {
        if (!patterns_.empty() || !externals_.empty() || web_peers_ || !shard_.empty() ||
            plan_shards_ > 0 ||
            sweep_ || !bench_json_.empty() || claims_ || hardcases_) {
            throw InputError(
                "--sequences: runs the built-in sequences and scene files' with --methods, "
                "--scenes, --size, --frames, --jobs and --out only (leave out --patterns, "
                "--external, --web-peers, --shard, --plan-shards, --sweep, --bench-json, "
                "--claims, --hardcases)");
        }
        SequenceRunOptions options;
        if (!sequences_.empty()) options.sequences = split_spec_list(sequences_);
        if (!methods_.empty()) options.method_specs = split_spec_list(methods_);
        // Every file read and checked here, before any work: a bad one fails at once.
        if (!scenes_.empty()) {
            options.scene_files = read_scene_files(split_path_list(scenes_, "--scenes"));
        }
        if (size_option_->count() > 0) {
            if (!scenes_.empty() && sequences_.empty()) {
                throw InputError(
                    "--size: applies to the built-in sequences only, and none is asked for; a "
                    "scene file has its own size (name built-ins in --sequences too, or leave "
                    "--size out)");
            }
            std::tie(options.width, options.height) = parse_size(size_, "--size");
        }
        options.frames = frames_;
        options.jobs = jobs_;
        const RunContext context = capture_context(inv.argc, inv.argv);
        ProgressBar bar(!quiet_ && stderr_is_terminal());
        const std::string dir = out_.empty() ? default_results_dir("sequences") : out_;
        const SequenceRunResult result = run_sequences(options, std::ref(bar));
        write_sequence_results(dir, result, context);
        if (!quiet_) {
            fmt::print("{}\nresults written to {}/: index.html (the report), table.txt, "
                       "results.csv, results.json, frames.csv, frames.json\n",
                       format_sequence_tables(result.rows), dir);
        }
        return 0;
    }

    CompareOptions parse_options() const {
        CompareOptions options;
        if (!methods_.empty()) options.method_specs = split_spec_list(methods_);
        if (!patterns_.empty()) options.pattern_specs = split_spec_list(patterns_);
        // Every file read and checked here, before any work: a bad one fails at once.
        if (!scenes_.empty()) {
            options.scene_files = read_scene_files(split_path_list(scenes_, "--scenes"));
        }
        if (size_option_->count() > 0 && !scenes_.empty() && patterns_.empty()) {
            throw InputError(
                "--size: applies to the built-in patterns only, and none is asked for; a scene "
                "file has its own size (give --patterns too, or leave --size out)");
        }
        std::tie(options.width, options.height) = parse_size(size_, "--size");
        options.runs = runs_;
        options.time_budget_ms = time_budget_ms_;
        options.sweep = sweep_;
        options.jobs = jobs_;
        options.render_threads = render_threads_;
        if (!shard_.empty()) std::tie(options.shard_index, options.shard_count) = parse_shard(shard_);
        return options;
    }

    // Names unique and not a method's; no shards (the rows of a process do not split).
    static void check_externals(const std::vector<ExternalRenderer>& externals,
                                const CompareOptions& options) {
        for (std::size_t k = 0; k < externals.size(); ++k) {
            for (std::size_t m = 0; m < k; ++m) {
                if (externals[m].name == externals[k].name) {
                    throw InputError("--external: the name '" + externals[k].name +
                                     "' is given twice (--web-peers adds skia and resvg)");
                }
            }
        }
        if (!externals.empty() && options.shard_count > 1) {
            throw InputError(
                "--external and --web-peers run whole, not in shards: leave out --shard");
        }
    }

    std::vector<std::string> externals_;
    std::string methods_, patterns_, scenes_, size_ = "256x256", out_, shard_, bench_json_;
    int runs_ = 7, jobs_ = 1, render_threads_ = 1, plan_shards_ = 0;
    double time_budget_ms_ = 50.0;
    bool quiet_ = false, sweep_ = false, hardcases_ = false, no_hardcases_ = false,
         claims_ = false, web_peers_ = false;
    CLI::Option* size_option_ = nullptr;
    std::string sequences_;
    int frames_ = kDefaultSequenceFrames;
    CLI::Option* sequences_option_ = nullptr;
    CLI::Option* frames_option_ = nullptr;
};

class MergeCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand("merge", "join the results of compare --shard runs");
        cmd->add_option("dirs", dirs_, "results directories of the shards")->required();
        cmd->add_option("--out", out_,
                        "merged results directory (default: results/merge-<UTC date-time>)");
        cmd->add_option("--same-as", same_as_,
                        "a results directory of the unsharded run: after merging, its error "
                        "columns must equal the merged ones bit for bit (exit 1 otherwise)");
        return cmd;
    }
    int run(const Invocation& inv) override {
        // Everything read and checked before anything is written: a refused merge leaves no
        // folder behind.
        std::vector<ShardFolder> folders;
        for (const std::string& d : dirs_) {
            ShardFolder& f = folders.emplace_back();
            f.dir = d;
            const std::filesystem::path marker = std::filesystem::path(d) / kShardMarkerFile;
            if (std::filesystem::exists(marker)) f.marker_text = read_text(marker.string());
            if (f.marker_text) {
                f.results_text = read_text((std::filesystem::path(d) / "results.json").string());
            }
        }
        const MergedShards merged = merge_shard_folders(folders);
        const std::vector<ResultRow>& rows = merged.rows;
        std::optional<std::vector<ResultRow>> unsharded;
        if (!same_as_.empty()) {
            const std::string path = (std::filesystem::path(same_as_) / "results.json").string();
            unsharded = rows_from_compare_json(read_text(path), path);
        }
        std::vector<std::string> scene_paths;  // the scene files' figures need the files again
        for (const ResultRow& r : rows) {
            if (!r.scene_file.empty() && std::find(scene_paths.begin(), scene_paths.end(),
                                                   r.scene_file) == scene_paths.end()) {
                scene_paths.push_back(r.scene_file);
            }
        }
        const std::vector<SceneFileInput> scenes = read_scene_files(scene_paths);
        const RunContext context = capture_context(inv.argc, inv.argv);
        const std::string dir = out_.empty() ? default_results_dir("merge") : out_;
        write_compare_results(dir, rows, context);
        write_html_report(dir, ReportData{context, rows, render_figures(rows, scenes), {}});
        fmt::print("{}\nmerged {} row{} from {} shard{} into {}/ (index.html, table.txt, "
                   "results.csv, results.json, shards.txt)\n",
                   format_compare_tables(rows), rows.size(), rows.size() == 1 ? "" : "s",
                   dirs_.size(), dirs_.size() == 1 ? "" : "s", dir);
        // Estimated against measured, per shard (docs/cluster.md, "What to expect").
        const std::string times = format_shard_times(merged.markers);
        write_text_file((std::filesystem::path(dir) / "shards.txt").string(), times);
        fmt::print("{}", times);
        if (unsharded) {
            const std::string diff = error_column_difference(rows, *unsharded);
            if (!diff.empty()) {
                fmt::print(stderr, "merged != unsharded ({}): {}\n", same_as_, diff);
                return 1;
            }
            fmt::print(
                "merged == unsharded: the error columns of {} rows equal {}'s bit for bit\n",
                rows.size(), same_as_);
        }
        return 0;
    }

private:
    std::vector<std::string> dirs_;
    std::string out_, same_as_;
};

}  // namespace

std::unique_ptr<Command> make_compare_command() { return std::make_unique<CompareCommand>(); }
std::unique_ptr<Command> make_merge_command() { return std::make_unique<MergeCommand>(); }

}  // namespace aabench
