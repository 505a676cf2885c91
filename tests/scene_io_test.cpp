// The scene file reader and writer: exact round trips on seeded random scenes with awkward
// doubles, the documented samples accepted, and one case per error class with the JSON path
// the message must name.
#include "patterns/scene/scene_io.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace aabench {
namespace {

constexpr char kSource[] = "test.json";

// Doubles that trip up writers that print a fixed number of digits or drop the sign of zero.
const std::vector<double> kAwkwardDoubles = {
    0.1 + 0.2,     // 0.30000000000000004: needs all 17 significant digits
    1e-300,        // tiny normal
    1073741824.3,  // 2^30 + 0.3: large integer part, fraction still significant
    -0.0,          // must come back negative
    0.0,
    5e-324,                   // smallest subnormal
    2.2250738585072014e-308,  // DBL_MIN
    1.7976931348623157e308,   // DBL_MAX
    1.0 / 3.0,
    3.0,  // integral: written "3.0" so it reads back as a float
    -1e22,
    9007199254740993.0,  // 2^53 + 1 rounds to 2^53 in double: what is stored round-trips
    0.5 - 1.0 / 3.0,
};

// Bit-exact comparison: Scene::operator== says 0.0 == -0.0, the round trip promises more.
bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

// Empty when bit-identical, else where the first difference is.
std::string first_difference(const Scene& a, const Scene& b) {
    if (a.width != b.width || a.height != b.height) return "size";
    if (!same_bits(a.origin_x, b.origin_x) || !same_bits(a.origin_y, b.origin_y)) return "origin";
    if (!same_bits(a.background, b.background)) return "background";
    if (a.metadata != b.metadata) return "metadata";
    if (a.shapes.size() != b.shapes.size()) return "shape count";
    for (std::size_t s = 0; s < a.shapes.size(); ++s) {
        const Shape& sa = a.shapes[s];
        const Shape& sb = b.shapes[s];
        if (!same_bits(sa.value, sb.value)) return fmt::format("shapes[{}].value", s);
        if (sa.contours.size() != sb.contours.size()) return fmt::format("shapes[{}]", s);
        for (std::size_t k = 0; k < sa.contours.size(); ++k) {
            if (sa.contours[k].size() != sb.contours[k].size()) {
                return fmt::format("shapes[{}].contours[{}] size", s, k);
            }
            for (std::size_t p = 0; p < sa.contours[k].size(); ++p) {
                const Point& pa = sa.contours[k][p];
                const Point& pb = sb.contours[k][p];
                if (!same_bits(pa.x, pb.x) || !same_bits(pa.y, pb.y)) {
                    return fmt::format("shapes[{}].contours[{}][{}]: [{}, {}] vs [{}, {}]", s, k, p,
                                       pa.x, pa.y, pb.x, pb.y);
                }
            }
        }
    }
    return "";
}

// Any finite double: awkward ones, uniform in a pixel range, and raw bit patterns (every
// exponent, subnormals included).
double random_double(std::mt19937_64& rng) {
    switch (rng() % 3) {
        case 0:
            return kAwkwardDoubles[rng() % kAwkwardDoubles.size()];
        case 1:
            return std::uniform_real_distribution<double>(-10.0, 300.0)(rng);
        default:
            for (;;) {
                const double value = std::bit_cast<double>(rng());
                if (std::isfinite(value)) return value;
            }
    }
}

// Any coordinate a scene may hold: a random double within kMaxCoordinate (1e300).
double random_coordinate(std::mt19937_64& rng) {
    for (;;) {
        const double v = random_double(rng);
        if (std::abs(v) <= kMaxCoordinate) return v;
    }
}

// A random value within what the reader accepts (kMaxValue: images are float32).
double random_value(std::mt19937_64& rng) {
    for (;;) {
        const double v = random_double(rng);
        if (std::abs(v) <= kMaxValue) return v;
    }
}

Scene random_scene(std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    Scene scene;
    scene.width = 1 + static_cast<int>(rng() % 512);
    scene.height = 1 + static_cast<int>(rng() % 512);
    scene.background = random_value(rng);
    if (rng() % 2 == 0) {  // half the scenes have a window origin, any finite double
        scene.origin_x = random_coordinate(rng);
        scene.origin_y = random_coordinate(rng);
    }
    scene.metadata = {{"pattern", "random"},
                      {"seed", std::to_string(seed)},
                      {"quote \" and \\ backslash", "tab\tnewline\n"},
                      {"", "empty key"},
                      {"unicode", "\xc3\xa9\xe2\x88\x9a\xf0\x9f\x98\x80"},  // é √ 😀
                      {"zzz", "last, so order is checked"}};
    const int shapes = 1 + static_cast<int>(rng() % 5);
    for (int s = 0; s < shapes; ++s) {
        Shape shape;
        shape.value = random_value(rng);
        const int contours = 1 + static_cast<int>(rng() % 4);
        for (int c = 0; c < contours; ++c) {
            Contour contour;
            const int points = 3 + static_cast<int>(rng() % 40);
            for (int p = 0; p < points; ++p)
                contour.push_back({random_coordinate(rng), random_coordinate(rng)});
            shape.contours.push_back(contour);
        }
        scene.shapes.push_back(shape);
    }
    return scene;
}

TEST(SceneIo, RandomScenesRoundTripBitExact) {
    constexpr std::uint64_t kScenes = 200;
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = random_scene(seed);
        const std::string text = scene_to_json(scene);
        const Scene back = parse_scene_json(text, kSource);
        ASSERT_EQ(first_difference(scene, back), "") << "seed " << seed << "\n" << text;
        // Writing again gives the same text: the writer is deterministic.
        ASSERT_EQ(scene_to_json(back), text) << "seed " << seed;
    }
}

