// The aabench command line, run as a user runs it: exit codes, one-line errors, no partial
// output, and the round trips it promises (export -> render --scene reproduces
// render --pattern bit for bit; reference and render --method exact agree with the library).
// Image contents are compared through library calls (read_image), never by parsing text.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <fmt/format.h>

#include "harness/reference/box_reference.h"
#include "harness/report/image_io.h"
#include "patterns/pattern.h"
#include "patterns/scene/scene_io.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

// Float32 output of a double reference: half an ulp at 1.0 is 6e-8; docs/architecture.md
// promises 1e-6 per pixel against an independent exact computation.
constexpr double kFloatOutputTolerance = 1e-6;

struct RunResult {
    int exit_code;
    std::string err;
};

RunResult run(const std::string& args) {
    const fs::path err_file = fs::temp_directory_path() / fmt::format("aabench_cli_err_{}", ::getpid());
    const std::string cmd = fmt::format("{} {} 2>{} >/dev/null", AABENCH_BINARY, args, err_file.string());
    const int status = std::system(cmd.c_str());
    std::ifstream in(err_file);
    std::string err((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    fs::remove(err_file);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, err};
}

class Cli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               fmt::format("aabench_cli_{}_{}", ::getpid(),
                           ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    // Number of files in the scratch directory: "nothing written" means this stays put.
    std::size_t file_count() const {
        return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
    }
    fs::path dir_;
};

void expect_one_line_error(const RunResult& r, const std::string& needle) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << "stderr: " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
}

TEST_F(Cli, ListExitsZero) { EXPECT_EQ(run("list").exit_code, 0); }

TEST_F(Cli, ExportThenRenderSceneReproducesRenderPatternBitForBit) {
    for (const PatternInfo& p : pattern_registry()) {
        if (p.model_file) continue;  // tests/mesh_patterns_test.cpp
        for (const char* method : {"none", "exact"}) {
            const std::string json = path(p.id + ".json");
            const std::string a = path(p.id + "_a.exr"), b = path(p.id + "_b.exr");
            ASSERT_EQ(run(fmt::format("export --pattern {} --size 96x64 --out {}", p.id, json)).exit_code, 0);
            ASSERT_EQ(run(fmt::format("render --pattern {} --size 96x64 --method {} --out {}", p.id, method, a)).exit_code, 0);
            ASSERT_EQ(run(fmt::format("render --scene {} --method {} --out {}", json, method, b)).exit_code, 0);
            const Image ia = read_image(a), ib = read_image(b);
            ASSERT_EQ(ia.data, ib.data) << p.id << " " << method;
        }
    }
}

TEST_F(Cli, ReferenceAndExactAgreeWithLibraryOnRandomSceneFiles) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> coord(-5.0, 37.0);
    for (int trial = 0; trial < 5; ++trial) {
        Scene scene;
        scene.width = 32;
        scene.height = 24;
        scene.background = 0.1;
        for (int s = 0; s < 3; ++s) {
            Contour c;
            for (int k = 0; k < 6; ++k) c.push_back({coord(rng), coord(rng)});
            scene.shapes.push_back({{c}, 0.25 + 0.25 * s});
        }
        const std::string json = path("scene.json");
        write_text_file(json, scene_to_json(scene));
        const Coverage want = box_reference(scene);
        for (const std::string& args :
             {fmt::format("reference --scene {} --out {}", json, path("ref.exr")),
              fmt::format("render --scene {} --method exact --out {}", json, path("ref.exr"))}) {
            ASSERT_EQ(run(args).exit_code, 0) << args;
            const Image got = read_image(path("ref.exr"));
            for (std::size_t k = 0; k < want.data.size(); ++k) {
                ASSERT_NEAR(got.data[k], want.data[k], kFloatOutputTolerance) << args << " pixel " << k;
            }
        }
    }
}

TEST_F(Cli, BadSceneFileIsOneLineExit2AndNothingWritten) {
    const std::string json = path("bad.json");
    write_text_file(json, R"({"width": 8, "height": 8, "shapes": [{"type": "polygon", "contours": [[[0,0],[1,0]]]}]})");
    const std::size_t before = file_count();
    expect_one_line_error(run(fmt::format("render --scene {} --method exact --out {}", json, path("out.exr"))),
                          "shapes[0].contours[0]");
    EXPECT_EQ(file_count(), before);
}

