// Text and JSON of one scored image (harness/report/score_report.h).
#include "harness/report/score_report.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "harness/report/report.h"

namespace aabench {

const std::vector<std::string>& score_fields() {
    static const std::vector<std::string> fields = {
        "pattern",        "pattern_id",
        "scene_file",     "width",
        "height",         "edges",
        "box_rmse",       "box_max_abs",
        "box_max_x",      "box_max_y",
        "box_bias",       "dropout",
        "dropout_pixels", "dropout_candidates",
        "nonfinite",      "reference_filter",
        "own_rmse",       "own_max_abs",
        "own_bias",       "edge_rmse",
        "alias_total_db", "alias_low_db",
        "ssim",           "seams_max",
        "seams_mean",     "world_ms",
    };
    return fields;
}

std::string score_json(const ResultRow& row, const std::string& image_path) {
    // Through compare_json: every column's name and encoding come from the one table.
    const nlohmann::ordered_json all =
        nlohmann::ordered_json::parse(compare_json({row}, RunContext{}))["rows"][0];
    nlohmann::ordered_json out;
    out["image"] = image_path;
    for (const std::string& field : score_fields()) out[field] = all.at(field);
    return out.dump(2) + "\n";
}

std::string format_score(const ResultRow& r, const std::string& image_path) {
    auto num = [](double v) {
        if (std::isnan(v)) return std::string("-");
        return fmt::format("{:.6g}", v);
    };
    std::string out =
        fmt::format("{} scored against {}  ({}x{}, {} edges{})\n", image_path, r.pattern, r.width,
                    r.height, r.edges, r.scene_file.empty() ? "" : ", scene file " + r.scene_file);
    auto line = [&out](const char* name, const std::string& value, const std::string& note) {
        out += fmt::format("  {:<15} {:>12}  {}\n", name, value, note);
    };
    line("box_rmse", num(r.box.rmse), "against the exact box reference");
    line("box_max_abs", num(r.box.max_abs),
         fmt::format("at pixel ({}, {})", r.box.max_x, r.box.max_y));
    line("box_bias", num(r.box.bias), "> 0: too bright");
    line("dropout", fmt::format("{:.2f}%", 100.0 * r.box.dropout),
         fmt::format("{} of {} covered pixels rendered empty", r.box.dropout_pixels,
                     r.box.dropout_candidates));
    line("own_rmse", num(r.own.rmse), "against the exact " + r.reference_filter + " reference");
    line("own_max_abs", num(r.own.max_abs), "");
    line("own_bias", num(r.own.bias), "");
    line("edge_rmse", num(r.edge_rmse), "within 1.5 px of an edge, against " + r.reference_filter);
    line("alias_total_db", num(r.alias_total_db), "error spectrum energy / reference energy");
    line("alias_low_db", num(r.alias_low_db), "the same below half of Nyquist (moire)");
    line("ssim", num(r.ssim), "against the box reference");
    if (!std::isnan(r.seams_max)) {
        line("seams_max", num(r.seams_max), "on edges shared by visible faces");
        line("seams_mean", num(r.seams_mean), "");
    }
    line("nonfinite", std::to_string(r.box.nonfinite), "NaN or infinite pixels");
    return out;
}

}  // namespace aabench
