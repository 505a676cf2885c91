// The HTML report: a small hand-made run (two patterns at 32x32, `exact` and `none` rendered,
// sweep rows with known times and errors) written to a temporary directory, then checked as
// files: every file present and non-empty, the page self-contained and referencing exactly the
// files on disk, the plots' curves, points and Pareto front counted, the table's numbers the
// rows' numbers (each table in its own scrolling box, the method column sticky), and the pixels
// of the views, error maps and magnified crops.
#include "harness/report/html_report.h"

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "harness/reference/box_reference.h"
#include "harness/report/image_io.h"
#include "harness/report/svg_plot.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "tests/text_search.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

constexpr int kSize = 32;
// Half an 8-bit step: a code read back as float (code / 255) against the value it shows.
constexpr double kHalfCode = 0.5 / 255.0;
// One 8-bit step, for values read back from 8-bit PNGs as float (code / 255 in float).
constexpr double kFloatOfCode = 1e-6;

// The error maps' colours, written out again: ColorBrewer RdBu from the most negative error to
// the most positive, 11 knots interpolated linearly.
constexpr std::uint32_t kRdBu[11] = {0x053061, 0x2166ac, 0x4393c3, 0x92c5de, 0xd1e5f0, 0xf7f7f7,
                                     0xfddbc7, 0xf4a582, 0xd6604d, 0xb2182b, 0x67001f};
// A colour computed in float and rounded to 8 bits, against the same in double.
constexpr double kColourRoundingCodes = 1.0;

// Expected colour of `error` on the signed log scale of 3 decades below `scale`.
std::vector<double> expected_colour(double error, double scale) {
    const double level = std::clamp(std::log10(std::abs(error) / scale * 1e3) / 3.0, 0.0, 1.0);
    const double t = 10.0 * (0.5 + 0.5 * std::copysign(level, error));  // in knot segments
    const int k = std::min(static_cast<int>(t), 9);
    std::vector<double> rgb;
    for (int shift : {16, 8, 0}) {
        const double a = (kRdBu[k] >> shift) & 0xff, b = (kRdBu[k + 1] >> shift) & 0xff;
        rgb.push_back(a + (t - k) * (b - a));
    }
    return rgb;
}

// The 8-bit RGB of pixel `p` (row-major) of a PNG.
std::vector<int> read_rgb(const fs::path& path, std::size_t p) {
    auto in = OIIO::ImageInput::open(path.string());
    EXPECT_TRUE(in) << path;
    if (!in) return {0, 0, 0};
    const OIIO::ImageSpec spec = in->spec();
    EXPECT_EQ(spec.nchannels, 3) << path;
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * spec.height *
                                     spec.nchannels);
    in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data());
    return {pixels[3 * p], pixels[3 * p + 1], pixels[3 * p + 2]};
}

using test::count;
using test::read_text;

ResultRow row(const std::string& pattern_spec, const std::string& pattern_id,
              const std::string& method, const std::string& method_id, bool sweep,
              const std::string& cost_param, double cost_value, double rmse, double time_ns) {
    ResultRow r;
    r.pattern = pattern_spec;
    r.pattern_id = pattern_id;
    r.method = method;
    r.method_id = method_id;
    r.sweep_point = sweep;
    r.cost_param = cost_param;
    r.cost_value = cost_value;
    r.width = kSize;
    r.height = kSize;
    r.edges = 123;
    r[metric::kBoxRmse] = rmse;
    r[metric::kBoxMaxAbs] = 3 * rmse;
    r[metric::kBoxBias] = -0.25 * rmse;
    r[metric::kDropout] = 0.125;
    r.reference_filter = "box";
    r[metric::kOwnRmse] = 0.5 * rmse;
    r[metric::kTimeMedianNs] = time_ns;
    r[metric::kTimeMinNs] = 0.9 * time_ns;
    r[metric::kTimeMaxNs] = 1.2 * time_ns;
    r.time_runs = 7;
    r[metric::kMpixelPerS] = kSize * kSize / time_ns * 1e3;
    return r;
}

