// The comparison run's task list, sweeps, shards and their merge, the result files' round
// trip and the benchmark-timing import: all through library calls.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>

#include "tests/small_sweep.h"
#include "harness/world/plan.h"

#include "harness/measure/compare.h"
#include "harness/report/context.h"
#include "harness/report/report.h"
#include "methods/method.h"

namespace aabench {
namespace {

using test::small_sweep;

// Everything but the timings, which differ from run to run by nature.
void expect_same_scores(const ResultRow& a, const ResultRow& b) {
    EXPECT_EQ(a.task, b.task);
    EXPECT_EQ(a.pattern, b.pattern);
    EXPECT_EQ(a.method, b.method);
    EXPECT_EQ(a.sweep_point, b.sweep_point);
    EXPECT_EQ(a.cost_value, b.cost_value);
    EXPECT_EQ(a[metric::kBoxRmse], b[metric::kBoxRmse]) << a.method;
    EXPECT_EQ(a[metric::kBoxMaxAbs], b[metric::kBoxMaxAbs]);
    EXPECT_EQ(a[metric::kBoxBias], b[metric::kBoxBias]);
    EXPECT_EQ(a[metric::kDropout], b[metric::kDropout]);
    EXPECT_EQ(a[metric::kOwnRmse], b[metric::kOwnRmse]);
    EXPECT_EQ(a.reference_filter, b.reference_filter);
}

TEST(Compare, SweepRunsEachCostValueOnce) {
    const CompareResult result = run_comparison(small_sweep());
    int box_points = 0, ssaa_points = 0, none_points = 0;
    for (const ResultRow& r : result.rows) {
        if (r.pattern_id != "star") continue;
        box_points += r.method_id == "box-multiscan";
        ssaa_points += r.method_id == "ssaa";
        none_points += r.method_id == "none";
    }
    // n in {1, 2, 3, 6, 12, 24}: the default n = 3 once, not twice.
    EXPECT_EQ(box_points, 6);
    // k in {1, 2, 3, 4, 5, 8, 16}, the asked-for k = 2 among them.
    EXPECT_EQ(ssaa_points, 7);
    EXPECT_EQ(none_points, 1);  // no cost parameter: a single point
    EXPECT_EQ(result.task_count, static_cast<long long>(result.rows.size()));
}

TEST(Compare, FourShardsMergedGiveTheUnshardedRows) {
    const CompareOptions options = small_sweep();
    const CompareResult whole = run_comparison(options);
    std::vector<std::vector<ResultRow>> shards;
    const RunContext context;
    for (int k = 0; k < 4; ++k) {
        CompareOptions shard = options;
        shard.shard_index = k;
        shard.shard_count = 4;
        // Through the results file, as `aabench merge` reads it.
        const std::string json = compare_json(run_comparison(shard).rows, context);
        shards.push_back(rows_from_compare_json(json, fmt::format("shard {}", k)));
    }
    const std::vector<ResultRow> merged = merge_shard_rows(shards);
    ASSERT_EQ(merged.size(), whole.rows.size());
    for (std::size_t k = 0; k < merged.size(); ++k) expect_same_scores(merged[k], whole.rows[k]);
    // The same shard twice is an error, not a silent duplicate.
    shards.push_back(shards.front());
    EXPECT_THROW(merge_shard_rows(shards), InputError);
}

TEST(Compare, ParallelScoresEqualSerialScores) {
    CompareOptions options = small_sweep();
    const CompareResult serial = run_comparison(options);
    options.jobs = 2;
    const CompareResult parallel = run_comparison(options);
    ASSERT_EQ(serial.rows.size(), parallel.rows.size());
    for (std::size_t k = 0; k < serial.rows.size(); ++k) {
        expect_same_scores(serial.rows[k], parallel.rows[k]);
    }
}

TEST(Compare, FiguresHoldTheDefaultRowsImages) {
    const CompareResult result = run_comparison(small_sweep());
    ASSERT_EQ(result.figures.size(), 2u);
    EXPECT_EQ(result.figures[0].methods.size(), 3u);  // sweep points are not kept
    EXPECT_EQ(result.figures[0].images[0].width, 40);
}

TEST(Compare, BenchmarkTimingsReplaceOwnTimings) {
    CompareOptions options;
    options.method_specs = {"none"};
    options.pattern_specs = {"star"};
    options.width = options.height = 32;
    options.runs = 1;
    std::vector<ResultRow> rows = run_comparison(options).rows;
    const std::string json = R"({"benchmarks": [
        {"name": "none/star/32/real_time", "run_type": "iteration", "real_time": 2.5,
         "time_unit": "ms"},
        {"name": "none/strips/32/real_time", "run_type": "iteration", "real_time": 1.0,
         "time_unit": "ms"}]})";
    EXPECT_EQ(apply_benchmark_timings(rows, json, "bench.json"), 1);
    EXPECT_EQ(rows[0][metric::kTimeMedianNs], 2.5e6);
    EXPECT_EQ(rows[0].time_source, "benchmark");
    EXPECT_THROW(apply_benchmark_timings(rows, "{", "bench.json"), InputError);
}

