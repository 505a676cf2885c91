// The aabench command line: subcommands list, render, reference, export, compare, merge,
// hardcases.
// Parsing happens here and nowhere else; each subcommand calls library stages in the order
// pattern/scene -> method -> image -> reference, metrics, timing -> results -> report.
#include "harness/cli.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/chrono.h>
#include <fmt/format.h>

#include "harness/box_reference.h"
#include "harness/compare.h"
#include "harness/context.h"
#include "harness/filter_reference.h"
#include "harness/hardcases.h"
#include "harness/html_report.h"
#include "harness/limits.h"
#include "harness/image_io.h"
#include "harness/report.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene_io.h"

namespace aabench {
namespace {

struct SceneSource {
    std::string scene_file;
    std::string pattern;
    std::string size;
};

// "WxH" -> (W, H), checked against the size limits.
std::pair<int, int> parse_size(const std::string& text, const std::string& where) {
    const auto x = text.find('x');
    long long w = -1, h = -1;
    try {
        std::size_t used_w = 0, used_h = 0;
        if (x == std::string::npos) throw std::invalid_argument("no x");
        w = std::stoll(text.substr(0, x), &used_w);
        h = std::stoll(text.substr(x + 1), &used_h);
        if (used_w != x || used_h != text.size() - x - 1) throw std::invalid_argument("junk");
    } catch (const std::exception&) {
        throw InputError(fmt::format("{}: '{}' is not a size of the form WxH (e.g. 256x256)",
                                     where, text));
    }
    check_image_size(w, h, where);
    return {static_cast<int>(w), static_cast<int>(h)};
}

void add_scene_options(CLI::App* cmd, SceneSource& src) {
    auto* scene = cmd->add_option("--scene", src.scene_file, "scene file (JSON, docs/scene-format.md)");
    auto* pattern = cmd->add_option("--pattern", src.pattern, "built-in pattern ID[:key=value,...]");
    auto* size = cmd->add_option("--size", src.size, "image size WxH, with --pattern");
    scene->excludes(pattern)->excludes(size);
    pattern->needs(size);
    size->needs(pattern);
}

Scene load_scene(const SceneSource& src) {
    if (!src.scene_file.empty()) return read_scene_file(src.scene_file);
    if (src.pattern.empty()) throw InputError("give --scene FILE.json or --pattern ID --size WxH");
    const auto [w, h] = parse_size(src.size, "--size");
    return make_pattern(src.pattern, w, h);
}

// Rejects an unsupported output extension before any rendering work is done.
void check_image_output_path(const std::string& path) {
    for (const char* ext : {".exr", ".pfm", ".png"}) {
        const std::string e(ext);
        if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0) {
            return;
        }
    }
    throw InputError(fmt::format("--out: {}: unsupported image format (use .exr, .pfm or .png)", path));
}

std::string param_line(const ParamSpec& p) {
    return fmt::format("      {:<14} default {:<10} range {:<16} {}", p.name, p.default_string(),
                       p.range_string(), p.doc);
}

int cmd_list() {
    fmt::print("methods (--method ID[:key=value,...]):\n");
    for (const MethodInfo& m : method_registry()) {
        fmt::print("  {:<18} {}\n", m.id, m.summary);
        for (const ParamSpec& p : m.params) fmt::print("{}\n", param_line(p));
    }
    fmt::print("\npatterns (--pattern ID[:key=value,...]):\n");
    for (const PatternInfo& p : pattern_registry()) {
        fmt::print("  {:<18} {}\n", p.id, p.summary);
        for (const ParamSpec& q : p.params) fmt::print("{}\n", param_line(q));
    }
    fmt::print("\nreference filters (aabench reference --filter ID[:key=value,...]):\n");
    for (const ReferenceFilterInfo& f : reference_filter_registry()) {
        fmt::print("  {:<18} {}\n", f.id, f.summary);
        for (const ParamSpec& q : f.params) fmt::print("{}\n", param_line(q));
    }
    return 0;
}

std::string default_results_dir(const std::string& kind) {
    const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    return fmt::format("results/{}-{:%Y%m%d-%H%M%S}", kind, fmt::gmtime(now));
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

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(fmt::format("{}: cannot open ({})", path, std::strerror(errno)));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(fmt::format("{}: cannot read", path));
    return text;
}

// A progress bar with an estimate of the time left, on stderr, redrawn in place; off when
// stderr is not a terminal (logs and CI get no control characters).
class ProgressBar {
public:
    explicit ProgressBar(bool enabled)
        : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}
    void operator()(std::size_t done, std::size_t total, const std::string& what) {
        if (!enabled_ || total == 0) return;
        constexpr int kWidth = 30;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double left = elapsed / done * (total - done);
        const int filled = static_cast<int>(kWidth * done / total);
        fmt::print(stderr, "\r\033[K[{}{}] {}/{}  {:.0f}:{:02.0f} left  {}",
                   std::string(filled, '#'), std::string(kWidth - filled, '.'), done, total,
                   std::floor(left / 60), std::fmod(left, 60.0), what);
        if (done == total) fmt::print(stderr, "\r\033[K");
    }

private:
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
};


}  // namespace

