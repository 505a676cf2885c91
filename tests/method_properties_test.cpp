// Properties every registered method must have, looped over the whole registry (at default
// parameters): any method added to methods/registry.cpp is tested here without a line changed.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

#include <fmt/format.h>

#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "tests/registry_ids.h"

namespace aabench {
namespace {

// Values of a 0/1 scene are weighted averages of 0 and 1; a method's float32 sums of weights
// may overshoot by a few float32 roundings (2^-24 relative each).
constexpr double kRangeSlack = 1e-6;
// A translation by whole pixels changes no coordinate's fractional bits (the test's vertices
// lie on a 2^-16 grid, so x + 3 is exact in double); what may differ is the rounding of
// intermediate double sums, which float32 output hides except at a rounding boundary: allow
// four float32 ulps at 1.0.
constexpr double kTranslationTolerance = 4.0 * FLT_EPSILON;
// A pixel-aligned square's exact coverage is 0 or 1; box-type methods must hit it to within
// float32 rounding of their sums.
constexpr double kAlignedSquareTolerance = 1e-6;

double snap(double v) { return std::round(v * 65536.0) / 65536.0; }

Scene random_binary_scene(std::uint64_t seed, int width, int height) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> x(-4.0, width + 4.0), y(-4.0, height + 4.0);
    Scene scene;
    scene.width = width;
    scene.height = height;
    const int shapes = 1 + static_cast<int>(rng() % 3);
    for (int s = 0; s < shapes; ++s) {
        Shape shape;
        shape.value = 1.0;
        Contour c;
        const int n = 3 + static_cast<int>(rng() % 6);
        for (int k = 0; k < n; ++k) c.push_back({snap(x(rng)), snap(y(rng))});
        shape.contours.push_back(c);
        scene.shapes.push_back(shape);
    }
    return scene;
}

std::vector<Scene> binary_scenes() {
    std::vector<Scene> scenes;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) scenes.push_back(random_binary_scene(seed, 24, 18));
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        scenes.push_back(make_pattern(p.id, 40, 32));
    }
    return scenes;
}

Image render_prefilled(const Method& method, const SceneInput& in) {
    // Prefilled with NaN so a pixel the method forgets to write shows up as non-finite.
    Image out(in.scene().width, in.scene().height, std::numeric_limits<float>::quiet_NaN());
    method.render(in, out);
    return out;
}

class EveryMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryMethod, FiniteAndInRangeOnBinaryScenes) {
    const MethodInstance m = make_method(GetParam());
    int index = 0;
    for (const Scene& scene : binary_scenes()) {
        if (!m.method->not_applicable(scene).empty()) {  // declared: tested below
            ++index;
            continue;
        }
        const Image out = render_prefilled(*m.method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const float v = out.at(i, j);
                // Written so that NaN fails.
                ASSERT_TRUE(v >= -kRangeSlack && v <= 1.0 + kRangeSlack)
                    << fmt::format("{} scene #{} pixel ({}, {}) = {}", m.spec, index, i, j, v);
            }
        }
        ++index;
    }
}

TEST_P(EveryMethod, EmptySceneGivesBackground) {
    const MethodInstance m = make_method(GetParam());
    Scene scene;
    scene.width = 13;
    scene.height = 7;
    scene.background = 0.375;
    const Image out = render_prefilled(*m.method, scene);
    for (float v : out.data) ASSERT_EQ(v, 0.375f) << m.spec;
}

