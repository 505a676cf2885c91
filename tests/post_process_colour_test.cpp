// Post-process passes on colour scenes (methods/post_process.h, "Colour"; docs/post-process.md):
// a colour scene whose every colour is grey gives, in every plane, the grey scene's image bit for
// bit (for every post-process row and the variants of its colour test); an edge between two
// colours of equal luma is left as the base drew it by SMAA's luma edges and blended by its
// colour edges, FXAA and MLAA, nearer the exact image; the same square with a luma step is
// blended by both detectors; the colour path is the same in bands, deterministic, and a warm
// colour pass or render allocates nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "harness/measure/metrics.h"
#include "harness/reference/filter_reference.h"
#include "harness/world/alloc_count.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "methods/post_process.h"
#include "patterns/pattern.h"
#include "tests/test_scenes.h"

namespace aabench {
namespace {

constexpr int kSide = 64;
constexpr int kRandomScenes = 6;

// Every post-process row at its defaults, and the variants whose colour paths the defaults do
// not take (FXAA's green luma, SMAA's colour edges, MLAA over an antialiased base).
std::vector<std::string> pass_specs() {
    std::vector<std::string> specs;
    for (const MethodInfo& info : method_registry()) {
        if (info.traits->post_process) specs.push_back(info.id);
    }
    for (const char* variant : {"fxaa:luma=green", "fxaa:space=linear", "smaa:edges=color",
                                "smaa:preset=ultra", "smaa:space=linear", "mlaa:base=exact"}) {
        specs.emplace_back(variant);
    }
    return specs;
}

// `grey` as a colour scene whose every colour is grey: r = g = b = the grey value (each shape's
// `value` its luminance, as a scene file's colours give it).
Scene with_grey_colours(const Scene& grey) {
    Scene scene = grey;
    scene.channels = 3;
    scene.background_rgb = Rgb{grey.background, grey.background, grey.background};
    scene.background = luminance(*scene.background_rgb);
    for (Shape& shape : scene.shapes) {
        shape.rgb = Rgb{shape.value, shape.value, shape.value};
        shape.value = luminance(*shape.rgb);
    }
    return scene;
}

std::vector<Scene> grey_scenes() {
    std::vector<Scene> scenes = {make_pattern("star", kSide, kSide),
                                 make_pattern("rings", kSide, kSide)};
    for (std::uint64_t seed = 1; seed <= kRandomScenes; ++seed) {
        scenes.push_back(testing::random_scene(seed, 40, 32, /*snap_half_pixel=*/false));
    }
    return scenes;
}

// The star with a colour of its own on each shape, so that the channels differ.
Scene coloured_star() {
    Scene scene = with_grey_colours(make_pattern("star", kSide, kSide));
    for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
        const double t = static_cast<double>(k + 1) / static_cast<double>(scene.shapes.size() + 1);
        scene.shapes[k].rgb = Rgb{t, 1.0 - t, 0.5 * t};
        scene.shapes[k].value = luminance(*scene.shapes[k].rgb);
    }
    return scene;
}

// The first pixel where two images differ, or -1.
long first_difference(const Image& a, const Image& b) {
    for (std::size_t k = 0; k < a.data.size(); ++k) {
        // Written so that a NaN on either side is a difference.
        if (!(a.data[k] == b.data[k])) return static_cast<long>(k);
    }
    return -1;
}

TEST(PostProcessColour, GreyColoursGiveTheGreyImageInEveryPlaneBitForBit) {
    // No tolerance: a grey pixel's luma (G + wr (R - G) + wb (B - G)) and its largest channel
    // difference are the grey path's numbers exactly, and each plane is blended with the grey
    // path's arithmetic.
    const std::vector<Scene> scenes = grey_scenes();
    for (const std::string& spec : pass_specs()) {
        const MethodInstance m = make_method(spec);
        for (std::size_t s = 0; s < scenes.size(); ++s) {
            const Image grey = render_scene(*m.method, scenes[s]);
            const Scene colour = with_grey_colours(scenes[s]);
            const ImagePlanes planes = render_planes(*m.method, colour);
            ASSERT_EQ(planes.channels(), 3);
            for (int c = 0; c < 3; ++c) {
                const long k = first_difference(planes[c], grey);
                EXPECT_EQ(k, -1) << m.spec << " scene " << s << " channel " << c << " pixel " << k
                                 << ": " << planes[c].data[static_cast<std::size_t>(k)]
                                 << " against grey " << grey.data[static_cast<std::size_t>(k)];
            }
        }
    }
}

// The colour path is the same in bands (each band renders the base's planes within the pass's
// reach) and from one render to the next.
TEST(PostProcessColour, DeterministicAndTheSameInBands) {
    const Scene scene = coloured_star();
    for (const std::string& spec : pass_specs()) {
        const MethodInstance m = make_method(spec);
        const ImagePlanes once = render_planes(*m.method, scene);
        const ImagePlanes again = render_planes(*make_method(spec).method, scene);
        for (int threads : {1, 2, 3, 7}) {
            ImagePlanes banded(3, kSide, kSide, -1.0f);
            render_in_bands(*m.method, scene, banded, threads);
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(first_difference(once[c], again[c]), -1) << m.spec << " channel " << c;
                EXPECT_EQ(first_difference(once[c], banded[c]), -1)
                    << m.spec << " channel " << c << " in " << threads << " bands";
            }
        }
    }
}

