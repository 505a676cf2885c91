// Scene file version 4, curve part (docs/scene-format.md, "Version 4: curves"): contour items
// `quad` and `cubic`, shapes of "type": "path" with `svg_path`, the writer's round trip, and
// every bad input refused in one line naming its JSON path (and the character of the path data).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <random>

#include "cli_runner.h"
#include "methods/method.h"
#include "patterns/scene/bezier.h"
#include "patterns/scene/scene_io.h"
#include "patterns/scene/svg_path.h"

namespace aabench {
namespace {

constexpr const char* kSource = "v4.json";

std::string with_shape(const std::string& shape) {
    return R"({"version": 4, "width": 32, "height": 32, "shapes": [)" + shape + "]}";
}

Scene parse(const std::string& text) { return parse_scene_json(text, kSource); }

// The same region written three ways: contour items, absolute path data, relative path data.
const char* kItems = R"({"type": "polygon", "value": 0.75, "contours": [
    [[4, 4], [20, 4], {"quad": [[28, 12], [20, 20]]}, {"cubic": [[14, 26], [8, 18], [4, 24]]}]]})";
const char* kAbsolute =
    R"({"type": "path", "value": 0.75, "svg_path": "M4,4 L20,4 Q28,12 20,20 C14,26 8,18 4,24 Z"})";
const char* kRelative =
    R"({"type": "path", "value": 0.75, "svg_path": "m4 4h16q8 8 0 16c-6 6-12-2-16 4z"})";

TEST(SceneIoV4, ContourItemsAndPathDataGiveTheSameShape) {
    const Scene items = parse(with_shape(kItems));
    ASSERT_EQ(items.shapes.size(), 1u);
    const Shape& shape = items.shapes[0];
    ASSERT_EQ(shape.outline.size(), 1u);
    ASSERT_EQ(shape.outline[0].size(), 4u);  // line, quad, cubic, the closing line
    EXPECT_EQ(shape.outline[0][1].degree, 2);
    EXPECT_EQ(shape.outline[0][2].degree, 3);
    EXPECT_EQ(shape.outline[0][3].end(), (Point{4, 4}));
    EXPECT_EQ(parse(with_shape(kAbsolute)).shapes[0], shape);
    EXPECT_EQ(parse(with_shape(kRelative)).shapes[0], shape);
}

// Done when: a file with svg_path and the same shape as contours give identical images for
// every method.
TEST(SceneIoV4, EveryMethodDrawsThePathAsItsContours) {
    const Scene items = parse(with_shape(kItems));
    const Scene path = parse(with_shape(kRelative));
    int drawn = 0;
    for (const MethodInfo& info : method_registry()) {
        const MethodInstance m = make_method(info.id);
        if (!m.method->not_applicable(items).empty()) continue;
        const Image a = render_scene(*m.method, items), b = render_scene(*m.method, path);
        EXPECT_EQ(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)), 0)
            << info.id;
        ++drawn;
    }
    EXPECT_GT(drawn, 10);
}

TEST(SceneIoV4, PathDataGrammar) {
    auto contours = [](const char* d) { return parse_svg_path(d, 1e9); };
    // Implicit linetos after a moveto, numbers run together, exponents, a leading '.'.
    const auto a = contours("M1.5.5 10-5e0 1e1,10");
    ASSERT_EQ(a.size(), 1u);
    EXPECT_EQ(a[0][0].p[0], (Point{1.5, 0.5}));
    EXPECT_EQ(a[0][0].p[1], (Point{10, -5}));
    EXPECT_EQ(a[0][1].p[1], (Point{10, 10}));
    EXPECT_EQ(a[0].size(), 3u);  // and the closing edge
    // Smooth curves reflect the previous control point; T after a cubic does not.
    const auto t = contours("M0 0 Q 10 0 10 10 T 20 20 L 0 20 Z");
    ASSERT_EQ(t[0][1].degree, 2);
    EXPECT_EQ(t[0][1].p[1], (Point{10, 20}));
    const auto s = contours("M0 0 C 5 0 10 5 10 10 S 20 20 20 30 T 0 30 Z");
    EXPECT_EQ(s[0][1].p[1], (Point{10, 15}));
    EXPECT_EQ(s[0][2].p[1], (Point{20, 30}));  // T after S: the current point
    // Two subpaths; a drawing command after Z starts at the last subpath's start.
    const auto two = contours("M0 0 L 10 0 L 0 10 Z l 5 5 l -5 5 z M 20 20 h 5 v 5 z");
    ASSERT_EQ(two.size(), 3u);
    EXPECT_EQ(two[1][0].p[0], (Point{0, 0}));
    EXPECT_EQ(two[1][0].p[1], (Point{5, 5}));
    // A subpath enclosing nothing is dropped, as renderers draw it.
    EXPECT_EQ(contours("M0 0 L 10 10 M 0 0 L 4 0 L 0 4").size(), 1u);
}

