// `crescents`: thin curved strips (value 1 on background 0), one column per width and one row
// per angle: `strips` on curves, the thin-object symptom where the boundary bends.
//
// Aliasing it provokes: a curved strip narrower than a pixel breaks into dashes under point
// sampling wherever its direction runs along the sample rows, and the direction changes along
// it, so every crescent has a stretch that is hard for a row-by-row sampler. A method that
// flattens the curve loses the area between chord and arc on the convex side and gains it on
// the concave side; on a strip of 0.05 px that is a large share of its ink.
//
// Crescent (row, column) lies in its cell: the chord of length kChordFraction x the cell's
// smaller side, centred at the cell's centre plus kOffGridOffsetPx, along the row's angle a
// (from the x axis towards +y); its first side is the quadratic from the chord's start to its
// end whose control point lies `bend` x 2 x the chord's length off its middle (so the arc
// departs from its chord by `bend` x the chord's length); its second side is the same
// quadratic moved by the column's width w across the chord, run backwards. The strip is w
// thick across the chord everywhere (w cos(phi) across the curve where its tangent turns by
// phi from the chord: the full w at the middle). Widths are spaced geometrically from
// min_width to max_width.
//
// Thin objects (Scene::thin_objects): every crescent, in shape order, labelled
// "crescent w=<width px> a=<angle deg>°".
//
// Parameters:
//   min_width      0.05  px
//   max_width      1.5   px
//   widths         8     columns
//   min_angle_deg  3     degrees, first row
//   max_angle_deg  87    degrees, last row
//   angles         3     rows: 3, 45, 87 at the defaults
//   bend           0.2   the arc's sagitta as a fraction of its chord
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "patterns/pattern.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// As in `strips`: no chord or control point lines up with the pixel grid.
constexpr Point kOffGridOffsetPx = {0.3183, 0.2719};
// The chord's length as a fraction of the cell's smaller side, leaving room for the bend.
constexpr double kChordFraction = 0.7;

Scene generate_crescents(const ParamValues& values, int width, int height) {
    const double min_width = values.get_real("min_width");
    const double max_width = values.get_real("max_width");
    const int widths = values.get_int("widths");
    const double min_angle = values.get_real("min_angle_deg");
    const double max_angle = values.get_real("max_angle_deg");
    const int angles = values.get_int("angles");
    const double bend = values.get_real("bend");
    if (!(max_width >= min_width)) {
        throw InputError(fmt::format(
            "pattern 'crescents': max_width={} is less than min_width={}; need min_width <= "
            "max_width",
            format_real(max_width), format_real(min_width)));
    }
    Scene scene = begin_pattern_scene("crescents", values, width, height);
    const double cell_w = static_cast<double>(width) / widths;
    const double cell_h = static_cast<double>(height) / angles;
    const double chord = kChordFraction * std::min(cell_w, cell_h);
    for (int row = 0; row < angles; ++row) {
        const double angle_deg =
            angles == 1 ? min_angle : min_angle + (max_angle - min_angle) * row / (angles - 1);
        const double a = angle_deg * std::numbers::pi / 180.0;
        const Point d{std::cos(a), std::sin(a)}, n{-std::sin(a), std::cos(a)};
        for (int col = 0; col < widths; ++col) {
            const double w = widths == 1
                                 ? min_width
                                 : min_width * std::pow(max_width / min_width,
                                                        static_cast<double>(col) / (widths - 1));
            const Point m{(col + 0.5) * cell_w + kOffGridOffsetPx.x,
                          (row + 0.5) * cell_h + kOffGridOffsetPx.y};
            auto at = [&](double along, double across) {
                return Point{m.x + along * d.x + across * n.x, m.y + along * d.y + across * n.y};
            };
            // The arc bulges to -n; its copy lies w further along +n.
            const double off = -2.0 * bend * chord;
            const Point a0 = at(-0.5 * chord, 0.0), b0 = at(0.5 * chord, 0.0);
            const Point a1 = at(-0.5 * chord, w), b1 = at(0.5 * chord, w);
            Shape shape = bezier_shape({{quad_segment(a0, at(0.0, off), b0), line_segment(b0, b1),
                                         quad_segment(b1, at(0.0, off + w), a1),
                                         line_segment(a1, a0)}},
                                       1.0);
            scene.thin_objects.push_back(
                {fmt::format("crescent w={:.3g} a={:.3g}°", w, angle_deg), shape});
            scene.shapes.push_back(std::move(shape));
        }
    }
    set_focus(scene, 0.5 * cell_w, 0.5 * cell_h, kFocusSidePx);  // the thinnest, flattest
    return scene;
}

}  // namespace

PatternInfo crescents_pattern() {
    return PatternInfo{
        "crescents",
        "thin curved strips, 0.05 to 1.5 px wide, quadratic sides; thin objects vanishing on "
        "curves",
        // clang-format off
        {
            {"min_width", ParamKind::kReal, 0.05, 0.001, 100, {},
             "width of the narrowest crescent in px; a twentieth of a pixel, which point "
             "sampling misses almost everywhere"},
            {"max_width", ParamKind::kReal, 1.5, 0.001, 100, {},
             "width of the widest crescent in px: wider than a pixel, edges only"},
            {"widths", ParamKind::kInt, 8, 1, 64, {},
             "number of widths (columns), spaced geometrically"},
            {"min_angle_deg", ParamKind::kReal, 3, -180, 180, {},
             "chord angle of the first row in degrees from the x axis (y down)"},
            {"max_angle_deg", ParamKind::kReal, 87, -180, 180, {},
             "chord angle of the last row in degrees"},
            {"angles", ParamKind::kInt, 3, 1, 64, {},
             "number of angles (rows), evenly spaced; 3 gives 3, 45, 87 degrees"},
            {"bend", ParamKind::kReal, 0.2, 0.0, 1.0, {},
             "the arc's sagitta as a fraction of its chord; 0.2 turns its tangent by 39 degrees "
             "at each end"},
        },
        // clang-format on
        generate_crescents,
        /*in_default_run=*/true,
        /*bezier=*/true,
    };
}

}  // namespace aabench
