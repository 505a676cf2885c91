// The method traits (methods/method_traits.h): every registered row's are complete, and a
// method defined in one file (here: one class and one row, added by a ScopedMethodRow) goes
// through everything the harness asks of a method — memory and time estimates, the hard-case
// suite with its documented bounds, a comparison — without any other file naming it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/measure/compare.h"
#include "harness/measure/hardcases.h"
#include "harness/measure/limits.h"
#include "harness/reference/box_reference.h"
#include "harness/reference/filter_reference.h"
#include "methods/method.h"
#include "methods/post_process.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

constexpr int kSide = 64;  // the default run's size

// ---- Every registered row ----

TEST(MethodTraits, EveryRowsFilterParsesBackToItself) {
    for (const MethodInfo& info : method_registry()) {
        const MethodInstance m = make_method(info.id);
        const Filter& filter = m.method->filter();
        EXPECT_EQ(Filter::parse(filter.text()), filter) << info.id;
        EXPECT_EQ(canonical_reference_spec(filter.text()), filter.text()) << info.id;
    }
}

TEST(MethodTraits, EveryRowsEstimatesAreFiniteAndPositiveOnEveryPattern) {
    for (const PatternInfo& pattern : pattern_registry()) {
        if (pattern.model_file) continue;  // tests/mesh_patterns_test.cpp
        const SceneSize size = measure_scene(make_pattern(pattern.id, kSide, kSide));
        for (const MethodInfo& info : method_registry()) {
            const MethodInstance m = make_method(info.id);
            const double bytes = m.method->traits().working_bytes(m.params, size);
            const double ms = estimate_render_ms(m, size);
            EXPECT_TRUE(std::isfinite(bytes) && bytes > 0.0) << info.id << " on " << pattern.id;
            EXPECT_TRUE(std::isfinite(ms) && ms > 0.0) << info.id << " on " << pattern.id;
        }
    }
}

TEST(MethodTraits, TimeEstimatesGrowWithTheCostParameter) {
    const SceneSize size = measure_scene(make_pattern("rings", kSide, kSide));
    for (const MethodInfo& info : method_registry()) {
        if (info.cost_param.empty()) continue;
        // A curve tolerance (cairo, agg, fast-edge, gl-msaa) costs nothing on a polygon
        // pattern such as this one, and its estimate rightly stays put there.
        if (info.sweep_on_curves_only) continue;
        const double lo = estimate_render_ms(
            make_method(info.id + ":" + info.cost_param + "=" +
                        format_real(info.sweep_values.front())),
            size);
        const double hi = estimate_render_ms(
            make_method(info.id + ":" + info.cost_param + "=" +
                        format_real(info.sweep_values.back())),
            size);
        EXPECT_LT(lo, hi) << info.id;
    }
}

TEST(MethodTraits, MsaaSamplesAreACountNotASide) {
    // ssaa:pattern=msaa,k=16 takes 16 samples per pixel, fewer than the grid's 16 x 16: its
    // estimates must be the smaller, and its sampling bound not the grid's 1/16.
    const SceneSize size = measure_scene(make_pattern("star", kSide, kSide));
    const MethodInstance grid = make_method("ssaa:k=16");
    const MethodInstance msaa = make_method("ssaa:k=16,pattern=msaa");
    EXPECT_LT(estimate_render_ms(msaa, size), estimate_render_ms(grid, size));
    EXPECT_LT(msaa.method->traits().working_bytes(msaa.params, size),
              grid.method->traits().working_bytes(grid.params, size));
    EXPECT_DOUBLE_EQ(grid.method->traits().hard_cases.figures(grid.params).edge_pixel_error,
                     1.0 / 16.0);
    EXPECT_DOUBLE_EQ(msaa.method->traits().hard_cases.figures(msaa.params).edge_pixel_error, 1.0);
}