TEST(SceneIoV4, WriterRoundTripsBitForBit) {
    std::mt19937_64 rng(44);
    std::uniform_real_distribution<double> u(-5.0, 40.0);
    for (int trial = 0; trial < 20; ++trial) {
        Scene scene;
        scene.width = 33;
        scene.height = 29;
        for (int k = 0; k < 3; ++k) {
            SegmentContour c;
            const Point start{u(rng), u(rng)};
            Point cur = start;
            const int n = 1 + trial % 4;
            for (int s = 0; s < n; ++s) {
                Segment seg;
                seg.degree = 1 + static_cast<int>(rng() % 3);
                seg.p[0] = cur;
                for (int q = 1; q <= seg.degree; ++q) seg.p[q] = {u(rng), u(rng)};
                if (s + 1 == n && seg.degree > 1) seg.p[seg.degree] = start;  // ends at the start
                c.push_back(seg);
                cur = seg.end();
            }
            if (!(cur == start)) {
                Segment closing;
                closing.p[0] = cur;
                closing.p[1] = start;
                c.push_back(closing);
            }
            bool curved = false;
            for (const Segment& seg : c) curved = curved || seg.degree > 1;
            if (!curved && c.size() < 3) continue;  // two points are no contour
            scene.shapes.push_back(bezier_shape({c}, 0.1 * k - 0.05));
        }
        const std::string text = scene_to_json(scene);
        EXPECT_EQ(text.find("\"version\": 4") != std::string::npos, has_bezier(scene)) << text;
        EXPECT_EQ(parse(text), scene) << text;
    }
    // Without curves nothing changes: a polygon path is written as version 1.
    const Scene polygon = parse(with_shape(R"({"type": "path", "svg_path": "M0 0 H 9 V 9 Z"})"));
    EXPECT_NE(scene_to_json(polygon).find("\"version\": 1"), std::string::npos);
}

struct ErrorCase {
    const char* what;
    std::string text;
    std::string expected_start;  // after "v4.json: "
};