// Line scores (Saito & Takahashi 1990) only on a scene that asks for edges: every method that draws
// a depth image gets them, one that cannot (cairo) gets none, and every row of the pattern carries
// the edge stage on the exact depth; a pattern without edges has none, and its JSON rows do not
// even have the columns. The JSON round trip keeps them.
TEST(Compare, LineScoresOnlyForScenesWithEdges) {
    // A drawing that finds fewer than half of the torus's lines, or whose detections are mostly
    // off them, is broken: at 64^2 exact and none score 0.81-0.94 (one run).
    constexpr double kWorkingScore = 0.5;
    CompareOptions options;
    options.method_specs = {"exact", "none", "cairo"};
    options.pattern_specs = {"torus", "star"};
    options.width = options.height = 64;
    options.runs = 1;
    options.symptoms = false;
    const CompareResult result = run_comparison(options);
    ASSERT_EQ(result.rows.size(), 6u);
    for (const ResultRow& r : result.rows) {
        if (r.pattern_id == "star") {
            EXPECT_TRUE(std::isnan(r[metric::kLineRmse]) &&
                        std::isnan(r[metric::kExactDepthLineRmse]));
            EXPECT_TRUE(std::isnan(r[metric::kExactDepthLineContourRecall]) &&
                        std::isnan(r[metric::kLineCreasePrecision]));
            continue;
        }
        EXPECT_TRUE(r[metric::kExactDepthLineRecall] > kWorkingScore)
            << r[metric::kExactDepthLineRecall];
        EXPECT_TRUE(r[metric::kExactDepthLinePrecision] > kWorkingScore)
            << r[metric::kExactDepthLinePrecision];
        // The torus has both kinds: each scored apart, and a working drawing finds each.
        for (const double v :
             {r[metric::kExactDepthLineContourPrecision], r[metric::kExactDepthLineContourRecall],
              r[metric::kExactDepthLineCreasePrecision], r[metric::kExactDepthLineCreaseRecall]}) {
            EXPECT_TRUE(v > kWorkingScore && v <= 1.0) << v;
        }
        if (r.method_id == "cairo") {
            EXPECT_TRUE(std::isnan(r[metric::kLineRmse]) && std::isnan(r[metric::kLineRecall]));
        } else {
            EXPECT_TRUE(r[metric::kLineRmse] >= 0.0 && r[metric::kLineRmse] < 1.0) << r.method;
            EXPECT_TRUE(r[metric::kLineRecall] > kWorkingScore) << r.method;
        }
        if (r.method_id == "exact") {
            // exact draws the depth image with the engine of the exact reference.
            EXPECT_EQ(r[metric::kLineRmse], r[metric::kExactDepthLineRmse]);
            EXPECT_EQ(r[metric::kLineRecall], r[metric::kExactDepthLineRecall]);
            EXPECT_EQ(r[metric::kLineContourRecall], r[metric::kExactDepthLineContourRecall]);
            EXPECT_EQ(r[metric::kLineCreasePrecision], r[metric::kExactDepthLineCreasePrecision]);
        }
    }
    ASSERT_TRUE(result.figures[0].edges.has_value());
    EXPECT_FALSE(result.figures[1].edges.has_value());
    const std::string json = compare_json(result.rows, RunContext{});
    const nlohmann::json doc = nlohmann::json::parse(json);
    EXPECT_TRUE(doc["rows"][0].contains("line_recall"));
    EXPECT_FALSE(doc["rows"][3].contains("line_recall"));
    const std::vector<ResultRow> back = rows_from_compare_json(json, "results.json");
    EXPECT_EQ(back[0][metric::kLineRecall], result.rows[0][metric::kLineRecall]);
    EXPECT_EQ(back[0][metric::kLineCreaseRecall], result.rows[0][metric::kLineCreaseRecall]);
    EXPECT_TRUE(std::isnan(back[3][metric::kLineRecall]));
}

