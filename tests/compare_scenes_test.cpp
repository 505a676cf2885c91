// compare --scenes: a user's scene files (version 1 and 2) go through the same pipeline as the
// built-in patterns, named by their file stem; bad files fail before any work. Library calls for
// the figures; the command line for exit codes, messages and the files a run writes.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "harness/measure/compare.h"
#include "harness/report/context.h"
#include "harness/report/report.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// A scene as a user's file holds it: written and read back (thin objects are not in files).
Scene as_file(const Scene& scene) { return parse_scene_json(scene_to_json(scene), "test"); }

CompareOptions small_run() {
    CompareOptions options;
    options.method_specs = {"none", "gauss-multiscan"};
    options.width = 40;
    options.height = 32;
    options.runs = 1;
    options.motion_frames = 4;
    options.keep_images = false;
    return options;
}

const ResultRow& find_row(const std::vector<ResultRow>& rows, const std::string& pattern_id,
                          const std::string& method_id) {
    for (const ResultRow& r : rows) {
        if (r.pattern_id == pattern_id && r.method_id == method_id) return r;
    }
    throw std::logic_error("no row " + pattern_id + " / " + method_id);
}

// Equal bit for bit (NaN equal to NaN): the same scene through the same code.
void expect_same(double a, double b, const std::string& what) {
    if (std::isnan(a) && std::isnan(b)) return;
    EXPECT_EQ(a, b) << what;
}

TEST(CompareScenes, AFileScoresExactlyLikeThePatternItHolds) {
    CompareOptions options = small_run();
    options.pattern_specs = {"star", "room"};  // 2-D, and 3-D through the world pipeline
    options.scene_files = {{"some/dir/my-star.json", as_file(make_pattern("star", 40, 32))},
                           {"other/my-room.json", as_file(make_pattern("room", 40, 32))}};
    const CompareResult result = run_comparison(options);
    ASSERT_EQ(result.rows.size(), 8u);
    for (const auto& [pattern, stem, path] :
         {std::tuple{"star", "my-star", "some/dir/my-star.json"},
          std::tuple{"room", "my-room", "other/my-room.json"}}) {
        for (const char* method : {"none", "gauss-multiscan"}) {
            const ResultRow& p = find_row(result.rows, pattern, method);
            const ResultRow& f = find_row(result.rows, stem, method);
            const std::string what = fmt::format("{} / {}", stem, method);
            EXPECT_EQ(f.pattern, stem);
            EXPECT_EQ(f.scene_file, path);
            EXPECT_EQ(p.scene_file, "");
            EXPECT_EQ(f.edges, p.edges) << what;
            expect_same(f[metric::kBoxRmse], p[metric::kBoxRmse], what);
            expect_same(f[metric::kBoxMaxAbs], p[metric::kBoxMaxAbs], what);
            expect_same(f[metric::kOwnRmse], p[metric::kOwnRmse], what);
            expect_same(f[metric::kEdgeRmse], p[metric::kEdgeRmse], what);
            expect_same(f[metric::kAliasLowDb], p[metric::kAliasLowDb], what);
            expect_same(f[metric::kCrawl], p[metric::kCrawl], what);
            expect_same(f[metric::kSsim], p[metric::kSsim], what);
            expect_same(f[metric::kSeamsMax], p[metric::kSeamsMax], what);
            // The world stages ran for the 3-D file as for the 3-D pattern.
            EXPECT_EQ(std::isnan(f[metric::kWorldMs]), std::isnan(p[metric::kWorldMs])) << what;
        }
    }
    EXPECT_TRUE(std::isnan(find_row(result.rows, "room", "none")[metric::kWorldMs]) == false);
}

TEST(CompareScenes, ScenesAloneRunNoBuiltInPatternAndKeepTheirOwnSize) {
    CompareOptions options = small_run();
    options.method_specs = {"exact"};
    options.symptoms = false;
    options.scene_files = {{"a.json", as_file(make_pattern("strips", 24, 20))}};
    const CompareResult result = run_comparison(options);
    ASSERT_EQ(result.rows.size(), 1u);
    EXPECT_EQ(result.rows[0].pattern_id, "a");
    EXPECT_EQ(result.rows[0].width, 24);
    EXPECT_EQ(result.rows[0].height, 20);
}

TEST(CompareScenes, NamesMustBeUniqueInARun) {
    CompareOptions options = small_run();
    options.scene_files = {{"x/s.json", as_file(make_pattern("star", 8, 8))},
                           {"y/s.json", as_file(make_pattern("star", 8, 8))}};
    EXPECT_THROW(run_comparison(options), InputError);
    options.pattern_specs = {"star"};
    options.scene_files = {{"x/star.json", as_file(make_pattern("star", 8, 8))}};
    EXPECT_THROW(run_comparison(options), InputError);
}

