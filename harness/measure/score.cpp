// Scoring one image (harness/measure/score.h): the single-image figures of compare's
// score_task (compare.cpp), computed by the same loop over the metric registry
// (harness/measure/metric_input.h), so that a render written exactly (EXR float32) and scored
// here gives compare's numbers bit for bit (tests/score_test.cpp).
#include "harness/measure/score.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "harness/measure/limits.h"
#include "harness/measure/metric_input.h"
#include "harness/reference/filter_reference.h"
#include "harness/world/frame.h"

namespace aabench {

namespace {

// The one scorer: `image` is the grey image, or a colour image's luminance with `planes` beside.
ResultRow score(const Image& image, const ImagePlanes* planes, const Scene& given,
                const std::string& filter_text, const std::string& image_name) {
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
    // A colour image's box reference per channel, and the luminance's from them (linear in
    // the values).
    std::optional<CoveragePlanes> box_planes;
    if (planes != nullptr) box_planes = exact_reference_planes(measured, Filter::box());
    const Coverage box = box_planes ? luminance_coverage(*box_planes)
                                    : exact_reference(measured, Filter::box());
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
                     .prepared = prepared,
                     .planes = planes,
                     .box_planes = box_planes ? &*box_planes : nullptr},
                    scope, row);
    return row;
}

}  // namespace

ResultRow score_image(const Image& image, const Scene& given, const std::string& filter_text,
                      const std::string& image_name) {
    if (given.channels == 3) {
        throw InputError(fmt::format(
            "{}: a grey image (one channel), and the scene is a colour scene (three): give its "
            "R, G, B image",
            image_name));
    }
    return score(image, nullptr, given, filter_text, image_name);
}

ResultRow score_image(const ImagePlanes& image, const Scene& given, const std::string& filter_text,
                      const std::string& image_name) {
    if (image.channels() == 1) return score_image(image[0], given, filter_text, image_name);
    if (given.channels == 1) {
        throw InputError(fmt::format(
            "{}: a colour image (R, G, B that differ), and the scene is a grey scene (one "
            "channel)",
            image_name));
    }
    Image luma;
    luminance_image(image, luma);
    return score(luma, &image, given, filter_text, image_name);
}

}  // namespace aabench
