// ꟻLIP (Andersson et al. 2020) and the sRGB rmse (harness/measure/flip.h), checked against the
// paper's building blocks: its viewing conditions, the contrast sensitivity filters, the
// Hunt-adjusted HyAB difference of its largest colour error, the redistribution's bend, the
// feature detectors on a step edge, and whole maps whose answer follows from those by hand.
#include "harness/measure/flip.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

namespace aabench {
namespace {

using flip::Vec3;

// Sums of a few hundred doubles and the constants below, worked by hand from the paper's
// formulas to 6 significant digits: agreement to 1e-5 relative is the same arithmetic.
constexpr double kHandWorked = 1e-5;
// Kernel sums in double over at most 21 x 21 weights.
constexpr double kSumRounding = 1e-12;

// The paper's default viewing conditions: 0.7 m from a 0.7 m wide 3840 px monitor.
constexpr double kDefaultPpd = 67.020643;
// Hunt-adjusted CIELAB of the green and blue primaries, and their HyAB distance: the largest
// colour difference, which the redistribution maps to 1.
constexpr double kGreenBlueHyab = 203.301655;
constexpr double kMaxColourError = 41.276098;  // kGreenBlueHyab^0.7
// Black against white everywhere: HyAB 100 (L* 0 and 100, no chroma), 100^0.7 = 25.1189 lies
// above the bend (0.4 * 41.2761 = 16.5104): 0.95 + (25.1189 - 16.5104) / (41.2761 - 16.5104) *
// 0.05. No features in a flat image, so this is the ꟻLIP value.
constexpr double kBlackWhiteFlip = 0.967380;
// L* of a linear grey 0.5: 116 * 0.5^(1/3) - 16.
constexpr double kLightnessOfHalf = 76.069261;
// sRGB encoding of 0.5: 1.055 * 0.5^(1/2.4) - 0.055.
constexpr double kSrgbOfHalf = 0.735357;

double relative_error(double value, double expected) {
    return std::abs(value - expected) / std::abs(expected);
}

Image uniform_image(int w, int h, float value) { return Image(w, h, value); }
Coverage uniform_reference(int w, int h, double value) { return Coverage(w, h, value); }

TEST(Flip, PixelsPerDegreeOfThePapersMonitor) {
    EXPECT_LT(relative_error(flip::pixels_per_degree(), kDefaultPpd), kHandWorked);
}

TEST(Flip, ContrastSensitivityFiltersSumToOneAndAreRadiallySymmetric) {
    const double ppd = flip::pixels_per_degree();
    for (int channel = 0; channel < 3; ++channel) {
        const flip::Kernel k = flip::csf_kernel(channel, ppd);
        // Three sd of the widest Gaussian (b = 0.04 deg^2): ceil(3 * 0.045016 * 67.02) = 10.
        EXPECT_EQ(k.radius, 10) << channel;
        const double sum = std::accumulate(k.weights.begin(), k.weights.end(), 0.0);
        EXPECT_NEAR(sum, 1.0, kSumRounding) << channel;
        EXPECT_DOUBLE_EQ(k.at(3, 1), k.at(-1, -3)) << channel;
        EXPECT_GT(k.at(0, 0), k.at(1, 0)) << channel;
    }
    // The blue-yellow channel sees only coarse detail: its filter is the widest, so its centre
    // weight the smallest.
    EXPECT_LT(flip::csf_kernel(2, ppd).at(0, 0), flip::csf_kernel(0, ppd).at(0, 0));
    EXPECT_THROW(flip::csf_kernel(3, ppd), std::invalid_argument);
}

TEST(Flip, HuntAdjustedHyabOfGreenAndBlueIsTheLargestColourError) {
    const Vec3 green = flip::hunt_adjust(flip::xyz_to_lab(flip::linear_rgb_to_xyz({0, 1, 0})));
    const Vec3 blue = flip::hunt_adjust(flip::xyz_to_lab(flip::linear_rgb_to_xyz({0, 0, 1})));
    EXPECT_LT(relative_error(flip::hyab(green, blue), kGreenBlueHyab), kHandWorked);
    EXPECT_LT(relative_error(flip::max_colour_error(), kMaxColourError), kHandWorked);
    // Hunt: chroma scaled by L / 100, lightness kept.
    const Vec3 adjusted = flip::hunt_adjust({50.0, 20.0, -10.0});
    EXPECT_DOUBLE_EQ(adjusted[0], 50.0);
    EXPECT_DOUBLE_EQ(adjusted[1], 10.0);
    EXPECT_DOUBLE_EQ(adjusted[2], -5.0);
    // HyAB: city-block in lightness, Euclidean in chroma.
    EXPECT_DOUBLE_EQ(flip::hyab({10, 0, 0}, {13, 3, 4}), 3.0 + 5.0);
}

TEST(Flip, ColourTransformsRoundTripAndGreyHasNoChroma) {
    const Vec3 rgb = {0.2, 0.5, 0.9};
    const Vec3 back = flip::xyz_to_linear_rgb(
        flip::ycxcz_to_xyz(flip::xyz_to_ycxcz(flip::linear_rgb_to_xyz(rgb))));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], rgb[c], kSumRounding);
    const Vec3 grey = flip::xyz_to_ycxcz(flip::linear_rgb_to_xyz({0.3, 0.3, 0.3}));
    EXPECT_NEAR(grey[1], 0.0, kSumRounding);
    EXPECT_NEAR(grey[2], 0.0, kSumRounding);
    const Vec3 lab = flip::xyz_to_lab(flip::linear_rgb_to_xyz({0.5, 0.5, 0.5}));
    EXPECT_LT(relative_error(lab[0], kLightnessOfHalf), kHandWorked);
}

