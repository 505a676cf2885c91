// aabench check, the regression gate: the verdict rules (NaN, infinity, tolerance, missing
// rows, timings) on made-up rows; the re-run plan; and end to end, the gate passing on an
// unchanged run and failing on a baseline better than reality, through the library and the
// command line.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "harness/measure/compare.h"
#include "harness/measure/gate.h"
#include "harness/report/context.h"
#include "harness/report/gate_report.h"
#include "harness/report/report.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"
#include "tests/cli_runner.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

constexpr double kInf = std::numeric_limits<double>::infinity();

ResultRow made_up_row(const std::string& pattern, const std::string& method) {
    ResultRow r;
    r.pattern = r.pattern_id = pattern;
    r.method = r.method_id = method;
    r.width = r.height = 16;
    r[metric::kBoxRmse] = r[metric::kOwnRmse] = 0.01;
    r[metric::kBoxMaxAbs] = r[metric::kOwnMaxAbs] = 0.2;
    r[metric::kEdgeRmse] = 0.02;
    r[metric::kCrawl] = 0.003;
    r[metric::kTimeMedianNs] = 1000.0;
    return r;
}

std::vector<GateVerdict> verdicts(const GateResult& result) {
    std::vector<GateVerdict> v;
    for (const GateChange& c : result.changes) v.push_back(c.verdict);
    return v;
}

TEST(Gate, UnchangedRowsPassWithNoChange) {
    const std::vector<ResultRow> rows = {made_up_row("star", "none"), made_up_row("star", "agg")};
    const GateResult result = gate_rows(rows, rows, GateTolerance{});
    EXPECT_TRUE(result.passed());
    EXPECT_TRUE(result.changes.empty());
    EXPECT_EQ(result.rows_checked, 2);
    EXPECT_EQ(result.figures_checked, 2 * static_cast<long long>(gated_metrics().size()));
    EXPECT_DOUBLE_EQ(result.time_ratio_geomean, 1.0);
}

TEST(Gate, WorseMeansBeyondRelativePlusAbsolute) {
    const GateTolerance tolerance{0.05, 1e-4};
    const std::vector<ResultRow> old_rows = {made_up_row("star", "none")};
    std::vector<ResultRow> new_rows = old_rows;
    // The bound is 0.01 * 1.05 + 1e-4 = 0.0106: just under passes (within), just over fails.
    new_rows[0][metric::kBoxRmse] = 0.0106 - 1e-9;
    EXPECT_EQ(verdicts(gate_rows(old_rows, new_rows, tolerance)),
              std::vector<GateVerdict>{GateVerdict::kWithin});
    new_rows[0][metric::kBoxRmse] = 0.0106 + 1e-9;
    GateResult worse = gate_rows(old_rows, new_rows, tolerance);
    EXPECT_FALSE(worse.passed());
    ASSERT_EQ(worse.changes.size(), 1u);
    EXPECT_EQ(worse.changes[0].figure, "box_rmse");
    EXPECT_EQ(worse.changes[0].method, "none");
    new_rows[0][metric::kBoxRmse] = 0.001;
    EXPECT_EQ(verdicts(gate_rows(old_rows, new_rows, tolerance)),
              std::vector<GateVerdict>{GateVerdict::kBetter});
}

TEST(Gate, NanAndInfinityFollowTheDocumentedRules) {
    ResultRow old_row = made_up_row("room", "none");
    ResultRow new_row = old_row;
    // Not measured before, measured now: reported, not gated.
    old_row[metric::kSeamsMax] = kNaN;
    new_row[metric::kSeamsMax] = 0.3;
    GateResult r = gate_rows({old_row}, {new_row}, GateTolerance{});
    EXPECT_TRUE(r.passed());
    EXPECT_EQ(verdicts(r), std::vector<GateVerdict>{GateVerdict::kAppeared});
    // Measured before, NaN now: worse.
    old_row[metric::kSeamsMax] = 0.3;
    new_row[metric::kSeamsMax] = kNaN;
    EXPECT_FALSE(gate_rows({old_row}, {new_row}, GateTolerance{}).passed());
    // NaN both times: unchanged.
    old_row[metric::kSeamsMax] = new_row[metric::kSeamsMax] = kNaN;
    EXPECT_TRUE(gate_rows({old_row}, {new_row}, GateTolerance{}).changes.empty());
    // Infinity: nothing is worse than it; reaching it from a finite value is.
    old_row[metric::kCrawl] = kInf;
    new_row[metric::kCrawl] = 5.0;
    EXPECT_TRUE(gate_rows({old_row}, {new_row}, GateTolerance{}).passed());
    old_row[metric::kCrawl] = 0.003;
    new_row[metric::kCrawl] = kInf;
    EXPECT_FALSE(gate_rows({old_row}, {new_row}, GateTolerance{}).passed());
}

