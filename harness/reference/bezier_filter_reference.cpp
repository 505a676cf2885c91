// Radial filters over Bezier regions (bezier_filter_reference.h).
//
// Along the line at height y the visible value is background + the jumps of the pieces left of
// x (methods/scan/reference/bezier_sweep.h). So with f the normalised filter about the centre
// (cx, cy), its integral against v is
//
//     V = background + sum_k jump_k * integral over piece k of H(x(y) - cx, y - cy) dy,
//     H(u, w) = integral_u^inf f(s, w) ds = A (P(w, inf) - sign(u) P(w, |u|)),
//
// P(w, x) = Filter::profile_line_integral (the profile's integral along the line at distance w,
// in closed form, saturating at the support). A piece left of the whole support adds the same
// jump * integral of 2 A P(w, inf) dy to every such centre of its row (a difference array
// carries it); a piece right of it adds nothing; a piece across it is integrated in t by
// adaptive Gauss-Legendre, split where it crosses the support's circle and its rows' edges
// (where H has kinks), each part refined until halves agree within the tolerance.
#include "harness/reference/bezier_filter_reference.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "methods/scan/reference/bezier_sweep.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// 8-point Gauss-Legendre on [-1, 1].
constexpr double kX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                          0.9602898564975363};
constexpr double kW[4] = {0.3626837833783620, 0.3137066859058880, 0.2223810344533745,
                          0.1012285362903763};

template <class F>
double gauss8(const F& f, double a, double b) {
    const double m = 0.5 * (a + b), h = 0.5 * (b - a);
    double sum = 0.0;
    for (int k = 0; k < 4; ++k) sum += kW[k] * (f(m - h * kX[k]) + f(m + h * kX[k]));
    return sum * h;
}

template <class F>
double adaptive(const F& f, double a, double b, double whole, double tolerance, int depth) {
    const double m = 0.5 * (a + b);
    const double left = gauss8(f, a, m), right = gauss8(f, m, b);
    if (depth <= 0 || std::abs(left + right - whole) <= tolerance) return left + right;
    return adaptive(f, a, m, left, 0.5 * tolerance, depth - 1) +
           adaptive(f, m, b, right, 0.5 * tolerance, depth - 1);
}

template <class F>
double integrate(const F& f, double a, double b, double tolerance) {
    if (a == b) return 0.0;
    return adaptive(f, a, b, gauss8(f, a, b), tolerance, 40);
}

// The same where the integrand behaves like the square root of the distance to an end (`at_a`,
// `at_b`): the line integral P(w, x) of a radial filter has a square-root edge at |w| = R, the
// rows' strip ends. t = a + (b - a) phi(s) with phi'(end) = 0 (phi = s^2, 1 - (1 - s)^2 or
// 3 s^2 - 2 s^3) turns sqrt(t - a) dt into a smooth s^2 ds, which Gauss-Legendre converges on;
// without it the bisection never meets the tolerance near the edge.
template <class F>
double integrate_edges(const F& f, double a, double b, bool at_a, bool at_b, double tolerance) {
    if (!at_a && !at_b) return integrate(f, a, b, tolerance);
    const double h = b - a;
    auto g = [&](double s) {
        double phi, dphi;
        if (at_a && at_b) {
            phi = s * s * (3.0 - 2.0 * s);
            dphi = 6.0 * s * (1.0 - s);
        } else if (at_a) {
            phi = s * s;
            dphi = 2.0 * s;
        } else {
            phi = 1.0 - (1.0 - s) * (1.0 - s);
            dphi = 2.0 * (1.0 - s);
        }
        return f(a + h * phi) * dphi * h;
    };
    return integrate(g, 0.0, 1.0, tolerance);
}

class Accumulator {
public:
    Accumulator(const Scene& scene, const Filter& filter)
        : filter_(filter),
          radius_(filter.radius_px()),
          amplitude_(filter.amplitude()),
          width_(scene.width),
          height_(scene.height),
          out_(scene.width, scene.height, 0.0),
          left_(static_cast<std::size_t>(scene.width + 1) * scene.height, 0.0) {}