TEST(PostProcessColour, AWarmColourPassAllocatesNothing) {
    const Scene scene = with_grey_colours(make_pattern("star", kSide, kSide));
    const ImagePlanes base = render_planes(*make_method("none").method, scene);
    for (const std::string& spec : pass_specs()) {
        const MethodInstance m = make_method(spec);
        const auto* pass = dynamic_cast<const PostProcessMethod*>(m.method.get());
        ASSERT_NE(pass, nullptr) << spec;
        ImagePlanes out(3, kSide, kSide);
        pass->pass(base, out);  // warm-up: per-thread scratch grows here
        const AllocCounts before = thread_alloc_counts();
        pass->pass(base, out);
        const AllocCounts after = thread_alloc_counts();
        EXPECT_EQ(after.allocations - before.allocations, 0u) << spec;
    }
}

// A warm render of a colour scene through its prepared frame (which makes the channel scenes
// once, SceneInput::with_channels), base included: nothing either.
TEST(PostProcessColour, AWarmColourRenderAllocatesNothing) {
    const Scene scene = coloured_star();
    const PreparedFrame frame = PreparedFrame::prepare(scene);
    for (const std::string& spec : pass_specs()) {
        const MethodInstance m = make_method(spec);
        const SceneInput in = frame.input_for(*m.method);
        ImagePlanes out(3, kSide, kSide);
        m.method->render(in, out);  // warm-up
        const AllocCounts before = thread_alloc_counts();
        m.method->render(in, out);
        const AllocCounts after = thread_alloc_counts();
        EXPECT_EQ(after.allocations - before.allocations, 0u) << spec;
    }
}

// --- An isoluminant edge ---

