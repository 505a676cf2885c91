// The aliasing symptoms (harness/measure/symptoms.h), each on a case built to show it: a square
// whose edge band is counted by hand, a long edge whose point-sampling error is known in closed
// form, a 0.1 px strip between the pixel centres, a grating at the pixel pitch, a 0.3 px square
// moving across a pixel, and stand-in methods whose error over the frames is known exactly.
#include "harness/measure/symptoms.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "harness/reference/box_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

using std::numbers::pi;

// Float32 rounding of a value in [0, 1]: at most half an ulp at 1.0. It bounds the error of
// `exact` per pixel, hence also its RMSE and its per-pixel standard deviation over frames.
constexpr double kFloat32Rounding = 0.5 * std::numeric_limits<float>::epsilon();
// A ratio of two sums of float32-rounded pixel values (each within 2^-24 relative, the sums in
// double): within about 2 x 2^-24 = 1.2e-7 relative; 1e-6 leaves room and still catches any
// real loss (a lost sample is a whole pixel's worth).
constexpr double kMassRatioTolerance = 1e-6;

Shape rectangle(double x0, double y0, double x1, double y1) {
    Shape shape;
    shape.contours.push_back({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
    return shape;
}

Scene scene_of(int width, int height, std::vector<Shape> shapes) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.shapes = std::move(shapes);
    return scene;
}

long long count_set(const Raster<std::uint8_t>& mask) {
    long long n = 0;
    for (std::uint8_t v : mask.data) n += v ? 1 : 0;
    return n;
}

std::unique_ptr<Method> method(const std::string& spec) { return make_method(spec).method; }

// ---- 1. Jagged edges ----

TEST(EdgeBand, SquareBandIsCountedExactly) {
    // Square [10, 20]^2. Centres 8.5 and 21.5 lie exactly 1.5 px outside (in), 7.5 and 22.5
    // 2.5 px (out); inside, 11.5 is 1.5 px from the side (in), 12.5 is 2.5 px (out). At each
    // corner, the outside centres (8.5, 8.5), (9.5, 8.5), (8.5, 9.5) are sqrt(4.5), sqrt(2.5),
    // sqrt(2.5) > 1.5 px from the corner (out) and (9.5, 9.5) is sqrt(0.5) (in). So: the 14 x 14
    // pixels 8..21, minus the 6 x 6 interior 12..17, minus 3 per corner: 196 - 36 - 12 = 148.
    const Scene scene = scene_of(32, 32, {rectangle(10, 10, 20, 20)});
    const Raster<std::uint8_t> mask = edge_band_mask(scene);
    EXPECT_EQ(count_set(mask), 148);
    EXPECT_EQ(mask.at(8, 15), 1);  // exactly 1.5 px: inclusive
    EXPECT_EQ(mask.at(7, 15), 0);
    EXPECT_EQ(mask.at(21, 15), 1);
    EXPECT_EQ(mask.at(22, 15), 0);
    EXPECT_EQ(mask.at(11, 15), 1);
    EXPECT_EQ(mask.at(12, 15), 0);  // interior: says nothing about antialiasing
    EXPECT_EQ(mask.at(9, 9), 1);
    EXPECT_EQ(mask.at(9, 8), 0);
    EXPECT_EQ(mask.at(8, 8), 0);
}

// Every pixel against every edge: the slow, obviously right band.
Raster<std::uint8_t> brute_force_band(const Scene& scene, double d) {
    Raster<std::uint8_t> mask(scene.width, scene.height, 0);
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            const double px = i + 0.5, py = j + 0.5;
            for (const Shape& shape : scene.shapes) {
                for (const Contour& c : shape.contours) {
                    for (std::size_t k = 0; k < c.size(); ++k) {
                        const Point a = c[k], b = c[(k + 1) % c.size()];
                        const double ex = b.x - a.x, ey = b.y - a.y;
                        const double len2 = ex * ex + ey * ey;
                        double t = len2 > 0 ? ((px - a.x) * ex + (py - a.y) * ey) / len2 : 0.0;
                        t = std::clamp(t, 0.0, 1.0);
                        const double dx = px - a.x - t * ex, dy = py - a.y - t * ey;
                        if (dx * dx + dy * dy <= d * d) mask.at(i, j) = 1;
                    }
                }
            }
        }
    }
    return mask;
}

