// Scoring one image (harness/measure/score.h): the single-image figures of compare's
// score_task (compare.cpp), computed by the same loop over the metric registry
// (harness/measure/metric_input.h), so that a render written exactly (EXR float32) and scored
// here gives compare's numbers bit for bit (tests/score_test.cpp).
#include "harness/measure/score.h"

#include <fmt/format.h>

#include <cmath>

#include "harness/measure/limits.h"
#include "harness/measure/metric_input.h"
#include "harness/reference/filter_reference.h"
#include "harness/world/frame.h"

namespace aabench {

ResultRow score_image(const Image& image, const Scene& given, const std::string& filter_text,
                      const std::string& image_name) {
    ResultRow row;
    Filter filter;
    try {
        filter = Filter::parse(filter_text);
        row.reference_filter = filter.text();
    } catch (const InputError& e) {
        throw InputError(std::string("--filter: ") + e.what());
    }
    if (image.width != given.width || image.height != given.height) {
        throw InputError(fmt::format("{}: the image is {}x{} but the scene is {}x{}", image_name,
                                     image.width, image.height, given.width, given.height));
    }
    const PreparedFrame frame = PreparedFrame::prepare(given);
    const SceneInput measured = frame.pieces();
    const Scene& scene = measured.scene();
    check_job_memory(estimate_job_bytes(measure_scene(scene), {}, {"box", row.reference_filter}),
                     kDefaultMemoryBudgetBytes, "score");
    row.width = scene.width;
    row.height = scene.height;
    row.edges = static_cast<long long>(scene.edge_count());
    const StageCosts costs = frame.costs();
    for (int k = 0; k < kStageCount; ++k) {
        const StageCost& c = costs[k];
        if (!c.ran) continue;
        add_stage_cost(row, k, c.time_ms, static_cast<double>(c.bytes));
    }
    const Coverage box = exact_reference(measured, Filter::box());
    const Coverage own = filter.is_box() ? Coverage() : exact_reference(measured, filter);
    // Only the one image: the metrics `score` shows, none that runs a method.
    MetricScope scope;
    scope.with_method = false;
    scope.score_only = true;
    const ScenePreparations prepared = prepare_scene(frame, metric_needs(scope));
    compute_metrics({.image = image,
                     .frame = frame,
                     .box = box,
                     .own = filter.is_box() ? box : own,
                     .prepared = prepared},
                    scope, row);
    return row;
}

}  // namespace aabench
