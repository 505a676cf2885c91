// The report's summary, the first thing a reader choosing a method sees (html_parts.h;
// docs/report.md, "Summary"): a method-family x pattern matrix of the default parameters, each
// cell the box error, the own-filter error and the time, coloured per pattern, the best of each
// pattern marked, sweep points folded under their family; then a paragraph, generated from the
// same rows, saying which method to take for what.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>

#include "harness/report/html_parts.h"
#include "harness/report/svg_plot.h"

namespace aabench::html_parts {
namespace {

// The figures of a cell, top to bottom.
struct Figure {
    MetricId id;
    const char* name;  // the legend's
};
constexpr Figure kFigures[] = {
    {metric::kBoxRmse, "box rmse"},
    {metric::kOwnRmse, "own-filter rmse (where the filter is not the box)"},
    {metric::kTimeMedianNs, "time in ms (median of one render)"}};
constexpr int kFigureCount = static_cast<int>(std::size(kFigures));

// Colours run over log10 of a pattern's figures. Errors below half an 8-bit step (1/510) are
// the same on any display, so they all take the best colour: otherwise `exact`'s 1e-8 would
// stretch the scale over eight decades and leave every other method the same red.
constexpr double kColourFloorError = 1.0 / 510.0;
// The paragraph's error budget: a hundredth of the value range (about 2.5 steps of 8 bits), a
// round figure the paragraph states, so a reader can judge it. Its time budget is the median of
// the pattern's default times (median_default_time).
constexpr double kErrorBudget = 0.01;

bool drawn(const ResultRow& row) { return row.not_applicable.empty(); }

// Whether a cell shows figure `id` of `row`: the own-filter error only where the method's filter
// is not the box (where it is, the own error is the box error, a second copy of the line above).
bool shows(const ResultRow& row, MetricId id) {
    return drawn(row) && (id != metric::kOwnRmse ||
                          (!row.reference_filter.empty() && row.reference_filter != "box"));
}

// Where a row's figure lies on its pattern's scale, 0 best .. 1 worst; nullopt without a
// value. Log scale between the pattern's smallest and largest (errors floored as above).
struct Scale {
    double lo = 0.0;
    double hi = 0.0;
    bool any = false;
    double best = 0.0;  // the smallest value itself (the marked one)
};

double scaled_value(MetricId id, double v) {
    return id == metric::kTimeMedianNs ? v : std::max(v, kColourFloorError);
}

// A figure that has a place on the scale: a time > 0, an error >= 0 (exact's 0 is the best).
bool on_scale(MetricId id, double v) {
    return std::isfinite(v) && (id == metric::kTimeMedianNs ? v > 0.0 : v >= 0.0);
}

std::optional<double> position(const Scale& s, MetricId id, double v) {
    if (!s.any || !on_scale(id, v)) return std::nullopt;
    const double l = std::log10(scaled_value(id, v));
    return s.hi > s.lo ? std::clamp((l - s.lo) / (s.hi - s.lo), 0.0, 1.0) : 0.0;
}

// Green (best) through yellow to red (worst), light enough for black text.
std::string colour(double t) { return fmt::format("hsl({:.0f},65%,84%)", 120.0 * (1.0 - t)); }

// Two significant digits: the colours carry the comparison, the tables below the exact figures.
// Times without an exponent (14, not 1.4e+01); errors below the plots' floor, float32 rounding
// of the exact answer, as "<1e-07".
std::string shown_figure(MetricId id, double v) {
    if (id == metric::kTimeMedianNs) {
        const double ms = v * 1e-6;
        return ms < 10.0 ? fmt::format("{:.2g}", ms) : fmt::format("{:.0f}", ms);
    }
    if (v < kPlotErrorFloor) return fmt::format("&lt;{:.0e}", kPlotErrorFloor);
    return fmt::format("{:.2g}", v);
}

// One pattern's column: its rows by family, the default row and the sweep points.
struct Column {
    const Section* section = nullptr;
    std::map<std::string, std::size_t> default_row;  // family -> row index
    std::array<Scale, kFigureCount> scales{};
};

// A method family: its id and its rows' specs (for the hover text).
struct Family {
    std::string id;
    std::string default_spec;
    std::vector<std::string> sweep_specs;  // in run order, once each
};

std::vector<Family> families(const ReportData& data) {
    std::vector<Family> out;
    for (const ResultRow& row : data.rows) {
        auto it = std::find_if(out.begin(), out.end(),
                               [&](const Family& f) { return f.id == row.method_id; });
        if (it == out.end()) {
            out.push_back({row.method_id, {}, {}});
            it = out.end() - 1;
        }
        if (!row.sweep_point) {
            if (it->default_spec.empty()) it->default_spec = row.method;
        } else if (std::find(it->sweep_specs.begin(), it->sweep_specs.end(), row.method) ==
                   it->sweep_specs.end()) {
            it->sweep_specs.push_back(row.method);
        }
    }
    return out;
}

Column make_column(const ReportData& data, const Section& s) {
    Column c;
    c.section = &s;
    for (std::size_t r : s.rows) {
        const ResultRow& row = data.rows[r];
        if (!row.sweep_point && !c.default_row.count(row.method_id))
            c.default_row[row.method_id] = r;
    }
    for (int f = 0; f < kFigureCount; ++f) {
        Scale& scale = c.scales[f];
        for (const auto& [family, r] : c.default_row) {
            const ResultRow& row = data.rows[r];
            const double v = row[kFigures[f].id];
            if (!shows(row, kFigures[f].id) || !on_scale(kFigures[f].id, v)) continue;
            const double l = std::log10(scaled_value(kFigures[f].id, v));
            scale.lo = scale.any ? std::min(scale.lo, l) : l;
            scale.hi = scale.any ? std::max(scale.hi, l) : l;
            scale.best = scale.any ? std::min(scale.best, v) : v;
            scale.any = true;
        }
    }
    return c;
}

// The figures some default row of some pattern has: the others' lines are left out.
std::vector<int> shown_figures(const ReportData& data, const std::vector<Column>& columns) {
    std::vector<int> out;
    for (int f = 0; f < kFigureCount; ++f) {
        bool any = false;
        for (const Column& c : columns) {
            for (const auto& [family, r] : c.default_row) {
                const ResultRow& row = data.rows[r];
                any = any || (shows(row, kFigures[f].id) && !std::isnan(row[kFigures[f].id]));
            }
        }
        if (any) out.push_back(f);
    }
    return out;
}

// The cell of one row: its figures stacked, each on its pattern's colour; the best marked.
std::string cell(const ResultRow& row, const Column& c, const std::vector<int>& figures,
                 bool colour_it) {
    if (!drawn(row)) {  // empty and grey: the line under the matrix says why
        return fmt::format("<td class=\"na\" title=\"cannot draw: {}\"></td>",
                           xml_escape(row.not_applicable));
    }
    std::string html = fmt::format("<td title=\"{}\">", xml_escape(row.method));
    for (int f : figures) {
        const MetricId id = kFigures[f].id;
        if (!shows(row, id)) continue;
        const double v = row[id];
        if (std::isnan(v)) {
            html += "<span class=\"f\">&ndash;</span>";
            continue;
        }
        const std::optional<double> t = position(c.scales[f], id, v);
        const bool best = colour_it && c.scales[f].any && v == c.scales[f].best;
        html += fmt::format("<span class=\"f{}\"{}>{}{}</span>", best ? " best" : "",
                            colour_it && t ? " style=\"background:" + colour(*t) + "\"" : "",
                            best ? "&#9733;" : "", shown_figure(id, v));
    }
    return html + "</td>";
}

// Per pattern, the pick of a rule, grouped: "agg on star, strips; exact on rings".
using Pick = std::optional<std::size_t>;

std::string grouped_picks(const ReportData& data, const std::vector<Column>& columns,
                          const std::vector<Pick>& picks, const char* none_text) {
    std::vector<std::pair<std::string, std::vector<std::string>>> groups;
    std::vector<std::string> without;
    for (std::size_t k = 0; k < columns.size(); ++k) {
        const std::string pattern = xml_escape(columns[k].section->name);
        if (!picks[k]) {
            without.push_back(pattern);
            continue;
        }
        const std::string spec = data.rows[*picks[k]].method;
        auto it = std::find_if(groups.begin(), groups.end(),
                               [&](const auto& g) { return g.first == spec; });
        if (it == groups.end()) {
            groups.push_back({spec, {}});
            it = groups.end() - 1;
        }
        it->second.push_back(pattern);
    }
    std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) {
        return a.second.size() > b.second.size();
    });
    std::vector<std::string> parts;
    for (const auto& [spec, patterns] : groups) {
        parts.push_back(
            fmt::format("<code>{}</code> on {}", xml_escape(spec), fmt::join(patterns, ", ")));
    }
    if (!without.empty())
        parts.push_back(fmt::format("{} on {}", none_text, fmt::join(without, ", ")));
    return fmt::format("{}", fmt::join(parts, "; "));
}

