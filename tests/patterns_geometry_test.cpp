// The built-in test patterns, each against its analytic description: star, strips, grating,
// rings, zoneplate. Areas and winding numbers are computed here from first principles
// (shoelace, crossing count), not with library code. Properties every generator must have are
// in patterns_test.cpp.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "pattern_checks.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

using std::numbers::pi;
using testing::kSizes;
using testing::signed_area;
using testing::Size;

constexpr double kInf = std::numeric_limits<double>::infinity();

// Coordinates are at most a few thousand px and each is a handful of double operations from
// the parameters, so rounding stays near 1e-12 px; 1e-9 px is still far below any feature
// the patterns draw (the smallest is 0.01 px, the circle tolerance).
constexpr double kCoordTolerancePx = 1e-9;
// A shoelace sum of n terms in double is good to about n * 1e-16 relative; n stays below
// 10^5 here, so 1e-9 relative is loose for rounding and tight for any geometric mistake.
constexpr double kAreaRelTolerance = 1e-9;
// The chord tolerance the star arcs and circle_contour calls use (star.cpp, rings.cpp,
// zoneplate.cpp, kMaxSagittaPx in pattern.h): every polygon lies within it inside its true circle.
constexpr double kGeneratorSagittaPx = kMaxSagittaPx;
// "Off the grid": a default centre or offset must be at least this far from a pixel corner
// or pixel centre in each axis (a hundredth of the sub-pixel span a method can resolve).
constexpr double kOffGridMarginPx = 0.01;

// Winding number of `shape` (all its contours) around p, by signed crossings of the
// horizontal ray to +x: upward crossings with p on the left count +1, downward ones -1.
// "Upward" here is increasing y, which makes positive-area contours wind +1.
int winding_number(const Shape& shape, Point p) {
    int winding = 0;
    for (const Contour& contour : shape.contours) {
        for (std::size_t i = 0; i < contour.size(); ++i) {
            const Point& a = contour[i];
            const Point& b = contour[(i + 1) % contour.size()];
            const double side = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
            if (a.y <= p.y && b.y > p.y && side > 0) ++winding;
            if (a.y > p.y && b.y <= p.y && side < 0) --winding;
        }
    }
    return winding;
}

double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Distance of x from the nearest pixel corner or pixel centre coordinate (multiples of 0.5).
double off_grid_distance(double x) {
    const double twice = 2.0 * x;
    return 0.5 * std::abs(twice - std::round(twice));
}

// Radius of a circle contour from its first vertex, after checking every vertex agrees.
double circle_radius(const Contour& contour, Point centre) {
    const double r = distance(contour.front(), centre);
    for (const Point& p : contour) EXPECT_NEAR(distance(p, centre), r, kCoordTolerancePx);
    return r;
}

// ---- star ----

