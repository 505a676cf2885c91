// gauss-multiscan (methods/gauss_multiscan.cpp) and its filter tables
// (methods/scan/multiscan/subscanline.h):
//   1. the closed-form cross-section integrals against adaptive quadrature, and the discrete
//      normalisation;
//   2. the region-by-region scatter (eq. 4–5, modes 0–3 of §3.3) against a slow per-pixel
//      evaluation of the same discrete sum, on seeded random scenes;
//   3. convergence, with lut = 0 and n = 256, to the exact filtered value computed by
//      brute-force 2-D quadrature of filter x visible value over the disc;
//   4. the 64-step table against the closed form, within the interpolation error bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "methods/method.h"
#include "methods/scan/multiscan/subscanline.h"
#include "test_scenes.h"

namespace aabench {
namespace {

// ---- Quadrature ------------------------------------------------------------------------

class GaussLegendre {
public:
    // Nodes by Newton's method on P_n from the Chebyshev-like initial guesses; |dx| < 1e-15.
    explicit GaussLegendre(int n) : x_(n), w_(n) {
        for (int k = 0; k < n; ++k) {
            double x = std::cos(std::numbers::pi * (k + 0.75) / (n + 0.5));
            double dp = 0.0;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1.0, p1 = x;
                for (int m = 2; m <= n; ++m) {
                    const double p2 = ((2.0 * m - 1.0) * x * p1 - (m - 1.0) * p0) / m;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n * (x * p1 - p0) / (x * x - 1.0);
                const double dx = p1 / dp;
                x -= dx;
                if (std::abs(dx) < 1e-16) break;
            }
            x_[k] = x;
            w_[k] = 2.0 / ((1.0 - x * x) * dp * dp);
        }
    }
    template <class F>
    double integrate(const F& f, double a, double b) const {
        const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
        double sum = 0.0;
        for (std::size_t k = 0; k < x_.size(); ++k) sum += w_[k] * f(mid + half * x_[k]);
        return sum * half;
    }

private:
    std::vector<double> x_, w_;
};

const GaussLegendre& rule10() {
    static const GaussLegendre rule(10);
    return rule;
}
const GaussLegendre& rule20() {
    static const GaussLegendre rule(20);
    return rule;
}

// Adaptive Gauss–Legendre: accepts a panel when the 10- and 20-point rules agree to `tol`
// (the 20-point value is then far more accurate than the difference), else bisects with
// half the tolerance per half, so the accepted panels' estimates sum to <= tol.
constexpr int kMaxDepth = 40;
template <class F>
double adaptive(const F& f, double a, double b, double tol, int depth = 0) {
    const double coarse = rule10().integrate(f, a, b), fine = rule20().integrate(f, a, b);
    if (std::abs(fine - coarse) <= tol || depth >= kMaxDepth) return fine;
    const double m = 0.5 * (a + b);
    return adaptive(f, a, m, 0.5 * tol, depth + 1) + adaptive(f, m, b, 0.5 * tol, depth + 1);
}

// ---- The filters, written out independently of methods/scan/multiscan/subscanline.cpp
// -----------------

enum class Profile { kGaussian, kCone };

struct TestFilter {
    Profile kind;
    double sigma;
    std::string spec;  // method parameters
};

double filter_value(const TestFilter& f, double r) {
    if (!(r < 1.0)) return 0.0;
    if (f.kind == Profile::kCone) return 1.0 - r;
    return std::exp(-r * r / (2.0 * f.sigma * f.sigma));
}

// Continuous volume over the unit disc, 2 pi integral_0^1 f(r) r dr, in closed form.
double filter_volume(const TestFilter& f) {
    if (f.kind == Profile::kCone) return std::numbers::pi / 3.0;
    const double s2 = f.sigma * f.sigma;
    return 2.0 * std::numbers::pi * s2 * (1.0 - std::exp(-1.0 / (2.0 * s2)));
}

const TestFilter kFilters[] = {
    {Profile::kGaussian, 0.5, "filter=gaussian,sigma=0.5"},
    {Profile::kGaussian, 0.3, "filter=gaussian,sigma=0.3"},
    {Profile::kCone, 0.5, "filter=cone"},
};

// The suite's filter (methods/scan/kernel/filter.h) of the same parameters.
Filter profile_of(const TestFilter& f) {
    return f.kind == Profile::kCone ? Filter::cone(1.0) : Filter::gaussian(f.sigma, 1.0);
}

// ---- 1. Cross-section integrals and normalisation ---------------------------------------

// Adaptive quadrature to kCrossSectionQuadrature of a smooth integrand (integrated only up to
// the support's end, where the truncated Gaussian jumps): the closed forms must agree to that
// plus a few roundings of O(1) terms.
constexpr double kCrossSectionQuadrature = 1e-13;
constexpr double kClosedFormTolerance = 1e-12;

TEST(CrossSection, ClosedFormMatchesQuadrature) {
    for (const TestFilter& f : kFilters) {
        const Filter profile = profile_of(f);
        for (const double y : {0.0, 1e-3, 0.2, 1.0 / 3.0, 0.7, 0.99, 1.0}) {
            const double support = std::sqrt(std::max(0.0, 1.0 - y * y));
            for (const double x : {0.0, 0.05, 0.3, 0.5, 0.9, 1.0, 1.5}) {
                const auto integrand = [&](double s) {
                    return filter_value(f, std::sqrt(s * s + y * y));
                };
                const double end = std::min(x, support);
                const double want =
                    end > 0.0 ? adaptive(integrand, 0.0, end, kCrossSectionQuadrature) : 0.0;
                const double got = profile.profile_line_integral(y, x);
                EXPECT_NEAR(got, want, kClosedFormTolerance)
                    << fmt::format("{} y {} x {}", f.spec, y, x);
            }
        }
    }
}

// The weights of all sub-scanlines through one pixel's support sum to 1 by construction;
// 2n - 1 lines of O(1) terms round at 1e-16 each.
constexpr double kNormalisationTolerance = 1e-13;

TEST(CrossSection, DiscreteVolumeIsOneAndTableNodesAreExact) {
    for (const TestFilter& f : kFilters) {
        for (const int n : {1, 2, 3, 6, 12, 256}) {
            const CrossSectionTable exact(profile_of(f), n, 0);
            const CrossSectionTable lut(profile_of(f), n, 64);
            double sum = 0.0;
            for (int k = -(n - 1); k <= n - 1; ++k) sum += 2.0 * exact.total(std::abs(k));
            EXPECT_NEAR(sum, 1.0, kNormalisationTolerance) << f.spec << " n " << n;
            EXPECT_EQ(exact.total(n), 0.0) << "the line at 1 px touches the support in a point";
            for (int l = 0; l <= n; l += std::max(1, n / 7)) {
                for (int m = 0; m <= 64; ++m) {
                    const double x = m / 64.0;
                    ASSERT_EQ(lut.at(l, x), exact.at(l, x)) << f.spec << " n " << n << " l " << l;
                }
            }
        }
    }
}

// ---- Brute-force visible value along a line ---------------------------------------------

// The visible value along the line at height y by brute force over every edge of the scene
// (no edge table, no bucketing): start value and (x, value after) in ascending x. The limit
// from below counts an edge when min_y <= y < max_y, from above when min_y < y <= max_y.
struct SlowProfile {
    double start;
    std::vector<std::pair<double, double>> changes;
};

SlowProfile slow_profile(const Scene& scene, double y, bool from_below) {
    struct Hit {
        double x;
        int shape;
        int winding;
    };
    std::vector<Hit> hits;
    for (int s = 0; s < static_cast<int>(scene.shapes.size()); ++s) {
        for (const Contour& c : scene.shapes[s].contours) {
            for (std::size_t k = 0; k < c.size(); ++k) {
                const Point a = c[k], b = c[(k + 1) % c.size()];
                if (a.y == b.y) continue;
                const double lo = std::min(a.y, b.y), hi = std::max(a.y, b.y);
                const bool hit = from_below ? (lo <= y && y < hi) : (lo < y && y <= hi);
                if (!hit) continue;
                hits.push_back({a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x), s,
                                a.y < b.y ? 1 : -1});
            }
        }
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& p, const Hit& q) { return p.x < q.x; });
    std::vector<int> winding(scene.shapes.size(), 0);
    auto visible = [&] {
        for (int s = static_cast<int>(scene.shapes.size()) - 1; s >= 0; --s) {
            if (winding[s] != 0) return scene.shapes[s].value;
        }
        return scene.background;
    };
    SlowProfile out{scene.background, {}};
    for (const Hit& h : hits) {
        winding[h.shape] += h.winding;
        out.changes.push_back({h.x, visible()});
    }
    return out;
}

