// The measured claims about circles, as tests: the polygonisation's error is far below every
// polygon method's error on the circle patterns, and a horizontal-distance rule thins the line
// toward 45° (ink per row 1 against the exact ring's 1 / cos θ).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "harness/measure/circle_angle.h"
#include "harness/measure/metrics.h"
#include "harness/reference/box_reference.h"
#include "methods/method.h"
#include "methods/scan/reference/box_coverage.h"
#include "patterns/pattern.h"
#include "patterns/scene/curves.h"

namespace aabench {
namespace {

// "The polygon methods draw the rings polygonised with a sagitta bound below 1e-4 of the
// smallest error they show" (docs/methods-circles.md, "Measured"): the polygonisation's own rmse
// against the exact curves, at most this share of the smallest box rmse of any method that draws
// the polygon.
constexpr double kPolygonisationShare = 1e-4;

Image as_image(const Coverage& c) {
    Image out(c.width, c.height);
    for (std::size_t k = 0; k < c.data.size(); ++k) out.data[k] = static_cast<float>(c.data[k]);
    return out;
}

double rmse(const Coverage& a, const Coverage& b) {
    double sum = 0.0;
    for (std::size_t k = 0; k < a.data.size(); ++k) sum += std::pow(a.data[k] - b.data[k], 2);
    return std::sqrt(sum / a.data.size());
}

TEST(CirclesClaims, PolygonisationIsFarBelowEveryPolygonMethodsError) {
    for (const char* spec : {"circles:max_radius=16", "circle-radii:max_radius=21"}) {
        const Scene scene = make_pattern(spec, 48, 40);
        const Coverage exact = box_reference(scene);
        Scene polygons = scene;
        for (Shape& s : polygons.shapes) s.circle.reset();
        const double polygonisation = rmse(box_coverage(polygons), exact);
        double smallest = INFINITY;
        std::string who;
        for (const MethodInfo& info : method_registry()) {
            // exact and exact-8bit read the curve (their errors are float32 and 8-bit
            // rounding); the circle methods draw the curve too. The rest draw the polygon.
            if (info.id == "exact" || info.id == "exact-8bit" ||
                info.id.find("circle") != std::string::npos) {
                continue;
            }
            const MethodInstance m = make_method(info.id);
            const ErrorStats e = compare_to_reference(render_scene(*m.method, scene), exact);
            std::printf("%s %s: box rmse %.3g\n", spec, m.spec.c_str(), e.rmse);
            if (e.rmse < smallest) {
                smallest = e.rmse;
                who = m.spec;
            }
        }
        std::printf("%s: polygonisation rmse %.3g, smallest method rmse %.3g (%s), share %.2g\n",
                    spec, polygonisation, smallest, who.c_str(), polygonisation / smallest);
        EXPECT_GT(polygonisation, 0.0);
        EXPECT_LE(polygonisation, kPolygonisationShare * smallest) << spec << " " << who;
    }
}

TEST(CirclesClaims, AaCircleThinsTowardFortyFiveDegrees) {
    // Rings 6 px apart, so no pixel holds two (on touching rings, `circles`, blending one ring
    // over the next also loses ink where they share a pixel).
    Scene scene;
    scene.width = scene.height = 128;
    for (int r = 20; r <= 62; r += 6) scene.shapes.push_back(ring_shape({64.5, 64.5}, r - 0.5, r + 0.5, 1.0));
    const std::optional<ConcentricCurves> curves = concentric_curves(scene);
    ASSERT_TRUE(curves);
    const Coverage exact = box_reference(scene);
    const AngleProfile exact_profile =
        angle_profile(as_image(exact), exact, *curves, 9);
    for (double v : exact_profile.ink_ratio) EXPECT_NEAR(v, 1.0, 1e-6);  // float32 rounding
    for (const char* spec : {"aa-circle", "aa-circle:alpha_max=0", "wu-circle"}) {
        const AngleProfile p = angle_profile(render_scene(*make_method(spec).method, scene), exact, *curves, 9);
        for (std::size_t b = 0; b < p.angle_deg.size(); ++b) {
            std::printf("%s %4.1f deg: ink ratio %.4f (cos %.4f)\n", spec, p.angle_deg[b],
                        p.ink_ratio[b], std::cos(p.angle_deg[b] * std::numbers::pi / 180.0));
        }
        // One unit of ink per row: the ratio follows cos θ. Tolerance: the 5° bins average
        // cos over their width (<= 0.4%) and rings cut by the bin edges (a few % at R <= 60).
        constexpr double kBinTolerance = 0.05;
        EXPECT_NEAR(p.ink_ratio.front(), std::cos(p.angle_deg.front() * std::numbers::pi / 180.0), kBinTolerance) << spec;
        EXPECT_NEAR(p.ink_ratio[7], std::cos(p.angle_deg[7] * std::numbers::pi / 180.0), kBinTolerance) << spec;
    }
}

}  // namespace
}  // namespace aabench