TEST(Star, WedgesAreSectorsOfTheSpecifiedCircle) {
    struct Case {
        std::string spec;
        int spokes;
        double radius, cx, cy, start_angle;
    };
    const Case cases[] = {
        {"star", 36, 0.92, 0.5012, 0.4987, 0.1},
        {"star:spokes=7,radius=0.5,cx=0.3,cy=0.61,start_angle=-2", 7, 0.5, 0.3, 0.61, -2.0},
        {"star:spokes=2", 2, 0.92, 0.5012, 0.4987, 0.1},
    };
    for (const Case& c : cases) {
        for (const Size size : kSizes) {
            SCOPED_TRACE(fmt::format("{} at {}x{}", c.spec, size.width, size.height));
            const Scene scene = make_pattern(c.spec, size.width, size.height);
            const double r = c.radius * 0.5 * std::min(size.width, size.height);
            const Point centre{c.cx * size.width, c.cy * size.height};
            ASSERT_EQ(scene.shapes.size(), static_cast<std::size_t>(c.spokes));
            double total_area = 0.0;
            for (int k = 0; k < c.spokes; ++k) {
                ASSERT_EQ(scene.shapes[k].contours.size(), 1u);
                const Contour& wedge = scene.shapes[k].contours[0];
                // The tip is the exact centre, then the arc from the wedge's first edge to
                // its second, half a period later.
                EXPECT_EQ(wedge.front(), centre);
                const double a0 = c.start_angle + 2.0 * pi * k / c.spokes;
                const double a1 = a0 + pi / c.spokes;
                const Point first = wedge[1], last = wedge.back();
                EXPECT_NEAR(first.x, centre.x + r * std::cos(a0), kCoordTolerancePx);
                EXPECT_NEAR(first.y, centre.y + r * std::sin(a0), kCoordTolerancePx);
                EXPECT_NEAR(last.x, centre.x + r * std::cos(a1), kCoordTolerancePx);
                EXPECT_NEAR(last.y, centre.y + r * std::sin(a1), kCoordTolerancePx);
                for (std::size_t i = 1; i < wedge.size(); ++i) {
                    EXPECT_NEAR(distance(wedge[i], centre), r, kCoordTolerancePx);
                }
                // Each chord stays within the sagitta tolerance of the arc.
                for (std::size_t i = 1; i + 1 < wedge.size(); ++i) {
                    const Point mid{0.5 * (wedge[i].x + wedge[i + 1].x),
                                    0.5 * (wedge[i].y + wedge[i + 1].y)};
                    EXPECT_LE(r - distance(mid, centre), kGeneratorSagittaPx + kCoordTolerancePx);
                }
                const double area = signed_area(wedge);
                EXPECT_GT(area, 0.0);
                total_area += area;
            }
            // Half the disc is dark. The polygon misses the slivers between chords and arcs:
            // at most (arc length) x (sagitta) = pi*r * tolerance in all, never more area.
            const double half_disc = 0.5 * pi * r * r;
            const double rounding = kAreaRelTolerance * half_disc;
            EXPECT_LE(total_area, half_disc + rounding);
            EXPECT_GE(total_area, half_disc - pi * r * kGeneratorSagittaPx - rounding);
        }
    }
}

TEST(Star, DefaultCentreIsOffTheGrid) {
    for (const Size size : kSizes) {
        const Point tip = make_pattern("star", size.width, size.height).shapes[0].contours[0][0];
        EXPECT_GE(off_grid_distance(tip.x), kOffGridMarginPx) << tip.x;
        EXPECT_GE(off_grid_distance(tip.y), kOffGridMarginPx) << tip.y;
    }
}

// Spoke tips (the star's thin objects): the triangle of the centre and the points on the
// wedge's two sides where the wedge is 1.5 px wide (star.cpp, kTipWidthPx), or the whole
// wedge's triangle when the star is smaller than that.
TEST(Star, SpokeTipsAreTheWedgesUpToWhereTheyAreOneAndAHalfPixelsWide) {
    constexpr double kTipWidthPx = 1.5;
    struct Case {
        std::string spec;
        int spokes;
        double radius, cx, cy, start_angle;
    };
    const Case cases[] = {
        {"star", 36, 0.92, 0.5012, 0.4987, 0.1},
        {"star:spokes=7,radius=0.5,cx=0.3,cy=0.61,start_angle=-2", 7, 0.5, 0.3, 0.61, -2.0},
        {"star:spokes=2", 2, 0.92, 0.5012, 0.4987, 0.1},
    };
    for (const Case& c : cases) {
        for (const Size size : kSizes) {
            SCOPED_TRACE(fmt::format("{} at {}x{}", c.spec, size.width, size.height));
            const Scene scene = make_pattern(c.spec, size.width, size.height);
            const double r = c.radius * 0.5 * std::min(size.width, size.height);
            const Point centre{c.cx * size.width, c.cy * size.height};
            const double span = pi / c.spokes;
            // Chord 2 d sin(span / 2) = 1.5 px, unless that lies past the rim.
            const double d = std::min(r, 0.5 * kTipWidthPx / std::sin(0.5 * span));
            ASSERT_EQ(scene.thin_objects.size(), static_cast<std::size_t>(c.spokes));
            for (int k = 0; k < c.spokes; ++k) {
                const ThinObject& tip = scene.thin_objects[k];
                EXPECT_EQ(tip.label, fmt::format("tip {}", k));
                EXPECT_EQ(tip.shape.value, 1.0);
                ASSERT_EQ(tip.shape.contours.size(), 1u);
                const Contour& t = tip.shape.contours[0];
                ASSERT_EQ(t.size(), 3u);
                EXPECT_EQ(t[0], centre);
                const double a0 = c.start_angle + 2.0 * pi * k / c.spokes;
                const double a1 = a0 + span;
                EXPECT_NEAR(t[1].x, centre.x + d * std::cos(a0), kCoordTolerancePx);
                EXPECT_NEAR(t[1].y, centre.y + d * std::sin(a0), kCoordTolerancePx);
                EXPECT_NEAR(t[2].x, centre.x + d * std::cos(a1), kCoordTolerancePx);
                EXPECT_NEAR(t[2].y, centre.y + d * std::sin(a1), kCoordTolerancePx);
                if (d < r) {
                    EXPECT_NEAR(distance(t[1], t[2]), kTipWidthPx, kCoordTolerancePx);
                }
                // On the wedge's own sides and no farther out than its rim: inside the wedge.
                EXPECT_LE(d, r);
                const double area = 0.5 * d * d * std::sin(span);
                EXPECT_NEAR(signed_area(t), area, kAreaRelTolerance * area);
            }
        }
    }
    // At the defaults the tip is 17.2 px long: 0.75 / sin(2.5 degrees).
    const Scene scene = make_pattern("star", 256, 256);
    const Contour& tip = scene.thin_objects[0].shape.contours[0];
    EXPECT_NEAR(distance(tip[0], tip[1]), 0.75 / std::sin(2.5 * pi / 180.0), kCoordTolerancePx);
}

