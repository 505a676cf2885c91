// SMAA 1x (methods/smaa/smaa_area_p.h, methods/smaa/smaa_pass_p.h, methods/smaa/smaa.cpp): the area
// table against its definition (the reconstructed L, Z and U shapes as polygons, clipped to the
// pixel and integrated by the shoelace formula, independently of the table's closed form),
// its symmetries and sums; the pass leaves constant and smooth images alone, is deterministic,
// gives the same rows in bands, allocates nothing warm, and moves a near-horizontal edge
// toward its exact coverage.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "harness/reference/box_reference.h"
#include "harness/world/alloc_count.h"
#include "methods/method.h"
#include "methods/post_process.h"
#include "methods/smaa/smaa_area_p.h"
#include "methods/smaa/smaa_pass_p.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

// Float32 table entries against double integrals of areas <= 1/2: a few float ulps.
constexpr double kAreaTolerance = 1e-6;

struct P {
    double x, y;
};
using Polygon = std::vector<P>;

// Sutherland–Hodgman against one axis-aligned half-plane: keep points with sign * (coord - c)
// >= 0 on axis 0 (x) or 1 (y).
Polygon clip(const Polygon& in, int axis, double c, double sign) {
    Polygon out;
    auto inside = [&](const P& p) { return sign * ((axis == 0 ? p.x : p.y) - c) >= 0.0; };
    for (std::size_t i = 0; i < in.size(); ++i) {
        const P& a = in[i];
        const P& b = in[(i + 1) % in.size()];
        if (inside(a)) out.push_back(a);
        if (inside(a) != inside(b)) {
            const double ca = axis == 0 ? a.x : a.y, cb = axis == 0 ? b.x : b.y;
            const double t = (c - ca) / (cb - ca);
            out.push_back({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
        }
    }
    return out;
}

double area_in_box(const Polygon& polygon, double x0, double x1, double y0, double y1) {
    Polygon p = clip(polygon, 0, x0, 1.0);
    p = clip(p, 0, x1, -1.0);
    p = clip(p, 1, y0, 1.0);
    p = clip(p, 1, y1, -1.0);
    double twice = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const P& a = p[i];
        const P& b = p[(i + 1) % p.size()];
        twice += a.x * b.y - b.x * a.y;
    }
    return std::abs(0.5 * twice);
}

// The region between the edge line (y = 0) and the reconstructed line, as triangles, for single
// crossings or none (smaa_area_p.h's definition: Z end to end, U and L to the middle).
std::vector<Polygon> shape_regions(SmaaCrossing first, SmaaCrossing second, double d) {
    auto h = [](SmaaCrossing c) { return c == SmaaCrossing::kOwn ? 0.5 : -0.5; };
    const bool f = first != SmaaCrossing::kNone, s = second != SmaaCrossing::kNone;
    std::vector<Polygon> regions;
    if (f && s && first != second) {  // Z: the line crosses y = 0 at d / 2
        regions.push_back({{0, 0}, {0, h(first)}, {d / 2, 0}});
        regions.push_back({{d / 2, 0}, {d, h(second)}, {d, 0}});
        return regions;
    }
    if (f) regions.push_back({{0, 0}, {0, h(first)}, {d / 2, 0}});
    if (s) regions.push_back({{d / 2, 0}, {d, h(second)}, {d, 0}});
    return regions;
}

SmaaArea polygon_area(SmaaCrossing first, SmaaCrossing second, int d1, int d2) {
    const double d = d1 + d2 + 1.0;
    SmaaArea a;
    for (const Polygon& region : shape_regions(first, second, d)) {
        a.own += static_cast<float>(area_in_box(region, d1, d1 + 1.0, 0.0, 1.0));
        a.other += static_cast<float>(area_in_box(region, d1, d1 + 1.0, -1.0, 0.0));
    }
    return a;
}

const SmaaCrossing kSingles[] = {SmaaCrossing::kNone, SmaaCrossing::kOwn, SmaaCrossing::kOther};
const SmaaCrossing kAll[] = {SmaaCrossing::kNone, SmaaCrossing::kOwn, SmaaCrossing::kOther,
                             SmaaCrossing::kBoth};
constexpr int kMaxDistance = 12;

TEST(SmaaArea, TableEqualsPolygonIntegrationOfLZUShapes) {
    const SmaaAreaTable table(kMaxDistance);
    int checked = 0;
    for (SmaaCrossing a : kSingles) {
        for (SmaaCrossing b : kSingles) {
            for (int d1 = 0; d1 <= kMaxDistance; ++d1) {
                for (int d2 = 0; d2 <= kMaxDistance; ++d2) {
                    const SmaaArea got = table.at(a, b, d1, d2);
                    const SmaaArea want = polygon_area(a, b, d1, d2);
                    ASSERT_NEAR(got.own, want.own, kAreaTolerance)
                        << int(a) << "," << int(b) << " d=" << d1 << "," << d2;
                    ASSERT_NEAR(got.other, want.other, kAreaTolerance)
                        << int(a) << "," << int(b) << " d=" << d1 << "," << d2;
                    ++checked;
                }
            }
        }
    }
    EXPECT_EQ(checked, 9 * 13 * 13);
    // A few by hand: an L of one pixel (the line from (0, 1/2) to (1/2, 0)) is a triangle of
    // area 1/8; a Z of one pixel has 1/8 on each side; the first pixel of a U of 4 pixels is the
    // trapezoid under the line from (0, 1/2) to (2, 0) over [0, 1]: (1/2 + 1/4) / 2 = 3/8.
    EXPECT_NEAR(table.at(SmaaCrossing::kOwn, SmaaCrossing::kNone, 0, 0).own, 0.125, kAreaTolerance);
    EXPECT_NEAR(table.at(SmaaCrossing::kOwn, SmaaCrossing::kOther, 0, 0).own, 0.125,
                kAreaTolerance);
    EXPECT_NEAR(table.at(SmaaCrossing::kOwn, SmaaCrossing::kOther, 0, 0).other, 0.125,
                kAreaTolerance);
    EXPECT_NEAR(table.at(SmaaCrossing::kOwn, SmaaCrossing::kOwn, 0, 3).own, 0.375, kAreaTolerance);
    EXPECT_EQ(table.at(SmaaCrossing::kNone, SmaaCrossing::kNone, 2, 5).own, 0.0f);
}

TEST(SmaaArea, MirrorAndSideSymmetries) {
    const SmaaAreaTable table(kMaxDistance);
    auto swap_side = [](SmaaCrossing c) {
        if (c == SmaaCrossing::kOwn) return SmaaCrossing::kOther;
        if (c == SmaaCrossing::kOther) return SmaaCrossing::kOwn;
        return c;
    };
    for (SmaaCrossing a : kAll) {
        for (SmaaCrossing b : kAll) {
            for (int d1 = 0; d1 <= kMaxDistance; ++d1) {
                for (int d2 = 0; d2 <= kMaxDistance; ++d2) {
                    const SmaaArea x = table.at(a, b, d1, d2);
                    const SmaaArea mirrored = table.at(b, a, d2, d1);
                    ASSERT_NEAR(x.own, mirrored.own, kAreaTolerance);
                    ASSERT_NEAR(x.other, mirrored.other, kAreaTolerance);
                    const SmaaArea flipped = table.at(swap_side(a), swap_side(b), d1, d2);
                    ASSERT_NEAR(x.own, flipped.other, kAreaTolerance);
                    ASSERT_NEAR(x.other, flipped.own, kAreaTolerance);
                    ASSERT_GE(x.own, 0.0f);
                    ASSERT_LE(x.own + x.other, 0.5f + kAreaTolerance);
                }
            }
        }
    }
}

TEST(SmaaArea, SumsOverASegmentAreTheShapesAreas) {
    const SmaaAreaTable table(kMaxDistance);
    using C = SmaaCrossing;
    for (int d = 1; d <= kMaxDistance + 1; ++d) {
        double l = 0, z_own = 0, z_other = 0, u = 0, both = 0;
        for (int d1 = 0; d1 < d; ++d1) {
            const int d2 = d - 1 - d1;
            l += table.at(C::kOwn, C::kNone, d1, d2).own;
            z_own += table.at(C::kOwn, C::kOther, d1, d2).own;
            z_other += table.at(C::kOwn, C::kOther, d1, d2).other;
            u += table.at(C::kOwn, C::kOwn, d1, d2).own;
            const SmaaArea t = table.at(C::kBoth, C::kOwn, d1, d2);
            both += t.own + t.other;
        }
        // A triangle of legs 1/2 and d/2 per line.
        const double triangle = d / 8.0;
        EXPECT_NEAR(l, triangle, 1e-5) << d;
        EXPECT_NEAR(z_own, triangle, 1e-5) << d;
        EXPECT_NEAR(z_other, triangle, 1e-5) << d;
        EXPECT_NEAR(u, 2 * triangle, 1e-5) << d;
        // "Both" is the mean of a U and a Z: two triangles either way.
        EXPECT_NEAR(both, 2 * triangle, 1e-5) << d;
    }
}

TEST(SmaaArea, DiagonalCornerIsTheMidlinesTriangle) {
    // The staircase's midline x + y = 1/2 in the pixel [0, 1]^2: the corner beyond it.
    const Polygon half_plane = {{-2, -2}, {2.5, -2}, {-2, 2.5}};
    EXPECT_NEAR(kSmaaDiagonalCornerArea, area_in_box(half_plane, 0, 1, 0, 1), kAreaTolerance);
}

// --- The pass ---

const char* const kPresets[] = {"low", "medium", "high", "ultra"};

Image srgb_luma(const Image& values) {
    Image luma(values.width, values.height);
    for (std::size_t i = 0; i < values.data.size(); ++i) luma.data[i] = srgb_encode(values.data[i]);
    return luma;
}

Image run_pass(const Image& values, const SmaaSettings& settings) {
    const SmaaAreaTable areas(settings.max_distance());
    SmaaScratch scratch;
    Image out(values.width, values.height);
    smaa_pass_rows(values, srgb_luma(values), settings, areas, scratch, out, 0, values.height);
    return out;
}

TEST(SmaaPass, ConstantImageIsUnchanged) {
    for (const char* preset : kPresets) {
        Scene scene;
        scene.width = 40;
        scene.height = 30;
        scene.background = 0.37;
        const MethodInstance m = make_method(std::string("smaa:preset=") + preset);
        const Image out = render_scene(*m.method, scene);
        for (float v : out.data) ASSERT_EQ(v, 0.37f) << preset;
    }
}

// Smooth random images: bilinear interpolation of random values on a coarse grid, so the luma
// never steps by the threshold between neighbours. No edge is found: every pixel is its input.
TEST(SmaaPass, SmoothLowContrastImagesAreUnchanged) {
    // Coarse cells of 8 px and values within a range of 0.25 from 0.2 up: neighbours differ by
    // at most 0.25 / 8 in linear value, at most 1.2 times that in sRGB luma above 0.2 (the
    // encoding's slope there): below ultra's 0.05 threshold, which the test asserts.
    constexpr int kCell = 8, kSide = 64;
    constexpr double kLow = 0.2, kRange = 0.25;
    int checked = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> value(kLow, kLow + kRange);
        const int coarse = kSide / kCell + 1;
        std::vector<double> grid(coarse * coarse);
        for (double& g : grid) g = value(rng);
        Image image(kSide, kSide);
        for (int y = 0; y < kSide; ++y) {
            for (int x = 0; x < kSide; ++x) {
                const int gx = x / kCell, gy = y / kCell;
                const double tx = (x % kCell) / double(kCell), ty = (y % kCell) / double(kCell);
                auto g = [&](int i, int j) { return grid[j * coarse + i]; };
                image.at(x, y) =
                    static_cast<float>((1 - ty) * ((1 - tx) * g(gx, gy) + tx * g(gx + 1, gy)) +
                                       ty * ((1 - tx) * g(gx, gy + 1) + tx * g(gx + 1, gy + 1)));
            }
        }
        const Image luma = srgb_luma(image);
        float max_delta = 0.0f;
        for (int y = 0; y < kSide; ++y) {
            for (int x = 0; x < kSide; ++x) {
                if (x > 0)
                    max_delta = std::max(max_delta, std::abs(luma.at(x, y) - luma.at(x - 1, y)));
                if (y > 0)
                    max_delta = std::max(max_delta, std::abs(luma.at(x, y) - luma.at(x, y - 1)));
            }
        }
        for (const char* preset : kPresets) {
            const SmaaSettings settings = smaa_preset(preset);
            ASSERT_LT(max_delta, settings.threshold) << "seed " << seed;
            const Image out = run_pass(image, settings);
            ASSERT_EQ(out.data, image.data) << preset << ", seed " << seed;
            ++checked;
        }
    }
    EXPECT_EQ(checked, 80);
}

