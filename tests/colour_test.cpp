// Colour scenes (docs/colour.md): the file's colour values, the channel scenes, every channel of
// the references and of `exact` against a slow clipping oracle, every method's planes against its
// grey drawing of each channel, and the colour image files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>

#include "harness/reference/filter_reference.h"
#include "harness/report/image_io.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"
#include "tests/input_error_of.h"
#include "tests/registry_ids.h"
#include "tests/slow_reference.h"
#include "tests/test_names.h"
#include "tests/test_scenes.h"

namespace aabench {
namespace {

// `exact` is held within 1e-6 of the double box reference (methods/exact.cpp), and the float32
// image of values in [0, 1] rounds by at most 3e-8 more.
constexpr double kExactTolerance = 1e-6;
// The slow clipping reference against the box reference: both exact, apart by rounding of
// sums of a few hundred terms of size <= 1 (the box reference's own suite uses 1e-9).
constexpr double kReferenceTolerance = 1e-9;
// A grey render() of a colour scene draws the luminance (shape values are luminances): against
// the luminance of the planes, float32 rounding of three planes and of the sum, a few ulps of
// values in [0, 1].
constexpr double kLuminanceTolerance = 1e-6;
// A method that rounds its values to 8 bits (exact-8bit: DocumentedBound::kRoundingStep) rounds
// the luminance once and each channel once: apart by at most one step of the value range [0, 1].
constexpr double kRoundedLuminanceTolerance = 1.0 / 255.0 + 1e-6;

bool rounds_values(const Method& method) {
    for (const DocumentedProperty& p : method.traits().hard_cases.properties) {
        if (p.bound == DocumentedBound::kRoundingStep) return true;
    }
    return false;
}

Scene parse(const std::string& text) { return parse_scene_json(text, "test.json"); }

TEST(ColourScene, ReadsArraysAsLinearRgbWithLuminanceValues) {
    const Scene s = parse(R"({"version": 4, "width": 8, "height": 6, "background": [0.5, 0.25, 1],
        "shapes": [{"type": "polygon", "value": [0.9, 0.2, 0.1], "contours": [[[0,0],[4,0],[0,4]]]},
                   {"type": "polygon", "value": 0.75, "contours": [[[4,4],[8,4],[8,6]]]}]})");
    EXPECT_EQ(s.channels, 3);
    ASSERT_TRUE(s.background_rgb.has_value());
    EXPECT_EQ(*s.background_rgb, (Rgb{0.5, 0.25, 1.0}));
    EXPECT_DOUBLE_EQ(s.background, 0.2126 * 0.5 + 0.7152 * 0.25 + 0.0722 * 1.0);
    ASSERT_TRUE(s.shapes[0].rgb.has_value());
    EXPECT_DOUBLE_EQ(s.shapes[0].value, 0.2126 * 0.9 + 0.7152 * 0.2 + 0.0722 * 0.1);
    EXPECT_FALSE(s.shapes[1].rgb.has_value());  // a grey number means [n, n, n]
    for (int c = 0; c < 3; ++c) {
        const Scene ch = channel_scene(s, c);
        EXPECT_EQ(ch.channels, 1);
        EXPECT_FALSE(ch.background_rgb.has_value());
        EXPECT_EQ(ch.background, (Rgb{0.5, 0.25, 1.0})[static_cast<std::size_t>(c)]);
        EXPECT_EQ(ch.shapes[0].value, (Rgb{0.9, 0.2, 0.1})[static_cast<std::size_t>(c)]);
        EXPECT_EQ(ch.shapes[1].value, 0.75);
    }
    // A grey scene is one channel, and its channel scene is itself.
    const Scene grey = parse(R"({"version": 4, "width": 8, "height": 6, "background": 0.5,
        "shapes": [{"type": "polygon", "value": 0.9, "contours": [[[0,0],[4,0],[0,4]]]}]})");
    EXPECT_EQ(grey.channels, 1);
    EXPECT_EQ(channel_scene(grey, 0), grey);
}

TEST(ColourScene, AColourOnAnyShapeKindMakesAColourScene) {
    for (
        const char* shape :
        {R"({"type": "disc", "value": [0, 1, 0], "center": [4, 4], "radius": 2})",
         R"({"type": "ring", "value": [0, 1, 0], "center": [4, 4], "inner": 1, "outer": 2})",
         R"({"type": "path", "value": [0, 1, 0], "svg_path": "M 1 1 L 6 1 Q 7 5 1 5 Z"})",
         R"({"type": "polygon", "value": [0, 1, 0], "contours": [[[1,1], {"quad": [[7,3],[1,5]]}]]})"}) {
        const Scene s = parse(
            fmt::format(R"({{"version": 4, "width": 8, "height": 8, "shapes": [{}]}})", shape));
        EXPECT_EQ(s.channels, 3) << shape;
        ASSERT_TRUE(s.shapes[0].rgb.has_value()) << shape;
        EXPECT_DOUBLE_EQ(s.shapes[0].value, 0.7152) << shape;
    }
}

