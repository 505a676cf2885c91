// The claims' verdict rule, their list and the circle's step test (harness/measure/claims.h).
#include "harness/measure/claims.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>

#include "patterns/scene/scene.h"

namespace aabench {

const char* const kVerdictRule =
    "A claim is checked on every scene it speaks of (a pattern, an edge angle, a radius), and "
    "the rule is fixed before measuring. A claimed ordering holds on a scene when the figure "
    "claimed smaller is below the other by at least 10 % of the other (a < b and a <= 0.9 b for "
    "figures >= 0). A claimed equality holds on a scene when the two figures lie within 10 % of "
    "the larger. A claimed occurrence holds on a scene when its count is above 0, a claimed "
    "bound (a sample count at most n) when it is met. The claim holds when it holds on every "
    "scene measured, partly when on some, and does not hold otherwise.";

const char* verdict_name(Verdict verdict) {
    switch (verdict) {
        case Verdict::kHolds:
            return "holds";
        case Verdict::kPartly:
            return "partly";
        case Verdict::kDoesNotHold:
            return "does not hold";
    }
    return "?";
}

bool ClaimCheck::holds() const {
    // NaN compares false everywhere: a figure that was not measured never holds a claim.
    switch (kind) {
        case CheckKind::kOrdering:
            return a < b && a <= b - kClaimMargin * std::abs(b);
        case CheckKind::kEquality:
            return std::abs(a - b) <= kClaimMargin * std::max(std::abs(a), std::abs(b));
        case CheckKind::kOccurrence:
            return a > 0.0;
        case CheckKind::kAtMost:
            return a <= b;
    }
    return false;
}

int ClaimResult::checks_holding() const {
    return static_cast<int>(
        std::count_if(checks.begin(), checks.end(), [](const ClaimCheck& c) { return c.holds(); }));
}

Verdict ClaimResult::verdict() const {
    const int n = checks_holding();
    if (!checks.empty() && n == static_cast<int>(checks.size())) return Verdict::kHolds;
    return n > 0 ? Verdict::kPartly : Verdict::kDoesNotHold;
}

std::string claim_number(double v) {
    if (std::isnan(v)) return "-";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    if (v == std::round(v) && std::abs(v) < 1e6)
        return fmt::format("{}", static_cast<long long>(v));
    return fmt::format("{:.3g}", v);
}

namespace {

using ClaimFn = ClaimResult (*)(const ClaimsOptions&);
const std::vector<std::pair<std::string, ClaimFn>>& claim_table() {
    static const std::vector<std::pair<std::string, ClaimFn>> table = {
        {"nn-2.3-thin-objects", claim_thin_objects},
        {"nn-5-near-horizontal", claim_near_horizontal},
        {"nn-4-bc-better-than-d", claim_bc_better_than_d},
        {"nn-4-bc-equal-d-horizontal", claim_bc_equal_d_horizontal},
        {"nn-4-n3-enough", claim_n3_enough},
        {"nn-5-box-gauss-equal", claim_box_gauss_equal},
        {"st-3.5-line-crawl", claim_line_crawl},
        {"st-6.2-facet-creases", claim_facet_creases},
        {"circle-step-test", claim_circle_steps},
        {"kk-ssaa-axes", claim_ssaa_axes},
    };
    return table;
}

}  // namespace

const std::vector<std::string>& claim_ids() {
    static const std::vector<std::string> ids = [] {
        std::vector<std::string> out;
        for (const auto& [id, fn] : claim_table()) out.push_back(id);
        return out;
    }();
    return ids;
}

void check_claim_ids(const std::vector<std::string>& only) {
    const auto& ids = claim_ids();
    for (const std::string& id : only) {
        if (std::find(ids.begin(), ids.end(), id) == ids.end()) {
            throw InputError(
                fmt::format("--only: unknown claim '{}' (claims: {})", id, fmt::join(ids, ", ")));
        }
    }
}

std::vector<ClaimResult> measure_claims(const ClaimsOptions& options) {
    check_claim_ids(options.only);
    std::vector<ClaimResult> out;
    for (const auto& [id, fn] : claim_table()) {
        if (!options.only.empty() &&
            std::find(options.only.begin(), options.only.end(), id) == options.only.end()) {
            continue;
        }
        ClaimResult r = fn(options);
        r.id = id;
        r.command = "aabench claims --only " + id;
        out.push_back(std::move(r));
    }
    return out;
}

// ---- The circle's step test ----

CircleStepFigures circle_step_figures(int radius, int alpha_max) {
    CircleStepFigures f;
    f.radius = radius;
    f.table_rows = static_cast<int>(std::ceil(radius / std::sqrt(2.0)));
    // The exact step: x = ceil(x_t), x_t = sqrt(r^2 - y^2) (the outer of the two pixels that
    // straddle the arc), which the level l = ceil(x_t) - x_t follows when kept in full.
    auto exact_x = [radius](int y) {
        const double xt = std::sqrt(static_cast<double>(static_cast<long long>(radius) * radius -
                                                        static_cast<long long>(y) * y));
        return static_cast<int>(std::ceil(xt));
    };
    auto level = [radius, alpha_max](int y) {
        const double xt = std::sqrt(static_cast<double>(static_cast<long long>(radius) * radius -
                                                        static_cast<long long>(y) * y));
        const double l = std::ceil(xt) - xt;
        // The source's int table; alpha_max = 0 keeps l itself (aa-circle's exact steps).
        return alpha_max == 0 ? l : std::trunc(alpha_max * l);
    };
    // The source's loop (methods/aa_circle.cpp), beside the exact x of each row.
    int x = radius, y = 0;
    double d_old = 0.0;
    int x_exact_prev = radius;
    f.x_truncated.push_back(x);
    while (y < x - 1) {
        ++y;
        const double d = level(y);
        if (d < d_old) --x;
        const int xe = exact_x(y);
        if (xe < x_exact_prev && x == f.x_truncated.back()) ++f.missed_steps;
        f.largest_error_px = std::max(f.largest_error_px, std::abs(x - xe));
        f.x_truncated.push_back(x);
        x_exact_prev = xe;
        d_old = d;
    }
    f.rows_drawn = y;
    return f;
}

ClaimResult claim_circle_steps(const ClaimsOptions& options) {
    ClaimResult r;
    r.source = "the fast antialiased circle (web article, docs/methods-circles.md)";
    r.claim =
        "The level read from the table decides the step of x (x steps left when d < d_old), so "
        "the loop needs no square root and reads only the table's rows y = 1..ceil(r / sqrt 2).";
    r.measure = fmt::format(
        "Every radius 1..{} (aa-circle's radius_max) at the source's ALPHA_MAX = 255: the "
        "source's loop beside the exact x = ceil(sqrt(r^2 - y^2)) of each row; a missed step is "
        "a row where the exact x steps and the truncated levels tie (d >= d_old); the position "
        "error is |x - exact x|; a radius reads past its table when the loop runs past "
        "y = ceil(r / sqrt 2). Each radius is a scene: the claim holds on a radius without a "
        "missed step.",
        options.radius_max);
    int radii_missing = 0, missed = 0, worst_error = 0, worst_radius = 0, past = 0;
    std::vector<int> past_radii, missing_radii;
    for (int radius = 1; radius <= options.radius_max; ++radius) {
        const CircleStepFigures f = circle_step_figures(radius, 255);
        ClaimCheck c;
        c.kind = CheckKind::kEquality;
        c.scene = fmt::format("r = {}", radius);
        c.a_label = "missed steps";
        c.a = f.missed_steps;
        c.b = 0.0;
        r.checks.push_back(c);
        if (f.missed_steps > 0) {
            ++radii_missing;
            missed += f.missed_steps;
            if (missing_radii.size() < 12) missing_radii.push_back(radius);
        }
        if (f.largest_error_px > worst_error) {
            worst_error = f.largest_error_px;
            worst_radius = radius;
        }
        if (f.reads_past_table()) {
            ++past;
            if (past_radii.size() < 12) past_radii.push_back(radius);
        }
    }
    ClaimTable t;
    t.header = {"radii",
                "radii with a missed step",
                "missed steps",
                "largest position error (px)",
                "at radius",
                "radii reading past the table",
                "first radii with a miss",
                "first radii reading past the table"};
    t.rows.push_back({fmt::format("1..{}", options.radius_max), std::to_string(radii_missing),
                      std::to_string(missed), std::to_string(worst_error),
                      std::to_string(worst_radius), std::to_string(past),
                      fmt::format("{}", fmt::join(missing_radii, ", ")),
                      fmt::format("{}", fmt::join(past_radii, ", "))});
    r.tables.push_back(std::move(t));
    r.finding = fmt::format(
        "{} of {} radii miss a step ({} misses in all), the largest position error is {} px "
        "(r = {}), and {} radii read past their table row",
        radii_missing, options.radius_max, missed, worst_error, worst_radius, past);
    return r;
}

}  // namespace aabench
