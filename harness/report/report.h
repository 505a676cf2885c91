// The report stage: the only place that turns results into files. Formatting functions are
// pure (they return text); write_compare_results() writes them atomically.
//
// The columns are the rows' identity fields (report.cpp, identity_columns()) and the metric
// registry's metrics (harness/measure/metric_registry.h), each declared once with its name and
// definition. The CSV header, the JSON rows, the JSON "definitions" block, the text table and
// the reader used by `aabench merge` and `aabench check` all come from them.
//
// results.json carries "schema_version". 1 (no field) is the files written before the metric
// registry; 2 has the same column names plus time_method_ms and time_stages_ms. Both read.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "harness/measure/compare.h"
#include "harness/report/context.h"

namespace aabench {

inline constexpr int kResultsSchemaVersion = 2;

// One row's value of a results column (identity field or metric) as results.json writes it
// (NaN as null, infinities as "inf"/"-inf"). std::invalid_argument for an unknown column.
nlohmann::ordered_json column_value(const ResultRow& row, std::string_view column);

// A fixed-width text table per pattern of the rows that are not sweep points.
std::string format_compare_tables(const std::vector<ResultRow>& rows);

// "ID: caveat" for every method of `rows` whose registry row has a time caveat
// (MethodTraits::time_caveat), in the registry's order: printed under the tables and in the
// report's note, so that no time is read as what it is not.
std::vector<std::string> time_caveats(const std::vector<ResultRow>& rows);
// One row per task; the header names every column.
std::string compare_rows_csv(const std::vector<ResultRow>& rows);
// {"context": {...}, "definitions": {...}, "rows": [...]}
std::string compare_json(const std::vector<ResultRow>& rows, const RunContext& context);
// Reads the rows back from compare_json() text (for merging shards). Throws InputError, also
// for a row that lacks a column, unless `missing_as_default`: then a column the file does not
// have keeps ResultRow's default (NaN for a figure), as a baseline written by an older build
// needs (aabench check). Columns added later (scene_file, external_*, time_method_ms, ...) and
// the line scores may always be missing. A schema_version this build does not know is an
// InputError saying how to regenerate the file.
std::vector<ResultRow> rows_from_compare_json(const std::string& text, const std::string& source,
                                              bool missing_as_default = false);

// Writes table.txt, results.csv and results.json into `dir` (created if missing).
void write_compare_results(const std::string& dir, const std::vector<ResultRow>& rows,
                           const RunContext& context);

}  // namespace aabench
