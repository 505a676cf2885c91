#include "harness/report/report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "harness/measure/line_scores.h"
#include "harness/report/image_io.h"
#include "patterns/scene/scene.h"

namespace aabench {
namespace {

using Json = nlohmann::ordered_json;

struct Column {
    const char* name;
    const char* definition;  // empty: self-explanatory (names, sizes)
    std::function<Json(const ResultRow&)> get;
    std::function<void(ResultRow&, const Json&)> set;
};

// `access` returns a reference to the field, so one lambda serves reading and writing.
template <class Access>
Column column(const char* name, const char* definition, Access access) {
    return {name, definition,
            [access](const ResultRow& r) {
                const auto& value = access(const_cast<ResultRow&>(r));
                using T = std::decay_t<decltype(value)>;
                // NaN and infinities are not JSON: NaN is written as null ("does not apply"
                // or "could not be measured"), an infinity as the string "inf" or "-inf"
                // (popping when an object vanishes), and both read back as they were.
                if constexpr (std::is_floating_point_v<T>) {
                    if (std::isinf(value)) return Json(value > 0 ? "inf" : "-inf");
                }
                return Json(value);
            },
            [access, name](ResultRow& r, const Json& j) {
                using T = std::decay_t<decltype(access(r))>;
                if constexpr (std::is_floating_point_v<T>) {
                    if (j.is_null()) {
                        access(r) = std::numeric_limits<T>::quiet_NaN();
                        return;
                    }
                    if (j.is_string() && (j == "inf" || j == "-inf")) {
                        access(r) = (j == "inf" ? 1 : -1) * std::numeric_limits<T>::infinity();
                        return;
                    }
                }
                try {
                    access(r) = j.get<T>();
                } catch (const nlohmann::json::exception&) {
                    throw InputError(fmt::format("column '{}' has the wrong type", name));
                }
            }};
}

// clang-format off
const std::vector<Column>& result_columns() {
    static const std::vector<Column> columns = {
        column("task", "index of the method x pattern task in the unsharded run", [](ResultRow& r) -> auto& { return r.task; }),
        column("pattern", "", [](ResultRow& r) -> auto& { return r.pattern; }),
        column("pattern_id", "", [](ResultRow& r) -> auto& { return r.pattern_id; }),
        column("scene_file", "the scene file the row's scene was read from (compare --scenes), as given; pattern and pattern_id are then its stem. Empty for a built-in pattern", [](ResultRow& r) -> auto& { return r.scene_file; }),
        column("method", "", [](ResultRow& r) -> auto& { return r.method; }),
        column("method_id", "", [](ResultRow& r) -> auto& { return r.method_id; }),
        column("sweep_point", "true for the points of --sweep, false for the method as asked for", [](ResultRow& r) -> auto& { return r.sweep_point; }),
        column("cost_param", "the parameter that trades time for accuracy", [](ResultRow& r) -> auto& { return r.cost_param; }),
        column("cost_value", "its value in this row", [](ResultRow& r) -> auto& { return r.cost_value; }),
        column("width", "", [](ResultRow& r) -> auto& { return r.width; }),
        column("height", "", [](ResultRow& r) -> auto& { return r.height; }),
        column("edges", "contour edges in the scene", [](ResultRow& r) -> auto& { return r.edges; }),
        column("not_applicable", "why the method cannot draw this scene (its errors and times are then empty); empty when it can", [](ResultRow& r) -> auto& { return r.not_applicable; }),
        column("box_rmse", "sqrt(mean((rendered - box_reference)^2)) over all pixels", [](ResultRow& r) -> auto& { return r.box.rmse; }),
        column("box_max_abs", "max |rendered - box_reference|, at (box_max_x, box_max_y)", [](ResultRow& r) -> auto& { return r.box.max_abs; }),
        column("box_max_x", "", [](ResultRow& r) -> auto& { return r.box.max_x; }),
        column("box_max_y", "", [](ResultRow& r) -> auto& { return r.box.max_y; }),
        column("box_bias", "mean(rendered - box_reference); > 0 means too bright", [](ResultRow& r) -> auto& { return r.box.bias; }),
        column("dropout", "fraction of the pixels with box_reference > 0.1 that are rendered < 0.01", [](ResultRow& r) -> auto& { return r.box.dropout; }),
        column("dropout_pixels", "", [](ResultRow& r) -> auto& { return r.box.dropout_pixels; }),
        column("dropout_candidates", "", [](ResultRow& r) -> auto& { return r.box.dropout_candidates; }),
        column("nonfinite", "rendered pixels that are NaN or infinite", [](ResultRow& r) -> auto& { return r.box.nonfinite; }),
        column("reference_filter", "the method's own filter: box, or a radial filter spec", [](ResultRow& r) -> auto& { return r.reference_filter; }),
        column("own_rmse", "rmse against the exact reference of reference_filter: the discretisation error alone, the choice of filter taken out", [](ResultRow& r) -> auto& { return r.own.rmse; }),
        column("own_max_abs", "max |rendered - own reference|", [](ResultRow& r) -> auto& { return r.own.max_abs; }),
        column("own_bias", "mean(rendered - own reference)", [](ResultRow& r) -> auto& { return r.own.bias; }),
        column("edge_rmse", "jagged edges: rmse against the own-filter reference over the pixels whose centre lies within 1.5 px of an edge", [](ResultRow& r) -> auto& { return r.edge_rmse; }),
        column("mass_worst", "vanishing thin objects: the smallest captured mass (rendered sum / exact sum, each thin object rendered alone) over the pattern's thin objects; 1 is perfect, 0 vanished", [](ResultRow& r) -> auto& { return r.mass_worst; }),
        column("mass_worst_label", "the thin object with the smallest captured mass", [](ResultRow& r) -> auto& { return r.mass_worst_label; }),
        column("mass_mean", "mean captured mass over the thin objects", [](ResultRow& r) -> auto& { return r.mass_mean; }),
        column("alias_total_db", "moire: energy of the Hann-windowed (rendered - own reference) spectrum relative to the windowed reference's energy, in dB", [](ResultRow& r) -> auto& { return r.alias_total_db; }),
        column("alias_low_db", "the same, only frequencies below 0.25 cycles/px (half of Nyquist), where aliases show as moire", [](ResultRow& r) -> auto& { return r.alias_low_db; }),
        column("crawl", "crawling edges: mean over pixels of the standard deviation over T sub-pixel diagonal offsets of (rendered - own reference)", [](ResultRow& r) -> auto& { return r.crawl; }),
        column("popping", "popping: the worst max/min ratio of a thin object's captured mass over the T offsets; inf when it vanishes in some frame", [](ResultRow& r) -> auto& { return r.popping; }),
        column("popping_worst_label", "the thin object with the worst popping", [](ResultRow& r) -> auto& { return r.popping_worst_label; }),
        column("ssim", "SSIM against the box reference (cv::quality, images scaled to 8-bit range so its constants apply)", [](ResultRow& r) -> auto& { return r.ssim; }),
        column("seams_max", "seams (3-D): max |rendered - box_reference| over the pixels crossed by an edge two visible faces of one object share, where the exact answer has no background; face-by-face compositing leaks it there", [](ResultRow& r) -> auto& { return r.seams_max; }),
        column("seams_mean", "seams (3-D): mean |rendered - box_reference| over the same pixels", [](ResultRow& r) -> auto& { return r.seams_mean; }),
        column("line_precision", "scenes with edges (Saito & Takahashi 1990): of the pixels the edge stage on the method's own depth image detects (p > 0.5 or crease_weight |e| > 0.025), the fraction whose centre is within 1 px of a ground-truth line (contour or crease, from the exact visible pieces); empty for other scenes and for methods that draw no depth image", [](ResultRow& r) -> auto& { return r.line_precision; }),
        column("line_recall", "scenes with edges: of the pixels whose centre is within 0.5 px of a ground-truth line, the fraction with a detected pixel within 1 px (itself or a 4-neighbour)", [](ResultRow& r) -> auto& { return r.line_recall; }),
        column("line_rmse", "scenes with edges: rmse of the edge stage's line image against the exact box coverage of the ground-truth lines drawn as one-pixel-wide strips, composed in the scene's style", [](ResultRow& r) -> auto& { return r.line_rmse; }),
        column("exact_depth_line_precision", "scenes with edges: line_precision of the edge stage on the exact depth image (the same for every row of a pattern: what the operator loses by itself)", [](ResultRow& r) -> auto& { return r.exact_depth_line_precision; }),
        column("exact_depth_line_recall", "scenes with edges: line_recall of the edge stage on the exact depth image", [](ResultRow& r) -> auto& { return r.exact_depth_line_recall; }),
        column("exact_depth_line_rmse", "scenes with edges: line_rmse of the edge stage on the exact depth image", [](ResultRow& r) -> auto& { return r.exact_depth_line_rmse; }),
        column("line_contour_precision", "scenes with edges: line_precision of the contour detections alone (p > 0.5) against the ground-truth contours alone", [](ResultRow& r) -> auto& { return r.line_contour_precision; }),
        column("line_contour_recall", "scenes with edges: line_recall of the ground-truth contours alone, found by contour detections alone", [](ResultRow& r) -> auto& { return r.line_contour_recall; }),
        column("line_crease_precision", "scenes with edges: line_precision of the crease detections alone (crease_weight |e| > 0.025) against the ground-truth creases (convex and concave) alone", [](ResultRow& r) -> auto& { return r.line_crease_precision; }),
        column("line_crease_recall", "scenes with edges: line_recall of the ground-truth creases alone, found by crease detections alone", [](ResultRow& r) -> auto& { return r.line_crease_recall; }),
        column("exact_depth_line_contour_precision", "scenes with edges: line_contour_precision of the edge stage on the exact depth image", [](ResultRow& r) -> auto& { return r.exact_depth_line_contour_precision; }),
        column("exact_depth_line_contour_recall", "scenes with edges: line_contour_recall of the edge stage on the exact depth image", [](ResultRow& r) -> auto& { return r.exact_depth_line_contour_recall; }),
        column("exact_depth_line_crease_precision", "scenes with edges: line_crease_precision of the edge stage on the exact depth image", [](ResultRow& r) -> auto& { return r.exact_depth_line_crease_precision; }),
        column("exact_depth_line_crease_recall", "scenes with edges: line_crease_recall of the edge stage on the exact depth image", [](ResultRow& r) -> auto& { return r.exact_depth_line_crease_recall; }),
        column("time_median_ns", "median wall time of one render after a warm-up, single-threaded unless time_threads > 1", [](ResultRow& r) -> auto& { return r.time.median_ns; }),
        column("time_min_ns", "", [](ResultRow& r) -> auto& { return r.time.min_ns; }),
        column("time_max_ns", "", [](ResultRow& r) -> auto& { return r.time.max_ns; }),
        column("time_runs", "timed runs after the warm-up", [](ResultRow& r) -> auto& { return r.time.runs; }),
        column("time_threads", "threads of each timed render (compare --render-threads; 1: single-threaded, the default)", [](ResultRow& r) -> auto& { return r.time.threads; }),
        column("time_source", "compare (its own timing), benchmark (--bench-json) or process (--external: the renderer's whole process, startup included)", [](ResultRow& r) -> auto& { return r.time_source; }),
        column("external_startup_ns", "--external: median wall time of the same command on an empty scene of this size (reported, not subtracted)", [](ResultRow& r) -> auto& { return r.external_startup_ns; }),
        column("external_reported_ms", "--external: median of the times the command printed as 'aabench-time-ms: X'; empty if it printed none", [](ResultRow& r) -> auto& { return r.external_reported_ms; }),
        column("mpixel_per_s", "width*height / time_median / 1e6", [](ResultRow& r) -> auto& { return r.mpixel_per_s; }),
        column("medges_per_s", "edges / time_median / 1e6", [](ResultRow& r) -> auto& { return r.medges_per_s; }),
        column("world_ms", "3-D patterns: time of the world stages the plan kept (projection, culling, patterns, shadows, shading, visibility, ...), one run; empty for 2-D", [](ResultRow& r) -> auto& { return r.world_ms; }),
    };
    return columns;
}
// clang-format on

// result_columns() and, after them, two per world stage: stage_<name>_ms and _bytes (empty
// where the plan left the stage out).
const std::vector<Column>& all_columns() {
    static const std::vector<Column> columns = [] {
        std::vector<Column> c = result_columns();
        static const std::vector<std::string> names = [] {
            std::vector<std::string> n;
            for (int k = 0; k < kStageCount; ++k) {
                n.push_back(fmt::format("stage_{}_ms", stage_name(static_cast<Stage>(k))));
                n.push_back(fmt::format("stage_{}_bytes", stage_name(static_cast<Stage>(k))));
            }
            return n;
        }();
        for (int k = 0; k < kStageCount; ++k) {
            c.push_back(column(names[2 * k].c_str(), "time of this world stage (ms, one run); empty: left out by the plan",
                               [k](ResultRow& r) -> auto& { return r.stage_ms[k]; }));
            c.push_back(column(names[2 * k + 1].c_str(), "heap bytes allocated by this world stage; empty: left out by the plan",
                               [k](ResultRow& r) -> auto& { return r.stage_bytes[k]; }));
        }
        return c;
    }();
    return columns;
}

// The columns of the line scores (scenes with `edges`): written to JSON only for their rows.
bool is_line_column(std::string_view name) {
    return name.find("line_") != std::string_view::npos;
}

std::string csv_field(const Json& value) {
    if (value.is_string()) {
        std::string out = "\"";
        for (char c : value.get<std::string>()) out += c == '"' ? std::string("\"\"") : std::string(1, c);
        return out + "\"";
    }
    if (value.is_null()) return "";  // NaN
    return value.dump();
}

constexpr const char* kExactDepthLabel = "(edge stage on the exact depth)";

// The line scores of one pattern's default rows, when it asks for edges: one row per method
// and a last row for the edge stage on the exact depth image.
std::string format_line_table(const std::vector<ResultRow>& rows, const std::string& pattern,
                              std::size_t name_width) {
    const ResultRow* any = nullptr;
    for (const ResultRow& r : rows) {
        if (r.pattern == pattern && !r.sweep_point && !std::isnan(r.exact_depth_line_rmse)) any = &r;
    }
    if (!any) return "";
    auto num = [](double v) {
        return std::isnan(v) ? fmt::format("{:>9}", "-") : fmt::format("{:>9.4f}", v);
    };
    name_width = std::max(name_width, std::string_view(kExactDepthLabel).size());
    std::string out = fmt::format(
        "  lines (edge stage on each depth image; detected p > {} or crease_weight |e| > {}, "
        "within {} px of the true lines; contours and creases apart on the right)\n"
        "  {:<{}} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}\n",
        kContourDetectThreshold, kCreaseDetectDarkness, kMatchRadiusPx, "depth image of",
        name_width, "precision", "recall", "line_rmse", "cont_prec", "cont_rec", "crea_prec",
        "crea_rec");
    for (const ResultRow& r : rows) {
        if (r.pattern != pattern || r.sweep_point) continue;
        out += fmt::format("  {:<{}} {} {} {} {} {} {} {}\n", r.method, name_width,
                           num(r.line_precision), num(r.line_recall), num(r.line_rmse),
                           num(r.line_contour_precision), num(r.line_contour_recall),
                           num(r.line_crease_precision), num(r.line_crease_recall));
    }
    out += fmt::format("  {:<{}} {} {} {} {} {} {} {}\n", kExactDepthLabel, name_width,
                       num(any->exact_depth_line_precision), num(any->exact_depth_line_recall),
                       num(any->exact_depth_line_rmse),
                       num(any->exact_depth_line_contour_precision),
                       num(any->exact_depth_line_contour_recall),
                       num(any->exact_depth_line_crease_precision),
                       num(any->exact_depth_line_crease_recall));
    return out;
}

}  // namespace

std::string format_compare_tables(const std::vector<ResultRow>& rows) {
    std::string out;
    std::string current;
    std::size_t name_width = 6;
    for (const ResultRow& r : rows) name_width = std::max(name_width, r.method.size());
    // NaN: the figure does not apply to this row (e.g. popping on a pattern without thin
    // objects); shown as "-" rather than a number.
    auto num = [](double v, int width, int precision) {
        if (std::isnan(v)) return fmt::format("{:>{}}", "-", width);
        if (std::isinf(v)) return fmt::format("{:>{}}", v > 0 ? "inf" : "-inf", width);
        return fmt::format("{:>{}.{}f}", v, width, precision);
    };
    for (const ResultRow& r : rows) {
        if (r.sweep_point) continue;
        if (r.pattern != current) {
            // The previous pattern's line scores after its table (a pattern's rows are
            // contiguous).
            if (!current.empty()) out += format_line_table(rows, current, name_width);
            current = r.pattern;
            out += fmt::format("\n{}  ({}x{}, {} edges{}; times {})\n", r.pattern, r.width,
                               r.height, r.edges,
                               r.scene_file.empty() ? "" : ", scene file " + r.scene_file,
                               r.time.threads > 1
                                   ? fmt::format("on {} threads in bands", r.time.threads)
                                   : std::string("single-threaded"));
            out += fmt::format(
                "  {:<{}} {:>8} {:>8} {:>9} {:>8} {:>8} {:>8} {:>6} {:>7} {:>7} {:>8} {:>6} {:>9} "
                "{:>8}\n",
                "method", name_width, "rmse", "max_abs", "bias", "dropout", "own_rmse", "edge",
                "mass", "lowf_dB", "crawl", "popping", "ssim", "time_ms", "Mpix/s");
        }
        if (!r.not_applicable.empty()) {  // the method cannot draw this scene: its reason
            out += fmt::format("  {:<{}} n/a: {}\n", r.method, name_width, r.not_applicable);
            continue;
        }
        out += fmt::format(
            "  {:<{}} {} {} {:>+9.5f} {:>7.2f}% {} {} {} {} {} {} {} {:>9.3f} {:>8.1f}\n",
            r.method, name_width, num(r.box.rmse, 8, 5), num(r.box.max_abs, 8, 5), r.box.bias,
            100.0 * r.box.dropout, num(r.own.rmse, 8, 5), num(r.edge_rmse, 8, 5),
            num(r.mass_worst, 6, 3), num(r.alias_low_db, 7, 1), num(r.crawl, 7, 4),
            num(r.popping, 8, 2), num(r.ssim, 6, 4), r.time.median_ns * 1e-6, r.mpixel_per_s);
    }
    if (!current.empty()) out += format_line_table(rows, current, name_width);
    return out;
}

std::string compare_rows_csv(const std::vector<ResultRow>& rows) {
    std::string out;
    for (const Column& c : all_columns()) out += (out.empty() ? "" : ",") + std::string(c.name);
    out += '\n';
    for (const ResultRow& r : rows) {
        bool first = true;
        for (const Column& c : all_columns()) {
            if (!first) out += ',';
            first = false;
            out += csv_field(c.get(r));
        }
        out += '\n';
    }
    return out;
}

std::string compare_json(const std::vector<ResultRow>& rows, const RunContext& context) {
    Json doc;
    doc["context"] = {
        {"tool", context.tool},
        {"git_revision", context.git_revision},
        {"build_type", context.build_type},
        {"compiler", context.compiler},
        {"flags", context.flags},
        {"cpu", context.cpu},
        {"hardware_threads", context.hardware_threads},
        {"date_utc", context.date_utc},
        {"command", context.command},
    };
    Json& definitions = doc["definitions"] = Json::object();
    for (const Column& c : all_columns()) {
        if (*c.definition) definitions[c.name] = c.definition;
    }
    Json& out_rows = doc["rows"] = Json::array();
    for (const ResultRow& r : rows) {
        Json row = Json::object();
        for (const Column& c : all_columns()) {
            // The line columns only for scenes that ask for edges (rows of other scenes keep
            // the columns they always had).
            if (is_line_column(c.name) && std::isnan(r.exact_depth_line_rmse)) continue;
            row[c.name] = c.get(r);
        }
        out_rows.push_back(std::move(row));
    }
    return doc.dump(2) + "\n";
}

std::vector<ResultRow> rows_from_compare_json(const std::string& text, const std::string& source,
                                              bool missing_as_default) {
    Json doc;
    try {
        doc = Json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(fmt::format("{}: byte {}: invalid JSON", source, e.byte));
    }
    if (!doc.is_object() || !doc.contains("rows") || !doc["rows"].is_array()) {
        throw InputError(source + ": not an aabench results.json (no \"rows\" array)");
    }
    std::vector<ResultRow> rows;
    for (std::size_t k = 0; k < doc["rows"].size(); ++k) {
        const Json& j = doc["rows"][k];
        ResultRow row;
        for (const Column& c : all_columns()) {
            if (!j.is_object()) throw InputError(fmt::format("{}: rows[{}]: not an object", source, k));
            if (!j.contains(c.name)) {
                // Columns that came after results files existed: a row without them is a
                // pattern's row of a registered method.
                const std::string_view name(c.name);
                const bool added_later = name == "scene_file" || name == "external_startup_ns" ||
                                         name == "external_reported_ms" || is_line_column(name);
                if (missing_as_default || added_later) continue;
                throw InputError(fmt::format("{}: rows[{}]: missing '{}'", source, k, c.name));
            }
            try {
                c.set(row, j[c.name]);
            } catch (const InputError& e) {
                throw InputError(fmt::format("{}: rows[{}]: {}", source, k, e.what()));
            }
        }
        rows.push_back(std::move(row));
    }
    return rows;
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
