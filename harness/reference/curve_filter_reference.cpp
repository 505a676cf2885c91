// Radial-filter references of discs and rings (curve_filter_reference.h).
//
// The filter mass of a disc. In polar form about the pixel centre c, with the disc's centre o
// at distance d along phi = 0 and F(r) = integral_0^min(r, R) f(s) s ds (closed form,
// Filter::radial_integral), a ray at angle phi meets the disc between r1(phi) and r2(phi), so
//     J = integral [F(r2(phi)) - F(r1(phi))] dphi,
//     r1,2 = d cos(phi) -+ sqrt(rho^2 - d^2 sin^2(phi)).
// c inside the disc (d < rho): r1 = 0 and phi runs over the whole circle; r2 is smooth.
// c outside (d >= rho): phi runs over |phi| <= asin(rho / d), where the square root has
// endpoint singularities; the substitution sin(phi) = (rho / d) sin(psi) makes it rho cos(psi)
// and dphi = (rho cos(psi)) / (d cos(phi)) dpsi, smooth in psi in [-pi/2, pi/2]. The only kink
// left is where a ray's crossing reaches the support radius R (F stops growing there): the
// angle of the point at distance R from c and rho from o, cos(phi*) = (R^2 + d^2 - rho^2) /
// (2 R d) (law of cosines); the range is split there. Each piece is integrated by adaptive
// 10-point Gauss-Legendre (halving until two halves agree with the whole to 1e-15 per unit of
// angle); where c is within a hair of the circle the integrand is steep but smooth and the
// halving follows it. By symmetry only phi >= 0 is integrated, and doubled.
#include "harness/reference/curve_filter_reference.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "harness/reference/bezier_filter_reference.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

constexpr double kGlNodes[5] = {0.97390652851717174, 0.86506336668898454, 0.67940956829902444,
                                0.43339539412924721, 0.14887433898163122};
constexpr double kGlWeights[5] = {0.066671344308688138, 0.14945134915058059, 0.21908636251598204,
                                  0.26926671930999635, 0.29552422471475287};
// Per unit of angle, times max(1, d): the integrand carries the rounding of the crossing
// distances, ~ulp(d) px, so a fixed tolerance below that noise would never be met and the
// halving would not stop. Summed over the <= pi of angle: <= 3e-14 d, below the 1e-10 bound
// for every centre within 3000 px of the disc's centre.
constexpr double kTolerancePerUnit = 1e-14;
constexpr int kMaxDepth = 40;

template <class Fn>
double gauss_legendre(const Fn& fn, double lo, double hi) {
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    double sum = 0.0;
    for (int q = 0; q < 5; ++q) {
        sum += kGlWeights[q] * (fn(mid + half * kGlNodes[q]) + fn(mid - half * kGlNodes[q]));
    }
    return sum * half;
}

template <class Fn>
double adaptive(const Fn& fn, double lo, double hi, double whole, double tol, int depth) {
    const double mid = 0.5 * (lo + hi);
    const double left = gauss_legendre(fn, lo, mid), right = gauss_legendre(fn, mid, hi);
    if (depth >= kMaxDepth || std::abs(left + right - whole) <= tol * (hi - lo)) {
        return left + right;
    }
    return adaptive(fn, lo, mid, left, tol, depth + 1) + adaptive(fn, mid, hi, right, tol, depth + 1);
}

template <class Fn>
double integrate(const Fn& fn, double lo, double hi, double split, double tol) {
    double sum = 0.0;
    double cuts[3] = {lo, hi, hi};
    int n = 2;
    if (split > lo && split < hi) {
        cuts[1] = split;
        n = 3;
    }
    for (int k = 0; k + 1 < n; ++k) {
        sum += adaptive(fn, cuts[k], cuts[k + 1], gauss_legendre(fn, cuts[k], cuts[k + 1]), tol, 0);
    }
    return sum;
}

}  // namespace