TEST(SmaaPass, DeterministicAndTheSameInBands) {
    const Scene scene = make_pattern("star", 96, 96);
    for (const char* preset : kPresets) {
        const MethodInstance m = make_method(std::string("smaa:preset=") + preset);
        const Image first = render_scene(*m.method, scene);
        const Image second = render_scene(*m.method, scene);
        ASSERT_EQ(first.data, second.data) << preset;
        Image banded(scene.width, scene.height, -1.0f);
        render_in_bands(*m.method, scene, banded, 3);
        ASSERT_EQ(first.data, banded.data) << preset;
        // It did something: the star's edges are blended.
        const Image base = render_scene(*make_method("none").method, scene);
        EXPECT_NE(first.data, base.data) << preset;
    }
}

TEST(SmaaPass, WarmPassAllocatesNothing) {
    const Scene scene = make_pattern("star", 128, 128);
    const Image base = render_scene(*make_method("none").method, scene);
    const Image luma = srgb_luma(base);
    for (const char* preset : kPresets) {
        const SmaaSettings settings = smaa_preset(preset);
        const SmaaAreaTable areas(settings.max_distance());
        SmaaScratch scratch;
        Image out(base.width, base.height);
        smaa_pass_rows(base, luma, settings, areas, scratch, out, 0, base.height);  // warm-up
        const AllocCounts before = thread_alloc_counts();
        smaa_pass_rows(base, luma, settings, areas, scratch, out, 0, base.height);
        EXPECT_EQ(thread_alloc_counts().allocations, before.allocations) << preset;
    }
}

