// The HTML report's summary tables (harness/report/html_parts.h): one per pattern, a column per
// figure of the metric registry (harness/measure/metric_registry.h), each cell's exact value
// kept as its sort key.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>

#include "harness/report/html_parts.h"
#include "harness/report/svg_plot.h"

namespace aabench::html_parts {
namespace {

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

std::string shown(double value, Shown how) {
    switch (how) {
        case Shown::kSigned:
            return shown_number(value, "{:+.3g}");
        case Shown::kPercent:
            return std::isnan(value) ? "NaN" : fmt::format("{:.2f}%", 100 * value);
        case Shown::kMsFromNs:
            return shown_number(value * 1e-6, "{:.4g}");
        case Shown::kInteger:
            return shown_number(value, "{:.0f}");
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

// The registry's metrics this pattern's table shows, in registry order: the ones some row of
// the pattern has a value for (the leading ones too: a column empty for the whole table says
// nothing), and the alarms (nonfinite) where some row is not 0. The world stages have their own
// table.
std::vector<MetricId> shown_columns(const ReportData& data,
                                    const std::vector<std::size_t>& members) {
    const MetricRegistry& registry = metric_registry();
    std::vector<MetricId> ids;
    for (MetricId id = 0; id < registry.size(); ++id) {
        const unsigned where = registry[id].shown_in;
        const auto any = [&](auto predicate) {
            return std::any_of(members.begin(), members.end(),
                               [&](std::size_t r) { return predicate(data.rows[r][id]); });
        };
        if (((where & (kInHtml | kInHtmlAlways)) && any([](double v) { return !std::isnan(v); })) ||
            ((where & kInHtmlWhenNonzero) &&
             any([](double v) { return !std::isnan(v) && v != 0.0; }))) {
            ids.push_back(id);
        }
    }
    return ids;
}

}  // namespace

std::vector<std::size_t> drawn_rows(const ReportData& data,
                                    const std::vector<std::size_t>& members) {
    std::vector<std::size_t> out;
    for (std::size_t r : members) {
        if (data.rows[r].not_applicable.empty()) out.push_back(r);
    }
    return out;
}

std::string cannot_draw_line(const ReportData& data, const std::vector<std::size_t>& members) {
    // Methods with the same reason together: "aa-circle, wu-circle (draws circles only)".
    std::vector<std::pair<std::string, std::vector<std::string>>> by_reason;
    for (std::size_t r : members) {
        const ResultRow& row = data.rows[r];
        if (row.not_applicable.empty()) continue;
        auto it = std::find_if(by_reason.begin(), by_reason.end(),
                               [&](const auto& g) { return g.first == row.not_applicable; });
        if (it == by_reason.end()) {
            by_reason.push_back({row.not_applicable, {}});
            it = by_reason.end() - 1;
        }
        it->second.push_back("<code>" + xml_escape(row.method) + "</code>");
    }
    if (by_reason.empty()) return {};
    std::vector<std::string> parts;
    for (const auto& [reason, methods] : by_reason) {
        parts.push_back(fmt::format("{} ({})", fmt::join(methods, ", "), xml_escape(reason)));
    }
    return fmt::format(
        "<p class=\"small cannot-draw\">Left out of the table and the plot, as they cannot draw "
        "this pattern: {}.</p>\n",
        fmt::join(parts, "; "));
}

std::string results_table(const ReportData& data, const std::vector<std::size_t>& all_members) {
    const MetricRegistry& registry = metric_registry();
    const std::vector<std::size_t> members = drawn_rows(data, all_members);
    const std::vector<MetricId> columns = shown_columns(data, members);
    // The box scrolls the table sideways (and, when long, down) inside the page; the page's
    // style keeps the method column and the header row in view while it does.
    std::string html =
        "<div class=\"table-box\"><table class=\"results\"><thead><tr><th class=\"m\">method"
        "</th>";
    for (MetricId id : columns) {
        html += fmt::format("<th title=\"{}\">{}</th>", xml_escape(registry[id].definition),
                            xml_escape(registry[id].header));
    }
    html += "</tr></thead>\n<tbody>\n";

    // Ordered by box_rmse, NaN last; ties keep run order.
    std::vector<std::size_t> order = members;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        const double x = data.rows[a][metric::kBoxRmse], y = data.rows[b][metric::kBoxRmse];
        if (std::isnan(x) || std::isnan(y)) return !std::isnan(x) && std::isnan(y);
        return x < y;
    });
    for (std::size_t r : order) {
        const ResultRow& row = data.rows[r];
        html += fmt::format("<tr class=\"{}\"><td class=\"m\" title=\"own reference: {}\">{}</td>",
                            row.sweep_point ? "sweep" : "default", xml_escape(row.reference_filter),
                            breakable_spec(row.method));
        for (MetricId id : columns) {
            const double value = row[id];
            // Hover text with the parts of a figure that have no column of their own.
            std::string title;
            if (id == metric::kBoxMaxAbs) {
                title = fmt::format(" title=\"at ({}, {})\"", row[metric::kBoxMaxX],
                                    row[metric::kBoxMaxY]);
            } else if (id == metric::kTimeMedianNs) {
                title = fmt::format(" title=\"min {:.4g} ms, max {:.4g} ms, {} runs, {}\"",
                                    row[metric::kTimeMinNs] * 1e-6, row[metric::kTimeMaxNs] * 1e-6,
                                    row.time_runs, xml_escape(row.time_source));
            } else if (id == metric::kDropout) {
                title = fmt::format(" title=\"{} of {} pixels\"", row[metric::kDropoutPixels],
                                    row[metric::kDropoutCandidates]);
            }
            html += fmt::format("<td data-v=\"{}\"{}>{}</td>", exact_number(value), title,
                                shown(value, registry[id].shown));
        }
        html += "</tr>\n";
    }
    html += "</tbody></table></div>\n";
    return html;
}

std::string stage_table(const ResultRow& row) {
    if (std::isnan(row[metric::kWorldMs])) return {};
    std::string html =
        "<div class=\"table-box\"><table class=\"stages\"><thead><tr><th class=\"m\">stage"
        "</th><th>time (ms)</th><th>heap bytes</th></tr></thead>\n<tbody>\n";
    for (int k = 0; k < kStageCount; ++k) {
        const double ms = row[stage_ms_metric(k)], bytes = row[stage_bytes_metric(k)];
        const bool ran = !std::isnan(ms);
        html +=
            fmt::format("<tr><td class=\"m\">{}</td><td>{}</td><td>{}</td></tr>\n",
                        stage_name(static_cast<Stage>(k)), ran ? fmt::format("{:.3f}", ms) : "out",
                        ran ? fmt::format("{:.0f}", bytes) : "&ndash;");
    }
    html += fmt::format("<tr><td class=\"m\"><b>all</b></td><td><b>{:.3f}</b></td><td></td></tr>\n",
                        row[metric::kWorldMs]);
    return html + "</tbody></table></div>\n";
}

}  // namespace aabench::html_parts