TEST(Gate, AMissingRowFailsAndTimesAreGatedOnlyWhenAsked) {
    const ResultRow a = made_up_row("star", "none"), b = made_up_row("star", "agg");
    const GateResult missing = gate_rows({a, b}, {a}, GateTolerance{});
    EXPECT_FALSE(missing.passed());
    EXPECT_EQ(verdicts(missing), std::vector<GateVerdict>{GateVerdict::kMissing});

    ResultRow slow = a;
    slow[metric::kTimeMedianNs] = 3 * a[metric::kTimeMedianNs];
    const GateResult reported = gate_rows({a}, {slow}, GateTolerance{});
    EXPECT_TRUE(reported.passed());
    EXPECT_DOUBLE_EQ(reported.time_ratio_max, 3.0);
    GateTolerance timed;
    timed.time_rel = 1.0;  // twice as slow is the most that passes
    EXPECT_FALSE(gate_rows({a}, {slow}, timed).passed());
    timed.time_rel = 2.5;
    EXPECT_TRUE(gate_rows({a}, {slow}, timed).passed());
}

// ---- What check prints ----

// The lines of `text` that contain `needle`.
long long lines_with(const std::string& text, const std::string& needle) {
    long long count = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        count += text.substr(start, end - start).find(needle) != std::string::npos;
        start = end + 1;
    }
    return count;
}

TEST(GateReport, SaysHowManyMovedAndListsOnlyThoseBeyondTheTolerance) {
    const GateTolerance tolerance{0.05, 1e-4};
    const std::vector<ResultRow> old_rows = {made_up_row("star", "none"),
                                             made_up_row("star", "agg"),
                                             made_up_row("strips", "exact")};
    std::vector<ResultRow> new_rows = old_rows;
    // Moved past the printed digits (0.01 prints as 0.01 either way): counted, never listed.
    new_rows[0][metric::kBoxRmse] = 0.01 * (1 + 1e-12);
    // Moved visibly, within the tolerance (bound 0.0106): listed only with list_moved.
    new_rows[1][metric::kEdgeRmse] = 0.0201;
    // Beyond the tolerance: always listed.
    new_rows[2][metric::kCrawl] = 0.01;
    const GateResult result = gate_rows(old_rows, new_rows, tolerance);
    ASSERT_EQ(result.changes.size(), 3u);
    const std::string text = format_gate(result, tolerance, "base.json");
    const long long figures = 3 * static_cast<long long>(gated_metrics().size());
    EXPECT_NE(text.find(fmt::format("{} gated figures compared: {} unchanged, 2 moved within the "
                                    "tolerance (0 better, 2 worse; 1 of them only past the 6th "
                                    "significant digit), 1 beyond it",
                                    figures, figures - 3)),
              std::string::npos)
        << text;
    EXPECT_EQ(lines_with(text, "WORSE"), 1) << text;
    EXPECT_EQ(lines_with(text, "crawl"), 1) << text;
    EXPECT_EQ(lines_with(text, "box_rmse"), 0) << "equal printed values are not listed\n" << text;
    EXPECT_EQ(lines_with(text, "edge_rmse"), 0) << "within the tolerance: not listed\n" << text;
    EXPECT_NE(text.find("FAIL: 1 figure worse"), std::string::npos) << text;

    const std::string all = format_gate(result, tolerance, "base.json", true);
    EXPECT_EQ(lines_with(all, "edge_rmse"), 1) << all;
    EXPECT_EQ(lines_with(all, "box_rmse"), 0) << "still not: old and new print the same\n" << all;
}

TEST(GateReport, AnUnchangedRunListsNothing) {
    const std::vector<ResultRow> rows = {made_up_row("star", "none")};
    const std::string text = format_gate(gate_rows(rows, rows, GateTolerance{}), GateTolerance{},
                                         "base.json");
    EXPECT_NE(text.find("1 row "), std::string::npos) << "one row, singular\n" << text;
    EXPECT_NE(text.find("0 moved within the tolerance, 0 beyond it"), std::string::npos) << text;
    EXPECT_NE(text.find("nothing to list"), std::string::npos) << text;
    EXPECT_NE(text.find("PASS"), std::string::npos) << text;
}

