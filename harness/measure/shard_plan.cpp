// Shards balanced by cost (harness/measure/shard_plan.h).
#include "harness/measure/shard_plan.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace aabench {

ShardSplit split_by_cost(const std::vector<double>& task_ms, int shard_count) {
    if (shard_count < 1) throw std::invalid_argument("split_by_cost: shard_count < 1");
    const std::size_t n = task_ms.size();
    // Whole microseconds, at least 1: integer sums make the greedy choices exact, and a task
    // estimated at zero still counts (it still costs a row).
    std::vector<long long> cost_us(n);
    for (std::size_t t = 0; t < n; ++t) {
        const double ms = std::isfinite(task_ms[t]) ? std::max(0.0, task_ms[t]) : 0.0;
        cost_us[t] = std::max(1LL, std::llround(ms * 1000.0));
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return cost_us[a] > cost_us[b]; });
    ShardSplit split;
    split.shard_count = shard_count;
    split.shard_of_task.assign(n, 0);
    split.shard_tasks.assign(shard_count, 0);
    split.shard_ms.assign(shard_count, 0.0);
    std::vector<long long> load_us(shard_count, 0);
    for (std::size_t t : order) {
        // The least-loaded shard, the lower one on a tie (min_element keeps the first).
        const int s =
            static_cast<int>(std::min_element(load_us.begin(), load_us.end()) - load_us.begin());
        load_us[s] += cost_us[t];
        split.shard_of_task[t] = s;
        ++split.shard_tasks[s];
    }
    for (std::size_t t = 0; t < n; ++t) split.shard_ms[split.shard_of_task[t]] += task_ms[t];
    std::uint64_t h = 14695981039346656037ULL;  // FNV-1a, 64 bits
    auto mix = [&h](std::uint64_t v) {
        for (int b = 0; b < 8; ++b) {
            h ^= (v >> (8 * b)) & 0xff;
            h *= 1099511628211ULL;
        }
    };
    mix(static_cast<std::uint64_t>(shard_count));
    for (int s : split.shard_of_task) mix(static_cast<std::uint64_t>(s));
    split.split_id = h;
    return split;
}

double largest_over_mean(const std::vector<double>& shard_values) {
    if (shard_values.empty()) return 1.0;
    const double sum = std::accumulate(shard_values.begin(), shard_values.end(), 0.0);
    const double largest = *std::max_element(shard_values.begin(), shard_values.end());
    return sum > 0.0 ? largest * static_cast<double>(shard_values.size()) / sum : 1.0;
}

}  // namespace aabench