TEST_P(EveryMethod, IntegerTranslationShiftsTheImage) {
    const MethodInstance m = make_method(GetParam());
    constexpr int kDx = 3, kDy = 2;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        // Shapes well inside so that nothing crosses the image border after the shift.
        Scene scene = random_binary_scene(seed, 20, 16);
        for (Shape& s : scene.shapes) {
            for (Contour& c : s.contours) {
                for (Point& p : c) {
                    p.x = snap(4.0 + std::fmod(std::abs(p.x), 10.0));
                    p.y = snap(4.0 + std::fmod(std::abs(p.y), 7.0));
                }
            }
        }
        Scene moved = scene;
        moved.width += kDx;
        moved.height += kDy;
        for (Shape& s : moved.shapes) {
            for (Contour& c : s.contours) {
                for (Point& p : c) p = {p.x + kDx, p.y + kDy};
            }
        }
        if (!m.method->not_applicable(scene).empty()) continue;  // circle methods: polygons
        const Image a = render_prefilled(*m.method, scene);
        const Image b = render_prefilled(*m.method, moved);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                ASSERT_NEAR(a.at(i, j), b.at(i + kDx, j + kDy), kTranslationTolerance)
                    << fmt::format("{} seed {} pixel ({}, {})", m.spec, seed, i, j);
            }
        }
    }
}

TEST_P(EveryMethod, PixelAlignedSquareIsExactForBoxMethods) {
    const MethodInstance m = make_method(GetParam());
    if (m.method->filter().text() != "box") GTEST_SKIP() << m.spec << " is not box-filtered";
    // The one box method that is not: Kato & Kameyama's formula taken as the paper gives it
    // (fast-edge's default) fattens every edge by half a pixel, which tests/fast_edge_test.cpp
    // asserts; its variant fast-edge:inset=0.5 runs this test.
    if (m.spec == make_method("fast-edge").spec) {
        GTEST_SKIP() << m.spec << ": half a pixel too fat by design";
    }
    if (m.method->traits().post_process) {
        // A pass sees only its base's samples: the square's corners are staircase ends to it, and
        // MLAA's L shapes, FXAA's sub-pixel blend and SMAA's corner rounding reshape them by
        // design. tests/post_process_test.cpp holds the passes to their own properties.
        GTEST_SKIP() << m.spec << ": a post-process pass reshapes corners by design";
    }
    Scene scene;
    scene.width = 12;
    scene.height = 10;
    scene.shapes.push_back({{{{3, 2}, {9, 2}, {9, 7}, {3, 7}}}, 1.0});
    if (!m.method->not_applicable(scene).empty()) GTEST_SKIP() << m.spec << " draws circles only";
    const Image out = render_prefilled(*m.method, scene);
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const double want = (i >= 3 && i < 9 && j >= 2 && j < 7) ? 1.0 : 0.0;
            ASSERT_NEAR(out.at(i, j), want, kAlignedSquareTolerance)
                << fmt::format("{} pixel ({}, {})", m.spec, i, j);
        }
    }
}

// 3-D scenes: each method draws what the prepared frame hands it (harness/world/frame.h,
// input_for): the ScreenScene for a method with its own visibility (scanline NEXT stack,
// z-buffer), the exact visible pieces for the others. Every 3-D pattern, small.
struct World3D {
    std::string id;
    Scene given;
    PreparedFrame world;
};

std::vector<World3D> worlds_3d(int width, int height) {
    std::vector<World3D> out;
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        Scene given = make_pattern(p.id, width, height);
        if (!given.world) continue;
        PreparedFrame world = PreparedFrame::prepare(given);
        out.push_back({p.id, std::move(given), std::move(world)});
    }
    return out;
}

// Shaded values reach ~1.5 (ambient + lights): the slack is relative to the range's size,
// float32 rounding of weighted sums (a few 2^-24 relative).
constexpr double kRangeSlackRelative = 1e-6;

