// The time-per-circle figures read from Google Benchmark JSON (harness/measure/circle_timing.h)
// and their plot (harness/report/circle_timing_plot.h), on a hand-written document whose
// answers are known: fill subtracted, divided by the circles drawn, slopes of exact powers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "harness/measure/circle_timing.h"
#include "harness/measure/timing.h"
#include "harness/report/circle_timing_plot.h"
#include "patterns/scene/scene.h"

namespace aabench {
namespace {

// One benchmark entry as Google Benchmark writes it (real_time in `unit`, counters top-level).
std::string entry(const std::string& name, double real_time, const std::string& unit,
                  double circles_per_s, double table_bytes) {
    return fmt::format(
        R"({{"name": "{}/real_time", "run_type": "iteration", "real_time": {}, "cpu_time": {},
            "time_unit": "{}", "circles/s": {}, "table_bytes": {}}})",
        name, real_time, real_time, unit, circles_per_s, table_bytes);
}

// Times in ns of 64 circles of radius r: 100 r (table) and 50 r^2 (on the fly), plus a fill of
// 10 r ns that must be subtracted.
std::string document() {
    std::string items;
    for (int r : {1, 4, 16, 64}) {
        const double fill = 10.0 * r, table = 64 * 100.0 * r + fill, fly = 64 * 50.0 * r * r + fill;
        if (!items.empty()) items += ",";
        items += entry(fmt::format("circle/fill/r={}", r), fill, "ns", 0.0, 0.0) + ",";
        // circles/s = 64 / time in s, as the benchmark's rate counter reports it.
        items += entry(fmt::format("circle/aa-circle-table/r={}", r), table / 1e3, "us",
                       64.0 / (table * 1e-9), 5935138.0) + ",";
        items += entry(fmt::format("circle/aa-circle-on-the-fly/r={}", r), fly, "ns",
                       64.0 / (fly * 1e-9), 0.0);
    }
    items += "," + entry("BM_other/star/256", 5.0, "ms", 0.0, 0.0);
    return R"({"context": {}, "benchmarks": [)" + items + "]}";
}

// The division by the circle count goes through a rounded count; the rest is double arithmetic.
constexpr double kRelativeTolerance = 1e-9;

TEST(CircleTiming, FillSubtractedPerCircleAndSlopesOfKnownPowers) {
    const std::vector<CircleTimingSeries> series = circle_timings_from_benchmark(document(), "doc");
    ASSERT_EQ(series.size(), 2u);  // fill and the non-circle benchmark are not series
    for (const CircleTimingSeries& s : series) {
        ASSERT_EQ(s.points.size(), 4u) << s.variant;
        for (const CircleTimingPoint& p : s.points) {
            const double want = s.variant == "aa-circle-table" ? 100.0 * p.radius
                                                               : 50.0 * p.radius * p.radius;
            EXPECT_NEAR(p.ns_per_circle, want, kRelativeTolerance * want) << s.variant << " r=" << p.radius;
        }
        const double slope = circle_timing_slope(s);
        EXPECT_NEAR(slope, s.variant == "aa-circle-table" ? 1.0 : 2.0, 1e-9) << s.variant;
        EXPECT_EQ(s.table_bytes, s.variant == "aa-circle-table" ? 5935138.0 : 0.0);
    }
    const std::string svg = circle_timing_svg(series, "t");
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    std::size_t groups = 0;
    for (std::size_t at = svg.find("class=\"series\""); at != std::string::npos;
         at = svg.find("class=\"series\"", at + 1)) {
        ++groups;
    }
    EXPECT_EQ(groups, 2u);
    EXPECT_NE(svg.find("slope 1.00"), std::string::npos);
    EXPECT_NE(svg.find("slope 2.00"), std::string::npos);
}

TEST(CircleTiming, TheMedianAggregateIsTakenOverRepetitions) {
    // Three repetitions of 64 circles in 640, 6400 and 1280 ns, and their median 1280 ns, as
    // --benchmark_repetitions=3 writes them (the aggregate named "<run_name>_median"), and the
    // coefficient of variation with the bare NaN / -Infinity tokens Google Benchmark writes.
    std::string items;
    for (double ns : {640.0, 6400.0, 1280.0}) {
        items += entry("circle/wu-circle/r=2", ns, "ns", 64.0 / (ns * 1e-9), 0.0) + ",";
    }
    items += R"({"name": "circle/wu-circle/r=2/real_time_median", "run_name": "circle/wu-circle/r=2/real_time",
                 "run_type": "aggregate", "aggregate_name": "median", "real_time": 1280, "time_unit": "ns",
                 "circles/s": 5e7},
                {"name": "circle/wu-circle/r=2/real_time_cv", "run_name": "circle/wu-circle/r=2/real_time",
                 "run_type": "aggregate", "aggregate_name": "cv", "real_time": 0.5, "time_unit": "ns",
                 "circles/s": NaN, "table_bytes": -Infinity, "label": "NaN in a string stays"})";
    const std::string text = R"({"benchmarks": [)" + items + "]}";
    // The bare tokens become null; the same letters inside a string stay as they are.
    const nlohmann::json doc = parse_benchmark_json(text, "doc");
    ASSERT_EQ(doc["benchmarks"].size(), 5u);
    EXPECT_TRUE(doc["benchmarks"][4]["circles/s"].is_null());
    EXPECT_TRUE(doc["benchmarks"][4]["table_bytes"].is_null());
    EXPECT_EQ(doc["benchmarks"][4]["label"], "NaN in a string stays");
    const auto series = circle_timings_from_benchmark(text, "doc");
    ASSERT_EQ(series.size(), 1u);
    ASSERT_EQ(series[0].points.size(), 1u);
    EXPECT_NEAR(series[0].points[0].ns_per_circle, 20.0, kRelativeTolerance * 20.0);
}

TEST(CircleTiming, NotBenchmarkJsonIsAnInputErrorNamingTheSource) {
    EXPECT_THROW(circle_timings_from_benchmark("{", "b.json"), InputError);
    try {
        circle_timings_from_benchmark(R"({"x": 1})", "b.json");
        FAIL() << "no throw";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("b.json"), std::string::npos);
    }
    EXPECT_TRUE(circle_timings_from_benchmark(R"({"benchmarks": []})", "b.json").empty());
}

}  // namespace
}  // namespace aabench
