// compare's timing loop (harness/measure/timing.h): how many runs a time budget leaves. The
// runs' speed is not measured here, only the count of calls.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "harness/measure/timing.h"

namespace aabench {
namespace {

// A body that takes at least a microsecond, so that any positive budget below that is spent
// by the first run.
struct CountedBody {
    int calls = 0;
    void operator()() {
        ++calls;
        std::this_thread::sleep_for(std::chrono::microseconds(1));
    }
};

TEST(TimeBudget, NoBudgetRunsEveryRunAfterTheWarmUp) {
    CountedBody body;
    const TimingStats stats = time_runs(7, [&] { body(); });
    EXPECT_EQ(body.calls, 8);
    EXPECT_EQ(stats.runs, 7);
    EXPECT_LE(stats.min_ns, stats.median_ns);
    EXPECT_LE(stats.median_ns, stats.max_ns);
}

TEST(TimeBudget, ASpentBudgetStopsAfterTheFewestRuns) {
    CountedBody body;
    const TimingStats stats = time_runs(
        7, [&] { body(); }, /*budget_ns=*/1.0);
    EXPECT_EQ(body.calls, 1 + kBudgetMinRuns);
    EXPECT_EQ(stats.runs, kBudgetMinRuns);
}

TEST(TimeBudget, FewerRunsAskedThanTheFewestAreAllRun) {
    CountedBody body;
    const TimingStats stats = time_runs(
        2, [&] { body(); }, /*budget_ns=*/1.0);
    EXPECT_EQ(body.calls, 3);
    EXPECT_EQ(stats.runs, 2);
}

TEST(TimeBudget, AnUnspentBudgetRunsThemAll) {
    CountedBody body;
    const TimingStats stats = time_runs(
        5, [&] { body(); }, /*budget_ns=*/3.6e12);  // an hour
    EXPECT_EQ(body.calls, 6);
    EXPECT_EQ(stats.runs, 5);
}

}  // namespace
}  // namespace aabench