std::vector<ErrorCase> error_cases() {
    auto path = [](const std::string& d) {
        return with_shape(R"({"type": "path", "svg_path": )" + d + "}");
    };
    auto contour = [](const std::string& items) {
        return with_shape(R"({"type": "polygon", "contours": [)" + items + "]}");
    };
    auto text = [](const std::string& keys) {
        return with_shape(R"({"type": "text", )" + keys + "}");
    };
    return {
        {"curve item in version 3",
         R"({"version": 3, "width": 8, "height": 8, "shapes": [{"type": "polygon", "contours": [[[0,0], {"quad": [[1,1],[2,0]]}]]}]})",
         "shapes[0].contours[0][1]: curve items (quad, cubic) need \"version\": 4"},
        {"path in version 3",
         R"({"version": 3, "width": 8, "height": 8, "shapes": [{"type": "path", "svg_path": "M0 0 Q 1 1 2 0"}]})",
         "shapes[0].type: unknown shape type \"path\" (version 3 has: polygon, disc, ring)"},
        {"quad with one point", contour(R"([[0,0], {"quad": [[1,1]]}])"),
         "shapes[0].contours[0][1].quad: expected 2 points (control, end), found [[1,1]]"},
        {"cubic with two points", contour(R"([[0,0], {"cubic": [[1,1],[2,2]]}])"),
         "shapes[0].contours[0][1].cubic: expected 3 points"},
        {"missing point", contour(R"([[0,0], {"quad": [[1,1], null]}])"),
         "shapes[0].contours[0][1].quad[1]: expected a point [x, y]"},
        {"non-finite point", contour(R"([[0,0], {"quad": [[1,1], [1e999, 0]]}])"),
         "shapes[0].contours[0][1].quad[1][0]: number 1e999 is not a finite double"},
        {"point too far", contour(R"([[0,0], {"quad": [[1,1], [2e9, 0]]}])"),
         "shapes[0].contours[0][1].quad[1]: a point of a shape with curves must lie within 1e9"},
        {"unknown segment key", contour(R"([[0,0], {"arc": [[1,1],[2,0]]}])"),
         "shapes[0].contours[0][1]: a curve item is {\"quad\": [c, p]} or {\"cubic\": [c1, c2, "
         "p]}, "
         "found the key \"arc\""},
        {"two keys", contour(R"([[0,0], {"quad": [[1,1],[2,0]], "cubic": []}])"),
         "shapes[0].contours[0][1]: a curve item is"},
        {"empty contour", contour(R"([], [[0,0], {"quad": [[1,1],[2,0]]}])"),
         "shapes[0].contours[0]: a contour needs a start point, found an empty array"},
        {"contour starting with a curve", contour(R"([{"quad": [[1,1],[2,0]]}])"),
         "shapes[0].contours[0][0]: a contour starts with a point [x, y]"},
        {"svg_path not a string", path("12"), "shapes[0].svg_path: expected a string"},
        {"no moveto", path(R"("L 1 1 2 2")"),
         "shapes[0].svg_path: character 1: path data must start with a moveto"},
        {"empty path", path(R"("  ")"), "shapes[0].svg_path: character 3: empty path data"},
        {"unknown command", path(R"("M 0 0 L 1 1 X 2 2")"),
         "shapes[0].svg_path: character 13: unknown path command 'X'"},
        {"missing number", path(R"("M 0 0 Q 1 1 2")"),
         "shapes[0].svg_path: character 14: missing number (y) at the end of the path data"},
        {"bad number", path(R"("M 0 0 L 1 , , 2")"),
         "shapes[0].svg_path: character 13: expected a number (y), found ','"},
        {"number out of range", path(R"("M 0 0 Q 1 1 1e999 0")"),
         "shapes[0].svg_path: character 13: number 1e999 is out of range"},
        {"coordinate too far", path(R"("M 0 0 q 1 1 2 0 t 9e8 0 t 9e8 0")"),
         "shapes[0].svg_path: character 27: point (1800000001, 1) lies beyond 1e+09 px"},
        {"reflected control too far", path(R"("M 0 0 Q -1e9 0 1e9 0 T 0 0")"),
         "shapes[0].svg_path: character 24: point (3000000000, 0) lies beyond 1e+09 px"},
        {"arc", path(R"("M 0 0 L 5 5 A 5 5 0 0 1 10 0 Z")"),
         "shapes[0].svg_path: character 13: arc command 'A' is not supported"},
        {"encloses nothing", path(R"("M 0 0 L 5 5")"),
         "shapes[0].svg_path: the path encloses nothing"},
        {"number after Z", path(R"("M 0 0 L 5 5 L 0 5 Z 3 3")"),
         "shapes[0].svg_path: character 21: a number with no command before it"},
        {"unknown path key",
         with_shape(R"({"type": "path", "svg_path": "M0 0 Q 1 1 2 0", "d": "x"})"),
         "shapes[0].d: unknown key"},
        {"text without a font", text(R"("string": "Ab", "size_px": 12, "origin": [1, 20])"),
         "shapes[0].font: required key is missing"},
        {"missing font file",
         text(R"("font": "no/such/font.ttf", "string": "Ab", "size_px": 12, "origin": [1, 20])"),
         "shapes[0].font: cannot open font file no/such/font.ttf"},
        {"not a font", text(R"("font": "/etc/hostname", "string": "Ab", "size_px": 12, "origin": [1, 20])"),
         "shapes[0].font: /etc/hostname: not a font file FreeType reads"},
        {"glyph the font lacks",
         text(R"("font": "sans", "string": "A\u4e00", "size_px": 12, "origin": [1, 20])"),
         "shapes[0].string: /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf has no glyph for "
         "U+4E00 (character 2)"},
        {"empty string", text(R"("font": "sans", "string": "", "size_px": 12, "origin": [1, 20])"),
         "shapes[0].string: an empty string draws nothing"},
        {"size too small", text(R"("font": "sans", "string": "A", "size_px": 0.1, "origin": [1, 20])"),
         "shapes[0].size_px: 0.1 px is outside 0.5..2048 px"},
        {"size too large", text(R"("font": "sans", "string": "A", "size_px": 4096, "origin": [1, 20])"),
         "shapes[0].size_px: 4096 px is outside 0.5..2048 px"},
        {"origin not a point", text(R"("font": "sans", "string": "A", "size_px": 12, "origin": 3)"),
         "shapes[0].origin: expected a point"},
        {"kerning not a boolean",
         text(R"("font": "sans", "string": "A", "size_px": 12, "origin": [1, 20], "kerning": 1)"),
         "shapes[0].kerning: expected true or false"},
        {"unknown text key",
         text(R"("font": "sans", "string": "A", "size_px": 12, "origin": [1, 20], "bold": true)"),
         "shapes[0].bold: unknown key"},
        {"text in version 3",
         R"({"version": 3, "width": 8, "height": 8, "shapes": [{"type": "text", "font": "sans", "string": "A", "size_px": 12, "origin": [1, 20]}]})",
         "shapes[0].type: unknown shape type \"text\" (version 3 has: polygon, disc, ring)"},
    };
}

