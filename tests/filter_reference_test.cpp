// The exact radial-filter references against known answers, the jump set they integrate, and
// the filter family's own properties. The check against a brute-force quadrature on seeded
// random scenes is in filter_reference_brute_test.cpp.
#include "harness/reference/filter_reference.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "filter_quadrature.h"
#include "methods/scan/reference/visible_boundary.h"

namespace aabench {
namespace {

using testing::composite;
using testing::kFilterSpecs;

constexpr double kPi = std::numbers::pi;

// Known answers built from exact geometry: the fast code's error is a few roundings of O(1)
// terms per jump segment near the pixel (~1e-15 each, tens of segments).
constexpr double kExactTolerance = 1e-12;
// Numerical integrals of f in the filter-family tests: composite 10-point Gauss-Legendre on
// pieces of at most sigma / 4 integrates the Gaussian to ~1e-16 relative, the cone exactly.
constexpr double kQuadratureTolerance = 1e-13;

// A polygon standing for the half-plane left of the directed line through (px, py) at angle
// `angle`, cut off far outside the image.
Contour half_plane(double px, double py, double angle) {
    const double far = 1000.0;
    const double ux = std::cos(angle), uy = std::sin(angle);
    const double nx = uy, ny = -ux;  // one side of the line
    return {{px - far * ux, py - far * uy},
            {px + far * ux, py + far * uy},
            {px + far * ux + far * nx, py + far * uy + far * ny},
            {px - far * ux + far * nx, py - far * uy + far * ny}};
}

Contour regular_polygon(double cx, double cy, double circumradius, int n, double phase) {
    Contour c;
    for (int k = 0; k < n; ++k) {
        const double a = phase + 2.0 * kPi * k / n;
        c.push_back({cx + circumradius * std::cos(a), cy + circumradius * std::sin(a)});
    }
    return c;
}

// ---------------------------------------------------------------------------------------
// The filter family.

TEST(FilterFamily, ParsesSpecsWithDefaultsAndCanonicalNames) {
    const Filter g = Filter::parse("gaussian");
    EXPECT_EQ(g.kind(), FilterKind::kGaussian);
    EXPECT_EQ(g.sigma_px(), 0.5);
    EXPECT_EQ(g.radius_px(), 1.0);
    EXPECT_EQ(g.text(), "gaussian:sigma=0.5,radius=1");
    EXPECT_EQ(Filter::parse("gaussian:radius=1.5,sigma=0.7").text(),
              "gaussian:sigma=0.7,radius=1.5");
    const Filter c = Filter::parse("cone");
    EXPECT_EQ(c.kind(), FilterKind::kCone);
    EXPECT_EQ(c.radius_px(), 1.0);
    EXPECT_EQ(c.text(), "cone:radius=1");
    EXPECT_EQ(Filter::parse("cone:radius=2").text(), "cone:radius=2");
    for (const std::string& spec : kFilterSpecs) {
        EXPECT_EQ(Filter::parse(Filter::parse(spec).text()).text(), Filter::parse(spec).text());
    }
}

TEST(FilterFamily, RejectsUnknownIdsKeysAndRanges) {
    for (const char* bad : {"box:radius=1", "gauss", "gaussian:radius=0.1", "gaussian:radius=9",
                            "gaussian:sigma=0.01", "gaussian:sigma=11", "gaussian:width=1",
                            "cone:sigma=0.5", "cone:radius=nan", "cone:radius="}) {
        EXPECT_THROW(Filter::parse(bad), InputError) << bad;
    }
    try {
        Filter::parse("lanczos");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("gaussian, cone"), std::string::npos) << e.what();
    }
}

TEST(FilterFamily, HasUnitVolumeAndVanishesPastItsRadius) {
    for (const std::string& spec : kFilterSpecs) {
        const Filter f = Filter::parse(spec);
        const double radius = f.radius_px();
        auto ring = [&](double r) { return f.value(r) * r; };
        const int pieces = 4 * static_cast<int>(std::ceil(radius / 0.05));
        EXPECT_NEAR(2.0 * kPi * composite(ring, 0.0, radius, pieces), 1.0, kQuadratureTolerance)
            << spec;
        EXPECT_EQ(f.value(radius * 1.0000001), 0.0) << spec;
        EXPECT_EQ(f.value(2.0 * radius), 0.0) << spec;
        EXPECT_GT(f.value(0.0), 0.0) << spec;
        // The closed form F against numerical integration of f.
        for (double r : {0.0, 0.1, 0.37, 0.5, 0.9, 1.3, 2.0, 3.0}) {
            const double m = std::min(r, radius);
            const double numeric = composite(ring, 0.0, m, pieces);
            EXPECT_NEAR(f.radial_integral(r), numeric, kQuadratureTolerance) << spec << " r=" << r;
        }
        EXPECT_NEAR(f.radial_integral(radius), 1.0 / (2.0 * kPi), kQuadratureTolerance);
    }
}

// ---------------------------------------------------------------------------------------
// Known answers.

TEST(FilterReference, EmptySceneGivesTheBackground) {
    Scene scene;
    scene.width = 9;
    scene.height = 7;
    scene.background = 0.3;
    for (const std::string& spec : kFilterSpecs) {
        const Coverage out = filtered_reference(scene, Filter::parse(spec));
        for (double v : out.data) EXPECT_EQ(v, 0.3) << spec;
    }
    // A shape of the background's value changes nothing either.
    scene.shapes.push_back({{regular_polygon(4.2, 3.1, 2.7, 7, 0.3)}, 0.3});
    for (const std::string& spec : kFilterSpecs) {
        const Coverage out = filtered_reference(scene, Filter::parse(spec));
        for (double v : out.data) EXPECT_NEAR(v, 0.3, kExactTolerance) << spec;
    }
}

TEST(FilterReference, FullCoverageGivesOne) {
    for (const std::string& spec : kFilterSpecs) {
        Scene scene;
        scene.width = 8;
        scene.height = 6;
        // Covers every disc: no jump within reach of any centre.
        scene.shapes.push_back({{{{-4.0, -4.0}, {12.0, -4.0}, {12.0, 10.0}, {-4.0, 10.0}}}, 1.0});
        const Coverage out = filtered_reference(scene, Filter::parse(spec));
        for (double v : out.data) EXPECT_NEAR(v, 1.0, kExactTolerance) << spec;
        // The same covered by two shapes meeting along edges through centres and corners.
        scene.shapes = {
            {{{{-4.0, -4.0}, {3.5, -4.0}, {3.5, 2.5}, {-4.0, 10.0}}}, 1.0},
            {{{{3.5, -4.0}, {12.0, -4.0}, {12.0, 10.0}, {-4.0, 10.0}, {3.5, 2.5}}}, 1.0}};
        const Coverage split = filtered_reference(scene, Filter::parse(spec));
        for (int j = 0; j < 6; ++j) {
            for (int i = 0; i < 8; ++i) {
                EXPECT_NEAR(split.at(i, j), 1.0, kExactTolerance) << spec << " " << i << "," << j;
            }
        }
    }
}

TEST(FilterReference, HalfPlaneThroughTheCentreGivesOneHalf) {
    const double cx = 5.5, cy = 4.5;  // pixel (5, 4)
    for (const std::string& spec : kFilterSpecs) {
        for (double degrees : {0.0, 90.0, 180.0, 270.0, 45.0, 30.0, 17.3, 123.4, 225.0, 301.0}) {
            const double angle = degrees * kPi / 180.0;
            Scene a, b;
            a.width = b.width = 11;
            a.height = b.height = 9;
            a.shapes.push_back({{half_plane(cx, cy, angle)}, 1.0});
            b.shapes.push_back({{half_plane(cx, cy, angle + kPi)}, 1.0});
            const Coverage ca = filtered_reference(a, Filter::parse(spec));
            const Coverage cb = filtered_reference(b, Filter::parse(spec));
            EXPECT_NEAR(ca.at(5, 4), 0.5, kExactTolerance) << spec << " " << degrees;
            EXPECT_NEAR(cb.at(5, 4), 0.5, kExactTolerance) << spec << " " << degrees;
            // Complementary half-planes add up to full coverage at every pixel (linearity),
            // whichever side of the shared line each centre is on.
            for (std::size_t k = 0; k < ca.data.size(); ++k) {
                EXPECT_NEAR(ca.data[k] + cb.data[k], 1.0, kExactTolerance)
                    << spec << " " << degrees << " pixel " << k;
            }
        }
    }
}

TEST(FilterReference, CornersAndSpokesAtTheCentreGiveTheirAngle) {
    // A wedge of opening angle alpha with its apex on the centre holds alpha / (2 pi) of
    // the filter's mass (the filter is radial), whatever the filter.
    const double cx = 4.5, cy = 3.5;
    for (const std::string& spec : kFilterSpecs) {
        for (double degrees : {90.0, 45.0, 10.0, 200.0, 333.0}) {
            for (double phase : {0.0, 0.7, -1.9}) {
                const double alpha = degrees * kPi / 180.0;
                Contour wedge = {{cx, cy}};
                for (int k = 0; k <= 16; ++k) {
                    const double a = phase + alpha * k / 16.0;
                    wedge.push_back({cx + 50.0 * std::cos(a), cy + 50.0 * std::sin(a)});
                }
                Scene scene;
                scene.width = 9;
                scene.height = 7;
                scene.shapes.push_back({{wedge}, 1.0});
                const Coverage out = filtered_reference(scene, Filter::parse(spec));
                EXPECT_NEAR(out.at(4, 3), alpha / (2.0 * kPi), kExactTolerance)
                    << spec << " wedge " << degrees << " phase " << phase;
            }
        }
    }
}

TEST(FilterReference, DiscCoveringTheSupportGivesOne) {
    // A regular 64-gon centred on a pixel centre whose inscribed circle has radius >= R
    // (tangent to the support circle, and beyond it): the filter sees only the shape.
    for (const std::string& spec : kFilterSpecs) {
        const Filter f = Filter::parse(spec);
        for (double scale : {1.0, 1.5}) {
            const int n = 64;
            const double apothem = scale * f.radius_px();
            Scene scene;
            scene.width = 12;
            scene.height = 12;
            scene.shapes.push_back(
                {{regular_polygon(6.5, 5.5, apothem / std::cos(kPi / n), n, 0.1)}, 1.0});
            const Coverage out = filtered_reference(scene, f);
            EXPECT_NEAR(out.at(6, 5), 1.0, kExactTolerance) << spec << " scale " << scale;
        }
    }
}

TEST(FilterReference, RegularPolygonCentredOnAPixelMatchesItsSectorIntegral) {
    // Inside a regular n-gon centred on c, the boundary is at rho(psi) = h / cos(psi) for psi
    // in [-pi/n, pi/n] in each of n sectors, so the value is n * integral F(min(rho, R)) dpsi.
    for (const std::string& spec : kFilterSpecs) {
        const Filter f = Filter::parse(spec);
        for (int n : {3, 5, 8}) {
            for (double fraction : {0.3, 0.8, 1.1}) {  // apothem / R
                const double h = fraction * f.radius_px();
                Scene scene;
                scene.width = 14;
                scene.height = 14;
                scene.background = 0.2;
                scene.shapes.push_back(
                    {{regular_polygon(7.5, 6.5, h / std::cos(kPi / n), n, 0.4)}, 0.9});
                const Coverage out = filtered_reference(scene, f);
                auto sector = [&](double psi) {
                    return f.radial_integral(std::min(h / std::cos(psi), f.radius_px()));
                };
                // Split where the boundary leaves the support circle.
                std::vector<double> cuts = {-kPi / n, kPi / n};
                if (h < f.radius_px() && std::acos(h / f.radius_px()) < kPi / n) {
                    cuts = {-kPi / n, -std::acos(h / f.radius_px()), std::acos(h / f.radius_px()),
                            kPi / n};
                }
                double mass = 0.0;
                for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
                    mass += composite(sector, cuts[k], cuts[k + 1], 64);
                }
                mass *= n;
                EXPECT_NEAR(out.at(7, 6), 0.2 + (0.9 - 0.2) * mass, kExactTolerance)
                    << spec << " n " << n << " apothem/R " << fraction;
            }
        }
    }
}

