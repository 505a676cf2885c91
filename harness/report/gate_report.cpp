// The regression gate's text (harness/report/gate_report.h).
#include "harness/report/gate_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace aabench {
namespace {

std::string num(double v) {
    if (std::isnan(v)) return "-";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return fmt::format("{:.6g}", v);
}

// The rule, with its tolerance when every gated metric has the same one (the built-ins do),
// else a pointer to the registry's.
std::string tolerance_text(const GateTolerance& tolerance) {
    std::optional<GateTolerancePair> common;
    bool same = true;
    for (const MetricId id : gated_metrics()) {
        const GateTolerancePair t = tolerance_for(metric_registry()[id], tolerance);
        if (common && (common->rel != t.rel || common->abs != t.abs)) same = false;
        if (!common) common = t;
    }
    if (!common || !same) {
        return "worse when new > old * (1 + rel) + abs, each metric's rel and abs as "
               "docs/metrics.md lists them";
    }
    return fmt::format("worse when new > old * (1 + {}) + {}", common->rel, common->abs);
}

}  // namespace

std::string format_gate(const GateResult& result, const GateTolerance& tolerance,
                        const std::string& baseline_path, bool list_moved) {
    std::string out = fmt::format("check against {}: {} row{} ({})\n", baseline_path,
                                  result.rows_checked, result.rows_checked == 1 ? "" : "s",
                                  tolerance_text(tolerance));
    // A pattern is named by its id unless two specs of one id changed (then by the spec).
    std::map<std::string, std::string> spec_of_id;
    bool ambiguous = false;  // over every change: the names stay the same with or without them
    for (const GateChange& c : result.changes) {
        const auto [it, added] = spec_of_id.emplace(c.pattern_id, c.pattern);
        ambiguous = ambiguous || (!added && it->second != c.pattern);
    }
    auto pattern_name = [&](const GateChange& c) { return ambiguous ? c.pattern : c.pattern_id; };
    // Figures the baseline has no value for (a column added since) would fill the table with
    // rows of "-": they are counted per figure below it instead.
    std::vector<std::pair<std::string, long long>> appeared;
    std::vector<const GateChange*> listed;
    long long better = 0, worse_within = 0, beyond = 0, missing = 0, appeared_total = 0;
    long long past_printed_digits = 0;  // moved, but old and new print the same
    for (const GateChange& c : result.changes) {
        const bool time = c.figure == metric_registry()[metric::kTimeMedianNs].key;
        switch (c.verdict) {
            case GateVerdict::kWorse:
                beyond += !time;
                listed.push_back(&c);
                break;
            case GateVerdict::kMissing:
                ++missing;
                listed.push_back(&c);
                break;
            case GateVerdict::kBetter:
            case GateVerdict::kWithin: {
                (c.verdict == GateVerdict::kBetter ? better : worse_within) += 1;
                const bool same_print = num(c.old_value) == num(c.new_value);
                past_printed_digits += same_print;
                if (list_moved && !same_print) listed.push_back(&c);
                break;
            }
            case GateVerdict::kAppeared: {
                ++appeared_total;
                const auto it = std::find_if(appeared.begin(), appeared.end(),
                                             [&](const auto& a) { return a.first == c.figure; });
                if (it == appeared.end()) {
                    appeared.emplace_back(c.figure, 1);
                } else {
                    ++it->second;
                }
                break;
            }
        }
    }
    const long long moved = better + worse_within;
    const long long unchanged = result.figures_checked - moved - beyond - appeared_total;
    out += fmt::format("  {} gated figure{} compared: {} unchanged, {} moved within the tolerance",
                       result.figures_checked, result.figures_checked == 1 ? "" : "s", unchanged,
                       moved);
    if (moved > 0) {
        out += fmt::format(" ({} better, {} worse", better, worse_within);
        if (past_printed_digits > 0) {
            out += fmt::format("; {} of them only past the 6th significant digit",
                               past_printed_digits);
        }
        out += ")";
    }
    out += fmt::format(", {} beyond it\n", beyond);
    std::size_t pattern_width = 7, method_width = 6;
    for (const GateChange* c : listed) {
        pattern_width = std::max(pattern_width, pattern_name(*c).size());
        method_width = std::max(method_width, c->method.size());
    }
    if (listed.empty()) {
        out += moved > 0 && !list_moved
                   ? "  nothing to list (--list-moved lists the figures within the tolerance)\n"
                   : "  nothing to list\n";
    } else {
        out += fmt::format("  {:<{}}  {:<{}}  {:<14} {:>12} {:>12} {:>12}  {}\n", "pattern",
                           pattern_width, "method", method_width, "figure", "old", "new", "bound",
                           "verdict");
    }
    for (const GateChange* change : listed) {
        const GateChange& c = *change;
        if (c.verdict == GateVerdict::kMissing) {
            out += fmt::format("  {:<{}}  {:<{}}  {:<14} {:>12} {:>12} {:>12}  {}\n",
                               pattern_name(c), pattern_width, c.method, method_width, "(the row)",
                               "", "not run", "", verdict_name(c.verdict));
            continue;
        }
        out += fmt::format("  {:<{}}  {:<{}}  {:<14} {:>12} {:>12} {:>12}  {}\n", pattern_name(c),
                           pattern_width, c.method, method_width, c.figure, num(c.old_value),
                           num(c.new_value), num(c.bound), verdict_name(c.verdict));
    }
    if (!appeared.empty()) {
        out += "  measured now, not in the baseline (not gated):";
        for (const auto& [figure, rows] : appeared) {
            out += fmt::format(" {} in {} row{}{}", figure, rows, rows == 1 ? "" : "s",
                               figure == appeared.back().first ? "" : ",");
        }
        out += "\n";
    }
    if (result.external_rows > 0) {
        out += fmt::format(
            "  {} row{} of external renderers not re-run (the baseline does not "
            "hold their commands; run compare --external again)\n",
            result.external_rows, result.external_rows == 1 ? "" : "s");
    }
    if (std::isnan(result.time_ratio_geomean)) {
        out += "timing: no row has both times\n";
    } else {
        out += fmt::format(
            "timing: new / old median time, geometric mean {:.2f}x, largest {:.2f}x ({}); {}\n",
            result.time_ratio_geomean, result.time_ratio_max, result.time_ratio_max_row,
            tolerance.time_rel
                ? fmt::format("gated: worse when new > old * (1 + {})", *tolerance.time_rel)
                : std::string("reported, not gated (--time-tolerance REL gates it)"));
    }
    const long long worse = result.failures - missing;  // gated figures and timings
    if (result.passed()) {
        out += "PASS: no gated figure is worse beyond the tolerance\n";
    } else {
        out += fmt::format(
            "FAIL: {} figure{} worse beyond the tolerance, {} baseline row{} not "
            "run\n",
            worse, worse == 1 ? "" : "s", missing, missing == 1 ? "" : "s");
    }
    return out;
}

}  // namespace aabench
