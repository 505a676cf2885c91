// The pattern registry (patterns/pattern.h): a pattern defined in this file only, one generator
// and one row added by a ScopedPatternRow, is listed, parses with its parameters, renders
// through a method and the reference, and goes through a comparison without any other file
// naming it; it is gone when its scope ends. A 2-D row (a square, whose exact coverage is a
// product of two interval overlaps) and a 3-D row (a square quad facing the camera, through the
// prepared frame) are the recipes "A new 2-D pattern" and "A new 3-D pattern" of
// docs/contributing.md, done.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "harness/measure/compare.h"
#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

// The box reference's promise for a 2-D scene (docs/architecture.md, "What the references
// promise"): the exact area in double, to 1e-12 per pixel.
constexpr double kBoxReferencePerPixel = 1e-12;
// Its promise for a 3-D scene, through exact visibility: 1e-9 per pixel against an independent
// computation (here the closed-form square on screen).
constexpr double kWorldReferencePerPixel = 1e-9;
// `exact` computes the box reference's answer in double and writes float32: held to 1e-6 per
// pixel, 10x the float32 rounding of values <= 1 (docs/architecture.md).
constexpr double kExactMethodPerPixel = 1e-6;

// The covered length of [lo, lo + length] within the pixel interval [k, k + 1].
double overlap(double lo, double length, int k) {
    return std::max(0.0, std::min(lo + length, k + 1.0) - std::max(lo, double(k)));
}

// ---- A new 2-D pattern: one axis-aligned square ----

constexpr char kSquareId[] = "test-square";

Scene generate_square(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene(kSquareId, values, width, height);
    const double x0 = values.get_real("x0"), y0 = values.get_real("y0");
    const double side = values.get_real("side");
    Shape square;
    square.value = 1.0;
    square.contours.push_back({{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}});
    scene.shapes.push_back(std::move(square));
    set_focus(scene, x0 + 0.5 * side, y0 + 0.5 * side, kFocusSidePx);
    return scene;
}

PatternInfo square_row() {
    return PatternInfo{
        kSquareId,
        "one axis-aligned square off the pixel grid (a test row)",
        {
            {"x0", ParamKind::kReal, 3.25, -100, 100, {}, "left edge in px, off the grid"},
            {"y0", ParamKind::kReal, 2.625, -100, 100, {}, "top edge in px, off the grid"},
            {"side", ParamKind::kReal, 9.5, 0, 1000, {}, "side in px"},
        },
        generate_square,
    };
}

// `exact` on one pattern in a comparison, as `aabench compare` runs it (one timing run, no
// symptoms: the row's identity and error figures are what these tests read).
CompareResult compare_exact_on(const std::string& pattern_spec, int width, int height) {
    CompareOptions options;
    options.method_specs = {"exact"};
    options.pattern_specs = {pattern_spec};
    options.width = width;
    options.height = height;
    options.runs = 1;
    options.keep_images = false;
    options.symptoms = false;
    return run_comparison(options);
}

TEST(PatternRegistry, ANewRowIsListedParsedRenderedAndCompared) {
    const std::size_t before = pattern_registry().size();
    const ScopedPatternRow row(square_row());
    ASSERT_EQ(pattern_registry().size(), before + 1);
    EXPECT_EQ(pattern_registry().back().id, kSquareId);

    // The spec: parameters given and defaulted, in table order; a value out of range refused.
    const PatternInstance instance = resolve_pattern("test-square:side=7.5,x0=4.375");
    EXPECT_EQ(instance.spec, "test-square:x0=4.375,y0=2.625,side=7.5");
    EXPECT_THROW(resolve_pattern("test-square:side=-1"), InputError);

    constexpr int kWidth = 17, kHeight = 13;
    const Scene scene = make_pattern(instance.spec, kWidth, kHeight);
    ASSERT_FALSE(scene.metadata.empty());
    EXPECT_EQ(scene.metadata.front(),
              std::make_pair(std::string("pattern"), std::string(kSquareId)));

    // The reference and a method against the closed form.
    const Coverage reference = box_reference(scene);
    const MethodInstance exact = make_method("exact");
    const Image image = render_scene(*exact.method, scene);
    for (int j = 0; j < kHeight; ++j) {
        for (int i = 0; i < kWidth; ++i) {
            const double expected = overlap(4.375, 7.5, i) * overlap(2.625, 7.5, j);
            ASSERT_LE(std::abs(reference.at(i, j) - expected), kBoxReferencePerPixel)
                << "pixel (" << i << ", " << j << ")";
            ASSERT_LE(std::abs(image.at(i, j) - expected), kExactMethodPerPixel)
                << "pixel (" << i << ", " << j << ")";
        }
    }

    // A comparison names it like a built-in pattern.
    const CompareResult result = compare_exact_on(instance.spec, kWidth, kHeight);
    ASSERT_EQ(result.rows.size(), 1u);
    EXPECT_EQ(result.rows[0].pattern_id, kSquareId);
    EXPECT_LE(result.rows[0][metric::kBoxMaxAbs], kExactMethodPerPixel);
}

