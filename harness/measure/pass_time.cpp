#include "harness/measure/pass_time.h"

#include <algorithm>
#include <chrono>
#include <vector>

namespace aabench {

MetricId time_pass_metric() {
    static const MetricId id = *metric_registry().find(kTimePassKey);
    return id;
}

TimingStats time_pass(const PostProcessMethod& method, const Image& base, Image& out, int runs) {
    method.pass(base, out);  // warm-up: the pass's per-thread scratch grows here
    std::vector<double> ns;
    ns.reserve(runs);
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        method.pass(base, out);
        const auto stop = std::chrono::steady_clock::now();
        ns.push_back(std::chrono::duration<double, std::nano>(stop - start).count());
    }
    std::sort(ns.begin(), ns.end());
    TimingStats stats;
    stats.runs = runs;
    if (ns.empty()) return stats;
    stats.min_ns = ns.front();
    stats.max_ns = ns.back();
    const std::size_t mid = ns.size() / 2;
    stats.median_ns = ns.size() % 2 ? ns[mid] : 0.5 * (ns[mid - 1] + ns[mid]);
    return stats;
}

}  // namespace aabench
