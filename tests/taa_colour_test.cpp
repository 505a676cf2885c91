// taa in colour (methods/taa.cpp, methods/taa_colour_p.h; docs/colour.md, "TAA in colour"): a
// colour sequence whose every colour is grey is the grey sequence plane by plane; YCoCg goes
// there and back; clip and minmax differ on a history outside the box in a direction the
// centre line leaves by another face than the clamp, and both end inside the box; the colour
// sequence runs through the sequence runner, its figures over every channel.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "harness/measure/sequence_run.h"
#include "harness/reference/filter_reference.h"
#include "harness/world/sequence.h"
#include "methods/method.h"
#include "methods/taa_colour_p.h"
#include "patterns/pattern.h"
#include "test_scenes.h"
#include "uniform_motion.h"

namespace aabench {
namespace {

using taa_colour::Box3;
using taa_colour::Vec3;

constexpr int kSide = 40;
constexpr int kFrames = 6;

// weight=luma divides by 1 + luminance: of a grey colour in colour (0.2126 v + 0.7152 v +
// 0.0722 v, whose weights sum to 1 only within a few double ulps) and of the value itself on
// one channel. The weights then differ by ~1e-16 relative, which can move the float32 output
// by one rounding step: one float ulp of values <= 1 (2^-23), doubled for the history that
// carries the last frame's step into the next blend.
constexpr double kLumaWeightTolerance = 2.0 * 0x1p-23;
// YCoCg there and back in double: each component is two sums of three terms scaled by powers
// of two, half an ulp of a value up to 2 max|c| per rounding: 8 ulp of max|c| is a bound.
constexpr double kRoundTripUlps = 8.0;
// Inside the box after the output's float32 rounding (half an ulp of values <= 2: 1.2e-7) and
// a second trip through YCoCg to test it (a few double ulps).
constexpr double kInsideBoxTolerance = 2.5e-7;
// The runner's references are of the prepared frame's disjoint pieces, the test's of the frame
// scene itself: both exact to 1e-10 per pixel (harness/reference/filter_reference.h).
constexpr double kReferenceTolerance = 1e-9;

using testing::uniform_motion;

// `scene` as a colour scene of grey colours: every shape and the background R = G = B.
Scene as_grey_colours(Scene scene) {
    scene.channels = 3;
    scene.background_rgb = Rgb{scene.background, scene.background, scene.background};
    for (Shape& shape : scene.shapes) shape.rgb = Rgb{shape.value, shape.value, shape.value};
    return scene;
}

// Frames t = 0..kFrames-1 of `scene` moving by (0.3, 0.2) px per frame, with their vectors.
struct Frames {
    std::vector<Scene> scenes;
    std::vector<MotionVectors> motions;
};
Frames drift(const Scene& scene) {
    constexpr float kDx = 0.3f, kDy = 0.2f;
    Frames f;
    for (int t = 0; t < kFrames; ++t) {
        f.scenes.push_back(translated(scene, t * double(kDx), t * double(kDy)));
        f.motions.push_back(t == 0 ? MotionVectors{}
                                   : uniform_motion(scene.width, scene.height, kDx, kDy));
    }
    return f;
}

std::vector<Image> run_grey(const Method& method, const Frames& f) {
    std::unique_ptr<TemporalState> state = method.begin(f.scenes[0].width, f.scenes[0].height);
    std::vector<Image> out;
    for (std::size_t t = 0; t < f.scenes.size(); ++t) {
        Image image(f.scenes[t].width, f.scenes[t].height);
        method.render_frame(f.scenes[t], f.motions[t], int(t), state.get(), image);
        out.push_back(std::move(image));
    }
    return out;
}

std::vector<ImagePlanes> run_colour(const Method& method, const Frames& f) {
    std::unique_ptr<TemporalState> state = method.begin(f.scenes[0].width, f.scenes[0].height);
    std::vector<ImagePlanes> out;
    for (std::size_t t = 0; t < f.scenes.size(); ++t) {
        ImagePlanes planes(3, f.scenes[t].width, f.scenes[t].height);
        method.render_frame(f.scenes[t], f.motions[t], int(t), state.get(), planes);
        out.push_back(std::move(planes));
    }
    return out;
}

TEST(TaaColour, AColourSequenceOfGreyColoursIsTheGreySequenceInEveryPlane) {
    const std::vector<Scene> scenes = {make_pattern("star", kSide, kSide),
                                       testing::random_scene(7, kSide, kSide, false),
                                       testing::random_scene(11, kSide, kSide, true)};
    int compared = 0;
    for (const char* clamp : {"none", "minmax", "clip", "variance"}) {
        for (const char* space : {"ycocg", "rgb"}) {
            for (const char* rest : {"", ",history=catmull", ",alpha=running", ",weight=luma",
                                     ",samples=16,gamma=2"}) {
                const std::string spec =
                    fmt::format("taa:clamp={},space={}{}", clamp, space, rest);
                const MethodInstance m = make_method(spec);
                const bool luma = std::string(rest) == ",weight=luma";
                for (std::size_t q = 0; q < scenes.size(); ++q) {
                    const Frames grey = drift(scenes[q]);
                    const Frames colour = drift(as_grey_colours(scenes[q]));
                    const std::vector<Image> g = run_grey(*m.method, grey);
                    const std::vector<ImagePlanes> c = run_colour(*m.method, colour);
                    for (int t = 0; t < kFrames; ++t) {
                        for (int ch = 0; ch < 3; ++ch) {
                            if (!luma) {
                                ASSERT_EQ(c[t][ch].data, g[t].data)
                                    << spec << " scene " << q << " frame " << t << " plane " << ch;
                                continue;
                            }
                            for (std::size_t k = 0; k < g[t].data.size(); ++k) {
                                ASSERT_LE(std::abs(double(c[t][ch].data[k]) - g[t].data[k]),
                                          kLumaWeightTolerance)
                                    << spec << " scene " << q << " frame " << t << " pixel " << k;
                            }
                        }
                    }
                    ++compared;
                }
            }
        }
    }
    EXPECT_EQ(compared, 4 * 2 * 5 * 3);
}

TEST(TaaColour, YCoCgRoundTripAndGreyIsExact) {
    std::mt19937_64 rng(2014);
    std::uniform_real_distribution<double> u(-0.5, 2.0);
    for (int n = 0; n < 100000; ++n) {
        const Vec3 c{u(rng), u(rng), u(rng)};
        const Vec3 back = taa_colour::from_ycocg(taa_colour::to_ycocg(c));
        const double scale = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])});
        for (int k = 0; k < 3; ++k) {
            ASSERT_LE(std::abs(back[k] - c[k]), kRoundTripUlps * DBL_EPSILON * scale)
                << "colour " << c[0] << ", " << c[1] << ", " << c[2] << " component " << k;
        }
        // A grey colour of a float value: (v, 0, 0) and back, exactly.
        const double v = static_cast<float>(u(rng));
        const Vec3 y = taa_colour::to_ycocg({v, v, v});
        ASSERT_EQ(y, (Vec3{v, 0.0, 0.0})) << v;
        ASSERT_EQ(taa_colour::from_ycocg(y), (Vec3{v, v, v})) << v;
    }
    // The transform's rows: the luma (1/4, 1/2, 1/4) and the two chroma axes.
    EXPECT_EQ(taa_colour::to_ycocg({1.0, 0.0, 0.0}), (Vec3{0.25, 0.5, -0.25}));
    EXPECT_EQ(taa_colour::to_ycocg({0.0, 1.0, 0.0}), (Vec3{0.5, 0.0, 0.5}));
    EXPECT_EQ(taa_colour::to_ycocg({0.0, 0.0, 1.0}), (Vec3{0.25, -0.5, -0.25}));
}