TEST(ColourScene, WriterRoundTripsColoursBitForBit) {
    Scene s = parse(R"({"version": 4, "width": 8, "height": 6, "background": [0.1, 0.2, 0.3],
        "shapes": [{"type": "polygon", "value": [0.9, 0.2, 0.1], "contours": [[[0,0],[4,0],[0,4]]]},
                   {"type": "disc", "value": [0.3, 0.6, 0.9], "center": [4, 3], "radius": 1.5},
                   {"type": "polygon", "value": 0.75, "contours": [[[4,4],[8,4],[8,6]]]}]})");
    const std::string json = scene_to_json(s);
    EXPECT_NE(json.find("\"version\": 4"), std::string::npos) << json;
    EXPECT_EQ(parse(json), s);
    // A colour scene whose every colour is grey stays a colour scene: its background is written
    // as an array.
    s = parse(R"({"version": 4, "width": 8, "height": 6, "background": [0.5, 0.5, 0.5],
        "shapes": [{"type": "polygon", "value": 1, "contours": [[[0,0],[4,0],[0,4]]]}]})");
    EXPECT_EQ(s.channels, 3);
    EXPECT_EQ(parse(scene_to_json(s)), s);
}

TEST(ColourScene, BadColoursAreOneLineErrorsNamingTheJsonPath) {
    const auto shape_with = [](const std::string& value) {
        return fmt::format(R"({{"version": 4, "width": 8, "height": 8, "shapes": [
            {{"type": "polygon", "value": {}, "contours": [[[0,0],[4,0],[0,4]]]}}]}})",
                           value);
    };
    const SceneErrorCase cases[] = {
        {shape_with("[1, 2]"), "shapes[0].value:", "three finite numbers"},
        {shape_with("[1, 2, 3, 4]"), "shapes[0].value:", "three finite numbers"},
        {shape_with("[]"), "shapes[0].value:", "three finite numbers"},
        {shape_with(R"([1, "a", 0])"), "shapes[0].value[1]:", "G component"},
        {shape_with("[1, [0], 0]"), "shapes[0].value[1]:", "finite number"},
        {shape_with("[1e31, 0, 0]"), "shapes[0].value[0]:", "1e30"},
        {shape_with("[0, 0, -2e30]"), "shapes[0].value[2]:", "1e30"},
        {R"({"version": 3, "width": 8, "height": 8, "background": [0, 0, 0], "shapes": []})",
         "background:", "version 4"},
        // A colour where a number is required.
        {R"({"version": 4, "width": 8, "height": 8, "shapes": [
             {"type": "disc", "value": [1, 0, 0], "center": [4, 4], "radius": [1, 1, 1]}]})",
         "shapes[0].radius:", "finite number"},
        {R"({"version": 4, "width": 8, "height": 8, "shapes": [{"type": "text", "value": [1, 0, 0],
             "font": "sans", "string": "a", "size_px": [12, 12, 12], "origin": [1, 7]}]})",
         "shapes[0].size_px", ""},
    };
    expect_scene_errors(cases, [](const std::string& text) { parse(text); });
}

// Random overlapping polygons with a random colour on each shape but a grey one, and a random
// background colour.
Scene random_colour_scene(std::uint64_t seed) {
    Scene scene = testing::random_scene(seed, 13, 11, /*snap_half_pixel=*/true);
    std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
    std::uniform_real_distribution<double> v(0.0, 1.0);
    scene.channels = 3;
    scene.background_rgb = Rgb{v(rng), v(rng), v(rng)};
    scene.background = luminance(*scene.background_rgb);
    for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
        if (k == 1) continue;  // grey: the same value in every channel
        Shape& shape = scene.shapes[k];
        shape.rgb = Rgb{v(rng), v(rng), v(rng)};
        shape.value = luminance(*shape.rgb);
    }
    return scene;
}