TEST(SceneIo, AwkwardDoublesRoundTripBitExact) {
    Scene scene;
    scene.width = 4;
    scene.height = 4;
    for (const double awkward : kAwkwardDoubles) {
        // As a value and as a coordinate only within their limits (DBL_MAX is neither).
        const double value =
            std::abs(awkward) <= kMaxValue ? awkward : std::copysign(kMaxValue, awkward);
        const double c =
            std::abs(awkward) <= kMaxCoordinate ? awkward : std::copysign(kMaxCoordinate, awkward);
        scene.background = value;
        scene.shapes = {Shape{{{{c, -c}, {c, 1.0}, {2.0, c}}}, value}};
        const Scene back = parse_scene_json(scene_to_json(scene), kSource);
        EXPECT_EQ(first_difference(scene, back), "") << fmt::format("{:.17g}", value);
    }
    // -0.0 is written with its sign rather than as 0 or -0 (which reads back as integer 0).
    scene.background = -0.0;
    EXPECT_NE(scene_to_json(scene).find("\"background\": -0.0,"), std::string::npos);
}

TEST(SceneIo, WriterIsCompactForLargePatterns) {
    constexpr int kVertices = 4096;
    // Two shortest-round-trip doubles (at most 24 characters each, e.g.
    // "-2.2250738585072014e-308") plus "[", ",", "]," per vertex.
    constexpr std::size_t kMaxBytesPerVertex = 2 * 24 + 4;
    constexpr std::size_t kFixedOverhead = 256;  // braces, keys, one shape's header
    Scene scene;
    scene.width = 1024;
    scene.height = 1024;
    Contour contour;
    std::mt19937_64 rng(7);
    for (int k = 0; k < kVertices; ++k) {
        contour.push_back({random_coordinate(rng), random_coordinate(rng)});
    }
    scene.shapes = {Shape{{contour}, 1.0}};
    const std::string text = scene_to_json(scene);
    EXPECT_LE(text.size(), kVertices * kMaxBytesPerVertex + kFixedOverhead);
    // One line per top-level key and per shape and contour, not per vertex.
    EXPECT_LE(std::count(text.begin(), text.end(), '\n'), 12);
    EXPECT_EQ(first_difference(scene, parse_scene_json(text, kSource)), "");
}

TEST(SceneIo, EmptySceneRoundTrips) {
    Scene scene;
    scene.width = 1;
    scene.height = 1;
    EXPECT_EQ(parse_scene_json(scene_to_json(scene), kSource), scene);
}

TEST(SceneIo, AcceptsAMinimalVersionOneFile) {
    // A minimal version-1 file, with numbers in place of x and y.
    const Scene scene = parse_scene_json(R"({ "width": 256, "height": 256, "background": 0.0,
      "shapes": [ { "type": "polygon", "value": 1.0,
                    "contours": [ [[10.5, 20], [200, 30.25], [120, 240]] ] } ] })",
                                         kSource);
    EXPECT_EQ(scene.width, 256);
    EXPECT_EQ(scene.height, 256);
    EXPECT_EQ(scene.background, 0.0);
    ASSERT_EQ(scene.shapes.size(), 1u);
    EXPECT_EQ(scene.shapes[0].value, 1.0);
    const Contour expected = {{10.5, 20.0}, {200.0, 30.25}, {120.0, 240.0}};
    EXPECT_EQ(scene.shapes[0].contours, std::vector<Contour>{expected});
}

