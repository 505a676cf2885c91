// The glyph rasterizers as peers (methods/freetype.cpp, methods/stb_truetype.cpp): each draws
// polygons and curves close to exact, in the right place and orientation, and its images are
// what the libraries give for the scene (a lost path, a y flip or a misread coverage would show
// as an error larger than none's, or as a bias).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "harness/measure/compare.h"
#include "harness/measure/metrics.h"
#include "harness/reference/box_reference.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// An 8-bit rasterizer's mean signed error over a pattern: its coverage rounds both ways and
// its flattening loses area on convex arcs only where it is coarse; a y flip, a shifted grid
// or coverage read as sRGB codes moves the mean by far more (0.02 and up on these patterns).
constexpr double kMaxBias = 0.005;
// One byte of coverage, and the rounding of the composite: an 8-bit peer within this of
// exact per pixel on a pixel-aligned square, where every pixel is 0 or 1; and one 8-bit step
// between two renders of a peer.
constexpr double kByteStep = 1.0 / 255.0 + 1e-6;

struct Errors {
    double rmse, bias;
};
Errors errors(const char* spec, const Scene& scene, const Coverage& reference) {
    const Image image = render_scene(*make_method(spec).method, scene);
    const ErrorStats e = compare_to_reference(image, reference);
    return {e.rmse, e.bias};
}

TEST(TextPeers, CloserThanNoneAndUnbiasedOnStarAndText) {
    for (const char* pattern : {"star", "text", "text-cff", "curves"}) {
        const Scene scene = make_pattern(pattern, 128, 128);
        const Coverage reference = box_reference(scene);
        const double none = errors("none", scene, reference).rmse;
        for (const char* peer : {"freetype", "stb-truetype"}) {
            const Errors e = errors(peer, scene, reference);
            EXPECT_LT(e.rmse, 0.5 * none) << peer << " on " << pattern;
            EXPECT_LT(std::abs(e.bias), kMaxBias) << peer << " on " << pattern;
        }
    }
}

TEST(TextPeers, PixelAlignedSquareIsExactToAByte) {
    Scene scene;
    scene.width = 20;
    scene.height = 16;
    scene.background = 0.25;
    Shape square;
    square.value = 1.0;
    square.contours = {{{3, 2}, {11, 2}, {11, 13}, {3, 13}}};
    scene.shapes.push_back(square);
    for (const char* peer : {"freetype", "stb-truetype"}) {
        const Image image = render_scene(*make_method(peer).method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const bool inside = i >= 3 && i < 11 && j >= 2 && j < 13;
                EXPECT_NEAR(image.at(i, j), inside ? 1.0 : 0.25, kByteStep)
                    << peer << " pixel " << i << "," << j;
            }
        }
    }
}

// FreeType refuses an outline reaching beyond 2^18 px (Invalid_Outline): a wedge whose tip
// lies at x = 1e6 px (found by render_fuzz) is clipped near the image first, so it is drawn,
// finite and close to exact, not refused as NaN. Within two bytes: the 1/64 px grid and the
// 8-bit coverage.
TEST(TextPeers, FreeTypeDrawsContoursReachingFarFromTheImage) {
    Scene scene;
    scene.width = 8;
    scene.height = 8;
    Shape wedge;
    wedge.value = 1.0;
    wedge.contours = {{{1e6, -2.0}, {0.0, -16.0}, {-3.5, -16.0}, {13.5, 6.0}, {3.0, 2.5}}};
    scene.shapes.push_back(wedge);
    const Coverage reference = box_reference(scene);
    const Image image = render_scene(*make_method("freetype").method, scene);
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            ASSERT_TRUE(std::isfinite(image.at(i, j))) << i << "," << j;
            EXPECT_NEAR(image.at(i, j), reference.at(i, j), 2.0 * kByteStep) << i << "," << j;
        }
    }
}

// The largest |freetype - exact| over the image, exact for the polygons' points rounded to
// 1/64 px as FreeType takes them (what is left is its 8-bit coverage).
double worst_freetype_error(const Scene& scene) {
    Scene rounded = scene;
    for (Shape& shape : rounded.shapes) {
        for (Contour& contour : shape.contours) {
            for (Point& p : contour) p = {std::round(p.x * 64.0) / 64.0, std::round(p.y * 64.0) / 64.0};
        }
    }
    const Coverage reference = box_reference(rounded);
    const Image image = render_scene(*make_method("freetype").method, scene);
    double worst = 0.0;
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            worst = std::max(worst, std::abs(image.at(i, j) - reference.at(i, j)));
        }
    }
    return worst;
}

// A run of one value with more points than an FT_Outline holds (16-bit counts): 24 rings as
// polygons of 2 x 1100 points, 52,800 in all. FreeType is handed each connected group of
// contours (a ring's outer contour with its hole) as one outline, so no hole is ever drawn
// without its outer contour: a filled hole would be 1.0 off. Within two bytes of the exact
// coverage of the points FreeType is given (8-bit coverage, and its rounding).
TEST(TextPeers, FreeTypeKeepsEveryHoleWithItsContourInRunsBeyondAnOutline) {
    Scene scene;
    scene.width = 96;
    scene.height = 64;
    constexpr int kVertices = 1100;  // 29 contours fill an outline: an odd cut would split a ring
    for (int r = 0; r < 24; ++r) {
        const double cx = 8.3 + 16.0 * (r % 6), cy = 8.6 + 16.0 * (r / 6);
        Shape ring;
        ring.value = 1.0;
        Contour outer, inner;
        for (int k = 0; k < kVertices; ++k) {
            const double t = 2.0 * std::numbers::pi * k / kVertices;
            outer.push_back({cx + 6.5 * std::cos(t), cy + 6.5 * std::sin(t)});
            inner.push_back({cx + 3.2 * std::cos(-t), cy + 3.2 * std::sin(-t)});
        }
        ring.contours = {outer, inner};
        scene.shapes.push_back(ring);
    }
    EXPECT_LE(worst_freetype_error(scene), 2.0 * kByteStep);
}

