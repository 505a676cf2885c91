// The metric registry: ONE table of every figure a result row can hold (docs/metrics.md is
// checked against it by tests/metric_registry_test.cpp). Each entry says what the figure is
// (key, table header, definition, unit), which way is better, whether the regression gate holds
// it and with what tolerance, where it applies (2-D, 3-D, line scores, sequences) and how the
// tables show it. The CSV and JSON columns (and JSON's "definitions"), the text table, the HTML
// table, the gate (aabench check) and `aabench score` all read this table; a result row holds
// its figures by the metric's index here (MetricValues), besides its identity fields
// (harness/measure/result_row.h). An entry also says how it is measured: its compute function
// and what that needs prepared per scene, which compare and score run for every entry
// (harness/measure/metric_input.h; docs/metrics.md, "The metric registry").
//
// The built-in metrics come first, in the order of the enum below (the column order), then a
// generated family of two metrics per world stage (stage_<name>_ms, stage_<name>_bytes), then
// the jagged-edge error per edge angle (edge_rmse_<lo>_<hi>deg, harness/measure/edge_angles.h).
// A test may add a metric for its own lifetime (ScopedMetric); nothing else changes the table.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "harness/world/plan.h"

namespace aabench {

// A metric's index in the registry: the index of its value in MetricValues.
using MetricId = int;

namespace metric {
// The built-in metrics, in registry (column) order; metric_registry.cpp's table has one entry
// per enumerator in this order (a static_assert checks it).
enum Builtin : MetricId {
    kBoxRmse,
    kBoxMaxAbs,
    kBoxMaxX,
    kBoxMaxY,
    kBoxBias,
    kDropout,
    kDropoutPixels,
    kDropoutCandidates,
    kNonfinite,
    kOwnRmse,
    kOwnMaxAbs,
    kOwnBias,
    kFlip,
    kSrgbRmse,
    kLumaRmse,
    kEdgeRmse,
    kMassWorst,
    kMassMean,
    kAliasTotalDb,
    kAliasLowDb,
    kCrawl,
    kPopping,
    kSsim,
    kSeamsMax,
    kSeamsMean,
    kLinePrecision,
    kLineRecall,
    kLineRmse,
    kExactDepthLinePrecision,
    kExactDepthLineRecall,
    kExactDepthLineRmse,
    kLineContourPrecision,
    kLineContourRecall,
    kLineCreasePrecision,
    kLineCreaseRecall,
    kExactDepthLineContourPrecision,
    kExactDepthLineContourRecall,
    kExactDepthLineCreasePrecision,
    kExactDepthLineCreaseRecall,
    kTimeMedianNs,
    kTimeMinNs,
    kTimeMaxNs,
    kTimeMethodMs,
    kTimeStagesMs,
    kExternalStartupNs,
    kExternalReportedMs,
    kMpixelPerS,
    kMedgesPerS,
    kWorldMs,
    kBuiltinCount
};
}  // namespace metric

// The generated family after the built-ins: time (ms, one run) and heap bytes of a world stage.
MetricId stage_ms_metric(int stage);
MetricId stage_bytes_metric(int stage);

// The per-angle family: edge_rmse over the pixels near edges whose angle from the horizontal
// lies in [bin * kEdgeAngleBinDeg, (bin + 1) * kEdgeAngleBinDeg) degrees (the last bin closed).
// 5° bins: the claims' resolution (docs/claims.md); 18 of them fold every edge into 0°..90°.
inline constexpr double kEdgeAngleBinDeg = 5.0;
inline constexpr int kEdgeAngleBins = 18;
MetricId edge_angle_metric(int bin);

enum class Better { kLower, kHigher, kNeither };

// The regression gate's rule for a metric. kYes: worse when new > old * (1 + rel) + abs (for a
// higher-is-better metric: new < old * (1 - rel) - abs), with the metric's own tolerance, or the
// one given on the command line (aabench check --tolerance) when there is one. kOnRequest: the
// median time, gated only with --time-tolerance. kNo: not gated.
enum class Gate { kNo, kYes, kOnRequest };
struct GateTolerancePair {
    double rel = 0.0;
    double abs = 0.0;
};
// The image-error figures' tolerance. 5%: above run-to-run noise of nothing (errors are
// deterministic), below any change a reader of the tables would call a change. 1e-4: a
// hundredth of a percent of the value range; below it, a rise from an almost-exact figure
// (exact's 1e-9) is float rounding, not a regression.
inline constexpr GateTolerancePair kImageErrorTolerance{0.05, 1e-4};

// Where a metric can have a value (bits). A metric outside a row's kind is empty there.
enum Applies : unsigned {
    kApplies2d = 1u,         // 2-D patterns and scene files
    kApplies3d = 2u,         // 3-D patterns (world stages)
    kAppliesLines = 4u,      // scenes with `edges` (line scores); JSON writes them only there
    kAppliesSequences = 8u,  // frame sequences (none yet: room for them)
    kAppliesImages = kApplies2d | kApplies3d,
};

// How a value is shown in the text and HTML tables (the files always hold the exact value).
enum class Shown { kGeneral, kSigned, kPercent, kMsFromNs, kInteger };

// Where a metric is shown besides results.csv and results.json (bits).
enum ShownIn : unsigned {
    kInText = 1u,              // the text table (table.txt, compare's output), in registry order
    kInHtml = 2u,              // the HTML table when some row of the pattern has a value
    kInHtmlAlways = 4u,        // the HTML table's leading columns, even when empty
    kInScore = 8u,             // `aabench score`: needs only the one image
    kInLineTable = 16u,        // the text table's line-score block (with its exact-depth twin)
    kInHtmlWhenNonzero = 32u,  // the HTML table when some row of the pattern is not 0: an alarm
};

// What a metric's computation needs prepared once per scene (bits): the scorer builds each
// preparation only when some metric it computes asks for it (harness/measure/metric_input.h).
enum Needs : unsigned {
    kNeedsEdgeBand = 1u,   // the pixels within kEdgeBandPx of an edge (edge_band_mask)
    kNeedsAngleBins = 2u,  // each band pixel's edge-angle bin (edge_angle_bins)
    kNeedsSeamMask = 4u,   // 3-D: the pixels of edges two visible faces share (seam_mask)
    kNeedsMasses = 8u,     // the thin objects, each rendered alone (prepare_mass_reference)
    kNeedsMotion = 16u,    // the moved frames and their references (prepare_motion_reference)
    kNeedsLines = 32u,     // scenes with `edges`: the ground-truth lines (prepare_line_truth)
    kNeedsMethod = 64u,    // the method itself, run again: none in `aabench score`
};

struct MetricInput;  // harness/measure/metric_input.h
struct ResultRow;    // harness/measure/result_row.h
// Computes a metric from one scored image and writes it into the row: its own value (`self`
// is its id), or a group's, when one measurement gives several (compare_to_reference gives
// box_* and dropout*: the first row of the group computes them all, the others have none).
using MetricFn = void (*)(const MetricInput& in, MetricId self, ResultRow& row);

struct MetricDef {
    std::string key;         // CSV/JSON column name
    std::string header;      // short name in the text and HTML tables
    std::string definition;  // JSON "definitions", the HTML header's hover text, docs
    std::string unit;        // "1" for a pure number or fraction
    Better better = Better::kNeither;
    Gate gate = Gate::kNo;
    GateTolerancePair tolerance{};  // when gate == kYes
    unsigned applies = kAppliesImages;
    unsigned shown_in = 0;
    Shown shown = Shown::kGeneral;
    int text_width = 8;  // in the text table: columns and decimals
    int text_decimals = 5;
    bool integer = false;  // written as an integer (counts, pixel positions)
    // Not in every results file that exists (added later): a row without it reads as empty.
    bool may_be_absent = false;
    // How it is measured: nullptr for figures the run writes itself (timing, world stage
    // costs) and for the later rows of a group.
    MetricFn compute = nullptr;
    unsigned needs = 0;    // Needs bits
    bool symptom = false;  // measured on default rows only, and only with compare's symptoms
};

class MetricRegistry {
public:
    // The one registry: the built-ins, then the stage family, then any ScopedMetric.
    static MetricRegistry& global();

