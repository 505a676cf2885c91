// `curves`: a Siemens star whose spokes are curved petals, each bounded by two cubic Bezier
// sides (value 1 on background 0): the curve pattern of the default run.
//
// Aliasing it provokes: what `star` provokes (spokes narrowing below a pixel towards the
// centre, jagged sides at every angle), on curves. Each petal leaves its base at the inner
// radius and swings by `twist_deg` on its way to its tip, so its two sides turn through a range
// of directions and their curvature changes along them: every edge angle and curvature occurs
// somewhere, the case a rasterizer's flattening (chords inside the convex side of each curve)
// gets systematically wrong. The exact references integrate the cubics themselves
// (docs/references.md, "Curves: Bezier segments"); methods that flatten lose the area between
// chord and arc on every petal.
//
// Petal k's base spans the angles theta_k -+ half_width at radius inner * R (R the star's
// radius), its tip lies at radius R and angle theta_k + twist. Its left side is the cubic from
// the base's left point to the tip with control points at 45% and 80% of R, swung by 35% and
// 85% of the twist and pulled towards the petal's other side by `bulge` of the half width;
// the right side comes back symmetrically; a straight edge across the base closes it. Each
// petal is its own shape; neighbouring petals do not touch at the defaults (gaps of about
// 0.4 half widths at the base).
//
// Parameters (sizes relative to the image):
//   petals     16     number of petals
//   radius     0.92   fraction of half the smaller side
//   inner      0.08   base radius as a fraction of the radius
//   twist_deg  40     degrees the tip turns from the base (curvature at every angle)
//   cx, cy     0.5012, 0.4987  centre as fractions of width and height (off the grid)
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "patterns/pattern.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

Point polar(Point c, double r, double a) { return {c.x + r * std::cos(a), c.y + r * std::sin(a)}; }

Scene generate_curves(const ParamValues& values, int width, int height) {
    const int petals = values.get_int("petals");
    const double inner = values.get_real("inner");
    const double twist = values.get_real("twist_deg") * std::numbers::pi / 180.0;
    Scene scene = begin_pattern_scene("curves", values, width, height);
    const Point c{values.get_real("cx") * width, values.get_real("cy") * height};
    const double r = values.get_real("radius") * 0.5 * std::min(width, height);
    // A petal's base covers 60% of its period, so petals leave gaps between them.
    const double half = 0.3 * 2.0 * std::numbers::pi / petals;
    const double bulge = 0.5;
    for (int k = 0; k < petals; ++k) {
        const double theta = 0.1 + 2.0 * std::numbers::pi * k / petals;
        const Point left = polar(c, inner * r, theta - half);
        const Point right = polar(c, inner * r, theta + half);
        const Point tip = polar(c, r, theta + twist);
        // The side's controls: along the swing, narrowing towards the tip.
        auto control = [&](double at_r, double swing, double side) {
            return polar(c, at_r * r, theta + swing * twist + side * half * (1.0 - bulge * at_r));
        };
        const Segment a =
            cubic_segment(left, control(0.45, 0.35, -1.0), control(0.8, 0.85, -0.35), tip);
        const Segment b =
            cubic_segment(tip, control(0.8, 0.85, 0.35), control(0.45, 0.35, 1.0), right);
        scene.shapes.push_back(bezier_shape({{a, b, line_segment(right, left)}}, 1.0));
    }
    set_focus(scene, c.x, c.y, kFocusSidePx);  // the centre, where the petals narrow
    return scene;
}

}  // namespace

PatternInfo curves_pattern() {
    return PatternInfo{
        "curves",
        "a Siemens star of curved petals with cubic Bezier sides; curvature at every angle, "
        "what flattening loses",
        // clang-format off
        {
            {"petals", ParamKind::kInt, 16, 2, 256, {},
             "number of petals; 16 leaves each petal tens of pixels wide at 256x256"},
            {"radius", ParamKind::kReal, 0.92, 0.01, 1.5, {},
             "star radius as a fraction of half the smaller side"},
            {"inner", ParamKind::kReal, 0.08, 0.0, 0.9, {},
             "radius of the petals' bases as a fraction of the radius"},
            {"twist_deg", ParamKind::kReal, 40, -180, 180, {},
             "degrees each petal turns from base to tip: its sides sweep that range of "
             "directions"},
            {"cx", ParamKind::kReal, 0.5012, -1, 2, {}, "centre x as a fraction of the width"},
            {"cy", ParamKind::kReal, 0.4987, -1, 2, {}, "centre y as a fraction of the height"},
        },
        // clang-format on
        generate_curves,
        /*in_default_run=*/true,
        /*bezier=*/true,
    };
}

}  // namespace aabench
