// Scoring one image (harness/measure/score.h): the single-image figures of compare's
// score_task (compare.cpp), computed by the same metric functions in the same order, so that a
// render written exactly (EXR float32) and scored here gives compare's numbers bit for bit
// (tests/score_test.cpp).
#include "harness/measure/score.h"

#include <fmt/format.h>

#include <cmath>

#include "harness/measure/flip.h"
#include "harness/measure/limits.h"
#include "harness/measure/metrics.h"
#include "harness/measure/symptoms.h"
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
    const Scene& scene = frame.pieces();
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
    const Coverage box = exact_reference(scene, Filter::box());
    const ErrorStats box_stats = compare_to_reference(image, box);
    set_box_stats(row, box_stats);
    const Coverage own = filter.is_box() ? Coverage() : exact_reference(scene, filter);
    const Coverage& own_ref = filter.is_box() ? box : own;
    set_own_stats(row, filter.is_box() ? box_stats : compare_to_reference(image, own_ref));
    row[metric::kFlip] = flip::mean_flip(image, box);
    row[metric::kSrgbRmse] = flip::srgb_rmse(image, box);
    row[metric::kEdgeRmse] = edge_rmse(image, own_ref, edge_band_mask(scene));
    const AliasEnergy alias = alias_energy(image, own_ref);
    row[metric::kAliasTotalDb] = alias.total_db;
    row[metric::kAliasLowDb] = alias.low_db;
    row[metric::kSsim] = ssim(image, box);
    if (given.world) {  // as compare: the seam figures are for 3-D scenes
        const SeamStats seams = seam_error(image, box, seam_mask(scene, frame.shared_edges()));
        row[metric::kSeamsMax] = seams.worst;
        row[metric::kSeamsMean] = seams.mean;
    }
    return row;
}

}  // namespace aabench
