// aabench score: an image from anywhere scored like a method's render in compare. The central
// promise: a render written exactly (EXR float32 holds the float image bit for bit) and scored
// gives compare's figures, equal, for every method; PNG and sRGB reading within their steps;
// bad input is one line and exit 2.
#include "harness/measure/score.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "harness/measure/compare.h"
#include "harness/reference/filter_reference.h"
#include "harness/report/image_io.h"
#include "harness/report/image_read.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// A 16-bit PNG code is round(v * 65535): each pixel within half a step of the float value, and
// |rmse(a) - rmse(b)| <= max |a - b| (triangle inequality), so every figure that is a mean or
// max of per-pixel errors moves by at most this.
constexpr double kHalf16BitStep = 0.5 / 65535.0;
// Decoded codes are stored as float32: half an ulp at 1.0.
constexpr double kFloatRounding = 6e-8;

constexpr int kWidth = 40;
constexpr int kHeight = 32;

void expect_same(double a, double b, const std::string& what) {
    if (std::isnan(a) && std::isnan(b)) return;
    EXPECT_EQ(a, b) << what;
}

// The figures score shares with a compare row, compared for equality.
void expect_same_figures(const ResultRow& score, const ResultRow& row, const std::string& what) {
    EXPECT_EQ(score.reference_filter, row.reference_filter) << what;
    EXPECT_EQ(score.edges, row.edges) << what;
    expect_same(score[metric::kBoxRmse], row[metric::kBoxRmse], what + " box_rmse");
    expect_same(score[metric::kBoxMaxAbs], row[metric::kBoxMaxAbs], what + " box_max_abs");
    EXPECT_EQ(score[metric::kBoxMaxX], row[metric::kBoxMaxX]) << what;
    EXPECT_EQ(score[metric::kBoxMaxY], row[metric::kBoxMaxY]) << what;
    expect_same(score[metric::kBoxBias], row[metric::kBoxBias], what + " box_bias");
    expect_same(score[metric::kDropout], row[metric::kDropout], what + " dropout");
    expect_same(score[metric::kOwnRmse], row[metric::kOwnRmse], what + " own_rmse");
    expect_same(score[metric::kOwnMaxAbs], row[metric::kOwnMaxAbs], what + " own_max_abs");
    expect_same(score[metric::kEdgeRmse], row[metric::kEdgeRmse], what + " edge_rmse");
    expect_same(score[metric::kAliasTotalDb], row[metric::kAliasTotalDb], what + " alias_total_db");
    expect_same(score[metric::kAliasLowDb], row[metric::kAliasLowDb], what + " alias_low_db");
    expect_same(score[metric::kSsim], row[metric::kSsim], what + " ssim");
    expect_same(score[metric::kSeamsMax], row[metric::kSeamsMax], what + " seams_max");
    expect_same(score[metric::kSeamsMean], row[metric::kSeamsMean], what + " seams_mean");
}

class Score : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               fmt::format("aabench_score_{}_{}", ::getpid(),
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

TEST_F(Score, EveryMethodsRenderThroughAnExrScoresAsInCompare) {
    for (const char* pattern : {"star", "blocks"}) {
        CompareOptions options;
        options.pattern_specs = {pattern};
        options.width = kWidth;
        options.height = kHeight;
        options.runs = 1;
        options.motion_frames = 2;
        options.keep_images = false;
        const CompareResult result = run_comparison(options);
        const Scene scene = make_pattern(pattern, kWidth, kHeight);
        for (const ResultRow& row : result.rows) {
            if (!row.not_applicable.empty()) continue;  // drew nothing (circle methods): no image
            const std::string exr = path("render.exr");
            const MethodInstance m = make_method(row.method);
            // The scene compare hands the method: the ScreenScene for own visibility.
            write_image(exr, render_scene(*m.method, PreparedFrame::prepare(scene).input_for(*m.method)));
            const ResultRow scored =
                score_image(read_image_to_score(exr, false), scene, row.reference_filter, exr);
            expect_same_figures(scored, row, fmt::format("{} / {}", pattern, row.method));
        }
    }
}

struct Output {
    int exit_code;
    std::string out;
    std::string err;
};

Output run(const std::string& args, const fs::path& dir) {
    const fs::path out_file = dir / "stdout", err_file = dir / "stderr";
    const std::string cmd =
        fmt::format("{} {} >{} 2>{}", AABENCH_BINARY, args, out_file.string(), err_file.string());
    const int status = std::system(cmd.c_str());
    auto slurp = [](const fs::path& p) {
        std::ifstream in(p);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out_file), slurp(err_file)};
}