PatternFigures figures_of(const std::string& spec, const std::string& focus) {
    PatternFigures fig;
    fig.scene = make_pattern(spec, kSize, kSize);
    fig.pattern_spec = resolve_pattern(spec).spec;
    fig.pattern_id = spec;
    // The test decides the focus (the patterns record their own): drop theirs first.
    std::erase_if(fig.scene.metadata, [](const auto& kv) { return kv.first == "focus"; });
    if (!focus.empty()) fig.scene.metadata.emplace_back("focus", focus);
    fig.reference = box_reference(fig.scene);
    for (const char* method : {"exact", "none"}) {
        const MethodInstance instance = make_method(method);
        fig.methods.push_back(instance.spec);
        fig.images.push_back(render_scene(*instance.method, fig.scene));
    }
    return fig;
}

// Star: the sweep of a fake "ssaa" with a known Pareto front (see Plot below). Strips: two
// default rows and one whose error is NaN.
ReportData sample_data() {
    ReportData data;
    data.context.git_revision = "0123456789ab";
    data.context.compiler = "GNU 12.2.0";
    data.context.cpu = "Test CPU";
    data.context.date_utc = "2024-01-02T03:04:05Z";
    data.context.command = "aabench compare --size 32 --out 'results/a b'";
    data.figures.push_back(figures_of("star", "8,8,12,10"));
    data.figures.push_back(figures_of("strips", ""));
    const std::string star = data.figures[0].pattern_spec;
    const std::string strips = data.figures[1].pattern_spec;
    data.rows = {
        row(star, "star", "none", "none", false, "", 0, 0.2, 1e4),
        row(star, "star", "exact", "exact", false, "", 0, 0.0, 5e5),
        row(star, "star", "ssaa:k=1", "ssaa", true, "k", 1, 0.2, 1.2e4),
        row(star, "star", "ssaa:k=2", "ssaa", true, "k", 2, 0.05, 4e4),
        row(star, "star", "ssaa:k=3", "ssaa", false, "k", 3, 0.03, 9e4),
        row(star, "star", "ssaa:k=4", "ssaa", true, "k", 4, 0.035, 1.6e5),
        row(star, "star", "ssaa:k=8", "ssaa", true, "k", 8, 0.01, 6.4e5),
        row(strips, "strips", "none", "none", false, "", 0, 0.3, 2e4),
        row(strips, "strips", "exact", "exact", false, "", 0, 3e-8, 7e5),
        row(strips, "strips", "broken", "broken", false, "", 0,
            std::numeric_limits<double>::quiet_NaN(), 1e5),
    };
    data.hard_case_table = "case  worst <method>\nstar  none & co\n";
    return data;
}

class HtmlReport : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        dir_ = new fs::path(fs::temp_directory_path() /
                            fmt::format("aabench_html_report_test-{}", ::getpid()));
        fs::remove_all(*dir_);
        data_ = new ReportData(sample_data());
        write_html_report(dir_->string(), *data_);
        html_ = new std::string(read_text(*dir_ / "index.html"));
    }
    static void TearDownTestSuite() {
        // AABENCH_KEEP_REPORT=1 keeps the report for a look (tests/report_screenshot.sh).
        if (std::getenv("AABENCH_KEEP_REPORT")) {
            std::cerr << "report kept in " << dir_->string() << "\n";
        } else {
            fs::remove_all(*dir_);
        }
        delete dir_;
        delete data_;
        delete html_;
    }
    static const fs::path& dir() { return *dir_; }
    static const ReportData& data() { return *data_; }
    static const std::string& html() { return *html_; }

private:
    static fs::path* dir_;
    static ReportData* data_;
    static std::string* html_;
};

fs::path* HtmlReport::dir_ = nullptr;
ReportData* HtmlReport::data_ = nullptr;
std::string* HtmlReport::html_ = nullptr;

TEST_F(HtmlReport, WritesEveryFileNonEmpty) {
    std::vector<std::string> expected = {"index.html", "plots/star.svg", "plots/strips.svg"};
    for (const char* pattern : {"star", "strips"}) {
        for (const char* file : {"reference.png", "reference.exr", "reference.zoom.png"}) {
            expected.push_back(fmt::format("images/{}/{}", pattern, file));
        }
        for (const char* method : {"exact", "none"}) {
            for (const char* suffix :
                 {".png", ".exr", ".error.png", ".zoom.png", ".error.zoom.png"}) {
                expected.push_back(fmt::format("images/{}/{}{}", pattern, method, suffix));
            }
        }
    }
    for (const std::string& file : expected) {
        const fs::path path = dir() / file;
        ASSERT_TRUE(fs::is_regular_file(path)) << path;
        EXPECT_GT(fs::file_size(path), 0u) << path;
    }
    // Atomic writes leave no temporaries behind.
    for (const auto& entry : fs::recursive_directory_iterator(dir())) {
        EXPECT_NE(entry.path().filename().string().rfind(".", 0), 0u) << entry.path();
    }
}