TEST(FilterReference, SymmetricSceneGivesSymmetricValues) {
    // A square centred on a pixel centre (and a rotated one): mirror images in x, y and the
    // diagonal are the same value.
    for (const std::string& spec : kFilterSpecs) {
        for (const double turn : {0.0, kPi / 4.0}) {
            Scene scene;
            scene.width = 11;
            scene.height = 11;
            scene.shapes.push_back({{regular_polygon(5.5, 5.5, 2.93, 4, kPi / 4.0 + turn)}, 1.0});
            const Coverage out = filtered_reference(scene, Filter::parse(spec));
            for (int j = 0; j < 11; ++j) {
                for (int i = 0; i < 11; ++i) {
                    const double v = out.at(i, j);
                    EXPECT_NEAR(v, out.at(10 - i, j), kExactTolerance)
                        << spec << " " << i << "," << j;
                    EXPECT_NEAR(v, out.at(i, 10 - j), kExactTolerance)
                        << spec << " " << i << "," << j;
                    EXPECT_NEAR(v, out.at(j, i), kExactTolerance) << spec << " " << i << "," << j;
                }
            }
        }
    }
}

TEST(FilterReference, LaterShapeHidesEarlierExactly) {
    for (const std::string& spec : kFilterSpecs) {
        const Filter f = Filter::parse(spec);
        Scene scene;
        scene.width = 8;
        scene.height = 7;
        const Contour square = {{1.25, 1.5}, {5.75, 1.5}, {5.75, 5.4}, {1.25, 5.4}};
        scene.shapes.push_back({{square}, 1.0});
        scene.shapes.push_back({{square}, 0.5});
        Scene only_last = scene;
        only_last.shapes.erase(only_last.shapes.begin());
        const Coverage got = filtered_reference(scene, f), want = filtered_reference(only_last, f);
        for (std::size_t k = 0; k < got.data.size(); ++k) {
            EXPECT_NEAR(got.data[k], want.data[k], kExactTolerance) << spec;
        }
        // A small shape wholly under a later, larger one is invisible.
        Scene hidden = only_last;
        hidden.shapes.insert(hidden.shapes.begin(),
                             {{regular_polygon(3.5, 3.5, 1.2, 6, 0.2)}, 0.9});
        const Coverage h = filtered_reference(hidden, f);
        for (std::size_t k = 0; k < h.data.size(); ++k) {
            EXPECT_NEAR(h.data[k], want.data[k], kExactTolerance) << spec;
        }
    }
}