TEST(SceneIoV4, EveryBadCurveInputIsOneLineNamingItsPath) {
    for (const ErrorCase& c : error_cases()) {
        SCOPED_TRACE(c.what);
        try {
            parse(c.text);
            ADD_FAILURE() << "accepted: " << c.text;
        } catch (const InputError& error) {
            const std::string message = error.what();
            const std::string expected = std::string(kSource) + ": " + c.expected_start;
            EXPECT_EQ(message.substr(0, expected.size()), expected) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

class CurveCli : public CliRunner {
protected:
    CurveCli() : CliRunner("curve_cli") {}
};

TEST_F(CurveCli, BadCurveInputExitsTwoAndWritesNothing) {
    const std::vector<ErrorCase> cases = error_cases();
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const ErrorCase& c = cases[k];
        SCOPED_TRACE(c.what);
        { std::ofstream(path("bad.json")) << c.text; }
        // render and reference in turn (one process each: ~0.25 s a case).
        for (const char* command :
             {k % 2 == 0 ? "render --method exact --out {}" : "reference --out {}"}) {
            const CliOutput r = run(fmt::format("{} --scene {}",
                                                fmt::format(fmt::runtime(command), path("out.exr")),
                                                path("bad.json")));
            EXPECT_EQ(r.exit_code, 2) << r.err;
            EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
            EXPECT_FALSE(std::filesystem::exists(path("out.exr")));
        }
    }
}

TEST_F(CurveCli, SvgExportWritesCurvesAsCurves) {
    { std::ofstream(path("c.json")) << with_shape(kItems); }
    const CliOutput r =
        run(fmt::format("export --scene {} --out {}", path("c.json"), path("c.svg")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(path("c.svg"));
    const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(svg.find("M4 4 L20 4 Q28 12 20 20 C14 26 8 18 4 24 Z"), std::string::npos) << svg;
}

// A text shape is its glyphs' contours: exported, it reads back without the font as the same
// segments, bit for bit, and every method draws the two files alike.
TEST_F(CurveCli, TextExportsAsItsContours) {
    { std::ofstream(path("t.json")) << with_shape(R"({"type": "text", "value": 0.8, "font": "serif", "string": "Ag", "size_px": 14.5, "origin": [2.25, 20.5], "kerning": true})"); }
    const CliOutput r =
        run(fmt::format("export --scene {} --out {}", path("t.json"), path("t-out.json")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Scene text = read_scene_file(path("t.json"));
    const Scene exported = read_scene_file(path("t-out.json"));
    ASSERT_EQ(text.shapes.size(), 1u);
    EXPECT_GE(text.shapes[0].outline.size(), 3u);  // A, and g's bowl and counter at least
    EXPECT_EQ(exported.shapes, text.shapes);
    std::ifstream in(path("t-out.json"));
    const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(json.find("\"text\""), std::string::npos);
    EXPECT_NE(json.find("\"quad\""), std::string::npos);
}

// A font path is taken relative to the scene file's folder.
TEST_F(CurveCli, AFontPathIsRelativeToTheSceneFile) {
    std::filesystem::create_directories(path("scenes/fonts"));
    std::filesystem::copy_file("/usr/share/fonts/truetype/dejavu/DejaVuSansMono.ttf",
                               path("scenes/fonts/m.ttf"),
                               std::filesystem::copy_options::overwrite_existing);
    { std::ofstream(path("scenes/t.json")) << with_shape(R"({"type": "text", "font": "fonts/m.ttf", "string": "x", "size_px": 20, "origin": [4, 24]})"); }
    { std::ofstream(path("scenes/u.json")) << with_shape(R"({"type": "text", "font": "mono", "string": "x", "size_px": 20, "origin": [4, 24]})"); }
    EXPECT_EQ(read_scene_file(path("scenes/t.json")).shapes,
              read_scene_file(path("scenes/u.json")).shapes);
}

}  // namespace
}  // namespace aabench
