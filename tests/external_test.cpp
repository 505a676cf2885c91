// compare --external (docs/external.md): the protocol with aabench itself as the external
// renderer (known answer), the worked example with rsvg-convert, the aabench-time-ms line, the
// errors; and the SVG the {svg} placeholder and export --out .svg write.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "harness/report/image_io.h"
#include "harness/report/scene_svg.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/curves.h"
#include "tests/cli_runner.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// A 16-bit PNG code is round(v * 65535); |rmse(a) - rmse(b)| <= max |a - b| (triangle
// inequality), so a figure read back from one moves by at most half a step.
constexpr double kHalf16BitStep = 0.5 / 65535.0;
// rsvg-convert draws with Cairo, as the `cairo` method does; on white-on-black patterns the two
// differ only in how 8-bit coverage is composited and rounded: at most one code per pixel.
constexpr double kOneEightBitCode = 1.0 / 255.0;

using Output = CliOutput;

class External : public CliRunner {
protected:
    External() : CliRunner("external") {}
    // The rows of a compare run's results.json.
    nlohmann::json rows(const std::string& dir) const {
        return nlohmann::json::parse(std::ifstream(path(dir + "/results.json")))["rows"];
    }
};

const nlohmann::json& find_row(const nlohmann::json& rows, const std::string& pattern_id,
                               const std::string& method) {
    for (const auto& r : rows) {
        if (r["pattern_id"] == pattern_id && r["method"] == method) return r;
    }
    throw std::logic_error("no row " + pattern_id + " / " + method);
}

TEST_F(External, AabenchRenderAsAnExternalRendererScoresAsTheMethodDoes) {
    // {scene} is the scene file: render --scene runs the world stages itself for room.
    const Output o = run(fmt::format(
        "compare --patterns star,room --size 32x24 --methods exact --runs 1 --no-hardcases "
        "--quiet --out {} --external \"self={} render --scene {{scene}} --method exact --out "
        "{{out}}\"",
        path("run"), AABENCH_BINARY));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    const nlohmann::json r = rows("run");
    ASSERT_EQ(r.size(), 4u);
    for (const char* pattern : {"star", "room"}) {
        const auto& method = find_row(r, pattern, "exact");
        const auto& external = find_row(r, pattern, "external:self");
        EXPECT_EQ(external["method_id"], "external:self");
        EXPECT_EQ(external["time_source"], "process");
        EXPECT_EQ(external["edges"], method["edges"]) << pattern;
        EXPECT_NEAR(external["box_rmse"].get<double>(), method["box_rmse"].get<double>(),
                    kHalf16BitStep)
            << pattern;
        EXPECT_GT(external["time_median_ns"].get<double>(), 0.0);
        EXPECT_GT(external["external_startup_ns"].get<double>(), 0.0);
        EXPECT_TRUE(external["external_reported_ms"].is_null());
        EXPECT_TRUE(external["crawl"].is_null()) << "needs moved scenes: not measured";
    }
    // Each external row right after its pattern's method rows.
    EXPECT_EQ(r[1]["method"], "external:self");
    EXPECT_EQ(r[3]["method"], "external:self");
}

TEST_F(External, ReportedTimeIsTheMedianOfWhatTheCommandPrinted) {
    write_image(path("pre.png"),
                render_scene(*make_method("exact").method, make_pattern("strips", 20, 16)));
    const Output o = run(fmt::format(
        "compare --patterns strips --size 20x16 --methods none --runs 3 --no-hardcases --quiet "
        "--out {} --external \"copy=cp {} {{out}} && echo aabench-time-ms: 2.5\"",
        path("run"), path("pre.png")));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    const nlohmann::json all = rows("run");
    const auto& row = find_row(all, "strips", "external:copy");
    EXPECT_EQ(row["external_reported_ms"].get<double>(), 2.5);
    EXPECT_EQ(row["time_runs"].get<int>(), 3);
}

TEST_F(External, WorkedExampleRsvgConvertLandsOnCairo) {
    ASSERT_EQ(std::system("command -v rsvg-convert >/dev/null"), 0)
        << "rsvg-convert is missing: scripts/install-deps installs librsvg2-bin";
    const Output o = run(fmt::format(
        "compare --patterns star,strips --size 64x64 --methods cairo:paths=per-shape --runs 1 "
        "--no-hardcases "
        "--quiet --out {} --external \"rsvg=rsvg-convert {{svg}} -o {{out}}\"",
        path("run")));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    const nlohmann::json r = rows("run");
    for (const char* pattern : {"star", "strips"}) {
        // The SVG holds one path element per shape, which rsvg fills one by one: Cairo's
        // per-shape fills are its twin.
        const double cairo =
            find_row(r, pattern, make_method("cairo:paths=per-shape").spec)["box_rmse"];
        const double rsvg = find_row(r, pattern, "external:rsvg")["box_rmse"];
        EXPECT_NEAR(rsvg, cairo, kOneEightBitCode) << pattern;
    }
    EXPECT_TRUE(fs::exists(path("run/index.html")));
}