// Sum over the runs [a, b] of a line of value * weight(a, b); weight(-inf, x) is passed as
// weight(-1e300, x).
template <class Weight>
double weighted_line(const SlowProfile& p, const Weight& weight) {
    constexpr double kFar = 1e300;
    double total = 0.0, from = -kFar, value = p.start;
    for (const auto& [x, next] : p.changes) {
        total += value * weight(from, x);
        from = x;
        value = next;
    }
    return total + value * weight(from, kFar);
}

// ---- Scenes ------------------------------------------------------------------------------

// ---- 2. The scatter against a per-pixel evaluation of the same sum ----------------------

// The discrete sum the method states, pixel by pixel: every sub-scanline (r + 0.5) + l/n
// within 1 px of the centre, the mean of its two limits, each run weighted by the
// cross-section integral between its ends measured from the centre (the table's F, tested
// above). No regions, no modes, no carried values.
double slow_discrete_pixel(const Scene& scene, const CrossSectionTable& table, int i, int j) {
    const int n = table.sub_scanlines();
    const double cx = i + 0.5;
    double total = 0.0;
    for (const int r : {j - 1, j}) {
        for (int l = 0; l < n; ++l) {
            const int offset = r == j ? l : n - l;  // vertical distance from the centre, in 1/n
            if (offset == n) continue;              // F_n = 0
            const double y = (r + 0.5) + static_cast<double>(l) / n;
            // Signed F: integral of the cross-section from the centre to u.
            const auto signed_f = [&](double u) {
                const double a = std::min(std::abs(u), 1.0);
                return u < 0.0 ? -table.at(offset, a) : table.at(offset, a);
            };
            const auto weight = [&](double a, double b) {
                return signed_f(b - cx) - signed_f(a - cx);
            };
            total += 0.5 * (weighted_line(slow_profile(scene, y, true), weight) +
                            weighted_line(slow_profile(scene, y, false), weight));
        }
    }
    return total;
}

