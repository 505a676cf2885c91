// Scoring one image (harness/measure/score.h): the single-image figures of compare's
// score_task (compare.cpp), computed by the same metric functions in the same order, so that a
// render written exactly (EXR float32) and scored here gives compare's numbers bit for bit
// (tests/score_test.cpp).
#include "harness/measure/score.h"

#include <fmt/format.h>

#include <cmath>

#include "harness/measure/limits.h"
#include "harness/measure/metrics.h"
#include "harness/measure/symptoms.h"
#include "harness/reference/filter_reference.h"
#include "harness/world/pipeline.h"

namespace aabench {

ResultRow score_image(const Image& image, const Scene& given, const std::string& filter_text,
                      const std::string& image_name) {
    ResultRow row;
    FilterSpec filter;
    try {
        filter = parse_filter_spec(filter_text);
        row.reference_filter = filter.text();
    } catch (const InputError& e) {
        throw InputError(std::string("--filter: ") + e.what());
    }
    if (image.width != given.width || image.height != given.height) {
        throw InputError(fmt::format("{}: the image is {}x{} but the scene is {}x{}", image_name,
                                     image.width, image.height, given.width, given.height));
    }
    const WorldRender world = render_world(given, make_plan(given));
    const Scene& scene = world.pieces;
    check_job_memory(estimate_job_bytes(measure_scene(scene), {}, {"box", row.reference_filter}),
                     kDefaultMemoryBudgetBytes, "score");
    row.width = scene.width;
    row.height = scene.height;
    row.edges = static_cast<long long>(scene.edge_count());
    for (int k = 0; k < kStageCount; ++k) {
        const StageCost& c = world.costs[k];
        if (!c.ran) continue;
        row.stage_ms[k] = c.time_ms;
        row.stage_bytes[k] = static_cast<double>(c.bytes);
        row.world_ms = (std::isnan(row.world_ms) ? 0.0 : row.world_ms) + c.time_ms;
    }
    const Coverage box = exact_reference(scene, FilterSpec::box());
    row.box = compare_to_reference(image, box);
    const Coverage own = filter.is_box() ? Coverage() : exact_reference(scene, filter);
    const Coverage& own_ref = filter.is_box() ? box : own;
    row.own = filter.is_box() ? row.box : compare_to_reference(image, own_ref);
    row.edge_rmse = edge_rmse(image, own_ref, edge_band_mask(scene));
    const AliasEnergy alias = alias_energy(image, own_ref);
    row.alias_total_db = alias.total_db;
    row.alias_low_db = alias.low_db;
    row.ssim = ssim(image, box);
    if (given.world) {  // as compare: the seam figures are for 3-D scenes
        const SeamStats seams = seam_error(image, box, seam_mask(scene, world.shared_edges));
        row.seams_max = seams.worst;
        row.seams_mean = seams.mean;
    }
    return row;
}

}  // namespace aabench
