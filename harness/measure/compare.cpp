// The comparison run (harness/measure/compare.h): the task list, the parallel render-and-score
// pass, the serial timing pass, and the shard, benchmark and figure helpers around them.
#include "harness/measure/compare.h"

#include <fmt/format.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <nlohmann/json.hpp>

#include "harness/measure/compare_tasks.h"
#include "harness/measure/limits.h"
#include "harness/measure/metric_input.h"
#include "harness/measure/pass_time.h"
#include "harness/measure/line_scores.h"
#include "harness/measure/shard_plan.h"
#include "harness/measure/symptoms.h"
#include "harness/reference/box_reference.h"
#include "harness/reference/filter_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

struct PatternState {
    std::string id;                     // the pattern's id, or the scene file's stem
    std::string spec;                   // the canonical pattern spec, or the stem
    std::string scene_file;             // empty for a built-in pattern
    PatternInstance instance;           // built-in patterns only
    const Scene* file_scene = nullptr;  // scene files only: as read (CompareOptions owns it)
    // The pattern prepared once: what each method draws (input_for), the pieces the references
    // measure, the world stages' costs. Empty until prepare_patterns() makes it.
    std::optional<PreparedFrame> frame;
    // What the references measure: the pattern itself (2-D) or its visible pieces (3-D), and
    // that scene alone (for its size and edges).
    SceneInput measured() const { return frame->pieces(); }
    const Scene& scene() const { return frame->pieces().scene(); }
    std::map<std::string, Coverage> references;  // by canonical filter spec
    // A colour scene's box reference per channel (references["box"] is its luminance's).
    std::optional<CoveragePlanes> box_planes;
    // What the metrics ask prepared (harness/measure/metric_input.h), once per pattern and
    // shared by its tasks; the motion references per filter of the pattern's default rows.
    ScenePreparations prepared;
};

// Progress over a count of steps that can grow while the run goes on (the motion references
// are counted when they are made). Calls to the callback are serialised.
class Progress {
public:
    Progress(const ProgressFn& callback, std::size_t total) : callback_(callback), total_(total) {}
    void add_to_total(std::size_t steps) { total_ += steps; }
    void step(const std::string& what) {
        if (!callback_) return;
        std::lock_guard<std::mutex> lock(mutex_);
        callback_(++done_, total_, what);
    }

private:
    const ProgressFn& callback_;
    std::mutex mutex_;
    std::size_t done_ = 0;
    std::size_t total_ = 0;
};

// What a task's method draws (the frame decides by the method's traits).
SceneInput drawn(const PatternState& ps, const Method& method) {
    return ps.frame->input_for(method);
}

void check_options(const CompareOptions& options) {
    check_image_size(options.width, options.height, "--size");
    if (!(options.time_budget_ms >= 0.0 && options.time_budget_ms <= 1e6)) {
        throw InputError(fmt::format("--time-budget: {} is out of range 0..1e6 ms",
                                     options.time_budget_ms));
    }
    if (options.runs < 1 || options.runs > 1000) {
        throw InputError(fmt::format("--runs: {} is out of range 1..1000", options.runs));
    }
    if (options.motion_frames < 1 || options.motion_frames > 1024) {
        throw InputError(
            fmt::format("--frames: {} is out of range 1..1024", options.motion_frames));
    }
    if (options.jobs < 1 || options.jobs > 256) {
        throw InputError(fmt::format("--jobs: {} is out of range 1..256", options.jobs));
    }
    if (options.render_threads < 1 || options.render_threads > 256) {
        throw InputError(fmt::format("--render-threads: {} is out of range 1..256",
                                     options.render_threads));
    }
    if (options.shard_count < 1 || options.shard_index < 0 ||
        options.shard_index >= options.shard_count) {
        throw InputError(fmt::format("--shard: {}/{} is not a shard K/N with 1 <= K <= N",
                                     options.shard_index + 1, options.shard_count));
    }
}

// The metrics a task computes: every row's, and the symptoms on a default row with
// options.symptoms (sweep points are timed and scored, not diagnosed).
MetricScope task_scope(const Task& task, const CompareOptions& options) {
    MetricScope scope;
    scope.symptoms = options.symptoms && !task.sweep_point;
    return scope;
}