// Channel c of `scene` as the test itself makes it: every value replaced by the colour's
// component (or the grey value), without channel_scene.
Scene oracle_channel(const Scene& scene, int c) {
    Scene out;
    out.width = scene.width;
    out.height = scene.height;
    const auto k = static_cast<std::size_t>(c);
    out.background = scene.background_rgb ? (*scene.background_rgb)[k] : scene.background;
    for (const Shape& shape : scene.shapes) {
        Shape grey;
        grey.contours = shape.contours;
        grey.value = shape.rgb ? (*shape.rgb)[k] : shape.value;
        out.shapes.push_back(grey);
    }
    return out;
}

TEST(ColourOracle, EveryChannelOfTheReferenceAndOfExactEqualsTheSlowClippingReference) {
    constexpr int kScenes = 60;
    const MethodInstance exact = make_method("exact");
    double worst_reference = 0.0, worst_exact = 0.0;
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = random_colour_scene(seed);
        const PreparedFrame frame = PreparedFrame::prepare(scene);
        const CoveragePlanes reference = exact_reference_planes(frame.pieces(), Filter::box());
        const ImagePlanes image = render_planes(*exact.method, frame.input_for(*exact.method));
        ASSERT_EQ(reference.channels(), 3);
        ASSERT_EQ(image.channels(), 3);
        for (int c = 0; c < 3; ++c) {
            const Scene grey = oracle_channel(scene, c);
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    const double slow = testing::slow_box_pixel(grey, i, j);
                    const double ref_error = std::abs(reference[c].at(i, j) - slow);
                    const double exact_error = std::abs(image[c].at(i, j) - slow);
                    worst_reference = std::max(worst_reference, ref_error);
                    worst_exact = std::max(worst_exact, exact_error);
                    ASSERT_LE(ref_error, kReferenceTolerance)
                        << "seed " << seed << " channel " << c << " pixel " << i << "," << j;
                    ASSERT_LE(exact_error, kExactTolerance)
                        << "seed " << seed << " channel " << c << " pixel " << i << "," << j;
                }
            }
        }
    }
    RecordProperty("worst_reference_error", fmt::format("{:.3g}", worst_reference));
    RecordProperty("worst_exact_error", fmt::format("{:.3g}", worst_exact));
}