TEST(EdgeBand, MatchesBruteForceOnRandomPolygons) {
    constexpr int kScenes = 40;
    for (int seed = 0; seed < kScenes; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> coord(-8.0, 56.0), dist(0.0, 4.0);
        Scene scene = scene_of(48, 40, {});
        for (int s = 0; s < 3; ++s) {
            Shape shape;
            Contour contour;
            for (int k = 0; k < 5; ++k) contour.push_back({coord(rng), coord(rng)});
            shape.contours.push_back(contour);
            scene.shapes.push_back(shape);
        }
        const double d = dist(rng);
        const Raster<std::uint8_t> fast = edge_band_mask(scene, d);
        const Raster<std::uint8_t> slow = brute_force_band(scene, d);
        for (int j = 0; j < scene.height; ++j) {
            for (int i = 0; i < scene.width; ++i) {
                ASSERT_EQ(fast.at(i, j), slow.at(i, j)) << "seed " << seed << ", distance " << d
                                                        << ", pixel (" << i << ", " << j << ")";
            }
        }
    }
}

TEST(EdgeRmse, KnownErrorsOverTheMaskOnly) {
    Coverage ref(3, 1, 0.0);
    Image img(3, 1, 0.0f);
    img.at(0, 0) = 0.5f;   // masked
    img.at(1, 0) = 0.25f;  // masked
    img.at(2, 0) = 1.0f;   // not masked: does not count
    Raster<std::uint8_t> mask(3, 1, 0);
    mask.at(0, 0) = mask.at(1, 0) = 1;
    EXPECT_DOUBLE_EQ(edge_rmse(img, ref, mask), std::sqrt((0.25 + 0.0625) / 2.0));
    EXPECT_EQ(edge_rmse(img, ref, Raster<std::uint8_t>(3, 1, 0)), 0.0);  // no edges
    img.at(1, 0) = std::numeric_limits<float>::quiet_NaN();
    EXPECT_FALSE(edge_rmse(img, ref, mask) <= 1.0);  // NaN never looks small
}

TEST(EdgeRmse, ExactIsZeroOnTheStar) {
    const Scene scene = make_pattern("star", 128, 128);
    const Coverage ref = box_reference(scene);
    const Image img = render_scene(*method("exact"), scene);
    EXPECT_LE(edge_rmse(img, ref, edge_band_mask(scene)), kFloat32Rounding);
}

TEST(EdgeRmse, PointSamplingOfALongEdgeHasTheClosedFormError) {
    // The edge x = 8.3 + y / 128 over 512 rows (4 whole periods of the sub-pixel phase, 128
    // phases each, evenly spaced). In each row the pixel the edge crosses has coverage c, the
    // phase, and `none` gives it 0 or 1 by its centre: error c or c - 1, |error| <= 1/2, mean
    // square 1/12 over uniform phases. The band holds 3 pixels per row (centres within
    // 1.5 px), the whole image 16: edge RMSE sqrt(1/36) whatever the image width, image RMSE
    // sqrt(1/192), diluted by the interiors.
    constexpr double kSlope = 1.0 / 128.0;
    const Scene scene = scene_of(
        16, 512,
        {Shape{{{{-4, -4}, {8.3 - 4 * kSlope, -4}, {8.3 + 516 * kSlope, 516}, {-4, 516}}}}});
    // The phases are a regular grid of 128 per period (not a continuum): the mean of e^2 over
    // it differs from 1/12 by O(1/128^2); the rows whose edge crosses a column boundary (1/128
    // of them) change little. 1% covers both.
    constexpr double kClosedFormRelTolerance = 0.01;
    const Coverage ref = box_reference(scene);
    const Raster<std::uint8_t> mask = edge_band_mask(scene);
    EXPECT_EQ(count_set(mask), 3 * 512);
    const Image none = render_scene(*method("none"), scene);
    const double edge = edge_rmse(none, ref, mask);
    const double all = edge_rmse(none, ref, Raster<std::uint8_t>(16, 512, 1));
    EXPECT_NEAR(edge, std::sqrt(1.0 / 36.0), kClosedFormRelTolerance * std::sqrt(1.0 / 36.0));
    EXPECT_NEAR(all, std::sqrt(1.0 / 192.0), kClosedFormRelTolerance * std::sqrt(1.0 / 192.0));
    // An antialiased method on the same edge: exact in x, so (nearly) no jagged edge at all.
    const Image multiscan = render_scene(*method("box-multiscan"), scene);
    EXPECT_LT(edge_rmse(multiscan, ref, mask), 0.01 * edge);
}