// Float32 output (<= 3e-8 for values <= 1) and O(100) double terms per pixel (~1e-14); the
// two sides evaluate F at 1 - x' and at cx - x, which differ by one rounding (~1e-16 x the
// slope of F). 1e-6 leaves a 30x margin over float32 rounding.
constexpr double kSameSumTolerance = 1e-6;
// 5..9 x 4..8 px, vertices up to 2.5 px outside, 1..3 shapes of 3..8 vertices; snapped scenes
// on the quarter-pixel grid with a rectangle of 1..12 quarters.
constexpr testing::SmallSceneShape kRandomScene = {5, 5, 4, 5, 2.5, 3, 6, 12};

TEST(GaussMultiscan, ScatterMatchesPerPixelSumOnRandomScenes) {
    constexpr std::uint64_t kScenes = 60;
    for (std::uint64_t seed = 1; seed <= kScenes; ++seed) {
        const Scene scene = testing::random_small_scene(seed, seed % 2 == 1, kRandomScene);
        for (const TestFilter& f : kFilters) {
            for (const int n : {1, 2, 3, 7}) {
                for (const int lut : {0, 64}) {
                    const std::string spec =
                        fmt::format("gauss-multiscan:n={},{},lut={}", n, f.spec, lut);
                    const Image fast = render_scene(*make_method(spec).method, scene);
                    const CrossSectionTable table(profile_of(f), n, lut);
                    for (int j = 0; j < scene.height; ++j) {
                        for (int i = 0; i < scene.width; ++i) {
                            const double slow = slow_discrete_pixel(scene, table, i, j);
                            ASSERT_TRUE(std::abs(fast.at(i, j) - slow) <= kSameSumTolerance)
                                << fmt::format("seed {} {} pixel ({}, {}): fast {} slow {}\n{}",
                                               seed, spec, i, j, fast.at(i, j), slow,
                                               testing::describe(scene));
                        }
                    }
                }
            }
        }
    }
}

// ---- 3. Convergence to the exact filtered value -----------------------------------------