TEST(MethodTraits, DocumentedBoundsHaveTheirFigures) {
    // Each documented bound the suite computes from a figure finds it set in the row.
    for (const std::string& spec : default_hard_case_methods()) {
        const MethodInstance m = make_method(spec);
        const HardCaseTraits& hc = m.method->traits().hard_cases;
        const BoundFigures figures = hc.figures(m.params);
        for (const DocumentedProperty& p : hc.properties) {
            EXPECT_FALSE(p.reason.empty()) << spec;
            switch (p.bound) {
                case DocumentedBound::kSamplingArea:
                    EXPECT_TRUE(figures.edge_pixel_error > 0.0 && figures.edge_pixel_error <= 1.0)
                        << spec;
                    break;
                case DocumentedBound::kTrapezoidArea:
                    EXPECT_GE(figures.sub_scanlines, 1) << spec;
                    break;
                case DocumentedBound::kQuantisedArea:
                    EXPECT_GT(figures.coverage_step, 0.0) << spec;
                    EXPECT_GT(figures.vertex_grid_px, 0.0) << spec;
                    break;
                default:
                    break;
            }
            // An area bound is only checked for box-filter methods (the area invariant).
            if (p.invariant == Invariant::kArea) EXPECT_TRUE(m.method->filter().is_box()) << spec;
        }
    }
}

TEST(MethodTraits, ExactlyOneReferenceRendererWithAffineValues) {
    int count = 0;
    for (const MethodInfo& info : method_registry()) {
        count += info.traits->reference_renderer && info.traits->affine_values;
    }
    EXPECT_EQ(count, 1);  // the benchmark's edge-stage input is the one it finds
}

TEST(MethodTraits, TemporalRowsKeepState) {
    // A temporal row is fed frame by frame (Method::begin, render_frame): it makes a state,
    // and a spatial one does not.
    for (const MethodInfo& info : method_registry()) {
        EXPECT_EQ(make_method(info.id).method->begin(4, 4) != nullptr, info.traits->temporal)
            << info.id;
    }
}

TEST(MethodTraits, PostProcessRowsArePostProcessMethods) {
    // The harness finds a row's pass (and times it alone) through PostProcessMethod: the trait
    // and the class go together.
    int post_process_rows = 0;
    for (const MethodInfo& info : method_registry()) {
        const MethodInstance m = make_method(info.id);
        const bool is_pass = dynamic_cast<const PostProcessMethod*>(m.method.get()) != nullptr;
        EXPECT_EQ(info.traits->post_process, is_pass) << info.id;
        post_process_rows += info.traits->post_process;
    }
    EXPECT_GE(post_process_rows, 1);
}

TEST(MethodTraits, CircleOnlyRowsRefusePolygons) {
    const Scene star = make_pattern("star", kSide, kSide);
    for (const MethodInfo& info : method_registry()) {
        const bool circles_only = info.traits->applies_to == Applicability::kGridCirclesOnly;
        EXPECT_EQ(!make_method(info.id).method->not_applicable(star).empty(), circles_only)
            << info.id;
    }
}

// ---- A new method in this file only ----

// The exact box image rounded to `levels` steps of the value range: a stand-in with a
// documented property of its own (rounding, as exact-8bit's), so the hard-case suite's
// documented bounds are exercised for it. Tests may use the harness's reference; a real
// method may not.
constexpr char kDummyId[] = "test-rounded-box";

class RoundedBoxMethod : public Method {
public:
    explicit RoundedBoxMethod(int levels) : levels_(levels) {}

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        const Coverage exact = box_reference(scene);
        const auto [lo, hi] = scene.value_range();
        const double span = hi - lo;
        for (int j = row_lo; j < row_hi; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                double v = exact.at(i, j);
                if (span > 0.0) {
                    const double t = std::clamp((v - lo) / span * levels_, 0.0, double(levels_));
                    v = lo + span / levels_ * static_cast<int>(t + 0.5);
                }
                out.at(i, j) = static_cast<float>(v);
            }
        }
    }

private:
    int levels_;
};