TEST_F(Score, CommandOnARenderFromTheCommandLineGivesComparesFigures) {
    // A box method on a 2-D pattern, a Gaussian one (own filter differs), a 3-D pattern.
    for (const auto& [pattern, method] :
         {std::pair{"star", "box-multiscan"}, std::pair{"star", "gauss-multiscan:n=6"},
          std::pair{"room", "none"}}) {
        CompareOptions options;
        options.pattern_specs = {pattern};
        options.method_specs = {method};
        options.width = kWidth;
        options.height = kHeight;
        options.runs = 1;
        options.motion_frames = 2;
        options.keep_images = false;
        const ResultRow row = run_comparison(options).rows.at(0);
        const std::string size = fmt::format("{}x{}", kWidth, kHeight);
        ASSERT_EQ(run(fmt::format("render --pattern {} --size {} --method {} --out {}", pattern,
                                  size, method, path("r.exr")),
                      dir_)
                      .exit_code,
                  0);
        const Output o = run(fmt::format("score {} --pattern {} --size {} --filter {} --json",
                                         path("r.exr"), pattern, size, row.reference_filter),
                             dir_);
        ASSERT_EQ(o.exit_code, 0) << o.err;
        const nlohmann::json j = nlohmann::json::parse(o.out);
        const std::string what = fmt::format("{} / {}", pattern, method);
        auto num = [&j](const char* key) {
            return j.at(key).is_null() ? std::nan("") : j.at(key).get<double>();
        };
        EXPECT_EQ(j.at("pattern").get<std::string>(), row.pattern);
        EXPECT_EQ(j.at("reference_filter").get<std::string>(), row.reference_filter);
        expect_same(num("box_rmse"), row[metric::kBoxRmse], what);
        expect_same(num("box_max_abs"), row[metric::kBoxMaxAbs], what);
        expect_same(num("box_bias"), row[metric::kBoxBias], what);
        expect_same(num("dropout"), row[metric::kDropout], what);
        expect_same(num("own_rmse"), row[metric::kOwnRmse], what);
        expect_same(num("edge_rmse"), row[metric::kEdgeRmse], what);
        expect_same(num("alias_low_db"), row[metric::kAliasLowDb], what);
        expect_same(num("ssim"), row[metric::kSsim], what);
        expect_same(num("seams_max"), row[metric::kSeamsMax], what);
    }
}

TEST_F(Score, A16BitPngScoresWithinHalfAStepOfTheExr) {
    const Scene scene = make_pattern("strips", kWidth, kHeight);
    const Image image = render_scene(*make_method("box-multiscan").method, scene);
    write_image(path("r.exr"), image);
    write_image(path("r.png"), image);
    const ResultRow exr = score_image(read_image_to_score(path("r.exr"), false), scene, "box", "e");
    const ResultRow png = score_image(read_image_to_score(path("r.png"), false), scene, "box", "p");
    EXPECT_NEAR(png[metric::kBoxRmse], exr[metric::kBoxRmse], kHalf16BitStep);
    EXPECT_NEAR(png[metric::kBoxMaxAbs], exr[metric::kBoxMaxAbs], kHalf16BitStep);
    EXPECT_NEAR(png[metric::kBoxBias], exr[metric::kBoxBias], kHalf16BitStep);
    EXPECT_NEAR(png[metric::kEdgeRmse], exr[metric::kEdgeRmse], kHalf16BitStep);
}

