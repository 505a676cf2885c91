// Error figures on images whose answers are known by hand, and the comparison run's rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "harness/measure/compare.h"
#include "harness/measure/metrics.h"
#include "methods/method.h"
#include "patterns/scene/scene.h"

namespace aabench {
namespace {

// Sums run in double over a handful of pixels holding float32-exact values (multiples of
// 1/8): only the final square root rounds.
constexpr double kSumTolerance = 1e-12;

TEST(Metrics, KnownErrors) {
    Coverage ref(4, 2, 0.0);
    Image img(4, 2, 0.0f);
    img.at(1, 0) = 0.5f;    // +0.5
    img.at(3, 1) = -0.25f;  // -0.25
    const ErrorStats s = compare_to_reference(img, ref);
    EXPECT_NEAR(s.rmse, std::sqrt((0.25 + 0.0625) / 8.0), kSumTolerance);
    EXPECT_NEAR(s.bias, (0.5 - 0.25) / 8.0, kSumTolerance);
    EXPECT_EQ(s.max_abs, 0.5);
    EXPECT_EQ(s.max_x, 1);
    EXPECT_EQ(s.max_y, 0);
    EXPECT_EQ(s.nonfinite, 0);
}

TEST(Metrics, DropoutCountsVanishedCoveredPixels) {
    Coverage ref(4, 1, 0.0);
    ref.at(0, 0) = 0.5;   // candidate, rendered 0 -> dropped
    ref.at(1, 0) = 0.5;   // candidate, rendered 0.5 -> kept
    ref.at(2, 0) = 0.05;  // not a candidate (coverage below the threshold)
    Image img(4, 1, 0.0f);
    img.at(1, 0) = 0.5f;
    const ErrorStats s = compare_to_reference(img, ref);
    EXPECT_EQ(s.dropout_candidates, 2);
    EXPECT_EQ(s.dropout_pixels, 1);
    EXPECT_EQ(s.dropout, 0.5);
}

TEST(Metrics, NanNeverLooksLikeASmallError) {
    Coverage ref(2, 2, 0.0);
    Image img(2, 2, 0.0f);
    img.at(1, 1) = std::numeric_limits<float>::quiet_NaN();
    const ErrorStats s = compare_to_reference(img, ref);
    EXPECT_EQ(s.nonfinite, 1);
    EXPECT_FALSE(s.rmse <= 1.0);
    EXPECT_FALSE(s.max_abs <= 1.0);
}

TEST(Compare, SplitSpecListKeepsParametersWithTheirSpec) {
    const auto specs = split_spec_list("ssaa:k=3,filter=box,none,gauss-multiscan:n=6");
    ASSERT_EQ(specs.size(), 3u);
    EXPECT_EQ(specs[0], "ssaa:k=3,filter=box");
    EXPECT_EQ(specs[1], "none");
    EXPECT_EQ(specs[2], "gauss-multiscan:n=6");
    EXPECT_THROW(split_spec_list("none,,exact"), InputError);
}

TEST(Compare, RowsCoverEveryMethodAndPatternAndExactIsNearZero) {
    CompareOptions options;
    options.width = 40;
    options.height = 32;
    options.runs = 1;
    const auto rows = run_comparison(options).rows;
    std::size_t patterns = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        if (k == 0 || rows[k].pattern != rows[k - 1].pattern) ++patterns;
        if (rows[k].method_id == "exact") {
            // Float32 rounding of values in [0, 1]: at most half an ulp at 1.0.
            EXPECT_LE(rows[k][metric::kBoxMaxAbs], 0.5 * std::numeric_limits<float>::epsilon());
        }
        EXPECT_EQ(rows[k][metric::kNonfinite], 0);
        if (rows[k].not_applicable.empty()) {
            EXPECT_GT(rows[k][metric::kTimeMedianNs], 0.0);
        } else {  // a method that cannot draw the pattern (circle methods on polygons): no time
            EXPECT_TRUE(std::isnan(rows[k][metric::kTimeMedianNs])) << rows[k].method;
        }
    }
    // Every method at its defaults, and the other readings the rows name (fast-edge's variant);
    // temporal methods run on sequences only (compare --sequences).
    std::size_t methods = 0;
    for (const MethodInfo& info : method_registry()) {
        if (info.traits->temporal) continue;
        methods += 1 + info.default_run_variants.size();
    }
    EXPECT_EQ(rows.size(), patterns * methods);
    EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [](const ResultRow& r) {
        return r.method == make_method("fast-edge:inset=0.5").spec;
    }));
}

TEST(Compare, BadSpecFailsBeforeAnyWork) {
    CompareOptions options;
    options.method_specs = {"exact", "no-such"};
    std::size_t calls = 0;
    EXPECT_THROW(run_comparison(options, [&](auto, auto, const auto&) { ++calls; }), InputError);
    EXPECT_EQ(calls, 0u);
}

}  // namespace
}  // namespace aabench