TEST(Flip, RedistributionBendsAtPcAndEndsAtOne) {
    const double m = flip::max_colour_error();
    EXPECT_DOUBLE_EQ(flip::redistribute_colour_error(0.0, m), 0.0);
    EXPECT_NEAR(flip::redistribute_colour_error(0.4 * m, m), 0.95, kSumRounding);
    EXPECT_NEAR(flip::redistribute_colour_error(m, m), 1.0, kSumRounding);
    EXPECT_NEAR(flip::redistribute_colour_error(0.2 * m, m), 0.475, kSumRounding);
}

TEST(Flip, FeatureDetectorsAreNormalisedAndAStepEdgeGivesTheFullEdgeResponse) {
    const double ppd = flip::pixels_per_degree();
    for (bool point : {false, true}) {
        const flip::Kernel k = flip::feature_kernel(point, ppd);
        // sd = 0.5 * 0.082 * 67.02 = 2.748 px; three of them: 9 px.
        EXPECT_EQ(k.radius, 9);
        double positive = 0.0, negative = 0.0;
        for (double w : k.weights) (w > 0 ? positive : negative) += w;
        EXPECT_NEAR(positive, 1.0, kSumRounding) << point;
        EXPECT_NEAR(negative, -1.0, kSumRounding) << point;
    }
    // A vertical step 0 | 1 under the edge detector, centred on the first lit column: every
    // weight on the lit side is negative (-x g), those of the centre column are 0, so the
    // response is the negative sum, -1: the largest an edge can give. Far from the step it is 0.
    const flip::Kernel edge = flip::feature_kernel(false, ppd);
    const auto response = [&](int offset) {  // the step at column `offset` of the window
        double sum = 0.0;
        for (int dy = -edge.radius; dy <= edge.radius; ++dy) {
            for (int dx = -edge.radius; dx <= edge.radius; ++dx) {
                sum += edge.at(dx, dy) * (dx >= offset ? 1.0 : 0.0);
            }
        }
        return sum;
    };
    EXPECT_NEAR(response(0), -1.0, kSumRounding);
    EXPECT_NEAR(response(edge.radius + 1), 0.0, kSumRounding);  // all dark
    EXPECT_NEAR(response(-edge.radius), 0.0, kSumRounding);     // all lit
}

TEST(Flip, IdenticalImagesScoreZero) {
    Image test(24, 20);
    Coverage reference(24, 20);
    for (std::size_t p = 0; p < test.pixel_count(); ++p) {
        const double v = (p * 37 % 101) / 100.0;  // detail everywhere: features on both sides
        test.data[p] = static_cast<float>(v);
        reference.data[p] = static_cast<float>(v);  // the same float, so truly identical
    }
    EXPECT_EQ(flip::mean_flip(test, reference), 0.0);
    EXPECT_EQ(flip::srgb_rmse(test, reference), 0.0);
}

TEST(Flip, BlackAgainstWhiteGivesTheKnownMaximumOfAFlatPair) {
    const Coverage map = flip::flip_map(uniform_image(16, 16, 0.0f), uniform_reference(16, 16, 1.0),
                                        flip::pixels_per_degree());
    for (double v : map.data) ASSERT_LT(relative_error(v, kBlackWhiteFlip), kHandWorked);
    EXPECT_LT(
        relative_error(flip::mean_flip(uniform_image(16, 16, 1.0f), uniform_reference(16, 16, 0.0)),
                       kBlackWhiteFlip),
        kHandWorked);
    // Out-of-range values are clamped to [0, 1] as LDR-ꟻLIP's domain: no larger error.
    EXPECT_LT(relative_error(
                  flip::mean_flip(uniform_image(16, 16, 3.0f), uniform_reference(16, 16, -1.0)),
                  kBlackWhiteFlip),
              kHandWorked);
}

