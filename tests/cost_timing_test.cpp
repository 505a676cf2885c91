// The cost model read from Google Benchmark JSON (harness/measure/cost_timing.h) and drawn in
// the report (harness/report/cost_plot.h), on a hand-written document whose answers are known:
// times of exact powers of the size, so the fitted slopes are those powers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "harness/measure/cost_timing.h"
#include "harness/report/cost_plot.h"
#include "patterns/scene/scene.h"

namespace aabench {
namespace {

// Slopes of exact power laws come back to rounding; the fit is a few dozen flops.
constexpr double kSlopeTolerance = 1e-9;

// One run as Google Benchmark writes it with UseRealTime() (the "/real_time" suffix).
std::string run(const std::string& name, double real_time, const std::string& unit) {
    return fmt::format(
        R"({{"name": "{0}/real_time", "run_name": "{0}/real_time", "run_type": "iteration",
            "repetitions": 1, "real_time": {1}, "cpu_time": {1}, "time_unit": "{2}"}})",
        name, real_time, unit);
}

std::string median(const std::string& name, double real_time, const std::string& unit) {
    return fmt::format(
        R"({{"name": "{0}/real_time_median", "run_name": "{0}/real_time", "run_type": "aggregate",
            "aggregate_name": "median", "real_time": {1}, "cpu_time": {1}, "time_unit": "{2}"}})",
        name, real_time, unit);
}

// exact: t = 1e-5 ms x pixels (slope 1); ssaa:k=3,...: t = 1e-3 ms x pixels^0.5 in us; against
// edges, exact: t = 2e-3 ms x edges^0.25, given as a median beside a single run that must lose.
std::string document() {
    std::string items;
    auto add = [&](const std::string& item) { items += (items.empty() ? "" : ",") + item; };
    for (const double pixels : {16384.0, 65536.0, 262144.0, 1048576.0}) {
        add(run(fmt::format("cost/pixels/exact/{}", pixels), 1e-5 * pixels, "ms"));
        add(run(fmt::format("cost/pixels/ssaa:k=3,filter=box/{}", pixels),
                1e-3 * std::sqrt(pixels) * 1e3, "us"));
    }
    for (const double edges : {192.0, 3072.0, 49152.0}) {
        const std::string name = fmt::format("cost/edges/exact/{}", edges);
        add(run(name, 999.0, "ms"));  // a repetition: the median wins
        add(median(name, 2e-3 * std::pow(edges, 0.25) * 1e6, "ns"));
    }
    add(run("none/star/1024", 1.0, "ms"));  // not a cost benchmark: ignored
    add(run("circle/fill/r=4", 1.0, "ns"));
    return R"({"context": {}, "benchmarks": [)" + items + "]}";
}

const CostSeries* find(const std::vector<CostSeries>& all, const std::string& method) {
    for (const CostSeries& s : all) {
        if (s.method == method) return &s;
    }
    return nullptr;
}

TEST(CostTiming, ReadsBothAxesAndTheFitGivesThePowers) {
    const CostModel model = cost_model_from_benchmark(document(), "doc.json");
    ASSERT_EQ(model.pixels.size(), 2u);
    ASSERT_EQ(model.edges.size(), 1u);
    const CostSeries* exact = find(model.pixels, "exact");
    const CostSeries* ssaa = find(model.pixels, "ssaa:k=3,filter=box");
    ASSERT_NE(exact, nullptr);
    ASSERT_NE(ssaa, nullptr);
    ASSERT_EQ(exact->points.size(), 4u);
    EXPECT_DOUBLE_EQ(exact->points.front().first, 16384.0);  // ascending size
    EXPECT_NEAR(exact->points.front().second, 0.16384, 1e-12);  // ms
    EXPECT_NEAR(fit_log_log(exact->points).slope, 1.0, kSlopeTolerance);
    EXPECT_NEAR(fit_log_log(ssaa->points).slope, 0.5, kSlopeTolerance);
    const CostSeries& edges = model.edges.front();
    ASSERT_EQ(edges.points.size(), 3u);
    EXPECT_NEAR(edges.points.front().second, 2e-3 * std::pow(192.0, 0.25), 1e-12);  // not 999
    EXPECT_NEAR(fit_log_log(edges.points).slope, 0.25, kSlopeTolerance);
}

TEST(CostTiming, TheReportPlotCarriesTheSlopes) {
    const CostModel model = cost_model_from_benchmark(document(), "doc.json");
    const std::string svg = cost_model_svg(model.pixels, "pixels", "Cost against pixels");
    EXPECT_NE(svg.find("slope 1.00"), std::string::npos) << svg.substr(0, 400);
    EXPECT_NE(svg.find("slope 0.50"), std::string::npos);
}

TEST(CostTiming, NoCostBenchmarksGiveAnEmptyModel) {
    const std::string doc =
        R"({"benchmarks": [{"name": "exact/star/1024/real_time", "real_time": 1.0}]})";
    EXPECT_TRUE(cost_model_from_benchmark(doc, "x.json").empty());
}

TEST(CostTiming, ASizeThatIsNotANumberIsAnErrorNamingTheFileAndBenchmark) {
    const std::string doc =
        R"({"benchmarks": [{"name": "cost/pixels/exact/lots/real_time", "real_time": 1.0}]})";
    try {
        cost_model_from_benchmark(doc, "bad.json");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.json"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("cost/pixels/exact/lots"), std::string::npos);
    }
}

TEST(CostTiming, NotBenchmarkJsonIsAnError) {
    EXPECT_THROW(cost_model_from_benchmark("not json", "x.json"), InputError);
}

}  // namespace
}  // namespace aabench
