// Shard plan text, completion marker and merge checks (harness/report/shards.h).
#include "harness/report/shards.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cstdint>

#include "harness/measure/limits.h"
#include "harness/report/report.h"

namespace aabench {
namespace {

using Json = nlohmann::ordered_json;

// The `schema_version` of a results.json (1 when absent, as rows_from_compare_json reads it).
int results_schema(const std::string& text, const std::string& source) {
    Json doc;
    try {
        doc = Json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(fmt::format("{}: byte {}: invalid JSON", source, e.byte));
    }
    if (!doc.is_object() || !doc.contains("schema_version")) return 1;
    if (!doc["schema_version"].is_number_integer()) {
        throw InputError(source + ": schema_version is not a number");
    }
    return doc["schema_version"].get<int>();
}

// "32x32" for a scalar; "others" for a list (too long for one line).
std::string describe_value(const Json& value) {
    if (value.is_array() || value.is_object()) return "others";
    return value.is_string() ? value.get<std::string>() : value.dump();
}

struct ReadShard {
    const ShardFolder* folder;
    ShardMarker marker;
    int schema = 0;
    std::vector<ResultRow> rows;
};

void check_same_run(const ReadShard& r, const ReadShard& first) {
    const std::string& dir = r.folder->dir;
    const std::string& first_dir = first.folder->dir;
    if (r.schema != first.schema) {
        throw InputError(fmt::format("merge: {}: results schema {}, not {} as {}", dir, r.schema,
                                     first.schema, first_dir));
    }
    if (r.marker.schema_version != r.schema) {
        throw InputError(fmt::format(
            "merge: {}: results.json is of schema {} but its {} says {} (half-written or altered)",
            dir, r.schema, kShardMarkerFile, r.marker.schema_version));
    }
    if (static_cast<long long>(r.rows.size()) != r.marker.rows) {
        throw InputError(fmt::format(
            "merge: {}: results.json holds {} rows, its {} says {} (half-written or altered)", dir,
            r.rows.size(), kShardMarkerFile, r.marker.rows));
    }
    for (const auto& [key, value] : first.marker.options.items()) {
        const bool has = r.marker.options.contains(key);
        if (has && r.marker.options[key] == value) continue;
        // "run with --size 24x24, not 16x16 as DIR"; lists: "run with other --methods than DIR"
        const bool list = value.is_array() || value.is_object();
        throw InputError(
            !has   ? fmt::format("merge: {}: run without {}, unlike {}", dir, key, first_dir)
            : list ? fmt::format("merge: {}: run with other {} than {}", dir, key, first_dir)
                   : fmt::format("merge: {}: run with {} {}, not {} as {}", dir, key,
                                 describe_value(r.marker.options[key]), describe_value(value),
                                 first_dir));
    }
    for (const auto& [key, value] : r.marker.options.items()) {
        if (!first.marker.options.contains(key)) {
            throw InputError(fmt::format("merge: {}: run with {} {}, which {} was not", dir, key,
                                         describe_value(value), first_dir));
        }
    }
    if (r.marker.shard_count != first.marker.shard_count) {
        throw InputError(fmt::format("merge: {}: shard {}/{}, of another N than {} ({}/{})", dir,
                                     r.marker.shard, r.marker.shard_count, first_dir,
                                     first.marker.shard, first.marker.shard_count));
    }
    if (r.marker.split_id != first.marker.split_id ||
        r.marker.task_count != first.marker.task_count) {
        throw InputError(fmt::format(
            "merge: {}: its tasks are split otherwise than {}'s (another aabench build or cost "
            "model): run every shard with one build",
            dir, first_dir));
    }
}

}  // namespace

ShardMarker make_shard_marker(const CompareOptions& options, const CompareResult& result) {
    ShardMarker m;
    m.schema_version = kResultsSchemaVersion;
    m.shard = options.shard_index + 1;
    m.shard_count = options.shard_count;
    m.task_count = result.task_count;
    m.rows = static_cast<long long>(result.rows.size());
    m.split_id = fmt::format("{:016x}", result.plan.split.split_id);
    // What decides the rows; --jobs and --bench-json do not (the first only how fast, the
    // second only the time columns, which differ from run to run anyway).
    Json& o = m.options;
    o["--size"] = fmt::format("{}x{}", options.width, options.height);
    o["--runs"] = options.runs;
    o["--time-budget"] = options.time_budget_ms;
    o["--sweep"] = options.sweep;
    o["--render-threads"] = options.render_threads;
    o["--methods"] = result.plan.method_specs;
    o["--patterns"] = result.plan.pattern_specs;
    std::vector<std::string> scenes;
    for (const SceneFileInput& f : options.scene_files) scenes.push_back(f.path);
    o["--scenes"] = scenes;
    o["motion_frames"] = options.motion_frames;
    o["symptoms"] = options.symptoms;
    const std::vector<double>& shard_ms = result.plan.split.shard_ms;
    m.estimate_s = options.shard_index < static_cast<int>(shard_ms.size())
                       ? shard_ms[options.shard_index] / 1000.0
                       : 0.0;
    return m;
}

std::string shard_marker_json(const ShardMarker& m) {
    Json doc;
    doc["schema_version"] = m.schema_version;
    doc["shard"] = m.shard;
    doc["shard_count"] = m.shard_count;
    doc["task_count"] = m.task_count;
    doc["rows"] = m.rows;
    doc["split"] = m.split_id;
    doc["options"] = m.options;
    doc["estimate_s"] = m.estimate_s;
    doc["tasks_s"] = m.tasks_s;
    doc["wall_s"] = m.wall_s;
    return doc.dump(2) + "\n";
}

ShardMarker shard_marker_from_json(const std::string& text, const std::string& source) {
    Json doc;
    try {
        doc = Json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(fmt::format("{}: byte {}: invalid JSON", source, e.byte));
    }
    ShardMarker m;
    try {
        m.schema_version = doc.at("schema_version").get<int>();
        m.shard = doc.at("shard").get<int>();
        m.shard_count = doc.at("shard_count").get<int>();
        m.task_count = doc.at("task_count").get<long long>();
        m.rows = doc.at("rows").get<long long>();
        m.split_id = doc.at("split").get<std::string>();
        m.options = doc.at("options");
        m.estimate_s = doc.at("estimate_s").get<double>();
        m.tasks_s = doc.at("tasks_s").get<double>();
        m.wall_s = doc.at("wall_s").get<double>();
    } catch (const nlohmann::json::exception&) {
        throw InputError(source + ": not an aabench shard marker (a field is missing or mistyped)");
    }
    if (m.shard_count < 1 || m.shard < 1 || m.shard > m.shard_count || !m.options.is_object()) {
        throw InputError(fmt::format("{}: shard {}/{} is not K/N with 1 <= K <= N", source, m.shard,
                                     m.shard_count));
    }
    return m;
}

std::string format_shard_plan(const ShardPlan& plan) {
    const int n = plan.split.shard_count;
    std::string out = fmt::format("{:>6}  {:>7}  {:>12}  {}\n", "task", "shard", "estimate_ms",
                                  "pattern / method");
    for (const PlannedTask& t : plan.tasks) {
        out += fmt::format("{:>6}  {:>7}  {:>12.3f}  {} / {}{}\n", t.task,
                           fmt::format("{}/{}", t.shard + 1, n), t.estimate_ms, t.pattern_id,
                           t.method, t.sweep_point ? " (sweep)" : "");
    }
    out += fmt::format(
        "\n{} tasks in {} shards, split by estimated cost (ms on the cost model's "
        "machine, methods/cost_model.h; docs/cluster.md):\n",
        plan.tasks.size(), n);
    out += fmt::format("{:>7}  {:>6}  {:>11}  {:>10}\n", "shard", "tasks", "estimate_s", "memory");
    int largest = 0;
    for (int s = 0; s < n; ++s) {
        if (plan.split.shard_ms[s] > plan.split.shard_ms[largest]) largest = s;
        out += fmt::format("{:>7}  {:>6}  {:>11.3f}  {:>10}\n", fmt::format("{}/{}", s + 1, n),
                           plan.split.shard_tasks[s], plan.split.shard_ms[s] / 1000.0,
                           format_bytes(static_cast<std::size_t>(plan.shard_peak_bytes[s])));
    }
    out += fmt::format("largest/mean (estimate): {:.3f}\n", largest_over_mean(plan.split.shard_ms));
    const double peak_bytes =
        *std::max_element(plan.shard_peak_bytes.begin(), plan.shard_peak_bytes.end());
    out += fmt::format("largest shard: {}/{} estimate_s={:.3f} memory_bytes={:.0f}\n", largest + 1,
                       n, plan.split.shard_ms[largest] / 1000.0, peak_bytes);
    return out;
}

MergedShards merge_shard_folders(const std::vector<ShardFolder>& folders) {
    if (folders.empty()) throw InputError("merge: no folders given");
    std::vector<ReadShard> shards;
    for (const ShardFolder& f : folders) {
        if (!f.marker_text) {
            throw InputError(fmt::format(
                "merge: {}: no {}, the marker a finished compare writes last: the shard is "
                "unfinished (or not a compare results folder)",
                f.dir, kShardMarkerFile));
        }
        ReadShard r{&f, shard_marker_from_json(*f.marker_text, f.dir + "/" + kShardMarkerFile)};
        const std::string results = f.dir + "/results.json";
        r.schema = results_schema(f.results_text, results);
        r.rows = rows_from_compare_json(f.results_text, results);
        shards.push_back(std::move(r));
    }
    for (const ReadShard& r : shards) check_same_run(r, shards.front());
    const int n = shards.front().marker.shard_count;
    std::vector<const ReadShard*> by_k(n, nullptr);
    for (const ReadShard& r : shards) {
        const ReadShard*& slot = by_k[r.marker.shard - 1];
        if (slot) {
            throw InputError(fmt::format("merge: {}: shard {}/{} again ({} is shard {}/{} too)",
                                         r.folder->dir, r.marker.shard, n, slot->folder->dir,
                                         r.marker.shard, n));
        }
        slot = &r;
    }
    for (int k = 0; k < n; ++k) {
        if (by_k[k]) continue;
        std::string given;
        for (const ShardFolder& f : folders) given += (given.empty() ? "" : ", ") + f.dir;
        throw InputError(
            fmt::format("merge: shard {}/{} is missing: none of the {} folders "
                        "given holds it ({})",
                        k + 1, n, folders.size(), given));
    }
    MergedShards merged;
    std::vector<std::vector<ResultRow>> rows;
    for (const ReadShard* r : by_k) {
        merged.markers.push_back(r->marker);
        rows.push_back(r->rows);
    }
    merged.rows = merge_shard_rows(std::move(rows));
    const long long task_count = shards.front().marker.task_count;
    if (static_cast<long long>(merged.rows.size()) != task_count) {
        throw InputError(fmt::format("merge: the {} shards hold {} rows of the run's {} tasks", n,
                                     merged.rows.size(), task_count));
    }
    return merged;
}

bool is_error_column(MetricId id) { return id >= 0 && id < metric::kTimeMedianNs; }

std::string error_column_difference(const std::vector<ResultRow>& merged,
                                    const std::vector<ResultRow>& whole) {
    if (merged.size() != whole.size()) {
        return fmt::format("{} merged rows, {} unsharded", merged.size(), whole.size());
    }
    for (std::size_t k = 0; k < merged.size(); ++k) {
        const ResultRow& a = merged[k];
        const ResultRow& b = whole[k];
        if (a.task != b.task || a.pattern != b.pattern || a.method != b.method) {
            return fmt::format("row {}: task {} {} / {} merged, task {} {} / {} unsharded", k,
                               a.task, a.pattern_id, a.method, b.task, b.pattern_id, b.method);
        }
        for (MetricId id = 0; is_error_column(id); ++id) {
            // Bits, not ==: NaN (does not apply) must meet NaN, and -0 is not 0.
            if (std::bit_cast<std::uint64_t>(a[id]) == std::bit_cast<std::uint64_t>(b[id])) {
                continue;
            }
            return fmt::format("row {} ({} / {}): {} is {} merged, {} unsharded", k, a.pattern_id,
                               a.method, metric_registry()[id].key, a[id], b[id]);
        }
    }
    return {};
}

std::string format_shard_times(const std::vector<ShardMarker>& markers) {
    std::string out = fmt::format("{:>7}  {:>6}  {:>11}  {:>8}  {:>8}\n", "shard", "tasks",
                                  "estimate_s", "tasks_s", "wall_s");
    std::vector<double> estimate, tasks, wall;
    for (const ShardMarker& m : markers) {
        out += fmt::format("{:>7}  {:>6}  {:>11.3f}  {:>8.3f}  {:>8.3f}\n",
                           fmt::format("{}/{}", m.shard, m.shard_count), m.rows, m.estimate_s,
                           m.tasks_s, m.wall_s);
        estimate.push_back(m.estimate_s);
        tasks.push_back(m.tasks_s);
        wall.push_back(m.wall_s);
    }
    out +=
        fmt::format("{:>15}  {:>11.3f}  {:>8.3f}  {:>8.3f}\n", "largest/mean",
                    largest_over_mean(estimate), largest_over_mean(tasks), largest_over_mean(wall));
    return out;
}

}  // namespace aabench
