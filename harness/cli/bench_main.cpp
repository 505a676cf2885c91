// Google Benchmark: every registered method x every built-in pattern x {256^2, 1024^2}, with
// Mpixel/s and Medges/s counters. Scenes are generated and output buffers allocated outside
// the timed loop. JSON output: --benchmark_format=json or --benchmark_out=FILE.
// Extra flag (ours, read before Google Benchmark's): --aabench_sizes=256,1024.
#include <benchmark/benchmark.h>

#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "harness/world/pipeline.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace {

using namespace aabench;

void run_benchmark(benchmark::State& state, const Scene* scene, const Method* method) {
    Image out(scene->width, scene->height);
    for (auto _ : state) {
        method->render(*scene, out);
        benchmark::DoNotOptimize(out.data.data());
        benchmark::ClobberMemory();
    }
    const double pixels = static_cast<double>(scene->width) * scene->height;
    state.counters["Mpixel/s"] =
        benchmark::Counter(pixels / 1e6, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["Medges/s"] = benchmark::Counter(static_cast<double>(scene->edge_count()) / 1e6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
    state.counters["edges"] = static_cast<double>(scene->edge_count());
}

std::vector<int> parse_sizes(int& argc, char** argv) {
    std::vector<int> sizes = {256, 1024};
    const char* prefix = "--aabench_sizes=";
    for (int k = 1; k < argc; ++k) {
        if (std::strncmp(argv[k], prefix, std::strlen(prefix)) != 0) continue;
        sizes.clear();
        std::string list = argv[k] + std::strlen(prefix);
        std::size_t start = 0;
        while (start < list.size()) {
            const auto comma = list.find(',', start);
            sizes.push_back(std::stoi(list.substr(start, comma - start)));
            if (comma == std::string::npos) break;
            start = comma + 1;
        }
        for (int m = k; m + 1 < argc; ++m) argv[m] = argv[m + 1];
        --argc;
        break;
    }
    return sizes;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<int> sizes = parse_sizes(argc, argv);
    // Owned for the whole run: benchmarks hold raw pointers to them.
    std::vector<std::unique_ptr<Scene>> scenes;
    std::vector<MethodInstance> methods;
    for (const MethodInfo& info : method_registry()) methods.push_back(make_method(info.id));
    for (const PatternInfo& pattern : pattern_registry()) {
        for (int size : sizes) {
            // 3-D patterns: the visible pieces every method draws, or the ScreenScene for the
            // methods with their own visibility (the world stages are not part of a method's
            // time; compare reports them apart).
            const Scene given = make_pattern(pattern.id, size, size);
            WorldRender world = render_world(given, make_plan(given));
            scenes.push_back(std::make_unique<Scene>(std::move(world.pieces)));
            const Scene* pieces = scenes.back().get();
            const Scene* screen = pieces;
            if (given.world) {
                scenes.push_back(std::make_unique<Scene>(std::move(world.screen)));
                screen = scenes.back().get();
            }
            for (const MethodInstance& method : methods) {
                const Scene* drawn = method.method->own_visibility() ? screen : pieces;
                benchmark::RegisterBenchmark(
                    fmt::format("{}/{}/{}", method.spec, pattern.id, size).c_str(), run_benchmark,
                    drawn, method.method.get())
                    ->Unit(benchmark::kMillisecond)
                    ->UseRealTime();
            }
        }
    }
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