TEST_F(Cli, BadArgumentsAreOneLineExit2AndNothingWritten) {
    const std::size_t before = file_count();
    expect_one_line_error(run(fmt::format("render --pattern star --size 64x64 --method nope --out {}", path("o.exr"))),
                          "unknown method 'nope'");
    expect_one_line_error(run(fmt::format("render --pattern nope --size 64x64 --method exact --out {}", path("o.exr"))),
                          "unknown pattern 'nope'");
    expect_one_line_error(run(fmt::format("render --pattern star --size 64by64 --method exact --out {}", path("o.exr"))),
                          "--size");
    expect_one_line_error(run(fmt::format("render --pattern star --size 0x64 --method exact --out {}", path("o.exr"))),
                          "out of range");
    expect_one_line_error(run(fmt::format("render --pattern star --size 64x64 --method exact --out {}", path("o.tif"))),
                          "o.tif");
    expect_one_line_error(run(fmt::format("render --pattern star:spokes=1 --size 64x64 --method exact --out {}", path("o.exr"))),
                          "spokes");
    expect_one_line_error(run(fmt::format("reference --pattern star --size 64x64 --filter nope --out {}", path("o.exr"))),
                          "nope");
    expect_one_line_error(run(fmt::format("compare --methods none --patterns star --size 32x32 --runs 1 --methods exact --out {}", path("c"))),
                          "methods");
    expect_one_line_error(run("frobnicate"), "frobnicate");
    expect_one_line_error(run(fmt::format("render --scene {} --method exact --out {}", path("missing.json"), path("o.exr"))),
                          "missing.json");
    EXPECT_EQ(file_count(), before);
}

// A misspelt option or command is named with the one meant, in one line, before anything runs;
// a value out of range says so in the subcommands' own style.
TEST_F(Cli, MisspeltOptionsAndCommandsSuggestTheOneMeant) {
    const std::size_t before = file_count();
    expect_one_line_error(
        run(fmt::format("render --pattern star --size 8x8 --method none --ouput {}", path("o.exr"))),
        "--ouput: unknown option of render; did you mean --out?");
    expect_one_line_error(run(fmt::format("compare --pattern star --out {}", path("c"))),
                          "--pattern: unknown option of compare; did you mean --patterns?");
    expect_one_line_error(run("rendr --pattern star"), "did you mean 'render'?");
    // Nothing close: no guess, still the option named.
    const RunResult far = run(fmt::format("compare --zzzzzzzz --out {}", path("c")));
    expect_one_line_error(far, "--zzzzzzzz: unknown option of compare");
    EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
    expect_one_line_error(
        run(fmt::format("render --pattern star --size 8x8 --method none --threads 0 --out {}",
                        path("o.exr"))),
        "--threads: 0 is out of range 1..256");
    EXPECT_EQ(file_count(), before);
}

// Misspelt values get the same help as misspelt options: every name and choice a spec can hold.
TEST_F(Cli, MisspeltValuesSuggestTheOneMeant) {
    const std::size_t before = file_count();
    const std::string out = path("o.exr");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"render --pattern star --size 8x8 --method exactt --out " + out,
         "unknown method 'exactt'; did you mean 'exact'?"},
        {"render --pattern starr --size 8x8 --method exact --out " + out,
         "unknown pattern 'starr'; did you mean 'star'?"},
        {"render --pattern star:spoke=3 --size 8x8 --method exact --out " + out,
         "unknown parameter 'spoke'; did you mean 'spokes'?"},
        {"render --pattern star --size 8x8 --method ssaa:pattern=rgs --out " + out,
         "pattern=rgs is not one of grid|rgss|msaa|halton; did you mean 'rgss'?"},
        {"render --pattern star --size 8x8 --method ssaa:filter=gausian --out " + out,
         "did you mean 'gaussian'?"},
        {"reference --pattern star --size 8x8 --filter gausian --out " + out,
         "unknown filter 'gausian'; did you mean 'gaussian'?"},
        {"compare --methods none,box-multscan --patterns star --out " + path("c"),
         "did you mean 'box-multiscan'?"},
        {"render --pattern star --size 0x64 --method exact --out " + out,
         "--size: 0x64 is out of range 1..65536 per side"},
    };
    for (const auto& [args, needle] : cases) expect_one_line_error(run(args), needle);
    // Nothing close: the valid names, no guess.
    const RunResult far = run("render --pattern star --size 8x8 --method qqqqqqq --out " + out);
    expect_one_line_error(far, "(valid: none, exact,");
    EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
    EXPECT_EQ(file_count(), before);
}

