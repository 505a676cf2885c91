// Filling result rows (harness/measure/result_row.h).
#include "harness/measure/result_row.h"

#include "harness/measure/sequence_metrics.h"

#include <cmath>

namespace aabench {

using namespace metric;

bool has_line_scores(const ResultRow& row) {
    const MetricRegistry& registry = metric_registry();
    for (MetricId id = 0; id < registry.size(); ++id) {
        if ((registry[id].applies & kAppliesLines) && !std::isnan(row[id])) return true;
    }
    return false;
}

bool is_sequence_row(const ResultRow& row) {
    const MetricRegistry& registry = metric_registry();
    for (MetricId id = 0; id < registry.size(); ++id) {
        if (registry[id].applies == kAppliesSequences && !std::isnan(row[id])) return true;
    }
    return false;
}

void set_box_stats(ResultRow& row, const ErrorStats& stats) {
    row[kBoxRmse] = stats.rmse;
    row[kBoxMaxAbs] = stats.max_abs;
    row[kBoxMaxX] = stats.max_x;
    row[kBoxMaxY] = stats.max_y;
    row[kBoxBias] = stats.bias;
    row[kDropout] = stats.dropout;
    row[kDropoutPixels] = static_cast<double>(stats.dropout_pixels);
    row[kDropoutCandidates] = static_cast<double>(stats.dropout_candidates);
    row[kNonfinite] = static_cast<double>(stats.nonfinite);
}

void set_own_stats(ResultRow& row, const ErrorStats& stats) {
    row[kOwnRmse] = stats.rmse;
    row[kOwnMaxAbs] = stats.max_abs;
    row[kOwnBias] = stats.bias;
}

void set_timing(ResultRow& row, const TimingStats& time, double relied_stages_ms) {
    const double stages_ns = relied_stages_ms * 1e6;
    row[kTimeMedianNs] = time.median_ns + stages_ns;
    row[kTimeMinNs] = time.min_ns + stages_ns;
    row[kTimeMaxNs] = time.max_ns + stages_ns;
    row.time_runs = time.runs;
    row.time_threads = time.threads;
    row[kTimeMethodMs] = time.median_ns * 1e-6;
    row[kTimeStagesMs] = std::isnan(time.median_ns) ? time.median_ns : relied_stages_ms;
    const double seconds = row[kTimeMedianNs] * 1e-9;
    if (seconds > 0.0) {
        row[kMpixelPerS] = static_cast<double>(row.width) * row.height / seconds / 1e6;
        row[kMedgesPerS] = static_cast<double>(row.edges) / seconds / 1e6;
    }
}

void set_line_scores(ResultRow& row, const LineScores& s, bool exact_depth) {
    row[exact_depth ? kExactDepthLinePrecision : kLinePrecision] = s.precision;
    row[exact_depth ? kExactDepthLineRecall : kLineRecall] = s.recall;
    row[exact_depth ? kExactDepthLineRmse : kLineRmse] = s.rmse;
    row[exact_depth ? kExactDepthLineContourPrecision : kLineContourPrecision] =
        s.contour_precision;
    row[exact_depth ? kExactDepthLineContourRecall : kLineContourRecall] = s.contour_recall;
    row[exact_depth ? kExactDepthLineCreasePrecision : kLineCreasePrecision] = s.crease_precision;
    row[exact_depth ? kExactDepthLineCreaseRecall : kLineCreaseRecall] = s.crease_recall;
}

void add_stage_cost(ResultRow& row, int stage, double time_ms, double bytes) {
    row[stage_ms_metric(stage)] = time_ms;
    row[stage_bytes_metric(stage)] = bytes;
    row[kWorldMs] = (std::isnan(row[kWorldMs]) ? 0.0 : row[kWorldMs]) + time_ms;
}

}  // namespace aabench
