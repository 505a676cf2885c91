// Colour worlds (docs/colour.md, "Colour worlds"): the reader's colour values in a world and
// their one-line refusals, the writer's round trip, every method that draws 3-D drawing each
// channel of a seeded random colour world bit for bit as it draws that channel's grey world,
// the exact reference against the slow clipping oracle, and the colour room's chroma.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "harness/reference/filter_reference.h"
#include "harness/world/frame.h"
#include "harness/world/overlay.h"
#include "tests/world_shadows.h"
#include "harness/world/stages.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"
#include "patterns/world_builders.h"
#include "tests/input_error_of.h"
#include "tests/registry_ids.h"
#include "tests/slow_reference.h"

namespace aabench {
namespace {

// The slow clipping reference against the box reference on visible pieces: both exact, apart by
// rounding of sums of a few hundred terms of size <= a few (the box reference's suite: 1e-9).
constexpr double kReferenceTolerance = 1e-9;

Scene parse(const std::string& text) { return parse_scene_json(text, "test.json"); }

// A one-face world of version `version` with `ambient`, one light of `intensity` and a face of
// `reflectance` (JSON texts).
std::string world_text(const std::string& reflectance, const std::string& intensity = "1",
                       const std::string& ambient = "0.1", int version = 4,
                       const std::string& extra = "") {
    return fmt::format(
        R"({{"version": {}, "width": 8, "height": 8,
             "camera": {{"eye": [0, 0, 5], "target": [0, 0, 0]}}, "ambient": {},
             "lights": [{{"type": "parallel", "direction": [0, 0, -1], "intensity": {}}}],
             "objects": [{{"vertices": [[-1, -1, 0], [1, -1, 0], [1, 1, 0]],
                          "faces": [{{"loop": [0, 1, 2], "reflectance": {}{}}}]}}]}})",
        version, ambient, intensity, reflectance, extra);
}

TEST(ColourWorld, ReadsColoursAsLinearRgbWithLuminanceGreys) {
    const Scene scene = parse(world_text("[0.5, 0.25, 1]", "[1, 0.5, 0.25]", "0.1"));
    ASSERT_TRUE(scene.world.has_value());
    EXPECT_EQ(scene.channels, 3);
    const World& w = *scene.world;
    EXPECT_TRUE(w.is_colour());
    const Face& f = w.objects[0].faces[0];
    ASSERT_TRUE(f.reflectance_rgb.has_value());
    EXPECT_EQ(*f.reflectance_rgb, (Rgb{0.5, 0.25, 1.0}));
    EXPECT_EQ(f.reflectance, luminance(Rgb{0.5, 0.25, 1.0}));
    ASSERT_TRUE(w.lights[0].intensity_rgb.has_value());
    EXPECT_EQ(w.lights[0].intensity, luminance(Rgb{1.0, 0.5, 0.25}));
    EXPECT_FALSE(w.ambient_rgb.has_value());  // a grey number in a colour world: [n, n, n]
    EXPECT_EQ(w.ambient, 0.1);
    // The channel worlds: each value its component, grey numbers as they are.
    const World green = channel_world(w, 1);
    EXPECT_FALSE(green.is_colour());
    EXPECT_EQ(green.objects[0].faces[0].reflectance, 0.25);
    EXPECT_EQ(green.lights[0].intensity, 0.5);
    EXPECT_EQ(green.ambient, 0.1);
    // A grey world stays one channel, and a grey background with it.
    const Scene grey = parse(world_text("0.5"));
    EXPECT_EQ(grey.channels, 1);
    EXPECT_FALSE(grey.world->is_colour());
}

