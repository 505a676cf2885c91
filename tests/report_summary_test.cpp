// The report's first screen and its details (docs/report.md): the summary matrix of method
// families x patterns with its colours, best marks, folded sweep points, the line naming the
// methods that cannot draw a pattern and the generated "which method for what" paragraph; the
// rows of such methods left out of their pattern's table and plot; columns empty for a whole
// table left out; the magnified window landing on something (the torus's own focus falls in its
// hole); and the plot's point labels covering no marker and no other label.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "tests/text_search.h"
#include "harness/reference/box_reference.h"
#include "harness/report/html_report.h"
#include "harness/report/image_io.h"
#include "harness/report/label_layout.h"
#include "harness/report/svg_plot.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 32;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kCannotDrawStar = "draws only circles; star has polygons";

using test::count;
using test::read_text;

// The text between `from` and the next `to` (both must be there).
std::string between(const std::string& text, const std::string& from, const std::string& to) {
    const std::size_t a = text.find(from);
    EXPECT_NE(a, std::string::npos) << from;
    if (a == std::string::npos) return {};
    const std::size_t b = text.find(to, a + from.size());
    EXPECT_NE(b, std::string::npos) << to;
    return text.substr(a, b == std::string::npos ? std::string::npos : b - a);
}

ResultRow row(const std::string& pattern, const std::string& method, const std::string& id,
              bool sweep, double rmse, double time_ns) {
    ResultRow r;
    r.pattern = pattern;
    r.pattern_id = pattern;
    r.method = method;
    r.method_id = id;
    r.sweep_point = sweep;
    if (sweep) {
        r.cost_param = "k";
        r.cost_value = method.back() - '0';
    }
    r.width = kSize;
    r.height = kSize;
    // ssaa is filtered here (its own-filter error differs from the box error), the rest not.
    r.reference_filter = id == "ssaa" ? "gaussian:sigma=0.5" : "box";
    r[metric::kBoxRmse] = rmse;
    r[metric::kOwnRmse] = 0.5 * rmse;
    r[metric::kTimeMedianNs] = time_ns;
    r[metric::kMpixelPerS] = kSize * kSize / time_ns * 1e3;
    return r;
}

// A method that cannot draw the pattern: compare's row has its reason and no figures.
ResultRow cannot_draw(const std::string& pattern) {
    ResultRow r;
    r.pattern = pattern;
    r.pattern_id = pattern;
    r.method = "aa-circle";
    r.method_id = "aa-circle";
    r.width = kSize;
    r.height = kSize;
    r.not_applicable = kCannotDrawStar;
    return r;
}

// Star: none, exact, ssaa (default k=3 and four sweep points), and aa-circle, which cannot draw
// it. Strips: none, exact and a method whose error is NaN; no own-filter error in any row.
ReportData sample_data() {
    ReportData data;
    data.context.command = "aabench compare --size 32";
    data.rows = {
        row("star", "none", "none", false, 0.2, 1e4),
        row("star", "exact", "exact", false, 0.0, 5e5),
        row("star", "ssaa:k=1", "ssaa", true, 0.2, 1.2e4),
        row("star", "ssaa:k=2", "ssaa", true, 0.05, 4e4),
        row("star", "ssaa:k=3", "ssaa", false, 0.03, 9e4),
        row("star", "ssaa:k=4", "ssaa", true, 0.035, 1.6e5),
        row("star", "ssaa:k=8", "ssaa", true, 0.01, 6.4e5),
        cannot_draw("star"),
        row("strips", "none", "none", false, 0.3, 2e4),
        row("strips", "exact", "exact", false, 3e-8, 7e5),
        row("strips", "broken", "broken", false, kNaN, 1e5),
    };
    for (ResultRow& r : data.rows) {
        if (r.pattern == "strips") r[metric::kOwnRmse] = kNaN;
    }
    return data;
}

class ReportSummary : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new fs::path(fs::temp_directory_path() /
                            fmt::format("aabench_report_summary_test-{}", ::getpid()));
        fs::remove_all(*dir_);
        write_html_report(dir_->string(), sample_data());
        html_ = new std::string(read_text(*dir_ / "index.html"));
    }
    static void TearDownTestSuite() {
        fs::remove_all(*dir_);
        delete dir_;
        delete html_;
    }
    static const fs::path& dir() { return *dir_; }
    static const std::string& html() { return *html_; }
    static std::string summary() {
        return between(html(), "<section id=\"summary\">", "</section>");
    }

private:
    static fs::path* dir_;
    static std::string* html_;
};

fs::path* ReportSummary::dir_ = nullptr;
std::string* ReportSummary::html_ = nullptr;