    void add(const BezierPiece& p, double t_top, double t_bottom, double y_top, double y_bottom,
             double jump) {
        const Segment& s = *p.segment;
        const double xa = bezier_at(s, t_top).x, xb = bezier_at(s, t_bottom).x;
        const double x_lo = std::min(xa, xb), x_hi = std::max(xa, xb);
        const int j_lo = std::max(0, static_cast<int>(std::ceil(y_top - radius_ - 0.5)));
        const int j_hi =
            std::min(height_ - 1, static_cast<int>(std::floor(y_bottom + radius_ - 0.5)));
        for (int j = j_lo; j <= j_hi; ++j) {
            const double cy = j + 0.5;
            const double ya = std::max(y_top, cy - radius_), yb = std::min(y_bottom, cy + radius_);
            if (!(ya < yb)) continue;
            const double ta = ya == y_top ? t_top : solve_monotone(s, 1, ya, p.t0, p.t1);
            const double tb = yb == y_bottom ? t_bottom : solve_monotone(s, 1, yb, p.t0, p.t1);
            // Ends on the strip's edges, |y - cy| = R, where the integrands have square-root edges.
            const bool edge_a = ya == cy - radius_, edge_b = yb == cy + radius_;
            // Centres whose support lies wholly right of the piece: the full line mass.
            const int i_full = std::max(0, static_cast<int>(std::ceil(x_hi + radius_ - 0.5)));
            if (i_full < width_) {
                const double mass = integrate_edges(
                    [&](double y) {
                        return 2.0 * amplitude_ * filter_.profile_line_integral(y - cy, radius_);
                    },
                    ya, yb, edge_a, edge_b, kBezierFilterQuadratureTolerance);
                left_[static_cast<std::size_t>(j) * (width_ + 1) + i_full] += jump * mass;
            }
            const int i_lo = std::max(0, static_cast<int>(std::floor(x_lo - radius_ - 0.5)));
            for (int i = i_lo; i < std::min(i_full, width_); ++i) {
                out_.at(i, j) += jump * across(s, ta, tb, edge_a, edge_b, i + 0.5, cy);
            }
        }
    }

    Coverage finish(double background) {
        for (int j = 0; j < height_; ++j) {
            double run = background;
            const double* left = &left_[static_cast<std::size_t>(j) * (width_ + 1)];
            for (int i = 0; i < width_; ++i) {
                run += left[i];
                out_.at(i, j) += run;
            }
        }
        return std::move(out_);
    }

private:
    // The integral over t in [ta, tb] of H(x - cx, y - cy) y'(t). The piece is x-monotone, so
    // it is cut where x = cx -+ R: left of the support H is the full line mass, right of it 0,
    // and only the part across the support needs the kinks found.
    double across(const Segment& s, double ta, double tb, bool edge_a, bool edge_b, double cx,
                  double cy) const {
        double cuts[4] = {ta, 0.0, 0.0, tb};
        const double lo = std::min(ta, tb), hi = std::max(ta, tb);
        cuts[1] = solve_monotone(s, 0, cx - radius_, lo, hi);
        cuts[2] = solve_monotone(s, 0, cx + radius_, lo, hi);
        if ((cuts[1] > cuts[2]) != (ta > tb)) std::swap(cuts[1], cuts[2]);  // in the order ta -> tb
        double sum = 0.0;
        for (int k = 0; k < 3; ++k) {
            const double a = cuts[k], b = cuts[k + 1];
            if (a == b) continue;
            const bool at_a = a == ta && edge_a, at_b = b == tb && edge_b;
            const double x_mid = bezier_at(s, 0.5 * (a + b)).x;
            if (x_mid >= cx + radius_) continue;  // right of the support: H = 0
            if (x_mid <= cx - radius_) {          // left of it: the full line mass
                sum += integrate_edges(
                    [&](double t) {
                        const Point p = bezier_at(s, t);
                        return 2.0 * amplitude_ * filter_.profile_line_integral(p.y - cy, radius_) *
                               bezier_derivative(s, t).y;
                    },
                    a, b, at_a, at_b, kBezierFilterQuadratureTolerance);
                continue;
            }
            sum += inside(s, a, b, at_a, at_b, cx, cy);
        }
        return sum;
    }

