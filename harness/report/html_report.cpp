// The HTML report (harness/report/html_report.h; what the page shows and why: docs/report.md):
// the page itself, its style, sorting script, sections and context. The summary tables are in
// html_table.cpp, the figure grid in html_figures.cpp.
#include "harness/report/html_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>

#include "harness/measure/circle_angle.h"
#include "harness/report/angle_plot.h"
#include "harness/report/circle_timing_plot.h"
#include "harness/report/cost_plot.h"
#include "harness/report/html_parts.h"
#include "harness/report/image_io.h"
#include "harness/report/report.h"
#include "harness/report/svg_plot.h"

namespace aabench {
namespace html_parts {

// A file name from a spec: letters, digits and ".-=_" kept, everything else (':', ',', '/')
// becomes '_'. Collisions are resolved by the caller.
std::string slug(const std::string& text) {
    std::string out;
    for (char c : text) {
        const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ||
                          c == '=' || c == '_';
        out += keep ? c : '_';
    }
    if (out.empty() || out[0] == '.') out = "_" + out;  // never a hidden file
    return out;
}

// `wanted`, or wanted-2, wanted-3, ... if already taken; the result is then taken.
std::string unique_name(const std::string& wanted, std::set<std::string>& taken) {
    std::string name = wanted;
    for (int k = 2; taken.count(name); ++k) name = fmt::format("{}-{}", wanted, k);
    taken.insert(name);
    return name;
}

}  // namespace html_parts

namespace {

namespace fs = std::filesystem;
using html_parts::Section;

// The summary tables (16 columns and more, as symptom figures are added) are wider than a
// 1200 px window, and a page cutting off their right-hand columns hides numbers. So each table
// scrolls inside its own .table-box, with the method column sticky on the left and the header
// row sticky on top: no number is seen without its method and its column name. The box is at
// most 80vh tall, so on a long sweep table the header stays in view too (a box that never
// scrolls down cannot keep it there). Borders are "separate" with no spacing, because collapsed
// borders belong to the table and stay behind when a sticky cell moves. Numbers are
// right-aligned in tabular figures, unbroken, so their digits line up.
// On a narrow screen (a 390 px phone) nothing but a table box may scroll sideways: the plots
// scale (their viewBox), and the figure grid's four columns share the width, images scaled.
constexpr const char* kStyle = R"css(
body{font-family:"DejaVu Sans",Verdana,sans-serif;margin:20px 28px;color:#222;font-size:14px}
h1{font-size:22px;margin:0 0 6px}
h2{font-size:19px;border-bottom:2px solid #ccc;padding-bottom:3px;margin-top:36px}
h3{font-size:15px;margin:18px 0 6px}
code,pre,.m{font-family:"DejaVu Sans Mono",Menlo,monospace;font-size:12.5px}
pre{background:#f5f5f5;border:1px solid #e2e2e2;padding:8px 10px;white-space:pre-wrap;
    word-break:break-all}
nav a{margin-right:14px}
.note{color:#555;max-width:1100px}
.table-box{width:fit-content;max-width:100%;max-height:80vh;overflow:auto;
    border:1px solid #e2e2e2;box-sizing:border-box}
table.results{border-collapse:separate;border-spacing:0;font-size:13px;
    font-variant-numeric:tabular-nums}
table.results th{background:#eef0f3;cursor:pointer;user-select:none;white-space:nowrap;
    position:sticky;top:0;z-index:1}
table.results th,table.results td{padding:3px 9px;border-bottom:1px solid #e4e4e4;
    text-align:right}
table.results th.m,table.results td.m{text-align:left;position:sticky;left:0;
    border-right:1px solid #d4d8de}
table.results td{white-space:nowrap}
table.results td.m{background:#fff;white-space:normal}
table.results th.m{z-index:2}
table.results th[data-dir=asc]::after{content:" \25B2"}
table.results th[data-dir=desc]::after{content:" \25BC"}
table.results tr.default td.m{font-weight:bold}
table.results tr.sweep td{color:#666}
body.hide-sweep tr.sweep{display:none}
table.context td{padding:2px 10px 2px 0;vertical-align:top}
table.context td:first-child{color:#555;white-space:nowrap}
.plot svg{max-width:100%;height:auto;border:1px solid #e2e2e2}
table.figures{border-collapse:collapse}
table.figures th{font-weight:normal;color:#555;text-align:left;padding:4px 8px 2px 0}
table.figures td{padding:0 8px 10px 0;vertical-align:top}
table.figures td.caption{padding:8px 0 3px;border-top:1px solid #e4e4e4}
table.figures img{display:block;image-rendering:pixelated;border:1px solid #ccc}
.small{font-size:12px;color:#555}
.focusbox{position:relative;display:inline-block;max-width:100%}
.focusbox span{position:absolute;border:2px solid #f28e2b;box-sizing:border-box}
table.summary{border-collapse:separate;border-spacing:0;font-size:11px;
    font-variant-numeric:tabular-nums}
table.summary th{background:#eef0f3;position:sticky;top:0;z-index:1;padding:3px 2px;
    font-size:10.5px;font-weight:normal}
table.summary td{padding:2px 1px;border-bottom:1px solid #e4e4e4;text-align:right;
    vertical-align:top}
table.summary th.m,table.summary td.m{text-align:left;position:sticky;left:0;
    border-right:1px solid #d4d8de;white-space:nowrap}
table.summary td.m{background:#fff;padding:2px 8px 2px 4px}
table.summary th.m{z-index:2}
table.summary .f{display:block;padding:0 2px;white-space:nowrap;line-height:1.3}
table.summary .f.best{font-weight:bold;box-shadow:inset 0 0 0 1px #333}
table.summary td.na{background:#f2f2f2}
table.summary tr.sweep{display:none}
table.summary tbody:has(details[open]) tr.sweep{display:table-row}
table.summary tr.sweep td{color:#555}
table.summary summary{cursor:pointer}
table.summary details{font-weight:normal;color:#555;font-size:11px}
table.summary summary span{font-size:12.5px;color:#222}
.advice{max-width:1100px;overflow-wrap:anywhere}
#summary h2{margin-top:14px}
p.small,.note{overflow-wrap:anywhere}
.plot svg{box-sizing:border-box}
table.figures td.caption,table.context td{overflow-wrap:anywhere}
@media (max-width:1100px){
  table.figures{width:100%;table-layout:fixed}
  table.figures img,table.figures svg{max-width:100%;height:auto;box-sizing:border-box}
}
@media (max-width:600px){
  body{margin:10px 8px}
  nav a{display:inline-block;margin:0 10px 4px 0}
}
)css";

// Sorts a results table by the clicked column: numbers by their data-v (NaN last either way),
// text alphabetically with digits as numbers (n=2 before n=12); a second click reverses.
constexpr const char* kScript = R"js(
document.querySelectorAll('table.results').forEach(function(t){
  var hs=t.tHead.rows[0].cells;
  Array.prototype.forEach.call(hs,function(h,i){h.addEventListener('click',function(){
    var asc=h.dataset.dir!=='asc';
    Array.prototype.forEach.call(hs,function(o){delete o.dataset.dir;});
    h.dataset.dir=asc?'asc':'desc';
    var b=t.tBodies[0],rows=Array.prototype.slice.call(b.rows);
    function key(r){var c=r.cells[i];return c.dataset.v===undefined?c.textContent:+c.dataset.v;}
    rows.sort(function(a,c){var x=key(a),y=key(c);
      if(typeof x==='string'){var o=x.localeCompare(y,undefined,{numeric:true});return asc?o:-o;}
      if(isNaN(x)||isNaN(y))return isNaN(x)-isNaN(y);return asc?x-y:y-x;});
    rows.forEach(function(r){b.appendChild(r);});
  });});
});
var sweep=document.getElementById('show-sweep');
if(sweep)sweep.addEventListener('change',function(){
  document.body.classList.toggle('hide-sweep',!sweep.checked);});
)js";

std::string context_table(const RunContext& c) {
    std::string html = "<table class=\"context\">\n";
    const std::vector<std::pair<const char*, std::string>> items = {
        {"tool", c.tool},
        {"git revision", c.git_revision},
        {"build type", c.build_type},
        {"compiler", c.compiler},
        {"flags", c.flags},
        {"cpu", c.cpu},
        {"hardware threads", std::to_string(c.hardware_threads)},
        {"date (UTC)", c.date_utc},
    };
    for (const auto& [key, value] : items) {
        html +=
            fmt::format("<tr><td>{}</td><td class=\"m\">{}</td></tr>\n", key, xml_escape(value));
    }
    return html + "</table>\n";
}

// Sections: patterns in order of their first row, then figures of patterns without rows.
std::vector<Section> make_sections(const ReportData& data) {
    std::vector<Section> sections;
    std::set<std::string> taken_names;
    auto section_for = [&](const std::string& spec, const std::string& id) -> Section& {
        for (Section& s : sections) {
            if (s.spec == spec) return s;
        }
        sections.push_back(
            {spec,
             id,
             html_parts::unique_name(html_parts::slug(id.empty() ? spec : id), taken_names),
             {},
             nullptr});
        return sections.back();
    };
    for (std::size_t r = 0; r < data.rows.size(); ++r) {
        section_for(data.rows[r].pattern, data.rows[r].pattern_id).rows.push_back(r);
    }
    for (const PatternFigures& fig : data.figures) {
        Section& s = section_for(fig.pattern_spec, fig.pattern_id);
        if (!s.figures) s.figures = &fig;
    }
    return sections;
}

// From <!DOCTYPE> to the note above the first section: title, the summary a reader choosing a
// method reads first (in the first screen), the command that reproduces the run, the
// navigation.
std::string page_head(const ReportData& data, const std::vector<Section>& sections,
                      const std::string& summary) {
    const RunContext& c = data.context;
    std::string html = fmt::format(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta "
        "name=\"viewport\" content=\"width=device-width\">\n<title>aabench report{}</title>\n"
        "<style>{}</style>\n</head>\n<body>\n<h1>aabench: antialiasing accuracy against time</h1>\n"
        "<p class=\"small\">{} &middot; revision <code>{}</code> &middot; {} &middot; {}</p>\n"
        "{}<p>Reproduce this run:</p>\n<pre>{}</pre>\n",
        c.date_utc.empty() ? "" : " " + xml_escape(c.date_utc), kStyle, xml_escape(c.date_utc),
        xml_escape(c.git_revision), xml_escape(c.cpu), xml_escape(c.compiler), summary,
        xml_escape(c.command));
    html += "<nav>";
    if (!summary.empty()) html += "<a href=\"#summary\">summary</a>";
    for (const Section& s : sections) {
        html += fmt::format("<a href=\"#{}\">{}</a>", xml_escape(s.name), xml_escape(s.name));
    }
    if (!data.circle_timings.empty()) html += "<a href=\"#circle-timing\">circle timing</a>";
    if (!data.cost_model.empty()) html += "<a href=\"#cost-model\">cost model</a>";
    if (!data.edge_timings.empty()) html += "<a href=\"#edge-timing\">edge timing</a>";
    if (!data.hard_case_table.empty()) html += "<a href=\"#hard-cases\">hard cases</a>";
    if (!data.claims_section.empty()) html += "<a href=\"#claims\">claims</a>";
    html += "<a href=\"#context\">context</a></nav>\n";
    html +=
        "<p class=\"note\">Every number on this page was measured in this run (results.csv "
        "and results.json beside it hold them all, with their definitions). Tables are "
        "ordered by box_rmse; click a header to sort by it, hover over it for its "
        "definition. Times are medians of one render each (single-threaded unless the "
        "pattern's heading says threads): compare them as ratios within this run.";
    for (const std::string& caveat : time_caveats(data.rows)) {
        html += " Times of " + xml_escape(caveat);
    }
    const bool any_sweep = std::any_of(data.rows.begin(), data.rows.end(),
                                       [](const ResultRow& r) { return r.sweep_point; });
    if (any_sweep) {
        html +=
            " <label><input type=\"checkbox\" id=\"show-sweep\" checked> show sweep points "
            "(grey) in the tables</label>";
    }
    html += "</p>\n";
    return html;
}

// Concentric circles (the `circles` pattern): ink against angle for every method drawn, the
// plot also written to base/plots/<name>-angle.svg. Empty for any other scene.
std::string angle_section(const fs::path& base, const Section& s) {
    const std::optional<ConcentricCurves> curves = concentric_curves(s.figures->scene);
    if (!curves) return {};
    std::vector<AngleSeries> series;
    for (std::size_t k = 0; k < s.figures->images.size(); ++k) {
        series.push_back({s.figures->methods[k],
                          angle_profile(s.figures->images[k], s.figures->reference, *curves, 45)});
    }
    const std::string svg = angle_profile_svg(
        series, fmt::format("{}: ink against angle along the circles", s.id.empty() ? s.name : s.id));
    const std::string plot_file = "plots/" + s.name + "-angle.svg";
    write_text_file((base / plot_file).string(), "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svg);
    return fmt::format(
        "<h3>Ink against angle <a class=\"small\" href=\"{}\">(SVG)</a></h3>\n<p class=\"small\">"
        "Rendered ink over exact ink in 1° bins of the angle along the circles (folded into one "
        "octant), pixels within 1.5 px of the ring set; on touching rings a method that blends\n"
        "each ring over the last loses ink where two rings share a pixel (conflation); dashed: exact (1) and cos θ, one "
        "unit of ink per pixel row.</p>\n<div class=\"plot\">{}</div>\n",
        xml_escape(plot_file), svg);
}

// One pattern's section: its table and plot (the plot also written to base/plots/), then its
// figure grid (images written to base/images/).
std::string pattern_section(const fs::path& base, const Section& s, const ReportData& data) {
    std::string html =
        fmt::format("<section id=\"{}\">\n<h2>{}</h2>\n<p class=\"small m\">{}", xml_escape(s.name),
                    xml_escape(s.id.empty() ? s.name : s.id), xml_escape(s.spec));
    if (!s.rows.empty()) {
        const ResultRow& first = data.rows[s.rows.front()];
        html += fmt::format(" &middot; {}&times;{} px &middot; {} edges", first.width, first.height,
                            first.edges);
    }
    html += "</p>\n";
    if (!s.rows.empty()) {
        html += "<h3>Results</h3>\n" + html_parts::results_table(data, s.rows) +
                html_parts::cannot_draw_line(data, s.rows);
        const std::string stages = html_parts::stage_table(data.rows[s.rows.front()]);
        if (!stages.empty()) {
            html += "<h3>World stages (the plan's cost for this scene, one run)</h3>\n" + stages;
        }
        std::vector<ResultRow> pattern_rows;
        for (std::size_t r : html_parts::drawn_rows(data, s.rows)) {
            pattern_rows.push_back(data.rows[r]);
        }
        const std::string svg = accuracy_time_svg(
            pattern_rows, fmt::format("{}: accuracy against time", s.id.empty() ? s.name : s.id));
        const std::string plot_file = "plots/" + s.name + ".svg";
        write_text_file((base / plot_file).string(),
                        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svg);
        html += fmt::format(
            "<h3>Accuracy against time <a class=\"small\" href=\"{}\">"
            "(SVG)</a></h3>\n<div class=\"plot\">{}</div>\n",
            xml_escape(plot_file), svg);
    }
    if (s.figures) html += angle_section(base, s);
    if (s.figures) html += "<h3>Images</h3>\n" + html_parts::figure_grid(base, s, data);
    if (s.figures && s.figures->edges) {
        html += "<h3>Lines (edge stage, Saito &amp; Takahashi 1990)</h3>\n" +
                html_parts::edge_figure_grid(base, s);
    }
    html += "</section>\n";
    return html;
}

std::vector<CostSeries> cost_series(const std::vector<EdgeTimingSeries>& series) {
    std::vector<CostSeries> out;
    for (const EdgeTimingSeries& s : series) out.push_back({s.name, s.points});
    return out;
}

// The edge stage's time against pixels and against faces (harness/measure/edge_timing.h), as
// the cost model's log-log plots with fitted slopes (harness/report/cost_plot.h).
std::string edge_timing_section(const fs::path& base, const EdgeTimings& timings) {
    std::string html =
        "<section id=\"edge-timing\">\n<h2>Edge stage (Saito &amp; Takahashi 1990): time against "
        "pixels and faces</h2>\n<p class=\"small\">From the edge-cost benchmarks of aabench_bench "
        "(<code>--aabench_edge_cost</code>) given with <code>--bench-json</code>: the stage on "
        "the <code>torus</code>'s depth and shaded images drawn by <code>exact</code>, against "
        "the pixel count (48 x 24 facets, 256&sup2; .. 2048&sup2;) and against the facet count "
        "at 512&sup2;, beside the depth image's own render time. The paper says the stage "
        "costs in proportion to the pixels and not to the shape's complexity: slope 1 against "
        "pixels, 0 against faces.</p>\n";
    const std::pair<const char*, const std::vector<EdgeTimingSeries>*> plots[] = {
        {"pixels", &timings.pixels}, {"faces", &timings.faces}};
    for (const auto& [axis, series] : plots) {
        if (series->empty()) continue;
        const std::string svg = cost_model_svg(
            cost_series(*series), fmt::format("{} (torus)", axis),
            fmt::format("Edge stage against {}", axis));
        const std::string file = fmt::format("plots/edge-timing-{}.svg", axis);
        write_text_file((base / file).string(),
                        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svg);
        html += fmt::format("<h3>Against {} <a class=\"small\" href=\"{}\">(SVG)</a></h3>\n"
                            "<div class=\"plot\">{}</div>\n",
                            axis, file, svg);
    }
    return html + "</section>\n";
}

}  // namespace

void write_html_report(const std::string& dir, const ReportData& data) {
    const fs::path base(dir);
    std::error_code ec;
    fs::create_directories(base / "plots", ec);
    if (ec) throw InputError(fmt::format("{}: cannot create directory ({})", dir, ec.message()));

    const std::vector<Section> sections = make_sections(data);

    std::string html = page_head(data, sections, html_parts::summary_section(data, sections));
    for (const Section& s : sections) {
        html += pattern_section(base, s, data);
    }
    if (!data.circle_timings.empty()) {
        const std::string svg = circle_timing_svg(data.circle_timings, "time per circle against radius");
        write_text_file((base / "plots" / "circle-timing.svg").string(),
                        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svg);
        html += fmt::format(
            "<section id=\"circle-timing\">\n<h2>Time per circle against radius <a "
            "class=\"small\" href=\"plots/circle-timing.svg\">(SVG)</a></h2>\n<p "
            "class=\"small\">From the circle benchmarks of aabench_bench given with "
            "<code>--bench-json</code> (harness/cli/bench_main.cpp: 64 rings of one radius per "
            "render, the empty canvas's fill time subtracted; <code>exact-polygon</code> is one "
            "polygonised ring through the polygon engine). Does the table still pay? Compare "
            "<code>aa-circle-table</code> with <code>aa-circle-on-the-fly</code>.</p>\n"
            "<div class=\"plot\">{}</div>\n</section>\n",
            svg);
    }
    if (!data.cost_model.empty()) {
        // Time against pixels and against edges, log-log with fitted slopes.
        html +=
            "<section id=\"cost-model\">\n<h2>Cost model</h2>\n<p class=\"small\">From the "
            "cost-model benchmarks of aabench_bench (<code>--aabench_cost_model</code>) given "
            "with <code>--bench-json</code>: each method's median time against the image's "
            "pixels (star: its edges grow only from 180 at 128&sup2; to 576 at 4096&sup2;) and "
            "against the scene's edges (rings at "
            "1024&sup2;, the period shrinking), log-log, the dashed line the least-squares fit "
            "with its slope in the legend (1: cost proportional to the size).</p>\n";
        struct Plot {
            const std::vector<CostSeries>* series;
            const char *axis, *x_label;
        };
        const Plot plots[] = {{&data.cost_model.pixels, "pixels", "pixels (star)"},
                              {&data.cost_model.edges, "edges", "edges (rings at 1024^2)"}};
        for (const Plot& plot : plots) {
            if (plot.series->empty()) continue;
            const std::string axis = plot.axis;
            const std::string svg = cost_model_svg(*plot.series, plot.x_label,
                                                   fmt::format("Cost against {}", axis));
            std::string file = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
            file += svg;
            write_text_file((base / "plots" / fmt::format("cost-{}.svg", axis)).string(), file);
            html += fmt::format(
                "<h3>Against {0} <a class=\"small\" href=\"plots/cost-{0}.svg\">(SVG)</a></h3>\n"
                "<div class=\"plot\">{1}</div>\n",
                axis, svg);
        }
        html += "</section>\n";
    }
    if (!data.edge_timings.empty()) html += edge_timing_section(base, data.edge_timings);
    if (!data.hard_case_table.empty()) {
        html += fmt::format(
            "<section id=\"hard-cases\">\n<h2>Hard cases</h2>\n<pre>{}</pre>\n"
            "</section>\n",
            xml_escape(data.hard_case_table));
    }
    html += data.claims_section;
    html += fmt::format(
        "<section id=\"context\">\n<h2>Context</h2>\n{}<p>Command:</p>\n"
        "<pre>{}</pre>\n</section>\n",
        context_table(data.context), xml_escape(data.context.command));
    html += fmt::format("<script>{}</script>\n</body>\n</html>\n", kScript);
    write_text_file((base / "index.html").string(), html);
}

}  // namespace aabench