void expect_one_line(const Output& o, const std::string& needle) {
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_NE(o.err.find(needle), std::string::npos) << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
}

TEST_F(External, ABadRendererIsOneLineExitTwoAndNothingWritten) {
    const std::string base =
        "compare --patterns star --size 16x16 --methods none --runs 1 "
        "--no-hardcases --quiet --out " +
        path("run") + " --external ";
    expect_one_line(run(base + "\"bad=false {out}\""), "--external bad: the command exited 1");
    expect_one_line(run(base + "\"bad=true\""), "never names {out}");
    expect_one_line(run(base + "\"bad=true {out}\""), "wrote no image");
    expect_one_line(
        run(base + fmt::format("\"small={} render --pattern star --size 8x8 --method none "
                               "--out {{out}}\"",
                               AABENCH_BINARY)),
        "the image is 8x8 but the scene is 16x16");
    expect_one_line(run(base + "\"no name here\""), "is not NAME");
    expect_one_line(run(base + "\"a=true {out}\" --external \"a=true {out}\""), "given twice");
    EXPECT_FALSE(fs::exists(path("run")));
}

TEST(SceneSvg, PathsInOrderWithNonzeroRuleAndLinearGreys) {
    Scene scene;
    scene.width = 10;
    scene.height = 8;
    scene.background = 0.25;
    scene.shapes.push_back({{{{1, 1}, {5, 1}, {5, 4}}, {{2, 2}, {3, 2}, {3, 3}}}, 1.0});
    scene.shapes.push_back({{{{0.5, 0.125}, {9, 7}, {1, 7}}}, 0.5});
    const std::string svg = scene_to_svg(scene);
    EXPECT_NE(svg.find("viewBox=\"0 0 10 8\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("<rect x=\"0\" y=\"0\" width=\"10\" height=\"8\" fill=\"#404040\"/>"),
              std::string::npos)
        << svg;  // round(0.25 * 255) = 64
    const auto first = svg.find("fill=\"#ffffff\" d=\"M1 1 L5 1 L5 4 Z M2 2 L3 2 L3 3 Z\"");
    const auto second = svg.find("fill=\"#808080\" d=\"M0.5 0.125 L9 7 L1 7 Z\"");
    ASSERT_NE(first, std::string::npos) << svg;
    ASSERT_NE(second, std::string::npos) << svg;
    EXPECT_LT(first, second);
    EXPECT_EQ(std::count(svg.begin(), svg.end(), '<') - 2,  // the xml declaration, </svg>
              2 + 1 + 1);                                   // <svg>, <rect>, two <path>
    // A world not yet drawn is refused: SVG holds what methods draw.
    EXPECT_THROW(scene_to_svg(make_pattern("room", 16, 16)), InputError);
}

TEST(SceneSvg, DiscsAndRingsAreWrittenAsArcsNotAsTheirPolygonisation) {
    Scene scene;
    scene.width = 16;
    scene.height = 16;
    scene.shapes.push_back(disc_shape({8, 8}, 2.5, 1.0));
    scene.shapes.push_back(ring_shape({4, 4}, 1, 3, 0.5));
    const std::string svg = scene_to_svg(scene);
    // The disc: two half circles of radius 2.5 about (8, 8), clockwise on screen (sweep 1).
    EXPECT_NE(svg.find("d=\"M10.5 8 A2.5 2.5 0 1 1 5.5 8 A2.5 2.5 0 1 1 10.5 8 Z\""),
              std::string::npos)
        << svg;
    // The ring: its outer circle one way, the hole the other, so that nonzero leaves it empty.
    EXPECT_NE(svg.find("d=\"M7 4 A3 3 0 1 1 1 4 A3 3 0 1 1 7 4 Z M5 4 A1 1 0 1 0 3 4 A1 1 0 1 0 5 "
                       "4 Z\""),
              std::string::npos)
        << svg;
    EXPECT_EQ(svg.find(" L"), std::string::npos) << "no polygon edge: " << svg;
}

TEST_F(External, ExportWritesSvgAndRefusesOtherFormats) {
    ASSERT_EQ(run("export --pattern room --size 16x12 --out " + path("room.svg")).exit_code, 0);
    std::ifstream in(path("room.svg"));
    const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(svg.find("fill-rule=\"nonzero\""), std::string::npos);
    expect_one_line(run("export --pattern star --size 16x12 --out " + path("star.txt")),
                    "unsupported format");
    EXPECT_FALSE(fs::exists(path("star.txt")));
}

}  // namespace
}  // namespace aabench