TEST_F(ReportSummary, ComesFirstWithARowPerFamilyAndAColumnPerPattern) {
    const std::size_t at = html().find("<section id=\"summary\">");
    ASSERT_NE(at, std::string::npos);
    EXPECT_LT(at, html().find("Reproduce this run"));
    EXPECT_LT(at, html().find("<section id=\"star\">"));
    const std::string s = summary();
    // Families in order of first appearance: none, exact, ssaa, aa-circle, broken.
    EXPECT_EQ(count(s, "<tbody>"), 5u);
    std::vector<std::size_t> order;
    for (const char* family : {">none<", ">exact<", ">ssaa<", ">aa-circle<", ">broken<"}) {
        order.push_back(s.find(family));
        ASSERT_NE(order.back(), std::string::npos) << family;
    }
    EXPECT_TRUE(std::is_sorted(order.begin(), order.end()));
    EXPECT_NE(s.find("<th><a href=\"#star\">star</a></th>"), std::string::npos);
    EXPECT_NE(s.find("<th><a href=\"#strips\">strips</a></th>"), std::string::npos);
    // The default row's figures: ssaa:k=3 on star, box 0.03, own 0.015, 0.09 ms.
    const std::string ssaa = between(s, "<td title=\"ssaa:k=3\">", "</td>");
    EXPECT_NE(ssaa.find(">0.03</span>"), std::string::npos) << ssaa;
    EXPECT_NE(ssaa.find(">&#9733;0.015</span>"), std::string::npos) << ssaa;  // the only one
    EXPECT_NE(ssaa.find(">0.09</span>"), std::string::npos) << ssaa;
    // A box-filtered method's own-filter error is its box error: not repeated.
    const std::string none = between(s, "<td title=\"none\">", "</td>");
    EXPECT_EQ(count(none, "<span"), 2u) << none;
}

TEST_F(ReportSummary, SweepPointsAreFoldedUnderTheirFamily) {
    const std::string s = summary();
    EXPECT_EQ(count(s, "<details>"), 1u);
    EXPECT_NE(s.find("4 sweep points</details>"), std::string::npos);
    EXPECT_EQ(count(s, "<tr class=\"sweep\">"), 4u);
    const std::size_t ssaa = s.find("<details>");
    for (const char* spec : {"ssaa:k=1", "ssaa:k=2", "ssaa:k=4", "ssaa:k=8"}) {
        EXPECT_GT(s.find(fmt::format("<tr class=\"sweep\"><td class=\"m\">{}</td>", spec)), ssaa)
            << spec;
    }
    // Folded by the page's style, shown when the family's details are open.
    EXPECT_NE(html().find("table.summary tr.sweep{display:none}"), std::string::npos);
    EXPECT_NE(html().find("table.summary tbody:has(details[open]) tr.sweep{display:table-row}"),
              std::string::npos);
}

TEST_F(ReportSummary, BestOfEachPatternIsMarkedAndColoursRunGreenToRed) {
    const std::string s = summary();
    // Star: exact's 0 is the best box error (green, shown as below the floor of float32
    // rounding), none's 0.2 the worst (red); none is the fastest (green) and exact the slowest.
    const std::string exact_star = between(s, "<td title=\"exact\">", "</td>");
    EXPECT_NE(exact_star.find("<span class=\"f best\" style=\"background:hsl(120,65%,84%)\">"
                              "&#9733;&lt;1e-07</span>"),
              std::string::npos)
        << exact_star;
    EXPECT_NE(exact_star.find("style=\"background:hsl(0,65%,84%)\">0.5</span>"), std::string::npos)
        << exact_star;
    const std::string none_star = between(s, "<td title=\"none\">", "</td>");
    EXPECT_NE(none_star.find("style=\"background:hsl(0,65%,84%)\">0.2</span>"), std::string::npos)
        << none_star;
    EXPECT_NE(none_star.find("<span class=\"f best\" style=\"background:hsl(120,65%,84%)\">"
                             "&#9733;0.01</span>"),
              std::string::npos)
        << none_star;
    // Per pattern and figure one best (no ties here): 3 on star (ssaa's own-filter error the
    // only one), 2 on strips, where no row has an own-filter error.
    EXPECT_EQ(count(s, "class=\"f best\""), 5u);
    // A NaN figure shows as a dash, uncoloured and never best.
    EXPECT_NE(between(s, "<td title=\"broken\">", "</td>").find("&ndash;"), std::string::npos);
}

TEST_F(ReportSummary, MethodsThatCannotDrawAreNamedOnceWithTheirReason) {
    const std::string s = summary();
    // An empty grey cell with the reason on hover, not "cannot draw" written in every cell.
    EXPECT_NE(
        s.find(fmt::format("<td class=\"na\" title=\"cannot draw: {}\"></td>", kCannotDrawStar)),
        std::string::npos);
    EXPECT_EQ(count(s, "<td class=\"na\""), 1u);
    EXPECT_NE(s.find(fmt::format("Empty grey cells: <code>aa-circle</code> cannot draw star ({}).",
                                 kCannotDrawStar)),
              std::string::npos)
        << s;
}