int run_cli(int argc, char** argv) {
    CLI::App app{"aabench: image-quality evaluation and benchmark suite for antialiasing"};
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "help for every subcommand");

    app.add_subcommand("list", "methods, patterns and reference filters with their parameters");

    SceneSource render_src;
    std::string render_method, render_out;
    auto* render = app.add_subcommand("render", "render a scene with one method to an image");
    add_scene_options(render, render_src);
    render->add_option("--method", render_method, "method ID[:key=value,...]")->required();
    render->add_option("--out", render_out, "output image: .exr (float32), .pfm, .png (16-bit)")
        ->required();

    SceneSource ref_src;
    std::string ref_filter = "box", ref_out;
    auto* reference = app.add_subcommand("reference", "write the exact reference image");
    add_scene_options(reference, ref_src);
    reference->add_option("--filter", ref_filter,
                          "box, gaussian[:sigma=S,radius=R] or cone[:radius=R]")
        ->capture_default_str();
    reference->add_option("--out", ref_out, "output image: .exr, .pfm, .png")->required();

    std::string export_pattern, export_size, export_out;
    auto* exp = app.add_subcommand("export", "write a built-in pattern as a scene file");
    exp->add_option("--pattern", export_pattern, "pattern ID[:key=value,...]")->required();
    exp->add_option("--size", export_size, "image size WxH")->required();
    exp->add_option("--out", export_out, "output scene file (.json)")->required();

    std::string compare_methods, compare_patterns, compare_size = "256x256", compare_out;
    std::string compare_shard, compare_bench_json;
    int compare_runs = 7, compare_jobs = 1;
    bool compare_quiet = false, compare_sweep = false;
    auto* compare = app.add_subcommand(
        "compare", "every method on every pattern against the exact reference, timed");
    compare->add_option("--methods", compare_methods,
                        "method specs, comma-separated (default: every registered method)");
    compare->add_option("--patterns", compare_patterns,
                        "pattern specs, comma-separated (default: every built-in pattern)");
    compare->add_option("--size", compare_size, "image size WxH")->capture_default_str();
    compare->add_option("--runs", compare_runs, "timed runs after one warm-up (median reported)")
        ->capture_default_str();
    compare->add_option("--out", compare_out,
                        "results directory (default: results/compare-<UTC date-time>)");
    compare->add_flag("--sweep", compare_sweep,
                      "also run each method across its cost parameter (n or k): curves, not points");
    compare->add_option("--jobs", compare_jobs,
                        "parallel render-and-score tasks; timing always runs alone, serially, "
                        "after them")
        ->capture_default_str();
    compare->add_option("--shard", compare_shard,
                        "K/N: run only the K-th of N disjoint slices of the tasks (see merge)");
    compare->add_option("--bench-json", compare_bench_json,
                        "take timings from aabench_bench --benchmark_format=json output where "
                        "it has them");
    bool compare_no_hardcases = false;
    compare->add_flag("--no-hardcases", compare_no_hardcases,
                      "leave the hard-case table out of the report (saves a few seconds)");
    compare->add_flag("--quiet", compare_quiet, "no table on stdout, no progress on stderr");

    std::string hard_methods, hard_out;
    auto* hardcases = app.add_subcommand(
        "hardcases", "degenerate and enormous geometry against every method and reference: "
                     "invariants checked, exit 1 if any fails");
    hardcases->add_option("--methods", hard_methods,
                          "method specs, comma-separated (default: every registered method, "
                          "plus n and k at their maxima)");
    hardcases->add_option("--out", hard_out,
                          "also write hardcases.txt and hardcases.json into this directory");

    std::vector<std::string> merge_dirs;
    std::string merge_out;
    auto* merge = app.add_subcommand("merge", "join the results of compare --shard runs");
    merge->add_option("dirs", merge_dirs, "results directories of the shards")->required();
    merge->add_option("--out", merge_out,
                      "merged results directory (default: results/merge-<UTC date-time>)");

    // CLI11 reports an unknown first word as "A subcommand is required"; name it instead.
    if (argc > 1 && argv[1][0] != '-') {
        const std::string word = argv[1];
        bool known = false;
        for (const CLI::App* sub : app.get_subcommands({})) known |= sub->get_name() == word;
        if (!known) {
            fmt::print(stderr,
                       "aabench: unknown command '{}' (valid: list, render, reference, export, "
                       "compare, merge, hardcases)\n",
                       word);
            return 2;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::string message = e.what();
        std::replace(message.begin(), message.end(), '\n', ' ');
        fmt::print(stderr, "aabench: {} (see aabench --help)\n", message);
        return 2;
    }

    try {
        if (app.got_subcommand("list")) return cmd_list();
        if (render->parsed()) {
            const MethodInstance method = make_method(render_method);  // check before work
            check_image_output_path(render_out);
            const Scene scene = load_scene(render_src);
            check_job_memory(estimate_job_bytes(measure_scene(scene), {method.spec}, {}),
                             kDefaultMemoryBudgetBytes, "render");
            write_image(render_out, render_scene(*method.method, scene));
            return 0;
        }
        if (reference->parsed()) {
            try {
                canonical_reference_spec(ref_filter);  // check before any work
            } catch (const InputError& e) {
                throw InputError(std::string("--filter: ") + e.what());
            }
            check_image_output_path(ref_out);
            const Scene scene = load_scene(ref_src);
            check_job_memory(estimate_job_bytes(measure_scene(scene), {}, {ref_filter}),
                             kDefaultMemoryBudgetBytes, "reference");
            const Coverage cov = exact_reference(scene, ref_filter);
            Image image(cov.width, cov.height);
            for (std::size_t k = 0; k < cov.data.size(); ++k) {
                image.data[k] = static_cast<float>(cov.data[k]);
            }
            write_image(ref_out, image);
            return 0;
        }
        if (exp->parsed()) {
            const auto [w, h] = parse_size(export_size, "--size");
            write_text_file(export_out, scene_to_json(make_pattern(export_pattern, w, h)));
            return 0;
        }
        if (compare->parsed()) {
            CompareOptions options;
            if (!compare_methods.empty()) options.method_specs = split_spec_list(compare_methods);
            if (!compare_patterns.empty()) {
                options.pattern_specs = split_spec_list(compare_patterns);
            }
            std::tie(options.width, options.height) = parse_size(compare_size, "--size");
            options.runs = compare_runs;
            options.sweep = compare_sweep;
            options.jobs = compare_jobs;
            if (!compare_shard.empty()) {
                std::tie(options.shard_index, options.shard_count) = parse_shard(compare_shard);
            }
            std::string bench_json;
            if (!compare_bench_json.empty()) bench_json = read_text(compare_bench_json);
            const RunContext context = capture_context(argc, argv);
            ProgressBar bar(!compare_quiet && isatty(STDERR_FILENO));
            CompareResult result = run_comparison(options, std::ref(bar));
            if (!compare_bench_json.empty()) {
                const int updated =
                    apply_benchmark_timings(result.rows, bench_json, compare_bench_json);
                if (!compare_quiet) {
                    fmt::print(stderr, "timings of {} of {} rows taken from {}\n", updated,
                               result.rows.size(), compare_bench_json);
                }
            }
            const std::string dir =
                compare_out.empty() ? default_results_dir("compare") : compare_out;
            std::string hard_table;
            if (!compare_no_hardcases) {
                std::vector<std::string> specs = options.method_specs;
                if (specs.empty()) specs = default_hard_case_methods();
                hard_table = format_hard_case_table(run_hard_cases(specs, std::ref(bar)));
            }
            write_compare_results(dir, result.rows, context);
            write_html_report(dir, ReportData{context, result.rows, std::move(result.figures),
                                              hard_table});
            if (!compare_quiet) {
                fmt::print("{}\nresults written to {}/: index.html (the report), table.txt, "
                           "results.csv, results.json\n",
                           format_compare_tables(result.rows), dir);
            }
            return 0;
        }
        if (hardcases->parsed()) {
            std::vector<std::string> specs =
                hard_methods.empty() ? default_hard_case_methods() : split_spec_list(hard_methods);
            ProgressBar bar(isatty(STDERR_FILENO));
            const std::vector<HardCaseRow> rows = run_hard_cases(specs, std::ref(bar));
            const std::string table = format_hard_case_table(rows);
            if (!hard_out.empty()) {
                std::error_code ec;
                std::filesystem::create_directories(hard_out, ec);
                if (ec) throw InputError(fmt::format("--out: {}: {}", hard_out, ec.message()));
                write_text_file((std::filesystem::path(hard_out) / "hardcases.txt").string(),
                                "command: " + capture_context(argc, argv).command + "\n" + table);
                write_text_file((std::filesystem::path(hard_out) / "hardcases.json").string(),
                                format_hard_case_json(rows));
            }
            fmt::print("{}", table);
            const bool failed = std::any_of(rows.begin(), rows.end(), [](const HardCaseRow& r) {
                return r.outcome == Outcome::kFail;
            });
            return failed ? 1 : 0;
        }
        if (merge->parsed()) {
            std::vector<std::vector<ResultRow>> shards;
            for (const std::string& d : merge_dirs) {
                const std::string path = (std::filesystem::path(d) / "results.json").string();
                shards.push_back(rows_from_compare_json(read_text(path), path));
            }
            const std::vector<ResultRow> rows = merge_shard_rows(std::move(shards));
            const RunContext context = capture_context(argc, argv);
            const std::string dir = merge_out.empty() ? default_results_dir("merge") : merge_out;
            write_compare_results(dir, rows, context);
            write_html_report(dir, ReportData{context, rows, render_figures(rows), {}});
            fmt::print("{}\nmerged {} rows from {} shards into {}/ (index.html, table.txt, "
                       "results.csv, results.json)\n",
                       format_compare_tables(rows), rows.size(), merge_dirs.size(), dir);
            return 0;
        }
    } catch (const InputError& e) {
        fmt::print(stderr, "aabench: {}\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "aabench: internal error: {}\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace aabench
