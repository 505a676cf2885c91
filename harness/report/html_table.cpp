// The HTML report's summary tables (harness/report/html_parts.h): one per pattern, a column per
// figure, each cell's exact value kept as its sort key.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

#include "harness/report/html_parts.h"
#include "harness/report/svg_plot.h"

namespace aabench::html_parts {
namespace {

using Json = nlohmann::ordered_json;

// Shortest text that reads back as the same double: how the table stores its sort keys, so a
// number on the page can be traced to the row bit for bit.
std::string exact_number(double value) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "Infinity" : "-Infinity";  // as JavaScript reads
    return fmt::format("{}", value);
}

std::string shown_number(double value, const char* format) {
    // NaN in a row means "not measured here" (symptoms of sweep points, popping without thin
    // objects): a dash reads as that, "NaN" reads as a failure.
    if (std::isnan(value)) return "&ndash;";
    if (std::isinf(value)) return value > 0 ? "&infin;" : "&minus;&infin;";
    return fmt::format(fmt::runtime(format), value);
}

// How a core column is shown; the sort key is always the exact value.
enum class Shown { kGeneral, kSigned, kPercent, kMsFromNs };

struct CoreColumn {
    const char* key;  // in compare_json()'s rows
    const char* header;
    Shown shown;
};

// The summary columns, in this order; every other numeric column of the rows that is not
// listed in kHiddenColumns follows (symptom figures as they are added), named by its key.
constexpr std::array<CoreColumn, 7> kCoreColumns = {{
    {"box_rmse", "box_rmse", Shown::kGeneral},
    {"own_rmse", "own_rmse", Shown::kGeneral},
    {"box_max_abs", "max_abs", Shown::kGeneral},
    {"box_bias", "bias", Shown::kSigned},
    {"dropout", "dropout", Shown::kPercent},
    {"time_median_ns", "time (ms)", Shown::kMsFromNs},
    {"mpixel_per_s", "Mpixel/s", Shown::kGeneral},
}};
// Numeric columns left to results.csv: identifiers, sizes, parts of a shown figure.
const std::set<std::string> kHiddenColumns = {
    "task",        "cost_value",     "width",
    "height",      "edges",          "box_max_x",
    "box_max_y",   "dropout_pixels", "dropout_candidates",
    "own_max_abs", "own_bias",       "time_min_ns",
    "time_max_ns", "time_runs",      "medges_per_s",
};

std::string shown(double value, Shown how) {
    switch (how) {
        case Shown::kSigned:
            return shown_number(value, "{:+.3g}");
        case Shown::kPercent:
            return std::isnan(value) ? "NaN" : fmt::format("{:.2f}%", 100 * value);
        case Shown::kMsFromNs:
            return shown_number(value * 1e-6, "{:.4g}");
        case Shown::kGeneral:
            break;
    }
    return shown_number(value, "{:.4g}");
}

// A spec as cell text that may wrap after each comma: the method column stays in view while the
// table scrolls, so it should be no wider than the spec's longest parameter run. <wbr> adds no
// text, so the column still sorts by the spec.
std::string breakable_spec(const std::string& spec) {
    std::string out;
    for (char c : xml_escape(spec)) {
        out += c;
        if (c == ',') out += "<wbr>";
    }
    return out;
}

double json_number(const Json& value) {
    return value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// The columns after the core ones: numeric in some row of this pattern, neither core nor
// hidden, in order of first appearance.
std::vector<std::string> extra_columns(const Json& json_rows,
                                       const std::vector<std::size_t>& members) {
    std::vector<std::string> extra;
    std::set<std::string> core_keys;
    for (const CoreColumn& c : kCoreColumns) core_keys.insert(c.key);
    for (std::size_t r : members) {
        for (const auto& [key, value] : json_rows[r].items()) {
            if (core_keys.count(key) || kHiddenColumns.count(key) || value.is_boolean()) continue;
            if (key.rfind("stage_", 0) == 0) continue;  // in the pattern's stage table instead
            if (value.is_number() || value.is_null()) {
                // null is a NaN number in a numeric column; a string column is never null.
                if (std::find(extra.begin(), extra.end(), key) == extra.end()) {
                    extra.push_back(key);
                }
            }
        }
    }
    // "nonfinite" is noise while it is 0 everywhere, and an alarm when it is not.
    std::erase_if(extra, [&](const std::string& key) {
        if (key != "nonfinite") return false;
        return std::all_of(members.begin(), members.end(),
                           [&](std::size_t r) { return json_number(json_rows[r][key]) == 0.0; });
    });
    return extra;
}

}  // namespace

std::string results_table(const ReportData& data, const Json& json_rows, const Json& definitions,
                          const std::vector<std::size_t>& members) {
    const std::vector<std::string> extra = extra_columns(json_rows, members);
    auto definition = [&](const std::string& key) {
        return definitions.contains(key) && definitions[key].is_string()
                   ? xml_escape(definitions[key].get<std::string>())
                   : std::string();
    };
    // The box scrolls the table sideways (and, when long, down) inside the page; the page's
    // style keeps the method column and the header row in view while it does.
    std::string html =
        "<div class=\"table-box\"><table class=\"results\"><thead><tr><th class=\"m\">method"
        "</th>";
    for (const CoreColumn& c : kCoreColumns) {
        html += fmt::format("<th title=\"{}\">{}</th>", definition(c.key), c.header);
    }
    for (const std::string& key : extra) {
        html += fmt::format("<th title=\"{}\">{}</th>", definition(key), xml_escape(key));
    }
    html += "</tr></thead>\n<tbody>\n";

    // Ordered by box_rmse, NaN last; ties keep run order.
    std::vector<std::size_t> order = members;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const double x = data.rows[a].box.rmse, y = data.rows[b].box.rmse;
        if (std::isnan(x) || std::isnan(y)) return !std::isnan(x) && std::isnan(y);
        return x < y;
    });
    for (std::size_t r : order) {
        const ResultRow& row = data.rows[r];
        html += fmt::format("<tr class=\"{}\"><td class=\"m\" title=\"own reference: {}\">{}</td>",
                            row.sweep_point ? "sweep" : "default", xml_escape(row.reference_filter),
                            breakable_spec(row.method));
        for (const CoreColumn& c : kCoreColumns) {
            const double value = json_number(json_rows[r][c.key]);
            std::string title;
            if (std::string(c.key) == "box_max_abs") {
                title = fmt::format(" title=\"at ({}, {})\"", row.box.max_x, row.box.max_y);
            } else if (std::string(c.key) == "time_median_ns") {
                title = fmt::format(" title=\"min {:.4g} ms, max {:.4g} ms, {} runs, {}\"",
                                    row.time.min_ns * 1e-6, row.time.max_ns * 1e-6, row.time.runs,
                                    xml_escape(row.time_source));
            } else if (std::string(c.key) == "dropout") {
                title = fmt::format(" title=\"{} of {} pixels\"", row.box.dropout_pixels,
                                    row.box.dropout_candidates);
            }
            html += fmt::format("<td data-v=\"{}\"{}>{}</td>", exact_number(value), title,
                                shown(value, c.shown));
        }
        for (const std::string& key : extra) {
            const double value = json_rows[r].contains(key)
                                     ? json_number(json_rows[r][key])
                                     : std::numeric_limits<double>::quiet_NaN();
            html += fmt::format("<td data-v=\"{}\">{}</td>", exact_number(value),
                                shown(value, Shown::kGeneral));
        }
        html += "</tr>\n";
    }
    html += "</tbody></table></div>\n";
    return html;
}

std::string stage_table(const ResultRow& row) {
    if (std::isnan(row.world_ms)) return {};
    std::string html =
        "<div class=\"table-box\"><table class=\"stages\"><thead><tr><th class=\"m\">stage"
        "</th><th>time (ms)</th><th>heap bytes</th></tr></thead>\n<tbody>\n";
    for (int k = 0; k < kStageCount; ++k) {
        const bool ran = !std::isnan(row.stage_ms[k]);
        html += fmt::format("<tr><td class=\"m\">{}</td><td>{}</td><td>{}</td></tr>\n",
                            stage_name(static_cast<Stage>(k)),
                            ran ? fmt::format("{:.3f}", row.stage_ms[k]) : "out",
                            ran ? fmt::format("{:.0f}", row.stage_bytes[k]) : "&ndash;");
    }
    html += fmt::format(
        "<tr><td class=\"m\"><b>all</b></td><td><b>{:.3f}</b></td><td></td></tr>\n", row.world_ms);
    return html + "</tbody></table></div>\n";
}

}  // namespace aabench::html_parts