TEST_F(ReportSummary, SaysWhichMethodForWhatFromTheNumbers) {
    const std::string advice = between(summary(), "<p class=\"advice\">", "</p>");
    // Box rmse <= 0.01, fastest: exact on both (ssaa:k=8's 0.01 is slower on star).
    EXPECT_NE(advice.find("Fastest with box rmse &le; 0.01 (a hundredth of the value range): "
                          "<code>exact</code> on star, strips."),
              std::string::npos)
        << advice;
    // Within the median default time (star: 0.09 ms; strips: 0.1 ms), most accurate:
    // ssaa:k=3 on star; on strips only none qualifies (broken's error is NaN).
    EXPECT_NE(advice.find("<code>ssaa:k=3</code> on star; <code>none</code> on strips"),
              std::string::npos)
        << advice;
}

TEST_F(ReportSummary, RowsOfMethodsThatCannotDrawAreLeftOutOfTheTableAndPlot) {
    const std::string star = between(html(), "<section id=\"star\">", "</section>");
    const std::string table = between(star, "<table class=\"results\">", "</table>");
    EXPECT_EQ(table.find("aa-circle"), std::string::npos);
    // No row of dashes, NaN or 0 Mpixel/s for it: 7 rows, all drawn.
    EXPECT_EQ(count(table, "<tr class="), 7u);
    EXPECT_EQ(table.find("data-v=\"NaN\""), std::string::npos);
    // One line says who and why.
    EXPECT_NE(star.find(fmt::format("cannot draw this pattern: <code>aa-circle</code> ({}).",
                                    kCannotDrawStar)),
              std::string::npos);
    // The plot: three series (none, exact, ssaa), no note about a left-out row.
    const std::string plot = read_text(dir() / "plots/star.svg");
    EXPECT_EQ(count(plot, "class=\"series\""), 3u);
    EXPECT_EQ(plot.find("aa-circle"), std::string::npos);
    EXPECT_EQ(plot.find("without a finite time"), std::string::npos);
}

TEST_F(ReportSummary, ColumnsEmptyForTheWholeTableAreNotShown) {
    const std::string star = between(html(), "<section id=\"star\">", "</section>");
    const std::string strips = between(html(), "<section id=\"strips\">", "</section>");
    // own_rmse: every strips row lacks it, star's rows have it.
    EXPECT_NE(star.find(">own_rmse</th>"), std::string::npos);
    EXPECT_EQ(strips.find(">own_rmse</th>"), std::string::npos);
    // max_abs, bias and dropout are in no row here: in neither table.
    for (const char* header : {">max_abs</th>", ">bias</th>", ">dropout</th>"}) {
        EXPECT_EQ(star.find(header), std::string::npos) << header;
        EXPECT_EQ(strips.find(header), std::string::npos) << header;
    }
    // The summary leaves out a figure only when no cell of any pattern has it: own is shown.
    EXPECT_NE(summary().find("box rmse, own-filter rmse (where the filter is not the box), time"),
              std::string::npos);
}

// The torus names its centre as its focus, which at 64x64 falls in the hole. The magnified
// window must land where the image has detail.
TEST(ReportFocus, MagnifiedWindowLandsOnDetailNotInTheTorusHole) {
    constexpr int kTorusSize = 64;
    // The window's reference must span at least this much of the value range: an edge crosses
    // it (the hole alone is flat background).
    constexpr double kMinContrast = 0.5;
    ReportData data;
    PatternFigures fig;
    const Scene scene = make_pattern("torus", kTorusSize, kTorusSize);
    const PreparedFrame frame = PreparedFrame::prepare(scene);
    fig.scene = frame.pieces().scene();
    fig.pattern_id = "torus";
    fig.pattern_spec = resolve_pattern("torus").spec;
    fig.reference = box_reference(fig.scene);
    for (const char* spec : {"exact", "none"}) {
        const MethodInstance m = make_method(spec);
        fig.methods.push_back(m.spec);
        fig.images.push_back(render_scene(*m.method, frame.input_for(*m.method)));
    }
    data.figures.push_back(std::move(fig));
    const fs::path dir =
        fs::temp_directory_path() / fmt::format("aabench_report_focus_test-{}", ::getpid());
    fs::remove_all(dir);
    write_html_report(dir.string(), data);
    const std::string html = read_text(dir / "index.html");
    fs::remove_all(dir);
    std::smatch at;
    ASSERT_TRUE(std::regex_search(
        html, at, std::regex(R"(x (\d+)\.\.(\d+), y (\d+)\.\.(\d+) \((\d+)&times;(\d+) px\))")));
    const int x0 = std::stoi(at[1]), x1 = std::stoi(at[2]);
    const int y0 = std::stoi(at[3]), y1 = std::stoi(at[4]);
    double lo = 1.0, hi = 0.0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            lo = std::min(lo, data.figures[0].reference.at(x, y));
            hi = std::max(hi, data.figures[0].reference.at(x, y));
        }
    }
    EXPECT_GT(hi - lo, kMinContrast)
        << "window x " << x0 << ".." << x1 << ", y " << y0 << ".." << y1;
}

