// Exact radial-filter references by reduction to the jump set of the visible value.
//
// What it computes. For the pixel centre c = (i + 0.5, j + 0.5) and a radial filter f of
// support radius R with 2 pi * integral_0^R f(s) s ds = 1, the value
//     I(c) = integral over the plane of f(|p - c|) v(p) dA,
// where v is the visible value (shapes in order, each by nonzero winding, the later on top).
//
// The reduction. Write I in polar form about c and integrate each ray by parts. With
//     F(r) = integral_0^min(r, R) f(s) s ds        (closed form; F(R) = 1 / (2 pi))
// a ray in direction theta along which v starts at v0(theta) and jumps by dv_k at r_k gives
//     integral_0^R f(r) v r dr = v0(theta) F(R) + sum_k dv_k (F(R) - F(r_k))   (r_k < R).
// Summing over theta turns the jumps into integrals along the jump set of v (the segments
// where v is discontinuous, methods/scan/reference/visible_boundary.h): for a jump segment s with
// weight w_s (v on its right-hand side minus v on its left, see JumpSegment)
//     I(c) = vbar(c) + sum_s w_s * integral_s (F(r) - F(R)) dtheta,
//     dtheta = cross(p - c, dp) / r^2,
// and vbar(c) = (1 / 2 pi) integral v0(theta) dtheta, the average of v around c. F(r) - F(R)
// vanishes for r >= R, so only the parts of segments inside the disc count: each segment is
// clipped where it crosses the support circle, and a segment reaches only the centres within
// R of it. Occlusion is honoured because the jump set is that of v itself: a hidden edge is
// not in it, and where a later shape covers part of an earlier one the jump is between the
// values actually seen.
//
// The angular integral. On the line of a segment, with d the signed distance from c and t the
// position along the line (r^2 = d^2 + t^2, dtheta = d dt / r^2),
//     integral (F(r) - F(R)) dtheta = d * integral H(r) dt - F(R) * dtheta_total,
//     H(r) = F(r) / r^2,
// where dtheta_total is the angle the clipped segment subtends (atan2, exact). Integrating in
// t rather than theta matters: when the segment passes close to c, F(r(theta)) is nearly a
// step at the ends of the angular range, while H is smooth in t (entire for the Gaussian,
// H(r) = (A / 2) (1 - exp(-u)) / u with u = r^2 / (2 sigma^2)). For the cone H = c (1/2 -
// r / (3R)) and integral r dt has a closed form, so the cone needs no quadrature at all. For
// the Gaussian, where exp(-u) < 4e-18 (u > 40) H is 1 / u to double precision and its integral
// is again an angle; the rest (|t| <= sqrt(80) sigma) is integrated by 10-point
// Gauss-Legendre on pieces no longer than 2 sigma. The integrand is entire and grows at most
// like exp(y^2 / (2 sigma^2)) off the real axis, so the Bernstein-ellipse bound of a piece of
// length 2 sigma gives ~1e-15 relative; measured against a long-double reference over 20000
// random (sigma, R, d, t) it is <= 2e-16 per segment (docs/references.md).
//
// The average around c. If c is on no jump segment, vbar(c) = v(c). We take the value in the
// direction just below the ray to the right (theta = 0+; y grows down): v0(0+) = background +
// sum of the jumps (right minus left) of the non-horizontal segments that span c's height
// (a.y <= c.y < b.y, so the band just below c) and have c on their right or on them. Segments
// through c count as left of that direction; a horizontal one at c's height does not. Segments
// that touch c (c on the segment, cross product exactly zero) are rays from c, of no angular
// extent; they change v0 by their outward weight w as theta passes their angle phi, so
//     vbar(c) = v0(0+) + sum over rays w_out (1 - phi / (2 pi)),   phi in (0, 2 pi].
// A half-plane through c gets 1/2, a right-angle corner at c gets 1/4, a vertex where spokes
// meet gets the angle-weighted average, as the integral demands: the integral does not care
// about v at the single point c, so there is no tie rule to choose, only one to compute.
//
// Consistency at the centre. The side of c on which a segment lies is decided once, by the
// sign of cross(a - c, b - c) in floating point, and used for both v0(0+) and the segment's
// angle, so a segment passing within rounding of c is seen on one side by both (an answer
// for a point 1e-16 away, which differs by ~1e-16). v0 is computed for a whole row by a
// difference array from the x where each spanning segment crosses c's height; for centres
// within R of the segment (the only ones where x and cross could disagree) the difference is
// corrected to the cross-product side in the scatter loop below. The mathematics of this file
// (the reduction, the line integrals, the centre average) is its own, shared with no method it
// scores: that independence is the point of a reference. Only the difference array of v0 is
// the kernel's cell row (methods/scan/kernel/cells.h), summed in order.
//
// Cost. The jump set is built over the rows within R of the image (plus one) by the band
// sweep, O(edges x rows they cross); each segment is scattered to the centres within R of its
// bounding box, O(jump-set length x (2R + 1)^2) pairs, each a few atan2 plus, for the
// Gaussian, 10 exp per 2 sigma of chord (20 at the defaults, at most 90); then O(pixels).
// Memory O(pixels): segments are consumed as the sweep produces them.
#include "harness/reference/filter_reference.h"

