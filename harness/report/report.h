// The report stage: the only place that turns results into files. Formatting functions are
// pure (they return text); write_compare_results() writes them atomically.
//
// Every result column is declared once (report.cpp, result_columns()): its name, its
// definition, and how to read and write it. The CSV header, the JSON rows, the JSON
// "definitions" block and the reader used by `aabench merge` all come from that one table.
#pragma once

#include <string>
#include <vector>

#include "harness/measure/compare.h"
#include "harness/report/context.h"

namespace aabench {

// A fixed-width text table per pattern of the rows that are not sweep points.
std::string format_compare_tables(const std::vector<ResultRow>& rows);
// One row per task; the header names every column.
std::string compare_rows_csv(const std::vector<ResultRow>& rows);
// {"context": {...}, "definitions": {...}, "rows": [...]}
std::string compare_json(const std::vector<ResultRow>& rows, const RunContext& context);
// Reads the rows back from compare_json() text (for merging shards). Throws InputError, also
// for a row that lacks a column, unless `missing_as_default`: then a column the file does not
// have keeps ResultRow's default (NaN for a figure), as a baseline written by an older build
// needs (aabench check). scene_file and external_*, added later, may always be missing.
std::vector<ResultRow> rows_from_compare_json(const std::string& text, const std::string& source,
                                              bool missing_as_default = false);

// Writes table.txt, results.csv and results.json into `dir` (created if missing).
void write_compare_results(const std::string& dir, const std::vector<ResultRow>& rows,
                           const RunContext& context);

}  // namespace aabench