// ---- 2. Vanishing thin objects: captured mass ----

TEST(CapturedMass, PointSamplingLosesAStripBetweenThePixelCentres) {
    // A vertical strip 0.1 px wide at x in [10.6, 10.7], between the pixel centres 10.5 and
    // 11.5: every point sampler whose samples miss that x range drops it completely. Methods
    // exact in x keep it all; box-multiscan's only error is at the two ends, in y, where its
    // trapezoidal rule over sub-scanlines 1/3 px apart is off by at most half a spacing each:
    // 2 * (1/6) / 24 px of length.
    const Shape strip = rectangle(10.6, 3.3, 10.7, 27.3);
    Scene scene = scene_of(32, 32, {strip});
    scene.thin_objects.push_back({"strip", strip});
    constexpr double kMultiscanEndError = 2.0 * (1.0 / 6.0) / 24.0;
    const MassReference ref = prepare_mass_reference(scene);
    ASSERT_EQ(ref.objects.size(), 1u);
    EXPECT_NEAR(ref.objects[0].exact_mass, 0.1 * 24.0, 1e-12 * 2.4);

    EXPECT_EQ(captured_masses(*method("none"), ref)[0], 0.0);
    // ssaa's 3 x 3 samples at 1/6, 1/2, 5/6 and nishita-d's lattice (the same x positions) miss
    // it too.
    EXPECT_EQ(captured_masses(*method("ssaa"), ref)[0], 0.0);
    EXPECT_EQ(captured_masses(*method("nishita-d"), ref)[0], 0.0);
    EXPECT_NEAR(captured_masses(*method("exact"), ref)[0], 1.0, kMassRatioTolerance);
    EXPECT_NEAR(captured_masses(*method("box-multiscan"), ref)[0], 1.0, kMultiscanEndError);
}

TEST(CapturedMass, WindowMassEqualsTheMassInPlace) {
    // The window is the object moved by whole pixels: a method's sum there is its sum over
    // the full image with the object alone, for every object of the strips pattern.
    const Scene scene = make_pattern("strips", 128, 96);
    const MassReference ref = prepare_mass_reference(scene);
    ASSERT_EQ(ref.objects.size(), scene.thin_objects.size());
    for (const char* spec : {"none", "exact", "box-multiscan"}) {
        const auto m = method(spec);
        const std::vector<double> masses = captured_masses(*m, ref);
        for (std::size_t k = 0; k < masses.size(); k += 7) {
            Scene alone = scene_of(scene.width, scene.height, {scene.thin_objects[k].shape});
            const Image full = render_scene(*m, alone);
            double sum = 0.0;
            for (float v : full.data) sum += v;
            EXPECT_NEAR(masses[k] * ref.objects[k].exact_mass, sum, kMassRatioTolerance * sum)
                << spec << " " << ref.objects[k].label;
        }
    }
}