#include "harness/reference/bezier_filter_reference.h"
#include "harness/reference/box_reference.h"
#include "harness/reference/curve_filter_reference.h"
#include "patterns/scene/bezier.h"
#include "patterns/scene/curves.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "methods/scan/kernel/cells.h"
#include "methods/scan/reference/visible_boundary.h"
#include "patterns/scene/params.h"

namespace aabench {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kInvTwoPi = 1.0 / kTwoPi;

// Beyond u = r^2 / (2 sigma^2) = 40, exp(-u) < 4.3e-18: the Gaussian's H is 1/u to double
// precision, and its integral is an angle.
constexpr double kGaussianCoreU = 40.0;
// Gauss-Legendre pieces no longer than this many sigma (measured error <= 2e-16 per segment
// at 2; 1e-14 at 3, 3e-12 at 4).
constexpr double kGaussianPieceSigmas = 2.0;

// 10-point Gauss-Legendre on [-1, 1]: nodes +-x_k and weights w_k (Newton on P_10 in long
// double, rounded; they match Abramowitz & Stegun table 25.4).
constexpr double kGlNodes[5] = {0.97390652851717174, 0.86506336668898454, 0.67940956829902444,
                                0.43339539412924721, 0.14887433898163122};
constexpr double kGlWeights[5] = {0.066671344308688138, 0.14945134915058059, 0.21908636251598204,
                                  0.26926671930999635, 0.29552422471475287};

// The chord integrals of a radial filter (the angular integral above), from its closed forms
// (methods/scan/kernel/filter.h): the Gaussian f = A exp(-r^2 / (2 s^2)), F = A s^2 (1 -
// exp(-r^2 / (2 s^2))); the cone f = c (1 - r / R), F = c (r^2 / 2 - r^3 / (3R)).
class RadialKernel {
public:
    explicit RadialKernel(const Filter& filter)
        : gaussian_(filter.kind() == FilterKind::kGaussian),
          radius_(filter.radius_px()),
          sigma_(filter.sigma_px()),
          inv_two_sigma2_(filter.inv_two_sigma2()),
          a_sigma2_(filter.amplitude_sigma2()),
          amplitude_(filter.amplitude()) {}

    // d * integral_tp^tq H(sqrt(d^2 + t^2)) dt, H = F / r^2, for a chord inside the disc.
    double line_integral(double d, double tp, double tq) const {
        return gaussian_ ? gaussian_line(d, tp, tq) : cone_line(d, tp, tq);
    }

private:
    double cone_line(double d, double tp, double tq) const {
        // H = c (1/2 - r / (3R)), and integral r dt is distance_line_integral.
        const double sq = distance_line_integral(tq, d), sp = distance_line_integral(tp, d);
        return d * amplitude_ * (0.5 * (tq - tp) - (sq - sp) / (3.0 * radius_));
    }

