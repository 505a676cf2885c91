// The overlay (harness/world/overlay.h): patterns and shadows laid over their faces as the
// scanline methods take them (Nishita & Nakamae 1984, §3.2), decided by the tie order. It must
// show what the cells show: the scanline methods draw the same image from either input, and
// with the tie order swapped (the face in front of its patterns and shadows) they must not.
#include "harness/world/overlay.h"
#include "tests/world_shadows.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "harness/world/frame.h"
#include "harness/world/stages.h"
#include "methods/method.h"
#include "methods/scan/multiscan/scanline_visibility.h"
#include "patterns/pattern.h"
#include "patterns/world_builders.h"

namespace aabench {
namespace {

// The methods round each pixel once to float32 (<= 1.2e-7 for the shaded values, up to ~1.5);
// the two inputs place a pattern's or a shadow's boundary by different clippings, ~1e-15 px
// apart. 1e-6 is the methods' own bound (docs/architecture.md).
constexpr double kTolerance = 1e-6;
// With the face in front, every pattern and shadow is lost: on each of these scenes the mass of
// the image moves by far more than this (the room's mat borders, windows and shadows; the
// blocks' shadows; the checkerboard's dark squares), so a swapped order cannot pass as equal.
constexpr double kSwappedMinDifference = 1.0;  // summed |difference| over the lines, in px

// A shaded value is a product of two doubles (reflectance x illuminance): ~1e-16 of rounding;
// a value this far below another is below it for certain.
constexpr double kValueRounding = 1e-12;

const char* const kLayeredPatterns[] = {"room", "blocks", "checkerboard"};
constexpr int kWidth = 64, kHeight = 48;

double worst_difference(const Image& a, const Image& b) {
    double worst = 0.0;
    for (std::size_t k = 0; k < a.data.size(); ++k) {
        worst = std::max(worst, std::abs(double(a.data[k]) - b.data[k]));
    }
    return worst;
}

// The integral of the visible value along the line y over [0, width] (constant values; the
// profile's runs are closed at `width`).
double line_mass(const LineProfile& p, double width) {
    double sum = 0.0, x = 0.0, v = p.start;
    for (const ValueChange& c : p.changes) {
        const double to = std::clamp(c.x, 0.0, width);
        sum += v * (to - x);
        x = to;
        v = c.value;
    }
    return sum + v * (width - x);
}

// Per pixel row, the line mass at the row's centre line, by ScanlineVisibility with `front`.
std::vector<double> centre_line_masses(const Scene& scene, const RoleFront& front) {
    ScanlineVisibility vis;
    vis.set_role_front(front);
    vis.reset(scene);
    LineProfile below, above;
    std::vector<double> out;
    for (int j = 0; j < scene.height; ++j) {
        vis.trace(j + 0.5, below, above);
        out.push_back(line_mass(below, scene.width));
    }
    return out;
}

TEST(Overlay, TheScanlineMethodsDrawTheOverlayAndTheOthersTheCells) {
    const PreparedFrame frame = PreparedFrame::prepare(make_pattern("room", kWidth, kHeight));
    for (const char* id : {"box-multiscan", "gauss-multiscan"}) {
        const MethodInstance m = make_method(id);
        EXPECT_TRUE(m.method->traits().coplanar_overlays) << id;
        EXPECT_EQ(&frame.input_for(*m.method).scene(), &frame.overlay()) << id;
    }
    for (const char* id : {"none", "ssaa", "nishita-d", "fast-edge"}) {
        EXPECT_EQ(&frame.input_for(*make_method(id).method).scene(), &frame.screen()) << id;
    }
    EXPECT_EQ(&frame.input_for(*make_method("exact").method).scene(), &frame.pieces().scene());
    // A world without patterns or shadows: the overlay would be the cells; none is built.
    const PreparedFrame plain = PreparedFrame::prepare(make_pattern("mesh", kWidth, kHeight));
    const MethodInstance box = make_method("box-multiscan");
    EXPECT_EQ(&plain.input_for(*box.method).scene(), &plain.screen());
    EXPECT_FALSE(plain.layer_costs().overlay_built);
}

// One face shape per visible face, whole; the patterns uncut; fewer shapes than the cells.
TEST(Overlay, FacesStayWholeAndPatternsUncut) {
    for (const char* id : kLayeredPatterns) {
        const Scene scene = make_pattern(id, kWidth, kHeight);
        const PreparedFrame frame = PreparedFrame::prepare(scene);
        const Scene& overlay = frame.overlay();
        std::vector<int> face_shapes(scene.world->face_count(), 0);
        int patterns = 0;
        for (const Shape& s : overlay.shapes) {
            ASSERT_TRUE(s.inv_depth.has_value()) << id;
            face_shapes[s.face] += s.role == ShapeRole::kFace;
            patterns += s.role == ShapeRole::kPattern;
        }
        for (int n : face_shapes) EXPECT_LE(n, 1) << id;
        int world_patterns = 0;
        for (const Object& o : scene.world->objects) {
            for (const Face& f : o.faces) world_patterns += static_cast<int>(f.patterns.size());
        }
        EXPECT_LE(patterns, world_patterns) << id;  // patterns on culled faces are left out
        const PreparedFrame::LayerCosts c = frame.layer_costs();
        ASSERT_TRUE(c.overlay_built) << id;
        EXPECT_EQ(c.overlay_shapes, overlay.shapes.size()) << id;
        EXPECT_LT(c.overlay_shapes, c.cell_shapes) << id;
        std::printf(
            "%-13s cells %zu shapes (cut in %.3f ms), overlay %zu shapes (layered in "
            "%.3f ms)\n",
            id, c.cell_shapes, c.cell_cutting_ms, c.overlay_shapes, c.overlay_layering_ms);
    }
}

// The paper's tie order makes the overlay show what the cells show: the scanline methods draw
// the same image from either input (and so match the reference as before).
TEST(Overlay, ScanlineMethodsDrawTheSameImageFromTheOverlayAsFromTheCells) {
    for (const char* id : kLayeredPatterns) {
        const PreparedFrame frame = PreparedFrame::prepare(make_pattern(id, kWidth, kHeight));
        for (const char* spec : {"box-multiscan", "box-multiscan:n=7", "gauss-multiscan"}) {
            const MethodInstance m = make_method(spec);
            const Image from_overlay = render_scene(*m.method, frame.overlay());
            const Image from_cells = render_scene(*m.method, frame.screen());
            EXPECT_LE(worst_difference(from_overlay, from_cells), kTolerance) << id << " " << spec;
        }
    }
}

// Swapping the tie order (the face in front, then the pattern, the shadow last) loses every
// pattern and shadow under its face: the lines differ from the cells'. The paper's order
// agrees with them line by line.
TEST(Overlay, TheTieOrderDecidesWhatTheOverlayShows) {
    const RoleFront swapped = {2, 1, 0};
    for (const char* id : kLayeredPatterns) {
        const PreparedFrame frame = PreparedFrame::prepare(make_pattern(id, kWidth, kHeight));
        const std::vector<double> cells = centre_line_masses(frame.screen(), kPaperRoleFront);
        const std::vector<double> paper = centre_line_masses(frame.overlay(), kPaperRoleFront);
        const std::vector<double> wrong = centre_line_masses(frame.overlay(), swapped);
        double paper_off = 0.0, wrong_off = 0.0;
        for (std::size_t j = 0; j < cells.size(); ++j) {
            paper_off = std::max(paper_off, std::abs(paper[j] - cells[j]));
            wrong_off += std::abs(wrong[j] - cells[j]);
        }
        EXPECT_LE(paper_off, kTolerance) << id;
        EXPECT_GT(wrong_off, kSwappedMinDifference) << id;
    }
}

// A floor of reflectance 0.7 with a dark (0.15) and a bright (0.95) rectangle pattern, its
// corners (s0, s1, t0, t1) on the floor, under a parallel sun and a point lamp that both cast
// shadows, ambient 0.2, seen from `eye`; the objects that cast come after the floor.
World patterned_floor_under_two_lights(const glm::dvec3& eye, const glm::dvec3& target,
                                       const std::array<double, 4>& dark,
                                       const std::array<double, 4>& bright) {
    World w;
    w.camera.eye = eye;
    w.camera.target = target;
    w.ambient = 0.2;
    Object floor = make_quad("floor", {-3, 0, 3}, {3, 0, 3}, {3, 0, -3}, {-3, 0, -3}, 0.7);
    const glm::dvec3 corner(-3, 0, 3), ux(1, 0, 0), vz(0, 0, -1);
    for (const auto& [r, reflectance] : {std::pair{dark, 0.15}, std::pair{bright, 0.95}}) {
        floor.faces[0].patterns.push_back(
            rect_pattern(corner, ux, vz, r[0], r[1], r[2], r[3], reflectance));
    }
    w.objects = {floor};
    Light sun;
    sun.direction = {-0.5, -2.0, -0.4};
    sun.intensity = 0.6;
    sun.shadows = true;
    Light lamp;
    lamp.type = LightType::kPoint;
    lamp.position = {1.2, 3.0, 0.9};
    lamp.intensity = 6.0;
    lamp.shadows = true;
    w.lights = {sun, lamp};
    return w;
}

Scene scene_of(const World& w) {
    Scene scene;
    scene.width = kWidth;
    scene.height = kHeight;
    scene.world = w;
    return scene;
}

// The overlay of such a floor shows what its cells show: some shadow cell lies over the dark
// pattern (darker than the floor's shadow with both lights out, 0.7 x 0.2 = 0.14, it can only
// carry the dark pattern's reflectance, as long as no other object receives a shadow darker:
// a lone convex box shadows nothing of itself, and boxes that shadow each other are given
// reflectance 0.9, so 0.18 at least), and each scanline method draws the same image from
// the overlay as from the cells. Returns the overlay's shadow cells.
int expect_the_overlay_shows_the_cells(const PreparedFrame& frame,
                                       std::initializer_list<const char*> specs) {
    int shadow_cells = 0, under_pattern = 0;
    for (const Shape& s : frame.overlay().shapes) {
        shadow_cells += s.role == ShapeRole::kShadow;
        under_pattern += s.role == ShapeRole::kShadow && s.value < 0.7 * 0.2 - kValueRounding;
    }
    EXPECT_GT(under_pattern, 0) << "no shadow falls on the dark pattern";
    for (const char* spec : specs) {
        const MethodInstance m = make_method(spec);
        EXPECT_LE(worst_difference(render_scene(*m.method, frame.overlay()),
                                   render_scene(*m.method, frame.screen())),
                  kTolerance)
            << spec;
    }
    return shadow_cells;
}

// A pattern in shadow keeps its reflectance and loses the light: two lights' shadows crossing a
// pattern and each other (a box over a patterned floor) come out as the cells have them.
TEST(Overlay, ShadowsOverPatternsKeepThePatternsReflectance) {
    World w = patterned_floor_under_two_lights({0.4, 3.1, 4.2}, {0.05, 0.0, 0.1},
                                               {2.2, 3.9, 1.1, 4.7}, {1.3, 4.4, 2.6, 3.3});
    w.objects.push_back(make_box("box", {-0.4, 0.3, -0.5}, {0.5, 1.1, 0.4}, 0.3, 0.6));
    const PreparedFrame frame = PreparedFrame::prepare(scene_of(w));
    EXPECT_GT(expect_the_overlay_shows_the_cells(frame, {"box-multiscan", "gauss-multiscan"}), 2);
}

// A face under more than kCutLayerShadows shadows takes its layer from the cut face: a
// patterned floor under a grid of small boxes and two shadowing lights (hundreds of shadows on
// the floor, overlapping each other and the patterns) still shows what the cells show, line by
// line and in every scanline method's image.
TEST(Overlay, AFaceUnderManyShadowsShowsWhatTheCellsShow) {
    World w = patterned_floor_under_two_lights({0.3, 5.5, 6.0}, {0.0, 0.0, 0.0},
                                               {0.5, 3.9, 1.1, 4.7}, {2.3, 5.4, 2.6, 5.3});
    for (int j = 0; j < 7; ++j) {
        for (int i = 0; i < 7; ++i) {
            const glm::dvec3 lo(-2.6 + 0.75 * i, 0.1 + 0.05 * ((i + j) % 3), -2.6 + 0.75 * j);
            w.objects.push_back(
                make_box("box", lo, lo + glm::dvec3(0.3, 0.45, 0.25), 0.3 * i + 0.2 * j, 0.9));
        }
    }
    // The floor really is past the threshold.
    ASSERT_GT(testing::shadows_on_first_face(w, kWidth, kHeight, 0), kCutLayerShadows);

    const PreparedFrame frame = PreparedFrame::prepare(scene_of(w));
    const std::vector<double> cells = centre_line_masses(frame.screen(), kPaperRoleFront);
    const std::vector<double> laid = centre_line_masses(frame.overlay(), kPaperRoleFront);
    for (std::size_t j = 0; j < cells.size(); ++j) EXPECT_NEAR(laid[j], cells[j], kTolerance) << j;
    expect_the_overlay_shows_the_cells(frame,
                                       {"box-multiscan", "box-multiscan:n=7", "gauss-multiscan"});
}

// The overlay is built once per frame, on first use, whatever asks for it.
TEST(Overlay, BuiltOncePerFrameAndOnlyWhenAsked) {
    const Scene scene = make_pattern("room", kWidth, kHeight);
    reset_stage_work_counts();
    const PreparedFrame frame = PreparedFrame::prepare(scene);
    EXPECT_EQ(stage_work_counts().build_overlay, 0);
    const MethodInstance box = make_method("box-multiscan");
    (void)frame.input_for(*box.method);
    (void)frame.overlay();
    (void)frame.relied_stage_ms(*box.method);
    EXPECT_EQ(stage_work_counts().build_overlay, 1);
    EXPECT_EQ(stage_work_counts().cast_shadows, 1);
    // Charged its own build and the shadows' casting, not the cells' cutting.
    const PreparedFrame::LayerCosts c = frame.layer_costs();
    EXPECT_GT(c.overlay.time_ms, 0.0);
    EXPECT_GE(frame.relied_stage_ms(*box.method), c.overlay.time_ms);
}

}  // namespace
}  // namespace aabench