TEST(Gate, RerunPlanGroupsBySizeAndNeedsTheSceneFiles) {
    std::vector<ResultRow> rows = {made_up_row("star", "none"), made_up_row("strips", "agg")};
    rows.push_back(made_up_row("star", "none"));
    rows.back().width = 32;
    ResultRow file_row = made_up_row("mine", "exact");
    file_row.scene_file = "dir/mine.json";
    rows.push_back(file_row);
    ResultRow sweep = made_up_row("star", "ssaa:k=2");
    sweep.sweep_point = true;
    rows.push_back(sweep);
    Scene scene = make_pattern("star", 16, 16);
    const std::vector<CompareOptions> runs =
        rerun_options(rows, {{"dir/mine.json", scene}}, CompareOptions{});
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_EQ(runs[0].width, 16);
    EXPECT_EQ(runs[0].pattern_specs, (std::vector<std::string>{"star", "strips"}));
    EXPECT_EQ(runs[0].method_specs, (std::vector<std::string>{"none", "agg"}));
    EXPECT_TRUE(runs[0].sweep);
    EXPECT_EQ(runs[1].width, 32);
    EXPECT_FALSE(runs[1].sweep);
    EXPECT_TRUE(runs[2].pattern_specs.empty());
    ASSERT_EQ(runs[2].scene_files.size(), 1u);
    EXPECT_EQ(runs[2].method_specs, std::vector<std::string>{"exact"});
    // The file not given, or a file of another size than the baseline saw: InputError.
    EXPECT_THROW(rerun_options(rows, {}, CompareOptions{}), InputError);
    EXPECT_THROW(
        rerun_options(rows, {{"dir/mine.json", make_pattern("star", 8, 8)}}, CompareOptions{}),
        InputError);
}

TEST(Gate, ExternalRowsAreCountedNotReRun) {
    ResultRow external = made_up_row("star", "external:rsvg");
    external.method_id = "external:rsvg";
    const std::vector<ResultRow> baseline = {made_up_row("star", "none"), external};
    EXPECT_EQ(rerun_options(baseline, {}, CompareOptions{}).at(0).method_specs,
              std::vector<std::string>{"none"});
    const GateResult result = gate_rows(baseline, {baseline[0]}, GateTolerance{});
    EXPECT_TRUE(result.passed());
    EXPECT_EQ(result.external_rows, 1);
    EXPECT_EQ(result.rows_checked, 1);
}

TEST(Gate, OldSpecsResolveToTodaysAndGoneOnesAreMissing) {
    // A baseline from before ssaa had `pattern`, and a method that no longer exists.
    std::vector<ResultRow> baseline = {made_up_row("star", "ssaa:k=2,filter=box,sigma=0.5"),
                                       made_up_row("star", "gone:n=3")};
    resolve_specs_again(baseline);
    EXPECT_EQ(baseline[0].method, "ssaa:k=2,filter=box,sigma=0.5,pattern=grid");
    EXPECT_EQ(baseline[1].method, "gone:n=3");
    EXPECT_EQ(baseline[0].pattern, resolve_pattern("star").spec);
    const std::vector<CompareOptions> runs = rerun_options(baseline, {}, CompareOptions{});
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_EQ(runs[0].method_specs, std::vector<std::string>{baseline[0].method});
    ResultRow rerun_row = baseline[0];
    const GateResult result = gate_rows(baseline, {rerun_row}, GateTolerance{});
    EXPECT_FALSE(result.passed());
    EXPECT_EQ(verdicts(result), std::vector<GateVerdict>{GateVerdict::kMissing});
}

CompareOptions small_baseline() {
    CompareOptions options;
    options.pattern_specs = {"star", "room"};
    options.method_specs = {"none", "box-multiscan", "gauss-multiscan"};
    options.width = 32;
    options.height = 24;
    options.runs = 1;
    options.motion_frames = 4;
    options.keep_images = false;
    return options;
}

std::vector<ResultRow> rerun(const std::vector<ResultRow>& baseline) {
    CompareOptions base = small_baseline();
    std::vector<ResultRow> rows;
    for (const CompareOptions& o : rerun_options(baseline, {}, base)) {
        for (ResultRow& r : run_comparison(o).rows) rows.push_back(std::move(r));
    }
    return rows;
}