// ---- strips ----

TEST(Strips, RectanglesHaveTheSpecifiedWidthsAnglesAndLengths) {
    struct Case {
        std::string spec;
        double min_width, max_width;
        int widths;
        double min_angle_deg, max_angle_deg;
        int angles;
    };
    const Case cases[] = {
        {"strips", 0.05, 1.5, 8, 1.0, 89.0, 5},
        {"strips:min_width=0.2,max_width=3,widths=3,min_angle_deg=-30,max_angle_deg=120,"
         "angles=4",
         0.2, 3.0, 3, -30.0, 120.0, 4},
        {"strips:min_width=0.7,max_width=0.7,widths=1,angles=1", 0.7, 0.7, 1, 1.0, 89.0, 1},
    };
    for (const Case& c : cases) {
        for (const Size size : kSizes) {
            SCOPED_TRACE(fmt::format("{} at {}x{}", c.spec, size.width, size.height));
            const Scene scene = make_pattern(c.spec, size.width, size.height);
            ASSERT_EQ(scene.shapes.size(), static_cast<std::size_t>(c.widths * c.angles));
            const double cell_w = static_cast<double>(size.width) / c.widths;
            const double cell_h = static_cast<double>(size.height) / c.angles;
            for (int row = 0; row < c.angles; ++row) {
                const double angle_deg =
                    c.angles == 1 ? c.min_angle_deg
                                  : c.min_angle_deg +
                                        (c.max_angle_deg - c.min_angle_deg) * row / (c.angles - 1);
                const double angle = angle_deg * pi / 180.0;
                const double length = 0.8 * std::min(cell_w / std::abs(std::cos(angle)),
                                                     cell_h / std::abs(std::sin(angle)));
                for (int col = 0; col < c.widths; ++col) {
                    const double width =
                        c.widths == 1
                            ? c.min_width
                            : c.min_width * std::pow(c.max_width / c.min_width,
                                                     static_cast<double>(col) / (c.widths - 1));
                    const Shape& shape = scene.shapes[row * c.widths + col];
                    ASSERT_EQ(shape.contours.size(), 1u);
                    const Contour& q = shape.contours[0];
                    ASSERT_EQ(q.size(), 4u);
                    // Opposite sides equal, adjacent sides perpendicular: a rectangle.
                    const Point along{q[1].x - q[0].x, q[1].y - q[0].y};
                    const Point across{q[2].x - q[1].x, q[2].y - q[1].y};
                    EXPECT_NEAR(q[2].x - q[3].x, along.x, kCoordTolerancePx);
                    EXPECT_NEAR(q[2].y - q[3].y, along.y, kCoordTolerancePx);
                    EXPECT_NEAR(along.x * across.x + along.y * across.y, 0.0, kCoordTolerancePx);
                    EXPECT_NEAR(std::hypot(across.x, across.y), width, kCoordTolerancePx);
                    EXPECT_NEAR(std::hypot(along.x, along.y), length, kCoordTolerancePx);
                    EXPECT_NEAR(std::atan2(along.y, along.x), std::remainder(angle, 2.0 * pi),
                                kCoordTolerancePx / length);
                    // Ink = width x length, exactly up to rounding.
                    EXPECT_NEAR(signed_area(q), width * length, kAreaRelTolerance * width * length);
                    // Centred in its cell, off the grid.
                    const double mx = 0.25 * (q[0].x + q[1].x + q[2].x + q[3].x);
                    const double my = 0.25 * (q[0].y + q[1].y + q[2].y + q[3].y);
                    EXPECT_NEAR(mx, (col + 0.5) * cell_w + 0.3183, kCoordTolerancePx);
                    EXPECT_NEAR(my, (row + 0.5) * cell_h + 0.2719, kCoordTolerancePx);
                }
            }
        }
    }
}