bool overlaps_any(const LabelBox& box, const std::vector<LabelBox>& others) {
    for (const LabelBox& o : others) {
        if (box.overlaps(o)) return true;
    }
    return false;
}

TEST(LabelLayout, CrowdedLabelsCoverNoMarkerAndNoOtherLabel) {
    // A sweep whose points crowd together (as ssaa's k=1..8 at nearly the same time and error),
    // beside a second method's points in the same spot.
    std::vector<Marker> markers;
    std::vector<LabelRequest> requests;
    for (int k = 0; k < 8; ++k) {
        const Marker m{200.0 + 6.0 * k, 150.0 + 4.0 * (k % 3), k == 2 ? 6.0 : 3.5};
        markers.push_back(m);
        requests.push_back({m, fmt::format("k={}", k + 1), 10.0, k == 2});
    }
    markers.push_back({215.0, 140.0, 10.0});  // a Pareto ring
    const LabelBox frame{78.0, 48.0, 610.0, 420.0};
    const std::vector<std::optional<PlacedLabel>> placed = place_labels(requests, markers, frame);
    ASSERT_EQ(placed.size(), requests.size());
    std::vector<LabelBox> marker_boxes, label_boxes;
    for (const Marker& m : markers) marker_boxes.push_back(m.box());
    std::size_t shown = 0;
    for (const auto& p : placed) {
        if (!p) continue;
        ++shown;
        EXPECT_FALSE(overlaps_any(p->box, marker_boxes));
        EXPECT_FALSE(overlaps_any(p->box, label_boxes));
        EXPECT_GE(p->box.x0, frame.x0);
        EXPECT_LE(p->box.x1, frame.x1);
        label_boxes.push_back(p->box);
        // The text sits in its box: it starts at the left edge, its baseline inside.
        EXPECT_DOUBLE_EQ(p->text_x, p->box.x0);
        EXPECT_GT(p->baseline_y, p->box.y0);
        EXPECT_LT(p->baseline_y, p->box.y1);
    }
    // There is room round the cluster for all eight (the last ones further out, with a leader
    // line to their point).
    EXPECT_EQ(shown, requests.size());
}

TEST(LabelLayout, ALonePointIsLabelledOnItsRightAndAHemmedInOneIsLeftOut) {
    const Marker lone{100.0, 100.0, 3.5};
    const LabelBox frame{0.0, 0.0, 400.0, 300.0};
    const auto placed = place_labels({{lone, "n=6", 10.0, false}}, {lone}, frame);
    ASSERT_TRUE(placed[0]);
    EXPECT_GT(placed[0]->box.x0, lone.x + lone.radius);
    EXPECT_LT(placed[0]->box.y0, lone.y);
    EXPECT_GT(placed[0]->box.y1, lone.y);
    // Markers packed all round it: no free spot, so no label.
    std::vector<Marker> packed;
    for (int dy = -40; dy <= 40; dy += 4) {
        for (int dx = -60; dx <= 60; dx += 4) packed.push_back({100.0 + dx, 100.0 + dy, 3.5});
    }
    EXPECT_FALSE(place_labels({{lone, "n=6", 10.0, false}}, packed, frame)[0]);
}

TEST(LabelLayout, PlotStatesLabelsItHadToLeaveOut) {
    // Twelve sweep points at one time and error: the plot places what fits, and the note says
    // how many labels it left out; every placed label plus every left-out one is a point.
    std::vector<ResultRow> rows;
    for (int k = 1; k <= 12; ++k) {
        ResultRow r = row("p", fmt::format("ssaa:k={}", k % 10), "ssaa", k != 3, 0.05, 1e5);
        r.cost_param = "k";  // the default row (k=3) is labelled too
        r.cost_value = k;
        rows.push_back(r);
    }
    const std::string svg = accuracy_time_svg(rows, "p");
    const std::size_t labels = count(svg, "<text class=\"label\"");
    std::smatch at;
    std::size_t left_out = 0;
    if (std::regex_search(svg, at, std::regex(R"((\d+) labels? left out)"))) {
        left_out = std::stoul(at[1]);
    }
    EXPECT_EQ(labels + left_out, rows.size());
    EXPECT_GT(labels, 0u);
}

}  // namespace
}  // namespace aabench
