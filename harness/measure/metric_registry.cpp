// The metric registry's table (harness/measure/metric_registry.h). Definitions are the ones
// results.json writes; docs/metrics.md lists the same keys (tests/metric_registry_test.cpp).
#include "harness/measure/metric_registry.h"

#include "harness/measure/sequence_metrics.h"
#include "harness/measure/pass_time.h"  // kTimePassKey

#include <fmt/format.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace aabench {
namespace {

using namespace metric;

// One built-in metric. Plain pointers so that the table is constexpr and its order can be
// checked against the enum at compile time.
struct BuiltinRow {
    MetricId id;
    const char* key;
    const char* header;
    const char* unit;
    Better better;
    Gate gate;
    unsigned applies;
    unsigned shown_in;
    Shown shown;
    int text_width;
    int text_decimals;
    bool integer;
    bool may_be_absent;
    const char* definition;
};

constexpr Better L = Better::kLower, H = Better::kHigher, N = Better::kNeither;
constexpr Gate kGated = Gate::kYes, kNo = Gate::kNo;
constexpr unsigned kImg = kAppliesImages, k3d = kApplies3d, kLn = kAppliesLines;
constexpr unsigned kHtmlCore = kInHtml | kInHtmlAlways;
constexpr Shown G = Shown::kGeneral, I = Shown::kInteger;

// clang-format off
constexpr BuiltinRow kBuiltins[] = {
    {kBoxRmse, "box_rmse", "rmse", "value", L, kGated, kImg, kInText | kHtmlCore | kInScore, G, 8, 5, false, false,
     "sqrt(mean((rendered - box_reference)^2)) over all pixels"},
    {kBoxMaxAbs, "box_max_abs", "max_abs", "value", L, kGated, kImg, kInText | kHtmlCore | kInScore, G, 8, 5, false, false,
     "max |rendered - box_reference|, at (box_max_x, box_max_y)"},
    {kBoxMaxX, "box_max_x", "max_x", "px", N, kNo, kImg, kInScore, I, 0, 0, true, false, ""},
    {kBoxMaxY, "box_max_y", "max_y", "px", N, kNo, kImg, kInScore, I, 0, 0, true, false, ""},
    {kBoxBias, "box_bias", "bias", "value", N, kNo, kImg, kInText | kHtmlCore | kInScore, Shown::kSigned, 9, 5, false, false,
     "mean(rendered - box_reference); > 0 means too bright"},
    {kDropout, "dropout", "dropout", "1", L, kGated, kImg, kInText | kHtmlCore | kInScore, Shown::kPercent, 8, 2, false, false,
     "fraction of the pixels with box_reference > 0.1 that are rendered < 0.01"},
    {kDropoutPixels, "dropout_pixels", "dropout_px", "pixels", L, kNo, kImg, kInScore, I, 0, 0, true, false, ""},
    {kDropoutCandidates, "dropout_candidates", "candidates", "pixels", N, kNo, kImg, kInScore, I, 0, 0, true, false, ""},
    {kNonfinite, "nonfinite", "nonfinite", "pixels", L, kGated, kImg, kInHtmlWhenNonzero | kInScore, I, 0, 0, true, false,
     "rendered pixels that are NaN or infinite"},
    {kOwnRmse, "own_rmse", "own_rmse", "value", L, kGated, kImg, kInText | kHtmlCore | kInScore, G, 8, 5, false, false,
     "rmse against the exact reference of reference_filter: the discretisation error alone, the choice of filter taken out"},
    {kOwnMaxAbs, "own_max_abs", "own_max_abs", "value", L, kGated, kImg, kInScore, G, 0, 0, false, false,
     "max |rendered - own reference|"},
    {kOwnBias, "own_bias", "own_bias", "value", N, kNo, kImg, kInScore, Shown::kSigned, 0, 0, false, false,
     "mean(rendered - own reference)"},
    {kFlip, "flip", "flip", "1", L, kGated, kImg, kInHtml | kInScore, G, 0, 0, false, true,
     "mean LDR-FLIP (Andersson et al. 2020) against the box reference, per pixel in [0, 1] (0 identical): the difference a viewer sees at 67 px per degree; grey as R = G = B, linear values clamped to [0, 1]"},
    {kSrgbRmse, "srgb_rmse", "srgb_rmse", "value", L, kGated, kImg, kInHtml | kInScore, G, 0, 0, false, true,
     "rmse of the sRGB-encoded values (IEC 61966-2-1, clamped to [0, 1], not quantised) against the encoded box reference: the error in what a display shows"},
    {kEdgeRmse, "edge_rmse", "edge", "value", L, kGated, kImg, kInText | kInHtml | kInScore, G, 8, 5, false, false,
     "jagged edges: rmse against the own-filter reference over the pixels whose centre lies within 1.5 px of an edge"},
    {kMassWorst, "mass_worst", "mass", "1", N, kNo, kImg, kInText | kInHtml, G, 6, 3, false, false,
     "vanishing thin objects: the smallest captured mass (rendered sum / exact sum, each thin object rendered alone) over the pattern's thin objects; 1 is perfect, 0 vanished"},
    {kMassMean, "mass_mean", "mass_mean", "1", N, kNo, kImg, kInHtml, G, 0, 0, false, false,
     "mean captured mass over the thin objects"},
    {kAliasTotalDb, "alias_total_db", "alias_dB", "dB", L, kNo, kImg, kInHtml | kInScore, G, 0, 0, false, false,
     "moire: energy of the Hann-windowed (rendered - own reference) spectrum relative to the windowed reference's energy, in dB"},
    {kAliasLowDb, "alias_low_db", "lowf_dB", "dB", L, kNo, kImg, kInText | kInHtml | kInScore, G, 7, 1, false, false,
     "the same, only frequencies below 0.25 cycles/px (half of Nyquist), where aliases show as moire"},
    {kCrawl, "crawl", "crawl", "value", L, kGated, kImg, kInText | kInHtml, G, 7, 4, false, false,
     "crawling edges: mean over pixels of the standard deviation over T sub-pixel diagonal offsets of (rendered - own reference)"},
    {kPopping, "popping", "popping", "1", L, kNo, kImg, kInText | kInHtml, G, 8, 2, false, false,
     "popping: the worst max/min ratio of a thin object's captured mass over the T offsets; inf when it vanishes in some frame"},
    {kSsim, "ssim", "ssim", "1", H, kNo, kImg, kInText | kInHtml | kInScore, G, 6, 4, false, false,
     "SSIM against the box reference (cv::quality, images scaled to 8-bit range so its constants apply)"},
    {kSeamsMax, "seams_max", "seams_max", "value", L, kGated, k3d, kInHtml | kInScore, G, 0, 0, false, false,
     "seams (3-D): max |rendered - box_reference| over the pixels crossed by an edge two visible faces of one object share, where the exact answer has no background; face-by-face compositing leaks it there"},
    {kSeamsMean, "seams_mean", "seams_mean", "value", L, kGated, k3d, kInHtml | kInScore, G, 0, 0, false, false,
     "seams (3-D): mean |rendered - box_reference| over the same pixels"},
    {kLinePrecision, "line_precision", "precision", "1", H, kNo, kLn, kInHtml | kInLineTable, G, 9, 4, false, true,
     "scenes with edges: of the pixels the edge stage on the method's own depth image detects (p > 0.5 or crease_weight |e| > 0.025), the fraction whose centre is within 1 px of a ground-truth line (contour or crease, from the exact visible pieces); empty for other scenes and for methods that draw no depth image"},
    {kLineRecall, "line_recall", "recall", "1", H, kNo, kLn, kInHtml | kInLineTable, G, 9, 4, false, true,
     "scenes with edges: of the pixels whose centre is within 0.5 px of a ground-truth line, the fraction with a detected pixel within 1 px (itself or a 4-neighbour)"},
    {kLineRmse, "line_rmse", "line_rmse", "value", L, kNo, kLn, kInHtml | kInLineTable, G, 9, 4, false, true,
     "scenes with edges: rmse of the edge stage's line image against the exact box coverage of the ground-truth lines drawn as one-pixel-wide strips, composed in the scene's style"},
    {kExactDepthLinePrecision, "exact_depth_line_precision", "exact_depth_line_precision", "1", H, kNo, kLn, kInHtml, G, 9, 4, false, true,
     "scenes with edges: line_precision of the edge stage on the exact depth image (the same for every row of a pattern: what the operator loses by itself)"},
    {kExactDepthLineRecall, "exact_depth_line_recall", "exact_depth_line_recall", "1", H, kNo, kLn, kInHtml, G, 9, 4, false, true,
     "scenes with edges: line_recall of the edge stage on the exact depth image"},
    {kExactDepthLineRmse, "exact_depth_line_rmse", "exact_depth_line_rmse", "value", L, kNo, kLn, kInHtml, G, 9, 4, false, true,
     "scenes with edges: line_rmse of the edge stage on the exact depth image"},
    {kLineContourPrecision, "line_contour_precision", "cont_prec", "1", H, kNo, kLn, kInHtml | kInLineTable, G, 9, 4, false, true,
     "scenes with edges: line_precision of the contour detections alone (p > 0.5) against the ground-truth contours alone"},
    {kLineContourRecall, "line_contour_recall", "cont_rec", "1", H, kNo, kLn, kInHtml | kInLineTable, G, 9, 4, false, true,
     "scenes with edges: line_recall of the ground-truth contours alone, found by contour detections alone"},
    {kLineCreasePrecision, "line_crease_precision", "crea_prec", "1", H, kNo, kLn, kInHtml | kInLineTable, G, 9, 4, false, true,
     "scenes with edges: line_precision of the crease detections alone (crease_weight |e| > 0.025) against the ground-truth creases (convex and concave) alone"},
    {kLineCreaseRecall, "line_crease_recall", "crea_rec", "1", H, kNo, kLn, kInHtml | kInLineTable, G, 9, 4, false, true,
     "scenes with edges: line_recall of the ground-truth creases alone, found by crease detections alone"},
    {kExactDepthLineContourPrecision, "exact_depth_line_contour_precision", "exact_depth_line_contour_precision", "1", H, kNo, kLn, kInHtml, G, 9, 4, false, true,
     "scenes with edges: line_contour_precision of the edge stage on the exact depth image"},
    {kExactDepthLineContourRecall, "exact_depth_line_contour_recall", "exact_depth_line_contour_recall", "1", H, kNo, kLn, kInHtml, G, 9, 4, false, true,
     "scenes with edges: line_contour_recall of the edge stage on the exact depth image"},
    {kExactDepthLineCreasePrecision, "exact_depth_line_crease_precision", "exact_depth_line_crease_precision", "1", H, kNo, kLn, kInHtml, G, 9, 4, false, true,
     "scenes with edges: line_crease_precision of the edge stage on the exact depth image"},
    {kExactDepthLineCreaseRecall, "exact_depth_line_crease_recall", "exact_depth_line_crease_recall", "1", H, kNo, kLn, kInHtml, G, 9, 4, false, true,
     "scenes with edges: line_crease_recall of the edge stage on the exact depth image"},
    {kTimeMedianNs, "time_median_ns", "time_ms", "ns", L, Gate::kOnRequest, kImg, kInText | kHtmlCore, Shown::kMsFromNs, 9, 3, false, false,
     "median wall time of one render after a warm-up, single-threaded unless time_threads > 1 (the whole time: time_method_ms + time_stages_ms)"},
    {kTimeMinNs, "time_min_ns", "time_min", "ns", L, kNo, kImg, 0, Shown::kMsFromNs, 0, 0, false, false, ""},
    {kTimeMaxNs, "time_max_ns", "time_max", "ns", L, kNo, kImg, 0, Shown::kMsFromNs, 0, 0, false, false, ""},
    {kTimeMethodMs, "time_method_ms", "method_ms", "ms", L, kNo, kImg, 0, G, 0, 0, false, true,
     "the method's own part of time_median_ns, in ms"},
    {kTimeStagesMs, "time_stages_ms", "stages_ms", "ms", L, kNo, kImg, kInHtmlWhenNonzero, G, 9, 3, false, true,
     "the part of time_median_ns spent in the world stages the method relies on, in ms: on a 3-D scene every stage that made its input, the visibility stage only for a method that draws the exact visible pieces (one without its own hidden-surface removal); 0 on a 2-D scene"},
    {kExternalStartupNs, "external_startup_ns", "startup_ns", "ns", L, kNo, kImg, kInHtml, G, 0, 0, false, true,
     "--external: median wall time of the same command on an empty scene of this size (reported, not subtracted)"},
    {kExternalReportedMs, "external_reported_ms", "reported_ms", "ms", L, kNo, kImg, kInHtml, G, 0, 0, false, true,
     "--external: median of the times the command printed as 'aabench-time-ms: X'; empty if it printed none"},
    {kMpixelPerS, "mpixel_per_s", "Mpix/s", "Mpixel/s", H, kNo, kImg, kInText | kHtmlCore, G, 8, 1, false, false,
     "width*height / time_median / 1e6"},
    {kMedgesPerS, "medges_per_s", "Medge/s", "Medge/s", H, kNo, kImg, 0, G, 0, 0, false, false,
     "edges / time_median / 1e6"},
    {kWorldMs, "world_ms", "world_ms", "ms", L, kNo, k3d, kInHtml | kInScore, G, 0, 0, false, false,
     "3-D patterns: time of the world stages the plan kept (projection, culling, patterns, shadows, shading, visibility, ...), one run; empty for 2-D"},
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
    // Found by its key (harness/measure/conflation.h): after the families, so no id moves.
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
    defs_.push_back(std::move(conflation));
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
