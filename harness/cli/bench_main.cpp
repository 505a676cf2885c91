// Google Benchmark: every registered method x every built-in pattern x {256^2, 1024^2}, with
// pixel_rate and edge_rate counters (per second; printed as "pixel_rate=223.3M/s"). Scenes are generated and output buffers allocated outside
// the timed loop. JSON output: --benchmark_format=json or --benchmark_out=FILE.
//
// The dense scenes (harness/measure/dense_scenes.h: dense-rings, dense-zoneplate, soup,
// glyphs) join the grid at the same sizes, as "<method>/<scene>/<size>": what users draw
// besides the built-in patterns' defaults.
//
// Also registered (filter them like any other):
//   threads/<method>/<rings|star>/1024/N   exact, box-multiscan, gauss-multiscan, ssaa and
//                                   none split in N bands on N threads (render_in_bands),
//                                   N = 1, 2, 4, 8; the speed-up is the one-band time over the
//                                   N-band time (past the cores: the split's overhead).
// Extra flags (ours, read before Google Benchmark's):
//   --aabench_sizes=256,1024        sizes of the method x pattern grid
//   --aabench_pattern=ID            (repeatable) a built-in pattern the default run leaves out
//                                   (text-page, the colour patterns, the mesh models) timed
//                                   in the grid besides the default ones.
//   --aabench_method=SPEC           (repeatable) a method spec timed in the grid besides the
//                                   registry's defaults, e.g. ssaa:k=5 or ssaa:pattern=halton,
//                                   so that its ratios come from the same interleaved run.
//   --aabench_cost_model            instead of the grid: every method against pixels (star,
//                                   128^2 .. 4096^2, its edges 180 .. 576) and against edges (rings
//                                   at 1024^2, period 64 .. 2.6 px), then a table of the
//                                   fitted log-log slopes (time ~ pixels^a, time ~ edges^b);
//                                   and every method on the dense scenes at 1024^2
//                                   ("cost/dense-<scene>/<method>/<edges>", one point each:
//                                   the estimate's check on what users draw).
//   --aabench_edge_cost             (with or without the cost model) the edge stage of
//                                   Saito & Takahashi 1990 against pixels (torus 256^2 .. 2048^2) and against
//                                   faces (torus at 512^2, 10^2 .. 10^5 facets), and the
//                                   depth image's render time against faces, with slopes.
//
// Circles: "circle/<method>/r=<radius>" draws kCirclesPerScene rings of one radius
// about one pixel centre on a (2r + 3)^2 canvas, for aa-circle with its table (radius_max =
// 4096, so every radius here is in the table) and on the fly (radius_max = 0), wu-circle and
// midpoint-circle; counters circle_rate, time_per_circle and the table's bytes (one per entry at
// alpha_max = 255). "circle/fill/r=<radius>" renders the same canvas with no circle: the
// background fill that every render pays and that is not the circle's cost. "circle/exact-
// polygon/r=<radius>" is `exact` on one ring given as its polygonisation (the curve removed,
// so the polygon engine runs), per render of the whole canvas.
//   --aabench_scaling               instead of the grid: the cost parameters on star and rings
//                                   at 1024^2 ("scaling/<spec>/<pattern>/1024"):
//                                   box-multiscan n = 1..12, gauss-multiscan n = 1..6, ssaa
//                                   k = 1..6, and none; multi-scanning should grow with n,
//                                   supersampling with k^2.
//   --aabench_cost_svg=PREFIX       the log-log plots, each curve with its fitted line and
//                                   slope (harness/report/cost_plot.h): with
//                                   --aabench_cost_model PREFIX-pixels.svg and
//                                   PREFIX-edges.svg; with --aabench_edge_cost
//                                   PREFIX-edge-pixels.svg and PREFIX-edge-faces.svg.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "build_info.h"  // generated: the build type and flags
#include "harness/measure/dense_scenes.h"
#include "harness/world/edges.h"
#include "harness/report/cost_plot.h"
#include "harness/world/frame.h"
#include "methods/aa_circle.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/curves.h"

