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
#include <functional>
#include <numbers>
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
constexpr double kW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                          0.1012285362903763};

// The integrands carry the rounding of the coordinates they are evaluated from (x(t) - cx of
// a curve at x ~ 100 px is good to ~1e-14 px, and H's slope and y'(t) scale that up), so a
// bisection held to a fixed absolute tolerance would chase that noise down to its depth limit.
// A part is accepted when its two halves agree within the tolerance or within this fraction
// of its own size (8-point Gauss-Legendre on a smooth part is far more accurate than either).
constexpr double kRelativeFloor = 1e-10;

template <class F>
double gauss8(const F& f, double a, double b, double* size = nullptr) {
    const double m = 0.5 * (a + b), h = 0.5 * (b - a);
    double sum = 0.0, abs_sum = 0.0;
    for (int k = 0; k < 4; ++k) {
        const double lo = f(m - h * kX[k]), hi = f(m + h * kX[k]);
        sum += kW[k] * (lo + hi);
        abs_sum += kW[k] * (std::abs(lo) + std::abs(hi));
    }
    if (size) *size = abs_sum * std::abs(h);
    return sum * h;
}

template <class F>
double adaptive(const F& f, double a, double b, double whole, double tolerance, int depth) {
    const double m = 0.5 * (a + b);
    double size_l = 0.0, size_r = 0.0;
    const double left = gauss8(f, a, m, &size_l), right = gauss8(f, m, b, &size_r);
    const double diff = std::abs(left + right - whole);
    if (depth <= 0 || diff <= tolerance || diff <= kRelativeFloor * (size_l + size_r)) {
        return left + right;
    }
    return adaptive(f, a, m, left, 0.5 * tolerance, depth - 1) +
           adaptive(f, m, b, right, 0.5 * tolerance, depth - 1);
}

template <class F>
double integrate(const F& f, double a, double b, double tolerance) {
    if (a == b) return 0.0;
    return adaptive(f, a, b, gauss8(f, a, b), tolerance, 40);
}

