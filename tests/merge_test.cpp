// aabench merge cannot lie (docs/cluster.md): it refuses, with exit 2, one line naming the
// folder and nothing written, a missing shard, a duplicated one, a shard of another results
// schema, of other options or size, and a half-written one; the merge of all N shards equals
// the unsharded run bit for bit on the error columns. Also compare --plan-shards.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_runner.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// A small sweep: box-multiscan's n over 6 values on one pattern, and none: 7 tasks, 3 shards.
constexpr const char* kSweep =
    "--methods none,box-multiscan --patterns star --size 16x16 --runs 1 --sweep --no-hardcases "
    "--quiet";

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void replace_in_file(const fs::path& p, const std::string& from, const std::string& to) {
    std::string text = slurp(p);
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from << " not in " << p;
    text.replace(at, from.size(), to);
    std::ofstream(p) << text;
}

class Merge : public CliRunner {
protected:
    Merge() : CliRunner("merge") {}
    // The three shards and the unsharded run, made once for the suite (each test copies them:
    // the runs are the slow part).
    static fs::path made() {
        static const fs::path dir = [] {
            const fs::path d =
                fs::temp_directory_path() / fmt::format("aabench_merge_{}", ::getpid());
            fs::create_directories(d);
            for (int k = 1; k <= 3; ++k) {
                const std::string cmd =
                    fmt::format("{} compare {} --shard {}/3 --out {} 2>&1", AABENCH_BINARY, kSweep,
                                k, (d / fmt::format("s{}", k)).string());
                if (std::system(cmd.c_str()) != 0) throw std::runtime_error(cmd + " failed");
            }
            const std::string whole = fmt::format("{} compare {} --out {} 2>&1", AABENCH_BINARY,
                                                  kSweep, (d / "whole").string());
            if (std::system(whole.c_str()) != 0) throw std::runtime_error(whole + " failed");
            return d;
        }();
        return dir;
    }
    static void TearDownTestSuite() { fs::remove_all(made()); }
    void SetUp() override {
        CliRunner::SetUp();
        for (const char* name : {"s1", "s2", "s3", "whole"}) {
            fs::copy(made() / name, path(name), fs::copy_options::recursive);
        }
    }
    // compare --shard K/N into "sK".
    void shard(int k, int n, const std::string& options, const std::string& name = "") {
        const CliOutput o = run(fmt::format("compare {} --shard {}/{} --out {}", options, k, n,
                                            path(name.empty() ? fmt::format("s{}", k) : name)));
        ASSERT_EQ(o.exit_code, 0) << o.err;
    }
    // merge of the named folders into "merged".
    CliOutput merge(const std::vector<std::string>& names, const std::string& extra = "") {
        std::string dirs;
        for (const std::string& n : names) dirs += " " + path(n);
        return run(fmt::format("merge{} --out {}{}", dirs, path("merged"), extra));
    }
    // Exit 2, one line holding `needle` (and the folder when given), no merged folder.
    void expect_refused(const CliOutput& o, const std::string& needle,
                        const std::string& folder = "") {
        EXPECT_EQ(o.exit_code, 2) << o.err;
        EXPECT_NE(o.err.find(needle), std::string::npos) << "stderr: " << o.err;
        if (!folder.empty()) {
            EXPECT_NE(o.err.find(path(folder)), std::string::npos) << "stderr: " << o.err;
        }
        EXPECT_EQ(std::count(o.err.begin(), o.err.end(), '\n'), 1) << "not one line: " << o.err;
        EXPECT_FALSE(fs::exists(path("merged"))) << "a refused merge wrote its folder";
    }
    void copy_shard(const std::string& from, const std::string& to) {
        fs::copy(path(from), path(to), fs::copy_options::recursive);
    }
};

TEST_F(Merge, AllShardsEqualTheUnshardedRunBitForBit) {
    const CliOutput o = merge({"s3", "s1", "s2"}, " --same-as " + path("whole"));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    EXPECT_NE(o.out.find("merged == unsharded: the error columns of 7 rows"), std::string::npos)
        << o.out;
    EXPECT_TRUE(fs::exists(fs::path(path("merged")) / "shards.txt"));
}