// (1 / V) * integral over the unit disc around the pixel centre of f(r) * v, by adaptive
// quadrature: y = sin(theta) (which removes the square-root ends of the chord length),
// panels in theta split at every height where the integrand's form changes (vertices, edge
// crossings, edges meeting the circle, and y = 0 for the cone's apex), and along x the exact
// runs of the visible value (brute force) integrated adaptively. With fewer than 100 panels
// of kPanelQuadrature and x-integrals of kRunQuadrature each, the error stays < 1e-9, far
// below kConvergedTolerance it is compared with.
constexpr double kRunQuadrature = 1e-12;
constexpr double kPanelQuadrature = 1e-11;

double quadrature_pixel(const Scene& scene, const TestFilter& f, int i, int j) {
    const double cx = i + 0.5, cy = j + 0.5;
    std::vector<double> breaks = {-1.0, 1.0};
    if (f.kind == Profile::kCone) breaks.push_back(0.0);
    struct Seg {
        Point a, b;
    };
    std::vector<Seg> segs;
    for (const Shape& shape : scene.shapes) {
        for (const Contour& c : shape.contours) {
            for (std::size_t k = 0; k < c.size(); ++k) {
                const Point a{c[k].x - cx, c[k].y - cy};
                const Point b{c[(k + 1) % c.size()].x - cx, c[(k + 1) % c.size()].y - cy};
                segs.push_back({a, b});
                breaks.push_back(a.y);
                // Where the segment meets the unit circle: |a + t (b - a)| = 1.
                const double dx = b.x - a.x, dy = b.y - a.y;
                const double qa = dx * dx + dy * dy, qb = 2.0 * (a.x * dx + a.y * dy);
                const double qc = a.x * a.x + a.y * a.y - 1.0;
                const double disc = qb * qb - 4.0 * qa * qc;
                if (qa > 0.0 && disc >= 0.0) {
                    for (const double sign : {-1.0, 1.0}) {
                        const double t = (-qb + sign * std::sqrt(disc)) / (2.0 * qa);
                        if (t >= 0.0 && t <= 1.0) breaks.push_back(a.y + t * dy);
                    }
                }
            }
        }
    }
    for (std::size_t p = 0; p < segs.size(); ++p) {
        for (std::size_t q = p + 1; q < segs.size(); ++q) {
            const Point a = segs[p].a, b = segs[p].b, c = segs[q].a, d = segs[q].b;
            const double den = (b.x - a.x) * (d.y - c.y) - (b.y - a.y) * (d.x - c.x);
            if (den == 0.0) continue;
            const double t = ((c.x - a.x) * (d.y - c.y) - (c.y - a.y) * (d.x - c.x)) / den;
            const double u = ((c.x - a.x) * (b.y - a.y) - (c.y - a.y) * (b.x - a.x)) / den;
            if (t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0) {
                breaks.push_back(a.y + t * (b.y - a.y));
            }
        }
    }
    std::vector<double> thetas;
    for (const double y : breaks) {
        if (y >= -1.0 && y <= 1.0) thetas.push_back(std::asin(y));
    }
    std::sort(thetas.begin(), thetas.end());
    thetas.erase(std::unique(thetas.begin(), thetas.end()), thetas.end());

    const auto line = [&](double theta) {
        const double y = std::sin(theta), chord = std::cos(theta);
        const SlowProfile p = slow_profile(scene, cy + y, true);
        const auto integrand = [&](double x) { return filter_value(f, std::sqrt(x * x + y * y)); };
        const auto weight = [&](double a, double b) {
            a = std::max(a - cx, -chord);
            b = std::min(b - cx, chord);
            if (!(b > a)) return 0.0;
            if (a < 0.0 && b > 0.0) {  // split at the cone's apex line
                return adaptive(integrand, a, 0.0, kRunQuadrature) +
                       adaptive(integrand, 0.0, b, kRunQuadrature);
            }
            return adaptive(integrand, a, b, kRunQuadrature);
        };
        return weighted_line(p, weight) * chord;  // dy = cos(theta) dtheta
    };
    double total = 0.0;
    for (std::size_t k = 0; k + 1 < thetas.size(); ++k) {
        if (!(thetas[k + 1] > thetas[k])) continue;
        total += adaptive(line, thetas[k], thetas[k + 1], kPanelQuadrature);
    }
    return total / filter_volume(f);
}

