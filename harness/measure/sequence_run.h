// The sequence run (`aabench compare --sequences`): every method on every sequence, frames
// rendered in order, each frame scored against its own exact reference, and the temporal
// measures of docs/metrics.md ("Sequences") put into one result row per method and sequence.
// Pure computation: the report stage writes the files.
//
// A temporal method gets begin() once per sequence and render_frame() per frame with the
// frame's input (PreparedFrame::input_for) and its motion vectors, never the reference; a
// spatial method's render_frame is its render(). Each frame is rendered once, timed as it is
// rendered (a temporal method's frame cannot be repeated without changing its state), on one
// thread. --jobs spreads the preparation of the frames (world stages, references, motion) only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "harness/measure/compare.h"
#include "harness/measure/result_row.h"
#include "harness/world/sequence.h"
#include "methods/scan/kernel/image.h"

namespace aabench {

// Ghosting looks at pixels disoccluded within the last 8 frames: taa's default history weight
// alpha = 0.1 leaves (1 - 0.1)^8 = 43 % of a stale value after 8 frames, the span where ghosts
// show; older disocclusions count as "the rest".
inline constexpr int kGhostFrames = 8;
// Convergence: the first frame after which the error stays within 10 % of its steady state.
inline constexpr double kConvergenceBand = 0.10;

struct SequenceRunOptions {
    // Built-in names; empty: every built-in, unless scene files are given (then none).
    std::vector<std::string> sequences;
    // Scene files carrying a sequence (version 3), read by the caller, run after the built-ins
    // in this order; rows named by the file stem. Each keeps its own size and, when it gives
    // them, its own frames.
    std::vector<SceneFileInput> scene_files;
    std::vector<std::string> method_specs;  // empty: every registered method at its defaults
    int width = kDefaultSequenceSide;       // of the built-ins
    int height = kDefaultSequenceSide;
    int frames = kDefaultSequenceFrames;  // of the built-ins and of files that give none
    int jobs = 1;
    // Frames kept for the report's filmstrip: this many, evenly spread, the last included.
    int filmstrip_frames = 6;
};

// One method on one sequence.
struct SequenceMethodRun {
    std::string method;              // canonical spec
    std::vector<double> frame_rmse;  // per frame, against the box reference
    std::vector<double> frame_ms;    // per frame, render_frame's wall time
    std::vector<Image> kept;         // at SequenceFigures::kept_frames
    Image last_error;                // last frame: rendered - box reference
};

// One sequence's figures and per-frame data for the report and frames.csv.
struct SequenceFigures {
    std::string sequence;
    std::string summary;
    bool still = false;
    int frames = 0;
    std::vector<int> kept_frames;           // indices of the filmstrip's frames
    std::vector<Coverage> kept_reference;   // the box reference at those frames
    std::vector<SequenceMethodRun> runs;    // in method order (applicable methods only)
    std::vector<double> disoccluded_share;  // per frame: the share of disoccluded pixels
};

struct SequenceRunResult {
    std::vector<ResultRow> rows;  // sequence-major, method order
    std::vector<SequenceFigures> figures;
};

// Called after each (sequence, method): (done, total, "sequence method").
using SequenceProgressFn = std::function<void(std::size_t, std::size_t, const std::string&)>;

// Checks every name and spec first (InputError before any work), then runs.
SequenceRunResult run_sequences(const SequenceRunOptions& options,
                                const SequenceProgressFn& progress = {});

// The measures of one method's frames against one sequence's references, as the runner takes
// them (exposed for tests). `errors[t]` = rendered - box reference, `own_errors[t]` = rendered
// - own-filter reference, `recent[t]` the ghosting mask (disoccluded within kGhostFrames),
// `edges[t]` the sign of the edge-blur direction per pixel (0 off the edge band).
struct TemporalInputs {
    std::vector<std::vector<double>> errors;
    std::vector<std::vector<double>> own_errors;
    std::vector<Raster<std::uint8_t>> recent;
    std::vector<Raster<std::int8_t>> edge_sign;
    bool still = false;
};
struct TemporalMeasures {
    std::vector<double> frame_rmse;
    double steady_rmse = 0.0;
    double convergence = 0.0;  // frames; NaN unless still
    double flicker = 0.0;
    double ghost_rmse = 0.0;  // NaN when no pixel was recently disoccluded
    double rest_rmse = 0.0;
    double ghost_ratio = 0.0;
    double edge_blur = 0.0;
};
TemporalMeasures temporal_measures(const TemporalInputs& inputs);

// The first frame c with |e_t - steady| <= kConvergenceBand * steady for every t >= c.
int convergence_frame(const std::vector<double>& frame_rmse, double steady);

// The recently-disoccluded masks of a sequence from its per-frame disocclusion masks: a pixel
// is recent at frame t when the surface it shows was disoccluded within the last kGhostFrames
// frames, followed back along the motion vectors to the nearest pixel centre. Frame 0 is not
// recent anywhere (it has no previous frame; convergence measures it).
std::vector<Raster<std::uint8_t>> recent_disocclusions(const std::vector<FrameMotion>& motion);

// Per pixel of an exact reference: +1 where the pixel is above the mean of its 3x3
// neighbourhood and on the edge band, -1 where below, 0 elsewhere: the direction a blur moves
// it (toward its neighbours).
Raster<std::int8_t> edge_blur_sign(const Coverage& reference, const Raster<std::uint8_t>& band);

}  // namespace aabench