    int size() const { return static_cast<int>(defs_.size()); }
    const MetricDef& operator[](MetricId id) const { return defs_[static_cast<std::size_t>(id)]; }
    const std::vector<MetricDef>& all() const { return defs_; }
    // The metric of this key, or nullopt.
    std::optional<MetricId> find(std::string_view key) const;

private:
    friend class ScopedMetric;
    MetricRegistry();
    std::vector<MetricDef> defs_;
};

inline const MetricRegistry& metric_registry() { return MetricRegistry::global(); }

// Adds a metric to the registry for this object's lifetime (tests: every consumer then shows
// and gates it). Scopes nest; each must end before the one made before it (ids are indices;
// ending an older one first aborts).
class ScopedMetric {
public:
    explicit ScopedMetric(MetricDef def);
    ~ScopedMetric();
    ScopedMetric(const ScopedMetric&) = delete;
    ScopedMetric& operator=(const ScopedMetric&) = delete;
    MetricId id() const { return id_; }

private:
    MetricId id_;
};

// A row's figures, by metric id. A metric without a value (never set, or added to the registry
// after the row was made) reads as NaN: "does not apply" or "not measured".
class MetricValues {
public:
    double operator[](MetricId id) const {
        const auto k = static_cast<std::size_t>(id);
        return k < values_.size() ? values_[k] : kNotMeasured;
    }
    double& operator[](MetricId id);

private:
    static constexpr double kNotMeasured = __builtin_nan("");
    std::vector<double> values_;
};

}  // namespace aabench