TEST(Flip, GreyDifferenceIsTheLightnessDifference) {
    // Grey 0.5 against black, both flat: HyAB = L*(0.5) - 0, below the bend.
    const double expected =
        flip::redistribute_colour_error(std::pow(kLightnessOfHalf, 0.7), flip::max_colour_error());
    EXPECT_LT(
        relative_error(flip::mean_flip(uniform_image(12, 12, 0.5f), uniform_reference(12, 12, 0.0)),
                       expected),
        kHandWorked);
}

TEST(Flip, SrgbRmseEncodesBeforeComparing) {
    EXPECT_LT(relative_error(flip::srgb_encode(0.5), kSrgbOfHalf), kHandWorked);
    EXPECT_DOUBLE_EQ(flip::srgb_encode(-1.0), 0.0);
    EXPECT_DOUBLE_EQ(flip::srgb_encode(2.0), 1.0);
    EXPECT_LT(
        relative_error(flip::srgb_rmse(uniform_image(4, 4, 0.5f), uniform_reference(4, 4, 0.0)),
                       kSrgbOfHalf),
        kHandWorked);
}

TEST(Flip, NonFinitePixelsGiveNaNAndSizesMustMatch) {
    Image test = uniform_image(8, 8, 0.5f);
    test.at(3, 3) = std::nanf("");
    const Coverage reference = uniform_reference(8, 8, 0.5);
    EXPECT_TRUE(std::isnan(flip::mean_flip(test, reference)));
    EXPECT_TRUE(std::isnan(flip::srgb_rmse(test, reference)));
    EXPECT_THROW(flip::flip_map(uniform_image(8, 4, 0.0f), reference, 67.0), std::invalid_argument);
    EXPECT_THROW(flip::srgb_rmse(uniform_image(8, 4, 0.0f), reference), std::invalid_argument);
}

// The map filters by the kernels' separable factors: their products are the kernels.
TEST(Flip, SeparableFactorsRebuildTheKernels) {
    constexpr double kFactorRounding = 1e-15;  // a product of two roundings beside one
    for (const double ppd : {flip::pixels_per_degree(), 12.5, 140.0}) {
        const auto same = [&](const flip::Kernel& a, const flip::Kernel& b, const char* what) {
            ASSERT_EQ(a.radius, b.radius) << what << " " << ppd;
            for (std::size_t k = 0; k < a.weights.size(); ++k) {
                ASSERT_NEAR(a.weights[k], b.weights[k], kFactorRounding) << what << " " << k;
            }
        };
        for (int c = 0; c < 3; ++c) {
            same(flip::csf_kernel(c, ppd), flip::csf_kernel_from_factors(c, ppd), "csf");
        }
        for (bool point : {false, true}) {
            same(flip::feature_kernel(point, ppd), flip::feature_kernel_from_factors(point, ppd),
                 point ? "point" : "edge");
        }
    }
}

// The reference's half prepared once (compare does, per pattern) gives every image's map to
// the bit, and refuses a preparation made at another viewing distance.
TEST(Flip, APreparedReferenceGivesTheSameMapToTheBit) {
    Coverage reference(40, 30);
    for (std::size_t p = 0; p < reference.pixel_count(); ++p) {
        reference.data[p] = (p * 53 % 97) / 96.0;
    }
    const double ppd = flip::pixels_per_degree();
    const flip::FlipReference prepared = flip::prepare_flip_reference(reference, ppd);
    for (int seed = 0; seed < 3; ++seed) {
        Image test(40, 30);
        for (std::size_t p = 0; p < test.pixel_count(); ++p) {
            test.data[p] = static_cast<float>(((p + 11 * seed) * 29 % 89) / 88.0);
        }
        const Coverage direct = flip::flip_map(test, reference, ppd);
        const Coverage shared = flip::flip_map(test, prepared);
        ASSERT_EQ(direct.data, shared.data) << seed;
        EXPECT_EQ(flip::mean_flip(test, reference), flip::mean_flip(test, prepared)) << seed;
    }
    EXPECT_THROW(flip::flip_map(Image(8, 8), prepared), std::invalid_argument);
    const flip::FlipReference elsewhere = flip::prepare_flip_reference(reference, 2.0 * ppd);
    EXPECT_THROW(flip::mean_flip(Image(40, 30), elsewhere), std::invalid_argument);
}

}  // namespace
}  // namespace aabench
