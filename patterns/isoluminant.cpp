// `isoluminant`: a colour pattern (Scene::channels == 3), two Siemens stars side by side on one
// green background. The left star's spokes are red of the background's luma; the right star's,
// the control, are the background's own green made brighter (one hue, another luma).
//
// What it measures: the blind spot of edge detection on luma. Post-process antialiasing (FXAA,
// SMAA, MLAA) finds the edges it smooths from the luma of the encoded colour; an edge between
// two colours of equal luma is invisible to that test and stays as aliased as the frame it was
// given. "Equal luma" is as SMAA's luma edge detection computes it (Jimenez et al. 2012,
// SMAALumaEdgeDetectionPS): Rec. 709 weights on the sRGB-encoded colour, the frame a renderer
// hands it with `space=srgb`:
//     background  encoded (0.10, 0.45, 0.10)                     luma 0.35032
//     left spokes encoded (r,    0.20, 0.20), r = 0.90706        luma 0.35032 (r solved for it)
//     right spokes the background's linear colour x 2.5          luma 0.53875 (+0.18843)
// Other detectors see other differences between the left spokes and the background (encoded
// colours; tests/colour_test.cpp, IsoluminantPattern, recomputes every figure here):
//     Rec. 601 weights (0.299, 0.587, 0.114), FXAA 3.11's luma            +0.10596
//     green alone (FXAA_GREEN_AS_LUMA)                                    -0.25
//     the largest channel difference (SMAA's colour edge detection)        0.80706
// and between the right spokes and the background +0.16757, +0.23478 and 0.23478. So SMAA's
// luma detector (threshold 0.1) finds no edge on the left star and every edge of the right one;
// the others find both, by different margins. docs/colour.md measures each method on each star.
//
// Geometry: each star as `star` draws it (patterns/star.cpp's wedges, value per wedge), centred
// at (0.25, 0.5) and (0.75, 0.5) of the image (nudged off the grid), radius `radius` of half of
// min(width / 2, height). Thin objects: each spoke tip of both stars ("iso tip k", "control tip
// k"), as star's. The focus is the isoluminant star's centre (the control's when it is alone).
//
// Parameters:
//   spokes       24     dark wedges per star (fewer than star's 36: each star is half as wide)
//   radius       0.9    fraction of half of min(width / 2, height)
//   start_angle  0.1    radians, edge of wedge 0 (off the pixel rows, as in star)
//   stars        both   both | iso | control: one star alone, in its place (its own figures)
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "patterns/pattern.h"

namespace aabench {
namespace {

// Width at which a spoke tip ends, as in star (patterns/star.cpp).
constexpr double kTipWidthPx = 1.5;
// Off-grid nudges of the centres, as star's 0.5012 and 0.4987.
constexpr double kNudgeX = 0.0012;
constexpr double kNudgeY = -0.0013;

// The sRGB decoding (IEC 61966-2-1) of an encoded value in [0, 1]: linear light.
double srgb_decode(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

// The encoded colours of the essay above.
constexpr Rgb kBackgroundEncoded{0.10, 0.45, 0.10};
constexpr double kSpokeEncodedGreenBlue = 0.20;
constexpr double kControlGain = 2.5;  // the control's linear colour: the background's x 2.5

Rgb decoded(const Rgb& encoded) {
    return {srgb_decode(encoded[0]), srgb_decode(encoded[1]), srgb_decode(encoded[2])};
}

Scene generate_isoluminant(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("isoluminant", values, width, height);
    const int spokes = values.get_int("spokes");
    const double radius_px = values.get_real("radius") * 0.5 * std::min(0.5 * width, 1.0 * height);
    const double a0 = values.get_real("start_angle");

    // Red of the background's luma, solved on the encoded colour with SMAA's weights.
    const Rgb& w = kLuminanceWeights;  // Rec. 709, the weights SMAA's luma takes
    const double luma = luminance(kBackgroundEncoded);
    const double red = (luma - (w[1] + w[2]) * kSpokeEncodedGreenBlue) / w[0];
    const Rgb background = decoded(kBackgroundEncoded);
    const Rgb iso = decoded({red, kSpokeEncodedGreenBlue, kSpokeEncodedGreenBlue});
    const Rgb control{kControlGain * background[0], kControlGain * background[1],
                      kControlGain * background[2]};

    scene.channels = 3;
    scene.background_rgb = background;
    scene.background = luminance(background);
    const double span = std::numbers::pi / spokes;
    const double tip_px = std::min(radius_px, 0.5 * kTipWidthPx / std::sin(0.5 * span));
    struct Star {
        double cx, cy;
        Rgb colour;
        const char* label;
    };
    const Star stars[] = {
        {(0.25 + kNudgeX) * width, (0.5 + kNudgeY) * height, iso, "iso"},
        {(0.75 + kNudgeX) * width, (0.5 + kNudgeY) * height, control, "control"},
    };
    const std::string& drawn = values.get_choice("stars");
    scene.shapes.reserve(2 * static_cast<std::size_t>(spokes));
    for (const Star& star : stars) {
        if (drawn != "both" && drawn != star.label) continue;
        for (int k = 0; k < spokes; ++k) {
            const double start = a0 + 2.0 * std::numbers::pi * k / spokes;
            Shape shape;
            shape.rgb = star.colour;
            shape.value = luminance(star.colour);
            shape.contours.push_back(star_wedge(star.cx, star.cy, radius_px, start, span));
            scene.shapes.push_back(std::move(shape));
            const double end = start + span;
            Shape tip;
            tip.rgb = star.colour;
            tip.value = luminance(star.colour);
            tip.contours.push_back(
                {{star.cx, star.cy},
                 {star.cx + tip_px * std::cos(start), star.cy + tip_px * std::sin(start)},
                 {star.cx + tip_px * std::cos(end), star.cy + tip_px * std::sin(end)}});
            scene.thin_objects.push_back({fmt::format("{} tip {}", star.label, k), std::move(tip)});
        }
    }
    const Star& focus = drawn == "control" ? stars[1] : stars[0];
    set_focus(scene, focus.cx, focus.cy, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo isoluminant_pattern() {
    PatternInfo info{
        "isoluminant",
        "colour: a star of equal luma and different chroma beside its control of one hue; "
        "the blind spot of luma edge detection",
        // clang-format off
        {
            {"spokes", ParamKind::kInt, 24, 2, 4096, {},
             "dark wedges per star; 24 (7.5 degree wedges) resolves to about 6 px from the "
             "centre of a 128 px star"},
            {"radius", ParamKind::kReal, 0.9, 0.01, 10, {},
             "each star's radius as a fraction of half of min(width / 2, height); 0.9 keeps "
             "both stars inside the image and apart"},
            {"start_angle", ParamKind::kReal, 0.1, -10, 10, {},
             "angle of wedge 0's first edge in radians (y down); 0.1 so no edge runs along a "
             "pixel row or column"},
            {"stars", ParamKind::kChoice, 0, 0, 0, {"both", "iso", "control"},
             "which stars are drawn, each where it is in the whole pattern: one alone gives "
             "the figures of that star (an edge rmse per star)"},
        },
        // clang-format on
        generate_isoluminant,
    };
    // Not in the default run yet: the post-process rows it is made for draw colour only once
    // their colour paths exist.
    info.in_default_run = false;
    return info;
}

}  // namespace aabench