TEST(CapturedMass, AndEdgeBandFollowTheWindowOrigin) {
    // The same strip in the window frame, [10.4, 10.7] (holding the centre 10.5), written once
    // with a zero origin and once in scene coordinates with the window at x = 0.25. Read in
    // scene coordinates without the origin, the second would hold no centre.
    auto strip_scene = [](double origin_x) {
        const Shape strip = rectangle(10.4 + origin_x, 3.3, 10.7 + origin_x, 27.3);
        Scene scene = scene_of(32, 32, {strip});
        scene.origin_x = origin_x;
        scene.thin_objects.push_back({"strip", strip});
        return scene;
    };
    const Scene plain = strip_scene(0.0), shifted = window_scene(strip_scene(0.25));
    const auto none = method("none");
    const double mass = captured_masses(*none, plain)[0];
    EXPECT_NEAR(mass, 1.0 / 0.3, kMassRatioTolerance * mass);  // one column of 24 samples
    EXPECT_NEAR(captured_masses(*none, shifted)[0], mass, kMassRatioTolerance * mass);
    EXPECT_EQ(edge_band_mask(shifted).data, edge_band_mask(plain).data);
}

TEST(CapturedMass, StripsPatternNoneLosesSomeExactKeepsAll) {
    const Scene scene = make_pattern("strips", 256, 256);
    const MassReference ref = prepare_mass_reference(scene);
    const MassStats none = summarise_masses(ref, captured_masses(*method("none"), ref));
    const MassStats exact = summarise_masses(ref, captured_masses(*method("exact"), ref));
    EXPECT_EQ(none.count, 40);
    EXPECT_EQ(none.worst, 0.0);  // at least one strip vanished altogether
    EXPECT_FALSE(none.worst_label.empty());
    EXPECT_NEAR(exact.worst, 1.0, kMassRatioTolerance);
    EXPECT_NEAR(exact.max, 1.0, kMassRatioTolerance);
    EXPECT_NEAR(exact.mean, 1.0, kMassRatioTolerance);
}

TEST(CapturedMass, SummaryPicksTheSmallestAndLargestAndNeverHidesNaN) {
    MassReference ref;
    for (const char* label : {"a", "b", "c"}) ref.objects.push_back({label, Scene{}, 1.0});
    const MassStats s = summarise_masses(ref, {0.9, 0.2, 1.6});
    EXPECT_EQ(s.worst, 0.2);
    EXPECT_EQ(s.worst_label, "b");
    EXPECT_EQ(s.max, 1.6);
    EXPECT_EQ(s.max_label, "c");
    EXPECT_DOUBLE_EQ(s.mean, 0.9);
    EXPECT_EQ(s.count, 3);
    const MassStats n = summarise_masses(ref, {0.9, std::nan(""), 1.0});
    EXPECT_FALSE(n.worst <= 1.0);
    EXPECT_FALSE(n.mean <= 1.0);
    EXPECT_TRUE(std::isnan(summarise_masses(MassReference{}, {}).worst));
}

// ---- 3. Moire: alias energy ----

TEST(AliasEnergy, ACosineErrorHasItsKnownEnergyInItsBand) {
    // Reference 0.5 everywhere, error 0.05 cos(2 pi f x): E_err / E_ref = (0.05^2 / 2) / 0.5^2
    // = -23.01 dB, all of it below half of Nyquist for f < 0.25 and none of it above. The Hann
    // window weighs both alike, so it cancels; what is left is the window's leakage (f is many
    // bins from 0 and from 0.25) and the float32 rounding of the image.
    constexpr int kSide = 128;
    constexpr double kAmplitude = 0.05, kLevel = 0.5;
    const double expected_db = 10.0 * std::log10(kAmplitude * kAmplitude / 2.0 / (kLevel * kLevel));
    constexpr double kLeakageDb = 0.01;     // measured: within 0.001 dB
    constexpr double kOutOfBandDb = -60.0;  // measured: -72 dB at f = 0.3, -79 dB at f = 0.4
    for (const double f : {0.05, 0.1, 0.2, 0.3, 0.4}) {
        SCOPED_TRACE(fmt::format("f = {}", f));
        const Coverage ref(kSide, kSide, kLevel);
        Image img(kSide, kSide);
        for (int j = 0; j < kSide; ++j) {
            for (int i = 0; i < kSide; ++i) {
                img.at(i, j) = static_cast<float>(
                    kLevel + kAmplitude * std::cos(2 * pi * f * (i + 0.5) + 0.3));
            }
        }
        const AliasEnergy e = alias_energy(img, ref);
        EXPECT_NEAR(e.total_db, expected_db, kLeakageDb);
        if (f < kLowFrequencyCyclesPerPx) {
            EXPECT_NEAR(e.low_db, expected_db, kLeakageDb);
        } else {
            EXPECT_LT(e.low_db, kOutOfBandDb);
        }
    }
}