TEST(Strips, DefaultsSpanTheDocumentedWidthsAndAngles) {
    const Scene scene = make_pattern("strips", 256, 256);
    double thinnest = kInf, widest = 0.0;
    bool near_horizontal = false, near_vertical = false;
    for (const Shape& shape : scene.shapes) {
        const Contour& q = shape.contours[0];
        thinnest = std::min(thinnest, distance(q[1], q[2]));
        widest = std::max(widest, distance(q[1], q[2]));
        // Angle of the long side folded into [0, 90] degrees from the x axis.
        const double deg =
            std::abs(std::atan(std::abs((q[1].y - q[0].y) / (q[1].x - q[0].x)))) * 180.0 / pi;
        near_horizontal = near_horizontal || deg <= 2.0;
        near_vertical = near_vertical || deg >= 88.0;
        EXPECT_GE(off_grid_distance(0.5 * (q[0].x + q[2].x)), kOffGridMarginPx);
        EXPECT_GE(off_grid_distance(0.5 * (q[0].y + q[2].y)), kOffGridMarginPx);
    }
    EXPECT_NEAR(thinnest, 0.05, kCoordTolerancePx);
    EXPECT_NEAR(widest, 1.5, kCoordTolerancePx);
    EXPECT_TRUE(near_horizontal);
    EXPECT_TRUE(near_vertical);
}