// Scenes and references: only the patterns this shard touches (`needed`), each once. Exact
// references in parallel; then what the metrics in scope ask prepared (the edge band, the
// thin objects, the motion references: one per filter of the pattern's default rows, ...).
void prepare_patterns(std::vector<PatternState>& patterns, const std::vector<char>& needed,
                      const std::vector<Task>& tasks, const std::vector<std::string>& method_specs,
                      const CompareOptions& options, Progress& progress) {
    std::vector<std::pair<std::size_t, std::string>> reference_jobs;
    for (std::size_t p = 0; p < patterns.size(); ++p) {
        if (!needed[p]) continue;
        PatternState& ps = patterns[p];
        check_job_memory(
            estimate_job_bytes(measure_scene(ps.scene()), method_specs, {"box"}, options.jobs),
            kDefaultMemoryBudgetBytes, "compare, pattern " + ps.id);
        std::vector<std::string> filters = {"box"};
        unsigned needs = 0;
        for (const Task& t : tasks) {
            if (t.pattern != p) continue;
            needs |= metric_needs(task_scope(t, options));
            const std::string f = t.method.method->filter().text();
            if (std::find(filters.begin(), filters.end(), f) == filters.end()) filters.push_back(f);
        }
        for (const std::string& f : filters) {
            ps.references.emplace(f, Coverage());
            reference_jobs.emplace_back(p, f);
        }
        // The report's edge figures read the line truth too.
        if (options.keep_images) needs |= kNeedsLines;
        ps.prepared = prepare_scene(*ps.frame, needs);
        if (!(needs & kNeedsMotion)) continue;
        for (const Task& t : tasks) {
            if (t.pattern != p || !(metric_needs(task_scope(t, options)) & kNeedsMotion)) continue;
            ps.prepared.motion.emplace(t.method.method->filter().text(), MotionReference());
        }
    }
    tbb::parallel_for(std::size_t(0), reference_jobs.size(), [&](std::size_t k) {
        PatternState& ps = patterns[reference_jobs[k].first];
        // Each job writes its own, pre-inserted map entry: no insertion races.
        // A colour scene's box reference per channel, and its luminance's from them (every
        // reference is linear in the values: no fourth sweep of the geometry).
        if (reference_jobs[k].second == "box" && ps.scene().channels == 3) {
            ps.box_planes = exact_reference_planes(ps.measured(), Filter::box());
            ps.references.at("box") = luminance_coverage(*ps.box_planes);
            return;
        }
        ps.references.at(reference_jobs[k].second) =
            exact_reference(ps.measured(), reference_jobs[k].second);
    });
    // The box reference's half of every row's ꟻLIP, once per pattern.
    tbb::parallel_for(std::size_t(0), patterns.size(), [&](std::size_t p) {
        if (!needed[p]) return;
        // A colour scene's from its box reference's planes (ꟻLIP in colour).
        patterns[p].prepared.flip =
            patterns[p].box_planes
                ? flip::prepare_flip_reference(*patterns[p].box_planes, flip::pixels_per_degree())
                : flip::prepare_flip_reference(patterns[p].references.at("box"),
                                               flip::pixels_per_degree());
    });
    std::vector<std::pair<std::size_t, std::string>> motion_jobs;
    for (std::size_t p = 0; p < patterns.size(); ++p) {
        for (const auto& entry : patterns[p].prepared.motion) {
            motion_jobs.emplace_back(p, entry.first);
        }
    }
    progress.add_to_total(motion_jobs.size());
    tbb::parallel_for(std::size_t(0), motion_jobs.size(), [&](std::size_t k) {
        PatternState& ps = patterns[motion_jobs[k].first];
        const std::string filter = motion_jobs[k].second;
        // 3-D: the camera moves, and each frame is prepared anew.
        ps.prepared.motion.at(filter) = prepare_motion_reference(
            ps.frame->given(), options.motion_frames,
            [&filter](const SceneInput& s) { return exact_reference(s, filter); });
        progress.step("motion reference " + ps.id + " / " + filter);
    });
}