namespace {

using namespace aabench;

// `in` views a scene kept for the whole run (keep_scene, a kept frame's input).
void run_benchmark(benchmark::State& state, SceneInput in, const Method* method) {
    const Scene* scene = &in.scene();
    Image out(scene->width, scene->height);
    for (auto _ : state) {
        method->render(in, out);
        benchmark::DoNotOptimize(out.data.data());
        benchmark::ClobberMemory();
    }
    const double pixels = static_cast<double>(scene->width) * scene->height;
    // Rates are given per iteration and flagged as rates: Google Benchmark divides by the time
    // and prints "pixel_rate=223.3M/s" itself (a value pre-divided by 1e6 under a name ending
    // in "/s" printed "Mpixel/s=223.256/s").
    state.counters["pixel_rate"] =
        benchmark::Counter(pixels, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["edge_rate"] = benchmark::Counter(static_cast<double>(scene->edge_count()),
                                                     benchmark::Counter::kIsIterationInvariantRate);
    state.counters["edges"] = static_cast<double>(scene->edge_count());
}

// Every plane of a colour scene (its channel scenes made once by the frame: `in` carries them).
void run_colour_benchmark(benchmark::State& state, SceneInput in, const Method* method) {
    const Scene* scene = &in.scene();
    ImagePlanes out(scene->channels, scene->width, scene->height);
    for (auto _ : state) {
        method->render(in, out);
        benchmark::DoNotOptimize(out[0].data.data());
        benchmark::ClobberMemory();
    }
    const double pixels = static_cast<double>(scene->width) * scene->height;
    state.counters["pixel_rate"] =
        benchmark::Counter(pixels, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["channels"] = scene->channels;
}

void run_threaded(benchmark::State& state, const Scene* scene, const Method* method,
                  int threads) {
    Image out(scene->width, scene->height);
    for (auto _ : state) {
        render_in_bands(*method, *scene, out, threads);
        benchmark::DoNotOptimize(out.data.data());
        benchmark::ClobberMemory();
    }
    const double pixels = static_cast<double>(scene->width) * scene->height;
    state.counters["pixel_rate"] =
        benchmark::Counter(pixels, benchmark::Counter::kIsIterationInvariantRate);
    state.counters["threads"] = threads;
}

// Removes `flag` from argv; true when it was there.
bool take_flag(int& argc, char** argv, const char* flag) {
    for (int k = 1; k < argc; ++k) {
        if (std::strcmp(argv[k], flag) != 0) continue;
        for (int m = k; m + 1 < argc; ++m) argv[m] = argv[m + 1];
        --argc;
        return true;
    }
    return false;
}

// Google Benchmark's console output warns "Library was built as DEBUG" when the library itself
// was compiled without NDEBUG, as Debian's libbenchmark is. That is about the library, not
// about the code it times: the timing loop (State's iterator) is inline in the header and
// compiled here with our flags. Said once on stderr before the run, so that no one reads the
// timings as those of a debug build.
void explain_library_build() {
    std::string flags = build_info::kCxxFlags;  // CMake joins them with a leading space
    flags.erase(0, flags.find_first_not_of(' '));
    fmt::print(stderr,
               "aabench_bench: aabench is a {} build ({}). Google Benchmark's \"Library was "
               "built as DEBUG\" warning, where it appears, is about the benchmark library as "
               "its package built it; the timing loop is compiled here, with these flags.\n",
               build_info::kBuildType, flags);
}

// The cost model: the runs of "cost/<axis>/<method>/<x>" benchmarks, and least-squares slopes
// of log(time) against log(x) per (axis, method).
class CostModelReporter : public benchmark::ConsoleReporter {
public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            // One point per benchmark: the median when repeated, else the run itself.
            const bool single = run.run_type == Run::RT_Iteration && run.repetitions <= 1;
            const bool median = run.run_type == Run::RT_Aggregate && run.aggregate_name == "median";
            if (!single && !median) continue;
            const std::string name = run.run_name.function_name;  // cost/<axis>/<method>/<x>
            const auto first = name.find('/'), second = name.find('/', first + 1),
                       last = name.rfind('/');
            if (name.rfind("cost/", 0) != 0 || last <= second) continue;
            const std::string key = name.substr(first + 1, last - first - 1);
            const double x = std::stod(name.substr(last + 1));
            points_[key].push_back({x, run.GetAdjustedRealTime()});
        }
    }
    void print_slopes() const {
        std::printf("\ncost model: fitted log-log slopes (time ~ x^slope)\n");
        std::printf("%-8s %-56s %6s %12s %12s\n", "axis", "method", "slope", "t(min x) ms",
                    "t(max x) ms");
        for (const auto& [key, pts] : points_) {
            if (pts.size() < 2) continue;
            const double slope = fit_log_log(pts).slope;  // the report's fit (cost_plot.h)
            const auto slash = key.find('/');
            std::printf("%-8s %-56s %6.2f %12.3f %12.3f\n", key.substr(0, slash).c_str(),
                        key.substr(slash + 1).c_str(), slope, pts.front().second,
                        pts.back().second);
        }
    }

    // The measurements of one axis ("pixels" or "edges"), one series per method, times in ms.
    std::vector<CostSeries> series(const std::string& axis) const {
        std::vector<CostSeries> out;
        for (const auto& [key, pts] : points_) {
            const auto slash = key.find('/');
            if (key.substr(0, slash) == axis) out.push_back({key.substr(slash + 1), pts});
        }
        return out;
    }

private:
    std::map<std::string, std::vector<std::pair<double, double>>> points_;
};
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
    state.counters["circle_rate"] =
        benchmark::Counter(circles, benchmark::Counter::kIsIterationInvariantRate);
    // The count itself (a median of rates times a median of times is not the count when the
    // repetitions are even: harness/measure/circle_timing.cpp divides by this).
    state.counters["circles"] = circles;
    // Not for the empty canvas (no circle): an inverted zero rate is Infinity, which Google
    // Benchmark writes into its JSON as a bare token no JSON reader takes.
    if (circles > 0) {
        // Inverted rate: seconds per circle, printed with its SI prefix ("350ns").
        state.counters["time_per_circle"] = benchmark::Counter(
            circles, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    }
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

// The value of --NAME=VALUE, removed from argv; empty when absent.
std::string take_value(int& argc, char** argv, const std::string& name) {
    const std::string prefix = name + "=";
    for (int k = 1; k < argc; ++k) {
        if (std::strncmp(argv[k], prefix.c_str(), prefix.size()) != 0) continue;
        std::string value = argv[k] + prefix.size();
        for (int m = k; m + 1 < argc; ++m) argv[m] = argv[m + 1];
        --argc;
        return value;
    }
    return {};
}

// Writes `text` to `path`; false (and a message) when it cannot.
bool write_text(const std::string& path, const std::string& text) {
    std::FILE* file = std::fopen(path.c_str(), "w");
    bool ok = file != nullptr;
    if (file != nullptr) {
        ok = std::fwrite(text.data(), 1, text.size(), file) == text.size();
        ok = std::fclose(file) == 0 && ok;
    }
    if (!ok) std::fprintf(stderr, "aabench_bench: cannot write %s\n", path.c_str());
    return ok;
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

// Owned for the whole run: benchmarks hold raw pointers to them.
std::vector<std::unique_ptr<Scene>> g_scenes;
std::vector<MethodInstance> g_methods;

const Scene* keep_scene(Scene scene) {
    g_scenes.push_back(std::make_unique<Scene>(window_scene(std::move(scene))));
    return g_scenes.back().get();
}

void register_cost_model() {
    // x in the name is the axis value: pixels (side^2) or edges.
    for (const int side : {128, 256, 512, 1024, 2048, 4096}) {
        const Scene* scene = keep_scene(make_pattern("star", side, side));
        for (const MethodInstance& m : g_methods) {
            // A method that cannot draw the scene (the circle methods on polygons) would time
            // its refusal: left out, as in the grid.
            if (!m.method->not_applicable(*scene).empty()) continue;
            benchmark::RegisterBenchmark(
                fmt::format("cost/pixels/{}/{}", m.spec, static_cast<long long>(side) * side)
                    .c_str(),
                run_benchmark, SceneInput(*scene), m.method.get())
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        }
    }
    for (const double period : {64.0, 32.0, 16.0, 8.0, 4.0, 2.6}) {
        const Scene* scene = keep_scene(make_pattern(fmt::format("rings:period={}", period), 1024, 1024));
        for (const MethodInstance& m : g_methods) {
            if (!m.method->not_applicable(*scene).empty()) continue;
            benchmark::RegisterBenchmark(
                fmt::format("cost/edges/{}/{}", m.spec, scene->edge_count()).c_str(),
                run_benchmark, SceneInput(*scene), m.method.get())
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        }
    }
    for (const std::string& name : dense_scene_names()) {
        const Scene* scene = keep_scene(make_dense_scene(name, 1024));
        for (const MethodInstance& m : g_methods) {
            if (!m.method->not_applicable(*scene).empty()) continue;
            benchmark::RegisterBenchmark(
                fmt::format("cost/dense-{}/{}/{}", name, m.spec, scene->edge_count()).c_str(),
                run_benchmark, SceneInput(*scene), m.method.get())
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        }
    }
}

// The edge stage (Saito & Takahashi 1990) against pixels and against faces. The paper says its
// cost depends on the pixel count only, not on the shape's complexity: it is image processing on
// the depth image. Inputs are made outside the timed loop: `torus`'s depth and shaded images
// rendered by `exact`. Axis "edge-pixels": torus (48 x 24 facets) at 256^2 .. 2048^2; axis
// "edge-faces": torus at 512^2 with 10^2 .. 10^5 facets (major x minor segments), and beside it
// "depth-faces", the depth image's own render time by `exact` on the same scenes, which does
// grow with the faces (what hidden-surface removal costs; the edge stage reuses its result).
// The stage writes into output images kept across iterations (as the method benchmarks keep
// theirs) and keeps its own buffers per thread (harness/world/edges.h), so the loop times the
// filtering, not fresh pages.
struct EdgeInput {
    std::optional<PreparedFrame> frame;  // the scene prepared once: the edge stage runs on it
    Image depth, shaded;
    std::optional<SceneInput> depth_scene;  // the depth pieces `exact` draws (depth-faces)
    // The stage's output, made (and its pages touched) once at registration and kept: Google
    // Benchmark calls a benchmark's function anew for its warm-up and for each repetition, and
    // a large image runs only one or two iterations, so outputs made inside the function would
    // put their first-touch page faults into the time.
    EdgeImages out;
};
std::vector<std::unique_ptr<EdgeInput>> g_edge_inputs;

// The method that renders the edge stage's inputs: the reference renderer, which draws affine
// values (the depth image) as it draws constant ones (MethodTraits).
const MethodInstance& edge_stage_renderer() {
    const auto it = std::find_if(g_methods.begin(), g_methods.end(), [](const MethodInstance& m) {
        return m.method->traits().reference_renderer && m.method->affine_values();
    });
    if (it == g_methods.end()) throw std::logic_error("no reference renderer with affine values");
    return *it;
}

EdgeInput* keep_edge_input(const std::string& pattern, int side) {
    const MethodInstance& exact = edge_stage_renderer();
    auto in = std::make_unique<EdgeInput>();
    in->frame = PreparedFrame::prepare(make_pattern(pattern, side, side));
    const PreparedFrame& frame = *in->frame;
    in->shaded = render_scene(*exact.method, frame.input_for(*exact.method));
    in->depth = *frame.after_method(*exact.method, exact.spec, in->shaded, true).depth;
    in->depth_scene = frame.depth_pieces();
    frame.edge_stage(in->depth, in->shaded, in->out);
    g_edge_inputs.push_back(std::move(in));
    return g_edge_inputs.back().get();
}

void run_edge_stage_bench(benchmark::State& state, EdgeInput* in) {
    for (auto _ : state) {
        in->frame->edge_stage(in->depth, in->shaded, in->out);
        benchmark::DoNotOptimize(in->out.composite.data.data());
        benchmark::ClobberMemory();
    }
    state.counters["pixel_rate"] = benchmark::Counter(
        static_cast<double>(in->depth.width) * in->depth.height,
        benchmark::Counter::kIsIterationInvariantRate);
}

void register_edge_cost() {
    for (const int side : {256, 512, 1024, 2048}) {
        EdgeInput* in = keep_edge_input("torus", side);
        benchmark::RegisterBenchmark(
            fmt::format("cost/edge-pixels/edge-stage/{}", static_cast<long long>(side) * side).c_str(),
            run_edge_stage_bench, in)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
    const MethodInstance& exact = edge_stage_renderer();
    // 10^2, 10^3, 10^4, 10^5 facets, and 3,200 and 32,768 between them.
    const std::vector<std::pair<int, int>> segments = {{10, 10},  {40, 25},   {80, 40},
                                                       {125, 80}, {256, 128}, {400, 250}};
    for (const auto& [major, minor] : segments) {
        EdgeInput* in = keep_edge_input(
            fmt::format("torus:major_segments={},minor_segments={}", major, minor), 512);
        const int faces = major * minor;
        benchmark::RegisterBenchmark(fmt::format("cost/edge-faces/edge-stage/{}", faces).c_str(),
                                     run_edge_stage_bench, in)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(fmt::format("cost/depth-faces/exact/{}", faces).c_str(),
                                     run_benchmark, *in->depth_scene, exact.method.get())
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
}

// Colour against grey on the same geometry (docs/colour.md, "What colour costs"): the colour
// pattern, and the same scene with every colour replaced by its luminance (one plane), for the
// methods whose colour cost is bounded there. Registered in every run.
void register_colour_cost(std::vector<std::unique_ptr<PreparedFrame>>& frames) {
    constexpr int kSide = 1024;
    Scene colour = make_pattern("isoluminant", kSide, kSide);
    Scene grey = colour;
    grey.channels = 1;
    grey.background_rgb.reset();
    for (Shape& s : grey.shapes) s.rgb.reset();
    for (ThinObject& t : grey.thin_objects) t.shape.rgb.reset();
    frames.push_back(std::make_unique<PreparedFrame>(PreparedFrame::prepare(colour)));
    const PreparedFrame& colour_frame = *frames.back();
    frames.push_back(std::make_unique<PreparedFrame>(PreparedFrame::prepare(grey)));
    const PreparedFrame& grey_frame = *frames.back();
    // The floor of any render's time: its planes written once with one value (std::fill), one
    // plane for grey, three for colour (docs/colour.md, "What colour costs").
    for (const int channels : {3, 1}) {
        benchmark::RegisterBenchmark(
            fmt::format("{}/fill-planes/{}", channels == 3 ? "colour" : "grey", kSide).c_str(),
            [channels](benchmark::State& state) {
                ImagePlanes out(channels, kSide, kSide);
                float value = 0.5f;
                for (auto _ : state) {
                    for (int c = 0; c < channels; ++c) {
                        std::fill(out[c].data.begin(), out[c].data.end(), value);
                    }
                    benchmark::DoNotOptimize(out[0].data.data());
                    benchmark::ClobberMemory();
                    value += 1.0f;
                }
                state.counters["pixel_rate"] = benchmark::Counter(
                    static_cast<double>(kSide) * kSide, benchmark::Counter::kIsIterationInvariantRate);
            })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
    for (const char* spec : {"none", "exact", "box-multiscan", "ssaa"}) {
        g_methods.push_back(make_method(spec));
        const Method* m = g_methods.back().method.get();
        benchmark::RegisterBenchmark(fmt::format("colour/{}/isoluminant/{}", spec, kSide).c_str(),
                                     run_colour_benchmark, colour_frame.input_for(*m), m)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(fmt::format("grey/{}/isoluminant/{}", spec, kSide).c_str(),
                                     run_benchmark, grey_frame.input_for(*m), m)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
}

void register_scaling() {
    std::vector<std::string> specs = {"none"};
    for (const int n : {1, 2, 3, 6, 12}) specs.push_back(fmt::format("box-multiscan:n={}", n));
    for (const int n : {1, 3, 6}) specs.push_back(fmt::format("gauss-multiscan:n={}", n));
    for (const int k : {1, 2, 3, 4, 6}) specs.push_back(fmt::format("ssaa:k={}", k));
    for (const std::string& spec : specs) g_methods.push_back(make_method(spec));
    for (const char* pattern : {"star", "rings"}) {
        const Scene* scene = keep_scene(make_pattern(pattern, 1024, 1024));
        for (const MethodInstance& m : g_methods) {
            benchmark::RegisterBenchmark(fmt::format("scaling/{}/{}/1024", m.spec, pattern).c_str(),
                                         run_benchmark, SceneInput(*scene), m.method.get())
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<int> sizes = parse_sizes(argc, argv);
    const bool cost_model = take_flag(argc, argv, "--aabench_cost_model");
    const bool edge_cost = take_flag(argc, argv, "--aabench_edge_cost");
    const std::string cost_svg = take_value(argc, argv, "--aabench_cost_svg");
    if (take_flag(argc, argv, "--aabench_scaling")) {
        register_scaling();
        benchmark::Initialize(&argc, argv);
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
        explain_library_build();
        benchmark::RunSpecifiedBenchmarks();
        benchmark::Shutdown();
        return 0;
    }
    auto& scenes = g_scenes;
    auto& methods = g_methods;
    std::vector<std::unique_ptr<PreparedFrame>> frames;  // the benchmarks keep pointers into them
    for (const MethodInfo& info : method_registry()) methods.push_back(make_method(info.id));
    std::vector<std::string> extra_patterns;
    for (std::string id; !(id = take_value(argc, argv, "--aabench_pattern")).empty();) {
        const auto& rows = pattern_registry();
        if (std::none_of(rows.begin(), rows.end(),
                         [&](const PatternInfo& row) { return row.id == id; })) {
            std::fprintf(stderr, "aabench_bench: --aabench_pattern=%s: no such built-in pattern\n",
                         id.c_str());
            return 2;
        }
        extra_patterns.push_back(id);
    }
    for (std::string spec; !(spec = take_value(argc, argv, "--aabench_method")).empty();) {
        try {
            methods.push_back(make_method(spec));
        } catch (const InputError& e) {
            std::fprintf(stderr, "aabench_bench: --aabench_method=%s: %s\n", spec.c_str(), e.what());
            return 2;
        }
    }
    if (cost_model || edge_cost) {
        if (cost_model) register_cost_model();
        if (edge_cost) register_edge_cost();
        benchmark::Initialize(&argc, argv);
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
        explain_library_build();
        CostModelReporter reporter;
        benchmark::RunSpecifiedBenchmarks(&reporter);
        reporter.print_slopes();
        benchmark::Shutdown();
        if (!cost_svg.empty() && cost_model) {
            const std::string pixels =
                cost_model_svg(reporter.series("pixels"), "pixels (star, 128^2 .. 4096^2)",
                               "Cost against pixels: star (180 .. 576 edges)");
            const std::string edges =
                cost_model_svg(reporter.series("edges"), "edges (rings at 1024^2)",
                               "Cost against edges: rings at 1024^2, period 64 .. 2.6 px");
            const bool ok = write_text(cost_svg + "-pixels.svg", pixels) &&
                            write_text(cost_svg + "-edges.svg", edges);
            if (!ok) return 1;
        }
        if (!cost_svg.empty() && edge_cost) {
            std::vector<CostSeries> faces = reporter.series("edge-faces");
            for (CostSeries& depth : reporter.series("depth-faces")) {
                depth.method = "depth image by " + depth.method;
                faces.push_back(std::move(depth));
            }
            const std::string pixels = cost_model_svg(
                reporter.series("edge-pixels"), "pixels (torus, 48 x 24 facets, 256^2 .. 2048^2)",
                "Edge stage (Saito & Takahashi 1990) against pixels");
            const std::string face_plot = cost_model_svg(
                faces, "faces (torus facets at 512^2)",
                "Edge stage (Saito & Takahashi 1990) against faces, and the depth image it is "
                "given");
            const bool ok = write_text(cost_svg + "-edge-pixels.svg", pixels) &&
                            write_text(cost_svg + "-edge-faces.svg", face_plot);
            if (!ok) return 1;
        }
        return 0;
    }
    // The band split (render_in_bands) of the five scanline methods: 1, 2, 4 and 8 bands on
    // as many threads, on rings and the star at 1024^2. The speed-up is the ratio of the
    // one-band time to the N-band time; past the machine's cores it shows the split's own
    // overhead (more bands, each paying its share of the edge table).
    const Scene* rings = keep_scene(make_pattern("rings", 1024, 1024));
    const Scene* star = keep_scene(make_pattern("star", 1024, 1024));
    for (const char* id : {"exact", "box-multiscan", "gauss-multiscan", "ssaa", "none"}) {
        const auto it = std::find_if(methods.begin(), methods.end(),
                                     [&](const MethodInstance& m) { return m.spec == id || m.id == id; });
        if (it == methods.end()) continue;
        for (const auto& [name, scene] : {std::pair{"rings", rings}, std::pair{"star", star}}) {
            for (const int threads : {1, 2, 4, 8}) {
                benchmark::RegisterBenchmark(
                    fmt::format("threads/{}/{}/1024/{}", id, name, threads).c_str(), run_threaded,
                    scene, it->method.get(), threads)
                    ->Unit(benchmark::kMillisecond)
                    ->UseRealTime();
            }
        }
    }
    for (const PatternInfo& pattern : pattern_registry()) {
        const bool named =
            std::find(extra_patterns.begin(), extra_patterns.end(), pattern.id) != extra_patterns.end();
        if (!pattern.in_default_run && !named) continue;
        for (int size : sizes) {
            // 3-D patterns: each method draws its input of the prepared frame (the visible
            // pieces, or the ScreenScene for a method with its own visibility). The world
            // stages are not part of this time; compare adds the stages a method relies on.
            frames.push_back(std::make_unique<PreparedFrame>(
                PreparedFrame::prepare(make_pattern(pattern.id, size, size))));
            const PreparedFrame& frame = *frames.back();
            for (const MethodInstance& method : methods) {
                const SceneInput drawn = frame.input_for(*method.method);
                // A method that cannot draw the scene (aa-circle on polygons) is not timed on it.
                if (!method.method->not_applicable(drawn.scene()).empty()) continue;
                benchmark::RegisterBenchmark(
                    fmt::format("{}/{}/{}", method.spec, pattern.id, size).c_str(), run_benchmark,
                    drawn, method.method.get())
                    ->Unit(benchmark::kMillisecond)
                    ->UseRealTime();
            }
        }
    }
    for (const std::string& name : dense_scene_names()) {
        for (int size : sizes) {
            const Scene* scene = keep_scene(make_dense_scene(name, size));
            for (const MethodInstance& method : methods) {
                if (!method.method->not_applicable(*scene).empty()) continue;
                benchmark::RegisterBenchmark(
                    fmt::format("{}/{}/{}", method.spec, name, size).c_str(), run_benchmark,
                    SceneInput(*scene), method.method.get())
                    ->Unit(benchmark::kMillisecond)
                    ->UseRealTime();
            }
        }
    }
    register_colour_cost(frames);
    std::vector<MethodInstance> circle_methods;
    circle_methods.reserve(8);  // the benchmarks keep pointers into it
    register_circle_benchmarks(scenes, circle_methods);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
    explain_library_build();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