TEST(Strips, InvertedRangesAreInputErrorsNamingBothParameters) {
    for (const auto& [spec, first, second] :
         {std::tuple{"strips:min_width=1,max_width=0.5", "min_width", "max_width"},
          std::tuple{"strips:min_angle_deg=50,max_angle_deg=10", "min_angle_deg",
                     "max_angle_deg"}}) {
        try {
            make_pattern(spec, 64, 64);
            ADD_FAILURE() << spec << ": no InputError";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(first), std::string::npos) << message;
            EXPECT_NE(message.find(second), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
}

TEST(Strips, EveryStripIsAThinObjectLabelledWithItsWidthAndAngle) {
    for (const Size size : kSizes) {
        SCOPED_TRACE(fmt::format("{}x{}", size.width, size.height));
        const Scene scene = make_pattern("strips", size.width, size.height);
        ASSERT_EQ(scene.thin_objects.size(), scene.shapes.size());
        std::vector<std::string> labels;
        for (std::size_t k = 0; k < scene.shapes.size(); ++k) {
            EXPECT_EQ(scene.thin_objects[k].shape, scene.shapes[k]);
            labels.push_back(scene.thin_objects[k].label);
        }
        // First and last: the narrowest strip at the first angle, the widest at the last.
        EXPECT_EQ(labels.front(), "strip w=0.05 a=1°");
        EXPECT_EQ(labels.back(), "strip w=1.5 a=89°");
        std::sort(labels.begin(), labels.end());
        EXPECT_EQ(std::adjacent_find(labels.begin(), labels.end()), labels.end()) << "duplicate";
    }
}

TEST(Patterns, OnlyStarAndStripsHaveThinObjects) {
    for (const char* id : {"grating", "rings", "zoneplate"}) {
        EXPECT_TRUE(make_pattern(id, 64, 64).thin_objects.empty()) << id;
    }
}

// ---- grating ----

TEST(Grating, BarsHaveThePeriodDutyAngleAndPhaseAndCoverTheImage) {
    struct Case {
        std::string spec;
        double period, duty, angle_deg, phase;
    };
    const Case cases[] = {
        {"grating", 1.06, 0.5, 3.0, 0.37},
        {"grating:period=2.5,duty=0.3,angle_deg=-10,phase=0.8", 2.5, 0.3, -10.0, 0.8},
        {"grating:period=7,duty=0.9,angle_deg=90,phase=-3.3", 7.0, 0.9, 90.0, -3.3},
    };
    for (const Case& c : cases) {
        for (const Size size : kSizes) {
            SCOPED_TRACE(fmt::format("{} at {}x{}", c.spec, size.width, size.height));
            const Scene scene = make_pattern(c.spec, size.width, size.height);
            ASSERT_EQ(scene.shapes.size(), 1u);
            const Shape& shape = scene.shapes[0];
            const double angle = c.angle_deg * pi / 180.0;
            const Point n{std::cos(angle), std::sin(angle)};  // across the bars
            const Point d{-n.y, n.x};                         // along the bars
            const auto across = [&](Point p) { return p.x * n.x + p.y * n.y; };
            const auto along = [&](Point p) { return p.x * d.x + p.y * d.y; };
            const Point corners[] = {{0.0, 0.0},
                                     {double(size.width), 0.0},
                                     {double(size.width), double(size.height)},
                                     {0.0, double(size.height)}};
            double image_t_min = kInf, image_t_max = -kInf;
            double image_s_min = kInf, image_s_max = -kInf;
            for (const Point& p : corners) {
                image_t_min = std::min(image_t_min, across(p));
                image_t_max = std::max(image_t_max, across(p));
                image_s_min = std::min(image_s_min, along(p));
                image_s_max = std::max(image_s_max, along(p));
            }

            double previous_t0 = -kInf;
            for (std::size_t b = 0; b < shape.contours.size(); ++b) {
                const Contour& q = shape.contours[b];
                ASSERT_EQ(q.size(), 4u);
                const double t0 = across(q[0]), t1 = across(q[1]);
                // A bar is duty x period wide across, its long sides along d, and reaches
                // past the image along d.
                EXPECT_NEAR(t1 - t0, c.duty * c.period, kCoordTolerancePx);
                EXPECT_NEAR(across(q[3]), t0, kCoordTolerancePx);
                EXPECT_NEAR(across(q[2]), t1, kCoordTolerancePx);
                EXPECT_LT(along(q[0]), image_s_min);
                EXPECT_GT(along(q[3]), image_s_max);
                EXPECT_NEAR(signed_area(q), c.duty * c.period * (along(q[3]) - along(q[0])),
                            kAreaRelTolerance * signed_area(q));
                // Bar edges sit at phase + k*period, consecutive bars one period apart.
                const double k = (t0 - c.phase) / c.period;
                EXPECT_NEAR(k, std::round(k), kCoordTolerancePx);
                if (b > 0) {
                    EXPECT_NEAR(t0 - previous_t0, c.period, kCoordTolerancePx);
                }
                previous_t0 = t0;
                // Nonzero winding fills the middle of the bar and not the middle of the gap.
                const double s_mid = 0.5 * (image_s_min + image_s_max);
                const double t_bar = t0 + 0.5 * c.duty * c.period;
                const double t_gap = t0 + (0.5 + 0.5 * c.duty) * c.period;
                EXPECT_EQ(
                    winding_number(shape, {t_bar * n.x + s_mid * d.x, t_bar * n.y + s_mid * d.y}),
                    1);
                if (b + 1 < shape.contours.size()) {
                    EXPECT_EQ(winding_number(
                                  shape, {t_gap * n.x + s_mid * d.x, t_gap * n.y + s_mid * d.y}),
                              0);
                }
            }
            // The bars cover the whole image across too.
            EXPECT_LE(across(shape.contours.front()[0]), image_t_min);
            EXPECT_GE(across(shape.contours.back()[0]) + c.period, image_t_max);
        }
    }
}

// ---- rings ----

TEST(Rings, AnnuliHaveThePeriodAndDutyAndFillByNonzeroWinding) {
    struct Case {
        std::string spec;
        double period, duty, cx, cy, max_radius;
    };
    const Case cases[] = {
        {"rings", 2.6, 0.5, 0.5012, 0.4987, 0.95},
        {"rings:period=5.3,duty=0.25,cx=0.4,cy=0.55,max_radius=0.7", 5.3, 0.25, 0.4, 0.55, 0.7},
        {"rings:period=1.1,duty=0.8", 1.1, 0.8, 0.5012, 0.4987, 0.95},
    };
    for (const Case& c : cases) {
        for (const Size size : kSizes) {
            SCOPED_TRACE(fmt::format("{} at {}x{}", c.spec, size.width, size.height));
            const Scene scene = make_pattern(c.spec, size.width, size.height);
            ASSERT_EQ(scene.shapes.size(), 1u);
            const Shape& shape = scene.shapes[0];
            const Point centre{c.cx * size.width, c.cy * size.height};
            const double max_radius_px = c.max_radius * 0.5 * std::min(size.width, size.height);

            // Contours: disc (outer only), then outer/inner pairs of annuli 1, 2, ...
            std::size_t i = 0;
            double expected_area = 0.0, sliver_bound = 0.0;
            for (int k = 0; i < shape.contours.size(); ++k) {
                const double outer_r = circle_radius(shape.contours[i], centre);
                const double expected_outer = std::min((k + c.duty) * c.period, max_radius_px);
                EXPECT_NEAR(outer_r, expected_outer, kCoordTolerancePx) << "annulus " << k;
                EXPECT_GT(signed_area(shape.contours[i]), 0.0) << "annulus " << k;
                ++i;
                double inner_r = 0.0;
                if (k > 0) {
                    ASSERT_LT(i, shape.contours.size());
                    inner_r = circle_radius(shape.contours[i], centre);
                    EXPECT_NEAR(inner_r, k * c.period, kCoordTolerancePx) << "annulus " << k;
                    EXPECT_LT(signed_area(shape.contours[i]), 0.0) << "annulus " << k;
                    ++i;
                }
                expected_area += pi * (outer_r * outer_r - inner_r * inner_r);
                // Each polygon lies within the sagitta inside its circle.
                sliver_bound += 2.0 * pi * (outer_r + inner_r) * kGeneratorSagittaPx;
                if (outer_r == expected_outer && outer_r < max_radius_px) {
                    // An uncut annulus: filled in its middle, empty in the following gap.
                    const double a = 0.7;  // any direction; off the axes
                    const double r_in = (k + 0.5 * c.duty) * c.period;
                    const double r_gap = (k + 0.5 + 0.5 * c.duty) * c.period;
                    EXPECT_EQ(winding_number(shape, {centre.x + r_in * std::cos(a),
                                                     centre.y + r_in * std::sin(a)}),
                              1);
                    EXPECT_EQ(winding_number(shape, {centre.x + r_gap * std::cos(a),
                                                     centre.y + r_gap * std::sin(a)}),
                              0);
                }
            }
            // Every annulus that fits is there: the next one would start past max_radius.
            const double drawn = (shape.contours.size() + 1) / 2;
            EXPECT_GE(drawn * c.period + 2.0 * kGeneratorSagittaPx, max_radius_px);
            double area = 0.0;
            for (const Contour& contour : shape.contours) area += signed_area(contour);
            EXPECT_LE(area, expected_area + sliver_bound);
            EXPECT_GE(area, expected_area - sliver_bound);
        }
    }
}

TEST(Rings, ZonesNarrowerThanTheCircleToleranceAreRefused) {
    EXPECT_THROW(make_pattern("rings:period=0.05,duty=0.1", 64, 64), InputError);
}

// ---- zoneplate ----

TEST(ZonePlate, BoundariesAreAtSqrtKcAndPassNyquistAtTheNyquistRadius) {
    struct Case {
        std::string spec;
        double nyquist_radius, max_radius, cx, cy;
    };
    const Case cases[] = {
        {"zoneplate", 0.6, 0.98, 0.5012, 0.4987},
        {"zoneplate:nyquist_radius=0.3,max_radius=0.8,cx=0.45,cy=0.52", 0.3, 0.8, 0.45, 0.52},
    };
    for (const Case& c : cases) {
        for (const Size size : kSizes) {
            SCOPED_TRACE(fmt::format("{} at {}x{}", c.spec, size.width, size.height));
            const Scene scene = make_pattern(c.spec, size.width, size.height);
            ASSERT_EQ(scene.shapes.size(), 1u);
            const Shape& shape = scene.shapes[0];
            const Point centre{c.cx * size.width, c.cy * size.height};
            const double half_side = 0.5 * std::min(size.width, size.height);
            const double nyquist_px = c.nyquist_radius * half_side;
            const double max_radius_px = c.max_radius * half_side;
            const double zone_c = 2.0 * nyquist_px;  // r_k = sqrt(k * zone_c)

            // Every boundary but a cut outermost one is r_k = sqrt(k c): outer circles (CCW)
            // at odd k, inner ones (CW) at even k.
            std::vector<double> boundaries = {0.0};
            for (const Contour& contour : shape.contours) {
                const double r = circle_radius(contour, centre);
                const bool outer = signed_area(contour) > 0.0;
                if (std::abs(r - max_radius_px) <= kCoordTolerancePx) {
                    EXPECT_TRUE(outer);
                    continue;  // cut at max_radius, not a zone boundary
                }
                const double k = r * r / zone_c;
                EXPECT_NEAR(k, std::round(k), kCoordTolerancePx * r);
                EXPECT_EQ(static_cast<long long>(std::round(k)) % 2, outer ? 1 : 0) << r;
                boundaries.push_back(r);
            }
            std::sort(boundaries.begin(), boundaries.end());
            ASSERT_GE(boundaries.size(), 3u);
            for (std::size_t j = 0; j < boundaries.size(); ++j) {
                EXPECT_NEAR(boundaries[j] * boundaries[j], j * zone_c, kCoordTolerancePx * zone_c)
                    << "boundary " << j << " missing or extra";
            }
            // Zone j is wider than a pixel (below Nyquist) exactly when its middle lies inside
            // the Nyquist radius: width r_j+1 - r_j = c / (r_j+1 + r_j) > 1 iff the mean < c/2.
            for (std::size_t j = 0; j + 1 < boundaries.size(); ++j) {
                const double width = boundaries[j + 1] - boundaries[j];
                const double middle = 0.5 * (boundaries[j + 1] + boundaries[j]);
                EXPECT_EQ(width > 1.0, middle < nyquist_px) << "zone " << j;
            }
            // Starts resolvable, ends past Nyquist (at all sizes, with these radii).
            EXPECT_GT(boundaries[1] - boundaries[0], 1.0);
            EXPECT_LT(boundaries.back() - boundaries[boundaries.size() - 2], 1.0);
            // Every filled zone that fits is drawn: the next boundary lies past max_radius.
            EXPECT_GE(std::sqrt(boundaries.size() * zone_c) + 2.0 * kGeneratorSagittaPx,
                      max_radius_px);
            // Nonzero winding: 1 in the middle of filled zones, 0 in empty ones.
            for (std::size_t j = 0; j + 1 < boundaries.size(); ++j) {
                const double r = 0.5 * (boundaries[j] + boundaries[j + 1]);
                const double a = 2.3;  // any direction; off the axes
                EXPECT_EQ(
                    winding_number(shape, {centre.x + r * std::cos(a), centre.y + r * std::sin(a)}),
                    j % 2 == 0 ? 1 : 0)
                    << "zone " << j;
            }
        }
    }
}

TEST(ZonePlate, ZonesNarrowerThanTheCircleToleranceAreRefused) {
    EXPECT_THROW(make_pattern("zoneplate:nyquist_radius=0.05,max_radius=10", 64, 64), InputError);
}

}  // namespace
}  // namespace aabench
