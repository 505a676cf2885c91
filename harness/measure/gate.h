// The regression gate (aabench check): a baseline's rows run again and every gated error figure
// compared, so that CI fails when antialiasing gets worse. Pure computation: the CLI reads the
// baseline and the scene files, the report formats the outcome.
//
// Which figures are gated, which way is better and with what tolerance is the metric registry's
// (harness/measure/metric_registry.h: Gate, Better, tolerance; docs/metrics.md lists them). The
// built-in gated figures are the image errors, all "lower is better" and all in image-value
// units or fractions, so one relative + absolute tolerance means the same for each:
//   box_rmse, box_max_abs, dropout, nonfinite, own_rmse, own_max_abs, edge_rmse, crawl,
//   seams_max, seams_mean.
// Not gated:
//   box_bias / own_bias   signed: closer to 0 is better, and |bias| <= rmse is gated already;
//   mass_*, popping       ratios about 1 (1 is perfect; a mass above 1 is a fault too; popping
//                         is infinite when an object vanishes): not "lower is better";
//   alias_*_db            logarithmic and negative: a relative tolerance has no meaning there;
//   ssim                  higher is better and saturates near 1; rmse and edge_rmse see it.
//
// A figure is worse when !(new <= old * (1 + rel) + abs) (higher-is-better figures: when
// !(new >= old * (1 - rel) - abs)): written so that a NaN new value fails (the comparison is
// false), as OpenImageIO's compare() does. NaN means "does not apply" or
// "could not be measured"; consistently:
//   old NaN, new NaN      unchanged;
//   old NaN, new number   "appeared" (the figure applies now): reported, not gated;
//   old number, new NaN   worse (it can no longer be measured);
//   old +inf              nothing is worse than it; new +inf from a finite old value is worse.
// Timings are reported (ratio new / old of the median) and gated only with a time tolerance:
// time worse when !(new <= old * (1 + time_rel)).
// A baseline row the new run does not produce (a method or pattern gone, a sweep changed) is
// "missing" and fails the gate: a gate must not pass by checking less. The one exception is
// said aloud: rows of an external renderer (compare --external, method "external:NAME") are
// not re-run — the baseline does not hold the command — and are counted as such.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "harness/measure/compare.h"

namespace aabench {

struct GateTolerance {
    // When set (aabench check --tolerance), they replace every gated metric's own tolerance
    // (the registry's; kImageErrorTolerance for the built-ins).
    std::optional<double> rel;
    std::optional<double> abs;
    std::optional<double> time_rel;  // gate timings too when set
};

// The tolerance the gate applies to `def` under `tolerance`.
GateTolerancePair tolerance_for(const MetricDef& def, const GateTolerance& tolerance);

// The metrics the gate compares (Gate::kYes in the registry), in registry order.
std::vector<MetricId> gated_metrics();

enum class GateVerdict {
    kWorse,     // beyond the tolerance: fails the gate
    kWithin,    // worse, but within the tolerance
    kBetter,    // lower than before
    kAppeared,  // NaN before, a number now (reported only)
    kMissing,   // the baseline row is not in the new run: fails the gate
};
const char* verdict_name(GateVerdict verdict);

struct GateChange {
    std::string pattern;  // the row's pattern spec (or scene-file stem)
    std::string pattern_id;
    std::string method;
    std::string figure;  // a gated column, "time_median_ns", or empty for a missing row
    double old_value = kNaN;
    double new_value = kNaN;
    double bound = kNaN;  // the largest new value that passes
    GateVerdict verdict = GateVerdict::kWithin;
};

struct GateResult {
    std::vector<GateChange> changes;  // every figure that changed, in baseline row order
    long long rows_checked = 0;       // baseline rows found in the new run
    long long figures_checked = 0;    // gated figures compared
    long long failures = 0;           // kWorse + kMissing
    long long external_rows = 0;      // baseline rows of external renderers, not re-run
    // Timing: the geometric mean and the largest of new/old median time over the rows with
    // both times > 0 (NaN when there is none); the row of the largest.
    double time_ratio_geomean = kNaN;
    double time_ratio_max = kNaN;
    std::string time_ratio_max_row;
    bool passed() const { return failures == 0; }
};

// The rows' method and pattern specs resolved again through today's registries, so that a
// parameter added since the baseline was made (whose default keeps the old behaviour, e.g.
// ssaa's pattern=grid) does not make the old rows look missing. A spec that no longer
// resolves (a method or pattern gone, a parameter removed) is left as it was: rerun_options
// leaves it out and gate_rows reports its rows missing.
void resolve_specs_again(std::vector<ResultRow>& rows);

// The runs that reproduce `baseline`: one per size of its built-in patterns' rows (their
// pattern specs and the methods of their default rows, with sweep when any row is a sweep
// point; specs that do not resolve left out), and one for its scene-file rows, which take their
// scenes from `scene_files` (by path; InputError if one is not there, or its size is not the size
// the baseline row has). `base` gives runs, jobs and the other options.
std::vector<CompareOptions> rerun_options(const std::vector<ResultRow>& baseline,
                                          const std::vector<SceneFileInput>& scene_files,
                                          const CompareOptions& base);

// True for the rows of compare --external (method_id "external:NAME").
bool is_external_row(const ResultRow& row);

// Compares every baseline row with the new row of the same pattern, method and size.
GateResult gate_rows(const std::vector<ResultRow>& baseline, const std::vector<ResultRow>& current,
                     const GateTolerance& tolerance);

}  // namespace aabench
