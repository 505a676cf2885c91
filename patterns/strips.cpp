// `strips`: a grid of thin straight strips (value 1 on background 0), one column per width and
// one row per angle.
//
// Aliasing it provokes: strips narrower than a pixel vanish or break into dashes under point
// sampling (Nishita & Nakamae's "small and thin objects vanishing"); wider ones show jagged
// edges. Near-horizontal and near-vertical strips are the hardest: they run along a pixel row
// or column for a long way, so a sampler either misses them over a long stretch or steps
// them in long runs. A correct method keeps each strip's total ink (width x length) at every
// width and angle.
//
// Widths are spaced geometrically from min_width to max_width (columns, left to right);
// angles evenly from min_angle_deg to max_angle_deg (rows, top to bottom), measured from the
// x axis towards +y (down). Strip (row, column) is shape number row * widths + column: a
// rectangle of its width, centred at its cell's centre plus kOffGridOffsetPx, along
// (cos a, sin a), of length kLengthFraction x the longest centred segment at that angle that
// fits in the cell. At the defaults the cells are large enough that every strip stays inside
// its cell; in very small images (e.g. 16x16) strips may poke into a neighbouring cell or past
// the image edge, which methods clip.
//
// Thin objects (Scene::thin_objects, measured for captured mass and popping): every strip, in
// shape order, labelled "strip w=<width px> a=<angle deg>°" (3 significant digits).
//
// Parameters:
//   min_width      0.05  px, narrowest strip (1/20 of a pixel: must not vanish)
//   max_width      1.5   px, widest strip (wider than a pixel: edges only)
//   widths         8     number of widths (columns)
//   min_angle_deg  1     degrees, first row: near-horizontal
//   max_angle_deg  89    degrees, last row: near-vertical
//   angles         5     number of angles (rows): 1, 23, 45, 67, 89 at the defaults
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "patterns/pattern.h"

namespace aabench {

namespace {

// Added to each cell centre so no strip centre or edge lines up with the pixel grid whatever
// the cell size (irrational-looking fractions of a pixel: 1/pi and e/10).
constexpr Point kOffGridOffsetPx = {0.3183, 0.2719};
// Strip length as a fraction of the longest centred segment that fits in its cell: leaves a
// margin so strips in neighbouring cells stay apart and each end is seen on its own.
constexpr double kLengthFraction = 0.8;

Scene generate_strips(const ParamValues& values, int width, int height) {
    const double min_width = values.get_real("min_width");
    const double max_width = values.get_real("max_width");
    const int widths = values.get_int("widths");
    const double min_angle_deg = values.get_real("min_angle_deg");
    const double max_angle_deg = values.get_real("max_angle_deg");
    const int angles = values.get_int("angles");
    if (!(max_width >= min_width)) {
        throw InputError(fmt::format(
            "pattern 'strips': max_width={} is less than min_width={}; need min_width <= "
            "max_width",
            format_real(max_width), format_real(min_width)));
    }
    if (!(max_angle_deg >= min_angle_deg)) {
        throw InputError(
            fmt::format("pattern 'strips': max_angle_deg={} is less than min_angle_deg={}; need "
                        "min_angle_deg <= max_angle_deg",
                        format_real(max_angle_deg), format_real(min_angle_deg)));
    }

    Scene scene = begin_pattern_scene("strips", values, width, height);
    const double cell_w = static_cast<double>(width) / widths;
    const double cell_h = static_cast<double>(height) / angles;
    scene.shapes.reserve(static_cast<std::size_t>(widths) * angles);
    scene.thin_objects.reserve(scene.shapes.capacity());
    for (int row = 0; row < angles; ++row) {
        const double angle_deg =
            angles == 1 ? min_angle_deg
                        : min_angle_deg + (max_angle_deg - min_angle_deg) * row / (angles - 1);
        const double angle = angle_deg * std::numbers::pi / 180.0;
        const double c = std::cos(angle);
        const double s = std::sin(angle);
        // Longest segment centred in the cell along (c, s): it ends where it first meets a
        // cell side. A zero cosine or sine never limits it (and is not divided by, so a
        // sanitizer build trapping float division by zero stays quiet).
        double fit_length = std::numeric_limits<double>::infinity();
        if (c != 0.0) fit_length = std::min(fit_length, cell_w / std::abs(c));
        if (s != 0.0) fit_length = std::min(fit_length, cell_h / std::abs(s));
        const double half_length = 0.5 * kLengthFraction * fit_length;
        for (int col = 0; col < widths; ++col) {
            // Geometric spacing: each column a constant factor wider than the last, so the
            // sub-pixel range (where methods differ most) gets as many columns as the rest.
            const double strip_width =
                widths == 1 ? min_width
                            : min_width * std::pow(max_width / min_width,
                                                   static_cast<double>(col) / (widths - 1));
            const double half_width = 0.5 * strip_width;
            const double mx = (col + 0.5) * cell_w + kOffGridOffsetPx.x;
            const double my = (row + 0.5) * cell_h + kOffGridOffsetPx.y;
            // Along the strip (dx, dy), across it (nx, ny) = (-s, c) * half_width. This
            // corner order has a positive shoelace area (the circle_contour orientation).
            const double dx = c * half_length, dy = s * half_length;
            const double nx = -s * half_width, ny = c * half_width;
            Shape shape;
            shape.value = 1.0;
            shape.contours.push_back({
                {mx - dx - nx, my - dy - ny},
                {mx + dx - nx, my + dy - ny},
                {mx + dx + nx, my + dy + ny},
                {mx - dx + nx, my - dy + ny},
            });
            // Each strip is measured on its own: the strips are the pattern's thin objects.
            scene.thin_objects.push_back(
                {fmt::format("strip w={:.3g} a={:.3g}°", strip_width, angle_deg), shape});
            scene.shapes.push_back(std::move(shape));
        }
    }
    // The thinnest, most nearly horizontal strip: the first cell.
    set_focus(scene, 0.5 * cell_w, 0.5 * cell_h, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo strips_pattern() {
    return PatternInfo{
        "strips",
        "thin strips, 0.05 to 1.5 px wide, near-horizontal to near-vertical; thin objects "
        "vanishing",
        // One row per parameter: name, kind, default, min, max, choices, doc.
        // clang-format off
        {
            {"min_width", ParamKind::kReal, 0.05, 0.001, 100, {},
             "width of the narrowest strip in px; 0.05 px covers a twentieth of a pixel, "
             "which point sampling misses almost everywhere"},
            {"max_width", ParamKind::kReal, 1.5, 0.001, 100, {},
             "width of the widest strip in px; 1.5 px is wider than a pixel, where every "
             "method should see a solid line and only edges differ"},
            {"widths", ParamKind::kInt, 8, 1, 64, {},
             "number of widths (columns), spaced geometrically; 8 gives steps of about x1.6"},
            {"min_angle_deg", ParamKind::kReal, 1, -180, 180, {},
             "angle of the first row in degrees from the x axis (y down); 1 degree is "
             "near-horizontal, the worst case for row-by-row samplers"},
            {"max_angle_deg", ParamKind::kReal, 89, -180, 180, {},
             "angle of the last row in degrees; 89 is near-vertical, the same worst case "
             "for columns"},
            {"angles", ParamKind::kInt, 5, 1, 64, {},
             "number of angles (rows), evenly spaced; 5 gives 1, 23, 45, 67, 89 degrees"},
        },
        // clang-format on
        generate_strips,
    };
}

}  // namespace aabench