// The median of the pattern's drawn default times: the paragraph's time budget.
double median_default_time(const ReportData& data, const Column& c) {
    std::vector<double> times;
    for (const auto& [family, r] : c.default_row) {
        const double t = data.rows[r][metric::kTimeMedianNs];
        if (drawn(data.rows[r]) && t > 0.0 && std::isfinite(t)) times.push_back(t);
    }
    if (times.empty()) return std::nan("");
    std::sort(times.begin(), times.end());
    return times[(times.size() - 1) / 2];
}

// "Which method for what", from every drawn row of each pattern (sweep points too: a cheaper
// parameter of a method may be the right choice).
std::string advice(const ReportData& data, const std::vector<Column>& columns) {
    std::vector<Pick> fastest, most_accurate;
    for (const Column& c : columns) {
        const double budget_ns = median_default_time(data, c);
        Pick fast, accurate;
        for (std::size_t r : c.section->rows) {
            const ResultRow& row = data.rows[r];
            const double e = row[metric::kBoxRmse], t = row[metric::kTimeMedianNs];
            if (!drawn(row) || !std::isfinite(e) || !(t > 0.0)) continue;
            if (e <= kErrorBudget && (!fast || t < data.rows[*fast][metric::kTimeMedianNs])) {
                fast = r;
            }
            if (t <= budget_ns && (!accurate || e < data.rows[*accurate][metric::kBoxRmse])) {
                accurate = r;
            }
        }
        fastest.push_back(fast);
        most_accurate.push_back(accurate);
    }
    return fmt::format(
        "<p class=\"advice\"><b>Which method for what.</b> Fastest with box rmse &le; {:g} (a "
        "hundredth of the value range): {}. Most accurate within the median time of the "
        "pattern's methods (the faster half): {}.</p>\n",
        kErrorBudget, grouped_picks(data, columns, fastest, "nothing within it"),
        grouped_picks(data, columns, most_accurate, "no method timed"));
}