// A 45-degree edge: the staircase's midline gives each pixel on it a corner triangle of 1/8.
// Presets with diagonal patterns read it as a diagonal run; low and medium as Z shapes of one
// pixel, one axis each (the neighbourhood blend's choice): both readings give the midline.
TEST(SmaaPass, FortyFiveDegreeStaircaseTakesItsMidlinesCorners) {
    constexpr int kSide = 48;
    Scene scene;
    scene.width = kSide;
    scene.height = kSide;
    Shape shape;  // value 1 below the line y = x + 10.25 (no pixel centre on it)
    shape.contours.push_back({{-10, -10 + 10.25}, {-10, 70}, {70, 70}, {70, 70 + 10.25}});
    scene.shapes.push_back(shape);
    // Float32 arithmetic on 0, 1 and 1/8: exact up to rounding of one blend.
    constexpr float kTolerance = 1e-6f;
    for (const char* preset : kPresets) {
        const Image out =
            render_scene(*make_method(std::string("smaa:preset=") + preset).method, scene);
        for (int i = 8; i <= 30; ++i) {
            ASSERT_NEAR(out.at(i, i + 11), 1.0f - kSmaaDiagonalCornerArea, kTolerance)
                << preset << " at x=" << i;
            ASSERT_NEAR(out.at(i, i + 10), kSmaaDiagonalCornerArea, kTolerance)
                << preset << " at x=" << i;
            ASSERT_EQ(out.at(i, i + 12), 1.0f) << preset;
            ASSERT_EQ(out.at(i, i + 9), 0.0f) << preset;
        }
    }
}