TEST(SceneIo, VersionOneWithoutExtensionsAndWithDefaults) {
    // No version, no metadata, no background, no value: the defaults apply.
    const Scene scene = parse_scene_json(
        R"({"width": 3, "height": 2, "shapes": [{"type": "polygon",
            "contours": [[[0, 0], [1, 0], [1, 1]], [[2, 0], [3, 0], [3, 2], [2, 2]]]}]})",
        kSource);
    EXPECT_EQ(scene.width, 3);
    EXPECT_EQ(scene.height, 2);
    EXPECT_EQ(scene.background, 0.0);
    EXPECT_TRUE(scene.metadata.empty());
    ASSERT_EQ(scene.shapes.size(), 1u);
    EXPECT_EQ(scene.shapes[0].value, 1.0);
    EXPECT_EQ(scene.shapes[0].contours.size(), 2u);

    const Scene empty = parse_scene_json(R"({"width": 1, "height": 1, "shapes": []})", kSource);
    EXPECT_TRUE(empty.shapes.empty());
}

TEST(SceneIo, ExtensionKeysKeepMetadataOrder) {
    const Scene scene = parse_scene_json(
        R"({"version": 1, "width": 8, "height": 8, "background": 0.25,
            "metadata": {"zeta": "1", "alpha": "2", "mid": "3"}, "shapes": []})",
        kSource);
    const Metadata expected = {{"zeta", "1"}, {"alpha", "2"}, {"mid", "3"}};
    EXPECT_EQ(scene.metadata, expected);
    EXPECT_EQ(scene.background, 0.25);
    // The writer keeps the Scene's order too.
    const std::string text = scene_to_json(scene);
    EXPECT_LT(text.find("zeta"), text.find("alpha"));
    EXPECT_LT(text.find("alpha"), text.find("mid"));
}

TEST(SceneIo, OriginIsOptionalAndWrittenOnlyWhenSet) {
    const Scene plain = parse_scene_json(R"({"width": 4, "height": 3, "shapes": []})", kSource);
    EXPECT_EQ(plain.origin_x, 0.0);
    EXPECT_EQ(plain.origin_y, 0.0);
    EXPECT_EQ(scene_to_json(plain).find("origin"), std::string::npos);

    const Scene far = parse_scene_json(
        R"({"width": 4, "height": 3, "origin": [1048576, -1073741824.25], "shapes": []})", kSource);
    EXPECT_EQ(far.origin_x, 1048576.0);
    EXPECT_EQ(far.origin_y, -1073741824.25);
    const std::string text = scene_to_json(far);
    EXPECT_NE(text.find("\"origin\": [1048576.0,-1073741824.25],"), std::string::npos) << text;
    EXPECT_EQ(first_difference(far, parse_scene_json(text, kSource)), "");

    // -0.0 is kept too: the round trip is bit for bit.
    Scene negative_zero = plain;
    negative_zero.origin_y = -0.0;
    EXPECT_EQ(
        first_difference(negative_zero, parse_scene_json(scene_to_json(negative_zero), kSource)),
        "");
}

TEST(SceneIo, InWindowFrameSubtractsTheOriginExactlyNearIt) {
    // Window coordinates on a 2^-20 grid, placed at 2^30: every sum is exact, and so is every
    // difference (Sterbenz), so the window frame gives back the coordinates bit for bit.
    constexpr double kOrigin = 1073741824.0;  // 2^30
    Scene window;
    window.width = 8;
    window.height = 8;
    window.shapes = {Shape{{{{0.5, 0.25}, {7.0 + 0x1p-20, 1.0}, {3.0, 6.5 - 0x1p-20}}}, 1.0}};
    window.thin_objects = {{"t", window.shapes[0]}};
    Scene far = window;
    far.origin_x = kOrigin;
    far.origin_y = -kOrigin;
    for (Shape* shape : {&far.shapes[0], &far.thin_objects[0].shape}) {
        for (Point& p : shape->contours[0]) p = {p.x + kOrigin, p.y - kOrigin};
    }
    EXPECT_FALSE(is_window_frame(far));
    EXPECT_TRUE(is_window_frame(window));
    EXPECT_EQ(in_window_frame(far), window);
    EXPECT_EQ(in_window_frame(window), window);
}