TEST_P(EveryMethod, FiniteAndInRangeOn3DScenes) {
    const MethodInstance m = make_method(GetParam());
    for (const World3D& w : worlds_3d(40, 32)) {
        const SceneInput input = w.world.input_for(*m.method);
        const Scene& drawn = input.scene();
        if (!m.method->not_applicable(drawn).empty()) continue;  // circle methods: polygons n/a
        const auto [lo, hi] = w.world.pieces().scene().value_range();
        const double slack = kRangeSlackRelative * std::max(1.0, hi - lo);
        const Image out = render_prefilled(*m.method, input);
        for (int j = 0; j < drawn.height; ++j) {
            for (int i = 0; i < drawn.width; ++i) {
                const float v = out.at(i, j);
                ASSERT_TRUE(v >= lo - slack && v <= hi + slack)
                    << fmt::format("{} on {} pixel ({}, {}) = {} outside [{}, {}]", m.spec, w.id,
                                   i, j, v, lo, hi);
            }
        }
    }
}

TEST_P(EveryMethod, EmptyWorldGivesBackground) {
    const MethodInstance m = make_method(GetParam());
    Scene given = make_pattern("blocks", 13, 7);
    ASSERT_TRUE(given.world.has_value());
    given.world->objects.clear();
    given.background = 0.375;
    const PreparedFrame world = PreparedFrame::prepare(given);
    const Image out = render_prefilled(*m.method, world.input_for(*m.method));
    for (float v : out.data) ASSERT_EQ(v, 0.375f) << m.spec;
}

// Translation by whole pixels through the window origin (Scene::origin_x/y): the drawn scene
// with its vertices on a 2^-16 grid (so that x + 3 is exact), rendered once as is and once in
// a window 3 x 2 px larger whose origin lies at (-3, -2): every pixel (i, j) of the first is
// pixel (i + 3, j + 2) of the second. The depth and value planes are re-based by
// in_window_frame (c + gx ox + gy oy, one rounding), which may move a depth tie or an affine
// value by an ulp: the same four float32 ulps as in 2-D. The 8-bit peers (cairo, agg,
// exact-8bit) round each piece's coverage to 1/255; on the 2^-16 grid a coverage often lies
// exactly on a rounding boundary (a half-covered pixel), and the last bit the re-basing or
// their own fixed point changes can flip it by one step: allowed, one step of the value range,
// on at most 5% of the pixels (measured: agg 20 of 480 pixels on blocks, 4.2%), and counted.
// Pixels on the border of the unshifted window are not compared: there the first render's
// window edge cuts the scene and the second's does not (cairo treats pixels at its surface's
// edge differently; measured 0.0094 at pixel (0, 10) of room).
constexpr double kEightBitFlipShare = 0.05;
// A pixel holding several pieces (the checkerboard near its horizon: many squares per pixel)
// is rounded piece by piece, so two of its pieces can flip: up to two steps (measured: agg on
// checkerboard at 24x20, 1.05 steps at pixel (2, 16)).
constexpr double kEightBitFlipSteps = 2.0;