// The errors of a row whose method cannot draw the scene: none (NaN, shown as "-").
ErrorStats not_applicable_stats() {
    ErrorStats s;
    s.rmse = s.max_abs = s.bias = s.dropout = kNaN;
    return s;
}

// Renders the task and scores it against the pattern's references: every metric of the
// registry in the task's scope. Renders into `out`, of the scene's size.
ResultRow score_task(const Task& task, const PatternState& ps, const CompareOptions& options,
                     Image& out, ImagePlanes& colour_out) {
    const Scene& scene = ps.scene();
    ResultRow row;
    row.task = task.index;
    row.pattern = ps.spec;
    row.pattern_id = ps.id;
    row.scene_file = ps.scene_file;
    row.method = task.method.spec;
    row.method_id = task.method.id;
    row.sweep_point = task.sweep_point;
    row.cost_param = task.cost_param;
    row.cost_value = task.cost_value;
    row.width = scene.width;
    row.height = scene.height;
    row.edges = static_cast<long long>(scene.edge_count());
    const StageCosts costs = ps.frame->costs();
    for (int k = 0; k < kStageCount; ++k) {
        const StageCost& c = costs[k];
        if (!c.ran) continue;
        add_stage_cost(row, k, c.time_ms, static_cast<double>(c.bytes));
    }
    row.reference_filter = task.method.method->filter().text();
    const SceneInput input = drawn(ps, *task.method.method);
    row.not_applicable = task.method.method->not_applicable(input.scene());
    if (!row.not_applicable.empty()) {  // a capability: no numbers rather than wrong ones
        set_box_stats(row, not_applicable_stats());
        set_own_stats(row, not_applicable_stats());
        return row;
    }
    // A colour scene: every plane drawn, the metrics on their luminance (`out`) and the box
    // errors over every channel (metric_input.h).
    const bool colour = input.scene().channels == 3;
    if (colour) {
        colour_out = ImagePlanes(3, scene.width, scene.height);
        render_in_bands(*task.method.method, input, colour_out, options.render_threads);
        luminance_image(colour_out, out);
    } else {
        render_in_bands(*task.method.method, input, out, options.render_threads);
    }
    const auto motion = ps.prepared.motion.find(row.reference_filter);
    const MetricInput in{.image = out,
                         .frame = *ps.frame,
                         .box = ps.references.at("box"),
                         .own = ps.references.at(row.reference_filter),
                         .prepared = ps.prepared,
                         .method = &task.method,
                         .drawn = &input,
                         .motion = motion == ps.prepared.motion.end() ? nullptr : &motion->second,
                         .planes = colour ? &colour_out : nullptr,
                         .box_planes = ps.box_planes ? &*ps.box_planes : nullptr};
    compute_metrics(in, task_scope(task, options), row);
    return row;
}

// Pass 1, parallel: render and score. With options.keep_images, the default rows' images are
// kept in `kept` (same index as the task).
void score_tasks(const std::vector<Task>& tasks, const std::vector<PatternState>& patterns,
                 const CompareOptions& options, std::vector<ResultRow>& rows,
                 std::vector<Image>& kept, std::vector<ImagePlanes>& kept_colour,
                 Progress& progress) {
    rows.resize(tasks.size());
    kept.resize(tasks.size());
    kept_colour.resize(tasks.size());
    tbb::parallel_for(std::size_t(0), tasks.size(), [&](std::size_t k) {
        const Task& task = tasks[k];
        const Scene& scene = patterns[task.pattern].scene();
        Image out(scene.width, scene.height);
        ImagePlanes colour;
        rows[k] = score_task(task, patterns[task.pattern], options, out, colour);
        if (options.keep_images && !task.sweep_point) {
            kept[k] = std::move(out);
            kept_colour[k] = std::move(colour);
        }
        progress.step("score " + rows[k].pattern_id + " / " + rows[k].method);
    });
}