TEST(CompareScenes, TheScenePathSurvivesTheResultsFileAndOldFilesStillRead) {
    CompareOptions options = small_run();
    options.method_specs = {"none"};
    options.symptoms = false;
    options.pattern_specs = {"strips"};
    options.scene_files = {{"dir/mine.json", as_file(make_pattern("star", 16, 12))}};
    const CompareResult result = run_comparison(options);
    const std::string json = compare_json(result.rows, RunContext{});
    const std::vector<ResultRow> back = rows_from_compare_json(json, "test");
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back[0].scene_file, "");
    EXPECT_EQ(back[1].scene_file, "dir/mine.json");
    // A results file written before the column existed reads as built-in patterns' rows.
    nlohmann::json doc = nlohmann::json::parse(json);
    for (auto& row : doc["rows"]) row.erase("scene_file");
    const std::vector<ResultRow> old = rows_from_compare_json(doc.dump(), "old");
    EXPECT_EQ(old[1].scene_file, "");
    // Any other missing column is an error, unless asked to take defaults (aabench check).
    for (auto& row : doc["rows"]) row.erase("edge_rmse");
    EXPECT_THROW(rows_from_compare_json(doc.dump(), "old"), InputError);
    const std::vector<ResultRow> lenient = rows_from_compare_json(doc.dump(), "old", true);
    EXPECT_TRUE(std::isnan(lenient[0][metric::kEdgeRmse]));
}

TEST(CompareScenes, ShardsWithScenesOfOtherSizesMerge) {
    CompareOptions options = small_run();
    options.method_specs = {"none", "exact"};
    options.symptoms = false;
    options.pattern_specs = {"star"};
    options.scene_files = {{"big.json", as_file(make_pattern("star", 50, 10))}};
    std::vector<std::vector<ResultRow>> shards;
    for (int k = 0; k < 2; ++k) {
        CompareOptions shard = options;
        shard.shard_index = k;
        shard.shard_count = 2;
        shards.push_back(run_comparison(shard).rows);
    }
    EXPECT_EQ(merge_shard_rows(shards).size(), 4u);
}

// ---- The command line ----

struct RunResult {
    int exit_code;
    std::string err;
};

RunResult run(const std::string& args) {
    const fs::path err_file =
        fs::temp_directory_path() / fmt::format("aabench_scenes_{}", ::getpid());
    const std::string cmd =
        fmt::format("{} {} 2>{} >/dev/null", AABENCH_BINARY, args, err_file.string());
    const int status = std::system(cmd.c_str());
    std::ifstream in(err_file);
    std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fs::remove(err_file);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, err};
}

class CompareScenesCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               fmt::format("aabench_scenes_{}_{}", ::getpid(),
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

TEST_F(CompareScenesCli, ABadFileIsOneLineNamingFileAndJsonPathAndNothingIsWritten) {
    ASSERT_EQ(run(fmt::format("export --pattern star --size 32x32 --out {}", path("good.json")))
                  .exit_code,
              0);
    std::ofstream(path("bad.json")) << R"({"width": 8, "height": 8, "shapes": [)"
                                    << R"({"type": "polygon", "contours": [[[0,0],[1,1]]]}]})";
    const RunResult r = run(fmt::format("compare --scenes {},{} --methods none --out {}",
                                        path("good.json"), path("bad.json"), path("out")));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(path("bad.json") + ": shapes[0].contours[0]"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(path("out")));
}

TEST_F(CompareScenesCli, AVersion2FileGetsItsSectionPlotAndImagesInTheReport) {
    ASSERT_EQ(
        run(fmt::format("export --pattern blocks --size 32x24 --out {}", path("my-blocks.json")))
            .exit_code,
        0);
    const RunResult r = run(fmt::format(
        "compare --scenes {} --methods none,exact --runs 1 --no-hardcases --quiet --out {}",
        path("my-blocks.json"), path("out")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_TRUE(fs::exists(path("out/plots/my-blocks.svg")));
    EXPECT_TRUE(fs::exists(path("out/images/my-blocks/exact.exr")));
    const std::string table = [&] {
        std::ifstream in(path("out/table.txt"));
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }();
    EXPECT_NE(table.find("scene file " + path("my-blocks.json")), std::string::npos) << table;
}

}  // namespace
}  // namespace aabench