TEST(ColourWorld, WriterRoundTripsBitForBitAsVersion4) {
    Scene scene = parse(world_text("[0.1, 0.7000000000000001, 1e-300]", "[3, 0.5, 0.25]",
                                   "[0.01, 0.02, 0.03]", 4,
                                   R"(, "patterns": [{"loop": [[0, -0.8, 0], [0.5, -0.8, 0],
                                       [0.5, -0.3, 0]], "reflectance": [0.9, 0.1, 0.2]}])"));
    scene.background_rgb = Rgb{0.0, 0.1, 0.2};
    scene.background = luminance(*scene.background_rgb);
    const std::string text = scene_to_json(scene);
    EXPECT_NE(text.find("\"version\": 4"), std::string::npos);
    const Scene back = parse(text);
    EXPECT_EQ(back, scene);
    EXPECT_EQ(back.channels, 3);
    EXPECT_EQ(scene_to_json(back), text);
    // A colour world whose background is grey writes it as a colour: the file stays colour.
    const Scene grey_background = parse(world_text("[0.5, 0.25, 1]"));
    EXPECT_EQ(parse(scene_to_json(grey_background)).channels, 3);
}

TEST(ColourWorld, BadColoursAreOneLineErrorsNamingTheJsonPath) {
    const SceneErrorCase cases[] = {
        {world_text("[1, 2]"), "objects[0].faces[0].reflectance:", "three finite numbers"},
        {world_text("[1, 2, 3, 4]"), "objects[0].faces[0].reflectance:", "three finite numbers"},
        {world_text(R"([1, "a", 0])"), "objects[0].faces[0].reflectance[1]:", "G component"},
        {world_text("[1e31, 0, 0]"), "objects[0].faces[0].reflectance[0]:", "1e30"},
        {world_text("0.5", "[1, 1]"), "lights[0].intensity:", "three finite numbers"},
        {world_text("0.5", "[1, 1, -2e30]"), "lights[0].intensity[2]:", "1e30"},
        {world_text("0.5", "1", "[0, null, 0]"), "ambient[1]:", "G component"},
        {world_text("0.5", "1", "0.1", 4,
                    R"(, "patterns": [{"loop": [[0, -0.8, 0], [0.5, -0.8, 0], [0.5, -0.3, 0]],
                        "reflectance": [0.9, 0.1]}])"),
         "objects[0].faces[0].patterns[0].reflectance:", "three finite numbers"},
        // Colours need version 4.
        {world_text("[1, 0, 0]", "1", "0.1", 3), "objects[0].faces[0].reflectance:", "version 4"},
        {world_text("0.5", "[1, 0, 0]", "0.1", 2), "lights[0].intensity:", "version 4"},
        // A colour where a number is required.
        {world_text("0.5", "1", "0.1", 4, R"(, "mirror": [0.1, 0.1, 0.1])"),
         "objects[0].faces[0].mirror:", "finite number"},
        // The edge stage composites over one grey image.
        {world_text("[1, 0, 0]", "1", "0.1", 4).insert(1, R"("edges": {}, )"),
         "edges:", "colour world"},
    };
    expect_scene_errors(cases, [](const std::string& text) { parse(text); });
}

// A random colour: each component in [0, 1], or (one time in four) a grey number.
Rgb random_rgb(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> v(0.0, 1.0);
    return {v(rng), v(rng), v(rng)};
}

void colour_or_grey(std::mt19937_64& rng, double scale, double& grey, std::optional<Rgb>& rgb) {
    const Rgb c = random_rgb(rng);
    if (rng() % 4 == 0) {
        grey = scale * c[0];
        rgb.reset();
        return;
    }
    rgb = Rgb{scale * c[0], scale * c[1], scale * c[2]};
    grey = luminance(*rgb);
}