// The families that cannot draw some pattern, in one line: families with the same patterns and
// reasons together, the patterns named as "every pattern but ..." when that is shorter.
std::string cannot_draw_note(const ReportData& data, const std::vector<Column>& columns) {
    struct Gap {
        std::vector<std::string> families;
        std::vector<std::string> patterns;
        std::vector<std::string> reasons;  // distinct, in order
    };
    std::vector<Gap> by_family;
    for (const Family& family : families(data)) {
        Gap gap{{family.id}, {}, {}};
        for (const Column& c : columns) {
            const auto it = c.default_row.find(family.id);
            if (it == c.default_row.end() || drawn(data.rows[it->second])) continue;
            gap.patterns.push_back(c.section->name);
            const std::string& why = data.rows[it->second].not_applicable;
            if (std::find(gap.reasons.begin(), gap.reasons.end(), why) == gap.reasons.end()) {
                gap.reasons.push_back(why);
            }
        }
        if (gap.patterns.empty()) continue;
        auto same = std::find_if(by_family.begin(), by_family.end(), [&](const Gap& g) {
            return g.patterns == gap.patterns && g.reasons == gap.reasons;
        });
        if (same != by_family.end()) {
            same->families.push_back(family.id);
        } else {
            by_family.push_back(std::move(gap));
        }
    }
    if (by_family.empty()) return {};
    std::vector<std::string> parts;
    for (const Gap& g : by_family) {
        std::vector<std::string> names, reasons, others;
        for (const std::string& f : g.families)
            names.push_back("<code>" + xml_escape(f) + "</code>");
        for (const std::string& r : g.reasons) reasons.push_back(xml_escape(r));
        for (const Column& c : columns) {
            if (std::find(g.patterns.begin(), g.patterns.end(), c.section->name) ==
                g.patterns.end()) {
                others.push_back(xml_escape(c.section->name));
            }
        }
        std::vector<std::string> listed;
        for (const std::string& p : g.patterns) listed.push_back(xml_escape(p));
        const std::string where =
            others.size() < g.patterns.size()
                ? (others.empty() ? std::string("any pattern")
                                  : fmt::format("any pattern but {}", fmt::join(others, ", ")))
                : fmt::format("{}", fmt::join(listed, ", "));
        parts.push_back(fmt::format("{} cannot draw {} ({})", fmt::join(names, ", "), where,
                                    fmt::join(reasons, "; ")));
    }
    return fmt::format("<p class=\"small\">Empty grey cells: {}.</p>\n", fmt::join(parts, ". "));
}

}  // namespace