// A subcommand's help: its own options with their defaults, not the top level's --help-all nor
// CLI11's Needs/Excludes bookkeeping; "every built-in pattern" names those left out.
TEST_F(Cli, SubcommandHelpShowsDefaultsAndNoNoise) {
    const std::string help_file = path("help.txt");
    for (const char* command : {"render", "compare", "check", "score", "reference", "plan"}) {
        ASSERT_EQ(std::system(fmt::format("{} {} --help >{}", AABENCH_BINARY, command, help_file)
                                  .c_str()),
                  0)
            << command;
        std::ifstream in(help_file);
        const std::string help((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        EXPECT_EQ(help.find("--help-all"), std::string::npos) << command << "\n" << help;
        EXPECT_EQ(help.find("Excludes:"), std::string::npos) << command << "\n" << help;
        EXPECT_EQ(help.find("Needs:"), std::string::npos) << command << "\n" << help;
        EXPECT_EQ(help.find("INT:INT"), std::string::npos) << command << "\n" << help;
        if (std::string(command) == "render") {
            EXPECT_NE(help.find("--threads INT=1"), std::string::npos) << help;
        }
        if (std::string(command) == "compare") {
            for (const char* needle : {"--size TEXT=256x256", "--runs INT=7", "--jobs INT=1",
                                       "every built-in pattern but isoluminant, text-page, colour-room, terrain-edges, mirror, bunny, "
                                       "horse, engine and truck"}) {
                EXPECT_NE(help.find(needle), std::string::npos) << needle << "\n" << help;
            }
        }
    }
    ASSERT_EQ(std::system(fmt::format("{} --help >{}", AABENCH_BINARY, help_file).c_str()), 0);
    std::ifstream in(help_file);
    const std::string top((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(top.find("--help-all"), std::string::npos) << "the top level keeps it\n" << top;
}

// --scenes alone: --size would apply to nothing, so it is refused; and the run does not wait
// for the hard-case suite unless asked.
TEST_F(Cli, CompareScenesRefusesSizeAndSkipsTheHardCases) {
    const std::string scene = path("mine.json");
    ASSERT_EQ(run(fmt::format("export --pattern star --size 24x16 --out {}", scene)).exit_code, 0);
    const std::size_t before = file_count();
    expect_one_line_error(
        run(fmt::format("compare --scenes {} --size 64x64 --methods none --out {}", scene,
                        path("refused"))),
        "--size: applies to the built-in patterns only");
    EXPECT_EQ(file_count(), before);
    const std::string out = path("run");
    const RunResult r = run(fmt::format(
        "compare --scenes {} --methods none --runs 1 --quiet --out {}", scene, out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(fs::path(out) / "index.html");
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(html.empty());
    EXPECT_EQ(html.find("subscanline-n3"), std::string::npos)
        << "no hard-case table unless asked for";
    const RunResult asked = run(fmt::format(
        "compare --scenes {} --methods none --runs 1 --quiet --hardcases --out {}", scene,
        path("asked")));
    ASSERT_EQ(asked.exit_code, 0) << asked.err;
    std::ifstream in2(fs::path(path("asked")) / "index.html");
    const std::string html2((std::istreambuf_iterator<char>(in2)),
                            std::istreambuf_iterator<char>());
    EXPECT_NE(html2.find("subscanline-n3"), std::string::npos) << "--hardcases asks for it";
}

TEST_F(Cli, CompareWritesTableCsvAndJson) {
    const std::string out = path("cmp");
    const RunResult r = run(fmt::format("compare --methods none,exact --patterns star,strips --size 48x40 --runs 1 --out {}", out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* f : {"table.txt", "results.csv", "results.json"}) {
        EXPECT_GT(fs::file_size(fs::path(out) / f), 0u) << f;
    }
}

TEST_F(Cli, HardcasesPassesForExactAndWritesItsTable) {
    const RunResult r = run(fmt::format("hardcases --methods exact --out {}", path("hc")));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_GT(fs::file_size(fs::path(path("hc")) / "hardcases.txt"), 0u);
    EXPECT_GT(fs::file_size(fs::path(path("hc")) / "hardcases.json"), 0u);
}

TEST_F(Cli, ShardsMergeIntoOneReport) {
    for (int k = 1; k <= 2; ++k) {
        const RunResult r = run(fmt::format(
            "compare --methods none,box-multiscan --patterns star --size 32x32 --runs 1 --sweep "
            "--no-hardcases --shard {}/2 --out {}",
            k, path(fmt::format("s{}", k))));
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const RunResult m =
        run(fmt::format("merge {} {} --out {}", path("s1"), path("s2"), path("merged")));
    ASSERT_EQ(m.exit_code, 0) << m.err;
    EXPECT_GT(fs::file_size(fs::path(path("merged")) / "index.html"), 0u);
    // The same shard twice: an error, and no merged directory written.
    expect_one_line_error(
        run(fmt::format("merge {} {} --out {}", path("s1"), path("s1"), path("twice"))),
        "shard 1/2 again");
    EXPECT_FALSE(fs::exists(path("twice")));
}

}  // namespace
}  // namespace aabench
