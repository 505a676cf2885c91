// What `aabench merge` needs of the comparison run (harness/measure/compare.h): the shards'
// rows put back in the unsharded order, and the report's figures rendered again from rows.
#include <fmt/format.h>

#include <algorithm>

#include "harness/measure/compare.h"
#include "harness/measure/metric_input.h"
#include "harness/reference/box_reference.h"
#include "harness/reference/filter_reference.h"
#include "harness/world/frame.h"
#include "methods/method.h"
#include "patterns/pattern.h"

namespace aabench {

std::vector<ComparisonFigures> render_figures(const std::vector<ResultRow>& rows,
                                              const std::vector<SceneFileInput>& scene_files) {
    std::vector<ComparisonFigures> figures;
    std::vector<PreparedFrame> frames;  // per figure: its pattern prepared once
    for (const ResultRow& row : rows) {
        if (row.sweep_point) continue;
        const SceneFileInput* file = nullptr;
        if (!row.scene_file.empty()) {
            for (const SceneFileInput& f : scene_files) file = f.path == row.scene_file ? &f : file;
            if (!file) continue;
        }
        auto it = std::find_if(figures.begin(), figures.end(), [&](const ComparisonFigures& f) {
            return f.pattern_spec == row.pattern;
        });
        if (it == figures.end()) {
            ComparisonFigures fig;
            fig.pattern_id = row.pattern_id;
            fig.pattern_spec = row.pattern;
            frames.push_back(PreparedFrame::prepare(
                file ? file->scene : make_pattern(row.pattern, row.width, row.height)));
            fig.scene = frames.back().pieces().scene();
            if (fig.scene.channels == 3) {  // per channel, and the luminance's from them
                fig.colour_reference =
                    exact_reference_planes(frames.back().pieces(), Filter::box());
                fig.reference = luminance_coverage(*fig.colour_reference);
            } else {
                fig.reference = box_reference(frames.back().pieces());
            }
            figures.push_back(std::move(fig));
            it = figures.end() - 1;
        }
        it->methods.push_back(row.method);
        const MethodInstance method = make_method(row.method);
        const PreparedFrame& frame = frames[it - figures.begin()];
        if (it->colour_reference) {
            it->colour_images.push_back(
                render_planes(*method.method, frame.input_for(*method.method)));
            Image luma;
            luminance_image(it->colour_images.back(), luma);
            it->images.push_back(std::move(luma));
        } else {
            it->images.push_back(render_scene(*method.method, frame.input_for(*method.method)));
        }
    }
    return figures;
}

std::vector<ResultRow> merge_shard_rows(std::vector<std::vector<ResultRow>> shards) {
    std::vector<ResultRow> rows;
    for (auto& shard : shards) {
        for (ResultRow& r : shard) rows.push_back(std::move(r));
    }
    std::sort(rows.begin(), rows.end(),
              [](const ResultRow& a, const ResultRow& b) { return a.task < b.task; });
    for (std::size_t k = 1; k < rows.size(); ++k) {
        if (rows[k].task == rows[k - 1].task) {
            throw InputError(fmt::format("merge: task {} ({} / {}) appears in two shards",
                                         rows[k].task, rows[k].pattern_id, rows[k].method));
        }
    }
    // The built-in patterns' rows share the run's --size; a scene file has its own.
    const ResultRow* sized = nullptr;
    for (const ResultRow& r : rows) {
        if (!r.scene_file.empty()) continue;
        if (!sized) sized = &r;
        if (r.width != sized->width || r.height != sized->height) {
            throw InputError("merge: the shards were run at different sizes");
        }
    }
    return rows;
}

}  // namespace aabench
