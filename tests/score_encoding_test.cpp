// aabench score reads what a PNG says about its codes: the report's 8-bit views (the sRGB chunk),
// aabench's 16-bit linear PNGs (gAMA 1.0), untagged files by their bit depth, and overrides.
// The promise: with no flag, a method's report view scores as its EXR does, within 8-bit sRGB
// quantisation, and the reading says which encoding it assumed and why.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "harness/measure/score.h"
#include "harness/report/html_parts.h"
#include "harness/report/image_io.h"
#include "harness/report/image_read.h"
#include "harness/report/png_codec.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

constexpr int kSide = 64;

// An 8-bit sRGB code stands for every linear value that rounds to it: at most half the largest
// gap between neighbouring decoded codes away, and the largest gap is the top one (the curve is
// steepest in linear light there). |rmse(a) - rmse(b)| <= max |a - b|.
double half_largest_srgb_step() {
    return 0.5 * (1.0 - srgb_to_linear(254.0 / 255.0));
}
// How far a view read with the wrong decoding must move the error, in units of that bound.
constexpr double kWrongDecodingFactor = 4.0;
// A 16-bit code is round(v * 65535): half a step.
constexpr double kHalf16BitStep = 0.5 / 65535.0;

class ScoreEncoding : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               fmt::format("aabench_score_encoding_{}", ::testing::UnitTest::GetInstance()
                                                            ->current_test_info()
                                                            ->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

TEST_F(ScoreEncoding, ReportViewsScoreAsTheirExrOnEvery2DPattern) {
    const double bound = half_largest_srgb_step();
    const MethodInstance m = make_method("box-multiscan");
    int patterns = 0;
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        const Scene scene = make_pattern(p.id, kSide, kSide);
        if (scene.world || !p.in_default_run) continue;
        const auto [lo, hi] = scene.value_range();
        if (lo < 0.0 || hi > 1.0) continue;  // a view clamps to [0, 1]
        ++patterns;
        const Image rendered = render_scene(*m.method, scene);
        write_image(path("r.exr"), rendered);
        html_parts::write_png_view(path("view.png"), html_parts::display_view(rendered));
        const ScoredImage exr = read_image_to_score(path("r.exr"), Encoding::kAuto);
        const ScoredImage png = read_image_to_score(path("view.png"), Encoding::kAuto);
        EXPECT_EQ(exr.used, Encoding::kLinear);
        EXPECT_EQ(png.used, Encoding::kSrgb) << p.id;
        EXPECT_NE(png.why.find("sRGB chunk"), std::string::npos) << png.why;
        const ResultRow a = score_image(exr.image, scene, "box", "r.exr");
        const ResultRow b = score_image(png.image, scene, "box", "view.png");
        EXPECT_LE(std::abs(a[metric::kBoxRmse] - b[metric::kBoxRmse]), bound)
            << p.id << ": exr " << a[metric::kBoxRmse] << " png " << b[metric::kBoxRmse];
        // Read as linear, as before the files were tagged, the view is far off: the default
        // matters (the code of half-covered edge pixels is ~0.74 where the light is 0.5).
        // Measured at 64^2: at least 8 times the bound (circles), far more on the others.
        const ResultRow wrong =
            score_image(read_image_to_score(path("view.png"), Encoding::kLinear).image, scene,
                        "box", "view.png");
        EXPECT_GT(wrong[metric::kBoxRmse] - a[metric::kBoxRmse], kWrongDecodingFactor * bound) << p.id;
    }
    EXPECT_GE(patterns, 5);
}

TEST_F(ScoreEncoding, SixteenBitPngsSayTheyAreLinear) {
    const Scene scene = make_pattern("star", kSide, kSide);
    const Image rendered = render_scene(*make_method("exact").method, scene);
    write_image(path("r.png"), rendered);
    const std::optional<PngTags> tags = read_png_tags(path("r.png"));
    ASSERT_TRUE(tags.has_value());
    EXPECT_EQ(tags->bit_depth, 16);
    EXPECT_FALSE(tags->srgb);
    ASSERT_TRUE(tags->gamma.has_value());
    EXPECT_DOUBLE_EQ(*tags->gamma, 1.0);
    const ScoredImage read = read_image_to_score(path("r.png"), Encoding::kAuto);
    EXPECT_EQ(read.used, Encoding::kLinear);
    EXPECT_EQ(read.gamma, 0.0);
    for (std::size_t k = 0; k < rendered.data.size(); ++k) {
        ASSERT_NEAR(read.image.data[k], std::clamp(rendered.data[k], 0.0f, 1.0f),
                    kHalf16BitStep + 1e-7)
            << k;
    }
}

// Files written by a renderer without colour chunks (OpenCV's encoder writes none): 8-bit is
// taken as sRGB, 16-bit as linear; --linear and --srgb override; float is never sRGB.
TEST_F(ScoreEncoding, UntaggedFilesGoByBitDepthAndFlagsOverride) {
    cv::Mat eight(4, 4, CV_8UC1, cv::Scalar(128));
    cv::Mat sixteen(4, 4, CV_16UC1, cv::Scalar(32768));
    ASSERT_TRUE(cv::imwrite(path("u8.png"), eight));
    ASSERT_TRUE(cv::imwrite(path("u16.png"), sixteen));
    const std::optional<PngTags> t8 = read_png_tags(path("u8.png"));
    ASSERT_TRUE(t8.has_value());
    EXPECT_FALSE(t8->srgb || t8->gamma || t8->icc);
    const ScoredImage a = read_image_to_score(path("u8.png"), Encoding::kAuto);
    EXPECT_EQ(a.used, Encoding::kSrgb);
    EXPECT_NE(a.why.find("untagged 8-bit"), std::string::npos) << a.why;
    EXPECT_FLOAT_EQ(a.image.data[0], static_cast<float>(srgb_to_linear(128.0 / 255.0)));
    const ScoredImage b = read_image_to_score(path("u16.png"), Encoding::kAuto);
    EXPECT_EQ(b.used, Encoding::kLinear);
    EXPECT_FLOAT_EQ(b.image.data[0], static_cast<float>(32768.0 / 65535.0));
    EXPECT_FLOAT_EQ(read_image_to_score(path("u8.png"), Encoding::kLinear).image.data[0],
                    static_cast<float>(128.0 / 255.0));
    EXPECT_EQ(read_image_to_score(path("u16.png"), Encoding::kSrgb).used, Encoding::kSrgb);
    write_image(path("f.exr"), Image(4, 4, 0.5f));
    EXPECT_THROW(read_image_to_score(path("f.exr"), Encoding::kSrgb), InputError);
    EXPECT_FALSE(read_png_tags(path("f.exr")).has_value());
}

}  // namespace
}  // namespace aabench