    double gaussian_line(double d, double tp, double tq) const {
        // Tails where u > kGaussianCoreU: d * (A/2) * integral 1/u dt = A s^2 * angle.
        const double core2 = kGaussianCoreU / inv_two_sigma2_ - d * d;
        if (core2 <= 0.0) return a_sigma2_ * (std::atan2(-d, tq) - std::atan2(-d, tp));
        const double core = std::sqrt(core2);
        double tail = 0.0, lo = tp, hi = tq;
        if (lo < -core) {
            const double end = std::min(hi, -core);
            tail += std::atan2(-d, end) - std::atan2(-d, lo);
            lo = end;
        }
        if (hi > core) {
            const double start = std::max(lo, core);
            tail += std::atan2(-d, hi) - std::atan2(-d, start);
            hi = start;
        }
        double sum = 0.0;
        if (hi > lo) {
            const int pieces = std::max(
                1, static_cast<int>(std::ceil((hi - lo) / (kGaussianPieceSigmas * sigma_))));
            const double half = 0.5 * (hi - lo) / pieces;
            const double d2 = d * d;
            for (int k = 0; k < pieces; ++k) {
                const double mid = lo + (2 * k + 1) * half;
                double piece = 0.0;
                for (int q = 0; q < 5; ++q) {
                    const double t1 = mid + half * kGlNodes[q], t2 = mid - half * kGlNodes[q];
                    piece += kGlWeights[q] * (g((d2 + t1 * t1) * inv_two_sigma2_) +
                                              g((d2 + t2 * t2) * inv_two_sigma2_));
                }
                sum += piece * half;
            }
        }
        return d * 0.5 * amplitude_ * sum + a_sigma2_ * tail;
    }

    // (1 - exp(-u)) / u, entire; the series near 0 avoids 0/0.
    static double g(double u) { return u < 1e-8 ? 1.0 - 0.5 * u : -std::expm1(-u) / u; }

    bool gaussian_;
    double radius_, sigma_;
    double inv_two_sigma2_;
    double a_sigma2_;   // A sigma^2 (Gaussian)
    double amplitude_;  // A (Gaussian) or c (cone): f(0)
};

// The share of the circle after the ray's angle phi in (0, 2 pi] (theta measured from +x
// towards +y): how much of vbar a jump on that ray carries.
double ray_share(double x, double y) {
    double phi = std::atan2(y, x);
    if (phi <= 0.0) phi += kTwoPi;
    return 1.0 - phi * kInvTwoPi;
}

class FilterAccumulator {
public:
    // The segment integrals accumulate in `out` (zeroed), which resolve() completes.
    FilterAccumulator(const Filter& filter, Coverage& out)
        : kernel_(filter),
          radius_(filter.radius_px()),
          radius2_(filter.radius_px() * filter.radius_px()),
          width_(out.width),
          height_(out.height),
          acc_(out),
          v0_rows_(static_cast<std::size_t>(height_)),
          v0_(static_cast<std::size_t>(width_)) {
        for (V0Row& row : v0_rows_) row.reset(width_);
    }

    void add(const JumpSegment& s) {
        Span span{-1, width_, 0.0};
        if (s.a.y < s.b.y) span = spanning(s);
        if (span.row >= 0 && span.first_left < width_) {
            v0_rows_[static_cast<std::size_t>(span.row)].writer().add(
                static_cast<std::size_t>(span.first_left), span.jump);
        }
        // Centres within R of the segment's bounding box (clamped in double: coordinates may
        // be far outside the image).
        const double ymin = std::min(s.a.y, s.b.y), ymax = std::max(s.a.y, s.b.y);
        const double xmin = std::min(s.a.x, s.b.x), xmax = std::max(s.a.x, s.b.x);
        const int j0 = first_index(ymin - radius_ - 0.5, height_);
        const int j1 = last_index(ymax + radius_ - 0.5, height_);
        const int i0 = first_index(xmin - radius_ - 0.5, width_);
        const int i1 = last_index(xmax + radius_ - 0.5, width_);
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                acc_.at(i, j) += contribution(s, i, j, span);
            }
        }
    }

    // Adds background + v0 corrections (row prefix sums, in order) to the segment integrals.
    void resolve(double background) {
        for (int j = 0; j < height_; ++j) {
            v0_rows_[static_cast<std::size_t>(j)].resolve_and_clear(
                background, v0_.data(), [](std::size_t, double v0) { return v0; });
            for (int i = 0; i < width_; ++i) acc_.at(i, j) += v0_[static_cast<std::size_t>(i)];
        }
    }

