// The papers' claims, each measured: the claim in one sentence, the command that measures it, the
// numbers, and a verdict by one rule fixed before measuring (kVerdictRule; docs/claims.md is the
// page `aabench claims --page` writes from these rows). Pure computation: no I/O.
//
// A claim is a list of checks, one per scene (or angle, or radius) measured. Each check is an
// ordering (the claimed smaller figure at least kClaimMargin below the larger), an equality (the
// two within kClaimMargin of the larger), an occurrence (a count above 0) or a bound (a count at
// most a stated value). The verdict: holds
// when every check holds, partly when some do, does not hold when none does.
#pragma once

#include <string>
#include <vector>

namespace aabench {

// 10 %: a difference a reader of the tables calls a difference (the regression gate's 5 % is
// about noise of one figure; a claim compares two methods, so twice that).
inline constexpr double kClaimMargin = 0.10;

// The rule as the page states it (tests/claims_test.cpp checks docs/claims.md holds it).
extern const char* const kVerdictRule;

enum class CheckKind { kOrdering, kEquality, kOccurrence, kAtMost };
enum class Verdict { kHolds, kPartly, kDoesNotHold };
const char* verdict_name(Verdict verdict);  // "holds", "partly", "does not hold"

struct ClaimCheck {
    CheckKind kind = CheckKind::kOrdering;
    std::string scene;  // what it was measured on: "star", "strips at 23°", "r = 804"
    // Ordering: a_label's figure `a` is claimed below b_label's `b` (a figure where lower is
    // better, or a count). Equality: a and b claimed equal. Occurrence: `a` claimed > 0. At
    // most: `a` claimed <= `b` (a count against a stated bound, no margin).
    std::string a_label;
    double a = 0.0;
    std::string b_label;
    double b = 0.0;
    bool holds() const;
};

struct ClaimTable {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

struct ClaimResult {
    std::string id;       // short and stable: "nn-2.3-thin-objects"; `aabench claims --only ID`
    std::string source;   // "Nishita & Nakamae 1984, §2.3"
    std::string claim;    // the paper's claim in one sentence
    std::string measure;  // how it is measured: scenes, methods, figure, threshold
    std::string command;  // the command that prints these numbers
    std::vector<ClaimCheck> checks;
    std::vector<ClaimTable> tables;  // the numbers
    std::string finding;             // the numbers that decide, in one sentence
    Verdict verdict() const;
    int checks_holding() const;
};

struct ClaimsOptions {
    int size = 256;                 // side of the 2-D patterns and the torus (px)
    int motion_size = 128;          // side of the 3-D scenes filmed under camera motion (px)
    int motion_frames = 8;          // camera offsets of the line-image crawl
    int radius_max = 1024;          // the circle's table: aa-circle's default radius_max
    std::vector<std::string> only;  // claim ids to run; empty: all
};

// The ids in page order, and every claim measured (those of options.only, in page order).
// InputError for an unknown id in options.only.
const std::vector<std::string>& claim_ids();
void check_claim_ids(const std::vector<std::string>& ids);  // InputError naming an unknown one
std::vector<ClaimResult> measure_claims(const ClaimsOptions& options);

// ---- The measurements, one file each by subject (claims_*.cpp) ----
ClaimResult claim_thin_objects(const ClaimsOptions& options);           // §2.3
ClaimResult claim_near_horizontal(const ClaimsOptions& options);        // §5, per angle
ClaimResult claim_bc_better_than_d(const ClaimsOptions& options);       // §4
ClaimResult claim_bc_equal_d_horizontal(const ClaimsOptions& options);  // §4, Fig. 5(f)
ClaimResult claim_n3_enough(const ClaimsOptions& options);              // §4
ClaimResult claim_box_gauss_equal(const ClaimsOptions& options);        // §5
ClaimResult claim_line_crawl(const ClaimsOptions& options);             // S&T §3.5
ClaimResult claim_facet_creases(const ClaimsOptions& options);          // S&T §6.2(2)
ClaimResult claim_circle_steps(const ClaimsOptions& options);           // the circle's step test
ClaimResult claim_ssaa_axes(const ClaimsOptions& options);              // Kato & Kameyama

// ---- Shared by the claims files ----

// "0.0123" with 3 significant digits; "-" for NaN.
std::string claim_number(double v);

// The circle's step test (the fast antialiased circle: methods/aa_circle.cpp) on one radius:
// the octant's x per row y with the truncated level (alpha_max) and with the exact level.
struct CircleStepFigures {
    int radius = 0;
    int missed_steps = 0;      // rows where x should step (exact) and the test kept it
    int largest_error_px = 0;  // max |x_truncated - x_exact| over the rows both draw
    int rows_drawn = 0;        // rows of the truncated loop
    int table_rows = 0;        // ceil(r / sqrt 2): the rows the source's table holds
    bool reads_past_table() const { return rows_drawn > table_rows; }
    std::vector<int> x_truncated;  // x per row y = 0 .. rows_drawn
};
CircleStepFigures circle_step_figures(int radius, int alpha_max);

}  // namespace aabench