// One group beyond an outline: 20 nested rings of one shape (44,000 points; every contour's
// box holds the next), as `rings` is at 1024². Its contours cannot be split into outlines
// without separating a ring from its hole, so the group is drawn in tiles, each contour clipped
// to the tile. A filled hole would be 1.0 off.
TEST(TextPeers, FreeTypeDrawsNestedContoursBeyondAnOutlineInTiles) {
    Scene scene;
    scene.width = 90;
    scene.height = 90;
    // 29 contours of 1100 points fill an outline: a cut in contour order would fall between
    // the 15th ring's outer contour and its hole.
    constexpr int kVertices = 1100;
    Shape rings;
    rings.value = 1.0;
    for (int r = 0; r < 20; ++r) {
        const double outer = 43.0 - 2.1 * r, inner = outer - 1.05;
        Contour out, in;
        for (int k = 0; k < kVertices; ++k) {
            const double t = 2.0 * std::numbers::pi * k / kVertices;
            out.push_back({45.3 + outer * std::cos(t), 44.8 + outer * std::sin(t)});
            in.push_back({45.3 + inner * std::cos(-t), 44.8 + inner * std::sin(-t)});
        }
        rings.contours.push_back(out);
        rings.contours.push_back(in);
    }
    scene.shapes.push_back(rings);
    EXPECT_LE(worst_freetype_error(scene), 2.0 * kByteStep);
}

// blend=srgb composites the same 8-bit coverage in sRGB codes: a pixel half covered by white on
// black shows dec(128/255) = 0.2158, not 0.502 (thinner), and black on white the same 0.2158,
// not 0.498 (bolder); a full or empty pixel keeps its value.
TEST(TextPeers, FreeTypeBlendsInSrgbCodesWhenAsked) {
    const auto decode = [](double c) {
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    for (const double background : {0.0, 1.0}) {
        Scene scene;
        scene.width = 8;
        scene.height = 4;
        scene.background = background;
        Shape half;
        half.value = 1.0 - background;
        half.contours = {{{1, 0}, {3.5, 0}, {3.5, 4}, {1, 4}}};  // pixel 3 half covered
        scene.shapes.push_back(half);
        const Image linear = render_scene(*make_method("freetype").method, scene);
        const Image srgb = render_scene(*make_method("freetype:blend=srgb").method, scene);
        for (int j = 0; j < scene.height; ++j) {
            EXPECT_NEAR(linear.at(3, j), 0.5, kByteStep) << background;
            // The composite of coverage a in codes: dec(a) white on black, dec(1 - a) black
            // on white: in both, the linear composite's value read as a code.
            EXPECT_NEAR(srgb.at(3, j), decode(linear.at(3, j)), 1e-6) << background;
            EXPECT_NEAR(srgb.at(3, j), 0.2158, 0.01) << background;
            EXPECT_EQ(srgb.at(2, j), linear.at(2, j));
            EXPECT_EQ(srgb.at(5, j), linear.at(5, j));
        }
    }
}

// The curves go to the libraries as curves: a coarser flatness moves stb_truetype's image
// away from exact, and its own flattening (flatten_bias's input) explains the difference.
TEST(TextPeers, StbFlatnessIsItsCurveTolerance) {
    const Scene scene = make_pattern("curves", 96, 96);
    const Coverage reference = box_reference(scene);
    const double fine = errors("stb-truetype:flatness=0.02", scene, reference).rmse;
    const double coarse = errors("stb-truetype:flatness=3", scene, reference).rmse;
    EXPECT_LT(fine, coarse);
    const MethodInstance m = make_method("stb-truetype:flatness=3");
    const std::optional<Scene> own = m.method->own_flattening(scene);
    ASSERT_TRUE(own.has_value());
    EXPECT_FALSE(has_bezier(*own));
    // Against the exact image of its own polygon, the coarse flattening's error is gone: what
    // remains is the 8-bit coverage and the vertex grid.
    const double own_error =
        compare_to_reference(render_scene(*m.method, scene), box_reference(*own)).rmse;
    EXPECT_LT(own_error, 0.25 * coarse);
}

// Drawing in bands (threads) gives the whole image: FreeType's bit for bit (its clip box of
// whole rows), stb_truetype's within an 8-bit step (its float x stepped from a band's first
// row; the vertex grid itself is placed per fill, not per band).
TEST(TextPeers, BandsGiveTheWholeImage) {
    const Scene scene = make_pattern("text", 96, 80);
    for (const auto& [peer, tolerance] :
         {std::pair{"freetype", 0.0}, std::pair{"stb-truetype", kByteStep}}) {
        const MethodInstance m = make_method(peer);
        const Image one = render_scene(*m.method, scene);
        Image three = one;
        render_in_bands(*m.method, scene, three, 3);
        for (std::size_t k = 0; k < one.data.size(); ++k) {
            ASSERT_NEAR(one.data[k], three.data[k], tolerance) << peer << " pixel " << k;
        }
    }
}

}  // namespace
}  // namespace aabench