TEST_F(HtmlReport, ReferencesExactlyTheFilesOnDisk) {
    std::set<std::string> referenced;
    const std::regex link("(?:src|href)=\"([^\"#][^\"]*)\"");
    for (std::sregex_iterator it(html().begin(), html().end(), link), end; it != end; ++it) {
        referenced.insert((*it)[1]);
    }
    for (const std::string& ref : referenced) {
        EXPECT_EQ(ref.find("://"), std::string::npos) << "a network reference: " << ref;
        EXPECT_TRUE(fs::is_regular_file(dir() / ref)) << "referenced but missing: " << ref;
    }
    for (const auto& entry : fs::recursive_directory_iterator(dir())) {
        if (!entry.is_regular_file()) continue;
        const std::string relative = fs::relative(entry.path(), dir()).generic_string();
        if (relative == "index.html") continue;
        EXPECT_TRUE(referenced.count(relative)) << "on disk but not on the page: " << relative;
    }
    // Every element id (anchors, the colour bars' gradients) once.
    std::set<std::string> ids;
    const std::regex id(" id=\"([^\"]*)\"");
    for (std::sregex_iterator it(html().begin(), html().end(), id), end; it != end; ++it) {
        EXPECT_TRUE(ids.insert((*it)[1]).second) << "id twice: " << (*it)[1];
    }
    EXPECT_TRUE(ids.count("star") && ids.count("strips") && ids.count("context"));
    // Self-contained: no external script, style sheet or font.
    EXPECT_EQ(count(html(), "<script src"), 0u);
    EXPECT_EQ(count(html(), "<link"), 0u);
    EXPECT_EQ(count(html(), "@import"), 0u);
    EXPECT_EQ(count(html(), "url(http"), 0u);
}

// Minimal XML check: every tag closed in order, attributes quoted, nothing after the root.
void expect_well_formed(const std::string& text, const std::string& what) {
    std::vector<std::string> open;
    std::size_t at = 0;
    bool root_closed = false;
    while ((at = text.find('<', at)) != std::string::npos) {
        const std::size_t end = text.find('>', at);
        ASSERT_NE(end, std::string::npos) << what << ": unterminated tag at " << at;
        const std::string tag = text.substr(at + 1, end - at - 1);
        at = end + 1;
        if (tag.empty() || tag[0] == '?' || tag[0] == '!') continue;
        ASSERT_FALSE(root_closed) << what << ": content after the root element";
        EXPECT_EQ(count(tag, "\"") % 2, 0u) << what << ": unbalanced quotes in <" << tag << ">";
        if (tag[0] == '/') {
            ASSERT_FALSE(open.empty()) << what << ": </" << tag << "> closes nothing";
            EXPECT_EQ(open.back(), tag.substr(1)) << what;
            open.pop_back();
            root_closed = open.empty();
        } else if (tag.back() != '/') {
            open.push_back(tag.substr(0, tag.find_first_of(" \n")));
        }
    }
    EXPECT_TRUE(open.empty()) << what << ": " << open.size() << " elements left open";
    EXPECT_TRUE(root_closed) << what;
}