Scene hand_scene() {
    // A concave arrow partly outside the image on a grey background, under a slanted bar of
    // another value: overlapping shapes, every pixel near an edge or a vertex.
    Scene scene;
    scene.width = 6;
    scene.height = 5;
    scene.background = 0.2;
    scene.shapes.push_back(
        {{{{-1.3, 0.4}, {3.7, 1.1}, {5.2, -0.6}, {6.9, 3.3}, {2.1, 4.6}, {3.05, 2.55}}}, 1.0});
    scene.shapes.push_back({{{{0.6, 5.8}, {1.4, -0.7}, {2.3, -0.55}, {1.45, 5.95}}}, 0.6});
    return scene;
}

double rms_error(const Image& image, const std::vector<double>& reference) {
    double sum = 0.0;
    for (std::size_t k = 0; k < reference.size(); ++k) {
        const double d = image.data[k] - reference[k];
        sum += d * d;
    }
    return std::sqrt(sum / static_cast<double>(reference.size()));
}

// Measured over the scenes and filters below (lut = 0, so only the y direction is
// discretised): the largest |error| at n = 256 is 4.0e-5 (Gaussian sigma 0.3), most are
// ~1e-6; 2e-4 leaves a 5x margin and is still 20x below the typical error at n = 3.
constexpr double kConvergedTolerance = 2e-4;
// rms(n = 256) / rms(n = 3) measured 1e-4 to 1.4e-3: ~1/n^2 ((3/256)^2 = 1.4e-4), slower
// for the truncated Gaussian whose cross-section jumps at the support's end. 0.01 leaves a
// 7x margin and fails a method converging only as 1/n (3/256 = 0.0117).
constexpr double kConvergenceRatio = 0.01;

TEST(GaussMultiscan, ConvergesToExactFilteredValue) {
    std::vector<Scene> scenes = {hand_scene()};
    for (std::uint64_t seed = 101; seed <= 103; ++seed) {
        scenes.push_back(testing::random_small_scene(seed, false, kRandomScene));
    }
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        const Scene& scene = scenes[s];
        for (const TestFilter& f : kFilters) {
            std::vector<double> reference(static_cast<std::size_t>(scene.width) * scene.height);
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    reference[static_cast<std::size_t>(j) * scene.width + i] =
                        quadrature_pixel(scene, f, i, j);
                }
            }
            const Image coarse = render_scene(
                *make_method(fmt::format("gauss-multiscan:n=3,{},lut=0", f.spec)).method, scene);
            const Image fine = render_scene(
                *make_method(fmt::format("gauss-multiscan:n=256,{},lut=0", f.spec)).method, scene);
            double max_error = 0.0;
            for (int j = 0; j < scene.height; ++j) {
                for (int i = 0; i < scene.width; ++i) {
                    const double want = reference[static_cast<std::size_t>(j) * scene.width + i];
                    const double err = std::abs(fine.at(i, j) - want);
                    max_error = std::max(max_error, err);
                    EXPECT_TRUE(err <= kConvergedTolerance)
                        << fmt::format("scene {} {} pixel ({}, {}): n=256 {} quadrature {}\n{}",
                                       s, f.spec, i, j, fine.at(i, j), want, testing::describe(scene));
                }
            }
            const double coarse_rms = rms_error(coarse, reference);
            const double fine_rms = rms_error(fine, reference);
            RecordProperty(fmt::format("scene{}_{}", s, f.spec),
                           fmt::format("max err n=256 {:.3e}, rms n=3 {:.3e}, n=256 {:.3e}",
                                       max_error, coarse_rms, fine_rms));
            EXPECT_TRUE(fine_rms <= kConvergenceRatio * coarse_rms)
                << fmt::format("scene {} {}: rms n=3 {:.3e}, n=256 {:.3e}", s, f.spec,
                               coarse_rms, fine_rms);
        }
    }
}

// ---- 4. The table's interpolation error --------------------------------------------------

// A 0/1 convex polygon: at most 2 visible changes per line, |dv| = 1.
constexpr int kMaxChangesPerLine = 2;
// Both outputs are rounded to float32 (<= 3e-8 each for values <= 1); 1e-6 with margin.
constexpr double kOutputRounding = 1e-6;