private:
    // A non-horizontal segment spans at most one centre row (it lies inside one pixel row).
    // From column first_left on, the difference array counts it as left of the centre.
    struct Span {
        int row;
        int first_left;
        double jump;  // v right minus v left
    };

    // The first index >= v and the last index <= v, clamped to [0, n) in double first.
    static int first_index(double v, int n) {
        return static_cast<int>(std::clamp(std::ceil(v), 0.0, static_cast<double>(n)));
    }
    static int last_index(double v, int n) {
        return static_cast<int>(std::clamp(std::floor(v), -1.0, n - 1.0));
    }

    Span spanning(const JumpSegment& s) const {
        // The centre row j with a.y <= j + 0.5 < b.y, if any.
        double j = std::ceil(s.a.y - 0.5);
        if (j + 0.5 < s.a.y) j += 1.0;  // a.y - 0.5 is inexact for |a.y| < 1
        if (j - 0.5 >= s.a.y) j -= 1.0;
        if (!(j + 0.5 < s.b.y) || j < 0.0 || j >= height_) return {-1, width_, 0.0};
        const double cy = j + 0.5;
        // The fraction first: (cy - a.y) (b.x - a.x) overflows for segments 1e300 px long.
        const double x = s.a.x + ((cy - s.a.y) / (s.b.y - s.a.y)) * (s.b.x - s.a.x);
        // Any column within one of the true crossing will do: centres that close are within
        // R of the segment, and their side is settled by the cross product in contribution().
        const double first = std::clamp(std::ceil(x - 0.5), 0.0, static_cast<double>(width_));
        return {static_cast<int>(j), static_cast<int>(first), -s.weight};
    }

    double contribution(const JumpSegment& s, int i, int j, const Span& span) const {
        const double cx = i + 0.5, cy = j + 0.5;
        const double ax = s.a.x - cx, ay = s.a.y - cy, bx = s.b.x - cx, by = s.b.y - cy;
        const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
        // cross(a - c, b - c) = cross(b - a, c - a): > 0 when c is on the segment's
        // right-hand side (for a downward segment: left of it in x). Exactly 0 when c is an
        // endpoint or the segment is axis-parallel through c.
        double cr = ax * by - ay * bx;
        const double len2 = dx * dx + dy * dy;
        double len = std::sqrt(len2);
        double d = cr / len;  // signed distance; dtheta = d dt / r^2
        double ta = (ax * dx + ay * dy) / len, tb = (bx * dx + by * dy) / len;
        if (!(std::isfinite(d) && std::isfinite(ta) && std::isfinite(tb))) {
            // Products of two coordinates overflow for segments 1e154 px long and more (found
            // by the render fuzzer: a segment 1e300 px long came out as NaN and was dropped).
            // The same along the unit direction, which cannot overflow.
            len = std::hypot(dx, dy);
            const double ux = dx / len, uy = dy / len;
            d = ax * uy - ay * ux;
            cr = d;  // only its sign and zero are used below
            ta = ax * ux + ay * uy;
            tb = bx * ux + by * uy;
        }
        double out = 0.0;
        if (j == span.row) {
            // v0(0+) counts this segment when c is right of it or on it (cr <= 0); the
            // difference array decided by x. Where they disagree (within rounding of the
            // segment), the cross product wins, to agree with the angle below.
            const bool left_by_x = i >= span.first_left;
            const bool left_by_cross = cr <= 0.0;
            if (left_by_cross && !left_by_x) out += span.jump;
            if (!left_by_cross && left_by_x) out -= span.jump;
        }
        if (cr == 0.0) {
            // On the segment's line: no angle. If c is on the segment itself, the segment is
            // one or two rays from c, which shape vbar(c).
            if (ta <= 0.0 && tb >= 0.0) {
                if (ax != 0.0 || ay != 0.0) out -= s.weight * ray_share(ax, ay);
                if (bx != 0.0 || by != 0.0) out += s.weight * ray_share(bx, by);
            }
            return out;
        }
        if (!(std::abs(d) < radius_)) return out;  // the line misses the disc
        // Split where the segment crosses the support circle: F(r) - F(R) = 0 outside.
        const double half_chord = std::sqrt(radius2_ - d * d);
        const double tp = std::max(ta, -half_chord), tq = std::min(tb, half_chord);
        if (!(tp < tq)) return out;
        const double angle = std::atan2(-d, tq) - std::atan2(-d, tp);
        return out + s.weight * (kernel_.line_integral(d, tp, tq) - angle * kInvTwoPi);
    }

    RadialKernel kernel_;
    double radius_, radius2_;
    int width_, height_;
    Coverage& acc_;
    // v0(0+) of each centre row as steps along it: the kernel cell row (its prefix sum, not
    // its piece arithmetic: methods/scan/kernel/cells.h), one per row.
    using V0Row = CellRow<double, 8>;
    std::vector<V0Row> v0_rows_;
    std::vector<double> v0_;  // one row of v0, resolved
};

}  // namespace