TEST(ScoreSrgb, TransferFunctionPoints) {
    EXPECT_EQ(srgb_to_linear(0.0), 0.0);
    EXPECT_NEAR(srgb_to_linear(1.0), 1.0, 1e-15);
    // The two pieces meet at 0.04045 (to the 1e-8 the standard's rounded constants allow).
    constexpr double kJoinMismatch = 1e-8;
    EXPECT_NEAR(0.04045 / 12.92, std::pow((0.04045 + 0.055) / 1.055, 2.4), kJoinMismatch);
    // Mid grey: code 0.5 is 0.21404 of the light (a well-known value).
    EXPECT_NEAR(srgb_to_linear(0.5), 0.214041140, 1e-9);
}

TEST_F(Score, EightBitPngCodesAreLinearByDefaultAndDecodedWithSrgb) {
    // Grey codes 0..255 in a 16x16 image; and the same as RGBA with alpha 128.
    std::vector<std::uint8_t> grey(256), rgba(256 * 4);
    for (int k = 0; k < 256; ++k) {
        grey[k] = static_cast<std::uint8_t>(k);
        for (int c = 0; c < 3; ++c) rgba[4 * k + c] = static_cast<std::uint8_t>(k);
        rgba[4 * k + 3] = 128;
    }
    write_display_png(path("grey.png"), 16, 16, 1, grey.data());
    write_display_png(path("rgba.png"), 16, 16, 4, rgba.data());
    const Image linear = read_image_to_score(path("grey.png"), false);
    const Image decoded = read_image_to_score(path("grey.png"), true);
    const Image alpha_linear = read_image_to_score(path("rgba.png"), false);
    const Image alpha_decoded = read_image_to_score(path("rgba.png"), true);
    const double alpha = 128.0 / 255.0;
    for (int k = 0; k < 256; ++k) {
        EXPECT_NEAR(linear.data[k], k / 255.0, kFloatRounding) << k;
        EXPECT_NEAR(decoded.data[k], srgb_to_linear(k / 255.0), kFloatRounding) << k;
        // Over black: value x alpha (alpha applied to light, after decoding).
        EXPECT_NEAR(alpha_linear.data[k], k / 255.0 * alpha, kFloatRounding) << k;
        EXPECT_NEAR(alpha_decoded.data[k], srgb_to_linear(k / 255.0) * alpha, kFloatRounding) << k;
    }
}

void expect_one_line_error(const Output& o, const std::string& needle) {
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_NE(o.err.find(needle), std::string::npos) << o.err;
    EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << o.err;
    EXPECT_EQ(o.out, "");
}

TEST_F(Score, BadInputIsOneLineAndExitTwo) {
    const Scene scene = make_pattern("star", 16, 16);
    write_image(path("r.exr"), render_scene(*make_method("none").method, scene));
    expect_one_line_error(
        run(fmt::format("score {} --pattern star --size 16x12", path("r.exr")), dir_),
        "the image is 16x16 but the scene is 16x12");
    expect_one_line_error(
        run(fmt::format("score {} --pattern star --size 16x16 --filter tent", path("r.exr")), dir_),
        "--filter");
    expect_one_line_error(
        run(fmt::format("score {} --pattern star --size 16x16 --srgb", path("r.exr")), dir_),
        "--srgb");
    expect_one_line_error(
        run(fmt::format("score {} --pattern star --size 16x16", path("missing.png")), dir_),
        "missing.png");
    expect_one_line_error(
        run(fmt::format("score {} --pattern nosuch --size 16x16", path("r.exr")), dir_),
        "unknown pattern");
}

}  // namespace
}  // namespace aabench