TEST_F(HtmlReport, PlotsHaveTheCurvesPointsAndParetoFront) {
    const std::string star = read_text(dir() / "plots/star.svg");
    expect_well_formed(star, "star.svg");
    EXPECT_NE(star.find("<svg"), std::string::npos);
    // none, exact, ssaa: three series; only ssaa has a curve (five points, ordered by k).
    EXPECT_EQ(count(star, "class=\"series\""), 3u);
    EXPECT_EQ(count(star, "class=\"curve\""), 1u);
    EXPECT_EQ(count(star, "class=\"point"), 7u);
    EXPECT_EQ(count(star, "class=\"point default\""), 3u);
    // The front: none (fastest), k=2, k=3, exact (at the floor). k=1 ties none's error but is
    // slower; k=4 is beaten by k=3; k=8 by exact.
    EXPECT_EQ(count(star, "class=\"pareto-front\""), 1u);
    EXPECT_EQ(count(star, "class=\"pareto-ring\""), 4u);
    for (const char* label : {">k=1<", ">k=2<", ">k=3<", ">k=4<", ">k=8<"}) {
        EXPECT_EQ(count(star, label), 1u) << label;
    }
    // exact's 0 is drawn at the floor, which the plot states; the floor is 5 decades below
    // the smallest other error (0.01), so the axis breaks and names the floor "<1e-7".
    EXPECT_NE(star.find(fmt::format("floor {:g}", kPlotErrorFloor)), std::string::npos);
    EXPECT_EQ(count(star, "class=\"axis-break\""), 2u);
    EXPECT_NE(star.find(">&lt;10⁻⁷<"), std::string::npos);
    // Decade ticks on both axes.
    EXPECT_NE(star.find(">10 µs<"), std::string::npos);
    EXPECT_NE(star.find(">1 ms<"), std::string::npos);
    EXPECT_NE(star.find(">10⁻²<"), std::string::npos);
    EXPECT_EQ(star.find(">10⁻³<"), std::string::npos);  // cut out by the break

    const std::string strips = read_text(dir() / "plots/strips.svg");
    expect_well_formed(strips, "strips.svg");
    EXPECT_EQ(count(strips, "class=\"series\""), 2u);  // broken (NaN) is left out...
    EXPECT_EQ(count(strips, "class=\"point"), 2u);
    EXPECT_EQ(count(strips, "class=\"curve\""), 0u);
    EXPECT_EQ(count(strips, "class=\"pareto-ring\""), 2u);
    EXPECT_NE(strips.find("1 row without a finite time and error"),
              std::string::npos);  // ...and said
    // The page inlines the same plot.
    EXPECT_NE(html().find(star.substr(star.find("<svg"))), std::string::npos);
}

TEST(AccuracyTimeSvg, FloorNearTheOtherErrorsNeedsNoBreak) {
    // 1e-6 is one decade above the floor: the axis runs on down to it, unbroken.
    std::vector<ResultRow> rows = {row("p", "p", "a", "a", false, "", 0, 1e-6, 1e3),
                                   row("p", "p", "b", "b", false, "", 0, 0.0, 2e3)};
    const std::string svg = accuracy_time_svg(rows, "p");
    expect_well_formed(svg, "plot");
    EXPECT_EQ(count(svg, "class=\"axis-break\""), 0u);
    EXPECT_NE(svg.find(">10⁻⁷<"), std::string::npos);
    EXPECT_NE(svg.find(fmt::format("drawn at {:g}", kPlotErrorFloor)), std::string::npos);
    // b is slower and more accurate: both on the front.
    EXPECT_EQ(count(svg, "class=\"pareto-ring\""), 2u);
    // No rows at all: still a document, saying so.
    const std::string empty = accuracy_time_svg({}, "none");
    expect_well_formed(empty, "empty plot");
    EXPECT_NE(empty.find("no rows"), std::string::npos);
}

TEST(ParetoFront, KeepsOnlyUndominatedPointsInTimeOrder) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<double> x = {3, 1, 2, 2, 4, 5, nan, 1};
    const std::vector<double> y = {1, 5, 3, 4, 1, 0.5, 0, 5};
    // (1,5) twice (duplicates both kept), (2,3), (3,1), (5,0.5); (2,4) and (4,1) are beaten,
    // the NaN point is never on the front.
    EXPECT_EQ(pareto_front(x, y), (std::vector<std::size_t>{1, 7, 2, 0, 5}));
    EXPECT_TRUE(pareto_front({}, {}).empty());
}