TEST(SceneIo, VertexLimitStopsTheParserAtTheFirstPointPastIt) {
    constexpr long long kLimit = 7;  // a test-sized limit; the real one is kMaxSceneVertices
    const std::string two_triangles = R"({"width": 4, "height": 4, "shapes": [
        {"type": "polygon", "contours": [[[0, 0], [1, 0], [0, 1]], [[2, 2], [3, 2], [2, 3]]]}]})";
    EXPECT_EQ(parse_scene_json(two_triangles, kSource, 6).shapes[0].contours.size(), 2u);
    const std::string eight = R"({"width": 4, "height": 4, "shapes": [
        {"type": "polygon", "contours": [[[0, 0], [1, 0], [0, 1]], [[2, 2], [3, 2], [2, 3]]]},
        {"type": "polygon", "contours": [[[0, 0], [1, 0]]]}]})";
    try {
        parse_scene_json(eight, kSource, kLimit);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
        // The eighth point, shapes[1].contours[0][1], is where it stops (before the contour is
        // even complete, and before the short contour would be reported).
        EXPECT_EQ(std::string(error.what()),
                  "test.json: shapes[1].contours[0][1]: more than 7 vertices in the scene "
                  "(the limit, docs/limits.md)");
    }
    // Arrays nested as deep as points, elsewhere, are not points: the error is the real one.
    try {
        parse_scene_json(R"({"metadata": {"a": [[[[1]]]]}, "width": 1, "height": 1, "shapes": []})",
                         kSource, 0);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("metadata.a: expected a string value"),
                  std::string::npos)
            << error.what();
    }
}

// --- Errors: one per class, each naming the JSON path ---

// A valid shape, to build files around one bad part.
constexpr char kGoodShape[] = R"({"type": "polygon", "contours": [[[0, 0], [4, 0], [0, 4]]]})";

std::string with_shape(const std::string& second_shape) {
    return fmt::format(R"({{"width": 16, "height": 16, "shapes": [{}, {}]}})", kGoodShape,
                       second_shape);
}

std::string with_top(const std::string& members) {
    return fmt::format(R"({{"width": 16, "height": 16, "shapes": [{}]{}}})", kGoodShape, members);
}

std::string with_point(const std::string& point) {
    return with_shape(
        fmt::format(R"({{"type": "polygon", "contours": [[[0, 0], [1, 0], {}]]}})", point));
}

struct ErrorCase {
    const char* what;
    std::string text;
    std::string expected_start;  // after "test.json: "
};