// ---------------------------------------------------------------------------------------
// The jump set.

TEST(VisibleBoundary, JumpSetOfASquareIsItsFourSidesWithSignedWeights) {
    Scene scene;
    scene.width = 8;
    scene.height = 8;
    scene.background = 0.25;
    scene.shapes.push_back({{{{2, 3}, {6, 3}, {6, 5}, {2, 5}}}, 1.0});
    const std::vector<JumpSegment> jumps = visible_jump_set(scene, -1, 9, -10.0, 20.0);
    // weight = v on the right-hand side (cross(b - a, q - a) > 0) minus v on the other side.
    double left = 0, right = 0, top = 0, bottom = 0;
    for (const JumpSegment& s : jumps) {
        const double len = std::hypot(s.b.x - s.a.x, s.b.y - s.a.y);
        if (s.a.x == 2 && s.b.x == 2) {
            EXPECT_EQ(s.weight, 0.25 - 1.0);
            left += len;
        } else if (s.a.x == 6 && s.b.x == 6) {
            EXPECT_EQ(s.weight, 1.0 - 0.25);
            right += len;
        } else if (s.a.y == 3 && s.b.y == 3) {
            EXPECT_EQ(s.weight, 1.0 - 0.25);
            top += len;
        } else if (s.a.y == 5 && s.b.y == 5) {
            EXPECT_EQ(s.weight, 0.25 - 1.0);
            bottom += len;
        } else {
            ADD_FAILURE() << "unexpected piece (" << s.a.x << "," << s.a.y << ")-(" << s.b.x << ","
                          << s.b.y << ") weight " << s.weight;
        }
    }
    EXPECT_EQ(left, 2.0);
    EXPECT_EQ(right, 2.0);
    EXPECT_EQ(top, 4.0);
    EXPECT_EQ(bottom, 4.0);
}

