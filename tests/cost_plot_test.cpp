// The cost-model plot (harness/report/cost_plot.h): the fitted slope of exact power laws, the
// cases with no fit, and the elements the plot promises.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness/report/cost_plot.h"

namespace aabench {
namespace {

// A least-squares fit of exact power-law points in double: rounding of a few logs and sums,
// ~1e-15 relative; the bound leaves three orders of magnitude.
constexpr double kSlopeTolerance = 1e-12;

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

TEST(CostPlot, FitsAPowerLaw) {
    std::vector<std::pair<double, double>> points;
    for (const double x : {128.0 * 128, 512.0 * 512, 1024.0 * 1024, 4096.0 * 4096}) {
        points.push_back({x, 3.0 * std::pow(x, 0.75)});
    }
    const LogLogFit fit = fit_log_log(points);
    EXPECT_NEAR(fit.slope, 0.75, kSlopeTolerance);
    EXPECT_NEAR(fit.intercept, std::log(3.0), 1e-9);
}

TEST(CostPlot, NoFitWithoutTwoSizes) {
    EXPECT_TRUE(std::isnan(fit_log_log({}).slope));
    EXPECT_TRUE(std::isnan(fit_log_log({{10.0, 1.0}}).slope));
    EXPECT_TRUE(std::isnan(fit_log_log({{10.0, 1.0}, {10.0, 2.0}}).slope));
    // Non-positive or non-finite points are left out, not fitted.
    EXPECT_TRUE(std::isnan(fit_log_log({{10.0, 1.0}, {0.0, 2.0}, {NAN, 3.0}}).slope));
}

TEST(CostPlot, OneCurveFitAndSlopePerMethod) {
    std::vector<CostSeries> series = {
        {"none", {{1e4, 0.1}, {1e5, 1.0}, {1e6, 10.0}}},
        {"ssaa:k=3", {{1e4, 0.9}, {1e5, 9.0}, {1e6, 90.0}}},
        {"one-point", {{1e5, 5.0}}},
    };
    const std::string svg = cost_model_svg(series, "pixels", "a <title> & more");
    EXPECT_EQ(count(svg, "class=\"series\""), 3);
    EXPECT_EQ(count(svg, "class=\"curve\""), 3);
    EXPECT_EQ(count(svg, "class=\"point\""), 7);
    EXPECT_EQ(count(svg, "class=\"fit\""), 2);
    EXPECT_EQ(count(svg, "slope 1.00"), 2);
    EXPECT_EQ(count(svg, "no fit"), 1);
    EXPECT_NE(svg.find("a &lt;title&gt; &amp; more"), std::string::npos);
    EXPECT_EQ(svg.find("nan"), std::string::npos);
}

}  // namespace
}  // namespace aabench