// Pass 2, serial: each task timed alone on this thread.
void time_tasks(const std::vector<Task>& tasks, const std::vector<PatternState>& patterns,
                const CompareOptions& options, std::vector<ResultRow>& rows, Progress& progress) {
    for (std::size_t k = 0; k < tasks.size(); ++k) {
        const SceneInput input = drawn(patterns[tasks[k].pattern], *tasks[k].method.method);
        const Scene& scene = input.scene();
        ResultRow& row = rows[k];
        if (!row.not_applicable.empty()) {  // nothing drawn, nothing timed
            progress.step("time " + row.pattern_id + " / " + row.method);
            continue;
        }
        // Every plane the scene has (one Image for a grey scene, as always).
        const bool colour = scene.channels == 3;
        Image out(colour ? 0 : scene.width, colour ? 0 : scene.height);
        ImagePlanes planes(colour ? 3 : 0, scene.width, scene.height);
        set_timing(row,
                   colour ? time_render(*tasks[k].method.method, input, planes, options.runs,
                                        options.render_threads, options.time_budget_ms * 1e6)
                          : time_render(*tasks[k].method.method, input, out, options.runs,
                                        options.render_threads, options.time_budget_ms * 1e6),
                   patterns[tasks[k].pattern].frame->relied_stage_ms(*tasks[k].method.method));
        // A post-process row: its pass alone too, on its base's image rendered once (a colour
        // scene: its planes, and the colour pass).
        if (const auto* pass =
                dynamic_cast<const PostProcessMethod*>(tasks[k].method.method.get())) {
            if (scene.channels == 3) {
                ImagePlanes base(3, scene.width, scene.height);
                pass->base().render(input, base);
                row[time_pass_metric()] =
                    time_pass(*pass, base, planes, options.runs).median_ns * 1e-6;
            } else {
                Image base(scene.width, scene.height);
                pass->base().render(input, base);
                row[time_pass_metric()] =
                    time_pass(*pass, base, out, options.runs).median_ns * 1e-6;
            }
        }
        progress.step("time " + row.pattern_id + " / " + row.method);
    }
}

// The kept images of each needed pattern's default rows, in task order.
std::vector<ComparisonFigures> collect_figures(const std::vector<PatternState>& patterns,
                                               const std::vector<char>& needed,
                                               const std::vector<Task>& tasks,
                                               const std::vector<ResultRow>& rows,
                                               std::vector<Image>& kept,
                                               std::vector<ImagePlanes>& kept_colour) {
    std::vector<ComparisonFigures> figures;
    for (std::size_t p = 0; p < patterns.size(); ++p) {
        if (!needed[p]) continue;
        ComparisonFigures fig;
        fig.pattern_id = patterns[p].id;
        fig.pattern_spec = patterns[p].spec;
        fig.scene = patterns[p].scene();
        fig.reference = patterns[p].references.at("box");
        fig.colour_reference = patterns[p].box_planes;
        if (const auto& lines = patterns[p].prepared.lines) {
            fig.edges = edge_figures(*lines, *patterns[p].frame, fig.reference);
        }
        for (std::size_t k = 0; k < tasks.size(); ++k) {
            if (tasks[k].pattern != p || tasks[k].sweep_point) continue;
            if (!rows[k].not_applicable.empty()) continue;  // drew nothing: no figure
            fig.methods.push_back(rows[k].method);
            fig.images.push_back(std::move(kept[k]));
            if (fig.colour_reference) fig.colour_images.push_back(std::move(kept_colour[k]));
        }
        figures.push_back(std::move(fig));
    }
    return figures;
}

// A scene file as one more pattern, named by its stem. Rows, sections and image directories
// are keyed by that name, so it must differ from every other pattern's in the run.
void add_scene_file(std::vector<PatternState>& patterns, const SceneFileInput& file) {
    const std::string stem = std::filesystem::path(file.path).stem().string();
    for (const PatternState& other : patterns) {
        if (other.spec != stem && other.id != stem) continue;
        throw InputError(fmt::format(
            "--scenes: {}: its name '{}' (the file stem) is taken by {} in this run; rename "
            "the file",
            file.path, stem,
            other.scene_file.empty() ? "the pattern " + other.spec : other.scene_file));
    }
    PatternState& ps = patterns.emplace_back();
    ps.id = stem;
    ps.spec = stem;
    ps.scene_file = file.path;
    ps.file_scene = &file.scene;
}

}  // namespace

