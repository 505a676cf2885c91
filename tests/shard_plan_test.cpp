// Shards balanced by cost (harness/measure/shard_plan.h, compare --shard K/N): the split is
// deterministic, balances estimated time rather than task count, and the shards of a run
// merged back equal the unsharded run bit for bit on every error column.
#include "tests/small_sweep.h"
#include "harness/measure/shard_plan.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "harness/measure/compare.h"
#include "harness/report/context.h"
#include "harness/report/report.h"
#include "harness/report/shards.h"

namespace aabench {
namespace {

// Sums of the same doubles in another order differ by rounding only: a few ulps of the total.
constexpr double kSumRoundingRel = 1e-12;

double max_of(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }
double mean_of(const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

TEST(ShardPlan, BalancesCostNotCount) {
    // One task of 100 ms and 99 of 1 ms: by count each shard of 2 would get 50 tasks (149 ms
    // against 50); by cost the big task is alone.
    std::vector<double> ms(100, 1.0);
    ms[0] = 100.0;
    const ShardSplit split = split_by_cost(ms, 2);
    EXPECT_EQ(split.shard_tasks[split.shard_of_task[0]], 1);
    EXPECT_DOUBLE_EQ(max_of(split.shard_ms), 100.0);
    EXPECT_DOUBLE_EQ(split.shard_ms[0] + split.shard_ms[1], 199.0);
}

TEST(ShardPlan, LargestShardIsWithinOneTaskOfTheMean) {
    // Greedy list scheduling: the last task put on the largest shard went to the least loaded
    // shard, whose load was at most the mean; so largest <= mean + the largest task.
    std::mt19937 rng(7);
    std::lognormal_distribution<double> cost(0.0, 1.5);
    for (int n : {2, 3, 4, 7, 16}) {
        std::vector<double> ms(300);
        for (double& m : ms) m = cost(rng);
        const ShardSplit split = split_by_cost(ms, n);
        EXPECT_LE(max_of(split.shard_ms), mean_of(split.shard_ms) + max_of(ms)) << n;
        long long tasks = 0;
        for (long long t : split.shard_tasks) tasks += t;
        EXPECT_EQ(tasks, 300);
    }
}

TEST(ShardPlan, DeterministicAndBlindToTheLastBitsOfAnEstimate) {
    const std::vector<double> ms = {3.0, 1.0, 2.0, 2.0, 1.0, 5.0, 0.0, 4.0};
    const ShardSplit a = split_by_cost(ms, 3), b = split_by_cost(ms, 3);
    EXPECT_EQ(a.shard_of_task, b.shard_of_task);
    EXPECT_EQ(a.split_id, b.split_id);
    // Estimates a machine computes a few ulps off: rounded to microseconds, the same split.
    std::vector<double> off = ms;
    for (double& m : off) m = std::nextafter(m, 1e9);
    EXPECT_EQ(split_by_cost(off, 3).shard_of_task, a.shard_of_task);
    EXPECT_EQ(split_by_cost(off, 3).split_id, a.split_id);
    // Another N is another split, and says so.
    EXPECT_NE(split_by_cost(ms, 4).split_id, a.split_id);
}

TEST(ShardPlan, EqualCostsGoRoundTheShards) {
    const ShardSplit split = split_by_cost(std::vector<double>(6, 1.0), 3);
    EXPECT_EQ(split.shard_of_task, (std::vector<int>{0, 1, 2, 0, 1, 2}));
}

using test::small_sweep;

TEST(ShardPlan, PlanAndRunAgree) {
    CompareOptions options = small_sweep();
    options.shard_count = 4;
    const ShardPlan plan = plan_shards(options);
    ASSERT_EQ(plan.tasks.size(), plan.split.shard_of_task.size());
    double total_ms = 0.0;
    for (const PlannedTask& t : plan.tasks) {
        EXPECT_GT(t.estimate_ms, 0.0) << t.method;
        total_ms += t.estimate_ms;
    }
    const double shards_ms =
        std::accumulate(plan.split.shard_ms.begin(), plan.split.shard_ms.end(), 0.0);
    EXPECT_NEAR(shards_ms, total_ms, kSumRoundingRel * total_ms);
    // Shard 3 of the run does exactly the plan's tasks of shard 3.
    options.shard_index = 2;
    const CompareResult result = run_comparison(options);
    std::vector<long long> planned, ran;
    for (const PlannedTask& t : plan.tasks) {
        if (t.shard == 2) planned.push_back(t.task);
    }
    for (const ResultRow& r : result.rows) ran.push_back(r.task);
    EXPECT_EQ(ran, planned);
    EXPECT_EQ(result.plan.split.split_id, plan.split.split_id);
}

TEST(ShardPlan, MergedShardsEqualTheUnshardedRunBitForBit) {
    const CompareOptions options = small_sweep();
    const RunContext context;
    // Both through results.json, as `aabench merge --same-as` reads them.
    const std::vector<ResultRow> whole =
        rows_from_compare_json(compare_json(run_comparison(options).rows, context), "whole");
    for (int n : {2, 4}) {
        std::vector<std::vector<ResultRow>> shards;
        for (int k = 0; k < n; ++k) {
            CompareOptions shard = options;
            shard.shard_index = k;
            shard.shard_count = n;
            shards.push_back(rows_from_compare_json(
                compare_json(run_comparison(shard).rows, context), fmt::format("shard {}", k)));
        }
        std::vector<ResultRow> merged = merge_shard_rows(shards);
        EXPECT_EQ(error_column_difference(merged, whole), "") << n << " shards";
        // And the check is one that can fail: one figure of one row changed.
        merged[3][metric::kOwnRmse] = std::nextafter(merged[3][metric::kOwnRmse], 1.0);
        EXPECT_NE(error_column_difference(merged, whole).find("own_rmse"), std::string::npos);
    }
}

}  // namespace
}  // namespace aabench
