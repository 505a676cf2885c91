// The sampling methods on Bezier curves: point samplers and multi-scan methods take the exact
// crossings of each sample row or sub-scanline with the curve (polygon_on_lines,
// patterns/scene/bezier.h), no flattening. Checked against an oracle written here: the roots
// of y(t) = row found by a dense scan of t and bisection on each segment's own polynomial,
// the visible value walked along the row from them, and each method's own formula applied
// to those values (a centre sample, a grid of samples, the trapezoidal sum of line integrals).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <vector>

#include "methods/method.h"
#include "patterns/scene/bezier.h"

namespace aabench {
namespace {

// The oracle's roots: bisection to 1e-15 in t moves x by less than 1e-13 at these sizes; the
// polygon's x comes from safeguarded Newton to full precision. 1e-9 px leaves four decades.
constexpr double kCrossingTolerancePx = 1e-9;
// A sample or a pixel border this close to a crossing is skipped: the oracle's and the
// method's roots may fall on either side of it (a sample on the curve itself).
constexpr double kNearCrossingPx = 1e-7;
// A pixel of line integrals is a sum of a few spans of values in [0, 1], written as float32:
// one rounding of the result (6e-8) plus the sums' double rounding, far below 1e-6.
constexpr double kFloatTolerance = 1e-6;
// t steps of the oracle's scan for sign changes of y(t) - row: two roots closer than 1/4096
// in t on random curves of these sizes are near-tangencies, which the rows below avoid.
constexpr int kScanSteps = 4096;

// The oracle's own Bernstein evaluation (not bezier_at()).
Point eval(const Segment& s, double t) {
    const double u = 1.0 - t;
    const auto& p = s.p;
    if (s.degree == 1) return {u * p[0].x + t * p[1].x, u * p[0].y + t * p[1].y};
    if (s.degree == 2) {
        return {u * u * p[0].x + 2 * u * t * p[1].x + t * t * p[2].x,
                u * u * p[0].y + 2 * u * t * p[1].y + t * t * p[2].y};
    }
    const double a = u * u * u, b = 3 * u * u * t, c = 3 * u * t * t, d = t * t * t;
    return {a * p[0].x + b * p[1].x + c * p[2].x + d * p[3].x,
            a * p[0].y + b * p[1].y + c * p[2].y + d * p[3].y};
}

struct Hit {
    double x;
    int winding;  // +1 when the curve runs downwards through the row
    int shape;
};

// Every crossing of the row y with the shapes' outlines, sorted by x; false when the row passes
// within kNearCrossingPx (in y) of a point where the scan cannot tell one crossing from two.
bool oracle_hits(const Scene& scene, double y, std::vector<Hit>& hits) {
    hits.clear();
    for (int shape = 0; shape < static_cast<int>(scene.shapes.size()); ++shape) {
        for (const SegmentContour& c : scene.shapes[shape].outline) {
            for (const Segment& s : c) {
                double t0 = 0.0, f0 = eval(s, 0.0).y - y;
                for (int k = 1; k <= kScanSteps; ++k) {
                    const double t1 = static_cast<double>(k) / kScanSteps;
                    const double f1 = eval(s, t1).y - y;
                    if (std::abs(f0) < kNearCrossingPx || std::abs(f1) < kNearCrossingPx) {
                        return false;
                    }
                    if ((f0 < 0) != (f1 < 0)) {
                        double lo = t0, hi = t1;
                        for (int b = 0; b < 60; ++b) {
                            const double mid = 0.5 * (lo + hi);
                            ((eval(s, mid).y - y < 0) == (f0 < 0) ? lo : hi) = mid;
                        }
                        hits.push_back({eval(s, 0.5 * (lo + hi)).x, f1 > f0 ? 1 : -1, shape});
                    }
                    t0 = t1;
                    f0 = f1;
                }
            }
        }
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.x < b.x; });
    return true;
}

// The visible value along the row as runs: value[k] holds right of hits[k] (value[-1]: the
// background, left of every hit), the last shape with a nonzero winding number on top.
std::vector<double> row_values(const Scene& scene, const std::vector<Hit>& hits) {
    std::vector<int> winding(scene.shapes.size(), 0);
    std::vector<double> values;
    for (const Hit& h : hits) {
        winding[h.shape] += h.winding;
        double v = scene.background;
        for (std::size_t s = 0; s < winding.size(); ++s) {
            if (winding[s] != 0) v = scene.shapes[s].value;
        }
        values.push_back(v);
    }
    return values;
}

// v(x, y) from the row's hits and values; nullopt within kNearCrossingPx of a hit.
std::optional<double> value_at(const Scene& scene, const std::vector<Hit>& hits,
                               const std::vector<double>& values, double x) {
    double v = scene.background;
    for (std::size_t k = 0; k < hits.size(); ++k) {
        if (std::abs(hits[k].x - x) < kNearCrossingPx) return std::nullopt;
        if (hits[k].x <= x) v = values[k];
    }
    return v;
}

// The integral of v over x in [a, b] on the row.
double integral(const Scene& scene, const std::vector<Hit>& hits, const std::vector<double>& values,
                double a, double b) {
    double sum = 0.0, x = a, v = scene.background;
    for (std::size_t k = 0; k < hits.size(); ++k) {
        const double h = std::clamp(hits[k].x, a, b);
        sum += (h - x) * v;
        x = std::max(x, h);
        v = values[k];
    }
    return sum + (b - x) * v;
}

// Random closed outlines of lines, quadratics and cubics (loops and self-overlaps included),
// 1-3 shapes of distinct values, inside a w x h window with a 2 px border.
Scene random_curve_scene(std::mt19937& rng, int w, int h) {
    std::uniform_real_distribution<double> ux(2.0, w - 2.0), uy(2.0, h - 2.0);
    std::uniform_int_distribution<int> shapes_n(1, 3), segments_n(1, 4), degree(1, 3);
    auto point = [&] { return Point{ux(rng), uy(rng)}; };
    Scene scene;
    scene.width = w;
    scene.height = h;
    scene.background = 0.1;
    const int shapes = shapes_n(rng);
    for (int s = 0; s < shapes; ++s) {
        SegmentContour contour;
        const Point start = point();
        Point at = start;
        const int n = segments_n(rng) + 1;
        for (int k = 0; k < n; ++k) {
            const Point end = k + 1 == n ? start : point();
            int d = degree(rng);
            if (k + 1 == n && n == 2 && d == 1) d = 3;  // not two lines back and forth
            contour.push_back(d == 1   ? line_segment(at, end)
                              : d == 2 ? quad_segment(at, point(), end)
                                       : cubic_segment(at, point(), point(), end));
            at = end;
        }
        scene.shapes.push_back(bezier_shape({contour}, 0.3 + 0.2 * s));
    }
    return scene;
}

TEST(PolygonOnLines, MeetsEveryLineWhereTheCurveDoes) {
    std::mt19937 rng(39);
    int rows_checked = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const Scene scene = random_curve_scene(rng, 40, 32);
        std::vector<double> ys;
        for (int j = -1; j <= 33; ++j) {
            for (double step : {0.0, 0.2, 0.45, 0.7}) ys.push_back(j + step);
        }
        Scene polygons = scene;
        for (Shape& shape : polygons.shapes) {
            shape.contours.clear();
            for (const SegmentContour& c : shape.outline) {
                Contour out;
                polygon_on_lines(c, ys, out);
                shape.contours.push_back(out);
            }
            shape.outline.clear();
        }
        std::vector<Hit> want;
        for (double y : ys) {
            if (!oracle_hits(scene, y, want)) continue;
            // The polygon's crossings, by the half-open rule y0 <= y < y1 of every edge.
            std::vector<Hit> got;
            for (int s = 0; s < static_cast<int>(polygons.shapes.size()); ++s) {
                for (const Contour& c : polygons.shapes[s].contours) {
                    for (std::size_t k = 0; k < c.size(); ++k) {
                        const Point a = c[k], b = c[(k + 1) % c.size()];
                        const Point top = a.y < b.y ? a : b, bottom = a.y < b.y ? b : a;
                        if (!(top.y <= y && y < bottom.y)) continue;
                        const double x =
                            top.x + (y - top.y) / (bottom.y - top.y) * (bottom.x - top.x);
                        got.push_back({x, b.y > a.y ? 1 : -1, s});
                    }
                }
            }
            std::sort(got.begin(), got.end(), [](const Hit& a, const Hit& b) { return a.x < b.x; });
            ASSERT_EQ(got.size(), want.size()) << "trial " << trial << " y " << y;
            for (std::size_t k = 0; k < got.size(); ++k) {
                EXPECT_NEAR(got[k].x, want[k].x, kCrossingTolerancePx)
                    << "trial " << trial << " y " << y;
                EXPECT_EQ(got[k].winding, want[k].winding) << "trial " << trial << " y " << y;
            }
            ++rows_checked;
        }
    }
    EXPECT_GT(rows_checked, 40 * 100);
}