TEST(AliasEnergy, UniformOffsetIsBiasNotPatternAndFlatReferenceIsUndefined) {
    const Coverage ref(16, 16, 0.5);
    const Image offset(16, 16, 0.75f);
    EXPECT_EQ(alias_energy(offset, ref).total_db, -std::numeric_limits<double>::infinity());
    EXPECT_TRUE(std::isnan(alias_energy(offset, Coverage(16, 16, 0.0)).total_db));
}

TEST(AliasEnergy, GratingAtThePixelPitchUnderNoneIsMoire) {
    // Bars of period 1 px, 3 degrees from vertical: every pixel's box average is ~0.5, but
    // point sampling sees the bars at a phase that drifts by sin(3 deg) per row, a beat of
    // ~19 px, which is all low-frequency error. Measured at 128^2: none -0.38 dB below half
    // of Nyquist (as strong as the image itself), exact -160 dB (float32 rounding),
    // box-multiscan -86 dB. The asserted gaps leave 40-60 dB of margin.
    constexpr double kNoneOverExactDb = 100.0;
    constexpr double kNoneOverMultiscanDb = 40.0;
    constexpr double kNoneLowAtLeastDb = -6.0;  // at least a quarter of the image's energy
    const Scene scene = make_pattern("grating:period=1", 128, 128);
    const Coverage ref = box_reference(scene);
    const AliasEnergy none = alias_energy(render_scene(*method("none"), scene), ref);
    const AliasEnergy exact = alias_energy(render_scene(*method("exact"), scene), ref);
    const AliasEnergy multiscan = alias_energy(render_scene(*method("box-multiscan"), scene), ref);
    EXPECT_GT(none.low_db, kNoneLowAtLeastDb);
    EXPECT_GT(none.low_db - exact.low_db, kNoneOverExactDb);
    EXPECT_GT(none.low_db - multiscan.low_db, kNoneOverMultiscanDb);
    EXPECT_LE(none.low_db, none.total_db);
}

// ---- SSIM ----

TEST(Ssim, OneForIdenticalImagesLowerOtherwiseAndRangeAware) {
    // Identical up to float32 rounding: SSIM departs from 1 by ~(rounding / C2) ~ 1e-12.
    constexpr double kIdenticalTolerance = 1e-9;
    const Scene scene = make_pattern("star", 96, 96);
    const Coverage ref = box_reference(scene);
    const Image exact = render_scene(*method("exact"), scene);
    const Image none = render_scene(*method("none"), scene);
    EXPECT_NEAR(ssim(exact, ref), 1.0, kIdenticalTolerance);
    const double s = ssim(none, ref);
    EXPECT_LT(s, 0.99);
    EXPECT_GT(s, 0.0);
    // Scaling both images and the range together changes nothing.
    Coverage ref2 = ref;
    for (double& v : ref2.data) v *= 2.0;
    Image none2 = none;
    for (float& v : none2.data) v *= 2.0f;
    EXPECT_NEAR(ssim(none2, ref2, 2.0), s, kIdenticalTolerance);
}