Coverage filtered_reference(const Scene& scene, const Filter& filter) {
    if (filter.is_box()) throw std::invalid_argument("filtered_reference: the box is not radial");
    require_window_frame(scene, "filtered reference");
    // Discs and rings: the closed form per curve, the other shapes (polygons or Bezier
    // segments) through this function again.
    if (has_curves(scene) && !has_planes(scene)) return curve_filtered_reference(scene, filter);
    if (has_bezier(scene)) {  // Bezier segments: the band sweep's pieces, not the flattening
        if (has_planes(scene)) {
            throw InputError(
                "filtered reference: a scene with Bezier segments has no depth planes or "
                "affine values yet");
        }
        return bezier_filtered_reference(scene, filter);
    }
    if (has_curves(scene)) return curve_filtered_reference(scene, filter);  // discs, rings
    Coverage out(scene.width, scene.height, 0.0);
    if (scene.width <= 0 || scene.height <= 0) return out;
    const double radius = filter.radius_px();
    // The centres lie in [0.5, H - 0.5]; their discs reach R further. One spare row on each
    // side keeps the sweep's own start and stop (reported as jumps from the background) out
    // of every disc.
    const int row_lo = static_cast<int>(std::floor(0.5 - radius)) - 1;
    const int row_hi = static_cast<int>(std::ceil(scene.height - 0.5 + radius)) + 1;
    const double x_lo = 0.5 - radius - 1.0, x_hi = scene.width - 0.5 + radius + 1.0;
    FilterAccumulator acc(filter, out);
    for_each_jump_segment(scene, row_lo, row_hi, x_lo, x_hi,
                          [&](const JumpSegment& s) { acc.add(s); });
    acc.resolve(scene.background);
    return out;
}

std::string canonical_reference_spec(const std::string& filter_spec) {
    return Filter::parse(filter_spec).text();
}

Coverage exact_reference(const SceneInput& in, const Filter& filter) {
    if (filter.is_box()) return box_reference(in);
    return filtered_reference(in.scene(), filter);
}

CoveragePlanes exact_reference_planes(const SceneInput& in, const Filter& filter) {
    if (in.scene().channels == 1) return CoveragePlanes(exact_reference(in, filter));
    CoveragePlanes planes;
    for (int c = 0; c < in.scene().channels; ++c) {
        std::optional<Scene> made;
        planes.planes.push_back(exact_reference(channel_input(in, c, made), filter));
    }
    return planes;
}

Coverage exact_reference(const SceneInput& in, const std::string& filter_spec) {
    return exact_reference(in, Filter::parse(filter_spec));
}

}  // namespace aabench
