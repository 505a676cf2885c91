// `zoneplate`: a binary zone plate, concentric rings (value 1 on background 0) whose spatial
// frequency grows linearly with the radius, from far below the Nyquist limit at the centre to
// past it at the outer edge.
//
// Aliasing it provokes: moiré, as a function of frequency in one picture. Inside the Nyquist
// radius a good method draws clean rings; past it the rings cannot be represented and every
// method either greys them out (a good filter) or folds them back into false rings centred
// elsewhere (point sampling, narrow filters). Because the frequency sweeps continuously, where
// the false rings start and how strong they are is a direct reading of a method's frequency
// response, in every direction at once.
//
// Geometry: the phase pi*r^2/c has zone boundaries (phase = k*pi) at r_k = sqrt(k*c) and local
// frequency r/c cycles/px, so Nyquist (0.5 cycles/px, a zone 1 px wide) is reached at
// r = c/2; c is chosen to put that at nyquist_radius. Zones [r_2k, r_2k+1] are filled, the
// first being the disc r <= sqrt(c); the outermost filled zone is cut at max_radius (and
// dropped if that leaves less than kMinZonePx). Each filled zone is an outer circle,
// counter-clockwise (positive shoelace area), and an inner circle, clockwise; zones are
// disjoint, so nonzero winding fills exactly them. All contours make one shape.
//
// Parameters:
//   nyquist_radius  0.6     fraction of half the smaller side where rings reach Nyquist
//   max_radius      0.98    fraction of half the smaller side; at the defaults the
//                           frequency there is 1.63x Nyquist (zones 0.61 px wide)
//   cx, cy          0.5012, 0.4987  centre as fractions of width and height (off the grid)
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

Scene generate_zoneplate(const ParamValues& values, int width, int height) {
    const double half_side = 0.5 * std::min(width, height);
    const double nyquist_radius_px = values.get_real("nyquist_radius") * half_side;
    const double max_radius_px = values.get_real("max_radius") * half_side;
    const double cx = values.get_real("cx") * width;
    const double cy = values.get_real("cy") * height;
    // Local frequency r/c reaches 0.5 cycles/px at r = c/2.
    const double c = 2.0 * nyquist_radius_px;
    // Zone widths r_k+1 - r_k = c/(r_k+1 + r_k) shrink with the radius; every zone inside
    // max_radius is at least c/(2*max_radius) wide.
    const double narrowest_zone = c / (2.0 * max_radius_px);
    if (!(narrowest_zone >= kMinZonePx)) {
        throw InputError(fmt::format(
            "pattern 'zoneplate': zones at max_radius are {} px wide, below {} px (the circle "
            "tolerance); increase nyquist_radius or reduce max_radius",
            format_real(narrowest_zone), format_real(kMinZonePx)));
    }

    Scene scene = begin_pattern_scene("zoneplate", values, width, height);
    // Boundaries from their index directly (not accumulated): r_j = sqrt(j*c).
    Shape shape = concentric_annuli(
        cx, cy,
        [&](long long k) {
            const double outer = std::sqrt(static_cast<double>(2 * k + 1) * c);
            return std::pair<double, double>{std::sqrt(static_cast<double>(2 * k) * c),
                                             std::min(outer, max_radius_px)};
        },
        kMinZonePx, "zoneplate", "increase nyquist_radius or reduce max_radius or the size");
    if (!shape.contours.empty()) scene.shapes.push_back(std::move(shape));
    // The outer zones, past Nyquist, on the right of the centre.
    set_focus(scene, cx + 0.85 * max_radius_px, cy, kFocusSidePx);
    return scene;
}

}  // namespace

PatternInfo zoneplate_pattern() {
    return PatternInfo{
        "zoneplate",
        "binary zone plate: ring frequency grows with radius through Nyquist; moire",
        // One row per parameter: name, kind, default, min, max, choices, doc.
        // clang-format off
        {
            {"nyquist_radius", ParamKind::kReal, 0.6, 0.05, 10, {},
             "radius where the rings reach 0.5 cycles/px, as a fraction of half the smaller "
             "side; 0.6 leaves most of the plate resolvable and a wide band past Nyquist"},
            {"max_radius", ParamKind::kReal, 0.98, 0.01, 10, {},
             "outer radius as a fraction of half the smaller side; 0.98 keeps the plate "
             "inside the image and goes to 1.63x Nyquist with the default nyquist_radius"},
            {"cx", ParamKind::kReal, 0.5012, -10, 10, {},
             "centre x as a fraction of the width; 0.5012 keeps the centre off the grid at "
             "every size"},
            {"cy", ParamKind::kReal, 0.4987, -10, 10, {},
             "centre y as a fraction of the height; 0.4987, off the grid like cx"},
        },
        // clang-format on
        generate_zoneplate,
    };
}

}  // namespace aabench
