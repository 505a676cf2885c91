// The temporal measures' place in the metric registry (harness/measure/metric_registry.h): a
// family after the built-ins, the stage family and the per-angle family, each applying to
// sequences only (kAppliesSequences), so that the tables and files of still runs are as they
// were. Definitions: docs/metrics.md, "Sequences"; the runner: harness/measure/sequence_run.h.
#pragma once

#include "harness/measure/metric_registry.h"
#include "harness/measure/result_row.h"

namespace aabench {

enum class SequenceMetric : int {
    kSteadyRmse,
    kConvergence,
    kFlicker,
    kGhostRmse,
    kRestRmse,
    kGhostRatio,
    kEdgeBlur,
    kFrameMs,
    kCount
};

// The registry id of a temporal measure.
MetricId sequence_metric(SequenceMetric which);

// True when the row has a temporal measure (a row of compare --sequences).
bool is_sequence_row(const ResultRow& row);

}  // namespace aabench