// The split and the total are added in double from ns and ms: far below a microsecond.
constexpr double kSplitRoundingMs = 1e-9;

// Honest time on a world: a method that draws the exact visible pieces is charged the
// visibility stage it relies on; one that removes hidden surfaces itself is not. The row keeps
// the split, and its time is the total.
TEST(Compare, TimeOnAWorldIncludesTheStagesTheMethodReliesOn) {
    CompareOptions options;
    options.method_specs = {"exact", "none"};
    options.pattern_specs = {"room"};
    options.width = options.height = 64;
    options.runs = 1;
    options.symptoms = false;
    options.keep_images = false;
    const CompareResult result = run_comparison(options);
    ASSERT_EQ(result.rows.size(), 2u);
    const MetricId vis = stage_ms_metric(static_cast<int>(Stage::kVisibility));
    for (const ResultRow& row : result.rows) {
        ASSERT_TRUE(std::isfinite(row[vis])) << row.method;
        EXPECT_GT(row[vis], 0.0);
        const double total_ms = row[metric::kTimeMedianNs] * 1e-6;
        // The total is the sum of its parts, to the rounding of ns and ms.
        EXPECT_NEAR(total_ms, row[metric::kTimeMethodMs] + row[metric::kTimeStagesMs],
                    kSplitRoundingMs)
            << row.method;
        if (row.method_id == "exact") {
            EXPECT_GE(row[metric::kTimeStagesMs], row[vis]);
            EXPECT_GE(total_ms, row[vis]);
        } else {
            // Every world stage but visibility (room asks for no depth or edges).
            EXPECT_NEAR(row[metric::kTimeStagesMs], row[metric::kWorldMs] - row[vis],
                        kSplitRoundingMs);
        }
    }
}

TEST(Compare, BadShardIsAnError) {
    CompareOptions options = small_sweep();
    options.shard_index = 4;
    options.shard_count = 4;
    EXPECT_THROW(run_comparison(options), InputError);
}

// --time-budget is a duration in ms: a negative one or NaN is refused in one line naming
// the option and its range; 0 (every run) is accepted.
TEST(Compare, TimeBudgetOutOfRangeIsAnError) {
    for (const double bad : {-1.0, 2e6, std::nan("")}) {
        CompareOptions options = small_sweep();
        options.time_budget_ms = bad;
        try {
            run_comparison(options);
            ADD_FAILURE() << bad << " accepted";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("--time-budget"), std::string::npos) << message;
            EXPECT_NE(message.find("0..1e6 ms"), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
    CompareOptions options = small_sweep();
    options.time_budget_ms = 0.0;
    options.runs = 2;
    const CompareResult result = run_comparison(options);
    for (const ResultRow& row : result.rows) {
        if (row.not_applicable.empty()) EXPECT_EQ(row.time_runs, 2) << row.method;
    }
}

}  // namespace
}  // namespace aabench
