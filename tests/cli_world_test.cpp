// The 3-D side of the command line, run as a user runs it: plan, render --stats, reference
// --depth, export of a 3-D pattern read back bit for bit, and the errors (one line, exit 2,
// nothing written).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "harness/reference/box_reference.h"
#include "harness/report/image_io.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// Float32 output of a double reference: half an ulp at the depth values here (~1e3) is
// 3e-5 relative... in absolute terms 6e-8 relative to the value; 1e-6 relative is the bound.
constexpr double kFloatRelative = 1e-6;

struct RunResult {
    int exit_code;
    std::string out;
    std::string err;
};

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

class CliWorld : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               fmt::format("aabench_cliw_{}_{}", ::getpid(),
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    RunResult run(const std::string& args) const {
        const std::string cmd = fmt::format("{} {} >{} 2>{}", AABENCH_BINARY, args,
                                            path("stdout.txt"), path("stderr.txt"));
        const int status = std::system(cmd.c_str());
        RunResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(path("stdout.txt")),
                    slurp(path("stderr.txt"))};
        fs::remove(path("stdout.txt"));
        fs::remove(path("stderr.txt"));
        return r;
    }
    fs::path dir_;
};

TEST_F(CliWorld, PlanPrintsEveryStageWithItsReason) {
    const RunResult r = run("plan --pattern room --size 64x64");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (int k = 0; k < kStageCount; ++k) {
        EXPECT_NE(r.out.find(stage_name(static_cast<Stage>(k))), std::string::npos) << r.out;
    }
    EXPECT_NE(r.out.find("shadows      in"), std::string::npos) << r.out;
    const RunResult star = run("plan --pattern star --size 64x64");
    ASSERT_EQ(star.exit_code, 0) << star.err;
    EXPECT_NE(star.out.find("visibility   out  2-D scene"), std::string::npos) << star.out;
}

TEST_F(CliWorld, RenderStatsReportsTheStagesThatRan) {
    const RunResult r = run(fmt::format("render --pattern room --size 64x64 --method exact "
                                        "--out {} --stats", path("room.exr")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(path("room.exr")));
    EXPECT_NE(r.out.find("projection"), std::string::npos);
    EXPECT_NE(r.out.find("not called"), std::string::npos) << r.out;  // depth, at least
}

TEST_F(CliWorld, RenderOfA3DPatternIsTheMethodOnItsVisiblePieces) {
    ASSERT_EQ(run(fmt::format("render --pattern blocks --size 48x40 --method none --out {}",
                              path("b.exr")))
                  .exit_code,
              0);
    const Image file = read_image(path("b.exr"));
    const Scene pieces = PreparedFrame::prepare(make_pattern("blocks", 48, 40)).pieces().scene();
    const Image direct = render_scene(*make_method("none").method, pieces);
    ASSERT_EQ(file.data.size(), direct.data.size());
    EXPECT_EQ(file.data, direct.data);
}

TEST_F(CliWorld, ExportedRoomReadsBackAndRendersBitForBitTheSame) {
    ASSERT_EQ(run(fmt::format("export --pattern room --size 64x48 --out {}", path("room.json")))
                  .exit_code,
              0);
    const Scene back = read_scene_file(path("room.json"));
    const Scene made = make_pattern("room", 64, 48);
    ASSERT_TRUE(back.world.has_value());
    EXPECT_EQ(*back.world, *made.world);
    ASSERT_EQ(run(fmt::format("render --scene {} --method exact --out {}", path("room.json"),
                              path("a.exr")))
                  .exit_code,
              0);
    ASSERT_EQ(run(fmt::format("render --pattern room --size 64x48 --method exact --out {}",
                              path("b.exr")))
                  .exit_code,
              0);
    EXPECT_EQ(read_image(path("a.exr")).data, read_image(path("b.exr")).data);
}

TEST_F(CliWorld, DepthReferenceIsTheBoxReferenceOfTheDepthScene) {
    ASSERT_EQ(run(fmt::format("reference --pattern mesh --size 48x48 --depth --out {}",
                              path("d.exr")))
                  .exit_code,
              0);
    const Image file = read_image(path("d.exr"));
    const Scene scene = make_pattern("mesh", 48, 48);
    const PreparedFrame r = PreparedFrame::prepare(scene, {.depth_image = true});
    const Coverage exact = box_reference(r.depth_pieces());
    ASSERT_EQ(file.data.size(), exact.data.size());
    double worst = 0.0;
    for (std::size_t k = 0; k < exact.data.size(); ++k) {
        worst = std::max(worst, std::abs(file.data[k] - exact.data[k]) /
                                    std::max(1.0, std::abs(exact.data[k])));
    }
    EXPECT_LE(worst, kFloatRelative);
}

TEST_F(CliWorld, DepthOfA2DSceneIsAnErrorAndWritesNothing) {
    const RunResult r =
        run(fmt::format("reference --pattern star --size 32x32 --depth --out {}", path("d.exr")));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("--depth"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(path("d.exr")));
}

}  // namespace
}  // namespace aabench