std::vector<ErrorCase> error_cases() {
    return {
        // Unknown keys.
        {"unknown top-level key", with_top(R"(, "colour": 1)"), "colour: unknown key"},
        {"unknown shape key", with_shape(R"({"type": "polygon", "colour": 1, "contours": []})"),
         "shapes[1].colour: unknown key"},
        {"unknown key, odd name", with_top(R"(, "a.b": 1)"), R"(["a.b"]: unknown key)"},
        // Wrong types.
        {"width not integral", R"({"width": 256.5, "height": 16, "shapes": []})", "width: "},
        {"width a string", R"({"width": "256", "height": 16, "shapes": []})", "width: "},
        {"width 256.0 is a float", R"({"width": 256.0, "height": 16, "shapes": []})", "width: "},
        {"height missing", R"({"width": 16, "shapes": []})", "height: required key is missing"},
        {"shapes missing", R"({"width": 16, "height": 16})", "shapes: required key is missing"},
        {"shapes not an array", R"({"width": 16, "height": 16, "shapes": {}})", "shapes: "},
        {"shape not an object", with_shape("[]"), "shapes[1]: expected a shape object"},
        {"background a string", with_top(R"(, "background": "0")"), "background: "},
        {"value a bool", with_shape(R"({"type": "polygon", "value": true,
            "contours": [[[0, 0], [1, 0], [0, 1]]]})"),
         "shapes[1].value: expected a finite number"},
        {"type missing", with_shape(R"({"contours": [[[0, 0], [1, 0], [0, 1]]]})"),
         "shapes[1].type: required key is missing"},
        {"type unknown",
         with_shape(R"({"type": "circle", "contours": [[[0, 0], [1, 0], [0, 1]]]})"),
         "shapes[1].type: unknown shape type \"circle\""},
        {"contours missing", with_shape(R"({"type": "polygon"})"),
         "shapes[1].contours: required key is missing"},
        {"contour not an array", with_shape(R"({"type": "polygon", "contours": [7]})"),
         "shapes[1].contours[0]: expected a contour"},
        // Points.
        {"point of one number", with_point("[1]"), "shapes[1].contours[0][2]: expected a point"},
        {"point of three numbers", with_point("[1, 2, 3]"),
         "shapes[1].contours[0][2]: expected a point"},
        {"point with a string", with_point(R"(["1", 2])"),
         "shapes[1].contours[0][2]: expected a point"},
        {"point an object", with_point(R"({"x": 1, "y": 2})"),
         "shapes[1].contours[0][2]: curve items (quad, cubic) need \"version\": 4"},
        {"point null", with_point("null"), "shapes[1].contours[0][2]: expected a point"},
        // Non-finite numbers: JSON has no inf/NaN literal; an overflowing one is caught.
        {"coordinate 1e999", with_point("[1, 1e999]"),
         "shapes[1].contours[0][2][1]: number 1e999 is not a finite double"},
        {"value -1e400", with_shape(R"({"type": "polygon", "value": -1e400,
            "contours": [[[0, 0], [1, 0], [0, 1]]]})"),
         "shapes[1].value: number -1e400 is not a finite double"},
        // Values past what a float32 image holds (kMaxValue, 1e30).
        {"value 1e31", with_shape(R"({"type": "polygon", "value": 1e31,
            "contours": [[[0, 0], [1, 0], [0, 1]]]})"),
         "shapes[1].value: 1e+31 is beyond the values an image holds"},
        {"background -1e50", with_top(R"(, "background": -1e50)"),
         "background: -1e+50 is beyond the values an image holds"},
        {"NaN literal", with_point("[1, NaN]"), "byte "},
        // Too few points, no contours.
        {"contour of two points",
         with_shape(R"({"type": "polygon", "contours": [[[0, 0], [1, 0]]]})"),
         "shapes[1].contours[0]: a contour needs at least 3 points, found 2"},
        {"shape with no contours", with_shape(R"({"type": "polygon", "contours": []})"),
         "shapes[1].contours: a shape needs at least one contour"},
        // Sizes out of range.
        {"width zero", R"({"width": 0, "height": 16, "shapes": []})",
         "width: 0x16 is out of range"},
        {"height negative", R"({"width": 16, "height": -3, "shapes": []})",
         "height: 16x-3 is out of range"},
        {"side too long", R"({"width": 65537, "height": 1, "shapes": []})",
         "width: 65537x1 is out of range"},
        {"too many pixels", R"({"width": 65536, "height": 1025, "shapes": []})",
         "width, height: size 65536x1025 has"},
        {"width beyond 64 bits", R"({"width": 18446744073709551615, "height": 1, "shapes": []})",
         "width: 18446744073709551615 is out of range"},
        // Version and metadata extensions.
        {"version 5", with_top(R"(, "version": 5)"), "version: unsupported version 5"},
        {"version 1.0", with_top(R"(, "version": 1.0)"), "version: expected the integer 1"},
        {"version string", with_top(R"(, "version": "1")"), "version: expected the integer 1"},
        {"version checked before unknown keys", with_top(R"(, "depth": [], "version": 5)"),
         "version: unsupported version 5"},
        {"metadata not an object", with_top(R"(, "metadata": ["a"])"), "metadata: expected"},
        {"metadata number value", with_top(R"(, "metadata": {"a": "x", "n": 64})"),
         "metadata.n: expected a string value, found 64"},
        {"origin of one number", with_top(R"(, "origin": [1])"),
         "origin: expected a point [x, y] of two finite numbers, found [1]"},
        {"origin a string", with_top(R"(, "origin": "0,0")"), "origin: expected a point"},
        {"origin 1e999", with_top(R"(, "origin": [0, 1e999])"),
         "origin[1]: number 1e999 is not a finite double"},
        {"origin beyond 1e300", with_top(R"(, "origin": [0, -1e301])"),
         "origin: beyond the coordinate limit of 1e300 px"},
        {"coordinate beyond 1e300", with_point("[1e300, 1.5e308]"),
         "shapes[1].contours[0][2][1]: coordinate 1.5e+308 is beyond the limit of 1e300 px"},
        // Duplicates, which nlohmann would otherwise resolve silently.
        {"duplicate top-level key", R"({"width": 16, "width": 32, "height": 16, "shapes": []})",
         "width: duplicate key"},
        {"duplicate shape key", with_shape(R"({"type": "polygon", "value": 1, "value": 2,
            "contours": [[[0, 0], [1, 0], [0, 1]]]})"),
         "shapes[1].value: duplicate key"},
        // Syntax, empty, not an object.
        {"syntax error", R"({"width": 16, "height": 16, "shapes": [})", "byte 40: invalid JSON ("},
        {"trailing text", R"({"width": 1, "height": 1, "shapes": []} x)", "byte "},
        {"truncated", R"({"width": 1, "height": 1, "sha)", "byte "},
        {"invalid UTF-8", "{\"width\": 1, \"height\": 1, \"shapes\": [], \"\xff\": 1}", "byte "},
        {"empty", "", "empty file"},
        {"only whitespace", " \n\t ", "empty file"},
        {"top level an array", "[]", "expected a JSON object at the top level, found []"},
        {"top level a number", "42", "expected a JSON object at the top level, found 42"},
        {"nested too deep", std::string(100, '[') + std::string(100, ']'), "[0]"},
    };
}