// A seeded random colour world: boxes on a ground quad with patterns, two lights casting
// shadows (parallel and point), coloured or grey, a coloured ambient; every stage in the plan
// but edges and reflections (visibility, culling, patterns, shadows, shading). With
// `many_shadows`, 36 small boxes besides, so that the ground receives more shadows than
// kCutLayerShadows and the overlay takes its shadow layer from the cut ground.
Scene random_colour_world(std::uint64_t seed, int width, int height, bool many_shadows = false) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    World w;
    w.camera.eye = {2.0 + 0.5 * u(rng), 3.0 + 0.5 * u(rng), 5.0};
    w.camera.target = {0.2 * u(rng), 0.3, 0.0};
    w.camera.fov_y_deg = 50.0;
    Object ground = make_quad("ground", {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}, 1.0);
    colour_or_grey(rng, 1.0, ground.faces[0].reflectance, ground.faces[0].reflectance_rgb);
    for (int k = 0; k < 3; ++k) {
        const double s0 = -2.5 + 1.6 * k + 0.3 * u(rng), t0 = -2.0 + 0.5 * u(rng);
        FacePattern p = rect_pattern({-3, 0, 3}, {1, 0, 0}, {0, 0, -1}, s0 + 3, s0 + 3.8, t0 + 3,
                                     t0 + 4.5, 0.0);
        colour_or_grey(rng, 1.0, p.reflectance, p.reflectance_rgb);
        ground.faces[0].patterns.push_back(p);
    }
    w.objects.push_back(ground);
    for (int k = 0; k < 2; ++k) {
        const glm::dvec3 lo(-1.5 + 1.6 * k + 0.3 * u(rng), 0.0, -0.8 + 0.4 * u(rng));
        Object box = make_box(fmt::format("box {}", k), lo,
                              lo + glm::dvec3(0.9, 0.7 + 0.3 * u(rng), 0.8), 0.4 * u(rng), 1.0);
        for (Face& f : box.faces) colour_or_grey(rng, 1.0, f.reflectance, f.reflectance_rgb);
        w.objects.push_back(box);
    }
    for (int k = 0; many_shadows && k < 36; ++k) {
        const glm::dvec3 lo(-2.7 + 0.9 * (k % 6) + 0.1 * u(rng), 0.05, -2.7 + 0.9 * (k / 6));
        Object box = make_box(fmt::format("small box {}", k), lo,
                              lo + glm::dvec3(0.25, 0.3 + 0.1 * u(rng), 0.2), 0.5 * u(rng), 1.0);
        for (Face& f : box.faces) colour_or_grey(rng, 1.0, f.reflectance, f.reflectance_rgb);
        w.objects.push_back(box);
    }
    Light sun;
    sun.direction = {-1.0 + 0.3 * u(rng), -2.0, -1.2};
    sun.shadows = true;
    colour_or_grey(rng, 0.8, sun.intensity, sun.intensity_rgb);
    Light lamp;
    lamp.type = LightType::kPoint;
    lamp.position = {1.5 + 0.3 * u(rng), 2.5, 1.2};
    lamp.shadows = true;
    colour_or_grey(rng, 3.0, lamp.intensity, lamp.intensity_rgb);
    w.lights = {sun, lamp};
    w.ambient_rgb = Rgb{0.1, 0.12, 0.15};
    w.ambient = luminance(*w.ambient_rgb);
    // At least one colour, whatever the draws gave.
    if (!w.is_colour()) w.objects[0].faces[0].reflectance_rgb = Rgb{0.9, 0.3, 0.1};
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.background_rgb = Rgb{0.05, 0.0, 0.1};
    scene.background = luminance(*scene.background_rgb);
    scene.channels = 3;
    check_world(w, "random colour world");
    scene.world = std::move(w);
    return scene;
}

constexpr int kRandomWorlds = 4;
// Seeds past kRandomWorlds draw the world with many shadows (one of them).
constexpr int kManyShadowWorlds = 1;
constexpr int kWorldWidth = 40, kWorldHeight = 30;

// The world with many shadows is past the overlay's threshold on its ground.
TEST(ColourWorlds, TheManyShadowWorldCutsItsGroundsShadowLayer) {
    const Scene scene = random_colour_world(kRandomWorlds + 1, kWorldWidth, kWorldHeight, true);
    const World& w = *scene.world;
    EXPECT_GT(testing::shadows_on_first_face(w, kWorldWidth, kWorldHeight, 0), kCutLayerShadows);
}

