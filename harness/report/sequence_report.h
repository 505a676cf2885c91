// The files of a sequence run (`aabench compare --sequences`; docs/report.md, "Sequences"):
//
//   table.txt     a table per sequence: every method's temporal measures (the metric
//                 registry's temporal family, harness/measure/sequence_metrics.h)
//   results.csv, results.json   the rows, every registry column (as compare writes them)
//   frames.csv, frames.json     the error per frame: sequence, method, frame, box rmse, time
//   index.html    the sequence section per sequence: its table, the error per frame plotted
//                 for every method (log scale), for a still sequence the convergence plot
//                 (|e_t - steady| / steady, with the 10 % band), a filmstrip of magnified
//                 crops over frames with the reference's above, and the last frame's error maps
//   images/<sequence>/*.png     the filmstrip and error-map images
#pragma once

#include <string>
#include <vector>

#include "harness/measure/sequence_run.h"
#include "harness/report/context.h"

namespace aabench {

// The text tables, one per sequence, rows in run order; n/a rows say why.
std::string format_sequence_tables(const std::vector<ResultRow>& rows);
// "sequence,method,frame,box_rmse,frame_ms,disoccluded_share" (header line included).
std::string sequence_frames_csv(const SequenceRunResult& result);
// {"context": {...}, "sequences": [{"sequence", "frames", "disoccluded_share": [...],
//   "methods": [{"method", "box_rmse": [...], "frame_ms": [...]}]}]}
std::string sequence_frames_json(const SequenceRunResult& result, const RunContext& context);
// The plot of the error per frame (SVG document): one polyline per run, log y.
std::string frame_error_svg(const SequenceFigures& figures, bool relative_to_steady);

// Writes every file above into `dir` (created if missing), each atomically.
void write_sequence_results(const std::string& dir, const SequenceRunResult& result,
                            const RunContext& context);

}  // namespace aabench
