// Every method on Bezier curves (scene file version 4): each draws the curve patterns as its
// row's `curves` trait says, with finite values in the scene's range, and the methods with a
// tolerance come closer to the exact image as it shrinks (the flattening is theirs, not the
// scene's).
#include <gtest/gtest.h>

#include <cmath>

#include "harness/measure/compare.h"
#include "harness/measure/metric_registry.h"
#include "harness/measure/metrics.h"
#include "harness/reference/box_reference.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

double rmse(const Image& image, const Coverage& reference) {
    return compare_to_reference(image, reference).rmse;
}

TEST(BezierMethods, EveryMethodDrawsTheCurvePatternsWithinTheirRange) {
    for (const char* pattern : {"curves", "crescents"}) {
        const Scene scene = make_pattern(pattern, 48, 40);
        ASSERT_TRUE(has_bezier(scene)) << pattern;
        const auto [lo, hi] = scene.value_range();
        int drawn = 0;
        for (const MethodInfo& info : method_registry()) {
            EXPECT_FALSE(info.traits->curves.empty()) << info.id;
            const MethodInstance m = make_method(info.id);
            if (!m.method->not_applicable(scene).empty()) {
                EXPECT_EQ(info.traits->curves.rfind("n/a", 0), 0u) << info.id << " on " << pattern;
                continue;
            }
            const Image image = render_scene(*m.method, scene);
            for (float v : image.data) {
                ASSERT_TRUE(std::isfinite(v) && v >= lo - 1e-6 && v <= hi + 1e-6)
                    << info.id << " on " << pattern << ": " << v;
            }
            ++drawn;
        }
        EXPECT_GT(drawn, 12) << pattern;
    }
}

// A flattening method's own tolerance moves its image towards the exact one: the error of a
// fine tolerance is below that of a coarse one, on the petals' curvature.
TEST(BezierMethods, ATighterToleranceComesCloserToExact) {
    const Scene scene = make_pattern("curves", 64, 64);
    const Coverage reference = box_reference(scene);
    const std::pair<const char*, const char*> pairs[] = {
        {"cairo:tolerance=1", "cairo:tolerance=0.01"},
        {"agg:approximation_scale=0.1", "agg:approximation_scale=10"},
        {"fast-edge:inset=0.5,flatness=2", "fast-edge:inset=0.5,flatness=0.01"},
        {"gl-msaa:flatness=2", "gl-msaa:flatness=0.01"},
    };
    for (const auto& [coarse, fine] : pairs) {
        const double e_coarse = rmse(render_scene(*make_method(coarse).method, scene), reference);
        const double e_fine = rmse(render_scene(*make_method(fine).method, scene), reference);
        EXPECT_LT(e_fine, e_coarse) << coarse << " vs " << fine;
    }
}

// flatten_bias (harness/measure/metric_registry.cpp) is there for the methods that flatten, on
// curves only; a flattening finer than the image can show leaves no bias, a coarse one a
// positive one (the chords lie inside every convex arc).
TEST(BezierMethods, FlattenBiasIsMeasuredWhereAMethodFlattens) {
    CompareOptions options;
    options.pattern_specs = {"curves", "star"};
    options.method_specs = {
        "cairo", "agg",  "fast-edge:inset=0.5", "gl-msaa",
        "exact", "none", "cairo:tolerance=2",   "fast-edge:inset=0.5,flatness=0.0001"};
    options.width = 48;
    options.height = 48;
    options.runs = 1;
    const MetricId bias = *MetricRegistry::global().find("flatten_bias");
    const auto rows = run_comparison(options).rows;
    ASSERT_EQ(rows.size(), 16u);
    for (const ResultRow& r : rows) {
        const bool flattens = r.method_id != "exact" && r.method_id != "none";
        const bool curves = r.pattern.rfind("curves", 0) == 0;
        EXPECT_EQ(std::isnan(r[bias]), !(flattens && curves)) << r.pattern << " " << r.method;
        if (r.method == make_method("cairo:tolerance=2").spec && curves) {
            EXPECT_GT(r[bias], 0.01) << "a 2 px flattening";
        }
        if (r.method == make_method("fast-edge:inset=0.5,flatness=0.0001").spec && curves) {
            EXPECT_LT(std::abs(r[bias]), 1e-4) << "the scene's own flattening";
        }
    }
}

}  // namespace
}  // namespace aabench