TEST(Symptoms, TinyImagesAreHandled) {
    // A 1 x 1 or 2 x 2 image is a valid scene size: no figure may crash on it. The Hann window
    // of 1 or 2 samples is zero, so alias energy is undefined there (NaN).
    for (const int side : {1, 2, 3}) {
        SCOPED_TRACE(side);
        const Scene scene = scene_of(side, side, {rectangle(0.3, 0.2, 0.9, 0.7)});
        const Coverage ref = box_reference(scene);
        const Image none = render_scene(*method("none"), scene);
        const AliasEnergy e = alias_energy(none, ref);
        if (side < 3) {
            EXPECT_TRUE(std::isnan(e.total_db));
        }
        EXPECT_TRUE(std::isfinite(ssim(none, ref)));
        EXPECT_GE(edge_rmse(none, ref, edge_band_mask(scene)), 0.0);
    }
}

// ---- 4 and 5. Motion ----

TEST(Translated, MovesEveryShapeAndThinObject) {
    Scene scene = scene_of(8, 8, {rectangle(1, 2, 3, 4)});
    scene.thin_objects.push_back({"t", rectangle(5, 5, 6, 7)});
    scene.metadata = {{"pattern", "x"}};
    const Scene moved = translated(scene, 0.25, -1.5);
    EXPECT_EQ(moved.shapes[0], rectangle(1.25, 0.5, 3.25, 2.5));
    EXPECT_EQ(moved.thin_objects[0].shape, rectangle(5.25, 3.5, 6.25, 5.5));
    EXPECT_EQ(moved.thin_objects[0].label, "t");
    EXPECT_EQ(moved.metadata, scene.metadata);
    EXPECT_EQ(moved.width, 8);
}

TEST(Motion, ReferenceFramesMoveDiagonallyOverOnePixel) {
    const Scene scene = make_pattern("star", 48, 48);
    const MotionReference motion = prepare_motion_reference(scene, 4);
    ASSERT_EQ(motion.frames, 4);
    ASSERT_EQ(motion.prepared.size(), 4u);
    for (int t = 0; t < 4; ++t) {
        EXPECT_EQ(motion.prepared[t].pieces().scene(), translated(scene, t / 4.0, t / 4.0));
        EXPECT_EQ(motion.references[t].data, box_reference(motion.prepared[t].pieces()).data);
        EXPECT_EQ(motion.masses[t].objects.size(), scene.thin_objects.size());
    }
    EXPECT_THROW(prepare_motion_reference(scene, 0), std::invalid_argument);
}

TEST(Motion, ExactDoesNotCrawlNoneDoesOnAMovingEdge) {
    // A half-plane with a tilted edge moving over one pixel. `exact` is wrong by float32
    // rounding only, in every frame; `none` flips whole pixels as the edge passes their
    // centres. The edge sweeps about 1.5 pixels in each of the 32 rows, whose error deviates
    // by ~0.2 over the frames, and the mean runs over all 1024 pixels: ~0.01. Measured: exact
    // 5e-10, none 0.0096, box-multiscan 2.9e-5 (exact in x, so its error barely moves).
    constexpr double kNoneCrawlsAtLeast = 0.003;
    constexpr double kNoneOverMultiscan = 100.0;  // measured 340
    const Scene scene = scene_of(32, 32, {Shape{{{{-4, -4}, {14.3, -4}, {20.1, 36}, {-4, 36}}}}});
    const MotionReference motion = prepare_motion_reference(scene);
    EXPECT_EQ(motion.frames, kMotionFrames);
    const MotionStats exact = motion_symptoms(*method("exact"), motion);
    const MotionStats none = motion_symptoms(*method("none"), motion);
    EXPECT_LE(exact.crawl, kFloat32Rounding);
    EXPECT_GT(none.crawl, kNoneCrawlsAtLeast);
    EXPECT_GT(none.crawl,
              kNoneOverMultiscan * motion_symptoms(*method("box-multiscan"), motion).crawl);
    EXPECT_EQ(none.frames, kMotionFrames);
    // No thin objects: nothing to pop, said as NaN rather than a perfect 1.
    EXPECT_EQ(none.thin_objects, 0);
    EXPECT_TRUE(std::isnan(none.popping));
    // The one-call form gives the same.
    EXPECT_EQ(motion_symptoms(*method("none"), scene).crawl, none.crawl);
}

