#include "harness/measure/timing.h"

#include <algorithm>
#include <chrono>
#include <vector>

namespace aabench {

TimingStats time_render(const Method& method, const Scene& scene, Image& out, int runs,
                        int threads) {
    render_in_bands(method, scene, out, threads);  // warm-up: caches, page faults, tables
    std::vector<double> ns;
    ns.reserve(runs);
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        render_in_bands(method, scene, out, threads);
        const auto stop = std::chrono::steady_clock::now();
        ns.push_back(std::chrono::duration<double, std::nano>(stop - start).count());
    }
    std::sort(ns.begin(), ns.end());
    TimingStats stats;
    stats.runs = runs;
    stats.threads = threads;
    if (ns.empty()) return stats;
    stats.min_ns = ns.front();
    stats.max_ns = ns.back();
    const std::size_t mid = ns.size() / 2;
    stats.median_ns = ns.size() % 2 ? ns[mid] : 0.5 * (ns[mid - 1] + ns[mid]);
    return stats;
}

}  // namespace aabench
