// compare --web-peers (docs/external.md, "Web peers"): Skia and tiny-skia through node. The
// tests that draw need node and the npm packages scripts/install-deps installs; without them
// they skip in one line. Finding the peers and leaving one out are tested everywhere.
#include "harness/cli/web_peers.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli_runner.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// The bar for every peer on star and text: a y flip, a gamma misreading of the codes
// or a lost path moves the mean error by far more than this (the peers measured at 64x64:
// |bias| <= 0.0012).
constexpr double kPeerBiasBound = 0.005;

std::string source_peers_dir() { return std::string(AABENCH_SOURCE_DIR) + "/scripts/web-peers"; }

using Output = CliOutput;

class WebPeersCli : public CliRunner {
protected:
    WebPeersCli() : CliRunner("web_peers") {}
    nlohmann::json rows(const std::string& dir) const {
        return nlohmann::json::parse(std::ifstream(path(dir + "/results.json")))["rows"];
    }
};

TEST(WebPeers, AFolderWithoutThePackagesLeavesEachPeerOutWithItsReason) {
    const fs::path dir =
        fs::temp_directory_path() / fmt::format("aabench_web_peers_empty_{}", ::getpid());
    fs::create_directories(dir);
    const WebPeers peers = find_web_peers(dir.string());
    fs::remove_all(dir);
    EXPECT_TRUE(peers.renderers.empty());
    ASSERT_EQ(peers.left_out.size(), 2u);
    for (const std::string& line : peers.left_out) {
        EXPECT_EQ(line.find('\n'), std::string::npos) << line;
        EXPECT_NE(line.find("left out"), std::string::npos) << line;
    }
    EXPECT_NE(peers.left_out[0].find("skia"), std::string::npos);
    EXPECT_NE(peers.left_out[1].find("resvg"), std::string::npos);
}

TEST_F(WebPeersCli, MissingPeersAreLeftOutInOneLineAndTheRunGoesOn) {
    const std::string cmd = fmt::format(
        "AABENCH_WEB_PEERS={} {} compare --patterns star --size 32x32 --methods none --runs 1 "
        "--no-hardcases --quiet --web-peers --out {} 2>{}",
        path("nowhere"), AABENCH_BINARY, path("missing"), path("err"));
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    std::ifstream err(path("err"));
    const std::string text((std::istreambuf_iterator<char>(err)), {});
    EXPECT_NE(text.find("--web-peers: skia left out"), std::string::npos) << text;
    EXPECT_NE(text.find("--web-peers: resvg left out"), std::string::npos) << text;
    const nlohmann::json r = rows("missing");
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0]["method"], "none");
}

TEST_F(WebPeersCli, SkiaAndResvgBeatNoneOnStarAndTextWithoutBias) {
    const WebPeers peers = find_web_peers(source_peers_dir());
    if (peers.renderers.size() < 2) {
        GTEST_SKIP() << peers.left_out.front();
    }
    const Output o = run(fmt::format(
        "compare --patterns star,text --size 64x64 --methods none --runs 1 --no-hardcases "
        "--quiet --web-peers --out {}",
        path("run")));
    ASSERT_EQ(o.exit_code, 0) << o.err;
    const nlohmann::json r = rows("run");
    ASSERT_EQ(r.size(), 6u);
    for (const char* pattern : {"star", "text"}) {
        double none_rmse = NAN;
        int peers_seen = 0;
        for (const auto& row : r) {
            if (row["pattern_id"] != pattern) continue;
            if (row["method"] == "none") none_rmse = row["box_rmse"].get<double>();
        }
        for (const auto& row : r) {
            if (row["pattern_id"] != pattern || row["method"] == "none") continue;
            const std::string id = row["method_id"];
            ASSERT_TRUE(id == "external:skia" || id == "external:resvg") << id;
            ++peers_seen;
            const std::string method = row["method"];
            // The version is in the row: "external:skia (Skia via @napi-rs/canvas 1.1.1)".
            EXPECT_EQ(method.rfind(id + " (", 0), 0u) << method;
            EXPECT_NE(method.find(id == "external:skia" ? "@napi-rs/canvas " : "@resvg/resvg-js "),
                      std::string::npos)
                << method;
            EXPECT_LT(row["box_rmse"].get<double>(), none_rmse) << pattern << " " << id;
            EXPECT_LE(std::abs(row["box_bias"].get<double>()), kPeerBiasBound)
                << pattern << " " << id;
            EXPECT_GT(row["external_reported_ms"].get<double>(), 0.0) << "the script's own time";
            EXPECT_EQ(row["time_source"], "process");
        }
        EXPECT_EQ(peers_seen, 2) << pattern;
    }
}

}  // namespace
}  // namespace aabench
