// The edge stage's timings read from Google Benchmark JSON (harness/measure/edge_timing.h) and
// drawn in the report (harness/report/html_report.cpp, with cost_plot.h's log-log plot), on a
// hand-written document whose slopes are known: time = 1e-5 ms x pixels (slope 1), a flat
// 2 ms against faces (slope 0), and the depth image at 0.1 ms x faces^0.5 (slope 0.5).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "harness/measure/edge_timing.h"
#include "harness/report/cost_plot.h"
#include "harness/report/html_report.h"
#include "patterns/scene/scene.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// One benchmark entry as Google Benchmark writes it (real_time in `unit`).
std::string entry(const std::string& name, double real_time, const std::string& unit) {
    return fmt::format(
        R"({{"name": "{}/real_time", "run_name": "{}/real_time", "run_type": "iteration",
            "real_time": {:.17g}, "cpu_time": {:.17g}, "time_unit": "{}", "Mpixel/s": 1}})",
        name, name, real_time, real_time, unit);
}

std::string document() {
    std::string items;
    for (const long long pixels : {65536LL, 262144LL, 1048576LL, 4194304LL}) {
        // Each in another unit: the reader converts them all to ms.
        const double ms = 1e-5 * static_cast<double>(pixels);
        const bool in_us = pixels == 262144LL;
        items += entry(fmt::format("cost/edge-pixels/edge-stage/{}", pixels),
                       in_us ? ms * 1e3 : ms, in_us ? "us" : "ms") + ",";
    }
    for (const int faces : {100, 1000, 10000, 100000}) {
        items += entry(fmt::format("cost/edge-faces/edge-stage/{}", faces), 2.0, "ms") + ",";
        items += entry(fmt::format("cost/depth-faces/exact/{}", faces),
                       0.1 * std::sqrt(faces) * 1e6, "ns") + ",";
    }
    items += entry("cost/pixels/exact/65536", 9.0, "ms") + ",";  // the cost model: not ours
    items += entry("exact/torus/256", 5.0, "ms");
    return R"({"context": {}, "benchmarks": [)" + items + "]}";
}

// Unit conversions and logs of exact powers in double: rounding only.
constexpr double kRelativeTolerance = 1e-9;
constexpr double kSlopeTolerance = 1e-9;

TEST(EdgeTiming, SeriesInMsWithTheSlopesOfKnownPowers) {
    const EdgeTimings t = edge_timings_from_benchmark(document(), "doc");
    ASSERT_EQ(t.pixels.size(), 1u);
    ASSERT_EQ(t.faces.size(), 2u);
    EXPECT_EQ(t.pixels[0].name, "edge-stage");
    ASSERT_EQ(t.pixels[0].points.size(), 4u);
    for (const auto& [pixels, ms] : t.pixels[0].points) {
        EXPECT_NEAR(ms, 1e-5 * pixels, kRelativeTolerance * ms) << pixels;
    }
    EXPECT_NEAR(fit_log_log(t.pixels[0].points).slope, 1.0, kSlopeTolerance);
    for (const EdgeTimingSeries& s : t.faces) {
        ASSERT_EQ(s.points.size(), 4u) << s.name;
        const bool depth = s.name == "depth image by exact";
        EXPECT_TRUE(depth || s.name == "edge-stage") << s.name;
        EXPECT_NEAR(fit_log_log(s.points).slope, depth ? 0.5 : 0.0, kSlopeTolerance) << s.name;
        EXPECT_EQ(s.points.front().first, 100.0);
        EXPECT_EQ(s.points.back().first, 100000.0);
    }
}

TEST(EdgeTiming, TheMedianAggregateIsTakenOverRepetitions) {
    std::string items;
    for (double ms : {3.0, 30.0, 4.0}) {
        items += entry("cost/edge-faces/edge-stage/1000", ms, "ms") + ",";
    }
    items += R"({"name": "cost/edge-faces/edge-stage/1000/real_time_median",
                 "run_name": "cost/edge-faces/edge-stage/1000/real_time", "run_type": "aggregate",
                 "aggregate_name": "median", "real_time": 4, "time_unit": "ms"},
                {"name": "cost/edge-faces/edge-stage/1000/real_time_cv",
                 "run_name": "cost/edge-faces/edge-stage/1000/real_time", "run_type": "aggregate",
                 "aggregate_name": "cv", "real_time": NaN, "time_unit": "ms"})";
    const EdgeTimings t = edge_timings_from_benchmark(R"({"benchmarks": [)" + items + "]}", "d");
    ASSERT_EQ(t.faces.size(), 1u);
    ASSERT_EQ(t.faces[0].points.size(), 1u);
    EXPECT_EQ(t.faces[0].points[0].second, 4.0);
    EXPECT_TRUE(t.pixels.empty());
}

TEST(EdgeTiming, BadInputIsAnInputErrorNamingTheSource) {
    EXPECT_THROW(edge_timings_from_benchmark("{", "b.json"), InputError);
    try {
        edge_timings_from_benchmark(
            R"({"benchmarks": [)" + entry("cost/edge-faces/edge-stage/many", 1.0, "ms") + "]}",
            "b.json");
        FAIL() << "no throw";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("b.json"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("edge-stage/many"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(edge_timings_from_benchmark(R"({"benchmarks": []})", "b.json").empty());
}

// The report draws both plots, with their slopes, when given the timings, and leaves the
// section out when not.
TEST(EdgeTiming, TheReportShowsBothPlotsWithTheirSlopes) {
    const fs::path dir =
        fs::temp_directory_path() / fmt::format("aabench_edge_timing_test-{}", ::getpid());
    fs::remove_all(dir);
    ReportData data;
    data.edge_timings = edge_timings_from_benchmark(document(), "doc");
    write_html_report(dir.string(), data);
    std::stringstream page;
    page << std::ifstream(dir / "index.html").rdbuf();
    const std::string html = page.str();
    EXPECT_NE(html.find("id=\"edge-timing\""), std::string::npos);
    EXPECT_NE(html.find("edge-stage  (slope 1.00)"), std::string::npos);
    EXPECT_NE(html.find("edge-stage  (slope 0.00)"), std::string::npos);
    EXPECT_NE(html.find("depth image by exact  (slope 0.50)"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir / "plots" / "edge-timing-pixels.svg"));
    EXPECT_TRUE(fs::exists(dir / "plots" / "edge-timing-faces.svg"));
    fs::remove_all(dir);
    write_html_report(dir.string(), ReportData{});
    std::stringstream empty;
    empty << std::ifstream(dir / "index.html").rdbuf();
    EXPECT_EQ(empty.str().find("edge-timing"), std::string::npos);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace aabench