TEST(Gate, PassesOnAnUnchangedRunAndFailsWhereTheBaselineIsBetterThanReality) {
    const std::vector<ResultRow> baseline = run_comparison(small_baseline()).rows;
    const GateResult same = gate_rows(baseline, rerun(baseline), GateTolerance{});
    EXPECT_TRUE(same.passed());
    EXPECT_TRUE(same.changes.empty()) << "the error figures are deterministic";
    EXPECT_EQ(same.rows_checked, static_cast<long long>(baseline.size()));

    // A baseline whose rmse is half of what the methods really give: the gate must fail on
    // exactly the rows where doubling is beyond the tolerance.
    std::vector<ResultRow> better = baseline;
    long long expected = 0;
    const GateTolerance tolerance;
    for (ResultRow& r : better) {
        r[metric::kBoxRmse] /= 2;
        const double bound =
            r[metric::kBoxRmse] * (1 + kImageErrorTolerance.rel) + kImageErrorTolerance.abs;
        expected += r[metric::kBoxRmse] * 2 > bound;
    }
    ASSERT_GT(expected, 0);
    const GateResult worse = gate_rows(better, rerun(better), tolerance);
    EXPECT_FALSE(worse.passed());
    EXPECT_EQ(worse.failures, expected);
    for (const GateChange& c : worse.changes) {
        if (c.verdict == GateVerdict::kWorse) EXPECT_EQ(c.figure, "box_rmse") << c.method;
    }
}

// ---- The command line ----

using Output = CliOutput;

class CheckCli : public CliRunner {
protected:
    CheckCli() : CliRunner("check") {}
    // A baseline made by compare, with a scene file among the patterns.
    std::string make_baseline() const {
        EXPECT_EQ(run(fmt::format("export --pattern blocks --size 24x20 --out {}",
                                  path("my-blocks.json")))
                      .exit_code,
                  0);
        const Output o = run(fmt::format(
            "compare --patterns star --scenes {} --methods none,box-multiscan --size 32x24 "
            "--runs 1 --no-hardcases --quiet --out {}",
            path("my-blocks.json"), path("base")));
        EXPECT_EQ(o.exit_code, 0) << o.err;
        return path("base/results.json");
    }
};

TEST_F(CheckCli, ExitsZeroOnAnUnchangedRunAndOneOnAWorsenedMethod) {
    const std::string baseline = make_baseline();
    const Output same = run("check --baseline " + baseline);
    EXPECT_EQ(same.exit_code, 0) << same.out << same.err;
    EXPECT_NE(same.out.find("PASS"), std::string::npos) << same.out;

    // Halve box-multiscan's rmse in a copy: the method now looks better than it is.
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(baseline));
    for (auto& row : doc["rows"]) {
        if (row["method_id"] == "box-multiscan")
            row["box_rmse"] = row["box_rmse"].get<double>() / 2;
    }
    std::ofstream(path("better.json")) << doc.dump();
    const Output worse = run("check --baseline " + path("better.json"));
    EXPECT_EQ(worse.exit_code, 1) << worse.out << worse.err;
    for (const char* needle :
         {"star", "my-blocks", "box-multiscan:n=3", "box_rmse", "WORSE", "FAIL"}) {
        EXPECT_NE(worse.out.find(needle), std::string::npos) << needle << "\n" << worse.out;
    }
    EXPECT_EQ(worse.out.find("none  "), std::string::npos) << "only the worsened rows\n"
                                                           << worse.out;
}

TEST_F(CheckCli, AnOlderBaselineWithoutANewColumnStillChecks) {
    const std::string baseline = make_baseline();
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(baseline));
    for (auto& row : doc["rows"]) row.erase("seams_max");
    std::ofstream(path("old.json")) << doc.dump();
    const Output o = run("check --baseline " + path("old.json"));
    EXPECT_EQ(o.exit_code, 0) << o.out << o.err;
    EXPECT_NE(o.out.find("seams_max in 2 rows"), std::string::npos) << o.out;
}

TEST_F(CheckCli, BadInputIsOneLineAndExitTwo) {
    for (const std::string& args :
         {"check --baseline " + path("nothing.json"),
          "check --baseline " + path("nothing.json") + " --tolerance rel=-1",
          "check --baseline " + path("nothing.json") + " --tolerance speed=2",
          "check --baseline " + path("nothing.json") + " --time-tolerance fast"}) {
        const Output o = run(args);
        EXPECT_EQ(o.exit_code, 2) << args << ": " << o.err;
        EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
    }
}

}  // namespace
}  // namespace aabench
