// The regression gate (harness/measure/gate.h): which runs reproduce a baseline, and the
// figure-by-figure comparison with its NaN rules.
#include "harness/measure/gate.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

void add_unique(std::vector<std::string>& list, const std::string& item) {
    if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

bool resolves(const ResultRow& r) {
    try {
        make_method(r.method);
        if (r.scene_file.empty()) resolve_pattern(r.pattern);
    } catch (const InputError&) {
        return false;
    }
    return true;
}

// Rows are matched by what they measured: pattern (and file), method, size.
using RowKey = std::tuple<std::string, std::string, std::string, int, int>;
RowKey key_of(const ResultRow& r) { return {r.pattern, r.scene_file, r.method, r.width, r.height}; }

// The verdict on one figure, or nullopt when it did not change. `bound` is the largest new
// value that passes (lower is better) or, with `higher_is_better`, the smallest.
std::optional<GateVerdict> judge(double old_value, double new_value, double bound,
                                 bool higher_is_better = false) {
    const bool old_nan = std::isnan(old_value), new_nan = std::isnan(new_value);
    if (old_nan && new_nan) return std::nullopt;
    if (old_nan) return GateVerdict::kAppeared;
    if (old_value == new_value) return std::nullopt;
    // Written so that a NaN new value is worse: the comparison is false.
    if (higher_is_better) {
        if (!(new_value >= bound)) return GateVerdict::kWorse;
        return new_value < old_value ? GateVerdict::kWithin : GateVerdict::kBetter;
    }
    if (!(new_value <= bound)) return GateVerdict::kWorse;
    return new_value > old_value ? GateVerdict::kWithin : GateVerdict::kBetter;
}

}  // namespace

GateTolerancePair tolerance_for(const MetricDef& def, const GateTolerance& tolerance) {
    return {tolerance.rel.value_or(def.tolerance.rel), tolerance.abs.value_or(def.tolerance.abs)};
}

std::vector<MetricId> gated_metrics() {
    std::vector<MetricId> ids;
    const MetricRegistry& registry = metric_registry();
    for (MetricId id = 0; id < registry.size(); ++id) {
        if (registry[id].gate == Gate::kYes) ids.push_back(id);
    }
    return ids;
}

bool is_external_row(const ResultRow& row) { return row.method_id.rfind("external:", 0) == 0; }

const char* verdict_name(GateVerdict verdict) {
    switch (verdict) {
        case GateVerdict::kWorse:
            return "WORSE";
        case GateVerdict::kWithin:
            return "within";
        case GateVerdict::kBetter:
            return "better";
        case GateVerdict::kAppeared:
            return "appeared";
        case GateVerdict::kMissing:
            return "MISSING";
    }
    return "?";
}

void resolve_specs_again(std::vector<ResultRow>& rows) {
    for (ResultRow& r : rows) {
        try {
            r.method = make_method(r.method).spec;
        } catch (const InputError&) {
        }
        if (!r.scene_file.empty()) continue;
        try {
            r.pattern = resolve_pattern(r.pattern).spec;
        } catch (const InputError&) {
        }
    }
}