// Every method that draws a colour scene draws each of its planes as its grey drawing of that
// channel (every method is linear in the values), and a grey render() of it the luminance. A
// post-process row is not: it finds its edges from the colour and blends every channel alike
// (tests/post_process_colour_test.cpp holds it to its grey image on grey colours).
class EveryMethodInColour : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryMethodInColour, EachPlaneIsTheGreyDrawingOfItsChannel) {
    const MethodInstance m = make_method(GetParam());
    if (m.method->traits().post_process) {
        GTEST_SKIP() << "a post-process pass: edges from the colour (post_process_colour_test)";
    }
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const Scene scene = random_colour_scene(seed);
        if (!m.method->not_applicable(scene).empty())
            GTEST_SKIP() << m.method->not_applicable(scene);
        const ImagePlanes planes = render_planes(*m.method, scene);
        ASSERT_EQ(planes.channels(), 3);
        Image luma(scene.width, scene.height);
        for (int c = 0; c < 3; ++c) {
            const Image grey = render_scene(*m.method, oracle_channel(scene, c));
            for (std::size_t k = 0; k < grey.data.size(); ++k) {
                ASSERT_EQ(planes[c].data[k], grey.data[k])
                    << m.spec << " seed " << seed << " channel " << c << " pixel " << k;
                luma.data[k] += static_cast<float>(kLuminanceWeights[static_cast<std::size_t>(c)] *
                                                   planes[c].data[k]);
            }
        }
        const Image as_grey = render_scene(*m.method, scene);
        const double tolerance =
            rounds_values(*m.method) ? kRoundedLuminanceTolerance : kLuminanceTolerance;
        for (std::size_t k = 0; k < as_grey.data.size(); ++k) {
            ASSERT_NEAR(as_grey.data[k], luma.data[k], tolerance)
                << m.spec << " seed " << seed << " pixel " << k;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryMethodInColour,
                         ::testing::ValuesIn(testing::registry_method_ids()),
                         testing::SpecTestName());

// The figures patterns/isoluminant.cpp's essay gives, recomputed from the scene it makes.
double srgb_encode_exact(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}
Rgb encoded(const Rgb& c) {
    return {srgb_encode_exact(c[0]), srgb_encode_exact(c[1]), srgb_encode_exact(c[2])};
}
double weighted(const Rgb& w, const Rgb& c) { return w[0] * c[0] + w[1] * c[1] + w[2] * c[2]; }

// `stars=iso` and `stars=control` are the two halves of the whole pattern, each in its place.
TEST(IsoluminantPattern, EachStarAloneIsItsPartOfTheWhole) {
    const Scene both = make_pattern("isoluminant", 128, 128);
    const Scene iso = make_pattern("isoluminant:stars=iso", 128, 128);
    const Scene control = make_pattern("isoluminant:stars=control", 128, 128);
    ASSERT_EQ(iso.shapes.size() + control.shapes.size(), both.shapes.size());
    for (std::size_t k = 0; k < both.shapes.size(); ++k) {
        const Shape& part =
            k < iso.shapes.size() ? iso.shapes[k] : control.shapes[k - iso.shapes.size()];
        EXPECT_EQ(part.contours, both.shapes[k].contours) << k;
        EXPECT_EQ(part.rgb, both.shapes[k].rgb) << k;
    }
    EXPECT_EQ(iso.background_rgb, both.background_rgb);
    EXPECT_NE(iso.shapes[0].rgb, control.shapes[0].rgb);
}

TEST(IsoluminantPattern, LumaDifferencesAreThoseItsEssayGives) {
    // The essay's figures have five decimals.
    constexpr double kEssayDecimals = 0.5e-5;
    // Encoding the decoded colours again: a few ulps of values in [0, 1].
    constexpr double kRoundTrip = 1e-12;
    const Scene s = make_pattern("isoluminant", 128, 64);
    ASSERT_EQ(s.channels, 3);
    const Rgb bg = encoded(*s.background_rgb);
    const Rgb iso = encoded(*s.shapes.front().rgb);
    const Rgb control = encoded(*s.shapes.back().rgb);
    const Rgb rec601{0.299, 0.587, 0.114};
    EXPECT_NEAR(weighted(kLuminanceWeights, iso), weighted(kLuminanceWeights, bg), kRoundTrip);
    EXPECT_NEAR(weighted(kLuminanceWeights, bg), 0.35032, kEssayDecimals);
    EXPECT_NEAR(iso[0], 0.90706, kEssayDecimals);
    EXPECT_NEAR(weighted(kLuminanceWeights, control) - weighted(kLuminanceWeights, bg), 0.18843,
                kEssayDecimals);
    EXPECT_NEAR(weighted(rec601, iso) - weighted(rec601, bg), 0.10596, kEssayDecimals);
    EXPECT_NEAR(iso[1] - bg[1], -0.25, kEssayDecimals);
    EXPECT_NEAR(iso[0] - bg[0], 0.80706, kEssayDecimals);
    EXPECT_NEAR(weighted(rec601, control) - weighted(rec601, bg), 0.16757, kEssayDecimals);
    EXPECT_NEAR(control[1] - bg[1], 0.23478, kEssayDecimals);
    // Each star's spokes share its colour; the two stars differ.
    const std::size_t spokes = s.shapes.size() / 2;
    for (std::size_t k = 0; k < s.shapes.size(); ++k) {
        EXPECT_EQ(*s.shapes[k].rgb, k < spokes ? *s.shapes.front().rgb : *s.shapes.back().rgb);
    }
}

TEST(ColourImages, ThreePlanesRoundTripThroughEveryFormat) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "aabench_colour_io";
    std::filesystem::create_directories(dir);
    ImagePlanes planes(3, 7, 5);
    for (int c = 0; c < 3; ++c) {
        for (std::size_t k = 0; k < planes[c].data.size(); ++k) {
            planes[c].data[k] =
                static_cast<float>((k * 37 + static_cast<std::size_t>(c) * 11) % 64) / 63.0f;
        }
    }
    // 16-bit PNG codes: half a step of 1/65535.
    constexpr double kPngStep = 0.5 / 65535.0 + 1e-9;
    for (const char* name : {"c.exr", "c.pfm", "c.png"}) {
        const std::string path = (dir / name).string();
        write_image(path, planes);
        const ImagePlanes back = read_image_planes(path);
        ASSERT_EQ(back.channels(), 3) << name;
        ASSERT_EQ(back.width(), 7);
        ASSERT_EQ(back.height(), 5);
        const bool png = std::string(name) == "c.png";
        for (int c = 0; c < 3; ++c) {
            for (std::size_t k = 0; k < planes[c].data.size(); ++k) {
                if (png) {
                    ASSERT_NEAR(back[c].data[k], planes[c].data[k], kPngStep) << name;
                } else {
                    ASSERT_EQ(back[c].data[k], planes[c].data[k]) << name << " channel " << c;
                }
            }
        }
        // read_image reads the first channel: red.
        const Image first = read_image(path);
        EXPECT_NEAR(first.data[3], planes[0].data[3], png ? kPngStep : 0.0) << name;
    }
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace aabench