    // The part of a piece across the support's square: split where it crosses the support
    // circle (kinks of H), found as sign changes of |B - c|^2 - R^2 on a grid and refined by
    // bisection.
    double inside(const Segment& s, double ta, double tb, bool edge_a, bool edge_b, double cx,
                  double cy) const {
        auto integrand = [&](double t) {
            const Point b = bezier_at(s, t);
            const double u = b.x - cx, w = b.y - cy;
            const double full = filter_.profile_line_integral(w, radius_);
            const double part = filter_.profile_line_integral(w, std::abs(u));
            const double h = amplitude_ * (full - (u < 0.0 ? -part : part));
            return h * bezier_derivative(s, t).y;
        };
        auto g = [&](double t) {
            const Point b = bezier_at(s, t);
            return (b.x - cx) * (b.x - cx) + (b.y - cy) * (b.y - cy) - radius_ * radius_;
        };
        constexpr int kGrid = 32;
        double sum = 0.0, from = ta, prev = ta, g_prev = g(ta);
        for (int k = 1; k <= kGrid; ++k) {
            const double t = ta + (tb - ta) * k / kGrid;
            const double gt = g(t);
            if ((gt > 0.0) != (g_prev > 0.0)) {
                double lo = prev, hi = t;
                const bool lo_outside = g_prev > 0.0;
                for (int it = 0; it < 200; ++it) {
                    const double mid = 0.5 * (lo + hi);
                    if (mid == lo || mid == hi) break;
                    ((g(mid) > 0.0) == lo_outside ? lo : hi) = mid;
                }
                const double cut = 0.5 * (lo + hi);
                sum += integrate_edges(integrand, from, cut, from == ta && edge_a, false,
                                       kBezierFilterQuadratureTolerance);
                from = cut;
            }
            prev = t;
            g_prev = gt;
        }
        return sum + integrate_edges(integrand, from, tb, from == ta && edge_a, edge_b,
                                     kBezierFilterQuadratureTolerance);
    }

    const Filter& filter_;
    double radius_, amplitude_;
    int width_, height_;
    Coverage out_;
    std::vector<double> left_;  // per row, width + 1 steps of the full-line mass
};

}  // namespace

Coverage bezier_filtered_reference(const Scene& scene, const Filter& filter) {
    if (filter.is_box())
        throw std::invalid_argument("bezier_filtered_reference: the box is not radial");
    require_window_frame(scene, "Bezier filtered reference");
    Accumulator acc(scene, filter);
    const double r = filter.radius_px();
    // A piece keeps its jump over many consecutive bands (bands end wherever any two pieces
    // cross or any piece ends): its bands are joined into one span while the jump holds, so
    // the quadrature runs once per span, not once per band.
    struct Span {
        double t_top, t_bottom, y_top, y_bottom, jump;
    };
    std::unordered_map<const BezierPiece*, Span> open;
    auto flush = [&](const BezierPiece* p, const Span& s) {
        acc.add(*p, s.t_top, s.t_bottom, s.y_top, s.y_bottom, s.jump);
    };
    const BezierPieces pieces = monotone_pieces(scene);
    sweep_bezier_bands(scene, pieces, 0.5 - r, scene.height - 0.5 + r, [&](const BezierBand& band) {
        for (const BandPiece& b : band.pieces) {
            const auto it = open.find(b.piece);
            if (it != open.end() && it->second.jump == b.jump &&
                it->second.y_bottom == band.y_top) {
                it->second.t_bottom = b.t_bottom;
                it->second.y_bottom = band.y_bottom;
                continue;
            }
            if (it != open.end()) flush(b.piece, it->second);
            open[b.piece] = {b.t_top, b.t_bottom, band.y_top, band.y_bottom, b.jump};
        }
    });
    for (const auto& [p, s] : open) flush(p, s);
    return acc.finish(scene.background);
}

}  // namespace aabench