double disc_filter_mass(const Filter& filter, double d, double rho) {
    const double R = filter.radius_px();
    if (!(rho > 0.0) || d >= rho + R) return 0.0;
    if (d + R <= rho) return 1.0;  // the support lies in the disc: the whole unit mass
    auto F = [&filter](double r) { return filter.radial_integral(r); };
    if (d == 0.0) return 2.0 * std::numbers::pi * F(rho);
    // The angle (from the direction of o) where the disc's boundary crosses the support circle.
    const double tol = kTolerancePerUnit * std::max(1.0, d);
    const double cos_star = (R * R + d * d - rho * rho) / (2.0 * R * d);
    const double phi_star = std::abs(cos_star) <= 1.0 ? std::acos(cos_star) : -1.0;
    if (d < rho) {
        auto g = [&](double phi) {
            const double s = d * std::sin(phi);
            return F(d * std::cos(phi) + std::sqrt((rho - s) * (rho + s)));
        };
        return 2.0 * integrate(g, 0.0, std::numbers::pi, phi_star, tol);
    }
    const double k = rho / d;
    auto h = [&](double psi) {
        const double ks = k * std::sin(psi);
        const double cos_phi = std::sqrt((1.0 - ks) * (1.0 + ks));
        const double half = rho * std::cos(psi);
        const double mid = d * cos_phi;
        // r1 = mid - half without the cancellation: (mid - half)(mid + half) = d^2 cos^2 phi -
        // rho^2 cos^2 psi = d^2 - rho^2, since d sin phi = rho sin psi.
        const double near = (d - rho) * (d + rho) / (mid + half);
        return (F(mid + half) - F(near)) * k * std::cos(psi) / cos_phi;
    };
    const double psi_star =
        phi_star >= 0.0 ? std::asin(std::min(1.0, std::sin(phi_star) / k)) : -1.0;
    return 2.0 * integrate(h, 0.0, 0.5 * std::numbers::pi, psi_star, tol);
}

Coverage curve_filtered_reference(const Scene& scene, const Filter& filter) {
    Scene polygons = scene;
    polygons.shapes.clear();
    std::vector<std::size_t> curves;
    for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
        if (scene.shapes[k].circle) {
            curves.push_back(k);
        } else {
            polygons.shapes.push_back(scene.shapes[k]);
        }
    }
    // Each curve disjoint from every other shape (see the header).
    for (std::size_t a : curves) {
        const Circle& c = *scene.shapes[a].circle;
        for (std::size_t b = 0; b < scene.shapes.size(); ++b) {
            if (b == a) continue;
            const Shape& other = scene.shapes[b];
            bool apart = true;
            if (other.circle) {
                apart = circles_disjoint(c, *other.circle);
            } else {  // bounding boxes apart (touching allowed)
                double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
                auto grow = [&](const Point& p) {
                    x0 = std::min(x0, p.x);
                    x1 = std::max(x1, p.x);
                    y0 = std::min(y0, p.y);
                    y1 = std::max(y1, p.y);
                };
                // A Bezier shape by its control points (each segment lies in their hull), not
                // by its flattening, whose chords lie inside the curve's box.
                for (const SegmentContour& contour : other.outline) {
                    for (const Segment& seg : contour) {
                        for (int q = 0; q <= seg.degree; ++q) grow(seg.p[q]);
                    }
                }
                if (other.outline.empty()) {
                    for (const Contour& contour : other.contours) {
                        for (const Point& p : contour) grow(p);
                    }
                }
                apart = x1 <= c.center.x - c.outer || x0 >= c.center.x + c.outer ||
                        y1 <= c.center.y - c.outer || y0 >= c.center.y + c.outer;
            }
            // Overlapping (or maybe): the band sweep of the whole scene, its circles as
            // quarter arcs, by the Bezier reference's quadrature (exact too, another route).
            if (!apart) return bezier_filtered_reference(scene, filter);
        }
    }
    Coverage out = polygons.shapes.empty()
                       ? Coverage(scene.width, scene.height, scene.background)
                       : filtered_reference(polygons, filter);
    const double R = filter.radius_px();
    for (std::size_t k : curves) {
        const Shape& shape = scene.shapes[k];
        const Circle& c = *shape.circle;
        const double weight = shape.value - scene.background;
        // Clamped in double before the casts (a far centre would overflow int).
        const double x_lo = std::floor(c.center.x - c.outer - R - 0.5);
        const double x_hi = std::ceil(c.center.x + c.outer + R);
        const double y_lo = std::floor(c.center.y - c.outer - R - 0.5);
        const double y_hi = std::ceil(c.center.y + c.outer + R);
        if (x_hi < 0 || x_lo > scene.width - 1 || y_hi < 0 || y_lo > scene.height - 1) continue;
        const int i0 = static_cast<int>(std::max(0.0, x_lo));
        const int i1 = static_cast<int>(std::min(scene.width - 1.0, x_hi));
        const int j0 = static_cast<int>(std::max(0.0, y_lo));
        const int j1 = static_cast<int>(std::min(scene.height - 1.0, y_hi));
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                const double d = std::hypot(i + 0.5 - c.center.x, j + 0.5 - c.center.y);
                double mass = disc_filter_mass(filter, d, c.outer);
                if (!c.is_disc() && mass > 0.0) mass -= disc_filter_mass(filter, d, c.inner);
                out.at(i, j) += weight * mass;
            }
        }
    }
    return out;
}

}  // namespace aabench