// The same for an integrand that may behave like the square root of the distance to either
// end: where a piece enters the support near its top or bottom, H carries the half chord
// sqrt(R^2 - w^2). t = a + (b - a) (3 s^2 - 2 s^3), whose derivative vanishes at both ends,
// turns sqrt(t - a) dt into a smooth ~s^2 ds, on which Gauss-Legendre converges; a regular end
// stays regular.
template <class F>
double integrate_ends(const F& f, double a, double b, double tolerance) {
    const double h = b - a;
    auto g = [&](double s) { return f(a + h * s * s * (3.0 - 2.0 * s)) * 6.0 * s * (1.0 - s) * h; };
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
          left_(static_cast<std::size_t>(scene.width + 1) * scene.height, 0.0) {
        build_mass_table();
    }

    void add(const BezierPiece& p, double t_top, double t_bottom, double y_top, double y_bottom,
             double jump) {
        // Column and row indices are clamped in double before the cast: far from the window
        // (a scene placed by a far origin) a coordinate is beyond int.
        auto index = [](double v, int lo, int hi) {
            return static_cast<int>(std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
        };
        const int j_lo = index(std::ceil(y_top - radius_ - 0.5), 0, height_);
        const int j_hi =
            index(std::floor(y_bottom + radius_ - 0.5), -1, height_ - 1);
        for (int j = j_lo; j <= j_hi; ++j) {
            const double cy = j + 0.5;
            const double ya = std::max(y_top, cy - radius_), yb = std::min(y_bottom, cy + radius_);
            if (!(ya < yb)) continue;
            const double ta = ya == y_top ? t_top : piece_solve(p, 1, ya, p.t0, p.t1);
            const double tb = yb == y_bottom ? t_bottom : piece_solve(p, 1, yb, p.t0, p.t1);
            // The piece's x range within this row's strip (it is x-monotone).
            const double xa = piece_at(p, ta).x, xb = piece_at(p, tb).x;
            const double x_lo = std::min(xa, xb), x_hi = std::max(xa, xb);
            // Centres whose support lies wholly right of the piece: the full line mass.
            const int i_full = index(std::ceil(x_hi + radius_ - 0.5), 0, width_);
            if (i_full < width_) {
                left_[static_cast<std::size_t>(j) * (width_ + 1) + i_full] +=
                    jump * strip_mass(ya - cy, yb - cy);
            }
            const int i_lo = index(std::floor(x_lo - radius_ - 0.5), 0, width_);
            for (int i = i_lo; i < std::min(i_full, width_); ++i) {
                out_.at(i, j) += jump * across(p, ta, tb, i + 0.5, cy);
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
    // The filter's mass in the horizontal strip wa <= w <= wb (offsets from the centre):
    // G(wb) - G(wa), G(v) the integral of M(w) = 2 A P(w, R) (the full line mass) from -R to v.
    double strip_mass(double wa, double wb) const { return below(wb) - below(wa); }

    // G(v), from a table of G at kMassCells + 1 angles built once. In w = R sin(phi) the
    // square-root edges of M at |w| = R vanish (M ~ cos(phi), dw = R cos(phi) dphi) and so does
    // the cancellation of R^2 - w^2 near them: on a cell of pi / 512 the integrand is smooth and
    // one 8-point Gauss-Legendre rule is exact to rounding, except next to phi = 0, where the
    // cone's w^2 asinh(m / |w|) is not (those two cells are integrated adaptively).
    static constexpr int kMassCells = 512;
    double mass_integrand(double phi) const {
        const double w = radius_ * std::sin(phi);
        return 2.0 * amplitude_ * filter_.profile_line_integral(w, radius_) * radius_ *
               std::cos(phi);
    }
    double cell_mass(int cell, double from, double to) const {
        auto f = [&](double phi) { return mass_integrand(phi); };
        if (cell == kMassCells / 2 - 1 || cell == kMassCells / 2) {
            return integrate(f, from, to, 1e-16);
        }
        return gauss8(f, from, to);
    }
    void build_mass_table() {
        const double step = std::numbers::pi / kMassCells;
        mass_.assign(kMassCells + 1, 0.0);
        for (int k = 0; k < kMassCells; ++k) {
            const double a = -0.5 * std::numbers::pi + k * step;
            mass_[static_cast<std::size_t>(k + 1)] =
                mass_[static_cast<std::size_t>(k)] + cell_mass(k, a, a + step);
        }
    }
    double below(double v) const {
        const double phi = std::asin(std::clamp(v / radius_, -1.0, 1.0));
        const double step = std::numbers::pi / kMassCells;
        const int cell =
            std::clamp(static_cast<int>((phi + 0.5 * std::numbers::pi) / step), 0, kMassCells - 1);
        const double a = -0.5 * std::numbers::pi + cell * step;
        return mass_[static_cast<std::size_t>(cell)] +
               (phi > a ? cell_mass(cell, a, phi) : -cell_mass(cell, phi, a));
    }

    // The integral over t in [ta, tb] of H(x - cx, y - cy) y'(t). The piece is x- and
    // y-monotone. It is cut where x = cx -+ R and where it crosses the support circle (the
    // kinks of H). Outside the circle H is the full line mass M(w) left of the centre and 0
    // right of it, so those parts are strip masses (integrals in w, no quadrature along the
    // curve); only the parts inside the circle are integrated in t, where H is smooth.
    double across(const BezierPiece& s, double ta, double tb, double cx, double cy) const {
        const double lo = std::min(ta, tb), hi = std::max(ta, tb);
        std::vector<double>& cuts = cuts_;
        cuts.assign({ta, tb});
        const double tl = piece_solve(s, 0, cx - radius_, lo, hi);
        const double tr = piece_solve(s, 0, cx + radius_, lo, hi);
        cuts.push_back(tl);
        cuts.push_back(tr);
        circle_crossings(s, std::min(tl, tr), std::max(tl, tr), cx, cy, cuts);
        std::sort(cuts.begin(), cuts.end());
        if (ta > tb) std::reverse(cuts.begin(), cuts.end());
        auto integrand = [&](double t) {
            const Point b = piece_at(s, t);
            const double u = b.x - cx, w = b.y - cy;
            const double full = filter_.profile_line_integral(w, radius_);
            const double part = filter_.profile_line_integral(w, std::abs(u));
            return amplitude_ * (full - (u < 0.0 ? -part : part)) * piece_derivative(s, t).y;
        };
        double sum = 0.0;
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            const double a = cuts[k], b = cuts[k + 1];
            if (a == b) continue;
            const Point pa = piece_at(s, a), pb = piece_at(s, b), pm = piece_at(s, 0.5 * (a + b));
            const double um = pm.x - cx, wm = pm.y - cy;
            if (um * um + wm * wm < radius_ * radius_) {
                sum += integrate_ends(integrand, a, b, kBezierFilterQuadratureTolerance);
            } else if (um < 0.0) {
                sum += strip_mass(pa.y - cy, pb.y - cy);
            }
        }
        return sum;
    }

    // Where the piece crosses the support circle within [lo, hi]: sign changes of
    // |B - c|^2 - R^2 on a grid, refined by bisection, appended to `cuts`.
    void circle_crossings(const BezierPiece& s, double lo, double hi, double cx, double cy,
                          std::vector<double>& cuts) const {
        if (!(lo < hi)) return;
        auto g = [&](double t) {
            const Point b = piece_at(s, t);
            return (b.x - cx) * (b.x - cx) + (b.y - cy) * (b.y - cy) - radius_ * radius_;
        };
        constexpr int kGrid = 32;
        double prev = lo, g_prev = g(lo);
        for (int k = 1; k <= kGrid; ++k) {
            const double t = k == kGrid ? hi : lo + (hi - lo) * k / kGrid;
            const double gt = g(t);
            if ((gt > 0.0) != (g_prev > 0.0)) {
                double a = prev, b = t;
                const bool a_outside = g_prev > 0.0;
                for (int it = 0; it < 200; ++it) {
                    const double mid = 0.5 * (a + b);
                    if (mid == a || mid == b) break;
                    ((g(mid) > 0.0) == a_outside ? a : b) = mid;
                }
                cuts.push_back(0.5 * (a + b));
            }
            prev = t;
            g_prev = gt;
        }
    }

    const Filter& filter_;
    double radius_, amplitude_;
    int width_, height_;
    Coverage out_;
    std::vector<double> left_;          // per row, width + 1 steps of the full-line mass
    mutable std::vector<double> cuts_;  // scratch of across()
    std::vector<double> mass_;          // G at the table's angles (build_mass_table)
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
    // The spans still open, in the pieces' order (not the map's, which follows the pointers'
    // hashes and so the allocation's address: the sums would round differently run to run).
    std::vector<std::pair<const BezierPiece*, Span>> last(open.begin(), open.end());
    std::sort(last.begin(), last.end(),
              [](const auto& u, const auto& v) { return std::less<>()(u.first, v.first); });
    for (const auto& [p, s] : last) flush(p, s);
    return acc.finish(scene.background);
}

}  // namespace aabench