std::vector<std::string> split_spec_list(const std::string& text) {
    std::vector<std::string> specs;
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto comma = text.find(',', start);
        const std::string item =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        const bool continues = item.find('=') != std::string::npos &&
                               item.find(':') == std::string::npos && !specs.empty();
        if (continues) {
            specs.back() += "," + item;
        } else if (!item.empty()) {
            specs.push_back(item);
        } else {
            throw InputError("empty item in the list '" + text + "'");
        }
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return specs;
}

namespace {

// What a run and its shard plan share: the patterns (frames prepared: cheap beside the
// references, and what the estimates need), the methods, every task and the split.
struct RunSetup {
    std::vector<PatternState> patterns;
    std::vector<std::string> method_specs;  // as given (the memory check takes them)
    std::vector<Task> all_tasks;             // the unsharded run
    ShardPlan plan;
};

RunSetup set_up_run(const CompareOptions& options) {
    check_options(options);
    RunSetup setup;
    std::vector<std::string> pattern_specs = options.pattern_specs;
    if (pattern_specs.empty() && options.scene_files.empty()) {
        for (const PatternInfo& info : pattern_registry()) {
            if (info.in_default_run) pattern_specs.push_back(info.id);
        }
    }
    setup.method_specs = options.method_specs;
    if (setup.method_specs.empty()) {
        // Every method at its defaults, and beside it the other readings its row names. A
        // temporal method's still image is its first frame (one jittered sample per pixel, no
        // history): it runs where its history exists, on sequences (compare --sequences), and
        // here only when named.
        for (const MethodInfo& info : method_registry()) {
            if (info.traits->temporal) continue;
            setup.method_specs.push_back(info.id);
            for (const std::string& variant : info.default_run_variants) {
                setup.method_specs.push_back(variant);
            }
        }
    }
    // Check every spec before any work, so a typo fails at once and not after an hour.
    std::vector<PatternState>& patterns = setup.patterns;
    for (const auto& spec : pattern_specs) {
        PatternState& ps = patterns.emplace_back();
        ps.instance = resolve_pattern(spec);
        ps.id = ps.instance.info->id;
        ps.spec = ps.instance.spec;
    }
    for (const SceneFileInput& file : options.scene_files) add_scene_file(patterns, file);
    std::vector<MethodInstance> methods;
    for (const auto& spec : setup.method_specs) methods.push_back(make_method(spec));
    std::vector<bool> curved;
    for (const PatternState& ps : patterns) {
        curved.push_back(ps.file_scene ? has_bezier(*ps.file_scene) : ps.instance.info->bezier);
    }
    setup.all_tasks = make_all_tasks(curved, methods, options);

    ShardPlan& plan = setup.plan;
    for (const PatternState& ps : patterns) plan.pattern_specs.push_back(ps.spec);
    for (const MethodInstance& m : methods) plan.method_specs.push_back(m.spec);
    // Every pattern's frame, and the size of what each method draws (one or two scenes per
    // pattern: the visible pieces, the ScreenScene), for the estimates.
    std::vector<std::map<const Scene*, SceneSize>> sizes(patterns.size());
    std::vector<double> task_ms;
    for (std::size_t p = 0; p < patterns.size(); ++p) {
        PatternState& ps = patterns[p];
        ps.frame = PreparedFrame::prepare(
            ps.file_scene
                ? *ps.file_scene
                : ps.instance.info->generate(ps.instance.params, options.width, options.height));
    }
    for (const Task& t : setup.all_tasks) {
        const Scene& scene = drawn(patterns[t.pattern], *t.method.method).scene();
        auto it = sizes[t.pattern].find(&scene);
        if (it == sizes[t.pattern].end()) {
            it = sizes[t.pattern].emplace(&scene, measure_scene(scene)).first;
        }
        task_ms.push_back(estimate_task_ms(t, it->second, options));
    }
    plan.split = split_by_cost(task_ms, options.shard_count);
    for (const Task& t : setup.all_tasks) {
        plan.tasks.push_back({t.index, patterns[t.pattern].id, t.method.spec, t.sweep_point,
                              task_ms[t.index], plan.split.shard_of_task[t.index]});
    }
    // Memory per shard: each pattern it touches holds its references and kept images until
    // the end, so the patterns' estimates add up (an upper bound: their working memory does
    // not overlap).
    plan.shard_peak_bytes.assign(options.shard_count, 0.0);
    std::map<std::pair<int, std::size_t>, std::vector<std::string>> specs;  // (shard, pattern)
    for (const Task& t : setup.all_tasks) {
        specs[{plan.split.shard_of_task[t.index], t.pattern}].push_back(t.method.spec);
    }
    for (const auto& [key, shard_specs] : specs) {
        plan.shard_peak_bytes[key.first] += static_cast<double>(estimate_job_bytes(
            measure_scene(patterns[key.second].scene()), shard_specs, {"box"}, options.jobs));
    }
    return setup;
}

}  // namespace