TEST(PatternRegistry, AScopedRowLeavesWithItsScope) {
    const std::size_t before = pattern_registry().size();
    {
        const ScopedPatternRow row(square_row());
        EXPECT_EQ(pattern_registry().size(), before + 1);
        EXPECT_THROW(ScopedPatternRow again(square_row()), InputError);
        PatternInfo built_in_id = square_row();
        built_in_id.id = "star";
        EXPECT_THROW(ScopedPatternRow{std::move(built_in_id)}, InputError);
    }
    EXPECT_EQ(pattern_registry().size(), before);
    EXPECT_THROW(resolve_pattern(kSquareId), InputError);
    // A row must generate something: no neutral default exists.
    PatternInfo empty = square_row();
    empty.generate = nullptr;
    EXPECT_THROW(ScopedPatternRow{std::move(empty)}, std::logic_error);
}

// ---- A new 3-D pattern: one quad facing the camera ----

constexpr char kQuadId[] = "test-quad";

Scene generate_quad(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene(kQuadId, values, width, height);
    const double a = values.get_real("half_size");
    World world;  // the default camera: eye (0, 0, 5) looking at the origin, fov 40 degrees
    world.objects.push_back(make_quad("quad", {-a, -a, 0}, {a, -a, 0}, {a, a, 0}, {-a, a, 0},
                                      values.get_real("reflectance")));
    scene.world = std::move(world);
    set_focus(scene, 0.5 * width, 0.5 * height, kFocusSidePx);
    return scene;
}

PatternInfo quad_row() {
    return PatternInfo{
        kQuadId,
        "one square quad facing the camera, no lights (a test row)",
        {
            {"half_size", ParamKind::kReal, 1.0, 0.1, 1.5, {}, "half the side, world units"},
            {"reflectance", ParamKind::kReal, 0.5, 0, 1, {}, "the value: no lights"},
        },
        generate_quad,
    };
}

TEST(PatternRegistry, ANew3dRowGoesThroughThePreparedFrame) {
    const ScopedPatternRow row(quad_row());
    constexpr int kWidth = 32, kHeight = 24;
    const std::string spec = resolve_pattern("test-quad:reflectance=0.75").spec;
    EXPECT_EQ(spec, "test-quad:half_size=1,reflectance=0.75");
    const Scene given = make_pattern(spec, kWidth, kHeight);
    ASSERT_TRUE(given.world.has_value());
    const PreparedFrame frame = PreparedFrame::prepare(given);
    ASSERT_TRUE(frame.is_world());
    EXPECT_TRUE(frame.costs()[static_cast<int>(Stage::kProjection)].ran);

    // On screen (docs/world.md: x = W/2 + f x_v / z_v, f = (H/2) / tan(fov/2)): a square of
    // half side f a / d about the image centre, d = 5 the eye's distance; value the reflectance.
    const double f = 0.5 * kHeight / std::tan(20.0 * std::numbers::pi / 180.0);
    const double half_px = f * 1.0 / 5.0;
    const double x0 = 0.5 * kWidth - half_px, y0 = 0.5 * kHeight - half_px;
    const Coverage reference = box_reference_of_pieces(frame.pieces().scene());
    const MethodInstance exact = make_method("exact");
    ASSERT_EQ(&frame.input_for(*exact.method).scene(), &frame.pieces().scene());
    const Image image = render_scene(*exact.method, frame.input_for(*exact.method));
    for (int j = 0; j < kHeight; ++j) {
        for (int i = 0; i < kWidth; ++i) {
            const double expected =
                0.75 * overlap(x0, 2 * half_px, i) * overlap(y0, 2 * half_px, j);
            ASSERT_LE(std::abs(reference.at(i, j) - expected), kWorldReferencePerPixel)
                << "pixel (" << i << ", " << j << ")";
            ASSERT_LE(std::abs(image.at(i, j) - expected), kExactMethodPerPixel)
                << "pixel (" << i << ", " << j << ")";
        }
    }

    // A method that removes hidden surfaces itself is handed the ScreenScene instead.
    for (const MethodInfo& info : method_registry()) {
        if (!info.traits->own_visibility) continue;
        const MethodInstance m = make_method(info.id);
        EXPECT_EQ(&frame.input_for(*m.method).scene(), &frame.screen()) << info.id;
    }

    // A comparison runs the world stages and records their cost in its row.
    const CompareResult result = compare_exact_on(spec, kWidth, kHeight);
    ASSERT_EQ(result.rows.size(), 1u);
    EXPECT_EQ(result.rows[0].pattern_id, kQuadId);
    EXPECT_FALSE(std::isnan(result.rows[0][stage_ms_metric(static_cast<int>(Stage::kProjection))]));
    EXPECT_LE(result.rows[0][metric::kBoxMaxAbs], kExactMethodPerPixel);
}

}  // namespace
}  // namespace aabench
