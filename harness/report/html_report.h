// The HTML report of a comparison run (results/RUN/index.html): what accuracy costs in time, for
// reading in a browser, offline. A pure consumer of the comparison's data: it measures nothing,
// and every number on the page comes from ReportData. docs/report.md says what each part shows
// and how to read it.
//
// Written, each file atomically (harness/report/image_io.h):
//   index.html                      one page, inline CSS and a small sorting script, no network
//   plots/<pattern>.svg             the accuracy-time plot (harness/report/svg_plot.h), also inlined
//   images/<pattern>/reference.*    the exact box reference
//   images/<pattern>/<method>.*     each method's image, signed error map, magnified crops
// PNGs are for viewing (the page states the display transform); beside each image (the
// reference's and each method's) a float32 EXR holds the linear data. Error maps have no EXR of
// their own: the error is the method's EXR minus the reference's, and at 256^2 the error EXRs
// alone would have taken the default run's report from 8.5 to 14 MB.
#pragma once

#include <string>
#include <vector>

#include "harness/measure/circle_timing.h"
#include "harness/measure/compare.h"
#include "harness/measure/cost_timing.h"
#include "harness/measure/edge_timing.h"
#include "harness/report/context.h"
#include "methods/scan/kernel/image.h"
#include "patterns/scene/scene.h"

namespace aabench {

// One pattern's figures: the comparison's kept images (harness/measure/compare.h). The scene's
// metadata key "focus" = "x,y,w,h" in px names the hardest region to magnify (absent: a
// centred square).
using PatternFigures = ComparisonFigures;

struct ReportData {
    // harness/report/context.h: command, git revision, compiler, flags, cpu, date
    RunContext context;
    std::vector<ResultRow> rows;  // every row: default methods and sweep points
    std::vector<PatternFigures> figures;
    std::string hard_case_table;  // preformatted text, may be empty (then omitted)
    // From `compare --bench-json` when the file has aabench_bench's circle benchmarks: the
    // time-per-circle plot (omitted when empty).
    std::vector<CircleTimingSeries> circle_timings;
    // From `compare --bench-json` when the file has aabench_bench's cost-model benchmarks
    // (`--aabench_cost_model`): time against pixels and against edges (omitted when empty).
    CostModel cost_model;
    // From `compare --bench-json` when the file has aabench_bench's edge-cost benchmarks
    // (--aabench_edge_cost): the edge stage's time against pixels and against faces, log-log
    // with fitted slopes (omitted when empty).
    EdgeTimings edge_timings;
    // From `compare --claims`: the claims table's section (harness/report/claims_table.h,
    // claims_html_section), omitted when empty.
    std::string claims_section;
};
// Writes dir/index.html, dir/plots/<pattern>.svg, dir/images/<pattern>/*.png and *.exr. Atomic
// per file. Creates `dir` and its subdirectories; leaves other files in them alone. Throws
// InputError when a directory or file cannot be written, or a figure's image is not the size
// of its reference.
void write_html_report(const std::string& dir, const ReportData& data);

}  // namespace aabench