// The sRGB transfer function's inverse (IEC 61966-2-1), in double: the test's own, so that the
// scene's colours do not come from the code under test.
double srgb_decode(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

// A square of side `side_px` turned by 20 degrees about the image's centre: slanted edges, the
// staircases a pass blends.
Contour turned_square(int size, double side_px) {
    constexpr double kTurnRad = 20.0 * std::numbers::pi / 180.0;
    const double c = std::cos(kTurnRad), s = std::sin(kTurnRad), h = 0.5 * side_px;
    const double mid = 0.5 * size;
    Contour square;
    for (const auto& [u, v] :
         {std::pair{-h, -h}, std::pair{h, -h}, std::pair{h, h}, std::pair{-h, h}}) {
        square.push_back({mid + c * u - s * v, mid + s * u + c * v});
    }
    return square;
}

// A red square on a background of `background` (linear), as a colour scene.
Scene red_square_on(const Rgb& background, int size) {
    Scene scene;
    scene.width = size;
    scene.height = size;
    scene.channels = 3;
    scene.background_rgb = background;
    scene.background = luminance(background);
    Shape square;
    square.contours.push_back(turned_square(size, 0.5 * size));
    square.rgb = Rgb{1.0, 0.0, 0.0};
    square.value = luminance(*square.rgb);
    scene.shapes.push_back(square);
    return scene;
}

// Green of the red's luma as SMAA's luma detector computes it, Rec. 709 weights on the
// sRGB-encoded colour: 0.2126 x 1 (red, encoded 1) = 0.7152 x G', G' the encoded green.
Rgb isoluminant_green() { return Rgb{0.0, srgb_decode(0.2126 / 0.7152), 0.0}; }

// The box rmse over every channel against the exact box reference, as compare's box_rmse on a
// colour scene: the mean of the squared errors of every value of every plane.
double box_rmse_over_channels(const ImagePlanes& planes, const CoveragePlanes& exact) {
    double squares = 0.0, values = 0.0;
    for (int c = 0; c < planes.channels(); ++c) {
        const ErrorStats e = compare_to_reference(planes[c], exact[c]);
        const double n = static_cast<double>(planes[c].pixel_count());
        squares += e.rmse * e.rmse * n;
        values += n;
    }
    return std::sqrt(squares / values);
}

bool same_planes(const ImagePlanes& a, const ImagePlanes& b) {
    for (int c = 0; c < a.channels(); ++c) {
        if (first_difference(a[c], b[c]) != -1) return false;
    }
    return true;
}

struct EdgeRun {
    ImagePlanes none;
    CoveragePlanes exact;
    double none_rmse = 0.0;
};

EdgeRun edge_run(const Scene& scene) {
    EdgeRun run;
    run.none = render_planes(*make_method("none").method, scene);
    run.exact = exact_reference_planes(scene, Filter::box());
    run.none_rmse = box_rmse_over_channels(run.none, run.exact);
    return run;
}

// The two colours' luma difference as SMAA's luma detector sees it: far below its threshold.
// Equal in exact arithmetic; the float32 colour, its encoding and the weighted sum round by a
// few 1e-7, so a hundredth of the threshold is a bound with room and still a luma "equal" for
// the detector.
constexpr float kIsoluminantLumaDifference = 0.001f;

TEST(PostProcessColour, TheTestSceneIsIsoluminantForSmaaLumaEdges) {
    ImagePlanes pair(3, 2, 1);
    const Rgb green = isoluminant_green();
    for (int c = 0; c < 3; ++c) {
        pair[c].at(0, 0) = c == 0 ? 1.0f : 0.0f;
        pair[c].at(1, 0) = static_cast<float>(green[static_cast<std::size_t>(c)]);
    }
    Image luma;
    colour_luma_rows(pair, /*srgb=*/true, kRec709Luma, luma, 0, 1);
    EXPECT_LT(std::abs(luma.at(0, 0) - luma.at(1, 0)), kIsoluminantLumaDifference)
        << luma.at(0, 0) << " against " << luma.at(1, 0);
    // Red's encoded colour is (1, 0, 0): its luma is the red weight, but for float32's rounding
    // of 1.055 - 0.055 (the encoding of 1), a few 1e-8: the pair is not black against black.
    constexpr float kEncodedOneRounding = 1e-6f;
    EXPECT_NEAR(luma.at(0, 0), kRec709Luma.r, kEncodedOneRounding);
}

TEST(PostProcessColour, SmaaLumaEdgesMissAnIsoluminantEdgeAndColourEdgesBlendIt) {
    const EdgeRun run = edge_run(red_square_on(isoluminant_green(), kSide));
    // Luma edges: no edge anywhere, so the image is exactly the one the base drew.
    const ImagePlanes luma = render_planes(*make_method("smaa:edges=luma").method,
                                           red_square_on(isoluminant_green(), kSide));
    EXPECT_TRUE(same_planes(luma, run.none)) << "smaa:edges=luma blended an isoluminant edge";
    // Colour edges (red differs by 1 in R): blended, and nearer the exact image.
    for (const char* spec : {"smaa:edges=color", "fxaa", "mlaa"}) {
        const ImagePlanes out =
            render_planes(*make_method(spec).method, red_square_on(isoluminant_green(), kSide));
        EXPECT_FALSE(same_planes(out, run.none)) << spec << " left the isoluminant edge as it was";
        const double rmse = box_rmse_over_channels(out, run.exact);
        EXPECT_LT(rmse, run.none_rmse) << spec;
        RecordProperty(std::string(spec) + "_box_rmse", std::to_string(rmse));
    }
    RecordProperty("none_box_rmse", std::to_string(run.none_rmse));
}

TEST(PostProcessColour, BothSmaaDetectorsBlendTheSameSquareWithALumaStep) {
    // The control: the red square on black (luma 0.2126 against 0, above the threshold 0.1).
    const Scene scene = red_square_on(Rgb{0.0, 0.0, 0.0}, kSide);
    const EdgeRun run = edge_run(scene);
    for (const char* spec : {"smaa:edges=luma", "smaa:edges=color"}) {
        const ImagePlanes out = render_planes(*make_method(spec).method, scene);
        EXPECT_FALSE(same_planes(out, run.none)) << spec << " left the edge as it was";
        EXPECT_LT(box_rmse_over_channels(out, run.exact), run.none_rmse) << spec;
    }
}

// FXAA's green luma is blind to an edge between colours of the same green: red on black.
TEST(PostProcessColour, FxaaGreenLumaMissesAnEdgeWithoutGreen) {
    const Scene scene = red_square_on(Rgb{0.0, 0.0, 0.0}, kSide);
    const ImagePlanes none = render_planes(*make_method("none").method, scene);
    const ImagePlanes green = render_planes(*make_method("fxaa:luma=green").method, scene);
    const ImagePlanes rgb = render_planes(*make_method("fxaa:luma=rgb").method, scene);
    EXPECT_TRUE(same_planes(green, none));
    EXPECT_FALSE(same_planes(rgb, none));
}

}  // namespace
}  // namespace aabench