TEST_F(HtmlReport, TableNumbersAreTheRowsNumbers) {
    for (const ResultRow& r : data().rows) {
        for (double value :
             {r[metric::kBoxRmse], r[metric::kOwnRmse], r[metric::kBoxMaxAbs], r[metric::kBoxBias],
              r[metric::kDropout], r[metric::kTimeMedianNs], r[metric::kMpixelPerS]}) {
            const std::string exact = std::isnan(value) ? "NaN" : fmt::format("{}", value);
            EXPECT_NE(html().find(fmt::format("data-v=\"{}\"", exact)), std::string::npos)
                << r.method << " " << exact;
        }
        if (!std::isnan(r[metric::kBoxRmse])) {
            EXPECT_NE(html().find(fmt::format(">{:.4g}<", r[metric::kBoxRmse])), std::string::npos);
        }
    }
    // Ordered by box_rmse within a pattern: exact (0), ssaa k=8 (0.01), ..., none (0.2).
    const std::size_t star_table = html().find("<table class=\"results\">");
    const std::size_t strips_table = html().find("<table class=\"results\">", star_table + 1);
    ASSERT_NE(strips_table, std::string::npos);
    const std::string star = html().substr(star_table, strips_table - star_table);
    std::vector<std::size_t> at;
    for (const char* method : {">exact<", ">ssaa:k=8<", ">ssaa:k=3<", ">ssaa:k=4<", ">ssaa:k=2<",
                               ">none<", ">ssaa:k=1<"}) {
        at.push_back(star.find(method));
        ASSERT_NE(at.back(), std::string::npos) << method;
    }
    EXPECT_TRUE(std::is_sorted(at.begin(), at.end()));
    // Sweep rows are marked (grey, hideable), defaults are not.
    EXPECT_EQ(count(star, "<tr class=\"sweep\">"), 4u);
    EXPECT_EQ(count(star, "<tr class=\"default\">"), 3u);
    // NaN sorts last (its sort key stays NaN) and shows as a dash: "not measured here".
    const std::string strips = html().substr(strips_table);
    EXPECT_LT(strips.find(">exact<"), strips.find(">broken<"));
    EXPECT_NE(strips.find("data-v=\"NaN\">&ndash;<"), std::string::npos);
}

// The declarations of every rule of `style` whose selector list names `selector`, joined, with
// white space removed ("a{x: 1}\nb, a{y: 2}" gives "x:1;y:2;" for "a").
std::string css_declarations(const std::string& style, const std::string& selector) {
    std::string declarations;
    std::size_t at = 0;
    for (std::size_t open; (open = style.find('{', at)) != std::string::npos;) {
        const std::size_t close = style.find('}', open);
        if (close == std::string::npos) break;
        std::istringstream selectors(style.substr(at, open - at));
        bool named = false;
        for (std::string item; std::getline(selectors, item, ',');) {
            // Selectors compare with their white space collapsed: "a  b\n" is "a b".
            std::istringstream words(item);
            std::string word, collapsed;
            while (words >> word) collapsed += (collapsed.empty() ? "" : " ") + word;
            named = named || collapsed == selector;
        }
        if (named) {
            std::string block = style.substr(open + 1, close - open - 1);
            std::erase_if(block,
                          [](char c) { return std::isspace(static_cast<unsigned char>(c)); });
            declarations += block + ";";
        }
        at = close + 1;
    }
    return declarations;
}

TEST_F(HtmlReport, TablesScrollInTheirOwnBoxWithTheMethodColumnSticky) {
    // Each summary table sits alone in a box, so a wide table scrolls inside it instead of
    // running off the page.
    const std::string box = "<div class=\"table-box\"><table class=\"results\">";
    EXPECT_EQ(count(html(), "<table class=\"results\">"), 2u);
    EXPECT_EQ(count(html(), box), 2u);
    EXPECT_EQ(count(html(), "</tbody></table></div>"), 2u);

    const std::size_t style_at = html().find("<style>");
    ASSERT_NE(style_at, std::string::npos);
    const std::size_t css_at = style_at + std::string("<style>").size();
    const std::string style = html().substr(css_at, html().find("</style>", css_at) - css_at);
    // The box scrolls and is no wider than the page.
    const std::string box_css = css_declarations(style, ".table-box");
    EXPECT_NE(box_css.find("overflow:auto;"), std::string::npos) << box_css;
    EXPECT_NE(box_css.find("max-width:100%;"), std::string::npos) << box_css;
    // The method column stays in view while it scrolls, on an opaque background (numbers
    // scrolled under it must not show through), above the other cells where they cross.
    for (const char* cell : {"table.results td.m", "table.results th.m"}) {
        const std::string css = css_declarations(style, cell);
        EXPECT_NE(css.find("position:sticky;"), std::string::npos) << cell << ": " << css;
        EXPECT_NE(css.find("left:0;"), std::string::npos) << cell << ": " << css;
        EXPECT_NE(css.find("text-align:left;"), std::string::npos) << cell << ": " << css;
    }
    EXPECT_NE(css_declarations(style, "table.results td.m").find("background:#fff;"),
              std::string::npos);
    EXPECT_NE(css_declarations(style, "table.results th.m").find("z-index:2;"), std::string::npos);
    // The header row stays on top, numbers are right-aligned.
    const std::string th = css_declarations(style, "table.results th");
    EXPECT_NE(th.find("position:sticky;"), std::string::npos) << th;
    EXPECT_NE(th.find("top:0;"), std::string::npos) << th;
    EXPECT_NE(css_declarations(style, "table.results td").find("text-align:right;"),
              std::string::npos);
    // Sorting still finds the tables: the script takes every table.results and its header row.
    EXPECT_NE(html().find("document.querySelectorAll('table.results')"), std::string::npos);
    EXPECT_EQ(count(html(), "<table class=\"results\"><thead><tr><th class=\"m\">method</th>"), 2u);
}

