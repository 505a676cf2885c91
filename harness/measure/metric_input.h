// What a metric's compute function reads (MetricDef::compute, harness/measure/metric_registry.h)
// and the loop that runs every row's: compare's score_task and `aabench score` call the same
// loop, so that they compute the same figures the same way (docs/metrics.md, "Adding a metric").
// A scene's preparations (edge band, angle bins, seam mask, thin objects, motion frames, line
// truth) are built once per scene and only when a metric in scope asks for them (MetricDef::needs).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "harness/measure/flip.h"
#include "harness/measure/line_scores.h"
#include "harness/measure/metric_registry.h"
#include "harness/measure/result_row.h"
#include "harness/measure/symptoms.h"
#include "harness/world/frame.h"
#include "methods/method.h"

namespace aabench {

// Which metrics a scorer computes.
struct MetricScope {
    bool symptoms = true;     // the rows marked symptom (compare: default rows, --symptoms)
    bool with_method = true;  // the rows that need the method (kNeedsMethod)
    bool score_only = false;  // only the rows `aabench score` shows (kInScore)
};

// True when `def` is computed in `scope`: it has a compute function and the scope admits it.
bool in_scope(const MetricDef& def, const MetricScope& scope);

// The Needs bits of every metric in `scope`: what the scorer prepares per scene.
unsigned metric_needs(const MetricScope& scope);

// One scene's preparations; each is empty unless asked for (and, for the seam mask and the
// line truth, unless the scene has what it measures: 3-D faces, `edges`).
struct ScenePreparations {
    Raster<std::uint8_t> edge_band;  // kNeedsEdgeBand
    Raster<std::int8_t> angle_bins;  // kNeedsAngleBins
    Raster<std::uint8_t> seam_mask;  // kNeedsSeamMask; empty for a 2-D scene
    MassReference masses;            // kNeedsMasses
    std::optional<LineTruth> lines;  // kNeedsLines; only for a plan with the edge stage
    // kNeedsMotion: by canonical filter spec. Made by the caller (compare, in parallel and
    // counted in its progress), since which filters are needed depends on its tasks.
    std::map<std::string, MotionReference> motion;
    // The box reference's half of the ꟻLIP map (flip::prepare_flip_reference), made by the
    // caller once it has the reference; without it each row's ꟻLIP makes its own.
    std::optional<flip::FlipReference> flip;
};

// Every preparation `needs` asks for, except the motion references.
ScenePreparations prepare_scene(const PreparedFrame& frame, unsigned needs);

// One scored image and what it is measured against.
struct MetricInput {
    const Image& image;                 // the rendered image
    const PreparedFrame& frame;         // frame.pieces(): the scene the references measure
    const Coverage& box;                // the exact box reference
    const Coverage& own;                // the exact reference of the method's own filter
    const ScenePreparations& prepared;  // what the metrics in scope asked for
    // The method that drew the image and the scene it drew; nullptr in `aabench score`.
    const MethodInstance* method = nullptr;
    const SceneInput* drawn = nullptr;
    const MotionReference* motion = nullptr;  // for the own filter, when prepared
    // A colour scene: the rendered planes and the box reference's, beside `image` and `box`
    // (their luminances: every metric but the box errors measures the luminance); nullptr
    // for a grey scene.
    const ImagePlanes* planes = nullptr;
    const CoveragePlanes* box_planes = nullptr;
};

// The luminance of linear Rec. 709 planes (kLuminanceWeights, patterns/scene/scene.h), summed in
// double and rounded once, into `out` (resized to their size).
void luminance_image(const ImagePlanes& planes, Image& out);
// The same of a reference's planes, in double (the luminance's reference: every reference is
// linear in the values).
Coverage luminance_coverage(const CoveragePlanes& planes);

// Runs the compute function of every metric in `scope`, in registry order.
void compute_metrics(const MetricInput& in, const MetricScope& scope, ResultRow& row);

// The built-in metrics' compute functions (metric_registry.cpp's table names them; each says
// which rows it fills, metric_input.cpp).
void measure_box(const MetricInput& in, MetricId self, ResultRow& row);
void measure_own(const MetricInput& in, MetricId self, ResultRow& row);
void measure_flip(const MetricInput& in, MetricId self, ResultRow& row);
void measure_srgb(const MetricInput& in, MetricId self, ResultRow& row);
void measure_edge_band(const MetricInput& in, MetricId self, ResultRow& row);
void measure_masses(const MetricInput& in, MetricId self, ResultRow& row);
void measure_alias(const MetricInput& in, MetricId self, ResultRow& row);
void measure_motion(const MetricInput& in, MetricId self, ResultRow& row);
void measure_ssim(const MetricInput& in, MetricId self, ResultRow& row);
void measure_seams(const MetricInput& in, MetricId self, ResultRow& row);
void measure_method_lines(const MetricInput& in, MetricId self, ResultRow& row);
void measure_exact_depth_lines(const MetricInput& in, MetricId self, ResultRow& row);
void measure_edge_angles(const MetricInput& in, MetricId self, ResultRow& row);
void measure_conflation(const MetricInput& in, MetricId self, ResultRow& row);
void measure_flatten_bias(const MetricInput& in, MetricId self, ResultRow& row);

}  // namespace aabench