// Regression (found by the hard-case suite, case "collinear" under continuity): a contour of
// collinear points on y = 18, each moved by < 1e-9 px, is a polygon 1e-9 px thin whose edges
// (slope ~1e-11) cross one another. At a crossing the two edges' x at the crossing height
// differ by 1.4e-4 px (an ulp of y times dx/dy), and the horizontal piece closing them got
// weight 1 instead of 2: a loose end that the Gaussian reference weighed in full, 2.2e-5 at
// the centre 0.5 px away, where the true value is below 2e-8. The jump set must close up: at
// every point, the weights arriving equal the weights leaving.
TEST(VisibleBoundary, JumpSetClosesAtCrossingsOfNearlyHorizontalEdges) {
    Scene scene;
    scene.width = 32;
    scene.height = 24;
    scene.shapes.push_back({{{{3.9999999992489452, 17.999999999399719},
                              {24.999999999854644, 17.999999999516781},
                              {9.9999999993168789, 17.999999999818382},
                              {30.000000000038863, 18.000000000110642}}},
                            1.0});
    // Rows and columns wide enough that nothing is clipped: every end must be matched.
    const std::vector<JumpSegment> jumps = visible_jump_set(scene, 10, 26, -100.0, 100.0);
    std::vector<std::pair<Point, double>> net;  // per end point: weight in - weight out
    auto add = [&](Point p, double w) {
        for (auto& [q, sum] : net) {
            if (q == p) {
                sum += w;
                return;
            }
        }
        net.push_back({p, w});
    };
    for (const JumpSegment& s : jumps) {
        add(s.a, -s.weight);
        add(s.b, s.weight);
    }
    for (const auto& [p, sum] : net) {
        EXPECT_EQ(sum, 0.0) << fmt::format("loose end at ({:.17g}, {:.17g})", p.x, p.y);
    }
    // The polygon's area is below its bounding box's, 26 px x 7.2e-10 px; the filters' peaks
    // are 0.736 (Gaussian, sigma 0.5, radius 1) and 3 / pi = 0.955 (cone, radius 1).
    constexpr double kValueBound = (3.0 / kPi) * 26.0 * 7.2e-10;
    const Coverage gaussian = filtered_reference(scene, Filter::parse("gaussian"));
    const Coverage cone = filtered_reference(scene, Filter::parse("cone"));
    for (const Coverage* c : {&gaussian, &cone}) {
        for (int j = 16; j <= 19; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                EXPECT_LE(std::abs(c->at(i, j)), kValueBound) << i << ", " << j;
            }
        }
    }
}

