// aabench check: the regression gate. Runs a baseline's rows again (same patterns, scene files,
// methods, sizes) and exits 1 when a gated error figure got worse beyond the tolerance
// (harness/measure/gate.h says which figures, and how NaN and timings are treated).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "harness/cli/command.h"
#include "harness/measure/gate.h"
#include "harness/report/context.h"
#include "harness/report/gate_report.h"
#include "harness/report/report.h"
#include "patterns/scene/params.h"

namespace aabench {
namespace {

// A non-negative finite number, or InputError naming `where`.
double parse_non_negative(const std::string& text, const std::string& where) {
    double value = 0.0;
    std::size_t used = 0;
    try {
        value = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || !std::isfinite(value) || value < 0.0) {
        throw InputError(fmt::format("{}: '{}' is not a non-negative number", where, text));
    }
    return value;
}

// "rel=R,abs=A", either key optional.
void parse_tolerance(const std::string& text, GateTolerance& tolerance) {
    for (const std::string& item : split_path_list(text, "--tolerance")) {
        const auto eq = item.find('=');
        const std::string key = item.substr(0, eq);
        if (eq == std::string::npos || (key != "rel" && key != "abs")) {
            throw InputError(fmt::format(
                "--tolerance: '{}' is not rel=R or abs=A (e.g. rel=0.05,abs=1e-4){}", item,
                did_you_mean(key, {"rel", "abs"})));
        }
        (key == "rel" ? tolerance.rel : tolerance.abs) =
            parse_non_negative(item.substr(eq + 1), "--tolerance " + key);
    }
}

class CheckCommand : public Command {
public:
    CLI::App* add_to(CLI::App& app) override {
        auto* cmd = app.add_subcommand(
            "check",
            "regression gate: run a baseline's rows again, exit 1 when an error got worse");
        cmd->add_option("--baseline", baseline_, "a results.json (e.g. results/baselines/*.json)")
            ->required();
        cmd->add_option("--tolerance", tolerance_,
                        "worse when new > old * (1 + rel) + abs (default rel=0.05,abs=1e-4)");
        cmd->add_option("--time-tolerance", time_tolerance_,
                        "also gate the median time: worse when new > old * (1 + REL)");
        cmd->add_option("--runs", runs_,
                        "timed runs per row (default: as many as the baseline's rows had)");
        cmd->add_option("--jobs", jobs_, "parallel render-and-score tasks, 1..256")
            ->capture_default_str();
        cmd->add_option("--out", out_,
                        "also write the new run's results here (to renew a baseline)");
        cmd->add_flag("--list-moved", list_moved_,
                      "also list the figures that moved within the tolerance (not those whose "
                      "printed values are equal)");
        return cmd;
    }

    int run(const Invocation& inv) override {
        GateTolerance tolerance;
        if (!tolerance_.empty()) parse_tolerance(tolerance_, tolerance);
        if (!time_tolerance_.empty()) {
            tolerance.time_rel = parse_non_negative(time_tolerance_, "--time-tolerance");
        }
        // Columns an older build did not write read as NaN: the gate reports them as appeared.
        std::vector<ResultRow> baseline =
            rows_from_compare_json(read_text(baseline_), baseline_, true);
        resolve_specs_again(baseline);
        if (baseline.empty()) throw InputError(baseline_ + ": the baseline has no rows");
        std::vector<std::string> scene_paths;
        for (const ResultRow& r : baseline) {
            if (!r.scene_file.empty() && std::find(scene_paths.begin(), scene_paths.end(),
                                                   r.scene_file) == scene_paths.end()) {
                scene_paths.push_back(r.scene_file);
            }
        }
        CompareOptions base;
        base.jobs = jobs_;
        base.keep_images = false;
        base.runs = runs_;
        // Every run counts: the time gate compares medians of the same number of runs.
        base.time_budget_ms = 0.0;
        if (runs_ == 0) {
            base.runs = 1;
            for (const ResultRow& r : baseline) base.runs = std::max(base.runs, r.time_runs);
        }
        const std::vector<CompareOptions> runs =
            rerun_options(baseline, read_scene_files(scene_paths), base);

        const RunContext context = capture_context(inv.argc, inv.argv);
        ProgressBar bar(stderr_is_terminal());
        std::vector<ResultRow> current;
        for (const CompareOptions& options : runs) {
            for (ResultRow& r : run_comparison(options, std::ref(bar)).rows) {
                current.push_back(std::move(r));
            }
        }
        const GateResult result = gate_rows(baseline, current, tolerance);
        if (!out_.empty()) write_compare_results(out_, current, context);
        fmt::print("{}", format_gate(result, tolerance, baseline_, list_moved_));
        return result.passed() ? 0 : 1;
    }

private:
    std::string baseline_, tolerance_, time_tolerance_, out_;
    int runs_ = 0, jobs_ = 1;
    bool list_moved_ = false;
};

}  // namespace

std::unique_ptr<Command> make_check_command() { return std::make_unique<CheckCommand>(); }

}  // namespace aabench
