// The colour engines (docs/colour.md, "Who draws what"): every plane of a colour render by
// `none`, `exact`, `box-multiscan` and `ssaa` (their parameter variants included) equals, bit for
// bit, the grey render of that channel's scene, on seeded random colour scenes of overlapping
// polygons (crossings: exact's band-sweep rows), shapes of equal luminance and of equal colour
// (a step that is zero in the luminance or in some channels), every 2-D pattern family (polygons,
// discs and rings, Bezier curves, text), affine values and a 3-D frame's disjoint pieces (the
// per-channel fallbacks), in bands on several threads; and a warm colour render allocates
// nothing. The channel scenes are the test's own (values replaced by the colours' components),
// not channel_scene's.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "harness/world/alloc_count.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "tests/test_names.h"
#include "tests/test_scenes.h"

namespace aabench {
namespace {

constexpr int kRandomScenes = 40;

// The methods with colour engines, at their defaults and the variants whose engines differ
// (box-multiscan's n = 1 has no inner line; ssaa's patterns and filters take other sums).
std::vector<std::string> engine_specs() {
    return {"none",
            "exact",
            "box-multiscan",
            "box-multiscan:n=1",
            "box-multiscan:n=6",
            "ssaa",
            "ssaa:k=1",
            "ssaa:k=4",
            "ssaa:pattern=rgss,k=2",
            "ssaa:pattern=msaa,k=4",
            "ssaa:pattern=halton",
            "ssaa:filter=gaussian"};
}

// How the colours of a scene are drawn.
enum class Colours {
    kRandom,         // a random colour on every shape but every third, which stays grey
    kIsoluminant,    // every colour of the background's luminance: no step in the luminance
    kSharedColours,  // two colours for all shapes: steps between shapes zero in every channel
    kDyadic,         // components in units of 1/4 (testing::with_dyadic_values): the grey
                     // channels take ssaa's run sums, the colour its runs
};

// `grey` with colours, a colour scene (each value the colour's luminance, as the reader makes it).
Scene colourised(const Scene& grey, std::uint64_t seed, Colours colours) {
    std::mt19937_64 rng(seed ^ 0x6a09e667f3bcc909ULL);
    std::uniform_real_distribution<double> v(0.0, 1.0);
    Scene scene = grey;
    scene.channels = 3;
    scene.background_rgb = Rgb{v(rng), v(rng), v(rng)};
    scene.background = luminance(*scene.background_rgb);
    const Rgb shared[2] = {Rgb{v(rng), v(rng), v(rng)}, Rgb{v(rng), v(rng), v(rng)}};
    constexpr double kDyadicValues[] = {0.0, 1.0, 0.25, 3.0, -0.5, 0.75};
    auto dyadic = [&] { return kDyadicValues[rng() % 6]; };
    if (colours == Colours::kDyadic) {
        scene.background_rgb = Rgb{dyadic(), dyadic(), dyadic()};
        scene.background = luminance(*scene.background_rgb);
    }
    auto colour_of = [&](std::size_t k, Shape& shape) {
        switch (colours) {
            case Colours::kRandom:
                if (k % 3 == 2) {
                    shape.rgb.reset();  // grey: its value in every channel
                    return;
                }
                shape.rgb = Rgb{v(rng), v(rng), v(rng)};
                break;
            case Colours::kIsoluminant: {
                // Blue solved for the background's luminance (not clamped: values are not).
                const double r = v(rng), g = v(rng);
                const double b = (scene.background - kLuminanceWeights[0] * r -
                                  kLuminanceWeights[1] * g) /
                                 kLuminanceWeights[2];
                shape.rgb = Rgb{r, g, b};
                break;
            }
            case Colours::kSharedColours:
                shape.rgb = shared[rng() % 2];
                break;
            case Colours::kDyadic:
                shape.rgb = Rgb{dyadic(), dyadic(), dyadic()};
                break;
        }
        shape.value = luminance(*shape.rgb);
    };
    for (std::size_t k = 0; k < scene.shapes.size(); ++k) colour_of(k, scene.shapes[k]);
    return scene;
}

// Channel c of a colour scene, made here: every value replaced by its colour's component c.
Scene oracle_channel(const Scene& scene, int c) {
    const auto k = static_cast<std::size_t>(c);
    Scene out = scene;
    out.channels = 1;
    out.background = scene.background_rgb ? (*scene.background_rgb)[k] : scene.background;
    out.background_rgb.reset();
    for (Shape& shape : out.shapes) {
        if (shape.rgb) shape.value = (*shape.rgb)[k];
        shape.rgb.reset();
    }
    for (ThinObject& thin : out.thin_objects) {
        if (thin.shape.rgb) thin.shape.value = (*thin.shape.rgb)[k];
        thin.shape.rgb.reset();
    }
    return out;
}

// Bit for bit (a -0 for a +0 or another NaN is a difference).
bool same_bits(float a, float b) {
    return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

// Fails, naming the case, the plane, the pixel and both values, at the first pixel where `got`
// differs from `want`.
void expect_same_image(const Image& got, const Image& want, const std::string& what) {
    ASSERT_EQ(got.data.size(), want.data.size()) << what;
    for (std::size_t k = 0; k < want.data.size(); ++k) {
        if (!same_bits(got.data[k], want.data[k])) {
            ADD_FAILURE() << what << ": pixel (" << k % static_cast<std::size_t>(want.width)
                          << ", " << k / static_cast<std::size_t>(want.width) << ") colour "
                          << fmt::format("{:a}", got.data[k]) << ", grey "
                          << fmt::format("{:a}", want.data[k]);
            return;
        }
    }
}

// Every plane of `in`'s render by `spec` against the grey render of its channel, whole and in
// bands on 2 and 3 threads.
void expect_planes_are_channels(const std::string& spec, const SceneInput& in,
                                const std::string& what) {
    const MethodInstance m = make_method(spec);
    const Scene& scene = in.scene();
    if (!m.method->not_applicable(scene).empty()) return;
    const ImagePlanes planes = render_planes(*m.method, in);
    ASSERT_EQ(planes.channels(), 3) << what;
    for (int c = 0; c < 3; ++c) {
        const Scene channel = oracle_channel(scene, c);
        const Image grey = render_scene(*m.method, in.same_kind(channel));
        expect_same_image(planes[c], grey, fmt::format("{} {} channel {}", spec, what, c));
    }
    for (const int threads : {2, 3}) {
        ImagePlanes banded(3, scene.width, scene.height);
        render_in_bands(*m.method, in, banded, threads);
        for (int c = 0; c < 3; ++c) {
            expect_same_image(banded[c], planes[c],
                              fmt::format("{} {} channel {} in {} bands", spec, what, c, threads));
        }
    }
}

class ColourEngine : public ::testing::TestWithParam<std::string> {};

TEST_P(ColourEngine, PlanesOfRandomPolygonsAreTheGreyRendersOfTheirChannels) {
    for (std::uint64_t seed = 1; seed <= kRandomScenes; ++seed) {
        const Scene grey = testing::random_scene(seed, 37, 29, /*snap_half_pixel=*/seed % 2 == 0);
        for (const Colours colours : {Colours::kRandom, Colours::kIsoluminant,
                                      Colours::kSharedColours, Colours::kDyadic}) {
            const Scene scene = colourised(grey, seed, colours);
            expect_planes_are_channels(
                GetParam(), scene,
                fmt::format("seed {} colours {}", seed, static_cast<int>(colours)));
        }
        if (::testing::Test::HasFailure()) return;
    }
}

TEST_P(ColourEngine, PlanesOfEveryPatternFamilyAreTheGreyRendersOfTheirChannels) {
    const char* patterns[] = {"star",        "strips:widths=3,angles=3",
                              "grating",     "rings",
                              "zoneplate",   "circle-radii:max_radius=13",
                              "curves",      "crescents",
                              "text",        "text-cff",
                              "isoluminant"};
    std::uint64_t seed = 100;
    for (const char* pattern : patterns) {
        const Scene grey = make_pattern(pattern, 61, 47);
        for (const Colours colours : {Colours::kRandom, Colours::kDyadic}) {
            const Scene scene = colourised(grey, ++seed, colours);
            expect_planes_are_channels(GetParam(), scene,
                                       fmt::format("{} colours {}", pattern, static_cast<int>(colours)));
        }
        // The pattern's own colours, where it has them (isoluminant).
        if (grey.channels == 3) expect_planes_are_channels(GetParam(), grey, pattern);
    }
}

TEST_P(ColourEngine, PlanesOfAffineValuesAndDisjointPiecesAreTheGreyRendersOfTheirChannels) {
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        // One contour a shape: the affine-value engine takes pieces (methods/exact.cpp).
        Scene grey = testing::with_constant_planes(testing::random_scene(seed, 31, 23, false));
        for (Shape& shape : grey.shapes) shape.contours.resize(1);
        expect_planes_are_channels(GetParam(), colourised(grey, seed, Colours::kRandom),
                                   fmt::format("constant planes, seed {}", seed));
    }
    // A 3-D frame's visible pieces, each with a colour of its own.
    const PreparedFrame frame = PreparedFrame::prepare(make_pattern("room", 64, 48));
    const SceneInput pieces = frame.pieces();
    const Scene colour = colourised(pieces.scene(), 7, Colours::kRandom);
    expect_planes_are_channels(GetParam(), pieces.same_kind(colour), "room's visible pieces");
}

TEST_P(ColourEngine, AWarmColourRenderAllocatesNothing) {
    const Scene scene = colourised(make_pattern("star", 64, 64), 3, Colours::kRandom);
    const PreparedFrame frame = PreparedFrame::prepare(scene);
    const MethodInstance m = make_method(GetParam());
    const SceneInput in = frame.input_for(*m.method);
    ImagePlanes out(3, scene.width, scene.height);
    m.method->render(in, out);  // warm-up: per-thread scratch grows here
    const AllocCounts before = thread_alloc_counts();
    m.method->render(in, out);
    const AllocCounts after = thread_alloc_counts();
    EXPECT_EQ(after.allocations - before.allocations, 0u) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(Engines, ColourEngine, ::testing::ValuesIn(engine_specs()),
                         testing::SpecTestName());

}  // namespace
}  // namespace aabench
