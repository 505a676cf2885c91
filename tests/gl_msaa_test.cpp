// gl-msaa (a real driver's MSAA: Mesa's llvmpipe via OSMesa) against the suite's own point
// sampler at the driver's own sample positions: the differential test of docs/gl-msaa.md.
//
// The driver snaps vertices to its 1/256 px grid (gl-msaa rounds them there itself) and
// re-polygonises discs and rings at 1/512 px, so near an edge a sample may land on the other
// side: those whole-sample flips are counted and their share bounded. Everywhere else the two
// must agree to within the float32 target's quantisation.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "harness/measure/symptoms.h"
#include "methods/gl_msaa/gl_raster_p.h"
#include "methods/method.h"
#include "methods/scan/sampling/sample_patterns.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

// An 80 x 64 image: not square, so a mix-up of x and y or of up and down cannot pass.
constexpr int kWidth = 80, kHeight = 64;

// Agreement "within the target's quantisation": both sides average the same float32 sample
// values (the driver in float, ssaa in double rounded once), so they differ by a few units in
// the last place of the largest value: 4 ulps of 1.
constexpr double kQuantisationTolerance = 4.0 * FLT_EPSILON;

// The share of the edge band's samples that may flip. A vertex moves by at most 2^-9 px per
// axis when rounded to the driver's 1/256 px grid (a disc's or ring's boundary by at most its
// 1/512 px sagitta), so only samples within about 0.003 px of an edge can land on the other
// side: some 4 x 2 x 0.003 = 0.024 samples per pixel of edge length, about 0.2% of the samples
// of the 3 px wide band around it (kEdgeBandPx each side). 1% leaves room for the tie rules,
// which differ on samples exactly on an edge (the driver's top-left rule in its own frame,
// ssaa's "right of and below"). The measured worst is printed with the pattern.
constexpr double kMaxFlippedShare = 0.01;

// The driver's positions as an ssaa spec (interface of methods/ssaa/ssaa.cpp: positions=X/Y;...).
std::string ssaa_at(const std::vector<std::array<double, 2>>& positions) {
    std::string spec = "ssaa:positions=";
    for (std::size_t s = 0; s < positions.size(); ++s) {
        spec += fmt::format("{}{}/{}", s ? ";" : "", positions[s][0], positions[s][1]);
    }
    return spec;
}

struct Agreement {
    long long band_pixels = 0;
    long long flipped_samples = 0;
    long long outside_band_failures = 0;
    double worst_in_band = 0.0;
    double worst_outside_band = 0.0;
    std::string first_failure;
};

// Compares `driver` with `sampler` (same scene, `samples` samples per pixel): a pixel differing
// by more than the quantisation holds round(|d| / (span / samples)) flipped samples, exact for
// the two-valued patterns and a lower bound otherwise.
Agreement agreement(const Scene& scene, const Image& driver, const Image& sampler, int samples) {
    const Raster<std::uint8_t> band = edge_band_mask(scene);
    const auto [lo, hi] = scene.value_range();
    const double span = hi - lo;
    Agreement a;
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const double d = std::abs(static_cast<double>(driver.at(i, j)) - sampler.at(i, j));
            const bool in_band = band.at(i, j) != 0;
            a.band_pixels += in_band;
            if (!(d <= kQuantisationTolerance)) {  // NaN counts as a difference
                if (in_band) {
                    a.flipped_samples += std::max(1LL, std::llround(d / (span / samples)));
                    a.worst_in_band = std::max(a.worst_in_band, d);
                } else {
                    if (a.outside_band_failures++ == 0) {
                        a.first_failure = fmt::format("pixel ({}, {}): {} vs {}", i, j,
                                                      driver.at(i, j), sampler.at(i, j));
                    }
                    a.worst_outside_band = std::max(a.worst_outside_band, d);
                }
            }
        }
    }
    return a;
}

std::vector<std::string> two_dimensional_patterns() {
    std::vector<std::string> ids;
    for (const PatternInfo& info : pattern_registry()) {
        if (info.model_file) continue;  // tests/mesh_patterns_test.cpp
        if (!make_pattern(info.id, 8, 8).world) ids.push_back(info.id);
    }
    return ids;
}

// The driver against the point sampler on every 2-D pattern.
void check_every_pattern(const std::string& driver_spec, const std::string& sampler_spec,
                         int samples) {
    const MethodInstance driver = make_method(driver_spec);
    const MethodInstance sampler = make_method(sampler_spec);
    const std::vector<std::string> patterns = two_dimensional_patterns();
    ASSERT_GE(patterns.size(), 5u);
    double worst_share = 0.0, worst_difference = 0.0;
    for (const std::string& pattern : patterns) {
        const Scene scene = make_pattern(pattern, kWidth, kHeight);
        const Agreement a = agreement(scene, render_scene(*driver.method, scene),
                                      render_scene(*sampler.method, scene), samples);
        const double share =
            static_cast<double>(a.flipped_samples) / (static_cast<double>(a.band_pixels) * samples);
        EXPECT_EQ(a.outside_band_failures, 0)
            << driver.spec << " vs " << sampler.spec << " on " << pattern << ": "
            << a.outside_band_failures << " pixels off the edge band differ (worst "
            << a.worst_outside_band << "), first " << a.first_failure;
        EXPECT_LE(share, kMaxFlippedShare)
            << driver.spec << " vs " << sampler.spec << " on " << pattern << ": "
            << a.flipped_samples << " flipped samples in " << a.band_pixels << " band pixels";
        std::cout << fmt::format(
            "{} vs {} on {}: {} of {} band samples flipped ({:.4f}%), worst "
            "pixel difference {:.6f} in the band, {:.3g} off it\n",
            driver.spec, sampler.spec, pattern, a.flipped_samples, a.band_pixels * samples,
            100.0 * share, a.worst_in_band, a.worst_outside_band);
        worst_share = std::max(worst_share, share);
        worst_difference = std::max(worst_difference, a.worst_in_band);
    }
    std::cout << fmt::format(
        "worst flipped share {:.4f}% (bound {:.1f}%), worst pixel difference "
        "{:.6f}\n",
        100.0 * worst_share, 100.0 * kMaxFlippedShare, worst_difference);
}