TEST(HtmlReportTable, MethodCellsMayWrapAfterCommasAndKeepTheSpecAsText) {
    const fs::path dir =
        fs::temp_directory_path() / fmt::format("aabench_html_table_test-{}", ::getpid());
    fs::remove_all(dir);
    ReportData data;
    const std::string spec = "ssaa:k=3,filter=box,sigma=0.5";
    data.rows = {row("star", "star", spec, "ssaa", false, "k", 3, 0.05, 1e4)};
    write_html_report(dir.string(), data);
    const std::string html = read_text(dir / "index.html");
    fs::remove_all(dir);
    // The results table's cell (the summary at the top names the family, not the spec).
    const std::size_t cell = html.find("<td class=\"m\"", html.find("<table class=\"results\">"));
    ASSERT_NE(cell, std::string::npos);
    const std::size_t text_at = html.find('>', cell) + 1;
    const std::string text = html.substr(text_at, html.find("</td>", text_at) - text_at);
    EXPECT_EQ(text, "ssaa:k=3,<wbr>filter=box,<wbr>sigma=0.5");
    // <wbr> holds no text: the cell's text, which the sort compares, is the spec.
    EXPECT_EQ(std::regex_replace(text, std::regex("<[^>]*>"), ""), spec);
}

TEST_F(HtmlReport, StatesContextCommandTransformAndHardCases) {
    // The command exactly, HTML-escaped (quotes become &#39;).
    EXPECT_NE(html().find("aabench compare --size 32 --out &#39;results/a b&#39;"),
              std::string::npos);
    for (const char* text :
         {"0123456789ab", "GNU 12.2.0", "Test CPU", "2024-01-02T03:04:05Z", "sRGB-encoded",
          "not transformed", "nearest-neighbour", "none &amp; co", "case  worst &lt;method&gt;"}) {
        EXPECT_NE(html().find(text), std::string::npos) << text;
    }
}

TEST_F(HtmlReport, ViewsAreTheSrgbEncodingOfTheLinearValues) {
    const Image view = read_image((dir() / "images/star/none.png").string());
    const Image& linear = data().figures[0].images[1];
    ASSERT_EQ(view.width, kSize);
    for (std::size_t p = 0; p < view.data.size(); ++p) {
        const double v = std::clamp(static_cast<double>(linear.data[p]), 0.0, 1.0);
        const double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
        EXPECT_NEAR(view.data[p], encoded, kHalfCode + kFloatOfCode) << p;
    }
    // The EXR beside it holds the linear data exactly.
    const Image exr = read_image((dir() / "images/star/none.exr").string());
    EXPECT_EQ(exr.data, linear.data);
}

