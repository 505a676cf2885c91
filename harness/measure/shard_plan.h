// Shards balanced by cost: the tasks of a comparison run split into N shards whose estimated
// times are about equal, so that N machines given one shard each finish at about the same time.
//
// The split is a deterministic function of the tasks' estimates alone (MethodTraits::time_ms,
// methods/cost_model.h: committed coefficients, never a measurement of the running machine),
// so every shard, on any machine, computes the same split and runs only its own part. The
// estimates are rounded to whole microseconds before they are compared, so that the split
// does not hang on the last bit of a double.
//
// Greedy longest-processing-time first (Graham 1969): tasks by decreasing estimate (ties: the
// lower task index first), each to the shard with the least estimated time so far (ties: the
// lower shard). Its largest shard is within 4/3 of the best possible split; with many small
// tasks, as a sweep has, it is within one task of the mean.
#pragma once

#include <cstdint>
#include <vector>

namespace aabench {

struct ShardSplit {
    int shard_count = 1;
    std::vector<int> shard_of_task;      // by task index: 0 .. shard_count - 1
    std::vector<long long> shard_tasks;  // per shard: how many tasks
    std::vector<double> shard_ms;        // per shard: the sum of its tasks' estimates
    // One number for the whole split (FNV-1a over shard_of_task): shards of one run carry the
    // same one, and merge refuses shards whose splits differ (another build, other costs).
    std::uint64_t split_id = 0;
};

// `task_ms`: each task's estimate in ms (finite, >= 0), in the unsharded task order.
ShardSplit split_by_cost(const std::vector<double>& task_ms, int shard_count);

// The largest shard's estimate over the mean shard's (1 for a perfect split).
double largest_over_mean(const std::vector<double>& shard_values);

}  // namespace aabench
