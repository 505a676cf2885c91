// `star`: a Siemens star, `spokes` dark-on-light wedges (value 1 on background 0) meeting at
// one centre.
//
// Aliasing it provokes: towards the centre the wedges get narrower than a pixel, so every
// method has a radius inside which it can no longer resolve them. Point sampling turns that
// region into false low-frequency patterns (moiré, spurious spokes), box filters into a grey
// disc; the radius of that disc and how cleanly the spokes fade is what to compare. The
// straight wedge sides, at every angle, also show jagged edges.
//
// Wedge k spans the angles [a0 + 2*pi*k/spokes, a0 + 2*pi*k/spokes + pi/spokes]: half of each
// period is filled. Each wedge is its own shape (so later measurements can find each spoke's
// tip), a polygon of the centre and points on the arc, spaced so that no chord departs from
// the true circle by more than kMaxSagittaPx.
//
// Thin objects (Scene::thin_objects, measured for captured mass and popping): each wedge's tip,
// labelled "tip k", the triangle of the centre and the two points on the wedge's sides at the
// distance d where the wedge is kTipWidthPx wide, 2 d sin(span / 2) = kTipWidthPx (the chord
// across, which is also the width perpendicular to the bisector there). That is the part of
// the spoke narrower than a one-pixel filter can resolve, where spokes vanish. When the star
// is too small to reach that width (d > radius), the tip is the whole wedge's triangle up to
// the radius.
//
// Parameters (sizes relative to the image, so any size works):
//   spokes       36      number of dark wedges
//   radius       0.92    fraction of half the smaller side
//   cx, cy       0.5012, 0.4987  centre as fractions of width and height (off the grid)
//   start_angle  0.1     radians, edge of wedge 0 (not 0, so no edge lies on a pixel row)
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "patterns/pattern.h"

namespace aabench {

namespace {

// Width at which a spoke tip ends: 1.5 px, wide enough that a one-pixel filter resolves the
// spoke beyond it, so everything that can vanish lies inside the tip.
constexpr double kTipWidthPx = 1.5;


Scene generate_star(const ParamValues& values, int width, int height) {
    Scene scene = begin_pattern_scene("star", values, width, height);
    const int spokes = values.get_int("spokes");
    const double radius_px = values.get_real("radius") * 0.5 * std::min(width, height);
    const double cx = values.get_real("cx") * width;
    const double cy = values.get_real("cy") * height;
    const double a0 = values.get_real("start_angle");

    const double span = std::numbers::pi / spokes;
    scene.shapes.reserve(spokes);
    scene.thin_objects.reserve(spokes);
    // Distance along each side to where the wedge is kTipWidthPx wide (see the top).
    const double tip_px = std::min(radius_px, 0.5 * kTipWidthPx / std::sin(0.5 * span));
    for (int k = 0; k < spokes; ++k) {
        // Angles computed from k directly (not accumulated) so every wedge is exact to
        // rounding and the result does not depend on summation order.
        const double start = a0 + 2.0 * std::numbers::pi * k / spokes;
        Shape shape;
        shape.value = 1.0;
        shape.contours.push_back(star_wedge(cx, cy, radius_px, start, span));
        scene.shapes.push_back(std::move(shape));

        // The tip: centre, then the first side, then the second (the wedge's orientation).
        const double end = start + span;
        Shape tip;
        tip.value = 1.0;
        tip.contours.push_back({{cx, cy},
                                {cx + tip_px * std::cos(start), cy + tip_px * std::sin(start)},
                                {cx + tip_px * std::cos(end), cy + tip_px * std::sin(end)}});
        scene.thin_objects.push_back({fmt::format("tip {}", k), std::move(tip)});
    }
    set_focus(scene, cx, cy, kFocusSidePx);  // the centre, where the wedges fall below a pixel
    return scene;
}

}  // namespace

// Number of chords needed for an arc of `span` radians at radius `radius_px` so that each
// chord's sagitta r*(1 - cos(half angle)) stays within kMaxSagittaPx.
static int arc_segments(double span, double radius_px) {
    if (radius_px <= kMaxSagittaPx) return 1;
    const double max_half_angle = std::acos(1.0 - kMaxSagittaPx / radius_px);
    return std::max(1, static_cast<int>(std::ceil(span / (2.0 * max_half_angle))));
}

Contour star_wedge(double cx, double cy, double radius_px, double start, double span) {
    const int segments = arc_segments(span, radius_px);
    Contour wedge;
    wedge.reserve(static_cast<std::size_t>(segments) + 2);
    wedge.push_back({cx, cy});
    // Increasing angle with y down: positive shoelace area, the same orientation as
    // circle_contour(..., clockwise = false).
    for (int i = 0; i <= segments; ++i) {
        const double a = start + span * i / segments;
        wedge.push_back({cx + radius_px * std::cos(a), cy + radius_px * std::sin(a)});
    }
    return wedge;
}

PatternInfo star_pattern() {
    return PatternInfo{
        "star",
        "Siemens star: wedges narrowing to a point; shows where detail is lost and moire",
        // One row per parameter: name, kind, default, min, max, choices, doc.
        // clang-format off
        {
            {"spokes", ParamKind::kInt, 36, 2, 4096, {},
             "number of dark wedges; 36 (5 degree wedges) puts the resolution limit of a "
             "one-pixel filter at a radius of about 11 px, well inside a 256 px star"},
            {"radius", ParamKind::kReal, 0.92, 0.01, 10, {},
             "star radius as a fraction of half the smaller side; 0.92 keeps the whole star "
             "inside the image with an off-grid centre"},
            {"cx", ParamKind::kReal, 0.5012, -10, 10, {},
             "centre x as a fraction of the width; 0.5012 keeps the tip off pixel corners "
             "and centres at every size"},
            {"cy", ParamKind::kReal, 0.4987, -10, 10, {},
             "centre y as a fraction of the height; 0.4987, off the grid like cx"},
            {"start_angle", ParamKind::kReal, 0.1, -10, 10, {},
             "angle of wedge 0's first edge in radians (y down); 0.1 so no edge runs along "
             "a pixel row or column"},
        },
        // clang-format on
        generate_star,
    };
}

}  // namespace aabench
