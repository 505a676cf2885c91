// Private to taa (methods/taa.cpp): the colour space of its neighbourhood box and the two ways
// a history colour is brought into that box. Exposed for tests/taa_colour_test.cpp only.
//
// YCoCg (Malvar & Sullivan's YCoCg, the space Karis 2014 clamps in):
//     Y  =  R/4 + G/2 + B/4        R = Y + Co - Cg
//     Co =  R/2       - B/2        G = Y      + Cg
//     Cg = -R/4 + G/2 - B/4        B = Y - Co - Cg
// Every coefficient is a power of two, so on a grey colour (R = G = B = v, v a float) the
// forward transform is exact in double (3v/4 needs 26 bits) and gives (v, 0, 0), and the
// inverse gives v back exactly: a colour sequence of grey colours is the grey sequence.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace aabench::taa_colour {

using Vec3 = std::array<double, 3>;

inline Vec3 to_ycocg(const Vec3& rgb) {
    return {0.25 * rgb[0] + 0.5 * rgb[1] + 0.25 * rgb[2], 0.5 * rgb[0] - 0.5 * rgb[2],
            -0.25 * rgb[0] + 0.5 * rgb[1] - 0.25 * rgb[2]};
}

inline Vec3 from_ycocg(const Vec3& ycocg) {
    return {ycocg[0] + ycocg[1] - ycocg[2], ycocg[0] + ycocg[2], ycocg[0] - ycocg[1] - ycocg[2]};
}

// An axis-aligned box of the colour space: [lo[k], hi[k]] per component.
struct Box3 {
    Vec3 lo, hi;
};

// The per-component clamp (clamp=minmax, and clamp=variance on its mu +- gamma sigma box).
inline Vec3 clamp_to_box(const Vec3& h, const Box3& box) {
    return {std::clamp(h[0], box.lo[0], box.hi[0]), std::clamp(h[1], box.lo[1], box.hi[1]),
            std::clamp(h[2], box.lo[2], box.hi[2])};
}

// Karis 2014's clip_aabb: the point where the segment from the box's centre to `h` leaves the
// box, or `h` inside it. The segment is centre + t (h - centre), and t = min over the
// components outside their half extent of half_extent / |offset| (a component inside has a
// ratio >= 1 and does not bind). A flat component (half extent 0) with an offset gives t = 0:
// the centre, the only point of the segment in a box of zero width there. On a colour whose
// only offset is in one component the result is centre + offset (half_extent / |offset|), the
// one-channel formula of taa.cpp term for term, so a grey colour clips as the grey image does.
// Unlike the clamp it keeps the history's hue relative to the centre: in colour the two differ
// whenever more than one component is outside, or one is outside and another is not at the
// centre.
inline Vec3 clip_to_box(const Vec3& h, const Box3& box) {
    Vec3 centre{}, half{}, offset{};
    bool inside = true;
    for (int k = 0; k < 3; ++k) {
        centre[k] = 0.5 * (box.lo[k] + box.hi[k]);
        half[k] = 0.5 * (box.hi[k] - box.lo[k]);
        offset[k] = h[k] - centre[k];
        // Written so that NaN counts as outside (and then propagates, as on one channel).
        if (!(std::abs(offset[k]) <= half[k])) inside = false;
    }
    if (inside) return h;
    double t = 1.0;
    for (int k = 0; k < 3; ++k) {
        if (std::abs(offset[k]) > half[k]) t = std::min(t, half[k] / std::abs(offset[k]));
    }
    return {centre[0] + offset[0] * t, centre[1] + offset[1] * t, centre[2] + offset[2] * t};
}

}  // namespace aabench::taa_colour
