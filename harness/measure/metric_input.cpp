// The metric loop, the scene preparations and the built-in metrics' compute functions
// (harness/measure/metric_input.h). The definitions each function measures are
// docs/metrics.md's; the functions only call the metric code (metrics.h, symptoms.h, flip.h,
// edge_angles.h, line_scores.h, conflation.h) and write the rows they fill.
#include "harness/measure/metric_input.h"

#include <cmath>

#include "harness/measure/conflation.h"
#include "harness/measure/edge_angles.h"
#include "harness/measure/flip.h"
#include "harness/measure/metrics.h"
#include "harness/reference/box_reference.h"

namespace aabench {

bool in_scope(const MetricDef& def, const MetricScope& scope) {
    if (def.compute == nullptr) return false;
    if (def.symptom && !scope.symptoms) return false;
    if ((def.needs & kNeedsMethod) && !scope.with_method) return false;
    return !scope.score_only || (def.shown_in & kInScore);
}

unsigned metric_needs(const MetricScope& scope) {
    unsigned needs = 0;
    for (const MetricDef& def : metric_registry().all()) {
        if (in_scope(def, scope)) needs |= def.needs;
    }
    return needs;
}

ScenePreparations prepare_scene(const PreparedFrame& frame, unsigned needs) {
    ScenePreparations prepared;
    const SceneInput measured = frame.pieces();
    const Scene& scene = measured.scene();
    if ((needs & kNeedsLines) && frame.plan().in(Stage::kEdges)) {
        prepared.lines = prepare_line_truth(frame, *frame.given().world->edges);
    }
    if (needs & kNeedsEdgeBand) prepared.edge_band = edge_band_mask(scene);
    if (needs & kNeedsAngleBins) prepared.angle_bins = edge_angle_bins(scene);
    if ((needs & kNeedsSeamMask) && frame.is_world()) {
        prepared.seam_mask = seam_mask(measured, frame.shared_edges());
    }
    if (needs & kNeedsMasses) prepared.masses = prepare_mass_reference(scene);
    return prepared;
}

void compute_metrics(const MetricInput& in, const MetricScope& scope, ResultRow& row) {
    const MetricRegistry& registry = metric_registry();
    for (MetricId id = 0; id < registry.size(); ++id) {
        if (in_scope(registry[id], scope)) registry[id].compute(in, id, row);
    }
}

// box_* (rmse, max_abs and where, bias), dropout, dropout_pixels, dropout_candidates, nonfinite.
void luminance_image(const ImagePlanes& planes, Image& out) {
    if (out.width != planes.width() || out.height != planes.height()) {
        out = Image(planes.width(), planes.height());
    }
    if (planes.channels() == 1) {
        out.data = planes[0].data;
        return;
    }
    for (std::size_t k = 0; k < out.data.size(); ++k) {
        double y = 0.0;
        for (int c = 0; c < 3; ++c) {
            y += kLuminanceWeights[static_cast<std::size_t>(c)] * planes[c].data[k];
        }
        out.data[k] = static_cast<float>(y);
    }
}

Coverage luminance_coverage(const CoveragePlanes& planes) {
    if (planes.channels() == 1) return planes[0];
    Coverage out(planes.width(), planes.height());
    for (std::size_t k = 0; k < out.data.size(); ++k) {
        for (int c = 0; c < 3; ++c) {
            out.data[k] += kLuminanceWeights[static_cast<std::size_t>(c)] * planes[c].data[k];
        }
    }
    return out;
}

// A colour image's box errors over every channel: rmse over all values, the largest |error| of
// any channel and where, the mean signed error; dropout and the non-finite count are the
// luminance's (`luma`).
ErrorStats colour_errors(const ImagePlanes& planes, const CoveragePlanes& box,
                         const ErrorStats& luma) {
    ErrorStats out = luma;
    double squares = 0.0, sum = 0.0, worst = -1.0;
    for (int c = 0; c < planes.channels(); ++c) {
        const ErrorStats e = compare_to_reference(planes[c], box[c]);
        const double n = static_cast<double>(planes[c].pixel_count());
        squares += e.rmse * e.rmse * n;
        sum += e.bias * n;
        if (e.max_abs > worst || std::isnan(e.max_abs)) {
            worst = e.max_abs;
            out.max_abs = e.max_abs;
            out.max_x = e.max_x;
            out.max_y = e.max_y;
        }
    }
    const double values = static_cast<double>(planes[0].pixel_count()) * planes.channels();
    out.rmse = std::sqrt(squares / values);
    out.bias = sum / values;
    return out;
}

void measure_box(const MetricInput& in, MetricId, ResultRow& row) {
    const ErrorStats luma = compare_to_reference(in.image, in.box);
    if (in.planes == nullptr || in.box_planes == nullptr) {
        set_box_stats(row, luma);
        return;
    }
    set_box_stats(row, colour_errors(*in.planes, *in.box_planes, luma));
    row[metric::kLumaRmse] = luma.rmse;
}

// own_rmse, own_max_abs, own_bias. For a box method `own` is the box reference itself, and its
// figures are the box figures measure_box (earlier in the registry's order) already wrote: the
// same comparison is not made twice.
void measure_own(const MetricInput& in, MetricId, ResultRow& row) {
    // (Not in a colour scene, whose box figures are over the channels and own_* the luminance's.)
    if (&in.own == &in.box && in.planes == nullptr && !std::isnan(row[metric::kBoxRmse])) {
        row[metric::kOwnRmse] = row[metric::kBoxRmse];
        row[metric::kOwnMaxAbs] = row[metric::kBoxMaxAbs];
        row[metric::kOwnBias] = row[metric::kBoxBias];
        return;
    }
    set_own_stats(row, compare_to_reference(in.image, in.own));
}

// What a viewer sees (harness/measure/flip.h): cheap beside the render, so every row has it.
void measure_flip(const MetricInput& in, MetricId self, ResultRow& row) {
    // A colour scene: ꟻLIP in colour (its reference prepared from the box reference's planes).
    if (in.planes != nullptr && in.box_planes != nullptr) {
        row[self] = in.prepared.flip
                        ? flip::mean_flip(*in.planes, *in.prepared.flip)
                        : flip::mean_flip(*in.planes, flip::prepare_flip_reference(
                                                          *in.box_planes, flip::pixels_per_degree()));
        return;
    }
    row[self] = in.prepared.flip ? flip::mean_flip(in.image, *in.prepared.flip)
                                 : flip::mean_flip(in.image, in.box);
}

void measure_srgb(const MetricInput& in, MetricId self, ResultRow& row) {
    row[self] = flip::srgb_rmse(in.image, in.box);
}

void measure_edge_band(const MetricInput& in, MetricId self, ResultRow& row) {
    row[self] = edge_rmse(in.image, in.own, in.prepared.edge_band);
}

// mass_worst (and the thin object it names), mass_mean; none for a scene without thin objects.
void measure_masses(const MetricInput& in, MetricId, ResultRow& row) {
    const MassReference& masses = in.prepared.masses;
    if (masses.objects.empty()) return;
    const MassStats mass = summarise_masses(masses, captured_masses(*in.method->method, masses));
    row[metric::kMassWorst] = mass.worst;
    row.mass_worst_label = mass.worst_label;
    row[metric::kMassMean] = mass.mean;
}

// alias_total_db, alias_low_db.
void measure_alias(const MetricInput& in, MetricId, ResultRow& row) {
    const AliasEnergy alias = alias_energy(in.image, in.own);
    row[metric::kAliasTotalDb] = alias.total_db;
    row[metric::kAliasLowDb] = alias.low_db;
}

// crawl, popping (and the thin object it names).
void measure_motion(const MetricInput& in, MetricId, ResultRow& row) {
    if (in.motion == nullptr) return;
    const MotionReference& moving = *in.motion;
    const Method& method = *in.method->method;
    // A method that draws only grid-aligned circles cannot draw them moved by a fraction of a
    // pixel: no crawl figure for it.
    if (!moving.prepared.empty() &&
        !method.not_applicable(moving.prepared.back().pieces().scene()).empty()) {
        return;
    }
    const MotionStats motion = motion_symptoms(method, moving);
    row[metric::kCrawl] = motion.crawl;
    row[metric::kPopping] = motion.popping;
    row.popping_worst_label = motion.popping_worst_label;
}

void measure_ssim(const MetricInput& in, MetricId self, ResultRow& row) {
    row[self] = ssim(in.image, in.box);
}

// seams_max, seams_mean: 3-D scenes only (the mask is empty for 2-D).
void measure_seams(const MetricInput& in, MetricId, ResultRow& row) {
    if (in.prepared.seam_mask.data.empty()) return;
    const SeamStats seams = seam_error(in.image, in.box, in.prepared.seam_mask);
    row[metric::kSeamsMax] = seams.worst;
    row[metric::kSeamsMean] = seams.mean;
}

// line_* (precision, recall, rmse, by contour and crease) of the edge stage on the method's own
// depth image; none for a method that draws no depth image.
void measure_method_lines(const MetricInput& in, MetricId, ResultRow& row) {
    if (!in.prepared.lines) return;
    if (const auto s = score_method_lines(*in.prepared.lines, in.frame, *in.method->method,
                                          in.method->spec, in.image)) {
        set_line_scores(row, *s, false);
    }
}

// exact_depth_line_*: the same on the exact depth image, the same for every row of a pattern.
void measure_exact_depth_lines(const MetricInput& in, MetricId, ResultRow& row) {
    if (in.prepared.lines) set_line_scores(row, in.prepared.lines->exact_scores, true);
}

// edge_rmse_<lo>_<hi>deg, every bin of the family.
void measure_edge_angles(const MetricInput& in, MetricId, ResultRow& row) {
    const EdgeAngleErrors by_angle = edge_errors_by_angle(in.image, in.own, in.prepared.angle_bins);
    for (int b = 0; b < kEdgeAngleBins; ++b) row[edge_angle_metric(b)] = by_angle.rmse[b];
}

// Methods with a paths choice only (harness/measure/conflation.h).
void measure_conflation(const MetricInput& in, MetricId self, ResultRow& row) {
    if (const auto rmse = conflation_rmse(*in.method, *in.drawn, in.image)) row[self] = *rmse;
}

void measure_flatten_bias(const MetricInput& in, MetricId self, ResultRow& row) {
    const std::optional<Scene> own = in.method->method->own_flattening(in.drawn->scene());
    if (!own) return;
    // box_rmse's own computation on both sides, so the figure is box_rmse minus the other.
    row[self] = compare_to_reference(in.image, in.box).rmse -
                compare_to_reference(in.image, box_reference(*own)).rmse;
}

}  // namespace aabench