// f just inside r = 1: the slope jump of F_l where a line leaves the truncated support.
double rim_value(const TestFilter& f) {
    if (f.kind == Profile::kCone) return 0.0;
    return std::exp(-1.0 / (2.0 * f.sigma * f.sigma));
}

TEST(GaussMultiscan, SixtyFourStepTableStaysWithinItsInterpolationBound) {
    Scene scene;
    scene.width = 9;
    scene.height = 8;
    scene.shapes.push_back({{{{1.3, 0.7}, {7.6, 2.2}, {6.1, 7.4}, {0.4, 5.9}}}, 1.0});
    constexpr int kLut = 64;
    const double h = 1.0 / kLut;
    for (const TestFilter& f : kFilters) {
        for (const int n : {3, 12}) {
            // Linear interpolation of F_l errs by <= h^2/8 max|F''| on a smooth interval; the
            // truncated Gaussian's F_l also has a kink where the line leaves the support
            // (slope jump f(1)), adding <= h/4 f(1). F = integral of f / (n V_d), and a pixel
            // sums 2n - 1 lines, each with at most kMaxChangesPerLine look-ups that matter.
            double max_slope;  // max |f'(r)| on [0, 1]
            if (f.kind == Profile::kCone) {
                max_slope = 1.0;
            } else {
                max_slope = f.sigma < 1.0 ? std::exp(-0.5) / f.sigma : 1.0 / (f.sigma * f.sigma);
            }
            const Filter profile = profile_of(f);
            double discrete_volume = 0.0;
            for (int k = -(n - 1); k <= n - 1; ++k) {
                discrete_volume +=
                    2.0 * profile.profile_line_integral(std::abs(k) / double(n), 1.0) / n;
            }
            const double per_lookup =
                (h * h / 8.0 * max_slope + h / 4.0 * rim_value(f)) /
                (n * discrete_volume);
            // Measured: 2.7e-5 (cone) to 9.3e-5 (Gaussian 0.5, n = 3) against bounds of 1e-4
            // to 1.6e-3.
            const double bound =
                (2 * n - 1) * kMaxChangesPerLine * per_lookup + kOutputRounding;
            const Image exact = render_scene(
                *make_method(fmt::format("gauss-multiscan:n={},{},lut=0", n, f.spec)).method,
                scene);
            const Image table = render_scene(
                *make_method(fmt::format("gauss-multiscan:n={},{},lut={}", n, f.spec, kLut)).method,
                scene);
            double max_diff = 0.0;
            for (std::size_t k = 0; k < exact.data.size(); ++k) {
                max_diff = std::max(max_diff, std::abs(double(exact.data[k]) - table.data[k]));
            }
            RecordProperty(fmt::format("{}_n{}", f.spec, n),
                           fmt::format("max |lut64 - exact| {:.3e}, bound {:.3e}", max_diff,
                                       bound));
            EXPECT_TRUE(max_diff <= bound) << f.spec << " n " << n << ": " << max_diff;
            EXPECT_GT(max_diff, 0.0) << f.spec << " n " << n << ": the table is not in use";
        }
    }
}

// ---- Parameters ------------------------------------------------------------------------

TEST(GaussMultiscan, OutOfRangeParametersNameTheRange) {
    const std::pair<const char*, const char*> cases[] = {
        {"gauss-multiscan:n=0", "1..256"},         {"gauss-multiscan:n=300", "1..256"},
        {"gauss-multiscan:sigma=0.01", "0.05..10"}, {"gauss-multiscan:lut=-1", "0..4096"},
        {"gauss-multiscan:lut=5000", "0..4096"},   {"gauss-multiscan:filter=box", "gaussian|cone"},
    };
    for (const auto& [spec, range] : cases) {
        try {
            make_method(spec);
            ADD_FAILURE() << spec << ": no error";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(range), std::string::npos) << e.what();
        }
    }
}

TEST(GaussMultiscan, NamesItsReferenceFilter) {
    EXPECT_EQ(make_method("gauss-multiscan").method->filter().text(),
              "gaussian:sigma=0.5,radius=1");
    EXPECT_EQ(make_method("gauss-multiscan:sigma=0.3").method->filter().text(),
              "gaussian:sigma=0.3,radius=1");
    EXPECT_EQ(make_method("gauss-multiscan:filter=cone").method->filter().text(),
              "cone:radius=1");
}

}  // namespace
}  // namespace aabench