// Regression (found by the render fuzzer): edges 1e300 px long. One runs from (1e300, 4) to
// (0, 3.5), dx/dy = 2e300, and crosses the nearly vertical edge at x = 1.5 within 1e-300 of
// y = 3.5, far below any band the sweep can split. The reference gave 1.0635 at pixel (0, 3)
// and 1.1269 at (2, 3) for a 0/1 scene: the band's pieces kept their rounded x at the border,
// inverted against the walk order by 1.5 px (fixed in visible_boundary.cpp), and dx^2 + dy^2
// overflowed, turning the long segment's integral into NaN, which was dropped (fixed in
// filter_reference.cpp). Checked against a polar midpoint quadrature of the two regions the
// scene draws: the strip 0 <= x <= 1.5 above y = 3.5, and x > 1.5 for 3.5 < y < 4.
TEST(FilterReference, EdgesOfLength1e300) {
    Scene scene;
    scene.width = 4;
    scene.height = 6;
    scene.background = 1.0;
    scene.shapes.push_back({{{{13.6666667, -1e300}, {1.5, 4.0}, {1e300, 4.0}, {0.0, 3.5}}}, 0.0});
    const Filter filter = Filter::parse("gaussian");
    const Coverage out = filtered_reference(scene, filter);
    auto visible = [](double x, double y) {
        const bool strip = y < 3.5 && x >= 0.0 && x <= 1.5;
        const bool band = y > 3.5 && y < 4.0 && x > 1.5;
        return strip || band ? 0.0 : 1.0;
    };
    // Midpoint rule in r and theta: its error at the regions' edges is O(1 / steps).
    constexpr int kRadialSteps = 800, kAngularSteps = 1600;
    constexpr double kQuadratureError = 3e-3;
    for (int j = 2; j <= 4; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const double cx = i + 0.5, cy = j + 0.5;
            double sum = 0.0;
            for (int a = 0; a < kAngularSteps; ++a) {
                const double theta = 2.0 * kPi * (a + 0.5) / kAngularSteps;
                for (int k = 0; k < kRadialSteps; ++k) {
                    const double r = filter.radius_px() * (k + 0.5) / kRadialSteps;
                    sum += filter.value(r) * r *
                           visible(cx + r * std::cos(theta), cy + r * std::sin(theta));
                }
            }
            sum *= (2.0 * kPi / kAngularSteps) * (filter.radius_px() / kRadialSteps);
            EXPECT_NEAR(out.at(i, j), sum, kQuadratureError) << i << ", " << j;
        }
    }
}

}  // namespace
}  // namespace aabench