TEST(SceneIo, EachErrorClassNamesItsPath) {
    for (const ErrorCase& c : error_cases()) {
        SCOPED_TRACE(c.what);
        try {
            parse_scene_json(c.text, kSource);
            ADD_FAILURE() << "accepted: " << c.text;
        } catch (const InputError& error) {
            const std::string message = error.what();
            const std::string expected = std::string(kSource) + ": " + c.expected_start;
            EXPECT_EQ(message.substr(0, expected.size()), expected) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

TEST(SceneIo, SyntaxErrorsGiveTheByteOffset) {
    // `{"a":}`: nlohmann stops at the '}' which is byte 6 (1-based).
    try {
        parse_scene_json(R"({"a":})", kSource);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "test.json: byte 6: invalid JSON (line 1, column 6: syntax error while parsing "
                  "value - unexpected '}'; expected '[', '{', or a literal)");
    }
}

TEST(SceneIo, WriterRejectsWhatJsonCannotHold) {
    Scene scene;
    scene.width = 4;
    scene.height = 4;
    scene.shapes = {Shape{{{{0, 0}, {1, 0}, {0, std::numeric_limits<double>::infinity()}}}, 1.0}};
    EXPECT_THROW(scene_to_json(scene), InputError);
    try {
        scene_to_json(scene);
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("shapes[0].contours[0][2]"), std::string::npos)
            << error.what();
    }
    scene.shapes.clear();
    scene.background = std::nan("");
    EXPECT_THROW(scene_to_json(scene), InputError);
    scene.background = 0.0;
    scene.metadata = {{"bad", "\xff"}};
    EXPECT_THROW(scene_to_json(scene), InputError);
}

class SceneFileTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               fmt::format("aabench_scene_io_test_{}", ::getpid());
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::filesystem::path dir_;
};

TEST_F(SceneFileTest, ReadsAFileAndNamesItInErrors) {
    const std::string good = (dir_ / "good.json").string();
    std::ofstream(good) << with_top("");
    EXPECT_EQ(read_scene_file(good).shapes.size(), 1u);

    const std::string bad = (dir_ / "bad.json").string();
    std::ofstream(bad) << with_point("[1]");
    try {
        read_scene_file(bad);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()).rfind(bad + ": shapes[1].contours[0][2]: ", 0), 0u)
            << error.what();
    }

    const std::string empty = (dir_ / "empty.json").string();
    std::ofstream(empty).flush();
    EXPECT_THROW(read_scene_file(empty), InputError);
}

TEST_F(SceneFileTest, UnreadableFilesAreInputErrors) {
    const std::string missing = (dir_ / "missing.json").string();
    try {
        read_scene_file(missing);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()), missing + ": cannot open: No such file or directory");
    }
    try {
        read_scene_file(dir_.string());
        ADD_FAILURE() << "accepted a directory";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()).rfind(dir_.string() + ": cannot", 0), 0u)
            << error.what();
    }
}

}  // namespace
}  // namespace aabench