// A half-plane (value 1 below the line y = y0 + x tan(angle), background 0).
Scene half_plane(double angle_deg, double y0, int width, int height) {
    const double slope = std::tan(angle_deg * std::numbers::pi / 180.0);
    Scene scene;
    scene.width = width;
    scene.height = height;
    Shape shape;
    shape.value = 1.0;
    const double x0 = -10.0, x1 = width + 10.0, bottom = height + 10.0;
    shape.contours.push_back(
        {{x0, y0 + slope * x0}, {x0, bottom}, {x1, bottom}, {x1, y0 + slope * x1}});
    scene.shapes.push_back(shape);
    return scene;
}

double rmse(const Image& image, const Coverage& reference) {
    double sum = 0.0;
    for (std::size_t i = 0; i < image.data.size(); ++i) {
        const double e = image.data[i] - reference.data[i];
        sum += e * e;
    }
    return std::sqrt(sum / static_cast<double>(image.data.size()));
}

TEST(SmaaPass, NearHorizontalEdgeMovesTowardItsExactCoverage) {
    // SMAA's rmse against the exact coverage, as a share of none's: measured 0.16 (8 degrees)
    // to 0.56 (2 degrees, preset low: the staircase's steps of 29 px are longer than the 17 px
    // its search sees, 4 steps of two pixels each way, so their ends go unseen). 0.6 leaves
    // room for that worst case only.
    constexpr double kMaxShareOfNone = 0.6;
    for (const double angle : {2.0, 4.0, 8.0, 15.0}) {
        const Scene scene = half_plane(angle, 20.3, 128, 64);
        const Coverage exact = box_reference(scene);
        const double none = rmse(render_scene(*make_method("none").method, scene), exact);
        for (const char* preset : kPresets) {
            const MethodInstance m = make_method(std::string("smaa:preset=") + preset);
            const double smaa = rmse(render_scene(*m.method, scene), exact);
            EXPECT_LT(smaa, kMaxShareOfNone * none) << angle << " deg, " << preset;
        }
    }
}

}  // namespace
}  // namespace aabench