// The image a method should give from the oracle's rows: each pixel its formula applied to
// v(x, y) from the exact crossings; nullopt where a sample or border lies on a crossing.
using PixelFormula = std::function<std::optional<double>(const Scene&, int i, int j)>;

void expect_method_matches(const char* spec, const PixelFormula& formula, double tolerance) {
    std::mt19937 rng(4039);
    int pixels = 0;
    for (int trial = 0; trial < 12; ++trial) {
        const Scene scene = random_curve_scene(rng, 36, 28);
        const Image image = render_scene(*make_method(spec).method, scene);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                const std::optional<double> want = formula(scene, i, j);
                if (!want) continue;
                ASSERT_NEAR(image.at(i, j), *want, tolerance)
                    << spec << " trial " << trial << " pixel " << i << "," << j;
                ++pixels;
            }
        }
    }
    EXPECT_GT(pixels, 12 * 36 * 28 * 9 / 10) << spec << ": too few pixels checked";
}

// `none`: the value at the pixel centre, bit for bit (its float).
TEST(SamplingOnCurves, NoneSamplesTheExactCrossings) {
    expect_method_matches(
        "none",
        [](const Scene& scene, int i, int j) -> std::optional<double> {
            std::vector<Hit> hits;
            if (!oracle_hits(scene, j + 0.5, hits)) return std::nullopt;
            const auto v = value_at(scene, hits, row_values(scene, hits), i + 0.5);
            if (!v) return std::nullopt;
            return static_cast<float>(*v);
        },
        0.0);
}

