// `rings`: concentric annuli (value 1 on background 0) of constant radial period around an
// off-grid centre.
//
// Aliasing it provokes: moiré and jagged curves. A ring pattern contains its period in every
// direction at once, so where the period meets the pixel grid the aliases form the familiar
// circular moiré "ghost rings" off the centre, symmetric in four quadrants; at larger periods
// it shows how evenly a method renders curved edges at every slope.
//
// Annulus k covers k*period <= r <= (k + duty)*period from the centre, up to max_radius; the
// innermost one (k = 0) is a disc. The outermost annulus is cut at max_radius (and dropped if
// that leaves less than kMinZonePx). Each annulus is an outer circle, counter-clockwise
// (positive shoelace area), and an inner circle, clockwise; the annuli are disjoint, so under
// nonzero winding a point gets +1 - 1 = 0 from every annulus it is not inside and 1 from the
// one it is in. All contours make one shape.
//
// Parameters:
//   period      2.6     px, radial distance from one annulus to the next
//   duty        0.5     fraction of the period that is filled
//   cx, cy      0.5012, 0.4987  centre as fractions of width and height (off the grid)
//   max_radius  0.95    fraction of half the smaller side
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "patterns/pattern.h"

namespace aabench {

namespace {

// Every filled and empty zone must be at least this wide. A polygonised circle lies within
// kMaxSagittaPx inside its true circle, so two circles further apart than that can never
// cross (a crossing would make the winding number -1 somewhere, and nonzero fill it);
// twice the tolerance leaves room for rounding.
constexpr double kMinZonePx = 2.0 * kMaxSagittaPx;

Scene generate_rings(const ParamValues& values, int width, int height) {
    const double period = values.get_real("period");
    const double duty = values.get_real("duty");
    const double cx = values.get_real("cx") * width;
    const double cy = values.get_real("cy") * height;
    const double max_radius_px = values.get_real("max_radius") * 0.5 * std::min(width, height);
    const double narrowest_zone = std::min(duty, 1.0 - duty) * period;
    if (!(narrowest_zone >= kMinZonePx)) {
        throw InputError(fmt::format(
            "pattern 'rings': period={} with duty={} makes zones {} px wide, below {} px (the "
            "circle tolerance); increase period or bring duty towards 0.5",
            format_real(period), format_real(duty), format_real(narrowest_zone),
            format_real(kMinZonePx)));
    }

    Scene scene = begin_pattern_scene("rings", values, width, height);
    // Radii from k directly (not accumulated) so the period stays exact to rounding.
    Shape shape = concentric_annuli(
        cx, cy,
        [&](long long k) {
            return std::pair<double, double>{k * period,
                                             std::min((k + duty) * period, max_radius_px)};
        },
        kMinZonePx, "rings", "increase period or reduce max_radius or the size");
    if (!shape.contours.empty()) scene.shapes.push_back(std::move(shape));
    set_focus(scene, cx, cy, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo rings_pattern() {
    return PatternInfo{
        "rings",
        "concentric annuli of constant period; circular moire and curved edges",
        // One row per parameter: name, kind, default, min, max, choices, doc.
        // clang-format off
        {
            {"period", ParamKind::kReal, 2.6, 0.05, 100000, {},
             "radial distance in px from one annulus to the next; 2.6 is below Nyquist, so a "
             "good method resolves it, but its square-wave harmonics are not, so point "
             "sampling shows moire"},
            {"duty", ParamKind::kReal, 0.5, 0.01, 0.99, {},
             "fraction of each period that is filled; 0.5 gives equal rings and gaps"},
            {"cx", ParamKind::kReal, 0.5012, -10, 10, {},
             "centre x as a fraction of the width; 0.5012 keeps the centre off the grid at "
             "every size"},
            {"cy", ParamKind::kReal, 0.4987, -10, 10, {},
             "centre y as a fraction of the height; 0.4987, off the grid like cx"},
            {"max_radius", ParamKind::kReal, 0.95, 0.01, 10, {},
             "outer radius as a fraction of half the smaller side; 0.95 keeps every ring "
             "inside the image with the off-grid centre"},
        },
        // clang-format on
        generate_rings,
    };
}

}  // namespace aabench