TEST(GlMsaa, TheDriverIsLlvmpipeWithTheStandardFourSamplePositions) {
    const std::string name = gl_driver_name();
    EXPECT_NE(name.find("llvmpipe"), std::string::npos) << name;
    const std::vector<std::array<double, 2>> positions = gl_sample_positions(4);
    ASSERT_EQ(positions.size(), 4u);
    // In the image frame (y down) they are the Direct3D / Vulkan standard 4x pattern; mirrored
    // (a missed or a doubled flip) they would not be.
    const SamplePattern standard = standard_msaa_pattern(4);
    for (std::size_t s = 0; s < standard.size(); ++s) {
        const std::array<double, 2> expected = {standard.x(s), standard.y(s)};
        EXPECT_NE(std::find(positions.begin(), positions.end(), expected), positions.end())
            << "standard position (" << expected[0] << ", " << expected[1] << ") missing";
    }
    EXPECT_EQ(gl_sample_positions(1), (std::vector<std::array<double, 2>>{{0.5, 0.5}}));
}

TEST(GlMsaa, FourSamplesAgreeWithSsaaAtTheDriversPositionsOnEvery2DPattern) {
    // flatness=0.0001: on the curve patterns the driver gets the very polygon the reader's
    // flattening gives ssaa (both cut each segment as patterns/scene/bezier.h does at 1e-4 px).
    check_every_pattern("gl-msaa:samples=4,flatness=0.0001", ssaa_at(gl_sample_positions(4)), 4);
}

TEST(GlMsaa, OneSampleAgreesWithNoneOnEvery2DPattern) {
    check_every_pattern("gl-msaa:samples=1,flatness=0.0001", "none", 1);
}

// Holes, overlaps and order, with vertices on the driver's grid (no rounding), no sample on an
// edge: the driver must give exactly what the sampler gives.
TEST(GlMsaa, HolesOverlapsAndOrderFollowTheNonzeroRule) {
    Scene scene;
    scene.width = 24;
    scene.height = 20;
    scene.background = 0.25;
    auto square = [](double x0, double y0, double x1, double y1, bool clockwise) {
        Contour c = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
        if (!clockwise) std::reverse(c.begin(), c.end());
        return c;
    };
    // A square with a hole (inner contour reversed: winding 0 inside).
    Shape holed;
    holed.value = 1.0;
    holed.contours = {square(1, 1, 11, 11, true), square(4, 4, 8, 8, false)};
    // Two same-direction contours overlapping: winding 2 in the overlap, filled (nonzero).
    Shape doubled;
    doubled.value = 0.5;
    doubled.contours = {square(13, 1, 20, 8, true), square(16, 4, 23, 11, true)};
    // A self-overlapping contour (a pentagram: winding 2 in its centre), moved right by one
    // step of the vertex grid so that no sample lies exactly on its slanted edges (the two
    // sides' tie rules differ there, and only there).
    Shape star;
    star.value = 0.75;
    star.contours = {{{6, 12}, {9, 19}, {2, 14}, {11, 14}, {3, 19}}};
    for (Point& p : star.contours[0]) p.x += kGlVertexGridPx;
    // A later shape covering parts of the earlier ones.
    Shape cover;
    cover.value = 0.0;
    cover.contours = {square(9, 6, 15, 16, true)};
    scene.shapes = {holed, doubled, star, cover};
    const MethodInstance driver = make_method("gl-msaa");
    const MethodInstance sampler = make_method(ssaa_at(gl_sample_positions(4)));
    const Image a = render_scene(*driver.method, scene), b = render_scene(*sampler.method, scene);
    int differing = 0;
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            if (!(std::abs(a.at(i, j) - b.at(i, j)) <= kQuantisationTolerance)) {
                ADD_FAILURE() << fmt::format("pixel ({}, {}): {} vs {}", i, j, a.at(i, j),
                                             b.at(i, j));
                if (++differing > 5) return;
            }
        }
    }
    // The hole shows the background, the doubled overlap and the star's centre are filled.
    EXPECT_FLOAT_EQ(a.at(5, 5), 0.25f);
    EXPECT_FLOAT_EQ(a.at(17, 5), 0.5f);
    EXPECT_FLOAT_EQ(a.at(6, 15), 0.75f);
    EXPECT_FLOAT_EQ(a.at(10, 8), 0.0f);
}

TEST(GlMsaa, OnlyOneAndFourSamplesAreOffered) {
    EXPECT_THROW(make_method("gl-msaa:samples=2"), InputError);
    EXPECT_THROW(make_method("gl-msaa:samples=8"), InputError);
}

}  // namespace
}  // namespace aabench
