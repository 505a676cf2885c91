// Text and JSON of one scored image (harness/report/score_report.h).
#include "harness/report/score_report.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>

#include "harness/report/report.h"

namespace aabench {
namespace {

// The identity fields `score` reports before the metrics.
const std::vector<std::string>& score_identity_fields() {
    static const std::vector<std::string> fields = {
        "pattern", "pattern_id", "scene_file", "width", "height", "edges", "reference_filter"};
    return fields;
}

// What a figure is measured against, or where: the row's parts that have no line of their
// own. Metrics not listed here have no note.
std::string note(MetricId id, const ResultRow& r) {
    using namespace metric;
    switch (id) {
        case kBoxRmse:
            return "against the exact box reference";
        case kBoxMaxAbs:
            return fmt::format("at pixel ({}, {})", r[kBoxMaxX], r[kBoxMaxY]);
        case kBoxBias:
            return "> 0: too bright";
        case kDropout:
            return fmt::format("{} of {} covered pixels rendered empty", r[kDropoutPixels],
                               r[kDropoutCandidates]);
        case kOwnRmse:
            return "against the exact " + r.reference_filter + " reference";
        case kEdgeRmse:
            return "within 1.5 px of an edge, against " + r.reference_filter;
        case kAliasTotalDb:
            return "error spectrum energy / reference energy";
        case kAliasLowDb:
            return "the same below half of Nyquist (moire)";
        case kSsim:
        case kFlip:
        case kSrgbRmse:
            return "against the box reference";
        case kSeamsMax:
            return "on edges shared by visible faces";
        case kNonfinite:
            return "NaN or infinite pixels";
        case kWorldMs:
            return "the world stages of the 3-D scene, one run";
        default:
            return "";
    }
}

}  // namespace

std::vector<std::string> score_fields() {
    std::vector<std::string> fields = score_identity_fields();
    const MetricRegistry& registry = metric_registry();
    for (MetricId id = 0; id < registry.size(); ++id) {
        if (registry[id].shown_in & kInScore) fields.push_back(registry[id].key);
    }
    return fields;
}

nlohmann::ordered_json score_figures(const ResultRow& row) {
    // Every field's name and encoding come from the results columns (report.h).
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    for (const std::string& field : score_fields()) out[field] = column_value(row, field);
    return out;
}

std::string score_json(const ResultRow& row, const std::string& image_path) {
    nlohmann::ordered_json out;
    out["image"] = image_path;
    const nlohmann::ordered_json figures = score_figures(row);  // outlives the loop's proxy
    for (const auto& [field, value] : figures.items()) out[field] = value;
    return out.dump(2) + "\n";
}

std::string format_score(const ResultRow& r, const std::string& image_path) {
    std::string out =
        fmt::format("{} scored against {}  ({}x{}, {} edges{})\n", image_path, r.pattern, r.width,
                    r.height, r.edges, r.scene_file.empty() ? "" : ", scene file " + r.scene_file);
    const MetricRegistry& registry = metric_registry();
    for (MetricId id = 0; id < registry.size(); ++id) {
        const MetricDef& def = registry[id];
        if (!(def.shown_in & kInScore)) continue;
        // A metric without a definition of its own is a part of another (the worst pixel's
        // position, dropout's counts): in that one's note.
        if (def.definition.empty()) continue;
        // A figure of 3-D scenes only (seams, world stages) is left out for a 2-D one.
        if (!(def.applies & kApplies2d) && std::isnan(r[id])) continue;
        const double v = r[id];
        std::string value;
        if (std::isnan(v)) {
            value = "-";
        } else if (def.shown == Shown::kPercent) {
            value = fmt::format("{:.2f}%", 100.0 * v);
        } else if (def.integer) {
            value = fmt::format("{:.0f}", v);
        } else {
            value = fmt::format("{:.6g}", v);
        }
        out += fmt::format("  {:<15} {:>12}  {}\n", def.key, value, note(id, r));
    }
    return out;
}

}  // namespace aabench