std::vector<CompareOptions> rerun_options(const std::vector<ResultRow>& baseline,
                                          const std::vector<SceneFileInput>& scene_files,
                                          const CompareOptions& base) {
    // Built-in patterns by size, in the baseline's order; scene files in one run of their own.
    std::map<std::pair<int, int>, CompareOptions> by_size;
    std::vector<std::pair<int, int>> size_order;
    CompareOptions files = base;
    files.pattern_specs.clear();
    files.method_specs.clear();
    files.scene_files.clear();
    for (const ResultRow& r : baseline) {
        if (is_external_row(r)) continue;  // gate_rows counts them
        if (!resolves(r)) continue;        // its row will be missing from the run
        CompareOptions* run = &files;
        if (r.scene_file.empty()) {
            const std::pair<int, int> size{r.width, r.height};
            if (!by_size.count(size)) {
                CompareOptions o = base;
                o.width = r.width;
                o.height = r.height;
                o.pattern_specs.clear();
                o.method_specs.clear();
                o.scene_files.clear();
                by_size.emplace(size, std::move(o));
                size_order.push_back(size);
            }
            run = &by_size.at(size);
            add_unique(run->pattern_specs, r.pattern);
        } else {
            const auto file =
                std::find_if(scene_files.begin(), scene_files.end(),
                             [&](const SceneFileInput& f) { return f.path == r.scene_file; });
            if (file == scene_files.end()) {
                throw InputError(fmt::format("baseline row {} / {}: scene file {} was not given",
                                             r.pattern, r.method, r.scene_file));
            }
            if (file->scene.width != r.width || file->scene.height != r.height) {
                throw InputError(fmt::format(
                    "{}: the scene is {}x{} but the baseline's rows of it are {}x{} (the file "
                    "changed since the baseline was made)",
                    r.scene_file, file->scene.width, file->scene.height, r.width, r.height));
            }
            const bool listed =
                std::any_of(run->scene_files.begin(), run->scene_files.end(),
                            [&](const SceneFileInput& f) { return f.path == r.scene_file; });
            if (!listed) run->scene_files.push_back(*file);
        }
        // A sweep point is made by the sweep of its method as asked for; a default row names it.
        if (r.sweep_point) {
            run->sweep = true;
        } else {
            add_unique(run->method_specs, r.method);
        }
    }
    std::vector<CompareOptions> runs;
    for (const auto& size : size_order) runs.push_back(std::move(by_size.at(size)));
    if (!files.scene_files.empty()) runs.push_back(std::move(files));
    return runs;
}

GateResult gate_rows(const std::vector<ResultRow>& baseline, const std::vector<ResultRow>& current,
                     const GateTolerance& tolerance) {
    std::map<RowKey, const ResultRow*> now;
    for (const ResultRow& r : current) now.emplace(key_of(r), &r);
    GateResult result;
    const std::vector<MetricId> gated = gated_metrics();
    double log_ratio_sum = 0.0;
    long long timed = 0;
    for (const ResultRow& old_row : baseline) {
        if (is_external_row(old_row)) {
            ++result.external_rows;
            continue;
        }
        GateChange change{old_row.pattern, old_row.pattern_id, old_row.method};
        const auto found = now.find(key_of(old_row));
        if (found == now.end()) {
            change.verdict = GateVerdict::kMissing;
            result.changes.push_back(change);
            ++result.failures;
            continue;
        }
        const ResultRow& new_row = *found->second;
        ++result.rows_checked;
        for (const MetricId id : gated) {
            const MetricDef& def = metric_registry()[id];
            const double old_value = old_row[id], new_value = new_row[id];
            const GateTolerancePair t = tolerance_for(def, tolerance);
            const bool higher = def.better == Better::kHigher;
            const double bound =
                higher ? old_value * (1.0 - t.rel) - t.abs : old_value * (1.0 + t.rel) + t.abs;
            ++result.figures_checked;
            const std::optional<GateVerdict> verdict = judge(old_value, new_value, bound, higher);
            if (!verdict) continue;
            change.figure = def.key;
            change.old_value = old_value;
            change.new_value = new_value;
            change.bound = bound;
            change.verdict = *verdict;
            result.changes.push_back(change);
            result.failures += *verdict == GateVerdict::kWorse;
        }
        const double old_ns = old_row[metric::kTimeMedianNs],
                     new_ns = new_row[metric::kTimeMedianNs];
        if (!(old_ns > 0.0 && new_ns > 0.0)) continue;
        const double ratio = new_ns / old_ns;
        log_ratio_sum += std::log(ratio);
        ++timed;
        if (!(ratio <= result.time_ratio_max)) {  // also replaces the initial NaN
            result.time_ratio_max = ratio;
            result.time_ratio_max_row = old_row.pattern_id + " / " + old_row.method;
        }
        if (!tolerance.time_rel) continue;
        const double bound = old_ns * (1.0 + *tolerance.time_rel);
        const std::optional<GateVerdict> verdict = judge(old_ns, new_ns, bound);
        if (!verdict || *verdict != GateVerdict::kWorse) continue;
        change.figure = metric_registry()[metric::kTimeMedianNs].key;
        change.old_value = old_ns;
        change.new_value = new_ns;
        change.bound = bound;
        change.verdict = *verdict;
        result.changes.push_back(change);
        ++result.failures;
    }
    if (timed > 0) result.time_ratio_geomean = std::exp(log_ratio_sum / timed);
    return result;
}

}  // namespace aabench