TEST_F(Merge, ADifferenceFromTheUnshardedRunIsExitOne) {
    // One error figure of the unsharded run moved by one ulp: the check must see it.
    const fs::path json = fs::path(path("whole")) / "results.json";
    nlohmann::ordered_json doc = nlohmann::ordered_json::parse(slurp(json));
    const double rmse = doc["rows"][0]["box_rmse"].get<double>();
    doc["rows"][0]["box_rmse"] = std::nextafter(rmse, 1.0);
    std::ofstream(json) << doc.dump(2);
    const CliOutput o = merge({"s1", "s2", "s3"}, " --same-as " + path("whole"));
    EXPECT_EQ(o.exit_code, 1) << o.err;
    EXPECT_NE(o.err.find("merged != unsharded"), std::string::npos) << o.err;
    EXPECT_NE(o.err.find("box_rmse"), std::string::npos) << o.err;
}

TEST_F(Merge, RefusesAMissingShard) {
    expect_refused(merge({"s1", "s3"}), "shard 2/3 is missing", "s1");
}

TEST_F(Merge, RefusesADuplicatedShard) {
    copy_shard("s2", "s2-again");
    expect_refused(merge({"s1", "s2", "s2-again", "s3"}), "shard 2/3 again", "s2-again");
}

TEST_F(Merge, RefusesAShardOfAnotherResultsSchema) {
    replace_in_file(fs::path(path("s2")) / "results.json", "\"schema_version\": 2",
                    "\"schema_version\": 1");
    expect_refused(merge({"s1", "s2", "s3"}), "results schema 1, not 2", "s2");
}

TEST_F(Merge, RefusesAShardOfOtherOptions) {
    std::string runs2 = kSweep;
    runs2.replace(runs2.find("--runs 1"), 8, "--runs 2");
    shard(2, 3, runs2, "s2-runs");
    expect_refused(merge({"s1", "s2-runs", "s3"}), "--runs 2, not 1", "s2-runs");
}

TEST_F(Merge, RefusesAShardOfAnotherSize) {
    const std::string other = kSweep;
    shard(2, 3,
          other.substr(0, other.find("16x16")) + "24x24" + other.substr(other.find("16x16") + 5),
          "s2-size");
    expect_refused(merge({"s1", "s2-size", "s3"}), "--size 24x24, not 16x16", "s2-size");
}

TEST_F(Merge, RefusesAShardOfAnotherN) {
    shard(2, 4, kSweep, "s2-of-4");
    expect_refused(merge({"s1", "s2-of-4", "s3"}), "of another N", "s2-of-4");
}

TEST_F(Merge, RefusesAShardWithoutItsCompletionMarker) {
    // A shard killed before the end: its files may be there, the marker written last is not.
    fs::remove(fs::path(path("s2")) / "shard.json");
    expect_refused(merge({"s1", "s2", "s3"}), "no shard.json", "s2");
}

TEST_F(Merge, RefusesAShardWhoseResultsAreCutShort) {
    // The marker there, results.json with a row fewer than it says (written over afterwards).
    replace_in_file(fs::path(path("s2")) / "shard.json", "\"rows\": ", "\"rows\": 1");
    expect_refused(merge({"s1", "s2", "s3"}), "half-written or altered", "s2");
}

TEST_F(Merge, ARefusedCompareLeavesAFinishedShardAsItWas) {
    // Bad input into the folder of a finished shard: refused before any work, the shard and its
    // marker untouched (the marker goes only when the new files are about to be written).
    const std::string before = slurp(fs::path(path("s2")) / "shard.json");
    const CliOutput o = run(fmt::format(
        "compare --methods none --patterns nosuch --size 16x16 --quiet --shard 2/3 --out {}",
        path("s2")));
    EXPECT_EQ(o.exit_code, 2) << o.err;
    EXPECT_EQ(slurp(fs::path(path("s2")) / "shard.json"), before);
}

TEST_F(Merge, PlanShardsPrintsEveryTaskAndEachShardsEstimate) {
    const CliOutput o = run(fmt::format("compare {} --plan-shards 3", kSweep));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    EXPECT_NE(o.out.find("7 tasks in 3 shards"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("star / box-multiscan:n=24"), std::string::npos) << o.out;
    EXPECT_NE(o.out.find("largest shard: "), std::string::npos) << o.out;
    // The plan and the shards agree: each shard's marker holds the plan's count of its tasks.
    for (int k = 1; k <= 3; ++k) {
        const std::string marker = slurp(fs::path(path(fmt::format("s{}", k))) / "shard.json");
        EXPECT_NE(marker.find(fmt::format("\"shard\": {}", k)), std::string::npos) << marker;
    }
}

}  // namespace
}  // namespace aabench