MethodInfo dummy_row() {
    MethodTraits t;
    t.working_bytes = [](const ParamValues&, const SceneSize& s) { return 16.0 * s.pixels(); };
    t.time_ms = [](const ParamValues&, const SceneSize& s) {
        return 0.01 + 1e-6 * s.pixels() + 1e-4 * static_cast<double>(s.vertices);
    };
    // 255 levels: one 8-bit step, the bound the suite checks kRoundingStep against.
    t.hard_cases.properties = {
        {Invariant::kArea, CaseSet::kAll, DocumentedBound::kRoundingStep, "rounded to 8 bits"},
        {Invariant::kContinuity, CaseSet::kAll, DocumentedBound::kRoundingStep,
         "rounded to 8 bits: a value at half a step flips"},
        {Invariant::kTranslation, CaseSet::kAll, DocumentedBound::kRoundingStep,
         "rounded to 8 bits: a value at half a step flips"},
    };
    return with_traits(
        {kDummyId,
         "the exact box image rounded to 8 bits (a test row)",
         {{"levels", ParamKind::kInt, 255, 255, 255, {}, "steps of the value range"}},
         [](const ParamValues& p) { return std::make_unique<RoundedBoxMethod>(p.get_int("levels")); }},
        std::move(t));
}

TEST(MethodTraits, ANewRowGoesThroughTheHarness) {
    const ScopedMethodRow row(dummy_row());
    const MethodInstance m = make_method(kDummyId);
    EXPECT_EQ(m.spec, std::string(kDummyId) + ":levels=255");
    EXPECT_TRUE(m.method->filter().is_box());
    EXPECT_FALSE(m.method->own_visibility());

    // Limits: the memory estimate takes the row's working memory.
    const Scene star = make_pattern("star", kSide, kSide);
    const SceneSize size = measure_scene(star);
    EXPECT_GE(estimate_job_bytes(size, {m.spec}, {}),
              static_cast<std::size_t>(16.0 * size.pixels()));
    EXPECT_GT(estimate_render_ms(m, size), 0.0);

    // The hard-case suite: listed by default, and every nominal violation is documented by
    // its row, within the documented bound.
    const std::vector<std::string> defaults = default_hard_case_methods();
    EXPECT_NE(std::find(defaults.begin(), defaults.end(), kDummyId), defaults.end());
    int documented = 0;
    for (const HardCaseRow& r : run_hard_cases({m.spec})) {
        if (r.reference) continue;
        EXPECT_NE(r.outcome, Outcome::kFail) << r.case_name;
        documented += r.outcome == Outcome::kDocumented;
    }
    EXPECT_GT(documented, 0);  // the rounding is seen, and settled by the row's bound

    // A comparison: its rows, against the box reference, within half a step.
    CompareOptions options;
    options.method_specs = {m.spec};
    options.pattern_specs = {"star"};
    options.width = options.height = kSide;
    options.runs = 1;
    options.keep_images = false;
    options.symptoms = false;
    const CompareResult result = run_comparison(options);
    ASSERT_EQ(result.rows.size(), 1u);
    EXPECT_EQ(result.rows[0].method_id, kDummyId);
    EXPECT_EQ(result.rows[0].reference_filter, "box");
    // Rounding to 255 levels of [0, 1] errs by at most half a step, plus float32 rounding.
    constexpr double kHalfStep = 0.5 / 255.0 + 1e-6;
    EXPECT_LE(result.rows[0][metric::kBoxMaxAbs], kHalfStep);
}

TEST(MethodTraits, AScopedRowLeavesWithItsScope) {
    const std::size_t before = method_registry().size();
    {
        const ScopedMethodRow row(dummy_row());
        EXPECT_EQ(method_registry().size(), before + 1);
        EXPECT_THROW(ScopedMethodRow again(dummy_row()), InputError);
    }
    EXPECT_EQ(method_registry().size(), before);
    EXPECT_THROW(make_method(kDummyId), InputError);
}

TEST(MethodTraits, ARowWithoutEstimatesIsRefused) {
    // No neutral default exists for the estimates: a row must state them.
    MethodInfo row = dummy_row();
    row.traits = std::make_shared<const MethodTraits>();
    EXPECT_THROW(ScopedMethodRow{std::move(row)}, std::logic_error);
    MethodTraits partial;
    partial.working_bytes = [](const ParamValues&, const SceneSize&) { return 1.0; };
    EXPECT_THROW(with_traits(dummy_row(), std::move(partial)), std::logic_error);
}

}  // namespace
}  // namespace aabench