TEST_P(EveryMethod, WindowOriginTranslatesOn3DScenes) {
    const MethodInstance m = make_method(GetParam());
    if (m.id == "cairo") {
        // Not translation-exact here, measured and left as the peer's property: near the left
        // window edge of room (24x20) its pixels move by up to 0.0094 (3 8-bit steps of the
        // value range) when the window moves, where the floor piece reaching far outside the
        // surface is clipped by cairo (the clipped vertices are rounded to its fixed point).
        GTEST_SKIP() << "cairo: window-dependent clipping, up to 0.0094 on room (documented)";
    }
    if (m.method->traits().post_process) {
        // A pass reads neighbours as far as its search reaches (FXAA's end-of-edge steps, MLAA's
        // and SMAA's runs): in the moved window those include pixels the original window clips
        // away, so pixels within that reach of the border differ by design. The passes' own
        // band-invariance and determinism are in tests/post_process_test.cpp.
        GTEST_SKIP() << m.spec << ": a pass's output near the border depends on the window";
    }
    constexpr int kDx = 3, kDy = 2;
    for (const World3D& w : worlds_3d(24, 20)) {
        Scene scene = w.world.input_for(*m.method).scene();
        if (!m.method->not_applicable(scene).empty()) continue;  // circle methods: polygons n/a
        for (Shape& s : scene.shapes) {
            for (Contour& c : s.contours) {
                for (Point& p : c) p = {snap(p.x), snap(p.y)};
            }
        }
        Scene moved = scene;
        moved.width += kDx;
        moved.height += kDy;
        moved.origin_x = -kDx;
        moved.origin_y = -kDy;
        const auto [lo, hi] = w.world.pieces().scene().value_range();
        const double step = (hi - lo) / 255.0;
        const Image a = render_prefilled(*m.method, scene);
        const Image b = render_prefilled(*m.method, window_scene(moved));
        int flips = 0;
        for (int j = 1; j + 1 < scene.height; ++j) {
            for (int i = 1; i + 1 < scene.width; ++i) {
                const double va = a.at(i, j), vb = b.at(i + kDx, j + kDy);
                const double d = std::abs(va - vb);
                if (d <= kTranslationTolerance * std::max(1.0, std::abs(va))) continue;
                ++flips;
                ASSERT_LE(d, kEightBitFlipSteps * step +
                                 kTranslationTolerance * std::max(1.0, std::abs(va)))
                    << fmt::format("{} on {} pixel ({}, {}): {} vs {}", m.spec, w.id, i, j, va, vb);
            }
        }
        EXPECT_LE(flips, kEightBitFlipShare * scene.width * scene.height) << m.spec << " on " << w.id;
        if (flips > 0) {
            std::printf("%s on %s: %d pixels moved by one 8-bit step\n", m.spec.c_str(),
                        w.id.c_str(), flips);
        }
    }
}

TEST_P(EveryMethod, NotApplicableRendersNaNAndCirclesAreDrawnByEveryMethod) {
    // A method either draws a scene or says why not, and then writes no number (NaN) rather
    // than a silent fallback. Every method draws the grid circles of the circle patterns.
    const MethodInstance m = make_method(GetParam());
    for (const Scene& scene : binary_scenes()) {
        if (m.method->not_applicable(scene).empty()) continue;
        const Image out = render_prefilled(*m.method, scene);
        for (float v : out.data) ASSERT_TRUE(std::isnan(v)) << m.spec;
    }
    for (const char* pattern : {"circles", "circle-radii"}) {
        EXPECT_EQ(m.method->not_applicable(make_pattern(pattern, 40, 32)), "") << m.spec << " " << pattern;
    }
}

// Every row at its defaults and the other readings the default comparison runs.
INSTANTIATE_TEST_SUITE_P(Registry, EveryMethod,
                         ::testing::ValuesIn(testing::registry_method_ids(
                             /*with_default_run_variants=*/true)),
                         testing::SpecTestName());

TEST(Registry, UnknownMethodListsValidIds) {
    try {
        make_method("no-such-method");
        FAIL() << "no error";
    } catch (const InputError& e) {
        for (const MethodInfo& info : method_registry()) {
            EXPECT_NE(std::string(e.what()).find(info.id), std::string::npos) << e.what();
        }
    }
}

TEST(Registry, UnknownParameterIsAnError) {
    EXPECT_THROW(make_method("none:k=3"), InputError);
}

TEST(Registry, ExactMatchesBoxReference) {
    // exact is its own fast engine (methods/scan/exact/fast_coverage.cpp), held to its bound of
    // 1e-6 from the double reference (docs/architecture.md; tests/fast_coverage_test.cpp has the
    // random and hard-case differential tests); values here are 0/1, where float32 rounding is
    // 3e-8.
    constexpr double kFastExactTolerance = 1e-6;
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(p.id, 64, 48);
        const Coverage ref = box_reference(scene);
        const Image img = render_scene(*make_method("exact").method, scene);
        for (std::size_t k = 0; k < ref.data.size(); ++k) {
            ASSERT_NEAR(img.data[k], ref.data[k], kFastExactTolerance) << p.id << " pixel " << k;
        }
    }
}

}  // namespace
}  // namespace aabench