ShardPlan plan_shards(const CompareOptions& options) { return set_up_run(options).plan; }

CompareResult run_comparison(const CompareOptions& options, const ProgressFn& progress) {
    RunSetup setup = set_up_run(options);
    std::vector<PatternState>& patterns = setup.patterns;
    CompareResult result;
    result.task_count = static_cast<long long>(setup.all_tasks.size());
    std::vector<Task> tasks;  // this shard's, in task order
    for (Task& t : setup.all_tasks) {
        if (setup.plan.split.shard_of_task[t.index] == options.shard_index) {
            tasks.push_back(std::move(t));
        }
    }

    // Score pass + timing pass (+ the motion references, counted when they are made).
    Progress counter(progress, 2 * tasks.size());
    // --render-threads needs its bands' threads even when --jobs is 1.
    tbb::global_control threads(
        tbb::global_control::max_allowed_parallelism,
        static_cast<std::size_t>(std::max(options.jobs, options.render_threads)));
    std::vector<char> needed(patterns.size(), 0);
    for (const Task& t : tasks) needed[t.pattern] = 1;
    prepare_patterns(patterns, needed, tasks, setup.method_specs, options, counter);

    std::vector<Image> kept;
    std::vector<ImagePlanes> kept_colour;
    score_tasks(tasks, patterns, options, result.rows, kept, kept_colour, counter);
    time_tasks(tasks, patterns, options, result.rows, counter);
    if (options.keep_images) {
        result.figures =
            collect_figures(patterns, needed, tasks, result.rows, kept, kept_colour);
    }
    result.plan = std::move(setup.plan);
    return result;
}

int apply_benchmark_timings(std::vector<ResultRow>& rows, const std::string& json_text,
                            const std::string& source) {
    const nlohmann::json doc = parse_benchmark_json(json_text, source);
    // name -> real time in ns. Names are "SPEC/PATTERN/SIZE"; with repetitions, the median
    // (benchmark_runs, the same picker as the report's plots; entries of the wrong types skipped).
    std::map<std::string, double> times;
    for (const BenchmarkRun& run : benchmark_runs(doc, "")) {
        if (std::isfinite(run.real_ms) && run.real_ms > 0.0) times[run.name] = run.real_ms * 1e6;
    }
    int updated = 0;
    for (ResultRow& row : rows) {
        if (row.width != row.height || !row.scene_file.empty()) continue;
        // The benchmark binary runs patterns at their default parameters only.
        if (row.pattern != resolve_pattern(row.pattern_id).spec) continue;
        const auto it = times.find(fmt::format("{}/{}/{}", row.method, row.pattern_id, row.width));
        if (it == times.end()) continue;
        // The benchmark times the method on its input; the stages it relies on are the run's.
        const double relied_ms = std::isnan(row[metric::kTimeStagesMs]) ? 0.0
                                                                          : row[metric::kTimeStagesMs];
        set_timing(row, TimingStats{it->second, it->second, it->second, 1}, relied_ms);
        row.time_source = "benchmark";
        ++updated;
    }
    return updated;
}

}  // namespace aabench
