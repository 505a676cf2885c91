// The claims table (harness/measure/claims.h, docs/claims.md): the verdict rule as stated, the
// per-angle edge figures it reads, the circle's step test against the method that draws it,
// docs/claims.md in sync with the claims and the rule, and the command's input errors.
#include "harness/measure/claims.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "harness/measure/edge_angles.h"
#include "harness/measure/metric_registry.h"
#include "harness/reference/box_reference.h"
#include "harness/report/claims_table.h"
#include "methods/method.h"
#include "patterns/scene/curves.h"
#include "tests/cli_runner.h"

namespace aabench {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

ClaimCheck check(CheckKind kind, double a, double b) { return {kind, "s", "a", a, "b", b}; }

TEST(ClaimVerdict, AnOrderingNeedsTheMargin) {
    EXPECT_TRUE(check(CheckKind::kOrdering, 0.89, 1.0).holds());
    EXPECT_TRUE(check(CheckKind::kOrdering, 0.90, 1.0).holds());  // exactly 10 % below
    EXPECT_FALSE(check(CheckKind::kOrdering, 0.95, 1.0).holds());
    EXPECT_FALSE(check(CheckKind::kOrdering, 0.0, 0.0).holds());  // equal is no ordering
    EXPECT_FALSE(check(CheckKind::kOrdering, NAN, 1.0).holds());  // not measured never holds
}

TEST(ClaimVerdict, AnEqualityHoldsWithinTenPercentOfTheLarger) {
    EXPECT_TRUE(check(CheckKind::kEquality, 0.91, 1.0).holds());
    EXPECT_TRUE(check(CheckKind::kEquality, 1.0, 0.91).holds());
    EXPECT_FALSE(check(CheckKind::kEquality, 0.85, 1.0).holds());
    EXPECT_TRUE(check(CheckKind::kEquality, 0.0, 0.0).holds());
    EXPECT_FALSE(check(CheckKind::kEquality, 1.0, 0.0).holds());
}

TEST(ClaimVerdict, OccurrenceAndBound) {
    EXPECT_TRUE(check(CheckKind::kOccurrence, 1.0, 0.0).holds());
    EXPECT_FALSE(check(CheckKind::kOccurrence, 0.0, 0.0).holds());
    EXPECT_TRUE(check(CheckKind::kAtMost, 3.0, 3.0).holds());
    EXPECT_FALSE(check(CheckKind::kAtMost, 4.0, 3.0).holds());
}

TEST(ClaimVerdict, HoldsOnEveryScenePartlyOnSomeElseNot) {
    ClaimResult r;
    EXPECT_EQ(r.verdict(), Verdict::kDoesNotHold);  // nothing measured holds nothing
    r.checks = {check(CheckKind::kOrdering, 0.5, 1.0), check(CheckKind::kOrdering, 0.5, 1.0)};
    EXPECT_EQ(r.verdict(), Verdict::kHolds);
    r.checks.push_back(check(CheckKind::kOrdering, 1.0, 0.5));
    EXPECT_EQ(r.verdict(), Verdict::kPartly);
    EXPECT_EQ(r.checks_holding(), 2);
    r.checks = {check(CheckKind::kOrdering, 1.0, 0.5)};
    EXPECT_EQ(r.verdict(), Verdict::kDoesNotHold);
}

TEST(EdgeAngles, BinsFoldEveryDirectionIntoZeroToNinety) {
    EXPECT_EQ(edge_angle_bin({0, 0}, {10, 0}), 0);
    EXPECT_EQ(edge_angle_bin({10, 0}, {0, 0.5}), 0);  // 2.9°, either direction
    EXPECT_EQ(edge_angle_bin({0, 0}, {0, -10}), kEdgeAngleBins - 1);
    EXPECT_EQ(edge_angle_bin({0, 0}, {10, 10}), 9);    // 45° opens the tenth bin
    EXPECT_EQ(edge_angle_bin({0, 0}, {-10, 9.9}), 8);  // 44.7°
    const MetricRegistry& registry = metric_registry();
    EXPECT_EQ(registry[edge_angle_metric(0)].key, "edge_rmse_00_05deg");
    EXPECT_EQ(registry[edge_angle_metric(kEdgeAngleBins - 1)].key, "edge_rmse_85_90deg");
    EXPECT_TRUE(registry[edge_angle_metric(0)].may_be_absent);  // older results files lack it
}

// An axis-aligned square: pixels near its top and bottom are in the horizontal bin, near its
// sides in the vertical one, near its corners in neither; the per-bin error of point sampling
// is the rmse over exactly those pixels.
TEST(EdgeAngles, ASquaresSidesFallInTheirBinsAndCornersInNone) {
    Scene scene;
    scene.width = scene.height = 32;
    Shape square;
    square.contours.push_back({{8.3, 8.3}, {23.6, 8.3}, {23.6, 23.6}, {8.3, 23.6}});
    scene.shapes.push_back(square);
    const Raster<std::int8_t> bins = edge_angle_bins(scene);
    EXPECT_EQ(bins.at(16, 8), 0);                   // the top edge, centre 0.2 px away
    EXPECT_EQ(bins.at(8, 16), kEdgeAngleBins - 1);  // the left edge
    EXPECT_EQ(bins.at(8, 8), kMixedAngleBins);      // the corner
    EXPECT_EQ(bins.at(16, 16), kNoAngleBin);        // the inside
    const Image img = render_scene(*make_method("none").method, scene);
    const Coverage ref = box_reference(scene);
    const EdgeAngleErrors e = edge_errors_by_angle(img, ref, bins);
    double sum = 0.0;
    long long n = 0;
    for (std::size_t k = 0; k < bins.data.size(); ++k) {
        if (bins.data[k] != 0) continue;
        sum += std::pow(img.data[k] - ref.data[k], 2);
        ++n;
    }
    EXPECT_EQ(e.pixels[0], n);
    EXPECT_DOUBLE_EQ(e.rmse[0], std::sqrt(sum / n));
    EXPECT_TRUE(std::isnan(e.rmse[5]));  // no edge at 25-30°
}

// The step test's x per row is the x aa-circle draws (its outer pixel of each row), also past the
// table's rows: at 804 the loop reads past them, the source's example.
TEST(CircleSteps, TheSimulatedLoopIsWhatAaCircleDraws) {
    const MethodInstance m = make_method("aa-circle");
    for (int r : {37, 300, 804}) {
        const CircleStepFigures f = circle_step_figures(r, 255);
        const int size = 2 * r + 3, c = r + 1;
        Scene s;
        s.width = s.height = size;
        s.shapes.push_back(ring_shape({c + 0.5, c + 0.5}, r - 0.5, r + 0.5, 1.0));
        const Image img = render_scene(*m.method, s);
        // Rows far from the diagonal, where no other octant writes.
        for (int y = 0; y < f.rows_drawn / 2; ++y) {
            const int x = f.x_truncated[y];
            ASSERT_GT(img.at(c + x, c + y), 0.0f) << fmt::format("r={} y={}", r, y);
            ASSERT_EQ(img.at(c + x + 1, c + y), 0.0f) << fmt::format("r={} y={}", r, y);
        }
    }
    EXPECT_TRUE(circle_step_figures(804, 255).reads_past_table());
    EXPECT_GT(circle_step_figures(804, 255).missed_steps, 0);
    // Exact levels (alpha_max 0 keeps l) never miss a step.
    for (int r = 1; r <= 1024; ++r) ASSERT_EQ(circle_step_figures(r, 0).missed_steps, 0) << r;
}

// docs/claims.md is the command's page: the rule word for word, a summary row and a section for
// every claim with its command, and verdicts that follow the rule from the counts it shows.
TEST(ClaimsPage, DocsClaimsHoldsTheRuleEveryClaimAndConsistentVerdicts) {
    const std::string page = read_file(fs::path(AABENCH_SOURCE_DIR) / "docs/claims.md");
    ASSERT_FALSE(page.empty());
    EXPECT_NE(page.find(kVerdictRule), std::string::npos)
        << "docs/claims.md's verdict rule differs from kVerdictRule: regenerate it with "
           "build/aabench claims --page docs/claims.md";
    EXPECT_NE(page.find("Generated by `aabench claims --page docs/claims.md`"), std::string::npos);
    for (const std::string& id : claim_ids()) {
        EXPECT_NE(page.find("`aabench claims --only " + id + "`"), std::string::npos) << id;
        EXPECT_NE(page.find("<a id=\"" + id + "\"></a>"), std::string::npos) << id;
    }
    const std::regex verdict(R"(\*\*Verdict: ([a-z ]+)\*\* \((\d+) of (\d+) checks hold\))");
    int sections = 0;
    for (auto it = std::sregex_iterator(page.begin(), page.end(), verdict);
         it != std::sregex_iterator(); ++it, ++sections) {
        const std::string word = (*it)[1];
        const int holding = std::stoi((*it)[2]), total = std::stoi((*it)[3]);
        const std::string want = holding == total && total > 0 ? "holds"
                                 : holding > 0                 ? "partly"
                                                               : "does not hold";
        EXPECT_EQ(word, want) << it->str();
    }
    EXPECT_EQ(sections, static_cast<int>(claim_ids().size()));
}

// The report's section: the rule, and per claim its verdict, count and command.
TEST(ClaimsPage, TheReportSectionHoldsTheRuleAndEveryVerdict) {
    ClaimResult r;
    r.claim = "a < b";
    r.source = "Someone & Other 1984";
    r.command = "aabench claims --only x";
    r.checks = {check(CheckKind::kOrdering, 0.5, 1.0), check(CheckKind::kOrdering, 1.0, 0.5)};
    const std::string html = claims_html_section({r});
    EXPECT_NE(html.find("<section id=\"claims\">"), std::string::npos);
    EXPECT_NE(html.find("partly"), std::string::npos) << html;
    EXPECT_NE(html.find("1 of 2"), std::string::npos) << html;
    EXPECT_NE(html.find("a &lt; b"), std::string::npos) << html;  // escaped
    EXPECT_NE(html.find("aabench claims --only x"), std::string::npos) << html;
}

class ClaimsCli : public CliRunner {
protected:
    ClaimsCli() : CliRunner("claims") {}
};

TEST_F(ClaimsCli, OneClaimPrintsItsVerdictAndWritesThePageAndJson) {
    const CliOutput r = run(fmt::format("claims --only circle-step-test --out {}", path("out")));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("circle-step-test"), std::string::npos) << r.out;
    EXPECT_NE(read_file(path("out/claims.md")).find(kVerdictRule), std::string::npos);
    EXPECT_NE(read_file(path("out/claims.json")).find("\"verdict\""), std::string::npos);
}

TEST_F(ClaimsCli, AnUnknownClaimIsOneLineAndExitTwo) {
    const CliOutput r = run(fmt::format("claims --only no-such-claim --out {}", path("out")));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no-such-claim"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(path("out/claims.md")));
}

}  // namespace
}  // namespace aabench