bool inside(const Vec3& p, const Box3& box, double tolerance) {
    for (int k = 0; k < 3; ++k) {
        if (!(p[k] >= box.lo[k] - tolerance && p[k] <= box.hi[k] + tolerance)) return false;
    }
    return true;
}

TEST(TaaColour, ClipLeavesTheBoxWhereTheCentreLineDoesNotTheClamp) {
    // The unit box, centre (0.5, 0.5, 0.5); the history (2, 0.25, 0.5) is outside in R only.
    // The clamp keeps G = 0.25; the segment to the centre leaves the box at R = 1 with t = 1/3
    // of the offset (1.5, -0.25, 0) kept: G = 0.5 - 0.25 / 3.
    const Box3 box{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
    const Vec3 h{2.0, 0.25, 0.5};
    const Vec3 clamped = taa_colour::clamp_to_box(h, box);
    const Vec3 clipped = taa_colour::clip_to_box(h, box);
    EXPECT_EQ(clamped, (Vec3{1.0, 0.25, 0.5}));
    EXPECT_DOUBLE_EQ(clipped[0], 1.0);
    EXPECT_DOUBLE_EQ(clipped[1], 0.5 - 0.25 / 3.0);
    EXPECT_DOUBLE_EQ(clipped[2], 0.5);
    EXPECT_TRUE(inside(clamped, box, 0.0));
    EXPECT_TRUE(inside(clipped, box, 0.0));
    // Inside: both leave it alone. A flat component with an offset: the clip ends on the centre.
    EXPECT_EQ(taa_colour::clip_to_box({0.2, 0.3, 0.9}, box), (Vec3{0.2, 0.3, 0.9}));
    const Box3 flat{{0.0, 0.4, 0.0}, {1.0, 0.4, 1.0}};
    EXPECT_EQ(taa_colour::clip_to_box({0.9, 0.7, 0.1}, flat), (Vec3{0.5, 0.4, 0.5}));
    EXPECT_EQ(taa_colour::clamp_to_box({0.9, 0.7, 0.1}, flat), (Vec3{0.9, 0.4, 0.1}));
    // On a segment between two colours (a two-colour neighbourhood's history) both are the
    // identity: that segment lies in the box the two colours span.
    const Vec3 a{0.8, 0.1, 0.3}, b{0.1, 0.6, 0.2};
    const Box3 ab{{0.1, 0.1, 0.2}, {0.8, 0.6, 0.3}};
    const Vec3 mix{0.3 * a[0] + 0.7 * b[0], 0.3 * a[1] + 0.7 * b[1], 0.3 * a[2] + 0.7 * b[2]};
    EXPECT_EQ(taa_colour::clip_to_box(mix, ab), taa_colour::clamp_to_box(mix, ab));
}

// A still two-frame sequence without jitter (samples=1: taa's samples are `none`'s): frame 0
// all one colour, frame 1 two others split at a vertical edge off the pixel centres, so each
// pixel beside the edge has a box spanning the two new colours and a history (the old colour)
// outside it in a direction the centre line leaves by another face than the clamp.
TEST(TaaColour, ClipDiffersFromMinMaxInAColourSequenceAndBothStayInTheBox) {
    constexpr int kW = 12, kH = 6;
    auto rect = [](double x0, double x1, Rgb c) {
        Shape s;
        s.contours = {{{x0, 0.0}, {x1, 0.0}, {x1, double(kH)}, {x0, double(kH)}}};
        s.rgb = c;
        s.value = luminance(c);
        return s;
    };
    Scene before, after;
    for (Scene* s : {&before, &after}) {
        s->width = kW;
        s->height = kH;
        s->channels = 3;
        s->background_rgb = Rgb{0.0, 0.0, 0.0};
        s->background = 0.0;
    }
    before.shapes = {rect(0.0, kW, {0.9, 0.2, 0.1})};
    after.shapes = {rect(0.0, 5.3, {0.1, 0.5, 0.3}), rect(5.3, kW, {0.3, 0.6, 0.8})};
    const Frames f{{before, after}, {MotionVectors{}, MotionVectors{}}};
    const ImagePlanes samples = render_planes(*make_method("none").method, after);
    for (const char* space : {"ycocg", "rgb"}) {
        const bool ycocg = std::string(space) == "ycocg";
        auto to_space = [&](const Vec3& c) { return ycocg ? taa_colour::to_ycocg(c) : c; };
        const ImagePlanes minmax = run_colour(
            *make_method(fmt::format("taa:samples=1,clamp=minmax,space={}", space)).method, f)[1];
        const ImagePlanes clip = run_colour(
            *make_method(fmt::format("taa:samples=1,clamp=clip,space={}", space)).method, f)[1];
        double largest_difference = 0.0;
        for (int y = 0; y < kH; ++y) {
            for (int x = 0; x < kW; ++x) {
                Box3 box{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
                for (int j = std::max(0, y - 1); j <= std::min(kH - 1, y + 1); ++j) {
                    for (int i = std::max(0, x - 1); i <= std::min(kW - 1, x + 1); ++i) {
                        const Vec3 c = to_space(
                            {samples[0].at(i, j), samples[1].at(i, j), samples[2].at(i, j)});
                        for (int k = 0; k < 3; ++k) {
                            box.lo[k] = std::min(box.lo[k], c[k]);
                            box.hi[k] = std::max(box.hi[k], c[k]);
                        }
                    }
                }
                const Vec3 a = to_space({minmax[0].at(x, y), minmax[1].at(x, y), minmax[2].at(x, y)});
                const Vec3 b = to_space({clip[0].at(x, y), clip[1].at(x, y), clip[2].at(x, y)});
                EXPECT_TRUE(inside(a, box, kInsideBoxTolerance)) << space << " minmax " << x << "," << y;
                EXPECT_TRUE(inside(b, box, kInsideBoxTolerance)) << space << " clip " << x << "," << y;
                for (int k = 0; k < 3; ++k) {
                    largest_difference = std::max(largest_difference, std::abs(a[k] - b[k]));
                }
            }
        }
        // The old colour is far outside (a full 0.9 of 0.1 alpha's history weight): the two
        // rectifications differ by a visible amount, not by rounding.
        EXPECT_GT(largest_difference, 0.01) << space;
    }
}

TEST(TaaColour, TheColourSequenceRunsWithFiguresOverEveryChannel) {
    const SequenceSpec& spec = find_sequence("isoluminant-drift");
    EXPECT_FALSE(spec.in_default_run);
    EXPECT_EQ(spec.pattern, "isoluminant");
    constexpr int kW = 48, kH = 24, kRunFrames = 4;
    SequenceRunOptions options;
    options.sequences = {"isoluminant-drift"};
    options.method_specs = {"none", "taa:clamp=clip", "taa:clamp=minmax,space=rgb"};
    options.width = kW;
    options.height = kH;
    options.frames = kRunFrames;
    const SequenceRunResult result = run_sequences(options);
    ASSERT_EQ(result.rows.size(), 3u);
    for (const ResultRow& row : result.rows) {
        EXPECT_TRUE(row.not_applicable.empty()) << row.method << ": " << row.not_applicable;
    }
    ASSERT_EQ(result.figures.size(), 1u);
    const SequenceMethodRun& none = result.figures[0].runs[0];
    ASSERT_EQ(none.frame_rmse.size(), std::size_t(kRunFrames));
    // `none`'s frame error is the rmse over the three planes of every channel's box reference.
    const Sequence seq = make_sequence(spec, kW, kH, kRunFrames);
    for (int t = 0; t < kRunFrames; ++t) {
        const Scene frame = frame_scene(seq, t);
        const ImagePlanes drawn = render_planes(*make_method("none").method, frame);
        const CoveragePlanes box = exact_reference_planes(frame, Filter::box());
        double sum = 0.0;
        for (int c = 0; c < 3; ++c) {
            for (std::size_t k = 0; k < drawn[c].data.size(); ++k) {
                const double e = double(drawn[c].data[k]) - box[c].data[k];
                sum += e * e;
            }
        }
        const double rmse = std::sqrt(sum / (3.0 * kW * kH));
        EXPECT_NEAR(none.frame_rmse[t], rmse, kReferenceTolerance) << "frame " << t;
    }
}

}  // namespace
}  // namespace aabench
