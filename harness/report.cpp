#include "harness/report.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "harness/image_io.h"
#include "patterns/scene.h"

namespace aabench {
namespace {

// CSV fields never need quoting except specs, which contain commas.
std::string csv_quote(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

}  // namespace

std::string format_compare_tables(const std::vector<ResultRow>& rows) {
    std::string out;
    std::string current;
    std::size_t name_width = 6;
    for (const ResultRow& r : rows) name_width = std::max(name_width, r.method.size());
    for (const ResultRow& r : rows) {
        if (r.pattern != current) {
            current = r.pattern;
            out += fmt::format("\n{}  ({}x{}, {} edges)\n", r.pattern, r.width, r.height, r.edges);
            out += fmt::format("  {:<{}} {:>9} {:>9} {:>11} {:>10} {:>8} {:>9} {:>10} {:>9}\n",
                               "method", name_width, "rmse", "max_abs", "at (x,y)", "bias", "dropout",
                               "own_rmse", "time_ms", "Mpix/s");
        }
        out += fmt::format(
            "  {:<{}} {:>9.5f} {:>9.5f} {:>11} {:>+10.6f} {:>7.2f}% {:>9.5f} {:>10.3f} {:>9.1f}\n",
            r.method, name_width, r.box.rmse,
            r.box.max_abs, fmt::format("({},{})", r.box.max_x, r.box.max_y), r.box.bias,
            100.0 * r.box.dropout, r.own.rmse, r.time.median_ns * 1e-6, r.mpixel_per_s);
    }
    return out;
}

std::string compare_rows_csv(const std::vector<ResultRow>& rows) {
    std::string out =
        "pattern,method,method_id,width,height,edges,box_rmse,box_max_abs,box_max_x,box_max_y,"
        "box_bias,dropout,dropout_pixels,dropout_candidates,nonfinite,reference_filter,own_rmse,"
        "own_max_abs,own_bias,time_median_ns,time_min_ns,time_max_ns,time_runs,mpixel_per_s,"
        "medges_per_s\n";
    for (const ResultRow& r : rows) {
        out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
                           csv_quote(r.pattern), csv_quote(r.method), r.method_id, r.width,
                           r.height, r.edges, r.box.rmse, r.box.max_abs, r.box.max_x,
                           r.box.max_y, r.box.bias, r.box.dropout, r.box.dropout_pixels,
                           r.box.dropout_candidates, r.box.nonfinite, csv_quote(r.reference_filter),
                           r.own.rmse, r.own.max_abs, r.own.bias, r.time.median_ns,
                           r.time.min_ns, r.time.max_ns, r.time.runs, r.mpixel_per_s,
                           r.medges_per_s);
    }
    return out;
}

std::string compare_json(const std::vector<ResultRow>& rows, const RunContext& context) {
    nlohmann::ordered_json doc;
    doc["context"] = {
        {"tool", context.tool},         {"git_revision", context.git_revision},
        {"build_type", context.build_type}, {"compiler", context.compiler},
        {"flags", context.flags},       {"cpu", context.cpu},
        {"hardware_threads", context.hardware_threads},
        {"date_utc", context.date_utc}, {"command", context.command},
    };
    doc["definitions"] = {
        {"box_rmse", "sqrt(mean((rendered - box_reference)^2)) over all pixels"},
        {"box_max_abs", "max |rendered - box_reference|, at (box_max_x, box_max_y)"},
        {"box_bias", "mean(rendered - box_reference); > 0 means too bright"},
        {"dropout", fmt::format("fraction of pixels with box_reference > {} rendered < {}",
                                kDropoutCoverage, kDropoutRendered)},
        {"reference_filter", "the method's own filter: box, or a radial filter spec"},
        {"own_rmse", "rmse against the exact reference of reference_filter: the method's "
                     "discretisation error alone, with the choice of filter taken out"},
        {"own_max_abs", "max |rendered - own reference|"},
        {"own_bias", "mean(rendered - own reference)"},
        {"time_median_ns", "median wall time of one render after a warm-up, single thread"},
        {"mpixel_per_s", "width*height / time_median / 1e6"},
        {"medges_per_s", "edges / time_median / 1e6"},
    };
    auto& out_rows = doc["rows"] = nlohmann::ordered_json::array();
    for (const ResultRow& r : rows) {
        out_rows.push_back({
            {"pattern", r.pattern},
            {"pattern_id", r.pattern_id},
            {"method", r.method},
            {"method_id", r.method_id},
            {"width", r.width},
            {"height", r.height},
            {"edges", r.edges},
            {"box_rmse", r.box.rmse},
            {"box_max_abs", r.box.max_abs},
            {"box_max_x", r.box.max_x},
            {"box_max_y", r.box.max_y},
            {"box_bias", r.box.bias},
            {"dropout", r.box.dropout},
            {"dropout_pixels", r.box.dropout_pixels},
            {"dropout_candidates", r.box.dropout_candidates},
            {"nonfinite", r.box.nonfinite},
            {"reference_filter", r.reference_filter},
            {"own_rmse", r.own.rmse},
            {"own_max_abs", r.own.max_abs},
            {"own_bias", r.own.bias},
            {"time_median_ns", r.time.median_ns},
            {"time_min_ns", r.time.min_ns},
            {"time_max_ns", r.time.max_ns},
            {"time_runs", r.time.runs},
            {"mpixel_per_s", r.mpixel_per_s},
            {"medges_per_s", r.medges_per_s},
        });
    }
    // NaN is not JSON: nlohmann writes it as null, which readers see as "no number".
    return doc.dump(2) + "\n";
}

void write_compare_results(const std::string& dir, const std::vector<ResultRow>& rows,
                           const RunContext& context) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw InputError(fmt::format("{}: cannot create directory ({})", dir, ec.message()));
    const std::filesystem::path base(dir);
    write_text_file((base / "table.txt").string(),
                    "command: " + context.command + "\n" + format_compare_tables(rows));
    write_text_file((base / "results.csv").string(), compare_rows_csv(rows));
    write_text_file((base / "results.json").string(), compare_json(rows, context));
}

}  // namespace aabench