TEST_F(HtmlReport, MagnifiedCropRepeatsEachPixelOfTheFocusRegion) {
    // star's focus "8,8,12,10" sets the window's size, 12x10; 256 / 12 = 21 clamps to the
    // maximum zoom 16. Where the window went, the page says: "x X..X+12, y Y..Y+10".
    constexpr int kW = 12, kH = 10, kZoom = 16;
    std::smatch at;
    const std::string note = html().substr(0, html().find("<section id=\"strips\">"));
    ASSERT_TRUE(std::regex_search(
        note, at, std::regex("x (\\d+)\\.\\.(\\d+), y (\\d+)\\.\\.(\\d+) \\(12&times;10 px\\)")));
    const int kX = std::stoi(at[1]), kY = std::stoi(at[3]);
    EXPECT_EQ(std::stoi(at[2]), kX + kW);
    EXPECT_EQ(std::stoi(at[4]), kY + kH);
    for (const char* name : {"reference", "none", "none.error"}) {
        const Image full = read_image((dir() / fmt::format("images/star/{}.png", name)).string());
        const Image zoom =
            read_image((dir() / fmt::format("images/star/{}.zoom.png", name)).string());
        ASSERT_EQ(zoom.width, kW * kZoom) << name;
        ASSERT_EQ(zoom.height, kH * kZoom) << name;
        for (int j = 0; j < zoom.height; ++j) {
            for (int i = 0; i < zoom.width; ++i) {
                ASSERT_EQ(zoom.at(i, j), full.at(kX + i / kZoom, kY + j / kZoom))
                    << name << " at " << i << "," << j;
            }
        }
    }
    EXPECT_NE(html().find("nearest-neighbour &times;16"), std::string::npos);
    // strips names no focus: a 32x32 square, i.e. the whole image, at 8x.
    const Image zoom = read_image((dir() / "images/strips/none.zoom.png").string());
    EXPECT_EQ(zoom.width, kSize * 8);
}

TEST_F(HtmlReport, ErrorMapsShareOneScaleAndExactIsWhite) {
    // exact's error is float32 rounding, far below the scale / 1000 set by none: all white
    // (RdBu's centre, 0xf7); channel 0 is red.
    const Image exact = read_image((dir() / "images/star/exact.error.png").string());
    for (float v : exact.data) ASSERT_NEAR(v, 0xf7 / 255.0, kFloatOfCode);
    // none's largest error, and one of each sign, have the map's colour on the scale 1 (none's
    // largest |error| rounded up to 1, 2 or 5 x 10^k).
    const PatternFigures& fig = data().figures[0];
    std::size_t worst = 0, negative = 0, positive = 0;
    auto error_at = [&](std::size_t p) {
        return static_cast<double>(fig.images[1].data[p]) - fig.reference.data[p];
    };
    for (std::size_t p = 0; p < fig.reference.data.size(); ++p) {
        if (std::abs(error_at(p)) > std::abs(error_at(worst))) worst = p;
        if (error_at(p) < -0.01 && negative == 0) negative = p;
        if (error_at(p) > 0.01 && positive == 0) positive = p;
    }
    ASSERT_GT(std::abs(error_at(worst)), 0.5);  // so that the scale is 1
    for (std::size_t p : {worst, negative, positive}) {
        const std::vector<int> rgb = read_rgb(dir() / "images/star/none.error.png", p);
        const std::vector<double> expected = expected_colour(error_at(p), 1.0);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(rgb[c], expected[c], kColourRoundingCodes)
                << "pixel " << p << " error " << error_at(p) << " channel " << c;
        }
    }
    // The data beside the maps: the reference as float32 (the error is none.exr minus it).
    const Image reference = read_image((dir() / "images/star/reference.exr").string());
    for (std::size_t p = 0; p < reference.data.size(); ++p) {
        ASSERT_EQ(reference.data[p], static_cast<float>(fig.reference.data[p]));
    }
    // One colour bar per pattern, stating the scale (none's max error rounds up to 1).
    EXPECT_EQ(count(html(), "<linearGradient"), 2u);
    EXPECT_NE(html().find(">+1<"), std::string::npos);
    EXPECT_NE(html().find(">-0.01<"), std::string::npos);
}

// `methods` on `patterns` at 48x48, one timed run, no symptoms, its report written to `dir`.
ReportData write_small_report(const fs::path& dir, std::vector<std::string> methods,
                              std::vector<std::string> patterns) {
    CompareOptions options;
    options.method_specs = std::move(methods);
    options.pattern_specs = std::move(patterns);
    options.width = options.height = 48;
    options.runs = 1;
    options.symptoms = false;
    const CompareResult result = run_comparison(options);
    ReportData data;
    data.rows = result.rows;
    data.figures = result.figures;
    write_html_report(dir.string(), data);
    return data;
}

