#include "harness/report/report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <type_traits>

#include "harness/measure/line_scores.h"
#include "harness/measure/sequence_metrics.h"
#include "harness/measure/pass_time.h"
#include "harness/report/image_io.h"
#include "methods/method.h"
#include "patterns/scene/scene.h"

namespace aabench {
namespace {

using Json = nlohmann::ordered_json;

// NaN and infinities are not JSON: NaN is written as null ("does not apply" or "could not be
// measured"), an infinity as the string "inf" or "-inf" (popping when an object vanishes), and
// both read back as they were.
Json number_json(double value, bool integer) {
    if (std::isnan(value)) return Json(nullptr);
    if (std::isinf(value)) return Json(value > 0 ? "inf" : "-inf");
    if (integer) return Json(static_cast<long long>(value));
    return Json(value);
}

double number_from_json(const Json& j, const std::string& name) {
    if (j.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (j.is_string() && (j == "inf" || j == "-inf")) {
        return (j == "inf" ? 1 : -1) * std::numeric_limits<double>::infinity();
    }
    if (!j.is_number()) throw InputError(fmt::format("column '{}' has the wrong type", name));
    return j.get<double>();
}

// One column of results.csv and results.json: an identity field of the row or a metric.
struct Column {
    std::string name;
    std::string definition;  // empty: self-explanatory (names, sizes)
    std::function<Json(const ResultRow&)> get;
    std::function<void(ResultRow&, const Json&)> set;
    bool may_be_absent = false;  // added after results files existed
    bool lines_only = false;     // written only for the rows of scenes with `edges`
    bool sequences_only = false;  // written only for the rows of a sequence run
};

// An identity field. `access` returns a reference to it, so one lambda serves reading and
// writing. `before`: the metric it is written in front of (-1: before every metric), which
// keeps the columns in the order they have always had.
struct IdentityColumn {
    Column column;
    MetricId before;
};

template <class Access>
IdentityColumn identity(const char* name, const char* definition, MetricId before, Access access) {
    Column c;
    c.name = name;
    c.definition = definition;
    c.get = [access](const ResultRow& r) {
        const auto& value = access(const_cast<ResultRow&>(r));
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_floating_point_v<T>) return number_json(value, false);
        return Json(value);
    };
    c.set = [access, name](ResultRow& r, const Json& j) {
        using T = std::decay_t<decltype(access(r))>;
        if constexpr (std::is_floating_point_v<T>) {
            access(r) = number_from_json(j, name);
        } else {
            try {
                access(r) = j.get<T>();
            } catch (const nlohmann::json::exception&) {
                throw InputError(fmt::format("column '{}' has the wrong type", name));
            }
        }
    };
    c.may_be_absent = std::string_view(name) == "scene_file";
    return {std::move(c), before};
}

// clang-format off
const std::vector<IdentityColumn>& identity_columns() {
    using namespace metric;
    static const std::vector<IdentityColumn> columns = {
        identity("task", "index of the method x pattern task in the unsharded run", -1, [](ResultRow& r) -> auto& { return r.task; }),
        identity("pattern", "", -1, [](ResultRow& r) -> auto& { return r.pattern; }),
        identity("pattern_id", "", -1, [](ResultRow& r) -> auto& { return r.pattern_id; }),
        identity("scene_file", "the scene file the row's scene was read from (compare --scenes), as given; pattern and pattern_id are then its stem. Empty for a built-in pattern", -1, [](ResultRow& r) -> auto& { return r.scene_file; }),
        identity("method", "", -1, [](ResultRow& r) -> auto& { return r.method; }),
        identity("method_id", "", -1, [](ResultRow& r) -> auto& { return r.method_id; }),
        identity("sweep_point", "true for the points of --sweep, false for the method as asked for", -1, [](ResultRow& r) -> auto& { return r.sweep_point; }),
        identity("cost_param", "the parameter that trades time for accuracy", -1, [](ResultRow& r) -> auto& { return r.cost_param; }),
        identity("cost_value", "its value in this row", -1, [](ResultRow& r) -> auto& { return r.cost_value; }),
        identity("width", "", -1, [](ResultRow& r) -> auto& { return r.width; }),
        identity("height", "", -1, [](ResultRow& r) -> auto& { return r.height; }),
        identity("edges", "contour edges in the scene", -1, [](ResultRow& r) -> auto& { return r.edges; }),
        identity("not_applicable", "why the method cannot draw this scene (its errors and times are then empty); empty when it can", -1, [](ResultRow& r) -> auto& { return r.not_applicable; }),
        identity("reference_filter", "the method's own filter: box, or a radial filter spec", kOwnRmse, [](ResultRow& r) -> auto& { return r.reference_filter; }),
        identity("mass_worst_label", "the thin object with the smallest captured mass", kMassMean, [](ResultRow& r) -> auto& { return r.mass_worst_label; }),
        identity("popping_worst_label", "the thin object with the worst popping", kSsim, [](ResultRow& r) -> auto& { return r.popping_worst_label; }),
        identity("time_runs", "timed runs after the warm-up", kTimeMethodMs, [](ResultRow& r) -> auto& { return r.time_runs; }),
        identity("time_threads", "threads of each timed render (compare --render-threads; 1: single-threaded, the default)", kTimeMethodMs, [](ResultRow& r) -> auto& { return r.time_threads; }),
        identity("time_source", "compare (its own timing), benchmark (--bench-json) or process (--external: the renderer's whole process, startup included)", kTimeMethodMs, [](ResultRow& r) -> auto& { return r.time_source; }),
    };
    return columns;
}
// clang-format on

Column metric_column(MetricId id) {
    const MetricDef& def = metric_registry()[id];
    Column c;
    c.name = def.key;
    c.definition = def.definition;
    const bool integer = def.integer;
    c.get = [id, integer](const ResultRow& r) { return number_json(r[id], integer); };
    c.set = [id, name = def.key](ResultRow& r, const Json& j) {
        r[id] = number_from_json(j, name);
    };
    c.may_be_absent = def.may_be_absent;
    c.lines_only = (def.applies & ~kAppliesLines) == 0;
    c.sequences_only = def.applies == kAppliesSequences;
    return c;
}

// Every column, in file order: the identity fields and the registry's metrics (built-ins, the
// world stage family, any metric a test added). Built on each call: the registry can grow.
std::vector<Column> all_columns() {
    std::vector<Column> columns;
    const auto add_identity_before = [&](MetricId id) {
        for (const IdentityColumn& c : identity_columns()) {
            if (c.before == id) columns.push_back(c.column);
        }
    };
    add_identity_before(-1);
    for (MetricId id = 0; id < metric_registry().size(); ++id) {
        add_identity_before(id);
        columns.push_back(metric_column(id));
    }
    return columns;
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

// A value in a text-table cell `width` wide, as the metric is shown. NaN: the figure does not
// apply to this row (e.g. popping on a pattern without thin objects): "-" rather than a number.
std::string text_cell(const MetricDef& def, double value, int width) {
    if (std::isnan(value)) return fmt::format("{:>{}}", "-", width);
    if (std::isinf(value)) return fmt::format("{:>{}}", value > 0 ? "inf" : "-inf", width);
    switch (def.shown) {
        case Shown::kSigned:
            return fmt::format("{:>+{}.{}f}", value, width, def.text_decimals);
        case Shown::kPercent:
            return fmt::format("{:>{}.{}f}%", 100.0 * value, width - 1, def.text_decimals);
        case Shown::kMsFromNs:
            return fmt::format("{:>{}.{}f}", value * 1e-6, width, def.text_decimals);
        case Shown::kInteger:
            return fmt::format("{:>{}.0f}", value, width);
        case Shown::kGeneral:
            break;
    }
    return fmt::format("{:>{}.{}f}", value, width, def.text_decimals);
}

std::vector<MetricId> metrics_shown_in(unsigned where) {
    std::vector<MetricId> ids;
    for (MetricId id = 0; id < metric_registry().size(); ++id) {
        if (metric_registry()[id].shown_in & where) ids.push_back(id);
    }
    return ids;
}

// The line scores of one pattern's default rows, when it asks for edges: one row per method
// and a last row for the edge stage on the exact depth image (each line metric's twin
// "exact_depth_<key>", the same in every row of the pattern).
std::string format_line_table(const std::vector<ResultRow>& rows, const std::string& pattern,
                              std::size_t name_width) {
    const ResultRow* any = nullptr;
    for (const ResultRow& r : rows) {
        if (r.pattern == pattern && !r.sweep_point && has_line_scores(r)) any = &r;
    }
    if (!any) return "";
    const MetricRegistry& registry = metric_registry();
    const std::vector<MetricId> columns = metrics_shown_in(kInLineTable);
    name_width = std::max(name_width, std::string_view(kExactDepthLabel).size());
    std::string out = fmt::format(
        "  lines (edge stage on each depth image; detected p > {} or crease_weight |e| > {}, "
        "within {} px of the true lines; contours and creases apart on the right)\n"
        "  {:<{}}",
        kContourDetectThreshold, kCreaseDetectDarkness, kMatchRadiusPx, "depth image of",
        name_width);
    for (MetricId id : columns) {
        out += fmt::format(" {:>{}}", registry[id].header, registry[id].text_width);
    }
    out += '\n';
    for (const ResultRow& r : rows) {
        if (r.pattern != pattern || r.sweep_point) continue;
        out += fmt::format("  {:<{}}", r.method, name_width);
        for (MetricId id : columns) {
            out += " " + text_cell(registry[id], r[id], registry[id].text_width);
        }
        out += '\n';
    }
    out += fmt::format("  {:<{}}", kExactDepthLabel, name_width);
    for (MetricId id : columns) {
        const std::optional<MetricId> twin = registry.find("exact_depth_" + registry[id].key);
        out += " " + text_cell(registry[id], twin ? (*any)[*twin] : kNaN, registry[id].text_width);
    }
    return out + '\n';
}

}  // namespace

std::string format_compare_tables(const std::vector<ResultRow>& rows) {
    const MetricRegistry& registry = metric_registry();
    const std::vector<MetricId> columns = metrics_shown_in(kInText);
    std::string out;
    std::string current;
    std::size_t name_width = 6;
    for (const ResultRow& r : rows) name_width = std::max(name_width, r.method.size());
    for (const ResultRow& r : rows) {
        if (r.sweep_point) continue;
        if (r.pattern != current) {
            // The previous pattern's line scores after its table (a pattern's rows are
            // contiguous).
            if (!current.empty()) out += format_line_table(rows, current, name_width);
            current = r.pattern;
            out += fmt::format(
                "\n{}  ({}x{}, {} edges{}; times {})\n", r.pattern, r.width, r.height, r.edges,
                r.scene_file.empty() ? "" : ", scene file " + r.scene_file,
                r.time_threads > 1 ? fmt::format("on {} threads in bands", r.time_threads)
                                   : std::string("single-threaded"));
            out += fmt::format("  {:<{}}", "method", name_width);
            for (MetricId id : columns) {
                out += fmt::format(" {:>{}}", registry[id].header, registry[id].text_width);
            }
            out += '\n';
        }
        if (!r.not_applicable.empty()) {  // the method cannot draw this scene: its reason
            out += fmt::format("  {:<{}} n/a: {}\n", r.method, name_width, r.not_applicable);
            continue;
        }
        out += fmt::format("  {:<{}}", r.method, name_width);
        for (MetricId id : columns) {
            out += " " + text_cell(registry[id], r[id], registry[id].text_width);
        }
        // A post-process row's pass alone, after its cells (no column empty for every other
        // row): time_ms is its base's render plus the pass.
        if (!std::isnan(r[time_pass_metric()])) {
            out += fmt::format("  (pass {:.3f} ms)", r[time_pass_metric()]);
        }
        out += '\n';
    }
    if (!current.empty()) out += format_line_table(rows, current, name_width);
    for (const std::string& caveat : time_caveats(rows)) out += "\ntimes of " + caveat + "\n";
    return out;
}

std::vector<std::string> time_caveats(const std::vector<ResultRow>& rows) {
    std::vector<std::string> caveats;
    for (const MethodInfo& info : method_registry()) {
        const std::string& caveat = info.traits->time_caveat;
        if (caveat.empty()) continue;
        const bool present = std::any_of(rows.begin(), rows.end(), [&](const ResultRow& r) {
            return r.method_id == info.id;
        });
        if (present) caveats.push_back(info.id + ": " + caveat);
    }
    return caveats;
}

std::string compare_rows_csv(const std::vector<ResultRow>& rows) {
    std::vector<Column> columns = all_columns();
    // The temporal columns only in a sequence run's file: the other runs' files keep the
    // columns they always had.
    if (std::none_of(rows.begin(), rows.end(), is_sequence_row)) {
        std::erase_if(columns, [](const Column& c) { return c.sequences_only; });
    }
    std::string out;
    for (const Column& c : columns) out += (out.empty() ? "" : ",") + c.name;
    out += '\n';
    for (const ResultRow& r : rows) {
        bool first = true;
        for (const Column& c : columns) {
            if (!first) out += ',';
            first = false;
            out += csv_field(c.get(r));
        }
        out += '\n';
    }
    return out;
}

Json column_value(const ResultRow& row, std::string_view column) {
    for (const Column& c : all_columns()) {
        if (c.name == column) return c.get(row);
    }
    throw std::invalid_argument("column_value: no column " + std::string(column));
}

std::string compare_json(const std::vector<ResultRow>& rows, const RunContext& context) {
    const std::vector<Column> columns = all_columns();
    Json doc;
    doc["schema_version"] = kResultsSchemaVersion;
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
    for (const Column& c : columns) {
        if (!c.definition.empty()) definitions[c.name] = c.definition;
    }
    Json& out_rows = doc["rows"] = Json::array();
    for (const ResultRow& r : rows) {
        Json row = Json::object();
        const bool lines = has_line_scores(r);
        const bool sequence = is_sequence_row(r);
        for (const Column& c : columns) {
            // The line columns only for scenes that ask for edges, the temporal ones only for
            // sequences (rows of other scenes keep the columns they always had).
            if (c.lines_only && !lines) continue;
            if (c.sequences_only && !sequence) continue;
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
    // Files without a version are the first schema: the same column names, fewer columns.
    int version = 1;
    if (doc.contains("schema_version")) {
        const Json& v = doc["schema_version"];
        if (!v.is_number_integer()) throw InputError(source + ": schema_version is not a number");
        version = v.get<int>();
    }
    if (version < 1 || version > kResultsSchemaVersion) {
        throw InputError(fmt::format(
            "{}: results schema {} is not one this build reads (1..{}); regenerate it with this "
            "build's aabench compare (or aabench check --out for a baseline)",
            source, version, kResultsSchemaVersion));
    }
    const std::vector<Column> columns = all_columns();
    std::vector<ResultRow> rows;
    for (std::size_t k = 0; k < doc["rows"].size(); ++k) {
        const Json& j = doc["rows"][k];
        if (!j.is_object()) throw InputError(fmt::format("{}: rows[{}]: not an object", source, k));
        ResultRow row;
        for (const Column& c : columns) {
            if (!j.contains(c.name)) {
                // Columns that came after results files existed, and the line columns, which
                // rows of scenes without `edges` do not have.
                if (missing_as_default || c.may_be_absent || c.lines_only || c.sequences_only) {
                    continue;
                }
                throw InputError(fmt::format(
                    "{}: rows[{}]: missing '{}' (written by an older aabench: regenerate it with "
                    "this build's aabench compare)",
                    source, k, c.name));
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
