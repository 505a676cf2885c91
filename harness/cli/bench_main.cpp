// Google Benchmark: every registered method x every built-in pattern x {256^2, 1024^2}, with
// Mpixel/s and Medges/s counters. Scenes are generated and output buffers allocated outside
// the timed loop. JSON output: --benchmark_format=json or --benchmark_out=FILE.
// Extra flag (ours, read before Google Benchmark's): --aabench_sizes=256,1024.
//
// Circles (issue 12): "circle/<method>/r=<radius>" draws kCirclesPerScene rings of one radius
// about one pixel centre on a (2r + 3)^2 canvas, for aa-circle with its table (radius_max =
// 4096, so every radius here is in the table) and on the fly (radius_max = 0), wu-circle and
// midpoint-circle; counters circles/s, ns/circle and the table's bytes (one per entry at
// alpha_max = 255). "circle/fill/r=<radius>" renders the same canvas with no circle: the
// background fill that every render pays and that is not the circle's cost. "circle/exact-
// polygon/r=<radius>" is `exact` on one ring given as its polygonisation (the curve removed,
// so the polygon engine runs), per render of the whole canvas.
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
#include "patterns/scene/curves.h"

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

constexpr int kCirclesPerScene = 64;
constexpr int kTableRadiusMax = 4096;

void run_circles(benchmark::State& state, const Scene* scene, const Method* method, int circles,
                 double table_bytes) {
    Image out(scene->width, scene->height);
    for (auto _ : state) {
        method->render(*scene, out);
        benchmark::DoNotOptimize(out.data.data());
        benchmark::ClobberMemory();
    }
    state.counters["circles/s"] =
        benchmark::Counter(circles, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["ns/circle"] = benchmark::Counter(
        circles * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["table_bytes"] = table_bytes;
}

// The circle benchmarks (see the top of the file). `methods` and `scenes` own what the
// benchmarks point to.
void register_circle_benchmarks(std::vector<std::unique_ptr<Scene>>& scenes,
                                std::vector<MethodInstance>& methods) {
    const std::vector<std::pair<std::string, std::string>> variants = {
        {"aa-circle-table", fmt::format("aa-circle:radius_max={}", kTableRadiusMax)},
        {"aa-circle-on-the-fly", "aa-circle:radius_max=0"},
        {"wu-circle", "wu-circle"},
        {"midpoint-circle", "midpoint-circle"},
    };
    const double table_bytes = static_cast<double>(aa_circle_table_entries(kTableRadiusMax));
    for (const auto& [name, spec] : variants) methods.push_back(make_method(spec));
    methods.push_back(make_method("exact"));
    for (int r : {1, 4, 16, 64, 256, 1024, 2048}) {
        const int size = 2 * r + 3;
        const Point centre{r + 1.5, r + 1.5};
        Scene base;
        base.width = base.height = size;
        scenes.push_back(std::make_unique<Scene>(base));  // the fill alone
        benchmark::RegisterBenchmark(fmt::format("circle/fill/r={}", r).c_str(), run_circles,
                                     scenes.back().get(), methods[methods.size() - 5].method.get(),
                                     0, 0.0)
            ->UseRealTime();
        Scene many = base;
        for (int k = 0; k < kCirclesPerScene; ++k) {
            many.shapes.push_back(ring_shape(centre, r - 0.5, r + 0.5, 1.0));
        }
        scenes.push_back(std::make_unique<Scene>(std::move(many)));
        for (std::size_t v = 0; v < variants.size(); ++v) {
            benchmark::RegisterBenchmark(
                fmt::format("circle/{}/r={}", variants[v].first, r).c_str(), run_circles,
                scenes.back().get(), methods[methods.size() - 5 + v].method.get(),
                kCirclesPerScene, v == 0 ? table_bytes : 0.0)
                ->UseRealTime();
        }
        if (r > 1024) continue;  // the polygon engine on a 4-Mpixel canvas: enough at 1024
        Scene polygon = base;
        polygon.shapes.push_back(ring_shape(centre, r - 0.5, r + 0.5, 1.0));
        polygon.shapes.back().circle.reset();  // only the polygonisation: the polygon engine
        scenes.push_back(std::make_unique<Scene>(std::move(polygon)));
        benchmark::RegisterBenchmark(fmt::format("circle/exact-polygon/r={}", r).c_str(),
                                     run_circles, scenes.back().get(),
                                     methods.back().method.get(), 1, 0.0)
            ->UseRealTime();
    }
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
            // 3-D patterns: the visible pieces every method draws (the world stages are not
            // part of a method's time; compare reports them apart).
            scenes.push_back(
                std::make_unique<Scene>(drawable_scene(make_pattern(pattern.id, size, size))));
            for (const MethodInstance& method : methods) {
                // A method that cannot draw the scene (aa-circle on polygons) is not timed on it.
                if (!method.method->not_applicable(*scenes.back()).empty()) continue;
                benchmark::RegisterBenchmark(
                    fmt::format("{}/{}/{}", method.spec, pattern.id, size).c_str(), run_benchmark,
                    scenes.back().get(), method.method.get())
                    ->Unit(benchmark::kMillisecond)
                    ->UseRealTime();
            }
        }
    }
    std::vector<MethodInstance> circle_methods;
    circle_methods.reserve(8);  // the benchmarks keep pointers into it
    register_circle_benchmarks(scenes, circle_methods);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