// A stand-in method: the exact answer times `gain_` plus `offset_`, where each is switched
// on only in frames whose first vertex has a fractional x >= 0.5 (the second half of a
// 16-frame path starting at a fraction of 1/32), or always when `always_` is set.
class SwitchingMethod : public Method {
public:
    SwitchingMethod(double gain, double offset, bool always)
        : gain_(gain), offset_(offset), always_(always) {}

protected:
    void draw_rows(const Scene& scene, Image& out, int row_lo, int row_hi) const override {
        const double x = scene.shapes.front().contours.front().front().x;
        const bool on = always_ || x - std::floor(x) >= 0.5;
        const Coverage c = box_reference(scene);
        const std::size_t first = static_cast<std::size_t>(row_lo) * scene.width;
        const std::size_t last = static_cast<std::size_t>(row_hi) * scene.width;
        for (std::size_t k = first; k < last; ++k) {
            const double v = on ? c.data[k] * gain_ + offset_ : c.data[k];
            out.data[k] = static_cast<float>(v);
        }
    }

private:
    double gain_, offset_;
    bool always_;
};

TEST(Motion, CrawlIsTheErrorsDeviationOverTimeNotItsSize) {
    // Frames 0..7 have fraction 1/32 + t/16 < 0.5, frames 8..15 >= 0.5. An error of 0.25 in
    // half of the frames and 0 in the other half: standard deviation 0.125 at every pixel.
    // The same error in every frame: no crawl at all.
    constexpr double kOffset = 0.25;
    const Scene scene = scene_of(12, 10, {rectangle(5.0 + 1.0 / 32, 3.3, 8.7, 6.1)});
    const MotionReference motion = prepare_motion_reference(scene);
    EXPECT_NEAR(motion_symptoms(SwitchingMethod(1.0, kOffset, false), motion).crawl, 0.5 * kOffset,
                2 * kFloat32Rounding);
    EXPECT_LE(motion_symptoms(SwitchingMethod(1.0, kOffset, true), motion).crawl,
              2 * kFloat32Rounding);
}

TEST(Motion, PoppingIsTheWorstMassRatioAcrossFrames) {
    // A small square whose mass is 1.5 x too large in half of the frames: popping 1.5.
    constexpr double kGain = 1.5;
    const Shape square = rectangle(5.0 + 1.0 / 32, 5.2, 5.9, 6.0);
    Scene scene = scene_of(12, 12, {square});
    scene.thin_objects.push_back({"square", square});
    const MotionStats s = motion_symptoms(SwitchingMethod(kGain, 0.0, false), scene);
    EXPECT_EQ(s.thin_objects, 1);
    EXPECT_FALSE(s.popping_infinite);
    EXPECT_NEAR(s.popping, kGain, kGain * kMassRatioTolerance);
    EXPECT_EQ(s.popping_worst_label, "square");
}

TEST(Motion, ASmallSquarePopsUnderPointSamplingAndNotUnderExact) {
    // A 0.3 px square at [10.1, 10.4]^2 moving by (t/16, t/16): it holds the pixel centre
    // (10.5, 10.5) only for offsets in (0.1, 0.4], frames 2..6, and vanishes in the others.
    const Shape square = rectangle(10.1, 10.1, 10.4, 10.4);
    Scene scene = scene_of(24, 24, {square});
    scene.thin_objects.push_back({"square 0.3", square});
    const MotionReference motion = prepare_motion_reference(scene);
    const MotionStats none = motion_symptoms(*method("none"), motion);
    EXPECT_TRUE(none.popping_infinite);
    EXPECT_EQ(none.popping, std::numeric_limits<double>::infinity());
    EXPECT_EQ(none.popping_worst_label, "square 0.3");
    const MotionStats exact = motion_symptoms(*method("exact"), motion);
    EXPECT_FALSE(exact.popping_infinite);
    EXPECT_NEAR(exact.popping, 1.0, kMassRatioTolerance);
}

}  // namespace
}  // namespace aabench