std::string summary_section(const ReportData& data, const std::vector<Section>& sections) {
    std::vector<Column> columns;
    for (const Section& s : sections) {
        if (!s.rows.empty()) columns.push_back(make_column(data, s));
    }
    if (columns.empty()) return {};
    const std::vector<int> figures = shown_figures(data, columns);
    std::vector<std::string> legend;
    for (int f : figures) legend.push_back(kFigures[f].name);

    std::string html = fmt::format(
        "<section id=\"summary\">\n<h2>Summary: default parameters</h2>\n<p class=\"small\">Each "
        "cell, top to bottom: {}. Colours per pattern and figure on a log scale, green best to "
        "red worst (errors below 1/510, half an 8-bit step, all green); &#9733; the pattern's "
        "best. Hover over a cell for the spec; open a method for its sweep points.</p>\n"
        "<div class=\"table-box\"><table class=\"summary\"><thead><tr><th "
        "class=\"m\">method</th>",
        fmt::join(legend, ", "));
    for (const Column& c : columns) {
        html += fmt::format("<th><a href=\"#{0}\">{0}</a></th>", xml_escape(c.section->name));
    }
    html += "</tr></thead>\n";
    for (const Family& family : families(data)) {
        html += "<tbody>";
        // The family's row: its default spec's figures; a <details> opens its sweep rows (the
        // page's style shows tr.sweep only inside a tbody whose details are open).
        const std::string name = fmt::format(
            "<span title=\"{}\">{}</span>", xml_escape(family.default_spec), xml_escape(family.id));
        html +=
            family.sweep_specs.empty()
                ? fmt::format("<tr><td class=\"m\">{}</td>", name)
                : fmt::format(
                      "<tr><td class=\"m\"><details><summary>{}</summary>{} sweep "
                      "point{}</details></td>",
                      name, family.sweep_specs.size(), family.sweep_specs.size() == 1 ? "" : "s");
        for (const Column& c : columns) {
            const auto it = c.default_row.find(family.id);
            html += it == c.default_row.end() ? std::string("<td></td>")
                                              : cell(data.rows[it->second], c, figures, true);
        }
        html += "</tr>\n";
        for (const std::string& spec : family.sweep_specs) {
            html += fmt::format("<tr class=\"sweep\"><td class=\"m\">{}</td>", xml_escape(spec));
            for (const Column& c : columns) {
                const auto r = std::find_if(
                    c.section->rows.begin(), c.section->rows.end(), [&](std::size_t k) {
                        return data.rows[k].sweep_point && data.rows[k].method == spec;
                    });
                html += r == c.section->rows.end() ? std::string("<td></td>")
                                                   : cell(data.rows[*r], c, figures, false);
            }
            html += "</tr>\n";
        }
        html += "</tbody>\n";
    }
    html += "</table></div>\n";
    html += cannot_draw_note(data, columns);
    html += advice(data, columns);
    return html + "</section>\n";
}

}  // namespace aabench::html_parts
