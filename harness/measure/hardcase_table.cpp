// The hard-case table and JSON (harness/measure/hardcases.h): invariant and outcome names, the
// text table the CLI prints (grid, failures, documented properties, worst passing values) and
// the rows as JSON.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "harness/measure/hardcase_internal.h"
#include "harness/measure/hardcases.h"

namespace aabench {

namespace hardcase_detail {

std::string short_number(double v) { return fmt::format("{:.3g}", v); }

}  // namespace hardcase_detail

using namespace hardcase_detail;

const char* invariant_name(Invariant invariant) {
    switch (invariant) {
        case Invariant::kFinite: return "finite";
        case Invariant::kRange: return "range";
        case Invariant::kArea: return "area";
        case Invariant::kContinuity: return "continuity";
        case Invariant::kTranslation: return "translation";
    }
    return "?";
}

const char* outcome_name(Outcome outcome) {
    switch (outcome) {
        case Outcome::kNotApplicable: return "n/a";
        case Outcome::kPass: return "pass";
        case Outcome::kDocumented: return "documented";
        case Outcome::kFail: return "FAIL";
    }
    return "?";
}

namespace {

// The grid: a numbered column per method, a line per case, each cell the row's outcome.
std::string outcome_grid(const std::vector<HardCaseRow>& rows) {
    std::vector<std::string> cases, methods;
    for (const HardCaseRow& r : rows) {
        if (std::find(cases.begin(), cases.end(), r.case_name) == cases.end()) {
            cases.push_back(r.case_name);
        }
        if (std::find(methods.begin(), methods.end(), r.method) == methods.end()) {
            methods.push_back(r.method);
        }
    }
    auto find_row = [&](const std::string& c, const std::string& m) -> const HardCaseRow* {
        for (const HardCaseRow& r : rows) {
            if (r.case_name == c && r.method == m) return &r;
        }
        return nullptr;
    };
    std::string out = "Hard cases: pass, doc (a documented property of the method, within its "
                      "documented bound), FAIL, - (not run)\n\ncolumns:\n";
    for (std::size_t m = 0; m < methods.size(); ++m) {
        out += fmt::format("  {:>2}  {}\n", m + 1, methods[m]);
    }
    std::size_t name_width = 4;
    for (const std::string& c : cases) name_width = std::max(name_width, c.size());
    out += fmt::format("\n{:<{}}", "case", name_width);
    for (std::size_t m = 0; m < methods.size(); ++m) out += fmt::format(" {:>4}", m + 1);
    out += "\n";
    for (const std::string& c : cases) {
        out += fmt::format("{:<{}}", c, name_width);
        for (const std::string& m : methods) {
            const HardCaseRow* r = find_row(c, m);
            const Outcome o = r ? r->outcome : Outcome::kNotApplicable;
            out += fmt::format(" {:>4}", o == Outcome::kPass         ? "ok"
                                         : o == Outcome::kDocumented ? "doc"
                                         : o == Outcome::kFail       ? "FAIL"
                                                                     : "-");
        }
        out += "\n";
    }
    return out;
}

// Failures, each with its worst value and pixel.
std::string failure_list(const std::vector<HardCaseRow>& rows) {
    std::string failures;
    for (const HardCaseRow& r : rows) {
        for (std::size_t i = 0; i < kInvariantCount; ++i) {
            const InvariantResult& res = r.results[i];
            if (res.outcome != Outcome::kFail) continue;
            failures += fmt::format("  {} / {} / {}: {} > bound {}", r.case_name, r.method,
                                    invariant_name(static_cast<Invariant>(i)),
                                    short_number(res.value), short_number(res.bound));
            if (res.x >= 0) failures += fmt::format(" at pixel ({}, {})", res.x, res.y);
            failures += fmt::format(": {}\n", res.note);
        }
    }
    return "\nfailures:\n" + (failures.empty() ? std::string("  none\n") : failures);
}

// Documented properties seen: per method and invariant, how often and the worst case.
std::string documented_list(const std::vector<HardCaseRow>& rows) {
    struct Seen {
        std::string method;
        Invariant invariant;
        int count = 0;
        const HardCaseRow* worst = nullptr;
        double worst_ratio = -1.0;
    };
    std::vector<Seen> seen;
    for (const HardCaseRow& r : rows) {
        for (std::size_t i = 0; i < kInvariantCount; ++i) {
            const InvariantResult& res = r.results[i];
            if (res.outcome != Outcome::kDocumented) continue;
            const auto inv = static_cast<Invariant>(i);
            auto it = std::find_if(seen.begin(), seen.end(), [&](const Seen& s) {
                return s.method == r.method && s.invariant == inv;
            });
            if (it == seen.end()) it = seen.insert(seen.end(), Seen{r.method, inv});
            ++it->count;
            const double ratio = res.documented_bound > 0.0 ? res.value / res.documented_bound
                                                            : res.changed_fraction;
            if (ratio > it->worst_ratio) it->worst_ratio = ratio, it->worst = &r;
        }
    }
    std::string out = "\ndocumented properties (method, invariant: cases; worst case):\n";
    if (seen.empty()) out += "  none\n";
    for (const Seen& s : seen) {
        const InvariantResult& res = s.worst->at(s.invariant);
        out += fmt::format("  {}, {}: {} case{}; worst {}: ", s.method, invariant_name(s.invariant),
                           s.count, s.count == 1 ? "" : "s", s.worst->case_name);
        if (s.invariant == Invariant::kArea) {
            out += fmt::format("|error| {} (documented bound {})", short_number(res.value),
                               short_number(res.documented_bound));
        } else {
            out += fmt::format("max change {}, {:.2g}% of pixels changed (allowed: the {:.2g}% "
                               "within {} px of an edge)",
                               short_number(res.value), 100.0 * res.changed_fraction,
                               100.0 * res.allowed_fraction, kFlipReachPx);
        }
        out += fmt::format("\n      {}\n", res.note);
    }
    return out;
}

// The worst value per invariant among passing results: how close to its bound it came.
std::string worst_passing(const std::vector<HardCaseRow>& rows) {
    std::string out = "\nworst passing value per invariant (value / bound):\n";
    for (std::size_t i = 0; i < kInvariantCount; ++i) {
        const HardCaseRow* worst_row = nullptr;
        double worst_ratio = -1.0;
        int passes = 0, documented = 0, failed = 0;
        for (const HardCaseRow& r : rows) {
            const InvariantResult& res = r.results[i];
            passes += res.outcome == Outcome::kPass;
            documented += res.outcome == Outcome::kDocumented;
            failed += res.outcome == Outcome::kFail;
            if (res.outcome != Outcome::kPass) continue;
            const double ratio = res.bound > 0.0 ? res.value / res.bound : res.value;
            if (ratio > worst_ratio) worst_ratio = ratio, worst_row = &r;
        }
        out += fmt::format("  {:<12} {} pass, {} documented, {} failed",
                           invariant_name(static_cast<Invariant>(i)), passes, documented, failed);
        if (worst_row) {
            const InvariantResult& res = worst_row->results[i];
            out += fmt::format("; worst {} (bound {}) on {} / {}", short_number(res.value),
                               short_number(res.bound), worst_row->case_name, worst_row->method);
        }
        out += "\n";
    }
    return out;
}

}  // namespace

// ---- Public: formatting ----

std::string format_hard_case_table(const std::vector<HardCaseRow>& rows) {
    return outcome_grid(rows) + failure_list(rows) + documented_list(rows) + worst_passing(rows);
}

std::string format_hard_case_json(const std::vector<HardCaseRow>& rows) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const HardCaseRow& r : rows) {
        nlohmann::ordered_json row;
        row["case"] = r.case_name;
        row["method"] = r.method;
        row["reference"] = r.reference;
        row["width"] = r.width;
        row["height"] = r.height;
        row["outcome"] = outcome_name(r.outcome);
        nlohmann::ordered_json invariants = nlohmann::ordered_json::object();
        for (std::size_t i = 0; i < kInvariantCount; ++i) {
            const InvariantResult& res = r.results[i];
            nlohmann::ordered_json item;
            item["outcome"] = outcome_name(res.outcome);
            // JSON has no infinity: an infinite figure (a NaN pixel) is written as null.
            auto number = [](double v) {
                return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
            };
            item["value"] = number(res.value);
            item["bound"] = number(res.bound);
            if (res.outcome == Outcome::kDocumented || res.documented_bound > 0.0) {
                item["documented_bound"] = number(res.documented_bound);
            }
            if (static_cast<Invariant>(i) == Invariant::kContinuity ||
                static_cast<Invariant>(i) == Invariant::kTranslation) {
                item["changed_fraction"] = res.changed_fraction;
                item["allowed_fraction"] = res.allowed_fraction;
            }
            if (res.x >= 0) item["pixel"] = {res.x, res.y};
            if (!res.note.empty()) item["note"] = res.note;
            invariants[invariant_name(static_cast<Invariant>(i))] = std::move(item);
        }
        row["invariants"] = std::move(invariants);
        out.push_back(std::move(row));
    }
    return out.dump(1);
}

}  // namespace aabench