// A scene with edges gets the edge figures (docs/edges.md): the exact depth, p, e, both compositing
// styles, the line image and the ground truth, each written and shown; a scene without edges
// gets none.
TEST(HtmlReportEdges, SceneWithEdgesShowsDepthContourCreaseAndBothStyles) {
    const fs::path dir =
        fs::temp_directory_path() / fmt::format("aabench_html_edges_test-{}", ::getpid());
    fs::remove_all(dir);
    const ReportData data = write_small_report(dir, {"exact"}, {"torus", "star"});
    const std::string html = read_text(dir / "index.html");
    for (const char* panel : {"depth", "p", "e", "black", "white-convex", "lines", "truth"}) {
        const std::string rel = fmt::format("images/torus/edges.{}.png", panel);
        EXPECT_TRUE(fs::is_regular_file(dir / rel)) << rel;
        EXPECT_NE(html.find(rel), std::string::npos) << rel;
        EXPECT_FALSE(fs::exists(dir / fmt::format("images/star/edges.{}.png", panel)));
    }
    EXPECT_EQ(count(html, "<h3>Lines"), 1u);
    fs::remove_all(dir);
}

// A colour scene's error maps: the luminance's, and beside it the largest channel's, the signed
// error of the channel whose error is largest at each pixel, on the same scale; a grey scene
// has no such column.
TEST(HtmlReportColour, TheLargestChannelsErrorIsMappedBesideTheLuminances) {
    const fs::path dir =
        fs::temp_directory_path() / fmt::format("aabench_html_colour_test-{}", ::getpid());
    fs::remove_all(dir);
    const ReportData data = write_small_report(dir, {"none", "exact"}, {"isoluminant", "star"});
    const std::string html = read_text(dir / "index.html");
    EXPECT_EQ(count(html, "<th>largest channel's error</th>"), 1u);
    EXPECT_FALSE(fs::exists(dir / "images/star/none.error.channel.png"));
    const PatternFigures& fig = data.figures[0];
    ASSERT_TRUE(fig.colour_reference.has_value());
    ASSERT_EQ(fig.colour_images.size(), 2u);
    // The scale: the largest |luminance error| of the pattern, rounded up to 1, 2 or 5 x 10^k.
    double largest = 0.0;
    for (const Image& image : fig.images) {
        for (std::size_t p = 0; p < image.data.size(); ++p)
            largest = std::max(largest, std::abs(double(image.data[p]) - fig.reference.data[p]));
    }
    const double decade = std::pow(10.0, std::floor(std::log10(largest)));
    double scale = 10.0 * decade;
    for (double step : {5.0, 2.0, 1.0}) {
        if (largest <= step * decade * (1.0 + 1e-6)) scale = step * decade;
    }
    // At each of none's pixels with a channel error of 0.05 or more, the map shows the error of
    // the channel whose error is largest.
    const ImagePlanes& none = fig.colour_images[0];
    std::size_t checked = 0;
    for (std::size_t p = 0; p < none[0].data.size(); ++p) {
        double e[3];
        for (int c = 0; c < 3; ++c)
            e[c] = double(none[c].data[p]) - fig.colour_reference->planes[c].data[p];
        const int top = std::abs(e[0]) >= std::abs(e[1]) && std::abs(e[0]) >= std::abs(e[2]) ? 0
                        : std::abs(e[1]) >= std::abs(e[2])                                   ? 1
                                                                                             : 2;
        if (std::abs(e[top]) < 0.05) continue;
        const std::vector<int> rgb = read_rgb(dir / "images/isoluminant/none.error.channel.png", p);
        const std::vector<double> expected = expected_colour(e[top], scale);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(rgb[c], expected[c], kColourRoundingCodes)
                << "pixel " << p << " channel " << c;
        }
        ++checked;
    }
    EXPECT_GT(checked, 20u);
    fs::remove_all(dir);
}

TEST(DisplayPng, KeepsRgbOrderAndRejectsOtherFormats) {
    const fs::path dir = fs::temp_directory_path() / fmt::format("aabench_png_test-{}", ::getpid());
    fs::create_directories(dir);
    const std::vector<std::uint8_t> red = {255, 0, 0, 255, 0, 0};
    write_display_png((dir / "red.png").string(), 2, 1, 3, red.data());
    EXPECT_EQ(read_image((dir / "red.png").string()).data, (std::vector<float>{1.0f, 1.0f}));
    EXPECT_THROW(write_display_png((dir / "red.exr").string(), 2, 1, 3, red.data()), InputError);
    EXPECT_THROW(write_display_png((dir / "red.png").string(), 1, 1, 2, red.data()), InputError);
    EXPECT_FALSE(fs::exists(dir / "red.exr"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace aabench
