// `grating`: parallel straight bars (value 1 on background 0) of constant period, tilted a
// little from vertical, covering the whole image.
//
// Aliasing it provokes: moiré. With the period near the pixel pitch, point sampling (and any
// filter too narrow for it) folds the grating's frequency down to a slow beat, broad light and
// dark bands that are not in the scene; the small tilt makes those bands run diagonally and
// drift along the bars, so a method that only aliases at some phases is still caught. An ideal
// box-filtered result is close to a flat grey of value duty.
//
// Geometry: with the unit normal n = (cos a, sin a) (a = angle_deg, y down) and t = p . n the
// signed distance of a point p from the image's top-left corner across the bars, bar k covers
// phase + k*period <= t <= phase + (k + duty)*period. Bars run along d = (-sin a, cos a) and
// extend kMarginPx past every image edge so no bar end is visible. All bars are contours of
// one shape; they are disjoint (duty < 1), so nonzero winding fills exactly the bars.
//
// Parameters:
//   period     1.06  px, bar-to-bar distance across the bars (just above the pixel pitch)
//   duty       0.5   fraction of the period that is bar
//   angle_deg  3     degrees of the normal from the x axis: bars 3 degrees from vertical
//   phase      0.37  px, offset of bar 0's leading edge from the corner (off the grid)
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "patterns/pattern.h"

namespace aabench {

namespace {

// How far bars reach past the image edges: more than any filter's support radius (a few
// pixels), so no method sees a bar end and every edge in the image is a long side.
constexpr double kMarginPx = 4.0;

Scene generate_grating(const ParamValues& values, int width, int height) {
    const double period = values.get_real("period");
    const double duty = values.get_real("duty");
    const double angle = values.get_real("angle_deg") * std::numbers::pi / 180.0;
    const double phase = values.get_real("phase");
    const double nx = std::cos(angle), ny = std::sin(angle);  // across the bars
    const double dx = -ny, dy = nx;                           // along the bars

    // Range of t (across) and s (along) over the corners of the image grown by the margin.
    const double x0 = -kMarginPx, x1 = width + kMarginPx;
    const double y0 = -kMarginPx, y1 = height + kMarginPx;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    double t_min = kInf, t_max = -kInf, s_min = kInf, s_max = -kInf;
    for (const Point corner : {Point{x0, y0}, Point{x1, y0}, Point{x1, y1}, Point{x0, y1}}) {
        const double t = corner.x * nx + corner.y * ny;
        const double s = corner.x * dx + corner.y * dy;
        t_min = std::min(t_min, t);
        t_max = std::max(t_max, t);
        s_min = std::min(s_min, s);
        s_max = std::max(s_max, s);
    }
    // Bars k_first..k_last are those whose interval can meet [t_min, t_max]; bar k_first may
    // end just before t_min, which is harmless (it lies past the margin).
    const double k_first = std::floor((t_min - phase) / period);
    const double k_last = std::floor((t_max - phase) / period);
    const double bar_count = k_last - k_first + 1.0;
    if (bar_count * 4.0 > static_cast<double>(kMaxPatternVertices)) {
        throw InputError(fmt::format(
            "pattern 'grating': {:.0f} bars need more than {} vertices; increase period "
            "or reduce the size",
            bar_count, kMaxPatternVertices));
    }

    Scene scene = begin_pattern_scene("grating", values, width, height);
    Shape shape;
    shape.value = 1.0;
    shape.contours.reserve(static_cast<std::size_t>(bar_count));
    for (double k = k_first; k <= k_last; k += 1.0) {
        // Edges computed from k directly (not accumulated) so the period stays exact to
        // rounding across thousands of bars.
        const double t0 = phase + k * period;
        const double t1 = phase + (k + duty) * period;
        // p = t*n + s*d; since n x d = +1, this corner order has a positive shoelace area
        // (the circle_contour orientation).
        shape.contours.push_back({
            {t0 * nx + s_min * dx, t0 * ny + s_min * dy},
            {t1 * nx + s_min * dx, t1 * ny + s_min * dy},
            {t1 * nx + s_max * dx, t1 * ny + s_max * dy},
            {t0 * nx + s_max * dx, t0 * ny + s_max * dy},
        });
    }
    scene.shapes.push_back(std::move(shape));
    set_focus(scene, 0.5 * width, 0.5 * height, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo grating_pattern() {
    return PatternInfo{
        "grating",
        "parallel bars near the pixel pitch at a small angle; moire",
        // One row per parameter: name, kind, default, min, max, choices, doc.
        // clang-format off
        {
            {"period", ParamKind::kReal, 1.06, 0.05, 100000, {},
             "bar-to-bar distance across the bars in px; 1.06, just above the pixel pitch, "
             "aliases to a beat about 18 px wide: slow, plain moire"},
            {"duty", ParamKind::kReal, 0.5, 0.01, 0.99, {},
             "fraction of each period covered by a bar; 0.5 gives the strongest fundamental "
             "and an ideal mean of 0.5"},
            {"angle_deg", ParamKind::kReal, 3, -90, 90, {},
             "angle of the bars' normal from the x axis in degrees (y down); 3 tilts the bars "
             "off vertical so the beat runs diagonally and every sub-pixel phase occurs"},
            {"phase", ParamKind::kReal, 0.37, -100000, 100000, {},
             "offset in px of bar 0's leading edge from the top-left corner, across the "
             "bars; 0.37 keeps edges off pixel boundaries"},
        },
        // clang-format on
        generate_grating,
    };
}

}  // namespace aabench