// `ssaa:k=3`: the mean of the 3 x 3 grid's values at (i + (a + 1/2)/3, j + (b + 1/2)/3).
TEST(SamplingOnCurves, SupersamplingAveragesItsSamplesOnTheExactCrossings) {
    expect_method_matches(
        "ssaa:k=3",
        [](const Scene& scene, int i, int j) -> std::optional<double> {
            double sum = 0.0;
            std::vector<Hit> hits;
            for (int b = 0; b < 3; ++b) {
                if (!oracle_hits(scene, j + (b + 0.5) / 3, hits)) return std::nullopt;
                const std::vector<double> values = row_values(scene, hits);
                for (int a = 0; a < 3; ++a) {
                    const auto v = value_at(scene, hits, values, i + (a + 0.5) / 3);
                    if (!v) return std::nullopt;
                    sum += *v;
                }
            }
            return sum / 9;
        },
        kFloatTolerance);
}

// `box-multiscan:n=4`: the trapezoidal sum over y_l = j + l/4 of the exact line integrals
// over [i, i + 1] (methods/box_multiscan.cpp).
TEST(SamplingOnCurves, MultiscanIntegratesEachSubscanlineExactly) {
    expect_method_matches(
        "box-multiscan:n=4",
        [](const Scene& scene, int i, int j) -> std::optional<double> {
            double sum = 0.0;
            std::vector<Hit> hits;
            for (int l = 0; l <= 4; ++l) {
                if (!oracle_hits(scene, j + l / 4.0, hits)) return std::nullopt;
                const double w = l == 0 || l == 4 ? 1.0 / 8 : 1.0 / 4;
                sum += w * integral(scene, hits, row_values(scene, hits), i, i + 1.0);
            }
            return sum;
        },
        kFloatTolerance);
}

}  // namespace
}  // namespace aabench