// Every method that draws 3-D draws each plane of a colour world as it draws that channel's
// grey world (channel_scene: channel_world and the background's component), bit for bit: the
// pipeline computes each channel as the channel world computes its one, and every method is
// linear in the values. A post-process row is not linear (its edges come from the colour:
// tests/post_process_colour_test.cpp).
class EveryMethodOnColourWorlds : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryMethodOnColourWorlds, EachPlaneIsTheGreyDrawingOfItsChannelWorld) {
    const MethodInstance m = make_method(GetParam());
    if (m.method->traits().post_process) {
        GTEST_SKIP() << "a post-process pass: edges from the colour (post_process_colour_test)";
    }
    for (std::uint64_t seed = 1; seed <= kRandomWorlds + kManyShadowWorlds; ++seed) {
        const Scene scene =
            random_colour_world(seed, kWorldWidth, kWorldHeight, seed > kRandomWorlds);
        const PreparedFrame frame = PreparedFrame::prepare(scene);
        const SceneInput input = frame.input_for(*m.method);
        ASSERT_EQ(input.scene().channels, 3);
        if (!m.method->not_applicable(input.scene()).empty()) {
            GTEST_SKIP() << m.method->not_applicable(input.scene());
        }
        const ImagePlanes planes = render_planes(*m.method, input);
        ASSERT_EQ(planes.channels(), 3);
        for (int c = 0; c < 3; ++c) {
            const Scene channel = channel_scene(scene, c);
            ASSERT_EQ(channel.channels, 1);
            const PreparedFrame grey_frame = PreparedFrame::prepare(channel);
            const Image grey = render_scene(*m.method, grey_frame.input_for(*m.method));
            for (std::size_t k = 0; k < grey.data.size(); ++k) {
                ASSERT_EQ(planes[c].data[k], grey.data[k])
                    << m.spec << " seed " << seed << " channel " << c << " pixel ("
                    << k % kWorldWidth << ", " << k / kWorldWidth << ")";
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryMethodOnColourWorlds,
                         ::testing::ValuesIn(testing::registry_method_ids()),
                         testing::SpecTestName());

// The exact box reference of a colour world, each channel: against the slow clipping oracle of
// tests/slow_reference.h (per-pixel polygon clipping, no code shared with the box reference) on
// the visible pieces with that channel's values, and bit for bit against the reference of the
// channel's grey world. The pieces' colours themselves: each channel is the channel world's
// value of the same piece.
TEST(ColourWorld, ExactReferenceOfEachChannelAgainstTheSlowOracleAndTheChannelWorld) {
    double worst = 0.0;
    for (std::uint64_t seed = 1; seed <= kRandomWorlds; ++seed) {
        const Scene scene = random_colour_world(seed, kWorldWidth, kWorldHeight);
        const PreparedFrame frame = PreparedFrame::prepare(scene);
        const SceneInput pieces = frame.pieces();
        const CoveragePlanes reference = exact_reference_planes(pieces, Filter::box());
        ASSERT_EQ(reference.channels(), 3);
        for (int c = 0; c < 3; ++c) {
            const PreparedFrame grey_frame = PreparedFrame::prepare(channel_scene(scene, c));
            const Scene& grey_pieces = grey_frame.pieces().scene();
            ASSERT_EQ(grey_pieces.shapes.size(), pieces.scene().shapes.size()) << "seed " << seed;
            Scene oracle = grey_pieces;
            for (std::size_t k = 0; k < grey_pieces.shapes.size(); ++k) {
                const Shape& coloured = pieces.scene().shapes[k];
                ASSERT_EQ(channel_value(coloured, c), grey_pieces.shapes[k].value)
                    << "seed " << seed << " channel " << c << " piece " << k;
                ASSERT_EQ(coloured.contours, grey_pieces.shapes[k].contours);
            }
            const Coverage grey_reference = exact_reference(grey_frame.pieces(), Filter::box());
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    ASSERT_EQ(reference[c].at(i, j), grey_reference.at(i, j))
                        << "seed " << seed << " channel " << c << " pixel " << i << "," << j;
                    const double slow = testing::slow_box_pixel(oracle, i, j);
                    const double error = std::abs(reference[c].at(i, j) - slow);
                    worst = std::max(worst, error);
                    ASSERT_LE(error, kReferenceTolerance)
                        << "seed " << seed << " channel " << c << " pixel " << i << "," << j;
                }
            }
        }
    }
    RecordProperty("worst_reference_error", fmt::format("{:.3g}", worst));
}

// The shading stage's colour by an independent computation: a face lit by one parallel light
// with no shadow, value per channel reflectance x (ambient + intensity x n . l).
TEST(ColourWorld, ShadedColourIsReflectanceTimesIlluminancePerChannel) {
    const Scene scene = parse(world_text("[0.5, 0.25, 1]", "[1, 0.5, 0.25]", "[0.1, 0.2, 0.3]"));
    const PreparedFrame frame = PreparedFrame::prepare(scene);
    const Scene& screen = frame.screen();
    ASSERT_EQ(screen.channels, 3);
    ASSERT_EQ(screen.shapes.size(), 1u);
    const Shape& s = screen.shapes[0];
    ASSERT_TRUE(s.rgb.has_value());
    // The face faces the light head on (n . l = 1).
    const Rgb expected{0.5 * (0.1 + 1.0), 0.25 * (0.2 + 0.5), 1.0 * (0.3 + 0.25)};
    for (int c = 0; c < 3; ++c) EXPECT_DOUBLE_EQ((*s.rgb)[c], expected[c]) << "channel " << c;
    EXPECT_DOUBLE_EQ(s.value, luminance(expected));
    // Depth images stay grey.
    const PreparedFrame with_depth = PreparedFrame::prepare(scene, {.depth_image = true});
    EXPECT_EQ(with_depth.depth_screen().channels, 1);
    EXPECT_EQ(with_depth.depth_pieces().scene().channels, 1);
}

// The colour room's neighbouring faces differ more in chroma than in luma somewhere: the
// floor against the back wall, each seen lit as the pipeline shades it (the largest piece of
// each face on screen).
TEST(ColourRoomPattern, SomeNeighbouringFacesDifferMoreInChromaThanInLuma) {
    const Scene scene = make_pattern("colour-room", 128, 96);
    ASSERT_EQ(scene.channels, 3);
    const PreparedFrame frame = PreparedFrame::prepare(scene);
    const Scene& screen = frame.screen();
    // The floor (face 0), the back wall (1) and the left wall (2): each face's role-face cell
    // that covers most area on screen, its lit colour.
    const auto colour_of = [&](int face) {
        double best = -1.0;
        Rgb colour{};
        for (const Shape& s : screen.shapes) {
            if (s.face != face || s.role != ShapeRole::kFace || !s.rgb) continue;
            double area = 0.0;
            const Contour& c = s.contours[0];
            for (std::size_t k = 0; k < c.size(); ++k) {
                const Point& a = c[k];
                const Point& b = c[(k + 1) % c.size()];
                area += a.x * b.y - b.x * a.y;
            }
            if (std::abs(area) > best) {
                best = std::abs(area);
                colour = *s.rgb;
            }
        }
        return colour;
    };
    // YCoCg (Malvar & Sullivan 2003): luma Y and the two chroma axes of one scale.
    const auto luma_chroma = [](const Rgb& a, const Rgb& b) {
        const Rgb d{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
        const double y = 0.25 * d[0] + 0.5 * d[1] + 0.25 * d[2];
        const double co = 0.5 * d[0] - 0.5 * d[2];
        const double cg = -0.25 * d[0] + 0.5 * d[1] - 0.25 * d[2];
        return std::pair{std::abs(y), std::hypot(co, cg)};
    };
    int chroma_wins = 0;
    for (const auto& [a, b] : {std::pair{0, 1}, std::pair{0, 2}, std::pair{1, 2}}) {
        const auto [luma, chroma] = luma_chroma(colour_of(a), colour_of(b));
        RecordProperty(fmt::format("faces_{}_{}", a, b),
                       fmt::format("luma {:.4f} chroma {:.4f}", luma, chroma));
        chroma_wins += chroma > luma;
    }
    EXPECT_GE(chroma_wins, 1);
}

}  // namespace
}  // namespace aabench
