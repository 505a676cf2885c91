// The metric registry's table (harness/measure/metric_registry.h). Definitions are the ones
// results.json writes; docs/metrics.md lists the same keys (tests/metric_registry_test.cpp).
#include "harness/measure/metric_registry.h"

#include "harness/measure/sequence_metrics.h"
#include "harness/measure/pass_time.h"  // kTimePassKey
#include "harness/measure/metric_input.h"  // the built-ins' compute functions

#include <fmt/format.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace aabench {
namespace {

using namespace metric;

// One built-in metric, with named fields: what it is, how tables show it, and how it is
// measured (compute, needs, symptom: MetricDef's). Plain pointers so that the table is
// constexpr and its order can be checked against the enum at compile time.
struct BuiltinRow {
    MetricId id;
    const char* key;
    const char* header;
    const char* unit;
    Better better = Better::kNeither;
    Gate gate = Gate::kNo;
    unsigned applies = kAppliesImages;
    unsigned shown_in = 0;
    Shown shown = Shown::kGeneral;
    int text_width = 0;
    int text_decimals = 0;
    bool integer = false;
    bool may_be_absent = false;
    MetricFn compute = nullptr;
    unsigned needs = 0;
    bool symptom = false;
    const char* definition = "";
};

constexpr Better L = Better::kLower, H = Better::kHigher, N = Better::kNeither;
constexpr Gate kGated = Gate::kYes, kNo = Gate::kNo;
constexpr unsigned kImg = kAppliesImages, k3d = kApplies3d, kLn = kAppliesLines;
constexpr unsigned kHtmlCore = kInHtml | kInHtmlAlways;
constexpr Shown G = Shown::kGeneral, I = Shown::kInteger;

// clang-format off
constexpr BuiltinRow kBuiltins[] = {
    {.id = kBoxRmse, .key = "box_rmse", .header = "rmse", .unit = "value", .better = L,
     .gate = kGated, .shown_in = kInText | kHtmlCore | kInScore, .text_width = 8,
     .text_decimals = 5, .compute = measure_box,
     .definition = "sqrt(mean((rendered - box_reference)^2)) over all pixels (and, in a colour scene, all three channels)"},
    {.id = kBoxMaxAbs, .key = "box_max_abs", .header = "max_abs", .unit = "value", .better = L,
     .gate = kGated, .shown_in = kInText | kHtmlCore | kInScore, .text_width = 8,
     .text_decimals = 5,
     .definition = "max |rendered - box_reference|, at (box_max_x, box_max_y)"},
    {.id = kBoxMaxX, .key = "box_max_x", .header = "max_x", .unit = "px", .shown_in = kInScore,
     .shown = I, .integer = true},
    {.id = kBoxMaxY, .key = "box_max_y", .header = "max_y", .unit = "px", .shown_in = kInScore,
     .shown = I, .integer = true},
    {.id = kBoxBias, .key = "box_bias", .header = "bias", .unit = "value",
     .shown_in = kInText | kHtmlCore | kInScore, .shown = Shown::kSigned, .text_width = 9,
     .text_decimals = 5,
     .definition = "mean(rendered - box_reference); > 0 means too bright"},
    {.id = kDropout, .key = "dropout", .header = "dropout", .unit = "1", .better = L,
     .gate = kGated, .shown_in = kInText | kHtmlCore | kInScore, .shown = Shown::kPercent,
     .text_width = 8, .text_decimals = 2,
     .definition = "fraction of the pixels with box_reference > 0.1 that are rendered < 0.01"},
    {.id = kDropoutPixels, .key = "dropout_pixels", .header = "dropout_px", .unit = "pixels",
     .better = L, .shown_in = kInScore, .shown = I, .integer = true},
    {.id = kDropoutCandidates, .key = "dropout_candidates", .header = "candidates",
     .unit = "pixels", .shown_in = kInScore, .shown = I, .integer = true},
    {.id = kNonfinite, .key = "nonfinite", .header = "nonfinite", .unit = "pixels", .better = L,
     .gate = kGated, .shown_in = kInHtmlWhenNonzero | kInScore, .shown = I, .integer = true,
     .definition = "rendered pixels that are NaN or infinite"},
    {.id = kOwnRmse, .key = "own_rmse", .header = "own_rmse", .unit = "value", .better = L,
     .gate = kGated, .shown_in = kInText | kHtmlCore | kInScore, .text_width = 8,
     .text_decimals = 5, .compute = measure_own,
     .definition = "rmse against the exact reference of reference_filter: the discretisation error alone, the choice of filter taken out"},
    {.id = kOwnMaxAbs, .key = "own_max_abs", .header = "own_max_abs", .unit = "value", .better = L,
     .gate = kGated, .shown_in = kInScore,
     .definition = "max |rendered - own reference|"},
    {.id = kOwnBias, .key = "own_bias", .header = "own_bias", .unit = "value", .shown_in = kInScore,
     .shown = Shown::kSigned,
     .definition = "mean(rendered - own reference)"},
    {.id = kFlip, .key = "flip", .header = "flip", .unit = "1", .better = L, .gate = kGated,
     .shown_in = kInHtml | kInScore, .may_be_absent = true, .compute = measure_flip,
     .definition = "mean LDR-FLIP (Andersson et al. 2020) against the box reference, per pixel in [0, 1] (0 identical): the difference a viewer sees at 67 px per degree; grey as R = G = B, a colour scene in its colours, linear values clamped to [0, 1]"},
    {.id = kSrgbRmse, .key = "srgb_rmse", .header = "srgb_rmse", .unit = "value", .better = L,
     .gate = kGated, .shown_in = kInHtml | kInScore, .may_be_absent = true, .compute = measure_srgb,
     .definition = "rmse of the sRGB-encoded values (IEC 61966-2-1, clamped to [0, 1], not quantised) against the encoded box reference: the error in what a display shows"},
    {.id = kLumaRmse, .key = "luma_rmse", .header = "luma_rmse", .unit = "value", .better = L,
     .shown_in = kInHtml | kInScore, .may_be_absent = true,
     .definition = "colour scenes: rmse of the luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (linear Rec. 709) against the box reference's; box_rmse is then over all three channels, and the other figures are measured on the luminance"},
    {.id = kEdgeRmse, .key = "edge_rmse", .header = "edge", .unit = "value", .better = L,
     .gate = kGated, .shown_in = kInText | kInHtml | kInScore, .text_width = 8, .text_decimals = 5,
     .compute = measure_edge_band, .needs = kNeedsEdgeBand, .symptom = true,
     .definition = "jagged edges: rmse against the own-filter reference over the pixels whose centre lies within 1.5 px of an edge"},
    {.id = kMassWorst, .key = "mass_worst", .header = "mass", .unit = "1",
     .shown_in = kInText | kInHtml, .text_width = 6, .text_decimals = 3, .compute = measure_masses,
     .needs = kNeedsMasses | kNeedsMethod, .symptom = true,
     .definition = "vanishing thin objects: the smallest captured mass (rendered sum / exact sum, each thin object rendered alone) over the pattern's thin objects; 1 is perfect, 0 vanished"},
    {.id = kMassMean, .key = "mass_mean", .header = "mass_mean", .unit = "1", .shown_in = kInHtml,
     .definition = "mean captured mass over the thin objects"},
    {.id = kAliasTotalDb, .key = "alias_total_db", .header = "alias_dB", .unit = "dB", .better = L,
     .shown_in = kInHtml | kInScore, .compute = measure_alias, .symptom = true,
     .definition = "moire: energy of the Hann-windowed (rendered - own reference) spectrum relative to the windowed reference's energy, in dB"},
    {.id = kAliasLowDb, .key = "alias_low_db", .header = "lowf_dB", .unit = "dB", .better = L,
     .shown_in = kInText | kInHtml | kInScore, .text_width = 7, .text_decimals = 1,
     .definition = "the same, only frequencies below 0.25 cycles/px (half of Nyquist), where aliases show as moire"},
    {.id = kCrawl, .key = "crawl", .header = "crawl", .unit = "value", .better = L, .gate = kGated,
     .shown_in = kInText | kInHtml, .text_width = 7, .text_decimals = 4, .compute = measure_motion,
     .needs = kNeedsMotion | kNeedsMethod, .symptom = true,
     .definition = "crawling edges: mean over pixels of the standard deviation over T sub-pixel diagonal offsets of (rendered - own reference)"},
    {.id = kPopping, .key = "popping", .header = "popping", .unit = "1", .better = L,
     .shown_in = kInText | kInHtml, .text_width = 8, .text_decimals = 2,
     .definition = "popping: the worst max/min ratio of a thin object's captured mass over the T offsets; inf when it vanishes in some frame"},
    {.id = kSsim, .key = "ssim", .header = "ssim", .unit = "1", .better = H,
     .shown_in = kInText | kInHtml | kInScore, .text_width = 6, .text_decimals = 4,
     .compute = measure_ssim, .symptom = true,
     .definition = "SSIM against the box reference (cv::quality, images scaled to 8-bit range so its constants apply)"},
    {.id = kSeamsMax, .key = "seams_max", .header = "seams_max", .unit = "value", .better = L,
     .gate = kGated, .applies = k3d, .shown_in = kInHtml | kInScore, .compute = measure_seams,
     .needs = kNeedsSeamMask, .symptom = true,
     .definition = "seams (3-D): max |rendered - box_reference| over the pixels crossed by an edge two visible faces of one object share, where the exact answer has no background; face-by-face compositing leaks it there"},
    {.id = kSeamsMean, .key = "seams_mean", .header = "seams_mean", .unit = "value", .better = L,
     .gate = kGated, .applies = k3d, .shown_in = kInHtml | kInScore,
     .definition = "seams (3-D): mean |rendered - box_reference| over the same pixels"},
    {.id = kLinePrecision, .key = "line_precision", .header = "precision", .unit = "1", .better = H,
     .applies = kLn, .shown_in = kInHtml | kInLineTable, .text_width = 9, .text_decimals = 4,
     .may_be_absent = true, .compute = measure_method_lines, .needs = kNeedsLines | kNeedsMethod,
     .definition = "scenes with edges: of the pixels the edge stage on the method's own depth image detects (p > 0.5 or crease_weight |e| > 0.025), the fraction whose centre is within 1 px of a ground-truth line (contour or crease, from the exact visible pieces); empty for other scenes and for methods that draw no depth image"},
    {.id = kLineRecall, .key = "line_recall", .header = "recall", .unit = "1", .better = H,
     .applies = kLn, .shown_in = kInHtml | kInLineTable, .text_width = 9, .text_decimals = 4,
     .may_be_absent = true,
     .definition = "scenes with edges: of the pixels whose centre is within 0.5 px of a ground-truth line, the fraction with a detected pixel within 1 px (itself or a 4-neighbour)"},
    {.id = kLineRmse, .key = "line_rmse", .header = "line_rmse", .unit = "value", .better = L,
     .applies = kLn, .shown_in = kInHtml | kInLineTable, .text_width = 9, .text_decimals = 4,
     .may_be_absent = true,
     .definition = "scenes with edges: rmse of the edge stage's line image against the exact box coverage of the ground-truth lines drawn as one-pixel-wide strips, composed in the scene's style"},
    {.id = kExactDepthLinePrecision, .key = "exact_depth_line_precision",
     .header = "exact_depth_line_precision", .unit = "1", .better = H, .applies = kLn,
     .shown_in = kInHtml, .text_width = 9, .text_decimals = 4, .may_be_absent = true,
     .compute = measure_exact_depth_lines, .needs = kNeedsLines,
     .definition = "scenes with edges: line_precision of the edge stage on the exact depth image (the same for every row of a pattern: what the operator loses by itself)"},
    {.id = kExactDepthLineRecall, .key = "exact_depth_line_recall",
     .header = "exact_depth_line_recall", .unit = "1", .better = H, .applies = kLn,
     .shown_in = kInHtml, .text_width = 9, .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_recall of the edge stage on the exact depth image"},
    {.id = kExactDepthLineRmse, .key = "exact_depth_line_rmse", .header = "exact_depth_line_rmse",
     .unit = "value", .better = L, .applies = kLn, .shown_in = kInHtml, .text_width = 9,
     .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_rmse of the edge stage on the exact depth image"},
    {.id = kLineContourPrecision, .key = "line_contour_precision", .header = "cont_prec",
     .unit = "1", .better = H, .applies = kLn, .shown_in = kInHtml | kInLineTable, .text_width = 9,
     .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_precision of the contour detections alone (p > 0.5) against the ground-truth contours alone"},
    {.id = kLineContourRecall, .key = "line_contour_recall", .header = "cont_rec", .unit = "1",
     .better = H, .applies = kLn, .shown_in = kInHtml | kInLineTable, .text_width = 9,
     .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_recall of the ground-truth contours alone, found by contour detections alone"},
    {.id = kLineCreasePrecision, .key = "line_crease_precision", .header = "crea_prec", .unit = "1",
     .better = H, .applies = kLn, .shown_in = kInHtml | kInLineTable, .text_width = 9,
     .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_precision of the crease detections alone (crease_weight |e| > 0.025) against the ground-truth creases (convex and concave) alone"},
    {.id = kLineCreaseRecall, .key = "line_crease_recall", .header = "crea_rec", .unit = "1",
     .better = H, .applies = kLn, .shown_in = kInHtml | kInLineTable, .text_width = 9,
     .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_recall of the ground-truth creases alone, found by crease detections alone"},
    {.id = kExactDepthLineContourPrecision, .key = "exact_depth_line_contour_precision",
     .header = "exact_depth_line_contour_precision", .unit = "1", .better = H, .applies = kLn,
     .shown_in = kInHtml, .text_width = 9, .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_contour_precision of the edge stage on the exact depth image"},
    {.id = kExactDepthLineContourRecall, .key = "exact_depth_line_contour_recall",
     .header = "exact_depth_line_contour_recall", .unit = "1", .better = H, .applies = kLn,
     .shown_in = kInHtml, .text_width = 9, .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_contour_recall of the edge stage on the exact depth image"},
    {.id = kExactDepthLineCreasePrecision, .key = "exact_depth_line_crease_precision",
     .header = "exact_depth_line_crease_precision", .unit = "1", .better = H, .applies = kLn,
     .shown_in = kInHtml, .text_width = 9, .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_crease_precision of the edge stage on the exact depth image"},
    {.id = kExactDepthLineCreaseRecall, .key = "exact_depth_line_crease_recall",
     .header = "exact_depth_line_crease_recall", .unit = "1", .better = H, .applies = kLn,
     .shown_in = kInHtml, .text_width = 9, .text_decimals = 4, .may_be_absent = true,
     .definition = "scenes with edges: line_crease_recall of the edge stage on the exact depth image"},
    {.id = kTimeMedianNs, .key = "time_median_ns", .header = "time_ms", .unit = "ns", .better = L,
     .gate = Gate::kOnRequest, .shown_in = kInText | kHtmlCore, .shown = Shown::kMsFromNs,
     .text_width = 9, .text_decimals = 3,
     .definition = "median wall time of one render after a warm-up, single-threaded unless time_threads > 1 (the whole time: time_method_ms + time_stages_ms)"},
    {.id = kTimeMinNs, .key = "time_min_ns", .header = "time_min", .unit = "ns", .better = L,
     .shown = Shown::kMsFromNs},
    {.id = kTimeMaxNs, .key = "time_max_ns", .header = "time_max", .unit = "ns", .better = L,
     .shown = Shown::kMsFromNs},
    {.id = kTimeMethodMs, .key = "time_method_ms", .header = "method_ms", .unit = "ms", .better = L,
     .may_be_absent = true,
     .definition = "the method's own part of time_median_ns, in ms"},
    {.id = kTimeStagesMs, .key = "time_stages_ms", .header = "stages_ms", .unit = "ms", .better = L,
     .shown_in = kInHtmlWhenNonzero, .text_width = 9, .text_decimals = 3, .may_be_absent = true,
     .definition = "the part of time_median_ns spent in the world stages the method relies on, in ms: on a 3-D scene every stage that made its input, the visibility stage only for a method that draws the exact visible pieces (one without its own hidden-surface removal); 0 on a 2-D scene"},
    {.id = kExternalStartupNs, .key = "external_startup_ns", .header = "startup_ns", .unit = "ns",
     .better = L, .shown_in = kInHtml, .may_be_absent = true,
     .definition = "--external: median wall time of the same command on an empty scene of this size (reported, not subtracted)"},
    {.id = kExternalReportedMs, .key = "external_reported_ms", .header = "reported_ms",
     .unit = "ms", .better = L, .shown_in = kInHtml, .may_be_absent = true,
     .definition = "--external: median of the times the command printed as 'aabench-time-ms: X'; empty if it printed none"},
    {.id = kMpixelPerS, .key = "mpixel_per_s", .header = "Mpix/s", .unit = "Mpixel/s", .better = H,
     .shown_in = kInText | kHtmlCore, .text_width = 8, .text_decimals = 1,
     .definition = "width*height / time_median / 1e6"},
    {.id = kMedgesPerS, .key = "medges_per_s", .header = "Medge/s", .unit = "Medge/s", .better = H,
     .definition = "edges / time_median / 1e6"},
    {.id = kWorldMs, .key = "world_ms", .header = "world_ms", .unit = "ms", .better = L,
     .applies = k3d, .shown_in = kInHtml | kInScore,
     .definition = "3-D patterns: time of the world stages the plan kept (projection, culling, patterns, shadows, shading, visibility, ...), one run; empty for 2-D"},
};
// clang-format on

// The temporal measures (harness/measure/sequence_metrics.h), in SequenceMetric order: not
// gated (no baseline holds sequences), absent from the files of still runs.
struct SequenceRow {
    SequenceMetric which;
    const char* key;
    const char* header;
    const char* unit;
    Better better;
    Shown shown;
    int text_width;
    int text_decimals;
    bool integer;
    const char* definition;
};

// clang-format off
constexpr SequenceRow kSequenceRows[] = {
    {SequenceMetric::kSteadyRmse, "seq_steady_rmse", "steady", "value", L, G, 8, 5, false,
     "sequences: steady-state error, the mean over the second half of the frames of each frame's rmse against its exact box reference"},
    {SequenceMetric::kConvergence, "seq_convergence", "converge", "frames", L, I, 8, 0, true,
     "still sequences: the first frame after which every frame's rmse stays within 10% of the steady-state error; empty on a moving sequence"},
    {SequenceMetric::kFlicker, "seq_flicker", "flicker", "value", L, G, 8, 5, false,
     "sequences: mean over pixels of the standard deviation over the second half of the frames of (rendered - own reference): crawl, generalised"},
    {SequenceMetric::kGhostRmse, "seq_ghost_rmse", "ghost", "value", L, G, 8, 5, false,
     "sequences: rmse against the box reference over the pixels (of frames 1..T-1) whose surface was disoccluded within the last 8 frames; empty when none was"},
    {SequenceMetric::kRestRmse, "seq_rest_rmse", "rest", "value", L, G, 8, 5, false,
     "sequences: the same rmse over the other pixels of frames 1..T-1"},
    {SequenceMetric::kGhostRatio, "seq_ghost_ratio", "ghost/rest", "1", L, G, 10, 2, false,
     "sequences: seq_ghost_rmse / seq_rest_rmse: how much worse newly uncovered surfaces are"},
    {SequenceMetric::kEdgeBlur, "seq_edge_blur", "blur", "value", N, Shown::kSigned, 9, 5, false,
     "sequences: over the edge band of the second half of the frames, the mean of (rendered - own reference) against the sign of (own reference - its 3x3 mean): > 0 is mass smeared toward the neighbours (blur), < 0 sharpening"},
    {SequenceMetric::kFrameMs, "seq_frame_ms", "frame_ms", "ms", L, G, 9, 3, false,
     "sequences: median wall time of one frame's render_frame, single-threaded (the world stages not included)"},
};
// clang-format on
static_assert(std::size(kSequenceRows) == static_cast<std::size_t>(SequenceMetric::kCount));

constexpr bool in_enum_order() {
    if (std::size(kBuiltins) != kBuiltinCount) return false;
    for (std::size_t k = 0; k < std::size(kBuiltins); ++k) {
        if (kBuiltins[k].id != static_cast<MetricId>(k)) return false;
    }
    return true;
}
static_assert(in_enum_order(), "kBuiltins must list every metric::Builtin once, in enum order");

MetricDef from_builtin(const BuiltinRow& b) {
    MetricDef d;
    d.key = b.key;
    d.header = b.header;
    d.definition = b.definition;
    d.unit = b.unit;
    d.better = b.better;
    d.gate = b.gate;
    if (b.gate == Gate::kYes) d.tolerance = kImageErrorTolerance;
    d.applies = b.applies;
    d.shown_in = b.shown_in;
    d.shown = b.shown;
    d.text_width = b.text_width;
    d.text_decimals = b.text_decimals;
    d.integer = b.integer;
    d.may_be_absent = b.may_be_absent;
    d.compute = b.compute;
    d.needs = b.needs;
    d.symptom = b.symptom;
    return d;
}

}  // namespace

MetricId stage_ms_metric(int stage) { return kBuiltinCount + 2 * stage; }
MetricId stage_bytes_metric(int stage) { return kBuiltinCount + 2 * stage + 1; }
MetricId edge_angle_metric(int bin) { return kBuiltinCount + 2 * kStageCount + bin; }
MetricId sequence_metric(SequenceMetric which) {
    return kBuiltinCount + 2 * kStageCount + kEdgeAngleBins + static_cast<int>(which);
}

MetricRegistry::MetricRegistry() {
    for (const BuiltinRow& b : kBuiltins) defs_.push_back(from_builtin(b));
    for (int k = 0; k < kStageCount; ++k) {
        const std::string name = stage_name(static_cast<Stage>(k));
        MetricDef ms;
        ms.key = fmt::format("stage_{}_ms", name);
        ms.header = name + " ms";
        ms.definition = "time of this world stage (ms, one run); empty: left out by the plan";
        ms.unit = "ms";
        ms.better = Better::kLower;
        ms.applies = kApplies3d;
        MetricDef bytes = ms;
        bytes.key = fmt::format("stage_{}_bytes", name);
        bytes.header = name + " bytes";
        bytes.definition = "heap bytes allocated by this world stage; empty: left out by the plan";
        bytes.unit = "bytes";
        defs_.push_back(std::move(ms));
        defs_.push_back(std::move(bytes));
    }
    for (int bin = 0; bin < kEdgeAngleBins; ++bin) {
        const int lo = static_cast<int>(bin * kEdgeAngleBinDeg);
        const int hi = static_cast<int>((bin + 1) * kEdgeAngleBinDeg);
        MetricDef d;
        d.key = fmt::format("edge_rmse_{:02}_{:02}deg", lo, hi);
        d.header = fmt::format("edge {}-{}°", lo, hi);
        d.definition = fmt::format(
            "jagged edges by edge angle: edge_rmse over the pixels whose centre lies within 1.5 px "
            "of an edge at {}° to {}° from the horizontal and of no edge at another angle; empty "
            "where no pixel is",
            lo, hi);
        d.unit = "value";
        d.better = Better::kLower;
        d.applies = kAppliesImages;
        d.may_be_absent = true;
        if (bin == 0) {  // one pass over the pixels gives every bin
            d.compute = measure_edge_angles;
            d.needs = kNeedsAngleBins;
            d.symptom = true;
        }
        defs_.push_back(std::move(d));
    }
    for (const SequenceRow& r : kSequenceRows) {
        MetricDef d;
        d.key = r.key;
        d.header = r.header;
        d.definition = r.definition;
        d.unit = r.unit;
        d.better = r.better;
        d.applies = kAppliesSequences;
        d.shown = r.shown;
        d.text_width = r.text_width;
        d.text_decimals = r.text_decimals;
        d.integer = r.integer;
        d.may_be_absent = true;
        defs_.push_back(std::move(d));
    }
    // Conflation (harness/measure/conflation.h): after the families, so that no id moves.
    MetricDef conflation;
    conflation.key = "conflation";
    conflation.header = "conflation";
    conflation.definition =
        "methods with a paths choice (cairo, agg): rmse between the image with each run of "
        "consecutive shapes of one value as one fill and the image with one fill per shape: "
        "what compositing coverage where shapes meet (conflation) changes";
    conflation.unit = "value";
    conflation.applies = kAppliesImages;
    conflation.shown_in = kInHtml;
    conflation.may_be_absent = true;
    conflation.compute = measure_conflation;
    conflation.needs = kNeedsMethod;  // the method's twin renders the scene again
    defs_.push_back(std::move(conflation));
    // Flattening's share of the error (Method::own_flattening): after conflation, no id moves.
    MetricDef flatten_bias;
    flatten_bias.key = "flatten_bias";
    flatten_bias.header = "flatten_bias";
    flatten_bias.definition =
        "scenes with Bezier curves, methods that flatten them (fast-edge, gl-msaa, cairo, agg "
        "and passes over them): box_rmse minus the rmse against the exact box reference of the "
        "method's own flattened polygon: how much of the error is the flattening (the rest is "
        "the coverage of that polygon); empty for other rows";
    flatten_bias.unit = "value";
    flatten_bias.applies = kAppliesImages;
    flatten_bias.shown_in = kInHtml;
    flatten_bias.may_be_absent = true;
    flatten_bias.compute = measure_flatten_bias;
    flatten_bias.needs = kNeedsMethod;  // the method's own polygon and its exact reference
    defs_.push_back(std::move(flatten_bias));
    // The pass alone of a post-process row (methods/post_process.h), found by its key
    // (kTimePassKey) by compare, which times it, and the text table, which prints it.
    MetricDef pass;
    pass.key = kTimePassKey;
    pass.header = "pass_ms";
    pass.definition = "post-process methods (fxaa, mlaa, ...): median wall time of the pass alone, single-threaded, in ms, on the base method's image rendered once (time_median_ns is base + pass); empty for other methods";
    pass.unit = "ms";
    pass.better = Better::kLower;
    pass.applies = kAppliesImages;
    pass.shown_in = kInHtml;
    pass.may_be_absent = true;
    defs_.push_back(std::move(pass));
}

MetricRegistry& MetricRegistry::global() {
    static MetricRegistry registry;
    return registry;
}

std::optional<MetricId> MetricRegistry::find(std::string_view key) const {
    for (std::size_t k = 0; k < defs_.size(); ++k) {
        if (defs_[k].key == key) return static_cast<MetricId>(k);
    }
    return std::nullopt;
}

ScopedMetric::ScopedMetric(MetricDef def) {
    MetricRegistry& registry = MetricRegistry::global();
    if (registry.find(def.key)) {
        throw std::logic_error("ScopedMetric: the registry already has " + def.key);
    }
    id_ = registry.size();
    registry.defs_.push_back(std::move(def));
}

ScopedMetric::~ScopedMetric() {
    MetricRegistry& registry = MetricRegistry::global();
    // Ids are indices: only the newest metric can go without moving the others.
    if (registry.size() != id_ + 1) {
        std::fputs("ScopedMetric: scopes must end newest first\n", stderr);
        std::abort();
    }
    registry.defs_.pop_back();
}

double& MetricValues::operator[](MetricId id) {
    const auto k = static_cast<std::size_t>(id);
    if (k >= values_.size()) values_.resize(k + 1, kNotMeasured);
    return values_[k];
}

}  // namespace aabench
